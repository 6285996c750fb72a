// The ivy table's rows (Table 2 of Shindo & Sakamoto and the choices of docs/ivy-model.md), the
// cross-row checks, the four presets and the scale (paper pixels per scene unit).
#include "ivy/ivy_params.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "params/embedded_presets.h"
#include "params/param_text.h"

namespace niwa {
namespace {

std::vector<ParamSpec> Rows() {
  const Stage g = Stage::kGrow;
  const Stage m = Stage::kMesh;
  return {
      {0, "L", "L", "px", 50, 1e-6, 1e6, false, "rules", g,
       "Internode length = sucker-to-sucker distance (Table 2)."},
      {1, "d", "d", "px", 20, 1e-6, 1e7, false, "rules", g,
       "Sucker length: the largest node-to-face distance (Table 2)."},
      {2, "t1", "t₁", "", 0.2, 0, 100, false, "rules", g,
       "Growth threshold of p0; must be below t2 (Table 2)."},
      {3, "t2", "t₂", "", 0.8, 0, 100, false, "rules", g,
       "Dormancy-breaking threshold of p1; must be above t1 (Table 2)."},
      {4, "n0", "N₀", "", 0.2, 0, 100, false, "rules", g, "Nutrient of the seed apex at step 0."},
      {5, "delta_a", "δ_A", "1/step", 0.12, 0, 10, false, "rules", g,
       "p2 accumulation per step of an apical bud (times λ^order)."},
      {6, "delta_d", "δ_D", "1/step", 0.035, 0, 10, false, "rules", g,
       "p2 accumulation per step of a dormant bud (times λ^order)."},
      {7, "alpha", "α", "", 0.75, 0.5, 1, false, "rules", g,
       "p0: share of the remainder given to the new apex (> 1/2: 'A more than D')."},
      {8, "kappa", "κ", "", 1, 0, 1, false, "rules", g,
       "Fraction of its threshold a firing rule consumes."},
      {9, "lambda", "λ", "", 0.5, 1e-6, 1, false, "rules", g,
       "p2 factor per branch order (dominance between axes)."},
      {10, "obstacle_break", "", "", 1, 0, 1, true, "rules", g,
       "An apex that cannot grow releases the nearest dormant bud (§2.2)."},
      {11, "theta_x", "θx", "deg", 0, -180, 180, false, "lateral", g,
       "R() of p1: roll about the parent direction H."},
      {12, "theta_y", "θy", "deg", 0, -180, 180, false, "lateral", g,
       "R() of p1: pitch about the binormal B."},
      {13, "theta_z", "θz", "deg", 45, -180, 180, false, "lateral", g,
       "R() of p1: yaw about the surface normal (turns within the surface)."},
      {14, "alternate", "", "", 1, 0, 1, true, "lateral", g,
       "Alternate the sign of θz along an axis."},
      {15, "candidates", "n_c", "", 16, 1, 256, true, "search", g,
       "Candidate points per attempt (E6)."},
      {16, "phi", "φ", "deg", 30, 1e-6, 90, false, "search", g, "Candidate cone half-angle."},
      {17, "retries", "R_max", "", 3, 0, 8, true, "search", g,
       "Corrected retries after every candidate failed (E10)."},
      {18, "phi_step", "Δφ", "deg", 15, 0, 90, false, "search", g, "Cone widening per retry."},
      {19, "g_min", "g_min", "", 0, -1, 1, false, "search", g,
       "Gravitropism: least u·ĝ of an internode (0: never downwards)."},
      {20, "w_dist", "w_d", "", 1, 0, 10, false, "search", g, "Score weight: distance to a face."},
      {21, "w_angle", "w_a", "", 1, 0, 10, false, "search", g,
       "Score weight: angle to the preferred direction."},
      {22, "w_grav", "w_g", "", 1, 0, 10, false, "search", g, "Score weight: gravitropism."},
      {23, "eps", "ε", "px", 2, 0, 1e7, false, "search", g,
       "Least node clearance (keeps tubes out of the support); must be below d."},
      {24, "up_x", "ĝx", "", 0, -1, 1, false, "search", g, "Anti-gravity direction, x."},
      {25, "up_y", "ĝy", "", 1, -1, 1, false, "search", g, "Anti-gravity direction, y."},
      {26, "up_z", "ĝz", "", 0, -1, 1, false, "search", g, "Anti-gravity direction, z."},
      {27, "max_bend", "β_max", "deg", 180, 1e-6, 180, false, "improved", g,
       "Largest turn between consecutive internodes (180: off; fixes §4 problem 1)."},
      {28, "avoid", "r_avoid", "px", 0, 0, 1e6, false, "improved", g,
       "Least distance to other internodes (0: off; fixes §4 problem 2)."},
      {29, "r_tip", "r_tip", "px", 1.5, 1e-6, 1e6, false, "look", m, "Tube radius at a tip."},
      {30, "pipe_exp", "", "", 2, 1, 4, false, "look", m, "Pipe-model exponent of tube radii."},
      {31, "leaf_size", "s_leaf", "px", 50, 0, 1e6, false, "look", m, "Leaf blade width."},
      {32, "petiole", "l_p", "px", 20, 0, 1e6, false, "look", m, "Petiole length."},
      {33, "leaf_age", "τ_leaf", "step", 5, 1e-6, 1e4, false, "look", m,
       "Steps until a leaf reaches full size."},
      {34, "leaf_tilt", "", "deg", 30, -90, 90, false, "look", m,
       "Petiole tilt from the surface normal toward up."},
      // Appended last (the keys of rows 0-34 keep their ids); docs/ivy-model.md "Convex edges".
      {35, "tangent_retry", "", "", 1, 0, 1, true, "search", g,
       "When every retry failed, try a fixed fan of directions in the face's tangent plane and "
       "tilted over its edge (0: off, the plain E10)."},
      // Appended last (issue 31 item 4): the scale is the support's, not a preset's. Every row in
      // px is in the paper's pixels, divided by this when the run starts (IvyScaledParams).
      {36, "scale", "k", "px/unit", 0, 0, 1e9, false, "scale", g,
       "Paper pixels per scene unit (1 px = 1 mm): 1000 metres, 10 cm, 1 mm or px; 0 = the "
       "support's own (built-in scenes 1, a tree 1000, a mesh file 1200 / its largest extent)."},
      // Appended (issue 31 item 6): §3.2's condition (b) checked along the internode too.
      {37, "body", "", "d", 0, 0, 10, false, "search", g,
       "Largest distance of an internode's midpoint and quarter points from a face, in d (0: "
       "off, only the nodes are checked; 1: the body stays within d)."},
      // Appended (issue 31 item 5): beyond §3.2, docs/ivy-model.md "The artist preset".
      {38, "hang", "", "internodes", 0, 0, 100, true, "search", g,
       "Hanging tendrils: internodes an apex may grow off the support, turning 30° a step toward "
       "the ground (0: off, §3.2 as written); an apex whose search failed, or a lateral born on a "
       "face looking down, hangs."},
      {39, "leaf_light", "", "", 0, 0, 1, false, "look", m,
       "Leaves by light and support normal: shaded leaves larger and fewer, blades hanging from "
       "the petiole, leaning out by half their face's angle from up (0: off, every leaf alike)."},
      // Appended (issue 31 items 4 and 7): leaves a real length apart along the stems, whatever
      // the growth's scale; docs/ivy-model.md "Leaves a real length apart".
      {40, "leaf_spacing", "s_n", "px", 0, 0, 1e6, false, "look", m,
       "Stem length between leaves: on a mesh whose growth is scaled to its size while its leaves "
       "keep their real size, long internodes carry several leaves and short ones share one "
       "(0: one leaf a bud, the paper; at most 8 a bud)."},
  };
}

struct Preset {
  std::string name;
  std::vector<std::pair<std::string, double>> overrides;
};

// core/ivy/presets/ivy_presets.json (embedded; docs/ivy-model.md, Presets), read once.
const std::vector<Preset>& Presets();

}  // namespace

const ParamTable& IvyTable() {
  static const ParamTable table("ivy", Rows(),
                                {{"scale", "Scale (the support's units)"},
                                 {"rules", "Nutrient rules (Table 2, p0-p3)"},
                                 {"lateral", "Lateral rotation R(θx, θy, θz)"},
                                 {"search", "Position search (§3.2)"},
                                 {"improved", "The paper's two problems (§4)"},
                                 {"look", "Tubes, leaves, suckers"}});
  return table;
}

const ParamTable& TableOf(IvyParam) { return IvyTable(); }

namespace {

const std::vector<Preset>& Presets() {
  static const std::vector<Preset> presets = [] {
    std::vector<Preset> out;
    for (ListedPreset& p : StudyPresetLists("ivy", IvyTable()))
      out.push_back({std::move(p.name), std::move(p.values)});
    return out;
  }();
  return presets;
}

}  // namespace

Status ValidateIvyParams(const IvyParams& p) {
  const double t1 = p.Get(IvyParam::kT1), t2 = p.Get(IvyParam::kT2);
  if (!(t1 < t2)) {
    return Status::Error("t1", FormatNumber(t1) + " is not below t2 = " + FormatNumber(t2) +
                                   "; must be in [0, t2) (§3.1: t1 < t2)");
  }
  if (!(p.Get(IvyParam::kAlpha) > 0.5)) {
    return Status::Error("alpha", FormatNumber(p.Get(IvyParam::kAlpha)) +
                                      " is out of range; must be a number in (0.5, 1]");
  }
  const double d = p.Get(IvyParam::kD), eps = p.Get(IvyParam::kEps), L = p.Get(IvyParam::kL);
  if (!(eps < d)) {
    return Status::Error(
        "eps", FormatNumber(eps) + " is not below d = " + FormatNumber(d) + "; must be in [0, d)");
  }
  if (d > 10 * L) {
    return Status::Error("d", FormatNumber(d) + " is out of range; must be in (0, 10 L] = (0, " +
                                  FormatNumber(10 * L) + "]");
  }
  if (p.Get(IvyParam::kAvoid) > L) {
    return Status::Error("avoid", FormatNumber(p.Get(IvyParam::kAvoid)) +
                                      " is out of range; must be in [0, L] = [0, " +
                                      FormatNumber(L) + "]");
  }
  const double ux = p.Get(IvyParam::kUpX), uy = p.Get(IvyParam::kUpY), uz = p.Get(IvyParam::kUpZ);
  if (ux * ux + uy * uy + uz * uz < 1e-12) {
    return Status::Error("up_y", "the up vector (up_x, up_y, up_z) is zero; must be non-zero");
  }
  return Status::Ok();
}

bool IsIvyLength(std::size_t row) { return std::strcmp(IvyTable().row(row).unit, "px") == 0; }

double IvyPxPerUnit(const IvyParams& params, double support_px_per_unit, double support_extent) {
  const double k = params.Get(IvyParam::kScale);
  if (k > 0) return k;
  if (support_px_per_unit > 0) return support_px_per_unit;
  if (support_extent > 0 && std::isfinite(support_extent)) return kIvyPaperExtent / support_extent;
  return 1;
}

double IvyLeafDensity(const IvyParams& scaled) {
  const double spacing = scaled.Get(IvyParam::kLeafSpacing);
  return spacing > 0 ? scaled.Get(IvyParam::kL) / spacing : 1.0;
}

int IvyLeavesPerBud(const IvyParams& scaled) {
  const double n = IvyLeafDensity(scaled);
  return n <= 1 ? 1 : static_cast<int>(std::min<double>(kIvyMaxLeavesPerBud, std::floor(n + 0.5)));
}

bool IsIvyLookLength(std::size_t row) {
  return IsIvyLength(row) && std::strcmp(IvyTable().row(row).group, "look") == 0;
}

double IvyLookPxPerUnit(const IvyParams& params, double support_px_per_unit,
                        double unit_px_per_unit, double px_per_unit) {
  const double k = params.Get(IvyParam::kScale);
  if (k > 0) return k;
  if (support_px_per_unit > 0) return support_px_per_unit;
  if (unit_px_per_unit > 0 && std::isfinite(unit_px_per_unit)) return unit_px_per_unit;
  return px_per_unit;
}

Result<IvyParams> IvyScaledParams(const IvyParams& declared, double px_per_unit,
                                  double look_px_per_unit) {
  for (const double k : {px_per_unit, look_px_per_unit}) {
    if (!(k > 0) || !std::isfinite(k)) {
      return Status::Error(
          "scale", FormatNumber(k) + " px per unit is out of range; must be a number in (0, 1e9]");
    }
  }
  IvyParams out = declared;
  for (std::size_t row = 0; row < out.size(); ++row) {
    if (!IsIvyLength(row)) continue;
    const double k = IsIvyLookLength(row) ? look_px_per_unit : px_per_unit;
    // A division (not a product with 1/k): 50 px at 1000 px/m is 0.05 exactly as written.
    const double value = declared.Get(row) / k;
    if (!out.Set(row, value).ok()) {
      const ParamSpec& spec = IvyTable().row(row);
      return Status::Error("scale",
                           FormatNumber(k) + " px per unit makes " + spec.key + " = " +
                               FormatNumber(declared.Get(row)) + " px " + FormatNumber(value) +
                               " scene units, outside its range; must make every length row fit");
    }
  }
  NIWA_RETURN_IF_ERROR(out.Set(IvyParam::kScale, 1));
  return out;
}

const std::vector<std::string>& IvyPresetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Preset& p : Presets()) n.push_back(p.name);
    return n;
  }();
  return names;
}

std::vector<std::pair<std::string, double>> IvyPresetOverrides(std::string_view name) {
  for (const Preset& p : Presets())
    if (name == p.name) return p.overrides;
  return {};
}

Result<IvyParams> IvyPreset(std::string_view name) {
  for (const Preset& preset : Presets()) {
    if (name != preset.name) continue;
    IvyParams params;
    for (const auto& [key, value] : preset.overrides) {
      std::optional<std::size_t> row = IvyTable().Find(key);
      NIWA_RETURN_IF_ERROR(params.Set(*row, value));
    }
    return params;
  }
  std::string names;
  for (const Preset& p : Presets()) names += (names.empty() ? "" : ", ") + p.name;
  return Status::Error("preset", "'" + std::string(name) + "' is unknown; must be one of " + names);
}

}  // namespace niwa
