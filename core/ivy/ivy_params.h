// The ivy study's parameter table ("ivy"): Shindo & Sakamoto's Table 2 (L, d, t1, t2) and every
// value the paper leaves open (docs/ivy-model.md), with bare keys on the ivy page and "ivy." on a
// composed page; the presets paper, literal, improved and metric; the cross-row checks (t1 < t2,
// eps < d, alpha > 1/2). Does not: parse text or JSON (params/, io/hash_codec, ivy_state) or grow.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "params/param_table.h"

namespace niwa {

// One entry per row of the ivy table, in panel order within each group.
enum class IvyParam : int {
  // Table 2 and the nutrient rules p0-p3 (§3.1)
  kL,
  kD,
  kT1,
  kT2,
  kN0,
  kDeltaA,
  kDeltaD,
  kAlpha,
  kKappa,
  kLambda,
  kObstacleBreak,
  // lateral rotation R(θx, θy, θz) of p1 (E11)
  kThetaX,
  kThetaY,
  kThetaZ,
  kAlternate,
  // position search (§3.2, E6-E10)
  kCandidates,
  kPhi,
  kRetries,
  kPhiStep,
  kGMin,
  kWDist,
  kWAngle,
  kWGrav,
  kEps,
  kUpX,
  kUpY,
  kUpZ,
  // the paper's two problems (§4), off in `paper`
  kMaxBend,
  kAvoid,
  // birth geometry (§1.5 of the spec): tubes, leaves, suckers
  kRTip,
  kPipeExp,
  kLeafSize,
  kPetiole,
  kLeafAge,
  kLeafTilt,
  // appended after the look rows (row ids are URL/JSON-stable): the position search's last resort
  kTangentRetry,
  // appended (issue 31 item 4): paper pixels per scene unit; 0 = the support's own
  kScale,
  // appended (issue 31 item 6): the internode body's largest distance to a face, in d; 0 = off
  kBody,
  // appended (issue 31 item 5, the artist preset): hanging tendrils and leaves by light
  kHang,
  kLeafLight,
  // appended (issue 31 items 4 and 7): the stem length between leaves; 0 = one leaf a bud
  kLeafSpacing,
  kCount
};

const ParamTable& IvyTable();
const ParamTable& TableOf(IvyParam);
using IvyParams = StudyParams<IvyParam>;

// Checks what one row's range cannot: t1 < t2 (§3.1), alpha > 1/2 ("A more than D"), eps < d, a
// non-zero up vector. The error names the row and its allowed range.
Status ValidateIvyParams(const IvyParams& params);

// The scale (issue 31 item 4). The rows whose unit is "px" (L, d, eps, avoid, r_tip, leaf_size,
// petiole) are in the paper's pixels (Table 2: L = 50 on cubes4, 1200 px high; 1 px = 1 mm, the
// old metric preset's reading); a run divides them by the pixels per scene unit, so the rules of
// any preset run on a support in any unit.
constexpr double kIvyPaperExtent = 1200;  // cubes4's largest extent, px
bool IsIvyLength(std::size_t row);        // the row's unit is "px"
// The pixels per scene unit of a run: the row "scale" when > 0, else the support's own (its
// px_per_unit: 1 on a built-in scene, 1000 on a tree), else its bounds (kIvyPaperExtent / its
// largest extent, so it is as big as cubes4 in pixels), else 1.
double IvyPxPerUnit(const IvyParams& params, double support_px_per_unit, double support_extent);
// The look's length rows (group "look": r_tip, leaf_size, petiole; issue 31 item 7: leaves and
// tubes keep their size in metres): their pixels per scene unit are the row "scale" when > 0 (a
// given unit, as every length row's), else the support's own (support_px_per_unit: a built-in
// scene's or a tree's), else the unit its file names (unit_px_per_unit: 1000 on a glTF, in
// metres), else px_per_unit (the bounds': an OBJ names no unit). So a leaf of s_leaf = 50 px is
// 5 cm on a 0.3 m rock and on a 20 m facade read as glTF, while the growth's lengths (L, d, eps,
// avoid) are read from the mesh's bounds.
bool IsIvyLookLength(std::size_t row);  // r_tip, leaf_size, petiole, leaf_spacing

// Leaves a bud carries with the row leaf_spacing s_n on scaled params: n = L / s_n; below 1 a bud
// keeps its leaf with probability n (IvyLeafKept), else round(n) leaves, at most
// kIvyMaxLeavesPerBud; 1 when s_n is 0 (the paper: one leaf a bud).
inline constexpr int kIvyMaxLeavesPerBud = 8;
double IvyLeafDensity(const IvyParams& scaled);  // n (1 when s_n is 0)
int IvyLeavesPerBud(const IvyParams& scaled);    // the leaves a bud draws at most (1..8)
double IvyLookPxPerUnit(const IvyParams& params, double support_px_per_unit,
                        double unit_px_per_unit, double px_per_unit);
// The parameters in scene units: every length row divided by px_per_unit (the look's by
// look_px_per_unit), "scale" set to 1 (the lengths now are per unit). Error "scale" naming the row
// a scale pushes out of its range.
Result<IvyParams> IvyScaledParams(const IvyParams& declared, double px_per_unit,
                                  double look_px_per_unit);
inline Result<IvyParams> IvyScaledParams(const IvyParams& declared, double px_per_unit) {
  return IvyScaledParams(declared, px_per_unit, px_per_unit);
}

// The preset names, in the order `niwa presets ivy` prints them.
const std::vector<std::string>& IvyPresetNames();
// The table defaults with the preset's overrides; error names "preset" and the allowed names.
Result<IvyParams> IvyPreset(std::string_view name);
// The overrides of one preset as (key, value) pairs (for printing).
std::vector<std::pair<std::string, double>> IvyPresetOverrides(std::string_view name);

}  // namespace niwa
