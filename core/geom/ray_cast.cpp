// FirstHit and SegmentHits through the BVH: depth-first, nearer child (by slab entry) first; a box
// entered beyond the best hit so far is skipped (ties kept for the lowest triangle index).
#include "geom/ray_cast.h"

#include "geom/query_detail.h"

namespace niwa::geom {

RayHit FirstHit(const TriMesh& mesh, const Bvh& bvh, glm::vec3 origin, glm::vec3 dir,
                float max_distance, QueryStats* stats) {
  if (stats) ++stats->queries;
  if (!(max_distance >= 0.0f) || bvh.empty() || bvh.triangle_count() != mesh.triangle_count())
    return {};
  detail::PreparedRay ray = detail::PrepareRay(origin, dir, /*normalize=*/true);
  if (!ray.valid) return {};
  detail::RayState state(static_cast<double>(max_distance));
  const std::vector<BvhNode>& nodes = bvh.nodes();
  const std::vector<uint32_t>& order = bvh.order();
  const std::vector<glm::vec3>& corners = bvh.corners();
  uint64_t visited = 1, tested = 0;
  struct Entry {
    uint32_t node;
    double t_near;
  };
  Entry stack[detail::kMaxStack];
  int top = 0;
  double t0;
  if (detail::RayBox(nodes[0].bounds, ray, state.best_t, &t0)) stack[top++] = {0, t0};
  while (top > 0) {
    Entry e = stack[--top];
    if (e.t_near > state.best_t) continue;
    const BvhNode& n = nodes[e.node];
    if (n.is_leaf()) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i)
        state.Test(&corners[3 * static_cast<std::size_t>(i)], ray, order[i]);
      tested += n.count;
      continue;
    }
    uint32_t l = n.first, r = n.first + 1;
    double tl = 0, tr = 0;
    bool hl = detail::RayBox(nodes[l].bounds, ray, state.best_t, &tl);
    bool hr = detail::RayBox(nodes[r].bounds, ray, state.best_t, &tr);
    visited += 2;
    if (hl && hr) {
      if (tl <= tr) {
        stack[top++] = {r, tr};
        stack[top++] = {l, tl};
      } else {
        stack[top++] = {l, tl};
        stack[top++] = {r, tr};
      }
    } else if (hl) {
      stack[top++] = {l, tl};
    } else if (hr) {
      stack[top++] = {r, tr};
    }
  }
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return state.Result(mesh, ray);
}

bool SegmentHits(const TriMesh& mesh, const Bvh& bvh, glm::vec3 a, glm::vec3 b, QueryStats* stats) {
  if (stats) ++stats->queries;
  if (bvh.empty() || bvh.triangle_count() != mesh.triangle_count()) return false;
  detail::PreparedRay seg = detail::PrepareRay(a, b - a, /*normalize=*/false);
  if (!seg.valid) return false;
  const std::vector<BvhNode>& nodes = bvh.nodes();
  const std::vector<glm::vec3>& corners = bvh.corners();
  uint64_t visited = 1, tested = 0;
  uint32_t stack[detail::kMaxStack];
  int top = 0;
  double t_near;
  bool hit = false;
  if (detail::RayBox(nodes[0].bounds, seg, 1.0, &t_near)) stack[top++] = 0;
  while (top > 0 && !hit) {
    const BvhNode& n = nodes[stack[--top]];
    if (n.is_leaf()) {
      for (uint32_t i = n.first; i < n.first + n.count && !hit; ++i) {
        ++tested;
        hit = detail::SegmentTriangle(&corners[3 * static_cast<std::size_t>(i)], seg);
      }
      continue;
    }
    visited += 2;
    if (detail::RayBox(nodes[n.first + 1].bounds, seg, 1.0, &t_near)) stack[top++] = n.first + 1;
    if (detail::RayBox(nodes[n.first].bounds, seg, 1.0, &t_near)) stack[top++] = n.first;
  }
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return hit;
}

}  // namespace niwa::geom
