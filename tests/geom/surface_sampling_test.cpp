// Surface sampling: points lie on their triangle, counts are area-proportional (chi-square), the
// same seed gives the same bits, and Poisson-disk points keep their distance.
#include "geom/surface_sampling.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "geom/triangle_queries.h"
#include "support/test_meshes.h"

namespace niwa::geom {
namespace {

TEST(SampleSurface, PointsLieOnTheirTriangle) {
  TriMesh m = test::RandomSoup(300, 4);
  std::vector<SurfaceSample> s = SampleSurface(m, 5000, 17);
  ASSERT_EQ(s.size(), 5000u);
  for (const SurfaceSample& p : s) {
    ASSERT_LT(p.triangle, m.triangle_count());
    DVec3 a = ToD(m.positions[m.indices[3 * p.triangle]]);
    DVec3 b = ToD(m.positions[m.indices[3 * p.triangle + 1]]);
    DVec3 c = ToD(m.positions[m.indices[3 * p.triangle + 2]]);
    TrianglePoint q = ClosestPointOnTriangle(ToD(p.point), a, b, c);
    EXPECT_LT(q.distance_squared, 1e-12);
    EXPECT_NEAR(p.barycentric.x + p.barycentric.y + p.barycentric.z, 1.0f, 1e-6f);
    EXPECT_GE(std::min({p.barycentric.x, p.barycentric.y, p.barycentric.z}), 0.0f);
    EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-5f);
    DVec3 n = Cross(Sub(b, a), Sub(c, a));
    EXPECT_GT(Dot(n, ToD(p.normal)), 0.0);  // the winding's side
  }
}

// Pearson's chi-square of triangle counts against n · area / total. 12 triangles of areas 1..12
// (plus zero-area ones that must get nothing): 11 degrees of freedom, whose 99.9 % quantile is
// 31.26; a sampler choosing triangles uniformly scores in the thousands here.
TEST(SampleSurface, CountsAreAreaProportional) {
  TriMesh m;
  for (int i = 1; i <= 12; ++i) {
    uint32_t base = static_cast<uint32_t>(m.positions.size());
    float x = 10.0f * static_cast<float>(i);
    m.positions.insert(m.positions.end(),
                       {{x, 0, 0}, {x + 2.0f * static_cast<float>(i), 0, 0}, {x, 1, 0}});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
    m.indices.insert(m.indices.end(), {base, base, base + 1});  // repeated index: zero area
  }
  const int n = 120000;
  std::vector<SurfaceSample> s = SampleSurface(m, n, 2024);
  std::vector<int> count(m.triangle_count(), 0);
  for (const SurfaceSample& p : s) ++count[p.triangle];
  double total = SurfaceArea(m), chi2 = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    if (t % 2 == 1) {
      EXPECT_EQ(count[t], 0) << "zero-area triangle " << t;
      continue;
    }
    double expected = n * TriangleArea(m, t) / total;
    chi2 += (count[t] - expected) * (count[t] - expected) / expected;
  }
  std::printf("chi-square %.2f (11 dof, bound 31.26)\n", chi2);
  EXPECT_LT(chi2, 31.26);
  // Within a triangle: the mean of uniform points is the centroid (barycentrics 1/3, within 0.01).
  glm::vec3 mean(0);
  for (const SurfaceSample& p : s) mean += p.barycentric;
  mean /= static_cast<float>(n);
  EXPECT_NEAR(mean.x, 1.0f / 3.0f, 0.01f);
  EXPECT_NEAR(mean.y, 1.0f / 3.0f, 0.01f);
}

TEST(SampleSurface, SameSeedSameBitsOtherSeedOtherPoints) {
  TriMesh m = MakeIcosphere(1.0f, 3);
  std::vector<SurfaceSample> a = SampleSurface(m, 1000, 5), b = SampleSurface(m, 1000, 5);
  std::vector<SurfaceSample> c = SampleSurface(m, 1000, 6);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(SurfaceSample)));
  int same = 0;
  for (std::size_t i = 0; i < a.size(); ++i) same += a[i].point == c[i].point ? 1 : 0;
  EXPECT_LT(same, 5);
}

TEST(SampleSurface, EmptyForNoAreaOrNoCount) {
  TriMesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.indices = {0, 1, 2};
  EXPECT_TRUE(SampleSurface(flat, 10, 1).empty());
  EXPECT_TRUE(SampleSurface(TriMesh{}, 10, 1).empty());
  EXPECT_TRUE(SampleSurface(MakeBox({1, 1, 1}), -3, 1).empty());
}

TEST(SamplePoissonDisk, KeepsTheMinimumDistance) {
  TriMesh m = MakeBox({1.0f, 1.0f, 1.0f});
  const float r = 0.08f;
  std::vector<SurfaceSample> s = SamplePoissonDisk(m, 400, r, 9);
  EXPECT_GT(s.size(), 300u);  // the 6 m² box holds ~ 6 / (0.866 r²) ≈ 1000 at most
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      ASSERT_GE(glm::length(s[i].point - s[j].point), r * (1.0f - 1e-6f)) << i << " " << j;
  std::vector<SurfaceSample> again = SamplePoissonDisk(m, 400, r, 9);
  ASSERT_EQ(again.size(), s.size());
  EXPECT_EQ(0, std::memcmp(again.data(), s.data(), s.size() * sizeof(SurfaceSample)));
  // Asking for more than fits stops at max_attempts.
  EXPECT_LT(SamplePoissonDisk(m, 100000, 0.2f, 9, 5000).size(), 300u);
}

}  // namespace
}  // namespace niwa::geom
