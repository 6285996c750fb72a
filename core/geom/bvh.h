// Bvh: a deterministic bounding volume hierarchy over a TriMesh's triangles (binned SAH, flat node
// array), the accelerator under closest_point, ray_cast and their users (ivy adhesion and
// collisions, moss photons). Does not: answer queries (closest_point.h, ray_cast.h do), refit or
// update after the mesh changes (build again), or own the mesh.
//
// Why no library (apt-cache, 2026-12-01; none of these is installed here, none was built):
// libembree-dev (Embree 3: compiled x86 SIMD kernels, no Emscripten build), libbullet-dev
// (compiled .so; btDbvt is a dynamic AABB tree) and libcgal-dev 5.5.1 (AABB_tree is header-only
// but needs the Boost headers, and GMP unless CGAL_DISABLE_GMP; not tried under em++ 3.1.6).
// `apt-cache search bvh` finds no BVH library. Beyond the build, the callers need what none of them
// gives: the very per-triangle routine and lowest-index tie rule of the brute-force twins (same
// triangle, same distance bits), segment any-hit with a stated edge epsilon, and visit counts
// (QueryStats). So this is a small one, checked against linear_queries.h on every test mesh.
//
// Build: centroids binned along the widest axis (Wald 2007), SAH cost N_L·A_L + N_R·A_R per bin
// boundary, leaves of at most max_leaf_triangles.
//
// Determinism: the build is single-threaded, in a fixed order (recursive, left child first),
// with float bounds and double SAH costs; ties between split candidates go to the lowest axis and
// bin. Same mesh, same options: the same nodes, bit for bit, on every build.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geom/bounds.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

struct BvhOptions {
  int bins = 16;               // SAH bins per axis, clamped to [2, 64]
  int max_leaf_triangles = 4;  // a node with at most this many triangles stays a leaf; [1, 16]
  bool all_axes = false;       // SAH over all three axes, not only the widest (slower build)
};

// One node, 32 bytes. A leaf (count > 0) holds triangles order[first .. first + count); an inner
// node (count == 0) has children first and first + 1 (allocated as a pair).
struct BvhNode {
  Bounds3 bounds;  // padded a few ulps outward so rounding in the queries never misses a triangle
  uint32_t first = 0;
  uint32_t count = 0;
  bool is_leaf() const { return count > 0; }
};

class Bvh {
 public:
  Bvh() = default;
  // Builds over every triangle of `mesh` (which should pass ValidateMesh; queries must pass the
  // same, unchanged mesh; a mesh with no triangles gives an empty tree that every query misses).
  // Degenerate triangles are kept (they never win a query the linear twins would not also give
  // them).
  static Bvh Build(const TriMesh& mesh, const BvhOptions& options = {});

  int node_count() const { return static_cast<int>(nodes_.size()); }
  int depth() const { return depth_; }  // levels; 1 for a single leaf, 0 when empty
  std::size_t triangle_count() const { return order_.size(); }
  bool empty() const { return nodes_.empty(); }

  // Root is node 0.
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  // Triangle indices in leaf order.
  const std::vector<uint32_t>& order() const { return order_; }
  // The corners of order()[i] at 3i, 3i+1, 3i+2: a copy of the mesh's positions in leaf order, so a
  // leaf's triangles are read from one run of memory (36 bytes per triangle).
  const std::vector<glm::vec3>& corners() const { return corners_; }

 private:
  friend struct BvhTestAccess;  // tests break a node on purpose to see the oracle tests fail
  std::vector<BvhNode> nodes_;
  std::vector<uint32_t> order_;
  std::vector<glm::vec3> corners_;
  int depth_ = 0;
};

}  // namespace niwa::geom
