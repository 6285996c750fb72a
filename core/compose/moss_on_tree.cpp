// Moss on a grown Niwa tree standing on a ground slab (see moss_on_tree.h).
#include "compose/moss_on_tree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "compose/bark_support.h"

namespace niwa::compose {

Result<moss::MossScene> MossTreeLand(const std::string& preset, double years, const Budget& budget,
                                     const std::string& years_name, std::string* truncated_by) {
  BarkBudget bark_budget;
  bark_budget.budget = budget;
  bark_budget.years_name = years_name;
  Result<BarkSupport> bark = GrowBarkSupport(preset, years, &bark_budget);
  if (!bark.ok()) return bark.status();
  if (truncated_by != nullptr) *truncated_by = bark->truncated_by;
  moss::MossScene scene;
  scene.name = "tree:" + preset;
  scene.description = bark->description + " on a square of humus";
  scene.region_names = {"bark", "ground"};
  scene.mesh.positions = std::move(bark->mesh.positions);
  scene.mesh.indices = std::move(bark->mesh.indices);
  double reach = 0;
  for (const glm::vec3& p : scene.mesh.positions)
    reach = std::max(reach, std::max(std::abs(double{p.x}), std::abs(double{p.z})));
  const std::size_t bark_triangles = scene.mesh.triangle_count();
  scene.geology.assign(bark_triangles, moss::Geology::kSandy);
  scene.region.assign(bark_triangles, 0);
  const float half = static_cast<float>(std::max(kMossGroundMinHalf, reach + kMossGroundMargin));
  const uint32_t base = static_cast<uint32_t>(scene.mesh.positions.size());
  scene.mesh.positions.insert(
      scene.mesh.positions.end(),
      {{-half, 0.0f, -half}, {half, 0.0f, -half}, {half, 0.0f, half}, {-half, 0.0f, half}});
  // Counter-clockwise seen from above: normal +y.
  scene.mesh.indices.insert(scene.mesh.indices.end(),
                            {base, base + 3, base + 2, base, base + 2, base + 1});
  scene.geology.insert(scene.geology.end(), 2, moss::Geology::kHumus);
  scene.region.insert(scene.region.end(), 2, 1);
  scene.mesh.normals.clear();
  scene.mesh.uvs.clear();
  scene.mesh.attributes.clear();
  return scene;
}

}  // namespace niwa::compose
