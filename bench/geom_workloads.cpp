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

struct Scene {
  geom::TriMesh mesh;
  geom::Bvh bvh;
  std::vector<glm::vec3> points;        // closest-point queries, within ±5 cm of the wall
  std::vector<glm::vec3> seg_a, seg_b;  // segments of length L, about a third crossing
};

float U(Pcg32& rng, double lo, double hi) { return static_cast<float>(rng.Uniform(lo, hi)); }

// Queries in walk order (ivy's pattern: each query near the last): a random walk over the wall in
// steps of about L, y within ±5 cm, segments from each point onward by L.
void MakeWalk(Scene* s) {
  Pcg32 rng(78);
  glm::vec3 p(0.0f);
  s->points.clear();
  s->seg_a.clear();
  s->seg_b.clear();
  for (int i = 0; i < kQueries; ++i) {
    float dx = U(rng, -1.0, 1.0);
    float dz = U(rng, -1.0, 1.0);
    float y = U(rng, -0.05, 0.05);
    glm::vec3 q = p + glm::vec3(dx, 0.0f, dz) * kSegment;
    q.x = std::clamp(q.x, -1.0f, 1.0f);
    q.z = std::clamp(q.z, -0.5f, 0.5f);
    q.y = y;
    s->points.push_back(p);
    s->seg_a.push_back(p);
    s->seg_b.push_back(q);
    p = q;
  }
}

std::shared_ptr<Scene> MakeScene(const WallSize& w, bool build_bvh) {
  auto s = std::make_shared<Scene>();
  s->mesh = geom::MakePlane(2.0f, 1.0f, w.sx, w.sz);
  if (build_bvh) s->bvh = geom::Bvh::Build(s->mesh);
  Pcg32 rng(77);
  for (int i = 0; i < kQueries; ++i) {
    // One draw per statement: argument evaluation order differs between g++ and clang (em++).
    float x = U(rng, -1.0, 1.0);
    float y = U(rng, -0.05, 0.05);
    float z = U(rng, -0.5, 0.5);
    s->points.push_back({x, y, z});
    float dx = U(rng, -1.0, 1.0);
    float dy = U(rng, -1.0, 1.0);
    float dz = U(rng, -1.0, 1.0);
    glm::vec3 d(dx, dy, dz);
    float len = glm::length(d);
    if (len < 1e-3f) d = glm::vec3(0, 1, 0), len = 1;
    s->seg_a.push_back({x, y, z});
    s->seg_b.push_back(glm::vec3(x, y, z) + d * (kSegment / len));
  }
  return s;
}

Workload BuildWorkload(const WallSize& w, bool cold) {
  Workload wl;
  wl.name = std::string("geom/bvh-build") + (cold ? "-cold" : "") + "/wall-" + w.label;
  wl.note = std::string("Bvh::Build (16 bins, leaves <= 4) of the ") + w.label + "-triangle wall" +
            (cold ? ", first build in the process (no warm-up)" : "");
  wl.unit = "triangle";
  wl.once = cold;
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [w, units]() -> WorkloadBody {
    auto scene = MakeScene(w, false);
    *units = static_cast<double>(scene->mesh.triangle_count());
    return [scene]() {
      geom::Bvh bvh = geom::Bvh::Build(scene->mesh);
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
  wl.prepare = [w, kind, linear, walk, n, units]() -> WorkloadBody {
    auto s = MakeScene(w, !linear);
    if (walk) MakeWalk(s.get());
    *units = n;
    if (kind == "closest") {
      return [s, linear, n]() {
        double sum = 0;
        for (int i = 0; i < n; ++i) {
          geom::ClosestHit h = linear ? geom::ClosestPointLinear(s->mesh, s->points[i], kRadius)
                                      : geom::ClosestPoint(s->mesh, s->bvh, s->points[i], kRadius);
          if (h.found) sum += h.distance + 1e-9 * h.triangle;
        }
        return sum;
      };
    }
    return [s, linear, n]() {
      double hits = 0;
      for (int i = 0; i < n; ++i) {
        std::size_t k = static_cast<std::size_t>(i);
        bool hit = linear ? geom::SegmentHitsLinear(s->mesh, s->seg_a[k], s->seg_b[k])
                          : geom::SegmentHits(s->mesh, s->bvh, s->seg_a[k], s->seg_b[k]);
        hits += hit ? 1 : 0;
      }
      return hits;
    };
  };
  return wl;
}

}  // namespace

std::vector<Workload> GeomWorkloads() {
  std::vector<Workload> all;
  all.push_back(BuildWorkload(kWalls[3], /*cold=*/true));
  for (const WallSize& w : kWalls) all.push_back(BuildWorkload(w, false));
  for (const char* kind : {"closest", "segment"}) {
    for (const WallSize& w : kWalls) all.push_back(QueryWorkload(w, kind, false));
    all.push_back(QueryWorkload(kWalls[2], kind, true));  // brute force at 262 k
    for (int k : {0, 4}) all.push_back(QueryWorkload(kWalls[k], kind, false, /*walk=*/true));
  }
  return all;
}

}  // namespace niwa
