// The terrain's stats object, shared by `niwa terrain grow --stats` and the page's statsJson.
// Does not: time anything (the CLI adds its ms* fields, the page keeps timings apart).
#pragma once

#include <nlohmann/json.hpp>

#include "terrain/erosion.h"
#include "terrain/heightfield.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {

// method, seed, the TerrainStats counts and measures, the generator's counts, res, cells and url.
nlohmann::json TerrainStatsJson(const TerrainState& state, const Terrain& terrain,
                                const Heightfield& hf, const TerrainStats& s);
// The erosion's measures (--stats' "erosion" object, present only while erosion is on):
// volume_moved, volume_laid, volume_exported (m³), max_cut, max_deposit (m), volume_change (Σh
// after + exported − before, m: rounding only), pits_before, pits_after, pits_levelled and the
// drainage measures before and after (erosion.h).
nlohmann::json ErosionJson(const ErosionReport& r);

}  // namespace niwa::terrain
