// The bark table (Tables 1, 2 and 4 of paper 003 with the spec's chosen values), its species
// presets and the cross-row checks.
#include "bark/bark_params.h"

#include "params/embedded_presets.h"
#include "params/param_text.h"

namespace niwa::bark {
namespace {

using P = BarkParam;
constexpr int Id(P p) { return static_cast<int>(p); }
constexpr Stage kGrow = Stage::kGrow;
constexpr Stage kMesh = Stage::kMesh;

std::vector<ParamSpec> BarkRows() {
  return {
      // ------------------------------------------------ growth (Table 1)
      {Id(P::kRho), "rho", "ρ", "g/cm³", 0.5, 0.1, 1.5, false, "growth", kGrow,
       "Bark density 樹皮の密度 (Table 1, no value printed; spec §2: 0.5). Node mass m = ρ·A_n·D."},
      {Id(P::kSigma), "sigma", "σ", "", 0.1, 0, 1, false, "growth", kGrow,
       "Material variability 材料のばらつき (Table 1, no value): spread of each spring's break "
       "ratio, κ_s = 1 + (κ̄ − 1)(1 + σξ), ξ normal, |ξ| ≤ 3 (spec §1.6)."},
      {Id(P::kD), "D", "D", "cm", 1.0, 0.1, 3, false, "growth", kGrow,
       "Layer thickness 層の厚さ (Table 1, no value; spec §4.1: 1 cm). Spring k = (√3/2)·E·D, "
       "shear k_s = G·A_n/D."},
      {Id(P::kLo), "L_o", "L_o", "cm", 0.33, 0.05, 2, false, "growth", kGrow,
       "Initial node spacing 初期ノード間隔 (Table 2: 0.33 cm for all three species)."},
      {Id(P::kT), "T", "T", "s", 0.01, 0.0001, 1, false, "growth", kGrow,
       "Maximum growth period 最大成長期間 (Table 1, no value): one cycle in simulated seconds, "
       "the mechanical clock (spec §1.5: 0.01 s is quasi-static)."},
      {Id(P::kDeltaR), "dR", "δr·T/R_o", "", 0.021, 0, 0.5, false, "growth", kGrow,
       "Radial growth 半径成長 δr per cycle as a share of R_o (spec §2: 0.021); the hoop strain "
       "one cycle adds."},
      {Id(P::kDeltaH), "dH", "δh·T/H_o", "", 0.030, 0, 0.5, false, "growth", kGrow,
       "Height growth 高さ成長 δh per cycle as a share of H_o (spec §4.1: 0.030 for all species, "
       "level A; the presets carry the per-species 0.028 / 0.042 / 0.032, level B)."},
      {Id(P::kCycles), "cycles", "", "", 1, 1, 100, true, "growth", kGrow,
       "Growth periods T run one after the other (the 2-layer model grows on linearly; the "
       "paper's 2-layer runs are one period)."},
      {Id(P::kSettleSteps), "settle_steps", "", "", 2000, 0, 100000, true, "growth", kGrow,
       "Steps integrated after growth stops, the inner layer frozen (breaks still checked; spec "
       "§1.5)."},
      // ------------------------------------------------ species (Table 2)
      {Id(P::kE1), "E1", "E_1", "g/(s²·cm)", 117.3e7, 1e6, 1e11, false, "species", kGrow,
       "Young's modulus of the axial springs (family 1, along the trunk; Table 2)."},
      {Id(P::kE2), "E2", "E_2", "g/(s²·cm)", 117.3e7, 1e6, 1e11, false, "species", kGrow,
       "Young's modulus of the diagonal springs (family 2, ±30° from around the trunk; Table 2)."},
      {Id(P::kG), "G", "G", "g/(s²·cm)", 53.3e7, 1e6, 1e11, false, "species", kGrow,
       "Shear modulus せん断弾性係数 of the springs tying the surface to the inner layer (Table "
       "2)."},
      {Id(P::kKappa1), "kappa1", "κ̄_1", "", 1.033, 1.0001, 1.5, false, "species", kGrow,
       "Mean critical elongation ratio of the axial springs (Table 2); breaking them makes "
       "horizontal cracks (spec §1.3)."},
      {Id(P::kKappa2), "kappa2", "κ̄_2", "", 1.015, 1.0001, 1.5, false, "species", kGrow,
       "Mean critical elongation ratio of the diagonal springs (Table 2); breaking them makes "
       "vertical cracks."},
      // ------------------------------------------------ damping (spec §1.5; not in the paper)
      {Id(P::kZetaS), "zeta_s", "ζ_s", "", 0.5, 0, 5, false, "damping", kGrow,
       "Damping ratio of the dashpot beside each shear spring, c_s = ζ_s·2√(k_s·m)."},
      {Id(P::kZetaT), "zeta_t", "ζ_t", "", 1.0, 0, 5, false, "damping", kGrow,
       "Damping ratio of the dashpot along each intact spring, c_t = ζ_t·2√(k_t·m/2)."},
      // ------------------------------------------------ lattice (§3.1)
      {Id(P::kNR), "N_R", "N_R", "", 128, 8, 2048, true, "lattice", kGrow,
       "Node columns around the trunk (even): R_o = √3·L_o·N_R/(4π) (128: 5.82 cm)."},
      {Id(P::kNH), "N_H", "N_H", "", 64, 4, 2048, true, "lattice", kGrow,
       "Nodes along the trunk: H_o = L_o·N_H (64: 21.1 cm); the patch wraps in height too."},
      // ------------------------------------------------ peeling (Table 4; 4-layer model)
      {Id(P::kKappaH), "kappa_h", "κ_h", "", 0.03, 0.001, 1, false, "peeling", kGrow,
       "Critical mean shear strain 限界平均せん断ひずみ between surface and intermediate layer "
       "(Table 4, no value): an S→M1 shear spring breaks when |slip|/D passes κ_h(1 + σξ) "
       "(4-layer model)."},
      {Id(P::kEta), "eta", "η", "cm", 0.5, 0, 10, false, "peeling", kGrow,
       "Drying range 乾燥範囲 (Table 4): within η of a crack or a peeled part a node's critical "
       "shear strain decays with time (4-layer model)."},
      {Id(P::kGamma), "gamma", "γ", "", 1.0, 0, 100, false, "peeling", kGrow,
       "Drying coefficient 乾燥係数 (Table 4): the decay exp(−γ·Δt/T), per cycle (4-layer "
       "model)."},
      {Id(P::kA), "A", "A", "", 2.0, 1, 100, false, "peeling", kGrow,
       "Peeling-area ratio 剥離領域割合 (Table 4): a closed surface region peels when its area "
       "over its bonded area exceeds A (4-layer model)."},
      {Id(P::kCork), "cork", "d_c/D", "", 1.0, 0.01, 1, false, "peeling", kGrow,
       "Cork made per cycle as a share of D (spec §1.7, cork per cycle d_c): how far the layers "
       "move out a cycle (Fig. 7); 1 = the paper's one D. M2's stiffness still follows D·τ "
       "(4-layer model)."},
      // ------------------------------------------------ maps (spec §1.9)
      {Id(P::kMapSize), "map_size", "", "px", 1024, 256, 4096, true, "maps", kMesh,
       "Width of the maps around the trunk (a power of two); the height is the power of two "
       "nearest width·H/C."},
  };
}

const std::vector<ListedPreset>& BarkPresetList_() {
  static const std::vector<ListedPreset> presets = StudyPresetLists("bark", BarkTable());
  return presets;
}

}  // namespace

const ParamTable& BarkTable() {
  static const ParamTable table("bark", BarkRows(),
                                {{"growth", "Growth and material (Table 1)"},
                                 {"species", "Species constants (Table 2)"},
                                 {"damping", "Damping (not in the paper)"},
                                 {"lattice", "Lattice"},
                                 {"peeling", "Peeling (Table 4, 4-layer model)"},
                                 {"maps", "Maps"}});
  return table;
}

const ParamTable& TableOf(BarkParam) { return BarkTable(); }

Status CheckBarkParams(const BarkParams& p) {
  const int n_r = p.GetInt(P::kNR);
  if (n_r % 2 != 0) {
    return Status::Error("N_R", std::to_string(n_r) +
                                    " is odd; must be an even whole number in [8, 2048] (the "
                                    "triangular lattice wraps around the trunk)");
  }
  const double nodes = static_cast<double>(n_r) * p.GetInt(P::kNH);
  if (nodes > kMaxNodes) {
    return Status::Error("N_H", FormatNumber(nodes) + " nodes (N_R·N_H); must be at most " +
                                    std::to_string(kMaxNodes));
  }
  const int size = p.GetInt(P::kMapSize);
  if ((size & (size - 1)) != 0) {
    return Status::Error("map_size", std::to_string(size) +
                                         " is not a power of two; must be 256, 512, 1024, 2048 "
                                         "or 4096");
  }
  return Status::Ok();
}

const std::vector<std::string>& BarkPresetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const ListedPreset& p : BarkPresetList_()) n.push_back(p.name);
    return n;
  }();
  return names;
}

std::string BarkPresetList() {
  std::string out;
  const std::vector<std::string>& names = BarkPresetNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

std::string BarkPresetSource(std::string_view name) {
  for (const ListedPreset& p : BarkPresetList_())
    if (name == p.name) return p.source;
  return "";
}

std::vector<std::pair<std::string, double>> BarkPresetValues(std::string_view name) {
  for (const ListedPreset& p : BarkPresetList_())
    if (name == p.name) return p.values;
  return {};
}

Result<BarkParams> BarkPreset(std::string_view name) {
  for (const ListedPreset& preset : BarkPresetList_()) {
    if (name != preset.name) continue;
    BarkParams params;
    for (const auto& [key, value] : preset.values)
      NIWA_RETURN_IF_ERROR(params.Set(*BarkTable().Find(key), value));
    return params;
  }
  return Status::Error("species",
                       "'" + std::string(name) + "' is unknown; must be " + BarkPresetList());
}

}  // namespace niwa::bark
