// PointIndex over nanoflann's kd-tree, and its brute-force twins (see point_index.h).
#include "geom/point_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>
#include <string>
#include <utility>

namespace niwa {
namespace geom {
namespace point_index_detail {  // named, not anonymous: PointIndex::Impl holds these types

// The one distance both the index and the twins report.
double DistanceSquared(const glm::dvec3& a, const glm::dvec3& b) {
  const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return (dx * dx + dy * dy) + dz * dz;
}

bool Closer(const PointHit& a, const PointHit& b) {
  return a.distance_squared < b.distance_squared ||
         (a.distance_squared == b.distance_squared && a.index < b.index);
}

double MaxAbs(const glm::dvec3& v) {
  return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z)));
}

// nanoflann's view of the points.
struct Cloud {
  const std::vector<glm::dvec3>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return (*points)[i][static_cast<glm::length_t>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud, double>, Cloud,
                                        3, uint32_t>;

}  // namespace point_index_detail
using namespace point_index_detail;  // this file's own helpers

struct PointIndex::Impl {
  std::vector<glm::dvec3> points;
  Cloud cloud;
  std::unique_ptr<Tree> tree;
  double max_abs = 0.0;  // largest |coordinate|: bounds the rounding of nanoflann's own distances

  // nanoflann's candidates for squared distance <= radius², a superset: its pruning sums the
  // distance along the axes differently, so the search radius is widened well past that rounding.
  std::vector<PointHit> Candidates(const glm::dvec3& query, double radius) const {
    std::vector<PointHit> hits;
    if (points.empty()) return hits;
    const double slack = 1e-9 * (max_abs + MaxAbs(query)) + 1e-9 * radius;
    const double wide = radius + slack;
    std::vector<std::pair<uint32_t, double>> found;
    const double q[3] = {query.x, query.y, query.z};
    tree->radiusSearch(q, wide * wide + std::numeric_limits<double>::min(), found,
                       nanoflann::SearchParams(32, 0.0f, false));
    const double r2 = radius * radius;
    for (const auto& f : found) {
      const double d2 = DistanceSquared(points[f.first], query);
      if (d2 <= r2) hits.push_back(PointHit{f.first, d2});
    }
    std::sort(hits.begin(), hits.end(), Closer);
    return hits;
  }
};

PointIndex::PointIndex(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PointIndex::PointIndex(PointIndex&&) noexcept = default;
PointIndex& PointIndex::operator=(PointIndex&&) noexcept = default;
PointIndex::~PointIndex() = default;

Result<PointIndex> PointIndex::Build(std::vector<glm::dvec3> points) {
  if (points.size() >= std::numeric_limits<uint32_t>::max()) {
    return Status::Error("points", "more than 4294967294 points");
  }
  auto impl = std::make_unique<Impl>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return Status::Error("points", "point " + std::to_string(i) + " is not finite");
    }
    impl->max_abs = std::max(impl->max_abs, MaxAbs(p));
  }
  impl->points = std::move(points);
  impl->cloud.points = &impl->points;
  impl->tree =
      std::make_unique<Tree>(3, impl->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  return PointIndex(std::move(impl));
}

std::size_t PointIndex::size() const { return impl_->points.size(); }
const std::vector<glm::dvec3>& PointIndex::points() const { return impl_->points; }

std::vector<PointHit> PointIndex::WithinRadius(const glm::dvec3& query, double radius) const {
  if (!(radius >= 0.0) || !std::isfinite(radius)) return {};
  return impl_->Candidates(query, radius);
}

std::vector<PointHit> PointIndex::Nearest(const glm::dvec3& query, std::size_t k) const {
  const std::size_t n = impl_->points.size();
  if (k == 0 || n == 0) return {};
  k = std::min(k, n);
  // nanoflann's k nearest give a distance D that at least k points are within; every point of the
  // true k nearest (ties included) is within it, so the exact radius search at D holds them all.
  std::vector<uint32_t> index(k);
  std::vector<double> distance(k);
  const double q[3] = {query.x, query.y, query.z};
  const std::size_t found = impl_->tree->knnSearch(q, k, index.data(), distance.data());
  double reach = 0.0;
  for (std::size_t i = 0; i < found; ++i) {
    reach = std::max(reach, DistanceSquared(impl_->points[index[i]], query));
  }
  std::vector<PointHit> hits = impl_->Candidates(query, std::sqrt(reach) * (1.0 + 1e-12));
  if (hits.size() < k) {  // cannot happen unless the arithmetic above is wrong: stay exact
    hits = NearestLinear(impl_->points, query, k);
  }
  hits.resize(k);
  return hits;
}

std::vector<PointHit> WithinRadiusLinear(const std::vector<glm::dvec3>& points,
                                         const glm::dvec3& query, double radius) {
  std::vector<PointHit> hits;
  if (!(radius >= 0.0) || !std::isfinite(radius)) return hits;
  const double r2 = radius * radius;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d2 = DistanceSquared(points[i], query);
    if (d2 <= r2) hits.push_back(PointHit{static_cast<uint32_t>(i), d2});
  }
  std::sort(hits.begin(), hits.end(), Closer);
  return hits;
}

std::vector<PointHit> NearestLinear(const std::vector<glm::dvec3>& points, const glm::dvec3& query,
                                    std::size_t k) {
  std::vector<PointHit> hits;
  hits.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    hits.push_back(PointHit{static_cast<uint32_t>(i), DistanceSquared(points[i], query)});
  }
  k = std::min(k, hits.size());
  std::partial_sort(hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(k), hits.end(),
                    Closer);
  hits.resize(k);
  return hits;
}

}  // namespace geom
}  // namespace niwa
