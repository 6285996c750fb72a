// Mesh geometry workloads (core/geom): BVH build per triangle, closest-point and segment queries
// at 4 k .. 4 M triangles, and the BVH against brute force at 262 k triangles.
#include <algorithm>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/linear_queries.h"
#include "geom/primitives.h"
#include "geom/ray_cast.h"
#include "random/pcg32.h"
#include "workloads.h"

namespace niwa {
namespace {

// The wall: 2 m × 1 m in x-z (normal +y), a grid of 2·sx·sz triangles: the same triangles as a
// quad pair subdivided K times (Subdivide's edge map would need ~40 B per edge at 4 M).
struct WallSize {
  const char* label;
  int sx, sz;
};
constexpr WallSize kWalls[] = {
    {"4k", 64, 32}, {"65k", 256, 128}, {"262k", 512, 256}, {"1m", 1024, 512}, {"4m", 2048, 1024}};
constexpr int kQueries = 20000;      // per timed run of a BVH query workload
constexpr int kLinearQueries = 20;   // per timed run of a brute-force workload
constexpr float kRadius = 0.05f;     // closest-point radius (ivy's sucker length d, scaled)
constexpr float kSegment = 0.0625f;  // segment length (ivy's internode L, scaled)

struct Queries {
  std::vector<glm::vec3> points;        // closest-point queries, within ±5 cm of the wall
  std::vector<glm::vec3> seg_a, seg_b;  // segments of length about L
};

struct Scene {
  geom::TriMesh mesh;
  geom::Bvh bvh;
  Queries scattered;  // uniform over the wall
  Queries walk;       // in walk order (ivy's pattern: each query near the last)
};

float U(Pcg32& rng, double lo, double hi) { return static_cast<float>(rng.Uniform(lo, hi)); }

Queries ScatteredQueries() {
  Queries q;
  Pcg32 rng(77);
  for (int i = 0; i < kQueries; ++i) {
    // One draw per statement: argument evaluation order differs between g++ and clang (em++).
    float x = U(rng, -1.0, 1.0);
    float y = U(rng, -0.05, 0.05);
    float z = U(rng, -0.5, 0.5);
    float dx = U(rng, -1.0, 1.0);
    float dy = U(rng, -1.0, 1.0);
    float dz = U(rng, -1.0, 1.0);
    glm::vec3 p(x, y, z), d(dx, dy, dz);
    float len = glm::length(d);
    if (len < 1e-3f) d = glm::vec3(0, 1, 0), len = 1;
    q.points.push_back(p);
    q.seg_a.push_back(p);
    q.seg_b.push_back(p + d * (kSegment / len));
  }
  return q;
}

// A random walk over the wall in steps of up to L along x and z, y within ±5 cm; each segment
// runs from one walk point to the next.
Queries WalkQueries() {
  Queries q;
  Pcg32 rng(78);
  glm::vec3 p(0.0f);
  for (int i = 0; i < kQueries; ++i) {
    float dx = U(rng, -1.0, 1.0);
    float dz = U(rng, -1.0, 1.0);
    float y = U(rng, -0.05, 0.05);
    glm::vec3 next = p + glm::vec3(dx, 0.0f, dz) * kSegment;
    next.x = std::clamp(next.x, -1.0f, 1.0f);
    next.z = std::clamp(next.z, -0.5f, 0.5f);
    next.y = y;
    q.points.push_back(p);
    q.seg_a.push_back(p);
    q.seg_b.push_back(next);
    p = next;
  }
  return q;
}

// The scene of one wall size, shared by that size's workloads (they come one after another): the
// 4 M wall with its BVH holds about 350 MB, so only the last one is kept.
std::shared_ptr<Scene> SceneFor(const WallSize& w) {
  static std::shared_ptr<Scene> last;
  static const WallSize* last_size = nullptr;
  if (last && last_size == &w) return last;
  last.reset();
  auto s = std::make_shared<Scene>();
  s->mesh = geom::MakePlane(2.0f, 1.0f, w.sx, w.sz);
  s->bvh = geom::Bvh::Build(s->mesh);
  s->scattered = ScatteredQueries();
  s->walk = WalkQueries();
  last = s;
  last_size = &w;
  return s;
}

Workload BuildWorkload(const WallSize& w, bool cold) {  // w: an element of kWalls
  Workload wl;
  wl.name = std::string("geom/bvh-build") + (cold ? "-cold" : "") + "/wall-" + w.label;
  wl.note = std::string("Bvh::Build (16 bins, leaves <= 4) of the ") + w.label + "-triangle wall" +
            (cold ? ", timed once: the first build on a fresh mesh, no warm-up" : "");
  wl.unit = "triangle";
  wl.once = cold;
  std::shared_ptr<double> units = wl.units;
  const WallSize* size = &w;
  wl.prepare = [size, cold, units]() -> WorkloadBody {
    // Cold: a mesh of its own, never built on before (the shared scene has been).
    auto mesh =
        cold ? std::make_shared<geom::TriMesh>(geom::MakePlane(2.0f, 1.0f, size->sx, size->sz))
             : std::shared_ptr<geom::TriMesh>(SceneFor(*size), &SceneFor(*size)->mesh);
    *units = static_cast<double>(mesh->triangle_count());
    return [mesh]() {
      geom::Bvh bvh = geom::Bvh::Build(*mesh);
      return static_cast<double>(bvh.node_count()) + 1e-3 * bvh.depth();
    };
  };
  return wl;
}

// kind: "closest" or "segment"; linear: brute force on the first kLinearQueries queries; walk:
// queries in walk order (MakeWalk) instead of uniformly scattered.
Workload QueryWorkload(const WallSize& w, const std::string& kind, bool linear, bool walk = false) {
  Workload wl;
  const int n = linear ? kLinearQueries : kQueries;
  wl.name = "geom/" + kind + (linear ? "-linear" : "") + (walk ? "-walk" : "") + "/wall-" + w.label;
  wl.note = std::to_string(n) +
            (kind == "closest" ? " ClosestPoint (r 5 cm)" : " SegmentHits (6.25 cm)") +
            (linear ? " by brute force" : " through the BVH") + (walk ? " in walk order" : "") +
            ", " + w.label + "-triangle wall";
  wl.unit = "query";
  std::shared_ptr<double> units = wl.units;
  const WallSize* size = &w;
  wl.prepare = [size, kind, linear, walk, n, units]() -> WorkloadBody {
    auto scene = SceneFor(*size);
    std::shared_ptr<const Queries> s(scene, walk ? &scene->walk : &scene->scattered);
    *units = n;
    if (kind == "closest") {
      return [scene, s, linear, n]() {
        double sum = 0;
        for (int i = 0; i < n; ++i) {
          std::size_t k = static_cast<std::size_t>(i);
          geom::ClosestHit h =
              linear ? geom::ClosestPointLinear(scene->mesh, s->points[k], kRadius)
                     : geom::ClosestPoint(scene->mesh, scene->bvh, s->points[k], kRadius);
          if (h.found) sum += h.distance + 1e-9 * h.triangle;
        }
        return sum;
      };
    }
    return [scene, s, linear, n]() {
      double hits = 0;
      for (int i = 0; i < n; ++i) {
        std::size_t k = static_cast<std::size_t>(i);
        bool hit = linear ? geom::SegmentHitsLinear(scene->mesh, s->seg_a[k], s->seg_b[k])
                          : geom::SegmentHits(scene->mesh, scene->bvh, s->seg_a[k], s->seg_b[k]);
        hits += hit ? 1 : 0;
      }
      return hits;
    };
  };
  return wl;
}

}  // namespace

std::vector<Workload> GeomWorkloads() {
  // Grouped by wall size so each size's scene is made once (SceneFor). The 4 M build is timed once
  // (cold: about 2 s natively per run), the 1 M build both cold and warm.
  std::vector<Workload> all;
  for (const WallSize& w : kWalls) {
    const bool big = std::string(w.label) == "4m", walk = std::string(w.label) == "4k" || big;
    if (std::string(w.label) == "1m") all.push_back(BuildWorkload(w, /*cold=*/true));
    all.push_back(BuildWorkload(w, /*cold=*/big));
    for (const char* kind : {"closest", "segment"}) {
      all.push_back(QueryWorkload(w, kind, false));
      if (walk) all.push_back(QueryWorkload(w, kind, false, /*walk=*/true));
      if (std::string(w.label) == "262k") all.push_back(QueryWorkload(w, kind, /*linear=*/true));
    }
  }
  return all;
}

}  // namespace niwa
