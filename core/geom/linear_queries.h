// Brute-force twins of the BVH queries: every triangle, in index order, through the same
// per-triangle routines (triangle_queries.h). The test oracle for closest_point/ray_cast and ivy's
// `--accel linear`. Does not: accelerate anything (O(triangles) per query).
#pragma once

#include <glm/vec3.hpp>

#include "geom/closest_point.h"
#include "geom/query_stats.h"
#include "geom/ray_cast.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

// Same contracts and the same bits as ClosestPoint, FirstHit and SegmentHits (ties: lowest
// triangle index); stats count triangles only.
ClosestHit ClosestPointLinear(const TriMesh& mesh, glm::vec3 p, float max_distance,
                              QueryStats* stats = nullptr);
RayHit FirstHitLinear(const TriMesh& mesh, glm::vec3 origin, glm::vec3 dir, float max_distance,
                      QueryStats* stats = nullptr);
bool SegmentHitsLinear(const TriMesh& mesh, glm::vec3 a, glm::vec3 b, QueryStats* stats = nullptr);

}  // namespace niwa::geom
