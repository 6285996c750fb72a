// FirstHit and SegmentHits through the BVH's 4-wide tree: depth-first, a node's four child boxes
// slab-tested from the node, nearer entry first; a box entered beyond the best hit so far is
// skipped (ties kept for the lowest triangle index). FirstHit's oblique rays key the boxes in
// float lanes with outward margins (WideRayKeysConservative: more boxes kept, never fewer, so the
// same hit; from Bvh::wide_boxes() when the tree has them decoded, the same keys without the
// bytes' decode); other rays and SegmentHits use the exact double slab test.
#include "geom/ray_cast.h"

#include "geom/query_detail.h"

namespace niwa::geom {

namespace {

// RayState as NearestFirstWalk's query: keys are slab entry distances along the ray (RayBox's,
// four children at once: detail::WideRayKeys).
// An oblique ray of tame size takes the float lanes' conservative keys (the same first hit, see
// WideRayKeysConservative); any other the exact ones.
struct FirstHitQuery {
  detail::RayState state;
  detail::PreparedRay ray;
  detail::FloatSlabRay float_ray;
  const BvhWideNode* wide;    // bvh.wide_nodes()
  const BvhWideBoxes* boxes;  // bvh.wide_boxes(), or null when not decoded
  double Bound() const { return state.best_t; }
  int Keys(const BvhWideNode& n, int /*slots*/, double keys[4]) const {
    if (float_ray.usable) {
      if (boxes != nullptr)
        return detail::WideRayKeysConservativeDecoded(boxes[&n - wide], float_ray, state.best_t,
                                                      keys);
      return detail::WideRayKeysConservative(n, float_ray, state.best_t, keys);
    }
    return detail::WideRayKeys(n, ray, state.best_t, keys);
  }
  void Test(const glm::vec3* abc, uint32_t t) { state.Test(abc, ray, t); }
};

RayHit FirstHitOf(const TriMesh& mesh, const Bvh& bvh, glm::vec3 origin, glm::vec3 dir,
                  float max_distance, QueryStats* stats, bool normal) {
  if (stats) ++stats->queries;
  if (!(max_distance >= 0.0f) || bvh.empty() || bvh.triangle_count() != mesh.triangle_count())
    return {};
  const detail::PreparedRay ray = detail::PrepareRay(origin, dir, /*normalize=*/true);
  if (!ray.valid) return {};
  FirstHitQuery query{detail::RayState(static_cast<double>(max_distance)), ray,
                      detail::PrepareFloatSlabRay(ray, origin, bvh.nodes()[0].bounds),
                      bvh.wide_nodes().data(),
                      bvh.wide_boxes().empty() ? nullptr : bvh.wide_boxes().data()};
  uint64_t visited = 1, tested = 0;
  double t0;
  if (detail::RayBox(bvh.nodes()[0].bounds, query.ray, query.state.best_t, &t0))
    detail::NearestFirstWalk(bvh, t0, query, &visited, &tested);
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return query.state.Result(mesh, query.ray, normal);
}

}  // namespace

RayHit FirstHit(const TriMesh& mesh, const Bvh& bvh, glm::vec3 origin, glm::vec3 dir,
                float max_distance, QueryStats* stats) {
  return FirstHitOf(mesh, bvh, origin, dir, max_distance, stats, true);
}

RayHit FirstHitWithoutNormal(const TriMesh& mesh, const Bvh& bvh, glm::vec3 origin, glm::vec3 dir,
                             float max_distance, QueryStats* stats) {
  return FirstHitOf(mesh, bvh, origin, dir, max_distance, stats, false);
}

bool SegmentHits(const TriMesh& mesh, const Bvh& bvh, glm::vec3 a, glm::vec3 b, QueryStats* stats) {
  if (stats) ++stats->queries;
  if (bvh.empty() || bvh.triangle_count() != mesh.triangle_count()) return false;
  detail::PreparedRay seg = detail::PrepareRay(a, b - a, /*normalize=*/false);
  if (!seg.valid) return false;
  const BvhWideNode* wide = bvh.wide_nodes().data();
  const glm::vec3* corners = bvh.corners().data();
  uint64_t visited = 1, tested = 0;
  detail::WideEntry stack[detail::kMaxStack];
  int top = 0;
  double t_near;
  bool hit = false;
  if (detail::RayBox(bvh.nodes()[0].bounds, seg, 1.0, &t_near)) stack[top++] = {0, 0, 0.0};
  while (top > 0 && !hit) {
    const detail::WideEntry e = stack[--top];
    if (e.count > 0) {  // a leaf
      for (uint32_t i = e.index; i < e.index + e.count && !hit; ++i) {
        ++tested;
        hit = detail::SegmentTriangle(&corners[3 * static_cast<std::size_t>(i)], seg);
      }
      continue;
    }
    const BvhWideNode& n = wide[e.index];
    for (int i = 3; i >= 0; --i) {  // left child on top
      if (n.count[i] == BvhWideNode::kEmpty) continue;
      ++visited;
      if (detail::RayBox(n.ChildBounds(i), seg, 1.0, &t_near)) {
        const detail::WideEntry c{n.child[i], n.count[i], 0.0};
        detail::Prefetch(c, wide, corners);
        stack[top++] = c;
      }
    }
  }
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return hit;
}

}  // namespace niwa::geom
