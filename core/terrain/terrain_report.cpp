// TerrainStatsJson: the one list of the terrain's stats keys.
#include "terrain/terrain_report.h"

#include <cstdint>

#include "terrain/terrain_params.h"

namespace niwa::terrain {

nlohmann::json TerrainStatsJson(const TerrainState& state, const Terrain& terrain,
                                const Heightfield& hf, const TerrainStats& s) {
  const TerrainParams& params = state.params;
  nlohmann::json j;
  j["method"] = MethodName(params.GetInt(TerrainParam::kMethod));
  // A whole number in [0, 2^32 − 1]: int would not hold it.
  j["seed"] = state.seed;
  j["levels"] = s.levels;
  j["contours"] = s.contours;
  j["peaks"] = s.peaks;
  j["splits"] = s.splits;
  j["vertices"] = s.vertices;
  j["self_intersections"] = s.self_intersections;
  j["nesting_violations"] = s.nesting_violations;
  j["relief"] = s.relief;
  j["hypsometric_integral"] = s.hypsometric_integral;
  j["mean_slope_deg"] = s.mean_slope_deg;
  j["pits"] = s.pits;
  j["cells_filled"] = hf.cells_filled;
  j["slot_cells"] = hf.slot_cells;
  j["loops_removed"] = terrain.counts.loops_removed;
  j["perturbations_reverted"] = terrain.counts.perturbations_reverted;
  j["slivers_dropped"] = terrain.counts.slivers_dropped;
  j["truncated"] = terrain.counts.truncated;
  if (!terrain.counts.truncated_by.empty()) j["truncated_by"] = terrain.counts.truncated_by;
  j["res"] = params.GetInt(TerrainParam::kRes);
  j["cells"] = hf.h.size();
  j["url"] = EncodeTerrainHash(state);
  return j;
}

}  // namespace niwa::terrain
