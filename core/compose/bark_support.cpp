// A grown tree's bark as a climbing support (see bark_support.h).
#include "compose/bark_support.h"

#include <limits>

#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "params/param_text.h"
#include "tree/growth.h"
#include "tree/tree_budget.h"
#include "tree/tree_state.h"

namespace niwa::compose {
namespace {

// The bark as a TriMesh (a position and a normal, 24 bytes a vertex, 12 of indices a triangle)
// and the BVH built on it for the seed (64 bytes a triangle, measured for the ivy's support in
// docs/budgets.md), while the tree and its TreeMesh are still held; 3 µs a triangle to copy and
// build (the ivy support's constant).
constexpr double kTriMeshBytesPerVertex = 24, kTriMeshBytesPerTriangle = 12 + 64;
constexpr double kNsPerBarkTriangle = 3000;
// Per alive internode, for the growth's check: a typical tube of 6 sides (7 ring vertices, 12
// triangles), as MeshBytesPerInternode counts the TreeMesh.
constexpr double kBarkVerticesPerInternode = 7, kBarkTrianglesPerInternode = 12;

}  // namespace

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

Result<BarkSupport> GrowBarkSupport(const std::string& preset, double years,
                                    const BarkBudget* budget, const BarkProgress& on_stage) {
  TreeState state;
  Status s = SetStatePreset(preset, &state);
  if (!s.ok()) return Status::Error("tree", s.message());
  s = CheckValue("tree_years", years, 1, kMaxYears, true);
  if (!s.ok()) return s;
  s = SetStateYears(years, &state);
  if (!s.ok()) return Status::Error("tree_years", s.message());
  if (budget != nullptr) {
    state.limits = TreeGrowLimits(state.params, budget->budget, budget->years_name);
    state.limits.bytes_per_alive_internode = MeshBytesPerInternode(state.params) +
                                             kTriMeshBytesPerVertex * kBarkVerticesPerInternode +
                                             kTriMeshBytesPerTriangle * kBarkTrianglesPerInternode;
  }
  Grower grower(state);
  while (grower.year() < state.years && !grower.stopped()) {
    grower.GrowYear();
    if (on_stage) on_stage("tree", grower.year(), state.years);
  }
  BarkSupport out;
  out.estimate = grower.estimate();
  const Tree tree = grower.TakeTree();
  out.truncated_by = tree.truncated_by;
  {
    // The bark's exact size, checked before the mesh is built (kMesh: every part of the TreeMesh
    // held at once), then its TriMesh and BVH.
    const TreeCounts counts = CountTree(tree);
    Estimate bark = EstimateTreeExport(counts, TreeExport::kMesh);
    const double triangles = counts.bark_indices / 3;
    bark.memory_bytes +=
        kTriMeshBytesPerVertex * counts.bark_vertices + kTriMeshBytesPerTriangle * triangles;
    bark.seconds += kNsPerBarkTriangle * 1e-9 * triangles;
    bark.what = "building its bark (" + FormatCount(counts.internodes) + " internodes, " +
                FormatCount(triangles) + " triangles)";
    out.estimate.what = "growing the " + preset + " tree (" + std::to_string(tree.years) + " of " +
                        FormatNumber(years) + " years)";
    out.estimate = out.estimate + bark;
    if (budget != nullptr) {
      s = CheckEstimate(out.estimate, budget->budget, "lower " + budget->years_name);
      if (!s.ok()) return s;
    }
  }
  if (on_stage) on_stage("bark", 0, static_cast<double>(CountTree(tree).internodes));
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

}  // namespace niwa::compose
