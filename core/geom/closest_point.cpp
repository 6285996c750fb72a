// ClosestPoint through the BVH's 4-wide tree (detail::NearestFirstWalk): boxes farther than the
// best distance so far are pruned (ties kept, so the lowest triangle index wins as in the linear
// twin).
#include "geom/closest_point.h"

#include "geom/query_detail.h"

namespace niwa::geom {

namespace {

// ClosestState as NearestFirstWalk's query: keys are squared box distances.
struct ClosestQuery {
  detail::ClosestState state;
  DVec3 p;
  double Bound() const { return state.best_d2; }
  bool Key(const Bounds3& box, double* key) const {
    *key = detail::BoxDistanceSquared(box, p);
    return *key <= state.best_d2;
  }
  int Keys(const BvhWideNode& n, int slots, double keys[4]) const {
    int kept = 0;
    for (int i = 0; i < slots; ++i)
      if (Key(n.ChildBounds(i), &keys[i])) kept |= 1 << i;
    return kept;
  }
  void Test(const glm::vec3* abc, uint32_t t) { state.Test(abc, p, t); }
};

}  // namespace

ClosestHit ClosestPoint(const TriMesh& mesh, const Bvh& bvh, glm::vec3 p, float max_distance,
                        QueryStats* stats) {
  if (stats) ++stats->queries;
  ClosestQuery query{detail::ClosestState(detail::MaxDistanceSquared(max_distance)), ToD(p)};
  if (query.state.best_d2 < 0.0 || bvh.empty() || bvh.triangle_count() != mesh.triangle_count())
    return {};
  uint64_t visited = 1, tested = 0;
  double root_d2 = detail::BoxDistanceSquared(bvh.nodes()[0].bounds, query.p);
  if (root_d2 <= query.state.best_d2)
    detail::NearestFirstWalk(bvh, root_d2, query, &visited, &tested);
  if (stats) {
    stats->nodes_visited += visited;
    stats->triangles_tested += tested;
  }
  return query.state.Result();
}

}  // namespace niwa::geom
