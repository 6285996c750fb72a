// The moss run on the land its state names (see moss_land.h).
#include "compose/moss_land.h"

#include <utility>

#include "compose/moss_on_terrain.h"
#include "compose/moss_on_tree.h"

namespace niwa::compose {

Result<moss::MossRun> StartMossOnLand(const moss::MossState& state, const Budget& budget,
                                      const run::FieldNames& words, std::string* truncated_by) {
  if (truncated_by != nullptr) truncated_by->clear();
  Result<moss::MossScene> land = Status::Error("scene", "no land");
  if (state.scene == moss::kTreeLand) {
    std::string years_name = "tree_years";
    for (const auto& [field, word] : words)
      if (field == "tree_years") years_name = word;
    land = MossTreeLand(state.tree, state.tree_years, budget, years_name, truncated_by);
  } else if (state.scene == moss::kTerrainLand) {
    land = MossTerrainLand(state.terrain, static_cast<double>(state.terrain_seed), budget,
                           truncated_by);
  } else {
    return moss::MossRun::Start(state, budget);
  }
  if (!land.ok()) return land.status();
  return moss::MossRun::StartOnScene(state, std::move(land).value(), budget, "");
}

}  // namespace niwa::compose
