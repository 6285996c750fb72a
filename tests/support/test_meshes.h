// Seeded test meshes and random query inputs for the geometry tests (and later ivy/moss tests): a
// random triangle soup, a thin/degenerate-heavy mesh, and Pcg32 points and directions.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "geom/bounds.h"
#include "geom/tri_mesh.h"
#include "random/pcg32.h"

namespace niwa::test {

inline float UniformF(Pcg32& rng, double lo, double hi) {
  return static_cast<float>(rng.Uniform(lo, hi));
}

// Every helper draws one number per statement: argument evaluation order differs between g++ and
// clang (em++), and the native and WASM tests must see the same inputs.
inline glm::vec3 RandomVec(Pcg32& rng, double lo, double hi) {
  float x = UniformF(rng, lo, hi);
  float y = UniformF(rng, lo, hi);
  float z = UniformF(rng, lo, hi);
  return glm::vec3(x, y, z);
}

inline glm::vec3 RandomPoint(Pcg32& rng, const geom::Bounds3& box) {
  float x = UniformF(rng, box.min.x, box.max.x);
  float y = UniformF(rng, box.min.y, box.max.y);
  float z = UniformF(rng, box.min.z, box.max.z);
  return glm::vec3(x, y, z);
}

// Uniform on the unit sphere by rejection from the cube (no std distributions).
inline glm::vec3 RandomDirection(Pcg32& rng) {
  for (;;) {
    glm::vec3 v = RandomVec(rng, -1, 1);
    float l2 = glm::dot(v, v);
    if (l2 > 1e-4f && l2 <= 1.0f) return v / std::sqrt(l2);
  }
}

// `count` independent triangles in the cube [-1, 1]³, edges up to `size` long (overlapping and
// intersecting each other; no shared vertices).
inline geom::TriMesh RandomSoup(int count, uint64_t seed, float size = 0.3f) {
  Pcg32 rng(seed);
  geom::TriMesh m;
  for (int i = 0; i < count; ++i) {
    glm::vec3 c = RandomVec(rng, -1, 1);
    for (int k = 0; k < 3; ++k) {
      m.indices.push_back(static_cast<uint32_t>(m.positions.size()));
      m.positions.push_back(c + RandomVec(rng, -size, size));
    }
  }
  return m;
}

// A mesh made to break ties and epsilons: long slivers, zero-area triangles (collinear corners and
// repeated indices), exact duplicate triangles (same corners, other index order) and a fan sharing
// one vertex. Built from a small pool of vertices so many triangles share corners and edges.
inline geom::TriMesh ThinDegenerateMesh(uint64_t seed) {
  Pcg32 rng(seed);
  geom::TriMesh m;
  for (int i = 0; i < 60; ++i) m.positions.push_back(RandomVec(rng, -1, 1));
  auto vertex = [&]() { return static_cast<uint32_t>(rng.NextU32() % 60u); };
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
  };
  for (int i = 0; i < 150; ++i) {
    uint32_t a = vertex();
    uint32_t b = vertex();
    uint32_t c = vertex();
    add(a, b, c);
    if (i % 5 == 0) add(b, c, a);  // duplicate, rotated
    if (i % 7 == 0) add(a, a, b);  // repeated index
  }
  for (int i = 0; i < 40; ++i) {  // slivers and collinear triangles from new vertices
    glm::vec3 p = m.positions[vertex()];
    glm::vec3 q = m.positions[vertex()];
    uint32_t ip = static_cast<uint32_t>(m.positions.size());
    m.positions.push_back(p);
    m.positions.push_back(q);
    m.positions.push_back(p + (q - p) * 0.5f + glm::vec3(0.0f, i % 2 ? 1e-4f : 0.0f, 0.0f));
    add(ip, ip + 1, ip + 2);
  }
  return m;
}

}  // namespace niwa::test
