// Moss on a grown Niwa terrain (see moss_on_terrain.h).
#include "compose/moss_on_terrain.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <utility>

#include "math/det_math.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_run.h"
#include "terrain/terrain_state.h"

namespace niwa::compose {

Result<moss::MossScene> MossTerrainLand(const std::string& preset, double seed,
                                        const Budget& budget, std::string* truncated_by) {
  terrain::TerrainState state;
  Status s = terrain::SetTerrainPreset(preset, &state);
  if (!s.ok()) return Status::Error("terrain", s.message());
  s = terrain::SetTerrainSeed(seed, &state);
  if (!s.ok()) return Status::Error("terrain_seed", s.message());
  NIWA_RETURN_IF_ERROR(state.params.Set(terrain::TerrainParam::kRes, kMossTerrainRes));
  terrain::TerrainRunPlan plan;
  plan.outputs = {terrain::TerrainOutput::kGlb};
  Result<terrain::TerrainRun> run = terrain::TerrainRun::Start(state, budget, std::move(plan));
  if (!run.ok()) return run.status();
  NIWA_RETURN_IF_ERROR(run->Advance(nullptr));
  if (truncated_by != nullptr) *truncated_by = run->truncated_by();
  std::vector<run::Part> parts = run->Parts();
  const auto surface = std::find_if(parts.begin(), parts.end(),
                                    [](const run::Part& p) { return p.name == "terrain"; });
  if (surface == parts.end() || surface->mesh.triangle_count() == 0)
    return Status::Error("terrain", "grew no surface");
  moss::MossScene scene;
  scene.name = "terrain:" + preset;
  scene.description = "terrain " + preset + " (seed " + std::to_string(state.seed) + ", res " +
                      std::to_string(kMossTerrainRes) + ") in metres";
  scene.region_names = {"foot", "middle", "top"};
  scene.mesh.positions = std::move(surface->mesh.positions);
  scene.mesh.indices = std::move(surface->mesh.indices);
  float lo = scene.mesh.positions.empty() ? 0.0f : scene.mesh.positions[0].y, hi = lo;
  for (const glm::vec3& p : scene.mesh.positions) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
  const double relief = std::max(1e-9, static_cast<double>(hi) - lo);
  const double rock_cos = std::cos(kMossRockSlopeDeg * det::kPi / 180.0);
  const std::size_t n = scene.mesh.triangle_count();
  scene.geology.reserve(n);
  scene.region.reserve(n);
  for (std::size_t t = 0; t < n; ++t) {
    const glm::dvec3 a(scene.mesh.positions[scene.mesh.indices[3 * t]]),
        b(scene.mesh.positions[scene.mesh.indices[3 * t + 1]]),
        c(scene.mesh.positions[scene.mesh.indices[3 * t + 2]]);
    const glm::dvec3 cr = glm::cross(b - a, c - a);
    const double len = glm::length(cr);
    const double up = len > 0 ? cr.y / len : 1.0;  // cos of the slope
    const double share = ((a.y + b.y + c.y) / 3.0 - lo) / relief;
    scene.geology.push_back(up < rock_cos              ? moss::Geology::kAsphalt
                            : share > kMossUplandShare ? moss::Geology::kSandy
                                                       : moss::Geology::kHumus);
    scene.region.push_back(share > 2.0 / 3.0 ? 2 : share > 1.0 / 3.0 ? 1 : 0);
  }
  scene.mesh.normals.clear();
  scene.mesh.uvs.clear();
  scene.mesh.attributes.clear();
  return scene;
}

}  // namespace niwa::compose
