// ClosestPoint through the BVH's 4-wide tree: depth-first, the four child boxes of a node tested
// from the node itself and entered nearest first, pruning boxes farther than the best distance so
// far (ties kept, so the lowest triangle index wins as in the linear twin).
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
  const BvhWideNode* wide = bvh.wide_nodes().data();
  const uint32_t* order = bvh.order().data();
  const glm::vec3* corners = bvh.corners().data();
  uint64_t visited = 1, tested = 0;
  detail::WideEntry stack[detail::kMaxStack];
  int top = 0;
  double root_d2 = detail::BoxDistanceSquared(bvh.nodes()[0].bounds, pd);
  if (root_d2 <= state.best_d2) stack[top++] = {0, 0, root_d2};
  while (top > 0) {
    const detail::WideEntry e = stack[--top];
    if (e.key > state.best_d2) continue;  // the best got closer since this was pushed
    if (e.count > 0) {                    // a leaf
      for (uint32_t i = e.index; i < e.index + e.count; ++i)
        state.Test(&corners[3 * static_cast<std::size_t>(i)], pd, order[i]);
      tested += e.count;
      continue;
    }
    const BvhWideNode& n = wide[e.index];
    detail::WideEntry kids[4];
    int k = 0;
    for (int i = 0; i < 4 && n.count[i] != BvhWideNode::kEmpty; ++i) {
      ++visited;
      double d2 = detail::WideBoxDistanceSquared(n, i, pd);
      if (d2 <= state.best_d2) kids[k++] = {n.child[i], n.count[i], d2};
    }
    // Push the farther first so the nearer is searched first (left first on equal distance).
    detail::SortDescending(kids, k);
    for (int i = 0; i < k; ++i) {
      detail::Prefetch(kids[i], wide, corners);
      stack[top++] = kids[i];
    }
  }
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return state.Result();
}

}  // namespace niwa::geom
