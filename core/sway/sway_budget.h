// Memory and time of a sway run (RunSway: duration / dt steps over every internode) and of its
// skinned .glb clip (WriteSwayGlb: keys × joints), estimated from the sway model's counts before
// the run starts (issue 16, docs/budgets.md). Does not: run the sway or measure anything (counts
// times calibrated constants, so native and WASM refuse at the same point).
#pragma once

#include "base/budget.h"
#include "sway/sway.h"
#include "tree/tree_budget.h"

namespace niwa {

// Steps RunSway takes for params' duration and dt.
double SwaySteps(const SwayParams& params);

// RunSway over `model` tracing `tips` tips: the simulator, its trajectories (8 + 24·tips bytes a
// step) and the steps × internodes of work.
Estimate EstimateSwayRun(const SwayModel& model, const SwayParams& params, int tips);

// WriteSwayGlb at `fps` with at most `max_joints` joints: the tree's mesh and skin, keys (at most
// one a step) × joints of 28 bytes (translation and rotation), and the simulation that makes them
// (twice when the skin is clustered: once to choose the groups).
Estimate EstimateSwayGlb(const SwayModel& model, const TreeCounts& counts, const SwayParams& params,
                         double fps, std::size_t max_joints);

// The page's sway (web/bindings/tree_bindings.cpp): `instances` simulators of `model` stepped by
// the wall clock and their pose arrays (16 floats a node point and instance); no trajectories.
Estimate EstimatePageSway(const SwayModel& model, int instances);

// The page's sway in time: the worker steps every simulator by the wall clock, at most
// kPageSwayMaxStepsPerTick steps a tick, and answers nothing else during a tick. A tick may take
// kPageSwayTickSeconds by estimate (the page answers a click within 1 s: a click that needs the
// worker waits for the tick in progress, then for its own work and a frame; docs/budgets.md), so
// the steps of a tick are lowered to fit it; a sway slower than kPageSwaySlowest of real time is
// refused (it would look frozen).
inline constexpr double kPageSwayTickSeconds = 0.25;
inline constexpr int kPageSwayMaxStepsPerTick = 8;
inline constexpr double kPageSwaySlowest = 0.25;

struct PageSwayTime {
  double step_seconds = 0;  // one step of every instance (internodes × 90 ns, as EstimateSwayRun)
  int steps_per_tick = 0;   // at most 8, at least 1, within kPageSwayTickSeconds when one fits
  double speed = 0;         // simulated over wall time the worker can keep up (at most 1)
};
PageSwayTime EstimatePageSwayTime(const SwayModel& model, const SwayParams& params, int instances);

// Ok when the sway fits the page's tick and plays at least kPageSwaySlowest of real time; else one
// line naming `limit` (the page's "page time budget") and `change` ("raise dt or lower years,
// ...").
Status CheckPageSwayTime(const PageSwayTime& time, const SwayModel& model, const SwayParams& params,
                         int instances, const std::string& limit, const std::string& change);

}  // namespace niwa
