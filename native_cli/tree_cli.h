// The tree state flags shared by every command that grows a tree (tree grow, mappings, sway,
// render-stats): --preset, --years, --seed, --set, --params, --prune, --url, --state, resolved
// through core/tree/tree_state. Does not: register commands (native_cli/*_commands.cpp do).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli_common.h"
#include "run/field_names.h"
#include "tree/tree.h"
#include "tree/tree_state.h"

namespace niwa::cli {

struct StateOptions {
  std::string preset = kDefaultPreset;
  int years = -1;  // -1: the preset's own
  uint64_t seed = 0;
  std::vector<std::string> sets, prunes;
  std::string params_file, url, state_file;
  std::string season, leaf_shape;  // --season, --leaf-shape by name (the tree's look rows)
  BudgetOptions budget;            // --max-memory, --max-seconds: the growth's GrowLimits
};

// The tree family's one field -> flag table: a core error's state field ("years", "max_triangles",
// "cam") as the flag that sets it ("--years", "--max-triangles", "--cam").
const run::FieldNames& TreeFlagNames();

// Adds the state flags of `table` (its --set keys; see 'niwa params') to cmd.
void AddStateOptions(CLI::App* cmd, const ParamTable& table, StateOptions* options);

// The state the flags give: --url (a whole link or a bare hash; any notice is an error) or --state
// (a state file, tree/tree_state's TreeStateFileJson), then --preset, --years, --seed,
// --params, --set and --prune on top, each through the tree_state setters. Throws BadInput.
TreeState ResolveTreeState(const StateOptions& options, const CLI::App& cmd);

}  // namespace niwa::cli
