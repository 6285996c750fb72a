// A grown tree's bark as a climbing support (see bark_support.h).
#include "tree/bark_support.h"

#include <limits>

#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "params/param_text.h"
#include "tree/growth.h"
#include "tree/tree_state.h"

namespace niwa {

geom::TriMesh BarkTriMesh(const MeshBuffers& bark) {
  geom::TriMesh mesh;
  const std::size_t n = bark.vertex_count();
  mesh.positions.reserve(n);
  mesh.normals.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    mesh.positions.emplace_back(bark.positions[3 * i], bark.positions[3 * i + 1],
                                bark.positions[3 * i + 2]);
    mesh.normals.emplace_back(bark.normals[3 * i], bark.normals[3 * i + 1],
                              bark.normals[3 * i + 2]);
  }
  mesh.indices = bark.indices;
  return mesh;
}

Result<BarkSupport> GrowBarkSupport(const std::string& preset, double years) {
  TreeState state;
  Status s = SetStatePreset(preset, &state);
  if (!s.ok()) return Status::Error("tree", s.message());
  s = CheckValue("tree_years", years, 1, kMaxYears, true);
  if (!s.ok()) return s;
  s = SetStateYears(years, &state);
  if (!s.ok()) return Status::Error("tree_years", s.message());
  const Tree tree = GrowTree(state);
  BarkSupport out;
  out.description =
      "the bark of Niwa's " + preset + " tree at " + FormatNumber(years) + " years (metres)";
  out.mesh = BarkTriMesh(BuildTreeMesh(tree).bark);
  if (out.mesh.triangle_count() == 0) {
    return Status::Error("tree_years",
                         FormatNumber(years) + " grows no bark to climb; must be at least 1");
  }
  const geom::Bvh bvh = geom::Bvh::Build(out.mesh);
  const geom::ClosestHit hit = geom::ClosestPoint(out.mesh, bvh, glm::vec3(0.0f, 0.05f, 0.001f),
                                                  std::numeric_limits<float>::infinity());
  out.trunk_seed = glm::dvec3(hit.point);
  return out;
}

}  // namespace niwa
