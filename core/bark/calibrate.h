// The bark study's calibration (`niwa bark calibrate`; ../shared/specs/bark.md §3 item 6, §4.1,
// §4.6): a deterministic, budgeted grid search over the rows the spec lets a species calibrate —
// the growth and thickness of the 2-layer model (dH, dR, D: Table 3 level B, "per-species growth"),
// the peeling constants of the 4-layer model (κ_h, γ, A, η: Table 4 prints no values) — each grid
// point run over the seeds and scored against the paper: the 2-layer model's crack spacing along
// scan lines (the paper's measure, regions.h Spacing) against Table 3's means (±25 %) and maxima
// (±40 %, camphor's "(>20)" as a line along the trunk crossing no crack), the 4-layer model
// against "part of the bark peeled" (the share of S peeled by each cycle's end within a band, and
// peeling in every cycle after the first). One JSON object: every candidate with its measures and
// score, the best, and whether it meets the bars. Does not: change a preset (the values found are
// recorded by hand in core/bark/presets, with the search in docs/bark-model.md), draw maps, search
// rows the spec does not name (Table 2's constants are the paper's), or refine past the grid.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bark/bark_state.h"
#include "base/budget.h"
#include "base/status.h"

namespace niwa::bark {

// One row searched: `points` values evenly from lo to hi (lo alone when points = 1), rounded to
// 1e-12.
struct CalibrateAxis {
  std::string key;
  double lo = 0, hi = 0;
  int points = 1;
  std::vector<double> Values() const;
};

constexpr int kMaxCalibratePoints = 9;   // values of one axis
constexpr int kMaxCalibrateRuns = 2000;  // grid points × seeds

// The 4-layer target band of the share of S peeled by a cycle's end ("part of the bark peeled",
// note *3; the paper prints no number): its centre ± half width, and the least share a cycle after
// the first must peel (the sequence repeats: peeling every cycle).
constexpr double kPeelShareCentre = 0.3, kPeelShareHalfWidth = 0.2, kPeelShareLeast = 0.02;

struct CalibrateRequest {
  BarkState base;  // species preset with any --set rows; its model picks the search
  std::vector<CalibrateAxis> vary;
  uint64_t first_seed = 1, last_seed = 3;
};

// The rows a model may calibrate: 2layer dH, dR, D; 4layer kappa_h, gamma, A, eta.
const std::vector<std::string>& CalibratableKeys(std::string_view model);
// The axes searched when none is given: 2layer dH over 0.020..0.050 (7 points); 4layer kappa_h
// 0.03..0.3 (4) × gamma 0.25..1 (2) × A 2..8 (2).
std::vector<CalibrateAxis> DefaultCalibrateAxes(std::string_view model);

// "KEY=LO:HI:N" (or "KEY=V", one point); errors name "vary" with the form, the key's row range
// and the model's calibratable keys.
Result<CalibrateAxis> ParseCalibrateAxis(std::string_view text, std::string_view model);

// The whole search's cost: every grid point's run (EstimateBarkRun, no maps) × the seeds; memory
// of one run (they run one after another).
Estimate EstimateCalibrate(const CalibrateRequest& request);

// Checks the request (axes: calibratable, within their rows, a key once; the 2-layer species in
// Table 3; the 4-layer model at least 2 cycles; grid × seeds ≤ kMaxCalibrateRuns; errors name
// "vary", "species", "cycles" or "seeds"), refuses the estimate over the budget up front, then runs
// the grid in order (the first axis slowest) and returns the JSON object.
Result<std::string> CalibrateJson(const CalibrateRequest& request, const Budget& budget);

}  // namespace niwa::bark
