// Area-weighted surface sampling (cumulative areas + binary search, sqrt warp) and Poisson-disk
// dart throwing on a uniform hash grid.
#include "geom/surface_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_map>

#include "geom/mesh_metrics.h"
#include "geom/triangle_queries.h"
#include "random/pcg32.h"

namespace niwa::geom {
namespace {

// Draws area-weighted samples from one Pcg32 stream: three uniforms per sample (triangle, u1, u2).
class AreaSampler {
 public:
  AreaSampler(const TriMesh& mesh, uint64_t seed) : mesh_(mesh), rng_(seed) {
    cumulative_.reserve(mesh.triangle_count());
    double sum = 0.0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      sum += IsDegenerateTriangle(mesh, t) ? 0.0 : TriangleArea(mesh, t);
      cumulative_.push_back(sum);
    }
    total_ = sum;
  }
  bool has_area() const { return total_ > 0.0; }

  SurfaceSample Next() {
    double target = rng_.Uniform() * total_;
    // First triangle whose cumulative area exceeds target: zero-area triangles are never chosen.
    std::size_t t = static_cast<std::size_t>(
        std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin());
    if (t >= cumulative_.size()) t = cumulative_.size() - 1;
    while (t > 0 && cumulative_[t] == cumulative_[t - 1]) --t;  // never land on a zero-area one
    double u1 = rng_.Uniform(), u2 = rng_.Uniform();
    double r1 = std::sqrt(u1);
    double wa = 1.0 - r1, wb = r1 * (1.0 - u2), wc = r1 * u2;  // Osada et al. 2002, eq. 1
    const std::size_t i = 3 * t;
    DVec3 a = ToD(mesh_.positions[mesh_.indices[i]]);
    DVec3 b = ToD(mesh_.positions[mesh_.indices[i + 1]]);
    DVec3 c = ToD(mesh_.positions[mesh_.indices[i + 2]]);
    DVec3 p = Add(Add(Mul(a, wa), Mul(b, wb)), Mul(c, wc));
    DVec3 n = Cross(Sub(b, a), Sub(c, a));
    double len = std::sqrt(Dot(n, n));
    SurfaceSample s;
    s.point = glm::vec3(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
    s.triangle = static_cast<uint32_t>(t);
    if (len > 0.0)
      s.normal = glm::vec3(static_cast<float>(n.x / len), static_cast<float>(n.y / len),
                           static_cast<float>(n.z / len));
    s.barycentric =
        glm::vec3(static_cast<float>(wa), static_cast<float>(wb), static_cast<float>(wc));
    return s;
  }

 private:
  const TriMesh& mesh_;
  Pcg32 rng_;
  std::vector<double> cumulative_;
  double total_ = 0.0;
};

}  // namespace

std::vector<SurfaceSample> SampleSurface(const TriMesh& mesh, int count, uint64_t seed) {
  std::vector<SurfaceSample> out;
  AreaSampler sampler(mesh, seed);
  if (count <= 0 || !sampler.has_area()) return out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) out.push_back(sampler.Next());
  return out;
}

std::vector<SurfaceSample> SamplePoissonDisk(const TriMesh& mesh, int count, float min_distance,
                                             uint64_t seed, int max_attempts) {
  std::vector<SurfaceSample> out;
  AreaSampler sampler(mesh, seed);
  if (count <= 0 || !sampler.has_area()) return out;
  if (!(min_distance > 0.0f)) return SampleSurface(mesh, count, seed);
  // Grid of cell size min_distance: a conflicting point lies in the 27 cells around a candidate.
  // The map is only looked up, never iterated, so its hash order does not reach the result.
  const double cell = min_distance;
  const double r2 = static_cast<double>(min_distance) * min_distance;
  auto cell_of = [&](double x) { return static_cast<int64_t>(std::floor(x / cell)); };
  auto key = [](int64_t x, int64_t y, int64_t z) {
    return (static_cast<uint64_t>(x & 0x1fffff) << 42) |
           (static_cast<uint64_t>(y & 0x1fffff) << 21) | static_cast<uint64_t>(z & 0x1fffff);
  };
  std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
  for (int attempt = 0; attempt < max_attempts && static_cast<int>(out.size()) < count; ++attempt) {
    SurfaceSample s = sampler.Next();
    int64_t cx = cell_of(s.point.x), cy = cell_of(s.point.y), cz = cell_of(s.point.z);
    bool ok = true;
    for (int64_t dx = -1; dx <= 1 && ok; ++dx)
      for (int64_t dy = -1; dy <= 1 && ok; ++dy)
        for (int64_t dz = -1; dz <= 1 && ok; ++dz) {
          auto it = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (uint32_t j : it->second) {
            double ex = static_cast<double>(out[j].point.x) - s.point.x;
            double ey = static_cast<double>(out[j].point.y) - s.point.y;
            double ez = static_cast<double>(out[j].point.z) - s.point.z;
            if (ex * ex + ey * ey + ez * ez < r2) {
              ok = false;
              break;
            }
          }
        }
    if (!ok) continue;
    grid[key(cx, cy, cz)].push_back(static_cast<uint32_t>(out.size()));
    out.push_back(s);
  }
  return out;
}

}  // namespace niwa::geom
