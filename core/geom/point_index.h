// A radius-query index over points in 3-D (e.g. photons for a photon-map gather): all points within
// a radius of a query, and the k nearest, in a deterministic order: by squared distance, then by
// point index, so ties come out the same in every build and every run.
//
// Why nanoflann (Debian libnanoflann-dev, header-only, BSD): a kd-tree over points is what it is
// for; it builds for both targets (no threads, no allocation tricks), and its answers are only a
// candidate set here: each candidate's squared distance is recomputed as the linear twin computes
// it, ((dx² + dy²) + dz²) in double, and filtered and sorted by (distance², index), so the results
// are the brute-force twin's bit for bit (tests/geom/point_index_test.cpp).
// Not here: moving or adding points after the build (build a new index), approximate searches,
// other metrics, triangle queries (geom::Bvh).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "base/status.h"

namespace niwa {
namespace geom {

struct PointHit {
  uint32_t index;           // into the points the index was built from
  double distance_squared;  // ((dx² + dy²) + dz²) in double
};

class PointIndex {
 public:
  // Indexes the points (copied). Error (field "points") for a non-finite coordinate or more than
  // 2^32 - 1 points.
  static Result<PointIndex> Build(std::vector<glm::dvec3> points);

  PointIndex(PointIndex&&) noexcept;
  PointIndex& operator=(PointIndex&&) noexcept;
  ~PointIndex();

  std::size_t size() const;
  const std::vector<glm::dvec3>& points() const;

  // Every point with squared distance <= radius² (radius² in double) from query, sorted by
  // (distance², index). Empty for a negative or non-finite radius.
  std::vector<PointHit> WithinRadius(const glm::dvec3& query, double radius) const;

  // The k points nearest to query (fewer when there are fewer), sorted by (distance², index):
  // among points at the same distance the lower indices come first.
  std::vector<PointHit> Nearest(const glm::dvec3& query, std::size_t k) const;

 private:
  struct Impl;
  explicit PointIndex(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// The brute-force twins: one pass over all points, the same distances and order (the test oracle).
std::vector<PointHit> WithinRadiusLinear(const std::vector<glm::dvec3>& points,
                                         const glm::dvec3& query, double radius);
std::vector<PointHit> NearestLinear(const std::vector<glm::dvec3>& points, const glm::dvec3& query,
                                    std::size_t k);

}  // namespace geom
}  // namespace niwa
