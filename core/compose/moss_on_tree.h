// Moss on a grown Niwa tree standing on a ground slab: the tree's bark (compose/bark_support) and a
// square of humus around its foot as the moss study's land, the one composition both front ends
// call (`niwa moss grow --tree-preset`). Does not: grow the moss (moss/moss_run does, through
// MossRun::StartOnScene on the scene this builds), add leaves or flowers to the land (moss grows on
// bark and ground only; the leaves' shade is not modelled), or name a flag (errors name "tree",
// "tree_years" or the budget's limit; the front ends rename them).
#pragma once

#include <string>

#include "base/budget.h"
#include "base/status.h"
#include "moss/scenes.h"

namespace niwa::compose {

// The ground's half-width: at least kMossGroundMinHalf metres, else the bark's horizontal reach
// from the trunk (its bounds' largest |x| or |z|) plus kMossGroundMargin.
constexpr double kMossGroundMinHalf = 1.0;
constexpr double kMossGroundMargin = 0.5;

// Grows tree preset `preset` for `years` years within `budget` (the limits of `niwa tree grow`; a
// stop line tells the user to lower `years_name`) and returns the land: scene "tree:<preset>",
// the bark's triangles (geology sandy, region "bark": bark holds little water, choice 29 of
// docs/moss-model.md) then the ground (two triangles at y = 0 facing up, humus, region "ground")
// whose soil cells the run splits; `truncated_by` gets the tree's stop line ("" if none).
Result<moss::MossScene> MossTreeLand(const std::string& preset, double years, const Budget& budget,
                                     const std::string& years_name, std::string* truncated_by);

}  // namespace niwa::compose
