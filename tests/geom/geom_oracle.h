// The BVH-against-brute-force comparison the geometry tests share: seeded random closest-point,
// ray and segment queries over a mesh, counting answers that differ from the linear twins.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/linear_queries.h"
#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "geom/ray_cast.h"
#include "support/test_meshes.h"

namespace niwa::test {

inline bool SameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool SameBits(const glm::vec3& a, const glm::vec3& b) {
  return SameBits(a.x, b.x) && SameBits(a.y, b.y) && SameBits(a.z, b.z);
}

inline bool SameHit(const geom::ClosestHit& a, const geom::ClosestHit& b) {
  if (a.found != b.found) return false;
  return !a.found || (a.triangle == b.triangle && SameBits(a.distance, b.distance) &&
                      SameBits(a.point, b.point) && SameBits(a.barycentric, b.barycentric));
}
inline bool SameHit(const geom::RayHit& a, const geom::RayHit& b) {
  if (a.hit != b.hit) return false;
  return !a.hit || (a.triangle == b.triangle && SameBits(a.distance, b.distance) &&
                    SameBits(a.point, b.point) && SameBits(a.normal, b.normal));
}

struct OracleCounts {
  int queries = 0;
  int closest_found = 0, closest_mismatch = 0;
  int ray_hits = 0, ray_mismatch = 0;
  int segment_hits = 0, segment_mismatch = 0;
  std::string first_mismatch;  // what differed first, for the failure message
};

// `count` queries of each kind. Points are drawn in the mesh bounds grown by half its diagonal;
// half the rays and segments aim at a random triangle's corner, edge midpoint or centroid (where
// ties and edge cases live), the rest are random. Radii and max distances run from 0 to beyond
// the mesh, with some +inf.
inline OracleCounts CompareWithLinear(const geom::TriMesh& mesh, const geom::Bvh& bvh, int count,
                                      uint64_t seed) {
  OracleCounts c;
  Pcg32 rng(seed);
  geom::Bounds3 box = geom::MeshBounds(mesh);
  const glm::vec3 grow = box.diagonal() * 0.5f;
  geom::Bounds3 outer{box.min - grow, box.max + grow};
  const float scale = glm::length(box.diagonal());
  const uint32_t tris = static_cast<uint32_t>(mesh.triangle_count());
  auto target = [&]() {
    uint32_t t = rng.NextU32() % tris;
    glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
              cc = mesh.positions[mesh.indices[3 * t + 2]];
    switch (rng.NextU32() % 3) {
      case 0:
        return a;
      case 1:
        return (a + b) * 0.5f;
      default:
        return (a + b + cc) / 3.0f;
    }
  };
  auto radius = [&]() {
    uint32_t k = rng.NextU32() % 8;
    return k == 0 ? std::numeric_limits<float>::infinity() : UniformF(rng, 0.0, scale * 0.6);
  };
  for (int i = 0; i < count; ++i) {
    ++c.queries;
    glm::vec3 p = i % 4 == 3 ? target() : RandomPoint(rng, outer);
    float r = radius();
    geom::ClosestHit h = geom::ClosestPoint(mesh, bvh, p, r);
    geom::ClosestHit hl = geom::ClosestPointLinear(mesh, p, r);
    c.closest_found += hl.found ? 1 : 0;
    if (!SameHit(h, hl)) {
      ++c.closest_mismatch;
      if (c.first_mismatch.empty())
        c.first_mismatch = "closest query " + std::to_string(i) + ": bvh tri " +
                           std::to_string(h.triangle) + " found " + std::to_string(h.found) +
                           " d " + std::to_string(h.distance) + ", linear tri " +
                           std::to_string(hl.triangle) + " found " + std::to_string(hl.found) +
                           " d " + std::to_string(hl.distance);
    }

    glm::vec3 o = RandomPoint(rng, outer);
    glm::vec3 dir = i % 2 ? target() - o : RandomDirection(rng);
    float max_t = radius() * 3.0f;
    geom::RayHit rh = geom::FirstHit(mesh, bvh, o, dir, max_t);
    geom::RayHit rl = geom::FirstHitLinear(mesh, o, dir, max_t);
    c.ray_hits += rl.hit ? 1 : 0;
    if (!SameHit(rh, rl)) {
      ++c.ray_mismatch;
      if (c.first_mismatch.empty())
        c.first_mismatch = "ray query " + std::to_string(i) + ": bvh tri " +
                           std::to_string(rh.triangle) + " hit " + std::to_string(rh.hit) +
                           ", linear tri " + std::to_string(rl.triangle) + " hit " +
                           std::to_string(rl.hit);
    }

    glm::vec3 a = RandomPoint(rng, outer);
    glm::vec3 b;
    if (i % 2) {
      glm::vec3 t = target();
      b = a + (t - a) * UniformF(rng, 0.5, 1.5);
    } else {
      glm::vec3 d = RandomDirection(rng);
      b = a + d * UniformF(rng, 0.0, scale * 0.5);
    }
    bool sh = geom::SegmentHits(mesh, bvh, a, b);
    bool sl = geom::SegmentHitsLinear(mesh, a, b);
    c.segment_hits += sl ? 1 : 0;
    if (sh != sl) {
      ++c.segment_mismatch;
      if (c.first_mismatch.empty())
        c.first_mismatch = "segment query " + std::to_string(i) + ": bvh " + std::to_string(sh) +
                           ", linear " + std::to_string(sl);
    }
  }
  return c;
}

// The meshes every oracle test runs over: closed and open, index-shared and soup, metres and px.
struct OracleCase {
  const char* name;
  geom::TriMesh mesh;
};

inline std::vector<OracleCase> OracleMeshes() {
  return {{"icosphere3", geom::MakeIcosphere(1.0f, 3)},
          {"box_sub3", geom::Subdivide(geom::MakeBox({2.0f, 1.0f, 0.5f}, {0.3f, 0.0f, -0.2f}), 3)},
          {"soup3000", RandomSoup(3000, 42)},
          {"thin_degenerate", ThinDegenerateMesh(9)},
          {"cylinder", geom::MakeCylinder(0.5f, 2.0f, 24, true)},
          {"wall_px", geom::Subdivide(geom::MakePlane(1600.0f, 1200.0f, 2, 1), 4)}};
}

}  // namespace niwa::test
