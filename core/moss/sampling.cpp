// The moss study's direction sampling (sampling.h).
#include "moss/sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "math/det_math.h"

namespace niwa::moss {

void BasisAbout(const glm::dvec3& n, glm::dvec3* b1, glm::dvec3* b2) {
  const double sign = n.z >= 0.0 ? 1.0 : -1.0;
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  *b1 = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  *b2 = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
}

glm::dvec3 CosineDirection(const glm::dvec3& n, double xi_1, double xi_2) {
  // moss eq. 3.1: polar angle arccos(√ξ_1), so cos θ = √ξ_1 and sin θ = √(1 − ξ_1).
  const double cos_theta = std::sqrt(xi_1);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - xi_1));
  double sin_phi = 0, cos_phi = 1;
  det::SinCos(2.0 * det::kPi * xi_2, &sin_phi, &cos_phi);
  glm::dvec3 b1, b2;
  BasisAbout(n, &b1, &b2);
  return (sin_theta * cos_phi) * b1 + (sin_theta * sin_phi) * b2 + cos_theta * n;
}

glm::dvec3 CosineDirection(const glm::dvec3& n, Pcg32* rng) {
  const double xi_1 = rng->Uniform();
  const double xi_2 = rng->Uniform();
  return CosineDirection(n, xi_1, xi_2);
}

void Hammersley(int i, int count, double* u, double* v) {
  *u = (i + 0.5) / count;
  uint32_t bits = static_cast<uint32_t>(i);
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  *v = static_cast<double>(bits) * (1.0 / 4294967296.0);
}

}  // namespace niwa::moss
