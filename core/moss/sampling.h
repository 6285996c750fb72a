// The moss study's direction sampling: eq 3.1's cosine-weighted direction about a normal (the sun
// light's emission and every diffuse bounce), an orthonormal basis about a unit vector, and the
// Hammersley points of the sky view. Deterministic math only (det_math); draws from the
// project's Pcg32. Does not: trace rays (photons.h), know a mesh or a light.
#pragma once

#include <glm/vec3.hpp>

#include "random/pcg32.h"

namespace niwa::moss {

// Two unit vectors b1, b2 with (b1, b2, n) right-handed and orthonormal, n unit (Duff et al.,
// "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017).
void BasisAbout(const glm::dvec3& n, glm::dvec3* b1, glm::dvec3* b2);

// Eq 3.1: w_d = (arccos(√ξ_1), 2πξ_2), the polar angle to the unit normal n and the rotation about
// it: a cosine-weighted direction on n's side.
glm::dvec3 CosineDirection(const glm::dvec3& n, double xi_1, double xi_2);
// The same from two draws of `rng` (ξ_1 first).
glm::dvec3 CosineDirection(const glm::dvec3& n, Pcg32* rng);

// The i-th of `count` Hammersley points: ((i + 0.5)/count, the base-2 radical inverse of i).
void Hammersley(int i, int count, double* u, double* v);

}  // namespace niwa::moss
