// Bounds3: an axis-aligned box (min/max corners) over points and boxes, for mesh bounds and BVH
// nodes. Does not: know meshes, transform boxes, or pad itself (bvh.cpp pads its node boxes).
#pragma once

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace niwa::geom {

struct Bounds3 {
  // Empty box: min = +inf, max = -inf, so the first Extend sets both.
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
  void Extend(const glm::vec3& p) {
    min = glm::vec3(std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z));
    max = glm::vec3(std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z));
  }
  void Extend(const Bounds3& b) {
    if (b.empty()) return;
    Extend(b.min);
    Extend(b.max);
  }
  // Centre and diagonal (max - min); both are zero for an empty box.
  glm::vec3 centre() const { return empty() ? glm::vec3(0.0f) : (min + max) * 0.5f; }
  glm::vec3 diagonal() const { return empty() ? glm::vec3(0.0f) : max - min; }
  // Surface area of the box (the SAH cost of a node), 0 when empty.
  float SurfaceArea() const {
    glm::vec3 d = diagonal();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  bool Contains(const glm::vec3& p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
           p.z <= max.z;
  }
};

}  // namespace niwa::geom
