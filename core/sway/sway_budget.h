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

// WriteSwayGlb at `fps`: the tree's mesh and skin, keys (at most one a step) × joints of 28 bytes
// (translation and rotation), and the simulation that makes them.
Estimate EstimateSwayGlb(const SwayModel& model, const TreeCounts& counts, const SwayParams& params,
                         double fps);

// The page's sway (web/bindings/tree_bindings.cpp): `instances` simulators of `model` stepped by
// the wall clock and their pose arrays (16 floats a node point and instance); no trajectories.
Estimate EstimatePageSway(const SwayModel& model, int instances);

}  // namespace niwa
