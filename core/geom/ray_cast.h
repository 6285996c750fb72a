// Ray casts through the BVH: the first hit of a ray within a max distance (moss photons, soil
// depth), and segment any-hit: does segment a→b cross any face (ivy: "an internode never passes
// through a face"). Does not: cull back faces (both sides count), return every hit, or offset
// origins off a surface (callers step off by their own epsilon to avoid re-hitting a start face).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "geom/bvh.h"
#include "geom/query_stats.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

struct RayHit {
  bool hit = false;
  float distance = 0;  // along the unit ray direction, metres
  glm::vec3 point{0};  // origin + distance · unit(dir)
  uint32_t triangle = 0;
  glm::vec3 barycentric{0};  // weights of a, b, c
  glm::vec3 normal{0};       // unit geometric normal of the triangle (from its winding)
};

// First triangle hit by origin + t·unit(dir), t in [0, max_distance] (max_distance may be +inf).
// Ties (equal t, in double) go to the lowest triangle index, as FirstHitLinear. A zero or
// non-finite dir, or a negative/NaN max_distance, hits nothing. Epsilons: triangle_queries.h.
RayHit FirstHit(const TriMesh& mesh, const Bvh& bvh, glm::vec3 origin, glm::vec3 dir,
                float max_distance, QueryStats* stats = nullptr);

// FirstHit without the normal (left zero): the same hit, distance, point, triangle and
// barycentrics, without reading the winning triangle's corners from the mesh again (callers that
// keep their own per-triangle normals: the moss photons).
RayHit FirstHitWithoutNormal(const TriMesh& mesh, const Bvh& bvh, glm::vec3 origin, glm::vec3 dir,
                             float max_distance, QueryStats* stats = nullptr);

// Does the closed segment a→b touch any triangle (a + t (b - a), t in [0, 1], edges and vertices
// included: watertight on shared edges)? a == b hits nothing. Stops at the first hit found.
bool SegmentHits(const TriMesh& mesh, const Bvh& bvh, glm::vec3 a, glm::vec3 b,
                 QueryStats* stats = nullptr);

}  // namespace niwa::geom
