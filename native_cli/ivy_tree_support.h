// `niwa ivy grow --tree-preset NAME --tree-years N`: a Niwa tree (core/tree) as an ivy support, so
// ivy climbs its trunk and branches. The CLI is where the two studies meet: core/ivy never includes
// core/tree; it gets the bark as a plain geom::TriMesh in metres. Header-only (used by
// ivy_commands.cpp alone). Does not: add leaves or flowers to the support (ivy climbs bark only).
#pragma once

#include <glm/geometric.hpp>
#include <limits>
#include <string>

#include "base/status.h"
#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/mesh_metrics.h"
#include "geom/tri_mesh.h"
#include "ivy/scenes.h"
#include "params/param_text.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/tree_state.h"

namespace niwa::cli {

// The bark of a grown tree as one TriMesh (metres, y up).
inline geom::TriMesh BarkTriMesh(const MeshBuffers& bark) {
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

// Grows tree preset `name` for `years` years (the errors name --tree-preset and --tree-years) and
// returns it as a scene whose one named seed, "trunk", is the bark point nearest to a point just
// +z of the trunk axis 5 cm above the ground: the +z side of the trunk foot.
inline Result<ivy::IvyScene> TreeSupportScene(const std::string& name, double years) {
  TreeState state;
  Status s = SetStatePreset(name, &state);
  if (!s.ok()) return Status::Error("--tree-preset", s.message());
  s = SetStateYears(years, &state);
  if (!s.ok()) return Status::Error("--tree-years", s.message());
  const Tree tree = GrowTree(state);
  ivy::IvyScene scene;
  scene.name = "tree:" + name;
  scene.description =
      "the bark of Niwa's " + name + " tree at " + FormatNumber(years) + " years (metres)";
  scene.mesh = BarkTriMesh(BuildTreeMesh(tree).bark);
  if (scene.mesh.triangle_count() == 0) {
    return Status::Error("--tree-years",
                         FormatNumber(years) + " grows no bark to climb; must be at least 1");
  }
  const geom::Bvh bvh = geom::Bvh::Build(scene.mesh);
  geom::ClosestHit hit = geom::ClosestPoint(scene.mesh, bvh, glm::vec3(0.0f, 0.05f, 0.001f),
                                            std::numeric_limits<float>::infinity());
  scene.seeds.push_back({"trunk", glm::dvec3(hit.point)});
  return scene;
}

}  // namespace niwa::cli
