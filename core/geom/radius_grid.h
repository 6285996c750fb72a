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
    const double r2 = radius_ * radius_;
    ForEachRowAround(q, [&](uint32_t k0, uint32_t k1) {
      for (uint32_t k = k0; k < k1; ++k) {
        const glm::dvec3& p = slot_points_[k];
        const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
        const double d2 = (dx * dx + dy * dy) + dz * dz;
        if (d2 <= r2) fn(items_[k], d2);
      }
    });
  }

  // The candidates of ForEachWithin before its distance test, as runs of slots: fn(k0, k1) for
  // each row of buckets around q, in the grid's order; slot k holds point order()[k]. For callers
  // that keep their own per-point data in slot order (a photon's normal and power beside its
  // position) and read it in one run.
  template <class Fn>
  void ForEachRowAround(const glm::dvec3& q, Fn&& fn) const {
    if (items_.empty()) return;
    int lo[3], hi[3];
    const double reach = radius_ * (1 + 1e-9);  // past any rounding of the bucket bounds
    for (int a = 0; a < 3; ++a) {
      lo[a] = Clamp(std::floor((q[a] - reach - origin_[a]) / bucket_), dims_[a]);
      hi[a] = Clamp(std::floor((q[a] + reach - origin_[a]) / bucket_), dims_[a]);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y) {
        const std::size_t row = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0];
        const uint32_t k0 = start_[row + lo[0]], k1 = start_[row + hi[0] + 1];
        if (k0 < k1) fn(k0, k1);
      }
  }
  // The point in each slot, bucket by bucket (each bucket in index order), and its position.
  const std::vector<uint32_t>& order() const { return items_; }
  const std::vector<glm::dvec3>& slot_points() const { return slot_points_; }

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

  std::vector<glm::dvec3> slot_points_;  // points_[items_[k]] at k: a query reads one run
  double radius_ = 0, bucket_ = 1;
  glm::dvec3 origin_{0.0};
  int dims_[3] = {1, 1, 1};
  std::vector<uint32_t> start_;  // bucket b's points: items_[start_[b] .. start_[b + 1])
  std::vector<uint32_t> items_;  // point indices, bucket by bucket, each bucket in index order
};

}  // namespace geom
}  // namespace niwa
