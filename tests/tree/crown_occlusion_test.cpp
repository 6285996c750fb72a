// Unit tests of the crown ambient occlusion (tree/crown_occlusion.h): inner leaves see less sky.
#include "tree/crown_occlusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "random/pcg32.h"
#include "support/grow.h"
#include "tree/mesh.h"

namespace niwa {
namespace {

// A double-sided square leaf of side `size` (metres) at `centre`, facing +y, as tree/mesh.h writes
// leaves: each face its own two triangles.
void AddLeaf(MeshBuffers* part, const glm::dvec3& centre, double size) {
  const uint32_t first = static_cast<uint32_t>(part->vertex_count());
  const double h = 0.5 * size;
  for (const auto& [dx, dz] : {std::pair{-h, -h}, {h, -h}, {h, h}, {-h, h}}) {
    part->positions.insert(part->positions.end(),
                           {static_cast<float>(centre.x + dx), static_cast<float>(centre.y),
                            static_cast<float>(centre.z + dz)});
    part->normals.insert(part->normals.end(), {0.0f, 1.0f, 0.0f});
  }
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u, 0u, 2u, 1u, 0u, 3u, 2u})
    part->indices.push_back(first + i);
}

// `count` leaves of side `size` at uniform random points of a ball of `radius` around `centre`.
MeshBuffers LeafBall(int count, double radius, double size, const glm::dvec3& centre = {0, 2, 0}) {
  MeshBuffers leaves;
  Pcg32 rng(7);
  while (count > 0) {
    const glm::dvec3 p(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
    if ((p.x * p.x + p.y * p.y) + p.z * p.z > 1.0) continue;
    AddLeaf(&leaves, centre + radius * p, size);
    --count;
  }
  return leaves;
}

TEST(CrownOcclusion, DeepInADenseBallMoreThanOnItsSkin) {
  // 4000 leaves of 10 cm in a ball of 1 m around (0, 2, 0): 40 m² one-sided in 4.19 m³, LAD about
  // 9.5 m²/m³; a trunk from the ground to the ball widens the grid down to y = 0.
  const MeshBuffers leaves = LeafBall(4000, 1.0, 0.1);
  MeshBuffers trunk;
  trunk.positions = {0, 0, 0, 0, 1, 0};
  const CrownOcclusionField field({&leaves}, {&trunk});
  const double centre = field.At({0, 2, 0});
  const double top = field.At({0, 2.95, 0});
  const double side = field.At({0.95, 2, 0});
  const double under = field.At({0, 0.5, 0});
  // From the centre every sky direction crosses 1 m of leaves: tau ≈ 0.5 · 9.5 · 1 ≈ 4.8.
  EXPECT_GT(centre, 0.9);
  EXPECT_LT(top, 0.5 * centre);  // the zenith and the 45° directions leave the ball at once
  EXPECT_LT(side, centre);
  // 1.5 m below the ball's centre only the zenith crosses it (2 m of leaves): 1/9 of the sky,
  // and a little more where the grid's cells blur the ball's edge.
  EXPECT_GT(under, 0.1);
  EXPECT_LT(under, 0.3);
  EXPECT_EQ(field.At({0, 10, 0}), 0.0);  // outside the grid's box: open sky
  EXPECT_EQ(field.At({5, 2, 0}), 0.0);
}

TEST(CrownOcclusion, DenserCrownOccludesMore) {
  const MeshBuffers sparse = LeafBall(200, 1.0, 0.1), dense = LeafBall(2000, 1.0, 0.1);
  const double a = CrownOcclusionField({&sparse}).At({0, 2, 0});
  const double b = CrownOcclusionField({&dense}).At({0, 2, 0});
  EXPECT_GT(a, 0.05);
  EXPECT_GT(b, a + 0.2);
}

TEST(CrownOcclusion, NoLeavesNoOcclusion) {
  const MeshBuffers empty;
  const CrownOcclusionField field({&empty});
  EXPECT_EQ(field.At({0, 0, 0}), 0.0);
  MeshBuffers bark;
  AddLeaf(&bark, {0, 1, 0}, 0.1);
  EXPECT_EQ(field.AtVertices(bark), std::vector<float>(4, 0.0f));
}

TEST(CrownOcclusion, GrownTreeInnerLeavesDarkerThanOuterOnes) {
  const TreeMesh mesh = BuildTreeMesh(testing::GrowPreset("keyaki", 12));
  ASSERT_GT(mesh.leaves.vertex_count(), 1000u);
  const CrownOcclusion occlusion = ComputeCrownOcclusion(mesh);
  ASSERT_EQ(occlusion.leaves.size(), mesh.leaves.vertex_count());
  ASSERT_EQ(occlusion.bark.size(), mesh.bark.vertex_count());
  ASSERT_EQ(occlusion.flowers.size(), mesh.flowers.vertex_count());
  // The leaves' box; the leaf nearest its centre (deep in the crown) against the highest leaf.
  const std::vector<float>& p = mesh.leaves.positions;
  glm::dvec3 lo(p[0], p[1], p[2]), hi = lo;
  for (std::size_t v = 0; v < mesh.leaves.vertex_count(); ++v) {
    const glm::dvec3 q(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::dvec3 mid = 0.5 * (lo + hi);
  std::size_t inner = 0, top = 0;
  double nearest = 1e30;
  for (std::size_t v = 0; v < mesh.leaves.vertex_count(); ++v) {
    const glm::dvec3 q(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
    const glm::dvec3 d = q - mid;
    const double d2 = (d.x * d.x + d.y * d.y) + d.z * d.z;
    if (d2 < nearest) nearest = d2, inner = v;
    if (q.y > p[3 * top + 1]) top = v;
  }
  EXPECT_GT(occlusion.leaves[inner], occlusion.leaves[top] + 0.1)
      << "inner " << occlusion.leaves[inner] << " top " << occlusion.leaves[top];
  for (float o : occlusion.leaves) ASSERT_TRUE(o >= 0.0f && o <= 1.0f) << o;
  // The trunk's foot, under the crown, sees less sky than the highest leaf.
  std::size_t foot = 0;
  for (std::size_t v = 0; v < mesh.bark.vertex_count(); ++v) {
    if (mesh.bark.positions[3 * v + 1] < mesh.bark.positions[3 * foot + 1]) foot = v;
  }
  EXPECT_GT(occlusion.bark[foot], occlusion.leaves[top]);
}

}  // namespace
}  // namespace niwa
