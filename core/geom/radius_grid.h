// A uniform grid over points in 3-D for many queries of ONE fixed radius (a photon-map gather over
// every soil cell and moss each day, a neighbour count): the points within the radius of a query,
// visited in a deterministic order (the grid's buckets in x, y, z order, each bucket's points in
// index order), without allocating per query.
//
// Why not geom::PointIndex (nanoflann) here: its radius search allocates and sorts a result per
// query, 0.75 µs a query on a moss day's 33,000 queries (16,488 cells, two radii): 25 ms of the
// day's budget of about 7 ms. A fixed radius lets buckets of the radius's size answer with the 27
// buckets around the query. No library gives that shape for both targets; it is small, and tested
// against the brute-force twin (geom::WithinRadiusLinear, tests/geom/radius_grid_test.cpp).
// Not here: other radii than the build's (ask a new grid), k nearest, moving points.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace niwa {
namespace geom {

class RadiusGrid {
 public:
  // Buckets of `radius` over the points' box (coarser when that would pass max_buckets). Points
  // must be finite and radius > 0 (the callers' positions are checked where they are made).
  RadiusGrid(const std::vector<glm::dvec3>& points, double radius,
             std::size_t max_buckets = std::size_t{1} << 21);

  double radius() const { return radius_; }

  // Calls fn(index, distance²) for every point with distance² <= radius² (distance² as
  // point_index.h computes it: ((dx² + dy²) + dz²) in double), in the grid's order.
  template <class Fn>
  void ForEachWithin(const glm::dvec3& q, Fn&& fn) const {
    if (points_.empty()) return;
    int lo[3], hi[3];
    const double reach = radius_ * (1 + 1e-9);  // past any rounding of the bucket bounds
    for (int a = 0; a < 3; ++a) {
      lo[a] = Clamp(std::floor((q[a] - reach - origin_[a]) / bucket_), dims_[a]);
      hi[a] = Clamp(std::floor((q[a] + reach - origin_[a]) / bucket_), dims_[a]);
    }
    const double r2 = radius_ * radius_;
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y) {
        const std::size_t row = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0];
        for (uint32_t k = start_[row + lo[0]]; k < start_[row + hi[0] + 1]; ++k) {
          const uint32_t i = items_[k];
          const glm::dvec3& p = points_[i];
          const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
          const double d2 = (dx * dx + dy * dy) + dz * dz;
          if (d2 <= r2) fn(i, d2);
        }
      }
  }

  // The number of points within the radius of q.
  std::size_t CountWithin(const glm::dvec3& q) const {
    std::size_t n = 0;
    ForEachWithin(q, [&](uint32_t, double) { ++n; });
    return n;
  }

 private:
  static int Clamp(double cell, int dim) {
    if (!(cell > 0)) return 0;  // also NaN
    if (cell >= dim - 1) return dim - 1;
    return static_cast<int>(cell);
  }

  std::vector<glm::dvec3> points_;
  double radius_ = 0, bucket_ = 1;
  glm::dvec3 origin_{0.0};
  int dims_[3] = {1, 1, 1};
  std::vector<uint32_t> start_;  // bucket b's points: items_[start_[b] .. start_[b + 1])
  std::vector<uint32_t> items_;  // point indices, bucket by bucket, each bucket in index order
};

}  // namespace geom
}  // namespace niwa
