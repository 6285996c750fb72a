// ClosestPoint: hand-computed cases (face, edge and vertex regions, radius, ties) and the BVH
// against ClosestPointLinear on thousands of seeded queries over several meshes.
#include "geom/closest_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geom/linear_queries.h"
#include "geom/primitives.h"
#include "geom_oracle.h"
#include "support/test_meshes.h"

namespace niwa::geom {
namespace {

TriMesh OneTriangle() {
  TriMesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  m.indices = {0, 1, 2};
  return m;
}

TEST(ClosestPoint, FaceEdgeAndVertexRegions) {
  TriMesh m = OneTriangle();
  Bvh bvh = Bvh::Build(m);
  // Above the face: straight down, distance 3, barycentrics (0.5, 0.25, 0.25).
  ClosestHit face = ClosestPoint(m, bvh, {0.5f, 0.5f, 3.0f}, 10.0f);
  ASSERT_TRUE(face.found);
  EXPECT_FLOAT_EQ(face.distance, 3.0f);
  EXPECT_FLOAT_EQ(face.point.x, 0.5f);
  EXPECT_FLOAT_EQ(face.point.y, 0.5f);
  EXPECT_FLOAT_EQ(face.point.z, 0.0f);
  EXPECT_FLOAT_EQ(face.barycentric.x, 0.5f);
  EXPECT_FLOAT_EQ(face.barycentric.y, 0.25f);
  EXPECT_FLOAT_EQ(face.barycentric.z, 0.25f);
  // Beyond vertex a = (0,0,0): the vertex itself, distance sqrt(2).
  ClosestHit va = ClosestPoint(m, bvh, {-1.0f, -1.0f, 0.0f}, 10.0f);
  EXPECT_FLOAT_EQ(va.distance, std::sqrt(2.0f));
  EXPECT_FLOAT_EQ(va.barycentric.x, 1.0f);
  // Beyond the hypotenuse bc at (2, 2, 0): its midpoint (1, 1, 0), distance sqrt(2).
  ClosestHit e = ClosestPoint(m, bvh, {2.0f, 2.0f, 0.0f}, 10.0f);
  EXPECT_FLOAT_EQ(e.point.x, 1.0f);
  EXPECT_FLOAT_EQ(e.point.y, 1.0f);
  EXPECT_FLOAT_EQ(e.distance, std::sqrt(2.0f));
  EXPECT_FLOAT_EQ(e.barycentric.y, 0.5f);
  EXPECT_FLOAT_EQ(e.barycentric.z, 0.5f);
  // Below edge ab at (1, -2, 1): the point (1, 0, 0), distance sqrt(5).
  ClosestHit ab = ClosestPoint(m, bvh, {1.0f, -2.0f, 1.0f}, 10.0f);
  EXPECT_FLOAT_EQ(ab.point.x, 1.0f);
  EXPECT_FLOAT_EQ(ab.point.y, 0.0f);
  EXPECT_FLOAT_EQ(ab.distance, std::sqrt(5.0f));
}

TEST(ClosestPoint, RadiusIsInclusiveAndBadRadiiFindNothing) {
  TriMesh m = OneTriangle();
  Bvh bvh = Bvh::Build(m);
  EXPECT_TRUE(ClosestPoint(m, bvh, {0.5f, 0.5f, 3.0f}, 3.0f).found);
  EXPECT_FALSE(ClosestPoint(m, bvh, {0.5f, 0.5f, 3.0f}, 2.999f).found);
  EXPECT_FALSE(ClosestPoint(m, bvh, {0.5f, 0.5f, 0.0f}, -1.0f).found);
  EXPECT_FALSE(ClosestPoint(m, bvh, {0.5f, 0.5f, 0.0f}, std::nanf("")).found);
  EXPECT_TRUE(
      ClosestPoint(m, bvh, {0.5f, 0.5f, 1e6f}, std::numeric_limits<float>::infinity()).found);
  EXPECT_TRUE(ClosestPoint(m, bvh, {0.5f, 0.5f, 0.0f}, 0.0f).found);  // on the face, radius 0
}

TEST(ClosestPoint, TiesGoToTheLowestTriangle) {
  // Two triangles sharing the edge x = 0 (mirror images): a point on the plane x = 0 above the edge
  // is equally far from both.
  TriMesh m;
  m.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {-1, 0, 0}};
  m.indices = {0, 2, 1, 0, 1, 3};
  Bvh bvh = Bvh::Build(m);
  ClosestHit h = ClosestPoint(m, bvh, {0.0f, 0.5f, 1.0f}, 5.0f);
  ASSERT_TRUE(h.found);
  EXPECT_EQ(h.triangle, 0u);
  TriMesh swapped = m;
  swapped.indices = {0, 1, 3, 0, 2, 1};
  EXPECT_EQ(ClosestPoint(swapped, Bvh::Build(swapped), {0.0f, 0.5f, 1.0f}, 5.0f).triangle, 0u);
}

TEST(ClosestPoint, StatsCountNodesAndTriangles) {
  TriMesh m = MakeIcosphere(1.0f, 4);  // 5120 triangles
  Bvh bvh = Bvh::Build(m);
  QueryStats bvh_stats, linear_stats;
  Pcg32 rng(3);
  for (int i = 0; i < 200; ++i) {
    glm::vec3 p = test::RandomDirection(rng) * 1.1f;
    (void)ClosestPoint(m, bvh, p, 0.5f, &bvh_stats);
    (void)ClosestPointLinear(m, p, 0.5f, &linear_stats);
  }
  EXPECT_EQ(bvh_stats.queries, 200u);
  EXPECT_EQ(linear_stats.triangles_tested, 200u * 5120u);
  EXPECT_EQ(linear_stats.nodes_visited, 0u);
  EXPECT_GT(bvh_stats.nodes_visited, 200u);
  // Near the surface the BVH touches a small part of the mesh.
  EXPECT_LT(bvh_stats.TrianglesPerQuery(), 0.02 * 5120);
  EXPECT_LT(bvh_stats.NodesPerQuery(), 200.0);
}

TEST(ClosestPoint, BvhEqualsLinearOnThousandsOfQueries) {
  uint64_t seed = 100;
  for (const test::OracleCase& c : test::OracleMeshes()) {
    Bvh bvh = Bvh::Build(c.mesh);
    test::OracleCounts counts = test::CompareWithLinear(c.mesh, bvh, 3000, seed++);
    SCOPED_TRACE(c.name);
    EXPECT_EQ(counts.closest_mismatch, 0) << counts.first_mismatch;
    EXPECT_GT(counts.closest_found, 1000);  // the comparison covered real hits
    EXPECT_LT(counts.closest_found, 3000);  // and misses
    std::printf("%-16s closest: %d found of %d, ray: %d hits, segment: %d hits\n", c.name,
                counts.closest_found, counts.queries, counts.ray_hits, counts.segment_hits);
  }
}

}  // namespace
}  // namespace niwa::geom
