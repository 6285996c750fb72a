// Ivy on a grown Niwa tree: the tree's bark (compose/bark_support) as an ivy support, the one
// composition both front ends call (`niwa ivy grow --tree-preset` / `--scene tree`, the ivy page's
// tree scene). Does not: grow the ivy (ivy/ivy_run does, on the support this prepares), add
// leaves or flowers to the support, or name a flag or a panel label (errors name "tree",
// "tree_years" or the budget's limit; the front ends rename them).
#pragma once

#include <string>

#include "base/budget.h"
#include "base/status.h"
#include "compose/bark_support.h"
#include "ivy/ivy_run.h"

namespace niwa::compose {

// Grows tree preset `preset` for `years` years within `budget` (the limits of `niwa tree grow`,
// shared with the ivy's own; a truncation line tells the user to lower `years_name`) and returns
// it as a prepared ivy support: scene "tree:<preset>" whose one named seed, "trunk", is the +z side
// of the trunk foot, with the tree's and its bark's estimate and the tree's stop line ("" if none).
// on_stage: GrowBarkSupport's progress (every year, then the bark).
Result<ivy::IvySupportInput> IvyTreeSupport(const std::string& preset, double years,
                                            const Budget& budget,
                                            const std::string& years_name = "tree_years",
                                            const BarkProgress& on_stage = {});

}  // namespace niwa::compose
