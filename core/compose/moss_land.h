// The moss run on the land its state names, the one start both front ends call: a built-in scene
// (moss/moss_run MossRun::Start), a Niwa tree (scene "tree": moss_on_tree.h, from the state's tree
// and tree_years) or a Niwa terrain (scene "terrain": moss_on_terrain.h, from the state's terrain
// and terrain_seed), so the state's hash regrows the same land. Does not: load a mesh file (the
// front ends do, then MossRun::StartOnScene), grow the days (MossRun::Advance), or name a flag
// (errors name state fields; `words` gives the front end's word for "tree_years" in a tree's
// budget stop line).
#pragma once

#include <string>

#include "base/budget.h"
#include "base/status.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "run/field_names.h"

namespace niwa::compose {

// Starts the moss run of `state` on its land within `budget` (the land's growth shares it);
// `truncated_by` gets the land's stop line ("" if none). Errors: the run's (MossRun::Start), the
// tree's ("tree", "tree_years") or the terrain's ("terrain", "terrain_seed"), or the budget's.
Result<moss::MossRun> StartMossOnLand(const moss::MossState& state, const Budget& budget,
                                      const run::FieldNames& words, std::string* truncated_by);

}  // namespace niwa::compose
