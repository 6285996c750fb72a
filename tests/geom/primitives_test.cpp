// Primitives (counts, area, outward winding, normals, uvs) and Subdivide (4^K counts, area kept,
// coplanar children, watertight edges, attributes interpolated).
#include "geom/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "geom/mesh_metrics.h"
#include "geom/triangle_queries.h"
#include "math/det_math.h"

namespace niwa::geom {
namespace {

// Signed volume by the divergence theorem: positive when every triangle winds outward.
double SignedVolume(const TriMesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    DVec3 a = ToD(m.positions[m.indices[3 * t]]), b = ToD(m.positions[m.indices[3 * t + 1]]),
          c = ToD(m.positions[m.indices[3 * t + 2]]);
    v += Dot(a, Cross(b, c)) / 6.0;
  }
  return v;
}

DVec3 FaceNormal(const TriMesh& m, std::size_t t) {
  DVec3 a = ToD(m.positions[m.indices[3 * t]]), b = ToD(m.positions[m.indices[3 * t + 1]]),
        c = ToD(m.positions[m.indices[3 * t + 2]]);
  DVec3 n = Cross(Sub(b, a), Sub(c, a));
  return Mul(n, 1.0 / std::sqrt(Dot(n, n)));
}

// Every undirected edge, by vertex positions (so duplicated seam/face vertices count as one), is
// used exactly twice, once in each direction: closed and consistently wound.
void ExpectClosedByPosition(const TriMesh& m) {
  auto key = [&](uint32_t i) {
    const glm::vec3& p = m.positions[i];
    return std::make_tuple(p.x, p.y, p.z);
  };
  std::map<std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>, int> uses;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      ++uses[{key(m.indices[3 * t + static_cast<std::size_t>(k)]),
              key(m.indices[3 * t + static_cast<std::size_t>((k + 1) % 3)])}];
  int bad = 0;
  for (const auto& [edge, n] : uses) {
    auto reverse = uses.find({edge.second, edge.first});
    if (n != 1 || reverse == uses.end() || reverse->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0) << "edges not used once each way, of " << uses.size();
}

void ExpectWellFormed(const TriMesh& m) {
  ASSERT_TRUE(ValidateMesh(m).ok()) << ValidateMesh(m).Line();
  ASSERT_EQ(m.normals.size(), m.vertex_count());
  ASSERT_EQ(m.uvs.size(), m.vertex_count());
  for (std::size_t i = 0; i < m.vertex_count(); ++i) {
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f);
    EXPECT_GE(m.uvs[i].x, 0.0f);
    EXPECT_LE(m.uvs[i].x, 1.0f);
    EXPECT_GE(m.uvs[i].y, 0.0f);
    EXPECT_LE(m.uvs[i].y, 1.0f);
  }
  EXPECT_EQ(CountDegenerateTriangles(m), 0u);
}

TEST(Primitives, Box) {
  TriMesh box = MakeBox({2.0f, 3.0f, 4.0f}, {1.0f, 0.0f, -1.0f});
  ExpectWellFormed(box);
  EXPECT_EQ(box.vertex_count(), 24u);
  EXPECT_EQ(box.triangle_count(), 12u);
  EXPECT_DOUBLE_EQ(SurfaceArea(box), 2.0 * (6 + 12 + 8));
  EXPECT_NEAR(SignedVolume(box), 24.0, 1e-9);
  Bounds3 b = MeshBounds(box);
  EXPECT_EQ(b.min, glm::vec3(0.0f, -1.5f, -3.0f));
  EXPECT_EQ(b.max, glm::vec3(2.0f, 1.5f, 1.0f));
  for (std::size_t t = 0; t < box.triangle_count(); ++t) {  // vertex normals match the winding
    DVec3 n = FaceNormal(box, t);
    glm::vec3 vn = box.normals[box.indices[3 * t]];
    EXPECT_NEAR(Dot(n, ToD(vn)), 1.0, 1e-12);
  }
  ExpectClosedByPosition(box);
}

TEST(Primitives, Plane) {
  TriMesh p = MakePlane(4.0f, 2.0f, 4, 3);
  ExpectWellFormed(p);
  EXPECT_EQ(p.vertex_count(), 20u);
  EXPECT_EQ(p.triangle_count(), 24u);
  EXPECT_NEAR(SurfaceArea(p), 8.0, 1e-6);
  for (std::size_t t = 0; t < p.triangle_count(); ++t) EXPECT_NEAR(FaceNormal(p, t).y, 1.0, 1e-12);
  EXPECT_EQ(MakePlane(1, 1, 0, -3).triangle_count(), 2u);  // segments clamped to 1
}

TEST(Primitives, Cylinder) {
  const int n = 32;
  TriMesh c = MakeCylinder(0.5f, 2.0f, n, true);
  ExpectWellFormed(c);
  EXPECT_EQ(c.triangle_count(), static_cast<std::size_t>(4 * n));
  // A regular n-gon prism: area of the sides and caps, volume of the prism.
  double polygon = 0.5 * n * 0.25 * det::Sin(2.0 * det::kPi / n);
  double side = n * 2.0 * (2.0 * 0.5 * det::Sin(det::kPi / n));
  EXPECT_NEAR(SurfaceArea(c), side + 2 * polygon, 1e-5);
  EXPECT_NEAR(SignedVolume(c), polygon * 2.0, 1e-5);
  ExpectClosedByPosition(c);
  TriMesh open = MakeCylinder(0.5f, 2.0f, n, false);
  EXPECT_EQ(open.triangle_count(), static_cast<std::size_t>(2 * n));
  EXPECT_EQ(MakeCylinder(1, 1, 1, false).triangle_count(), 6u);  // segments clamped to 3
}

TEST(Primitives, Icosphere) {
  for (int level = 0; level <= 4; ++level) {
    TriMesh s = MakeIcosphere(2.0f, level);
    ExpectWellFormed(s);
    std::size_t tris = 20u << (2 * level);
    EXPECT_EQ(s.triangle_count(), tris);
    EXPECT_EQ(s.vertex_count(), tris / 2 + 2);  // Euler: V = F/2 + 2 for a closed triangulation
    EXPECT_GT(SignedVolume(s), 0.0);            // outward
    for (const glm::vec3& p : s.positions) EXPECT_NEAR(glm::length(p), 2.0f, 1e-5f);
    ExpectClosedByPosition(s);
  }
  // Level 4 is within 1 % of the sphere's area and volume.
  TriMesh s = MakeIcosphere(2.0f, 4);
  EXPECT_NEAR(SurfaceArea(s) / (4 * det::kPi * 4), 1.0, 0.01);
  EXPECT_NEAR(SignedVolume(s) / (4.0 / 3.0 * det::kPi * 8), 1.0, 0.01);
}

TEST(Subdivide, CountsAreaAndCoplanarChildren) {
  TriMesh base = MakeIcosphere(1.0f, 1);  // 80 triangles, shared vertices
  for (int k = 0; k <= 3; ++k) {
    TriMesh s = Subdivide(base, k);
    ASSERT_TRUE(ValidateMesh(s).ok());
    std::size_t factor = std::size_t{1} << (2 * k);
    EXPECT_EQ(s.triangle_count(), base.triangle_count() * factor);
    // Shared edges get one midpoint each: V = F/2 + 2 stays true.
    EXPECT_EQ(s.vertex_count(), s.triangle_count() / 2 + 2);
    EXPECT_NEAR(SurfaceArea(s) / SurfaceArea(base), 1.0, 1e-6);
    for (std::size_t t = 0; t < s.triangle_count(); ++t) {  // child t lies in parent t / 4^k
      DVec3 child = FaceNormal(s, t), parent = FaceNormal(base, t / factor);
      ASSERT_NEAR(Dot(child, parent), 1.0, 1e-5) << "triangle " << t;
    }
    ExpectClosedByPosition(s);
  }
}

TEST(Subdivide, BoxStaysClosedAndAttributesAreInterpolated) {
  TriMesh box = MakeBox({2.0f, 1.0f, 3.0f});
  VertexAttribute& x = box.AddAttribute("x_copy", 1);
  for (std::size_t i = 0; i < box.vertex_count(); ++i) x.values[i] = box.positions[i].x;
  TriMesh s = Subdivide(box, 3);
  EXPECT_EQ(s.triangle_count(), 12u * 64u);
  EXPECT_DOUBLE_EQ(SurfaceArea(s), SurfaceArea(box));  // exact: all midpoints are dyadic
  ExpectClosedByPosition(s);
  ExpectWellFormed(s);
  const VertexAttribute* xs = s.FindAttribute("x_copy");
  ASSERT_NE(xs, nullptr);
  ASSERT_EQ(xs->values.size(), s.vertex_count());
  for (std::size_t i = 0; i < s.vertex_count(); ++i) {
    EXPECT_FLOAT_EQ(xs->values[i], s.positions[i].x);
    EXPECT_FLOAT_EQ(
        std::fabs(s.normals[i].x) + std::fabs(s.normals[i].y) + std::fabs(s.normals[i].z), 1.0f);
  }
  EXPECT_EQ(Subdivide(box, -2).triangle_count(), 12u);
}

}  // namespace
}  // namespace niwa::geom
