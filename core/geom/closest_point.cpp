// ClosestPoint through the BVH: depth-first, nearer child first, pruning boxes farther than the
// best distance so far (ties kept, so the lowest triangle index wins as in the linear twin).
#include "geom/closest_point.h"

#include "geom/query_detail.h"

namespace niwa::geom {

ClosestHit ClosestPoint(const TriMesh& mesh, const Bvh& bvh, glm::vec3 p, float max_distance,
                        QueryStats* stats) {
  if (stats) ++stats->queries;
  detail::ClosestState state(detail::MaxDistanceSquared(max_distance));
  if (state.best_d2 < 0.0 || bvh.empty() || bvh.triangle_count() != mesh.triangle_count())
    return {};
  const DVec3 pd = ToD(p);
  const std::vector<BvhNode>& nodes = bvh.nodes();
  const std::vector<uint32_t>& order = bvh.order();
  const std::vector<glm::vec3>& corners = bvh.corners();
  uint64_t visited = 1, tested = 0;
  struct Entry {
    uint32_t node;
    double d2;
  };
  Entry stack[detail::kMaxStack];
  int top = 0;
  double root_d2 = detail::BoxDistanceSquared(nodes[0].bounds, pd);
  if (root_d2 <= state.best_d2) stack[top++] = {0, root_d2};
  while (top > 0) {
    Entry e = stack[--top];
    if (e.d2 > state.best_d2) continue;  // the best got closer since this was pushed
    const BvhNode& n = nodes[e.node];
    if (n.is_leaf()) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i)
        state.Test(&corners[3 * static_cast<std::size_t>(i)], pd, order[i]);
      tested += n.count;
      continue;
    }
    uint32_t l = n.first, r = n.first + 1;
    double dl = detail::BoxDistanceSquared(nodes[l].bounds, pd);
    double dr = detail::BoxDistanceSquared(nodes[r].bounds, pd);
    visited += 2;
    // Push the farther first so the nearer is searched first (left first on equal distance).
    if (dl <= dr) {
      if (dr <= state.best_d2) stack[top++] = {r, dr};
      if (dl <= state.best_d2) stack[top++] = {l, dl};
    } else {
      if (dl <= state.best_d2) stack[top++] = {l, dl};
      if (dr <= state.best_d2) stack[top++] = {r, dr};
    }
  }
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return state.Result();
}

}  // namespace niwa::geom
