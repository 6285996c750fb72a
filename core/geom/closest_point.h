// ClosestPoint: the nearest surface point within a radius, through the BVH (ivy's node-to-face
// distance and anchors, moss attachment). Does not: give signed distances or inside/outside (the
// distance is unsigned, so open meshes work), or search beyond max_distance.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "geom/bvh.h"
#include "geom/query_stats.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

struct ClosestHit {
  bool found = false;  // some triangle is within max_distance (distance <= max_distance)
  float distance = 0;  // |p - point|, metres
  glm::vec3 point{0};  // the closest surface point
  uint32_t triangle = 0;
  glm::vec3 barycentric{0};  // weights of the triangle's corners a, b, c (sum 1)
};

// Nearest point of any triangle to p with distance <= max_distance (max_distance may be +inf).
// Ties (equal squared distance, in double) go to the lowest triangle index, so the answer equals
// ClosestPointLinear's bit for bit. A negative or NaN max_distance finds nothing.
ClosestHit ClosestPoint(const TriMesh& mesh, const Bvh& bvh, glm::vec3 p, float max_distance,
                        QueryStats* stats = nullptr);

}  // namespace niwa::geom
