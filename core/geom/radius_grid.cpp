// RadiusGrid's build: a counting sort of the points into buckets (see radius_grid.h).
#include "geom/radius_grid.h"

#include <algorithm>
#include <limits>

namespace niwa {
namespace geom {

RadiusGrid::RadiusGrid(const std::vector<glm::dvec3>& points, double radius,
                       std::size_t max_buckets)
    : radius_(radius), bucket_(radius > 0 ? radius : 1.0) {
  if (points.empty()) {
    start_.assign(2, 0);
    return;
  }
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : points) {
    lo = glm::dvec3(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
    hi = glm::dvec3(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
  }
  origin_ = lo;
  for (;;) {
    double cells = 1;
    for (int a = 0; a < 3; ++a) {
      dims_[a] = std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / bucket_)) + 1);
      cells *= dims_[a];
    }
    if (cells <= static_cast<double>(max_buckets)) break;
    bucket_ *= 2;
  }
  const std::size_t n = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  auto bucket_of = [&](const glm::dvec3& p) {
    std::size_t b = 0;
    for (int a = 2; a >= 0; --a)
      b = b * dims_[a] + Clamp(std::floor((p[a] - origin_[a]) / bucket_), dims_[a]);
    return b;
  };
  start_.assign(n + 1, 0);
  // Each point's bucket once (the same floor as a query's), then a counting sort.
  std::vector<uint32_t> bucket(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    bucket[i] = static_cast<uint32_t>(bucket_of(points[i]));
    ++start_[bucket[i] + 1];
  }
  for (std::size_t b = 0; b < n; ++b) start_[b + 1] += start_[b];
  items_.resize(points.size());
  slot_points_.resize(points.size());
  for (uint32_t i = 0; i < points.size(); ++i) {
    const uint32_t k = start_[bucket[i]]++;
    items_[k] = i;
    slot_points_[k] = points[i];
  }
  // start_[b] now holds bucket b's end, which is bucket b + 1's start: shift back by one.
  for (std::size_t b = n; b > 0; --b) start_[b] = start_[b - 1];
  start_[0] = 0;
}

}  // namespace geom
}  // namespace niwa
