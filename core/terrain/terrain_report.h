// The terrain's stats object, shared by `niwa terrain grow --stats` and the page's statsJson.
// Does not: time anything (the CLI adds its ms* fields, the page keeps timings apart).
#pragma once

#include <nlohmann/json.hpp>

#include "terrain/heightfield.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {

// method, seed, the TerrainStats counts and measures, the generator's counts, res, cells and url.
nlohmann::json TerrainStatsJson(const TerrainState& state, const Terrain& terrain,
                                const Heightfield& hf, const TerrainStats& s);

}  // namespace niwa::terrain
