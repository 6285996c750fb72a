// The tree's table: every model parameter (thesis tables 2.1, 3.1 and the choices documented in
// docs/growth-model.md, docs/sway-model.md and docs/rendering-model.md).
#include "tree/tree_params.h"

namespace niwa {
namespace {

using P = TreeParam;
constexpr Stage kGrow = Stage::kGrow;
constexpr Stage kSway = Stage::kSway;
constexpr Stage kMesh = Stage::kMesh;
constexpr Stage kView = Stage::kView;
constexpr int Id(TreeParam p) { return static_cast<int>(p); }

// Stages: every growth row regrows (leaf_size and pipe_area too: the leaf-sphere radius and the
// pipe model are growth inputs); sway and wind rows only restart the sway; render rows only change
// the hybrid view. leaf_shape, leaf_card and leaf_spray are used by the mesh alone (kMesh);
// season, autumn_colour, flower_colour and flower_form only dress the tree already grown (kView):
// none regrows. terminal_flowers places flowers while growing (kGrow) but draws no random number,
// so trees without it grow the same. bark and bark_model only re-texture the tree grown (kView).
//
// Defaults are the sakura column of thesis table 2.2. "a ~ b" ranges are split into *_low (value at
// hormone 0, or for P_l at age 0) and *_high (value at hormone H_sat, or at age P_l_years).
const std::vector<ParamSpec>& Rows() {
  static const std::vector<ParamSpec> rows = {
      {Id(P::kAlphaT), "alpha_t", "α_t", "", 0.7, 0, 1, false, "hormone", kGrow,
       "Share of the parent's hormone inherited by the terminal shoot (eq. 2.1)."},
      {Id(P::kAlphaTl), "alpha_tl", "α_tl", "", 0.55, 0, 1, false, "hormone", kGrow,
       "Share of the parent's hormone inherited by a terminally-lateral shoot (eq. 2.1)."},
      {Id(P::kAlphaL), "alpha_l", "α_l", "", 0.4, 0, 1, false, "hormone", kGrow,
       "Share of the parent's hormone inherited by a lateral shoot (eq. 2.1)."},
      {Id(P::kBetaC), "beta_c", "β_c", "", 0.2, 0, 1, false, "hormone", kGrow,
       "Share of its initial hormone a new shoot keeps after growing (eq. 2.2)."},
      {Id(P::kBetaP), "beta_p", "β_p", "", 0.25, 0, 1, false, "hormone", kGrow,
       "Share of last year's hormone an older branch keeps (eq. 2.3)."},
      {Id(P::kHS), "h_s", "h_s", "", 0.2, 0, 5, false, "hormone", kGrow,
       "Hormone a dwarf shoot makes per unit of received light (eq. 2.2)."},
      {Id(P::kHL), "h_l", "h_l", "", 0.5, 0, 5, false, "hormone", kGrow,
       "Hormone a long shoot makes per unit of received light (eq. 2.2)."},
      {Id(P::kGamma), "gamma", "γ", "", 0.2, 0, 1, false, "hormone", kGrow,
       "Share of the children's hormone passed down to the parent branch (eq. 2.3)."},
      {Id(P::kHShort), "H_s", "H_s", "", 0.1, 0, 10, false, "hormone", kGrow,
       "Dwarf-shoot threshold: a shoot whose initial hormone is below it is a dwarf shoot."},
      {Id(P::kHInit), "H_init", "H_0", "", 1.0, 0, 10, false, "hormone", kGrow,
       "Initial hormone of the seedling's first shoot (not in the thesis; see docs)."},
      {Id(P::kHSat), "H_sat", "H_sat", "", 1.0, 0.01, 10, false, "hormone", kGrow,
       "Hormone at which the hormone-dependent ranges reach their second value (figs. 2.5, 2.6, "
       "2.8)."},

      {Id(P::kNLow), "N_low", "N", "nodes", 6, 1, 100, true, "branching", kGrow,
       "Nodes per shoot at hormone 0 (first value of the range N in table 2.2)."},
      {Id(P::kNHigh), "N_high", "N", "nodes", 25, 1, 100, true, "branching", kGrow,
       "Nodes per shoot at hormone H_sat (second value of the range N in table 2.2)."},
      {Id(P::kDLow), "D_low", "D", "cm", 0.2, 0.01, 100, false, "branching", kGrow,
       "Internode length at hormone 0 (first value of the range D)."},
      {Id(P::kDHigh), "D_high", "D", "cm", 3.0, 0.01, 100, false, "branching", kGrow,
       "Internode length at hormone H_sat (second value of the range D)."},
      {Id(P::kDwarfInternodeRatio), "D_s_ratio", "D_s/D_l", "", 1.0, 0.01, 4, false, "branching",
       kGrow, "Dwarf-shoot internode length as a fraction of the long-shoot length (fig. 2.13)."},
      {Id(P::kLengthStep), "length_step", "", "", 0, 0, 1, false, "branching", kGrow,
       "Share of the N and D ranges that jumps at the dwarf threshold H_s (fig. 2.5): 0 linear in "
       "the initial hormone; 1 dwarf shoots at the first value, long shoots at the second."},
      {Id(P::kBT), "B_t", "B_t", "buds", 1, 0, 1, true, "branching", kGrow,
       "Terminal buds per shoot."},
      {Id(P::kBTl), "B_tl", "B_tl", "buds", 1, 0, 8, true, "branching", kGrow,
       "Terminally-lateral buds at the tip of each shoot."},
      {Id(P::kBL), "B_l", "B_l", "buds/node", 1, 0, 8, true, "branching", kGrow,
       "Lateral buds (and leaves) per node: 1 alternate, 2 decussate, 3+ verticillate."},
      {Id(P::kPhi), "phi", "ϕ", "turn", 0.4, 0, 1, false, "branching", kGrow,
       "Phyllotaxis: turn between successive nodes (1/2, 1/3, 2/5, 3/8; 1/4 for decussate)."},
      {Id(P::kThetaN), "theta_N", "θ_N", "deg", 0, -90, 90, false, "branching", kGrow,
       "Bend at each node of a sympodial shoot, alternating side (zigzag)."},
      {Id(P::kSympodial), "sympodial", "", "", 0, 0, 1, true, "branching", kGrow,
       "1: sympodial branching (no true terminal bud; the top lateral bud takes over)."},
      {Id(P::kPsiT), "psi_t", "ψ_t", "deg", 0, -90, 90, false, "branching", kGrow,
       "Branching angle of the terminal shoot from its parent's tip direction."},
      {Id(P::kPsiTl), "psi_tl", "ψ_tl", "deg", 45, -90, 90, false, "branching", kGrow,
       "Branching angle of terminally-lateral shoots."},
      {Id(P::kPsiL), "psi_l", "ψ_l", "deg", 45, -90, 90, false, "branching", kGrow,
       "Branching angle of lateral shoots."},
      {Id(P::kPTlS), "P_tl_s", "P_tl^s", "", 0, 0, 1, false, "branching", kGrow,
       "Largest break probability of a dwarf shoot's terminally-lateral buds (fig. 2.8)."},
      {Id(P::kPTlL), "P_tl_l", "P_tl^l", "", 0.9, 0, 1, false, "branching", kGrow,
       "Largest break probability of a long shoot's terminally-lateral buds (fig. 2.8)."},
      {Id(P::kPLYoung), "P_l_young", "P_l", "", 0.1, 0, 1, false, "branching", kGrow,
       "Largest break probability of a long shoot's lateral buds in a young tree (fig. 2.9)."},
      {Id(P::kPLOld), "P_l_old", "P_l", "", 0.6, 0, 1, false, "branching", kGrow,
       "Largest break probability of a long shoot's lateral buds from age P_l_years on (fig. "
       "2.9)."},
      {Id(P::kPLYears), "P_l_years", "", "years", 10, 1, 100, false, "branching", kGrow,
       "Tree age at which the lateral break probability reaches P_l_old."},
      {Id(P::kDwarfLateralFlowers), "dwarf_flowers", "", "", 1, 0, 1, true, "branching", kGrow,
       "1: the lateral buds of dwarf shoots are flower buds (sakura, thesis 2.5.4)."},
      {Id(P::kClearStem), "clear_stem", "", "cm", 0, 0, 1000, false, "branching", kGrow,
       "Nursery crown raising (not in the thesis): each year, side shoots starting below "
       "min(clear_stem, 0.4 × height) are cut; 0: off."},
      {Id(P::kTrimHeight), "trim_height", "", "cm", 0, 0, 500, false, "branching", kGrow,
       "Gardener's trim of hanging shoots (not in the thesis): each year, a shoot whose tip hangs "
       "below this height is cut; 0: off."},
      {Id(P::kStandardHeight), "standard_height", "H_std", "cm", 0, 0, 1000, false, "branching",
       kGrow,
       "Trained standard (not in the thesis): the leader (the seedling and its chain of terminal "
       "shoots) is tied to a stake and grows straight up until its base passes this height; 0: "
       "off."},
      {Id(P::kBasalShoots), "basal_shoots", "B_c", "buds", 0, 0, 8, true, "branching", kGrow,
       "Basal shoots (not in the thesis): shoots that break from the root collar each year from "
       "year 1 to basal_years, with the seedling's hormone H_init, leaning psi_tl; 0: off."},
      {Id(P::kBasalYears), "basal_years", "k_c", "years", 1, 1, 100, true, "branching", kGrow,
       "Last year in which basal shoots break from the root collar (with basal_shoots > 0)."},
      {Id(P::kBH), "b_h", "b_h", "", 0, 0, 1, false, "branching", kGrow,
       "Plagiotropism rate (not in the thesis): every shoot but the leader also bends towards the "
       "horizontal of its bud direction, as a conifer's whorl branches do; 0: off."},

      {Id(P::kUseLight), "use_light", "", "", 1, 0, 1, true, "light", kGrow,
       "1: light model on (death and phototropism); 0: every shoot gets full light, straight up."},
      {Id(P::kKDeath), "k_death", "k", "", 0.1, 0, 1, false, "light", kGrow,
       "A new shoot dies when its light is below k × U(0.5, 1) (2.4.1)."},
      {Id(P::kSphereOpacity), "sphere_opacity", "", "", 0.3, 0, 0.99, false, "light", kGrow,
       "Share of light stopped by a ray through the full diameter of one leaf sphere."},
      {Id(P::kSunElevation), "sun_elevation", "", "deg", 60, 5, 90, false, "light", kGrow,
       "Elevation of the sun above the horizon."},
      {Id(P::kSunAzimuth), "sun_azimuth", "", "deg", 0, -180, 180, false, "light", kGrow,
       "Azimuth of the sun, from +x towards +z."},
      {Id(P::kSunWeight), "sun_weight", "", "", 0, 0, 1, false, "light", kGrow,
       "Share of the light that comes from the sun; the rest is the overcast sky. Default 0: the "
       "thesis's light is sky light only, and a sun makes every tree lean towards it."},
      {Id(P::kSkyZenithRatio), "sky_zenith_ratio", "", "", 1, 1, 3, false, "light", kGrow,
       "Sky radiance at the zenith over that at the horizon: 1 uniform sky, 3 CIE overcast sky."},
      {Id(P::kLightScale), "light_scale", "", "", 1, 0.1, 1, false, "light", kGrow,
       "L = this × the light reaching the shoot's leaf sphere (1 = open sky): sets the scale of L, "
       "which the thesis does not give, against table 2.2's hormone values."},

      {Id(P::kBLLow), "b_L_low", "b_L", "", 0.12, 0, 1, false, "bending", kGrow,
       "Phototropism rate at hormone 0 (fig. 2.6)."},
      {Id(P::kBLHigh), "b_L_high", "b_L", "", 0.01, 0, 1, false, "bending", kGrow,
       "Phototropism rate at hormone H_sat (fig. 2.6)."},
      {Id(P::kBGLow), "b_g_low", "b_g", "", 0.01, -1, 1, false, "bending", kGrow,
       "Negative geotropism rate at hormone 0 (fig. 2.6); below 0 shoots droop (weeping forms)."},
      {Id(P::kBGHigh), "b_g_high", "b_g", "", 0.02, -1, 1, false, "bending", kGrow,
       "Negative geotropism rate at hormone H_sat (fig. 2.6); below 0 shoots droop (weeping "
       "forms)."},
      {Id(P::kThetaBmaxN), "theta_bmax_N", "θ_bmax^N", "deg", 15, 0, 180, false, "bending", kGrow,
       "Largest bend at one node (eq. 2.9)."},
      {Id(P::kThetaBmaxB), "theta_bmax_b", "θ_bmax^b", "deg", 20, 0, 180, false, "bending", kGrow,
       "Largest change of the branching angle (eq. 2.7)."},
      {Id(P::kBLByLight), "b_L_by_light", "", "", 0, 0, 1, true, "bending", kGrow,
       "1: phototropism rate follows the received light L instead of the hormone (fig. 2.16 c)."},

      {Id(P::kHBL), "H_b_l", "H_b^l", "", 0.05, 0, 10, false, "dormancy_break", kGrow,
       "An old branch whose hormone falls below this breaks dormant buds (0: off)."},
      {Id(P::kDeltaL), "delta_l", "δ_l", "", 0.3, 0, 1, false, "dormancy_break", kGrow,
       "Chance of each dormant bud to break when the threshold is crossed."},
      {Id(P::kBBL), "B_b_l", "B_b^l", "buds", 2, 0, 20, true, "dormancy_break", kGrow,
       "Most dormant buds one branch breaks through the threshold."},
      {Id(P::kHNL), "H_n_l", "H_n^l", "", 0.3, 0, 10, false, "dormancy_break", kGrow,
       "Extra initial hormone of a bud broken through the threshold."},
      {Id(P::kHBD), "h_b_d", "h_b^d", "", 4, 0, 100, false, "dormancy_break", kGrow,
       "A sudden drop H < H'/h_b^d breaks dormant buds (0: off)."},
      {Id(P::kDeltaD), "delta_d", "δ_d", "", 0.35, 0, 1, false, "dormancy_break", kGrow,
       "Chance of each dormant bud to break after a sudden drop."},
      {Id(P::kBBD), "B_b_d", "B_b^d", "buds", 2, 0, 20, true, "dormancy_break", kGrow,
       "Most dormant buds one branch breaks after a sudden drop."},
      {Id(P::kHND), "H_n_d", "H_n^d", "", 0.4, 0, 10, false, "dormancy_break", kGrow,
       "Extra initial hormone of a bud broken after a sudden drop."},

      {Id(P::kUseHormone), "use_hormone", "", "", 1, 0, 1, true, "shape", kGrow,
       "1: hormone model on; 0: every shoot long, with the high end of every range (2.5.1)."},
      {Id(P::kPipeAreaPerLeaf), "pipe_area", "", "cm²/leaf", 0.02, 0, 10, false, "shape", kGrow,
       "Cross-section added to a branch each year per leaf above it (pipe model, 2.4.4)."},
      {Id(P::kLeafSize), "leaf_size", "", "cm", 6, 0.1, 50, false, "shape", kGrow,
       "Leaf length, used for drawing and for the leaf-sphere radius."},
      {Id(P::kMaxInternodes), "max_internodes", "", "internodes", 2000000, 1000, 5000000, true,
       "shape", kGrow, "Safety limit: growth stops adding shoots past this many internodes."},

      // Wind sway (thesis ch. 3). Units as table 3.1: cgs inside the model (cm, g, s, dyn); wind
      // speed in m/s and g in m/s². Defaults: examples 2-4 of table 3.1 (docs/sway-model.md).
      {Id(P::kKWind), "K_wind", "K_wind", "g/(cm²·s)", 0.1, 0, 100, false, "sway", kSway,
       "Wind force per unit area and unit relative speed (eq. 3.5; table 3.1: 0.1)."},
      {Id(P::kKDirTrunk), "K_dir_trunk", "K_dir", "dyn/cm²", 150000, 0, 1e9, false, "sway", kSway,
       "Direction-restoring coefficient at the thickest branch (eq. 3.8; table 3.1: "
       "50000~150000)."},
      {Id(P::kKDirTip), "K_dir_tip", "K_dir", "dyn/cm²", 50000, 0, 1e9, false, "sway", kSway,
       "Direction-restoring coefficient at the thinnest branch; linear in radius between (eq. "
       "3.8)."},
      {Id(P::kKRev), "K_rev", "K_rev", "", 0.8, 0, 1, false, "sway", kSway,
       "Share of the restoring force's reaction passed to the parent node (eq. 3.10; table 3.1: "
       "0.8)."},
      {Id(P::kKVdel), "K_vdel", "K_vdel", "", 1, 0, 1, false, "sway", kSway,
       "Velocity kept per step, damping by the tree itself (eq. 3.13; table 3.1: 1)."},
      {Id(P::kWoodDensity), "wood_density", "δ", "g/cm³", 0.12, 0.01, 2, false, "sway", kSway,
       "Branch density (eqs. 3.1, 3.3; table 3.1: 0.12)."},
      {Id(P::kMLeaf), "m_leaf", "m_leaf", "g", 3, 0, 100, false, "sway", kSway,
       "Mass of one leaf (eq. 3.3; table 3.1: 3 g, exaggerated in the thesis). 0: no leaf mass."},
      {Id(P::kSLeaf), "s_leaf", "s_leaf", "cm²", 30, 0, 1000, false, "sway", kSway,
       "Surface area of one leaf (eq. 3.4; table 3.1: 30 cm²). 0: no leaf area."},
      {Id(P::kSwayAlpha), "sway_alpha", "α", "", 2, 1, 8, false, "sway", kSway,
       "Exponent of the interpolation of intermediate nodes (eq. 3.15); 1 bends at the node."},
      {Id(P::kGravity), "gravity", "g", "m/s²", 9.8, 0, 100, false, "sway", kSway,
       "Gravitational acceleration, along -y (eq. 3.6)."},
      {Id(P::kGravityPreload), "gravity_preload", "", "", 1, 0, 1, true, "sway", kSway,
       "1: the grown shape is the rest pose under gravity (no sag at t = 0); 0: as the thesis."},
      {Id(P::kSwayDt), "dt", "dt", "s", 1.0 / 30.0, 0.0001, 0.1, false, "sway", kSway,
       "Time step of the sway simulation (eqs. 3.13, 3.14, 3.16; table 3.1: 1/30 s)."},
      {Id(P::kOmitLimit), "omit_limit", "", "", 1, 0.1, 4, false, "sway", kSway,
       "A node point moves only if K_x dt²/m is at most this: 3 in eq. 3.16; 1 (default) keeps "
       "thin tips from jittering (docs/sway-model.md)."},

      {Id(P::kWindSpeed), "wind_speed", "v_wind", "m/s", 5, 0, 100, false, "wind", kSway,
       "Wind speed while the gust blows (eq. 3.5; thesis examples: 5, 10, 20)."},
      {Id(P::kWindDir), "wind_dir", "", "deg", 0, -360, 360, false, "wind", kSway,
       "Wind azimuth in the horizontal plane: 0 blows towards +x, 90 towards +z."},
      {Id(P::kGustOn), "gust_on", "", "s", 1, 0, 3600, false, "wind", kSway,
       "Time the wind starts suddenly from still air (thesis 3.5); at the origin with a gust "
       "front."},
      {Id(P::kGustOff), "gust_off", "", "s", 6, 0, 3600, false, "wind", kSway,
       "Time the wind stops suddenly; must be after gust_on."},
      {Id(P::kGustFrontSpeed), "gust_front_speed", "", "m/s", 0, 0, 100, false, "wind", kSway,
       "Speed of the gust front along the wind: a point d m downwind of the origin gets the wind "
       "d / speed s later (start and stop). 0: everywhere at once, as the thesis."},
      {Id(P::kWindVariation), "wind_variation", "", "", 0, 0, 1, false, "wind", kSway,
       "Amplitude v of a gust wave travelling with the wind: speed × (1 + v sin(2π(x/λ - t/T))). "
       "0: "
       "uniform, as the thesis."},
      {Id(P::kWindWavelength), "wind_wavelength", "λ", "m", 25, 1, 1000, false, "wind", kSway,
       "Wavelength λ of the travelling gust wave along the wind (with wind_variation > 0)."},
      {Id(P::kWindPeriod), "wind_period", "T", "s", 5, 0.1, 600, false, "wind", kSway,
       "Period T of the travelling gust wave at a fixed point (with wind_variation > 0)."},
      {Id(P::kSwayDuration), "duration", "", "s", 12, 0, 600, false, "wind", kSway,
       "Simulated time of a sway run."},
      {Id(P::kRenderMode), "render_mode", "", "", 0, 0, 1, true, "render", kView,
       "0: full polygons (generalized cylinders, leaf quads; what glTF export writes); 1: hybrid "
       "(thesis ch. 4: thick branches and leaves as texture cards, thin twigs as lines)."},
      {Id(P::kLineThreshold), "line_threshold", "", "px", 4, 0.1, 1000, false, "render", kView,
       "Hybrid mode: a branch whose on-screen width D_i (eq. 4.1) is below this is drawn as a "
       "line, "
       "above it as a card (with hysteresis, so nothing pops while the view moves)."},
      {Id(P::kCardPlanes), "card_planes", "", "", 2, 2, 8, true, "render", kView,
       "Hybrid mode: card planes per branch, rotated about the branch axis b_i; the plane facing "
       "the "
       "viewer is drawn (thesis 4.2.1 uses at least 2)."},
      {Id(P::kLeafClusterCards), "leaf_cluster_cards", "", "", 1, 0, 1, true, "render", kView,
       "Hybrid mode: 1 merges the leaves of nearby branches into leaf-cluster cards (thesis 5.2); "
       "0 draws leaves on their branch's card (thesis 4.2.1)."},
      {Id(P::kLeafShape), "leaf_shape", "", "", 0, 0, 3, true, "shape", kMesh,
       "Leaf blade on every leaf quad: 0 broad (elliptic: sakura, keyaki), 1 needle (a cluster of "
       "needles: pine), 2 palmate (seven lobes: maple), 3 fan (ginkgo)."},
      // Not in the thesis (issue 32 item 3; docs/tree-species.md "The pine's needles"): leaf_size
      // is the leaf sphere the light model grows with (growth.cpp); the card drawn for it may show
      // more than one leaf's length, as a pine's fascicle of 7-12 cm needles on a 3 cm sphere.
      {Id(P::kLeafCard), "leaf_card", "", "", 1, 0.25, 4, false, "shape", kMesh,
       "Drawn leaf card's length over leaf_size (the light model's leaf): 1 the leaf itself; "
       "above 1 a bundle or cluster longer than one leaf sphere (pine 2.5: its needles' 7.5 cm)."},
      // Not in the thesis (issue 32 item 3; docs/tree-species.md "Leaf sprays"): as ez-tree and
      // SpeedTree, one card may show a spray, a twig with several leaves, so a crown drawn by a
      // standard engine reads as dense as the species'. The grown leaves and the light model stay
      // one per leaf; only the drawn card (tree_textures.h MakeLeafTexture) changes.
      {Id(P::kLeafSpray), "leaf_spray", "", "leaves", 1, 1, 12, true, "shape", kMesh,
       "Leaves painted on each drawn leaf card: 1 the leaf itself; n > 1 a spray, a twig with n "
       "leaves of leaf_shape, each leaf_size × leaf_card long, on one card of the same two "
       "triangles a side (a crown as dense as the species', as ez-tree and SpeedTree draw)."},
      {Id(P::kSeason), "season", "", "", 1, 0, 3, true, "render", kView,
       "0 spring (fresh leaves; a flowering deciduous tree blossoms on bare wood, as cherries do), "
       "1 summer (leaves and flowers as grown), 2 autumn (autumn colour, no flowers), 3 winter "
       "(bare; evergreens keep their leaves)."},
      {Id(P::kAutumnColour), "autumn_colour", "", "", 1, 0, 4, true, "render", kView,
       "Colour the leaves turn in autumn: 0 evergreen (stay green, kept in winter), 1 red-orange "
       "(sakura), 2 red (maple), 3 yellow (ginkgo), 4 orange-brown (keyaki)."},
      {Id(P::kFlowerColour), "flower_colour", "", "", 0, 0, 4, true, "render", kView,
       "Colour of the flowers: 0 pale pink (Somei-yoshino), 1 deep pink (beni-shidare), 2 "
       "magenta (Hirado and Kurume azaleas), 3 red (azalea 'Hinode-giri'), 4 white."},
      {Id(P::kFlowerForm), "flower_form", "", "", 0, 0, 1, true, "render", kView,
       "Form of the flowers: 0 cherry (umbels of five notched petals, flat), 1 azalea (trusses "
       "of funnel flowers with five round lobes, a spotted upper lobe and long stamens)."},
      {Id(P::kTerminalFlowers), "terminal_flowers", "", "", 0, 0, 1, true, "branching", kGrow,
       "Terminal flower buds (not in the thesis; Rhododendron): 1: every shoot of last year opens "
       "a flower truss at its tip this spring (the new shoots break beside it); 0: off."},
      // Not in the thesis (issue 30 item 3; docs/bark-model.md "Bark on Niwa's trees"): the tree
      // study only carries these two rows; core/compose/bark_on_tree reads them (the CLI's
      // `tree grow` and the page's TreeSession), so they dress the tree grown (kView).
      {Id(P::kBark), "bark", "", "", 0, 0, 1, true, "bark", kView,
       "0: the procedural bark texture; 1: simulated, the bark study (paper 003) run on the "
       "trunk's own radius history over its last years and its maps wrapped around every branch "
       "(the full .glb and the page; a few seconds)."},
      {Id(P::kBarkModel), "bark_model", "", "layers", 2, 2, 4, true, "bark", kView,
       "With bark 1: the trunk's bark model, 2 (the 2-layer model: one cycle) or 4 (the 4-layer "
       "model: 3 cycles with layer birth, peeling and shedding; several times the cost, "
       "estimated and refused up front)."},
  };
  return rows;
}

}  // namespace

const ParamTable& TreeParamTable() {
  static const ParamTable table("tree", Rows(),
                                {{"hormone", "Hormone"},
                                 {"branching", "Branching"},
                                 {"light", "Light"},
                                 {"bending", "Bending"},
                                 {"dormancy_break", "Dormancy break"},
                                 {"shape", "Shape and limits"},
                                 {"sway", "Sway"},
                                 {"wind", "Wind"},
                                 {"render", "Render"},
                                 {"bark", "Bark"}});
  return table;
}

std::optional<TreeParam> FindParam(std::string_view key) {
  std::optional<std::size_t> row = TreeParamTable().Find(key);
  if (!row) return std::nullopt;
  return static_cast<TreeParam>(*row);
}

}  // namespace niwa
