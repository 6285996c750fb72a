// Surface sampling: seeded, area-weighted random points on a mesh (moss seeds and spores, photon
// emitters, ivy seed placement), optionally Poisson-disk by rejection. Does not: sample volumes,
// weight by anything but area, or use any generator but Pcg32.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "geom/tri_mesh.h"

namespace niwa::geom {

struct SurfaceSample {
  glm::vec3 point{0};
  uint32_t triangle = 0;
  glm::vec3 normal{0};       // unit geometric normal of the triangle (from its winding)
  glm::vec3 barycentric{0};  // weights of a, b, c
};

// `count` points (clamped to >= 0), triangle chosen with probability area / total area (degenerate
// triangles never), uniform within it (u1, u2 → sqrt warp, Turk 1990 / Osada et al. 2002 eq. 1).
// Same mesh, count and seed: the same points on every build. Empty when the mesh has no area.
std::vector<SurfaceSample> SampleSurface(const TriMesh& mesh, int count, uint64_t seed);

// Poisson-disk by rejection (dart throwing): area-weighted candidates as SampleSurface, kept only
// when no kept point is closer than min_distance (Euclidean, in 3-D); stops at `count` points or
// after max_attempts candidates. Deterministic as SampleSurface.
std::vector<SurfaceSample> SamplePoissonDisk(const TriMesh& mesh, int count, float min_distance,
                                             uint64_t seed, int max_attempts = 100000);

}  // namespace niwa::geom
