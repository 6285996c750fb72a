// The bark study on a grown Niwa tree (issue 30 item 3; ../shared/specs/bark.md §6): the trunk's
// radius history at a height, the 2-layer bark model run on it (one cycle: the real circumference,
// the strain the visible surface has seen since it formed, read off the tree's own radial growth
// over at most the last W years), and the tree's .glb re-textured with the maps: the tile wrapped
// a whole number of times around each branch, v in metres over the tile's height, a younger
// surface's maps (half the strain) on the young shoots; the old bark may be the 4-layer model
// (kFourLayerCycles cycles, peeling). Part of the composition tier (core/compose includes the tree
// and bark studies; neither includes it), for `niwa tree grow --bark sim` and the page alike. Does
// not: grow the tree (the caller's Grower or TreeRun does, calling RecordTrunkYear after each
// year), change the procedural export (the default .glb keeps its bytes), run the young shoots'
// bark with the 4-layer model, or name a flag (errors name "bark", "bark_height", "bark_species",
// "bark_model", "bark_map_size").
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bark/bark_state.h"
#include "base/budget.h"
#include "base/status.h"
#include "image/image.h"
#include "io/gltf_writer.h"
#include "params/param_table.h"
#include "run/study_run.h"
#include "tree/mesh.h"
#include "tree/tree.h"

namespace niwa::compose {

constexpr double kDefaultBarkHeight = 1.3;  // m above the ground (breast height)
constexpr double kMaxBarkHeight = 100;      // m: the flag's static range; the tree's is tighter
constexpr int kBarkWindow = 4;              // W: years of growth the surface may have seen
// The visible surface's life in the species' calibrated cycles: it has grown by at most this many
// of the cycle's absolute radial growth, dR·R_o of the preset's lattice (Table 3's 0.021 × 5.82 cm
// = 0.122 cm; tallow's 0.009 × 5.82 cm), since it formed (docs/bark-model.md, "On Niwa's trees").
constexpr double kSurfaceCycles = 2;
// The 4-layer old bark's cycles: the surface shown at the end is kSurfaceCycles role exchanges old
// (the first cycle's surface cracks, peels and is shed), each cycle 1/kSurfaceCycles of ε_s.
constexpr int kFourLayerCycles = static_cast<int>(kSurfaceCycles) + 1;
// Shoots of at most this age in years (grown this year: 1) get the young bark (half the trunk
// surface's strain); older ones and the trunk the old bark.
constexpr int kYoungBarkYears = 2;

// The trunk at one height, year by year: the trunk is the seedling shoot and, from each shoot's
// tip, its thickest living continuation (the tube the mesh tapers into).
struct TrunkYear {
  int year = 0;
  double top_m = 0;      // height of the trunk's top node
  double radius_cm = 0;  // the trunk's radius at the height (the mesh's linear taper); 0: below
};
struct TrunkHistory {
  double height_m = kDefaultBarkHeight;
  std::vector<TrunkYear> years;  // ascending, one per year grown (the last: the shown tree)
};

// The trunk's radius (cm) at height_m of the tree as grown now (0 when the trunk does not reach
// it) and the top of the trunk (m).
TrunkYear MeasureTrunk(const Tree& tree, double height_m);
// Appends the tree's year (no-op when that year is already recorded).
void RecordTrunkYear(const Tree& tree, TrunkHistory* history);

// The heights the bark may be read at (m): [0, the trunk's top a year before the last], so that
// at least one year of growth passes at the height. max < 0: the tree grew fewer than two years.
struct BarkHeightRange {
  double min = 0, max = -1;
};
BarkHeightRange BarkHeights(const TrunkHistory& history);

// What the bark run on the tree will be: the state (species preset, one cycle, dR the surface's
// strain ε_s, N_R from the real circumference when that surface formed, so the run ends at the
// last year's), the window's radii, and the two runs' estimate. ε_s combines two limits on the
// surface's age as rates that add (docs/bark-model.md, "On Niwa's trees", item 4):
//   ε_window   = r(last)/r(first) − 1: the surface is at most the window's W years old;
//   ε_turnover = G / max(R_o, r(last) − G), G = kSurfaceCycles·dR·R_o (cm, R_o the preset's lattice
//                radius): it has grown at most G since it formed, so a thicker trunk's surface is
//                less strained (Table 3's note *3; spec E3: the same absolute ΔR on a larger R);
//   ε_s = ε_window·ε_turnover / (ε_window + ε_turnover), below both (no ceiling is reached).
struct BarkOnTreePlan {
  bark::BarkState state;        // the old bark's run (one cycle)
  bark::BarkState young_state;  // the same lattice and seed, half the strain: the young shoots'
  int first_year = 0, last_year = 0;  // r(first_year) .. r(last_year), one a year
  std::vector<double> radii_cm;       // r(first_year), ..., r(last_year)
  double hoop_strain = 0;             // ε_window = r(last)/r(first) − 1
  double surface_growth_cm = 0;       // G = kSurfaceCycles·dR·R_o of the species' preset
  double turnover_strain = 0;         // ε_turnover = G / max(R_o, r(last) − G)
  double surface_strain = 0;          // ε_s: the old run's dR
  double surface_years = 0;           // years since the surface formed (radii linear between)
  Estimate estimate;                  // both runs, their maps and the .glb's re-texturing
};

// ε_s of a trunk from its window's hoop strain and the turnover's strain (0 when either is ≤ 0).
double SurfaceStrain(double hoop_strain, double turnover_strain);

struct BarkOnTreeOptions {
  std::string species = "camphor";  // a bark preset (bark::BarkPresetNames)
  std::string model = "2layer";     // the old bark's model: 2layer or 4layer (bark::SetBarkModel)
  int map_size = 1024;              // the maps' width, a power of two in [256, 4096]
  uint64_t seed = 1;
};

// The options' own checks, before any growth: "bark_species" (a bark preset), "bark_model"
// (2layer or 4layer), "bark_map_size" (a power of two in [256, 4096]).
Status CheckBarkOnTreeOptions(const BarkOnTreeOptions& options);

// The plan for the history's height. Errors: "bark_height" (outside BarkHeights, with the range
// in metres), "bark" (a tree of fewer than two years), "bark_species", "bark_model",
// "bark_map_size". With model 4layer the old run is the 4-layer model over kFourLayerCycles cycles
// of dR = ε_s / kSurfaceCycles each, N_R from the inner layer's radius at the run's start,
// (r(last) − 2.5·d_c)/(1 + kFourLayerCycles·dR), so that the surface layer S ends at r(last);
// the young run stays the 2-layer cycle at ε_s/2.
Result<BarkOnTreePlan> PlanBarkOnTree(const TrunkHistory& history,
                                      const BarkOnTreeOptions& options);

// One frame of bark maps (PNG bytes) and the tile they cover on the trunk.
struct BarkFrame {
  std::string base_colour, normal, orm, height;    // height: empty in GrowOldBark's frames
  double tile_width_m = 0, tile_height_m = 0;      // circumference and height of the grown patch
  std::string hash;                                // the bark run's share hash
  image::Rgba8Image colour_pixels, normal_pixels;  // the page's textures (row 0 = v 0)
  // The base colour map's mean in linear values (image::MeanLinearRgb): the colour a far tree's
  // eq. 4.2 lines take as C_b in the garden's hybrid view.
  std::array<double, 3> mean_colour = {0, 0, 0};
};
struct BarkOnTree {
  BarkOnTreePlan plan;
  BarkFrame old_bark, young_bark;
  double height_m = 0;  // the trunk's height the plan read (GrowTreeBark)
};

// Runs both bark runs of the plan (checked against `budget`: a refusal names "bark"), with the
// observer seeing the old run's progress then the young one's; a cancel is returned as is.
Result<BarkOnTree> GrowBarkOnTree(const BarkOnTreePlan& plan, const Budget& budget,
                                  const run::Observer& observer = nullptr);

// The tree table's bark rows (tree/tree_params.h: `bark`, `bark_model`), as the tree's state
// carries them from a link, a state file, `--set` or the page's panel: true when `bark` is 1.
bool TreeBarkSimulated(const ParamSet& tree_params);
// The model `bark_model` names: "2layer" (2) or "4layer" (4); any other value an error naming
// "bark_model".
Result<std::string> TreeBarkModel(const ParamSet& tree_params);

// The one run of the bark on a tree, for `niwa tree grow --bark sim` and the page's TreeSession
// alike: the plan at the first of `trunks` (one height each, in the caller's order: the CLI gives
// one, the page its fallbacks from breast height down) whose height the tree allows (else that
// last plan's error), then `held` (what the caller holds and will make: the tree, its export)
// plus the plan's estimate checked against `budget` before any bark work, a refusal naming "bark"
// with `hint` (the caller's words for what to change), then both runs (GrowBarkOnTree).
Result<BarkOnTree> GrowTreeBark(const std::vector<TrunkHistory>& trunks,
                                const BarkOnTreeOptions& options, const Estimate& held,
                                const Budget& budget, const std::string& hint,
                                const run::Observer& observer = nullptr);

// The plan's old bark run alone (no young shoots' run: the garden wears one frame on every tube),
// checked against `budget` with its own estimate (OldBarkEstimate): a refusal names "bark". Its
// maps' longer side is the plan's map_size: a thin trunk's tall, narrow tile gets a narrower map
// (a power of two, at least 32 px wide) at the texel density of its height, not a map_size-wide
// one up to 16× as tall (docs/garden-model.md, "Bark").
Result<BarkFrame> GrowOldBark(const BarkOnTreePlan& plan, const Budget& budget,
                              const run::Observer& observer = nullptr);
// The old bark run's estimate (its run and maps; plan.estimate counts both runs).
Estimate OldBarkEstimate(const BarkOnTreePlan& plan);

// Puts the frame's maps on `material` of `doc`: its base colour and normal textures (names `name`,
// `name`_normal) replace the ones it has (the procedural bark's give way) or are appended, and the
// ORM map (`name`_orm, appended) is its occlusion (R) and metallic-roughness (G, B), sampler
// REPEAT.
void DressBarkMaterial(const BarkFrame& frame, const std::string& name, gltf::Material* material,
                       gltf::Document* doc);

// Whole wraps of a tile `tile_width_m` around a branch of radius `radius_m`:
// max(1, round(2π·r / C_tile)).
int WrapsAround(double radius_m, double tile_width_m);

// True when the branch (grown in `branch_year`) is young on a tree of `tree_year` years.
bool YoungShoot(int branch_year, int tree_year);

// The tree mesh's bark split by age (old: index 0, young: index 1), every tube's ring UVs
// rewritten: u = ring_u · n_u(branch), v = metres along the wood / tile height (its frame's
// tile); end caps keep their disc UVs.
struct BarkParts {
  MeshBuffers old_bark, young_bark;
};
BarkParts WrapBark(const Tree& tree, const TreeMesh& mesh, const BarkOnTree& bark);

// The bark's ring UVs of one frame for every tube, in the mesh's vertex order (the page's one bark
// part: its young shoots wear the old frame too); caps keep their disc UVs.
std::vector<float> WrapBarkUvs(const Tree& tree, const TreeMesh& mesh, const BarkFrame& frame);

// The tree's glTF document (TreeGltfDocument: bark, leaves, flowers) with the bark as the
// simulated maps: material "bark" (the old frame) and, when any young shoot is drawn, material
// "bark_young" as a fourth primitive; base colour, normal, occlusion and metallic-roughness
// (the ORM map) textures, sampler REPEAT.
Result<gltf::Document> BarkTreeDocument(const Tree& tree, const TreeMesh& mesh,
                                        const BarkOnTree& bark);

// BarkTreeDocument written as binary glTF: the one .glb of a tree dressed in its simulated bark,
// `niwa tree grow --bark sim --out t.glb` and the tree page's "Download .glb" with `bark` 1 alike
// (the same state and bark give the same bytes). Errors name "glb" (io/gltf_writer).
Result<std::string> BarkTreeGlb(const Tree& tree, const TreeMesh& mesh, const BarkOnTree& bark);

// {"species", "model", "height_m", "years": [first, last], "radii_cm": [...], "hoop_strain",
// "surface_growth_cm", "turnover_strain", "surface_years", "N_R", "N_H", "cycles", "dR",
// "young_dR", "tile_cm": [w, h], "young_years", "hash"} for the CLI's stats.
std::string BarkOnTreeJson(const BarkOnTree& bark);  // "height_m" is bark.height_m

}  // namespace niwa::compose
