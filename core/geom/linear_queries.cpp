// Brute-force twins of ClosestPoint, FirstHit and SegmentHits: every triangle in index order.
#include "geom/linear_queries.h"

#include "geom/query_detail.h"

namespace niwa::geom {

ClosestHit ClosestPointLinear(const TriMesh& mesh, glm::vec3 p, float max_distance,
                              QueryStats* stats) {
  if (stats) ++stats->queries;
  detail::ClosestState state(detail::MaxDistanceSquared(max_distance));
  if (state.best_d2 < 0.0) return {};
  const DVec3 pd = ToD(p);
  const uint32_t tris = static_cast<uint32_t>(mesh.triangle_count());
  for (uint32_t t = 0; t < tris; ++t) state.Test(detail::MeshCorners(mesh, t).v, pd, t);
  if (stats) stats->triangles_tested += tris;
  return state.Result();
}

RayHit FirstHitLinear(const TriMesh& mesh, glm::vec3 origin, glm::vec3 dir, float max_distance,
                      QueryStats* stats) {
  if (stats) ++stats->queries;
  if (!(max_distance >= 0.0f)) return {};
  detail::PreparedRay ray = detail::PrepareRay(origin, dir, /*normalize=*/true);
  if (!ray.valid) return {};
  detail::RayState state(static_cast<double>(max_distance));
  const uint32_t tris = static_cast<uint32_t>(mesh.triangle_count());
  for (uint32_t t = 0; t < tris; ++t) state.Test(detail::MeshCorners(mesh, t).v, ray, t);
  if (stats) stats->triangles_tested += tris;
  return state.Result(mesh, ray);
}

bool SegmentHitsLinear(const TriMesh& mesh, glm::vec3 a, glm::vec3 b, QueryStats* stats) {
  if (stats) ++stats->queries;
  detail::PreparedRay seg = detail::PrepareRay(a, b - a, /*normalize=*/false);
  if (!seg.valid) return false;
  const uint32_t tris = static_cast<uint32_t>(mesh.triangle_count());
  for (uint32_t t = 0; t < tris; ++t) {
    if (stats) ++stats->triangles_tested;
    if (detail::SegmentTriangle(detail::MeshCorners(mesh, t).v, seg)) return true;
  }
  return false;
}

}  // namespace niwa::geom
