// Small vector helpers for growth geometry: rotation about an axis and towards a target direction.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "math/det_math.h"
#include "math/simd4.h"

namespace niwa {

constexpr float kPi = 3.14159265358979323846f;
inline float Radians(float degrees) { return degrees * (kPi / 180.0f); }

// v / s, the three quotients in one SIMD division where there is one (SSE2, WASM simd128): each
// lane is the same correctly rounded IEEE division as the scalar v.x / s, so results are identical;
// it only saves the divider's time, which bounds much of the growth geometry.
inline glm::vec3 Divide(const glm::vec3& v, float s) {
#if NIWA_SIMD
  simd::Float4 a = {v.x, v.y, v.z, 1.0f};
  simd::Float4 q = a / simd::Splat4(s);
  return glm::vec3(q[0], q[1], q[2]);
#else
  return v / s;
#endif
}

// Rodrigues rotation of v about the unit axis by the angle whose cosine and sine are c and s.
inline glm::vec3 RotateAbout(const glm::vec3& v, const glm::vec3& axis, float c, float s) {
  return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (1.0f - c));
}

// The same on four lanes (one vec3 each), lane by lane the scalar's operations in its order.
inline simd::Vec3x4 RotateAbout(const simd::Vec3x4& v, const simd::Vec3x4& axis, simd::Float4 c,
                                simd::Float4 s) {
  const simd::Vec3x4 turned = simd::Cross(axis, v);
  const simd::Float4 along = simd::Dot(axis, v) * (1.0f - c);
  return simd::Vec3x4{(v.x * c + turned.x * s) + axis.x * along,
                      (v.y * c + turned.y * s) + axis.y * along,
                      (v.z * c + turned.z * s) + axis.z * along};
}

// Rodrigues rotation of v about the unit axis by angle (radians).
inline glm::vec3 RotateAbout(const glm::vec3& v, const glm::vec3& axis, float angle) {
  return RotateAbout(v, axis, det::Cosf(angle), det::Sinf(angle));
}

// Unit vector perpendicular to unit v, stable for every v.
inline glm::vec3 AnyPerpendicular(const glm::vec3& v) {
  glm::vec3 other = std::fabs(v.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(v, other));
}

// Angle in radians between unit vectors (thesis eqs. 2.6, 2.8).
inline float AngleBetween(const glm::vec3& a, const glm::vec3& b) {
  float d = glm::dot(a, b);
  d = d > 1.0f ? 1.0f : (d < -1.0f ? -1.0f : d);
  return det::Acosf(d);
}

// Rotates unit v by angle (radians) in the plane of v and unit target, towards target
// (negative angle: away from it). Returns v unchanged when the two are parallel.
inline glm::vec3 RotateToward(const glm::vec3& v, const glm::vec3& target, float angle) {
  glm::vec3 axis = glm::cross(v, target);
  float length = glm::length(axis);
  if (length < 1e-6f) return v;
  return glm::normalize(RotateAbout(v, Divide(axis, length), angle));
}

// Removes from v its component along unit n and normalizes; fallback when degenerate.
inline glm::vec3 Orthonormalize(const glm::vec3& v, const glm::vec3& n) {
  glm::vec3 p = v - n * glm::dot(v, n);
  float length = glm::length(p);
  return length < 1e-6f ? AnyPerpendicular(n) : Divide(p, length);
}

}  // namespace niwa
