// Tests of geom::PointIndex against its brute-force twins: random point sets (spread, clustered,
// on a lattice with many equal distances, duplicates), radii and k; identical hits in identical
// order (distance², then index), and the errors of Build.
#include "geom/point_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "random/pcg32.h"

namespace niwa {
namespace {

using geom::PointHit;

// Same indices and the same distance bits, in the same order.
void ExpectSameHits(const std::vector<PointHit>& got, const std::vector<PointHit>& want,
                    const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].index, want[i].index) << what << " hit " << i;
    ASSERT_EQ(std::memcmp(&got[i].distance_squared, &want[i].distance_squared, sizeof(double)), 0)
        << what << " hit " << i;
  }
}

std::vector<glm::dvec3> Spread(Pcg32& rng, int n, double extent) {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < n; ++i) {
    p.push_back(glm::dvec3(rng.Uniform(-extent, extent), rng.Uniform(-extent, extent),
                           rng.Uniform(-extent, extent)));
  }
  return p;
}

// Integer lattice points with duplicates: many points at exactly equal distances from a lattice
// query, so the (distance, index) order of ties decides the results.
std::vector<glm::dvec3> Lattice(Pcg32& rng, int n) {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < n; ++i) {
    p.push_back(glm::dvec3(static_cast<double>(rng.NextU32() % 9),
                           static_cast<double>(rng.NextU32() % 9),
                           static_cast<double>(rng.NextU32() % 9)));
  }
  return p;
}

void CheckSet(const std::vector<glm::dvec3>& points, Pcg32& rng, double extent, bool lattice,
              const char* what) {
  Result<geom::PointIndex> index = geom::PointIndex::Build(points);
  ASSERT_TRUE(index.ok()) << index.status().Line();
  ASSERT_EQ(index->size(), points.size());
  for (int q = 0; q < 60; ++q) {
    glm::dvec3 query =
        lattice ? glm::dvec3(static_cast<double>(rng.NextU32() % 11) - 1.0,
                             static_cast<double>(rng.NextU32() % 11) - 1.0,
                             static_cast<double>(rng.NextU32() % 11) - 1.0)
                : glm::dvec3(rng.Uniform(-extent, extent) * 1.2, rng.Uniform(-extent, extent) * 1.2,
                             rng.Uniform(-extent, extent) * 1.2);
    if (q % 10 == 0 && !points.empty()) query = points[rng.NextU32() % points.size()];  // a point
    for (double radius : {0.0, 0.37 * extent * rng.Uniform(), 0.1 * extent, 1.0, 2.0, 3.0,
                          std::sqrt(2.0), 4.0 * extent}) {
      ExpectSameHits(index->WithinRadius(query, radius),
                     geom::WithinRadiusLinear(points, query, radius), what);
    }
    for (std::size_t k : {1u, 2u, 5u, 17u, 64u, 1000u}) {
      ExpectSameHits(index->Nearest(query, k), geom::NearestLinear(points, query, k), what);
    }
  }
}

TEST(PointIndex, MatchesBruteForceOnRandomSets) {
  Pcg32 rng(2026, 12);
  for (int n : {1, 2, 7, 100, 1000, 5000}) {
    CheckSet(Spread(rng, n, 10.0), rng, 10.0, false, "spread");
  }
  // Far from the origin with a small spread: rounding of large coordinates.
  std::vector<glm::dvec3> far = Spread(rng, 2000, 0.01);
  for (glm::dvec3& p : far) p += glm::dvec3(1e5, -3e4, 7e5);
  Result<geom::PointIndex> index = geom::PointIndex::Build(far);
  ASSERT_TRUE(index.ok());
  for (int q = 0; q < 100; ++q) {
    const glm::dvec3 query = far[rng.NextU32() % far.size()] +
                             glm::dvec3(rng.Uniform(-0.01, 0.01), rng.Uniform(-0.01, 0.01), 0.0);
    for (double radius : {1e-4, 1e-3, 3e-3, 0.02}) {
      ExpectSameHits(index->WithinRadius(query, radius),
                     geom::WithinRadiusLinear(far, query, radius), "far");
    }
    ExpectSameHits(index->Nearest(query, 9), geom::NearestLinear(far, query, 9), "far knn");
  }
}

TEST(PointIndex, TiesAreOrderedByIndex) {
  Pcg32 rng(7, 1);
  for (int n : {50, 800, 3000}) CheckSet(Lattice(rng, n), rng, 9.0, true, "lattice");
  // Six points at distance 1 from the origin and duplicates: the k nearest are the lowest
  // indices among the ties.
  const std::vector<glm::dvec3> star = {{0, 0, 2}, {1, 0, 0},  {0, -1, 0}, {0, 0, 1}, {-1, 0, 0},
                                        {0, 1, 0}, {0, 0, -1}, {1, 0, 0},  {0, 0, 0}};
  Result<geom::PointIndex> index = geom::PointIndex::Build(star);
  ASSERT_TRUE(index.ok());
  const std::vector<PointHit> three = index->Nearest(glm::dvec3(0.0), 3);
  ASSERT_EQ(three.size(), 3u);
  EXPECT_EQ(three[0].index, 8u);  // the origin itself
  EXPECT_EQ(three[1].index, 1u);  // then distance 1, lowest indices first
  EXPECT_EQ(three[2].index, 2u);
  const std::vector<PointHit> unit = index->WithinRadius(glm::dvec3(0.0), 1.0);
  ASSERT_EQ(unit.size(), 8u);  // radius inclusive: all but (0, 0, 2)
  const uint32_t order[] = {8, 1, 2, 3, 4, 5, 6, 7};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(unit[i].index, order[i]);
}

TEST(PointIndex, EdgeCasesAndErrors) {
  Result<geom::PointIndex> empty = geom::PointIndex::Build({});
  ASSERT_TRUE(empty.ok());
  EXPECT_TRUE(empty->WithinRadius(glm::dvec3(0.0), 10.0).empty());
  EXPECT_TRUE(empty->Nearest(glm::dvec3(0.0), 3).empty());
  Result<geom::PointIndex> two = geom::PointIndex::Build({{0, 0, 0}, {3, 4, 0}});
  ASSERT_TRUE(two.ok());
  EXPECT_TRUE(two->Nearest(glm::dvec3(0.0), 0).empty());
  EXPECT_EQ(two->Nearest(glm::dvec3(0.0), 10).size(), 2u);        // fewer points than k
  EXPECT_EQ(two->WithinRadius(glm::dvec3(0.0), 5.0).size(), 2u);  // exactly on the radius
  EXPECT_DOUBLE_EQ(two->WithinRadius(glm::dvec3(0.0), 5.0)[1].distance_squared, 25.0);
  EXPECT_TRUE(two->WithinRadius(glm::dvec3(0.0), -1.0).empty());
  EXPECT_TRUE(two->WithinRadius(glm::dvec3(0.0), std::nan("")).empty());
  // A moved index still answers (its tree refers to points it owns).
  geom::PointIndex moved = std::move(two).value();
  EXPECT_EQ(moved.Nearest(glm::dvec3(3, 4, 1), 1)[0].index, 1u);
  Result<geom::PointIndex> bad =
      geom::PointIndex::Build({{0, 0, 0}, {1, std::numeric_limits<double>::infinity(), 0}});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().field(), "points");
  EXPECT_EQ(bad.status().Line(), "points: point 1 is not finite");
}

}  // namespace
}  // namespace niwa
