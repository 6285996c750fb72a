// Tests of geom::RadiusGrid against the brute-force twin (geom::WithinRadiusLinear): the same
// points with the same distance bits for random sets (spread, flat like a ground, on a lattice
// with points exactly at the radius, and a coarsened grid), and its visiting order: buckets in
// x, y, z order, each bucket's points in index order, the same on every call.
#include "geom/radius_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

#include "geom/point_index.h"
#include "random/pcg32.h"

namespace niwa {
namespace {

using Hits = std::vector<std::pair<uint32_t, double>>;

Hits FromGrid(const geom::RadiusGrid& grid, const glm::dvec3& q) {
  Hits hits;
  grid.ForEachWithin(q, [&](uint32_t i, double d2) { hits.push_back({i, d2}); });
  return hits;
}

// The grid's hits as a set equal to the twin's (index and distance bits).
void ExpectSameSet(Hits got, const std::vector<geom::PointHit>& want, const char* what) {
  std::sort(got.begin(), got.end());
  Hits w;
  for (const geom::PointHit& h : want) w.push_back({h.index, h.distance_squared});
  std::sort(w.begin(), w.end());
  ASSERT_EQ(got.size(), w.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].first, w[i].first) << what;
    ASSERT_EQ(std::memcmp(&got[i].second, &w[i].second, sizeof(double)), 0) << what;
  }
}

TEST(RadiusGrid, SameHitsAsTheBruteForceTwin) {
  Pcg32 rng(3, 9);
  int total = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + static_cast<int>(rng.NextU32() % 3000);
    const double r = rng.Uniform(0.01, 0.5);
    const bool flat = trial % 3 == 0;  // a ground: every point at y = 0
    std::vector<glm::dvec3> points;
    for (int i = 0; i < n; ++i)
      points.push_back({rng.Uniform(-2, 2), flat ? 0.0 : rng.Uniform(-1, 1), rng.Uniform(-2, 2)});
    const geom::RadiusGrid grid(points, r);
    for (int k = 0; k < 60; ++k) {
      const glm::dvec3 q(rng.Uniform(-2.5, 2.5), flat ? 0.0 : rng.Uniform(-1.2, 1.2),
                         rng.Uniform(-2.5, 2.5));
      const Hits got = FromGrid(grid, q);
      ExpectSameSet(got, geom::WithinRadiusLinear(points, q, r), "random");
      EXPECT_EQ(grid.CountWithin(q), got.size());
      total += static_cast<int>(got.size());
    }
  }
  EXPECT_GT(total, 5000);  // the queries found many points
}

TEST(RadiusGrid, LatticePointsExactlyAtTheRadiusAndACoarseGrid) {
  std::vector<glm::dvec3> points;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z) points.push_back({0.25 * x, 0.25 * y, 0.25 * z});
  for (std::size_t buckets : {std::size_t{1} << 21, std::size_t{8}}) {  // 8: coarsened to fit
    const geom::RadiusGrid grid(points, 0.5, buckets);
    for (const glm::dvec3& q : {glm::dvec3(0.0), glm::dvec3(0.5, 0.25, -0.75),
                                glm::dvec3(1.25, 1.25, 1.25), glm::dvec3(9.0, 0.0, 0.0)}) {
      ExpectSameSet(FromGrid(grid, q), geom::WithinRadiusLinear(points, q, 0.5), "lattice");
    }
  }
}

TEST(RadiusGrid, VisitsInOneOrderEveryTime) {
  Pcg32 rng(4, 1);
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 500; ++i)
    points.push_back({rng.Uniform(0, 1), rng.Uniform(0, 1), rng.Uniform(0, 1)});
  const geom::RadiusGrid a(points, 0.2), b(points, 0.2);
  const glm::dvec3 q(0.5, 0.5, 0.5);
  const Hits first = FromGrid(a, q);
  EXPECT_EQ(FromGrid(a, q), first);
  EXPECT_EQ(FromGrid(b, q), first);
  EXPECT_FALSE(first.empty());
  EXPECT_TRUE(FromGrid(geom::RadiusGrid({}, 0.2), q).empty());
}

}  // namespace
}  // namespace niwa
