// TerrainStatsJson: the one list of the terrain's stats keys.
#include "terrain/terrain_report.h"

#include <cmath>
#include <cstdint>

#include "terrain/level_measures.h"
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
  // Per level (issue 31 item 2, the spec's §3 measures; level_measures.h); NaN (no level below,
  // too short a ring for two divider steps) is null.
  const auto number = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
  };
  nlohmann::json per_level = nlohmann::json::array();
  for (const LevelMeasures& m : ComputeLevelMeasures(terrain)) {
    per_level.push_back({{"level", m.level},
                         {"elevation", m.elevation},
                         {"rings", m.rings},
                         {"vertices", m.vertices},
                         {"area", m.area},
                         {"perimeter", m.perimeter},
                         {"area_ratio", number(m.area_ratio)},
                         {"compactness", m.compactness},
                         {"long_edge_share", m.long_edge_share},
                         {"fractal_dimension", number(m.fractal_dimension)}});
  }
  j["per_level"] = per_level;
  j["res"] = params.GetInt(TerrainParam::kRes);
  j["cells"] = hf.h.size();
  j["url"] = EncodeTerrainHash(state);
  return j;
}

nlohmann::json ErosionJson(const ErosionReport& r) {
  const auto drainage = [](const DrainageMeasure& m) {
    return nlohmann::json{{"channel_threshold", m.threshold},
                          {"channel_share", m.channel_share},
                          {"max_accumulation", m.max_accumulation},
                          {"mean_accumulation", m.mean_accumulation}};
  };
  nlohmann::json j;
  j["volume_moved"] = r.volume_moved;
  j["max_cut"] = r.max_cut;
  j["max_deposit"] = r.max_deposit;
  j["volume_laid"] = r.volume_laid;
  j["volume_exported"] = r.volume_exported;  // m³ that left at the grid's edge
  // Σh after + exported − before (m): rounding only.
  j["volume_change"] = r.sum_after + r.exported - r.sum_before;
  j["pits_before"] = r.pits_before;
  j["pits_after"] = r.pits_after;
  j["pits_levelled"] = r.pits_levelled;
  j["drainage_before"] = drainage(r.drainage_before);
  j["drainage_after"] = drainage(r.drainage_after);
  return j;
}

}  // namespace niwa::terrain
