// Tangents for normal maps (geom/tangents): dP/du on a UV-mapped quad, a cylinder and planes with
// affine uv maps, w = +1 where the map's +Y runs along -dP/dv (glTF), and a unit tangent perpendicular to the normal (never
// NaN) for degenerate uvs and normals.
#include "geom/tangents.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "support/test_meshes.h"

namespace niwa::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 TangentOf(const std::vector<float>& t, std::size_t v) {
  return {t[v * 4], t[v * 4 + 1], t[v * 4 + 2]};
}

// Every tangent finite, unit, perpendicular to its (unit) normal, w exactly +-1.
void ExpectWellFormed(const TriMesh& m, const std::vector<float>& t) {
  ASSERT_EQ(t.size(), m.vertex_count() * 4);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const glm::vec3 x = TangentOf(t, v);
    ASSERT_TRUE(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)) << "vertex " << v;
    EXPECT_NEAR(glm::length(x), 1.0f, 1e-5f) << "vertex " << v;
    const glm::vec3 n = m.normals[v];
    if (glm::length(n) > 0) {
      EXPECT_NEAR(glm::dot(x, glm::normalize(n)), 0.0f, 1e-5f) << "vertex " << v;
    }
    EXPECT_TRUE(t[v * 4 + 3] == 1.0f || t[v * 4 + 3] == -1.0f) << "vertex " << v;
  }
}

// A unit quad in the xy plane, normal +z, u along +x (or -x when mirrored), v along +y.
TriMesh Quad(bool mirrored) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals.assign(4, {0, 0, 1});
  for (const glm::vec3& p : m.positions) m.uvs.push_back({mirrored ? 1 - p.x : p.x, p.y});
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

TEST(Tangents, QuadTangentIsDPdu) {
  TriMesh m = Quad(false);
  const std::vector<float> t = ComputeTangentValues(m);
  ExpectWellFormed(m, t);
  for (std::size_t v = 0; v < 4; ++v) {
    EXPECT_EQ(TangentOf(t, v), glm::vec3(1, 0, 0)) << "vertex " << v;
    // cross(+z, +x) = +y = dP/dv, but glTF's map +Y runs along -dP/dv (v grows down the image).
    EXPECT_EQ(t[v * 4 + 3], -1.0f);
  }
}

TEST(Tangents, MirroringFlipsTheHandedness) {
  TriMesh m = Quad(true);
  const std::vector<float> t = ComputeTangentValues(m);
  ExpectWellFormed(m, t);
  for (std::size_t v = 0; v < 4; ++v) {
    EXPECT_EQ(TangentOf(t, v), glm::vec3(-1, 0, 0)) << "vertex " << v;
    EXPECT_EQ(t[v * 4 + 3], 1.0f);  // cross(+z, -x) = -y = -dP/dv
  }
  // Mirrored in v instead: the tangent stays +x, the handedness flips.
  TriMesh flipped = Quad(false);
  for (glm::vec2& uv : flipped.uvs) uv.y = 1 - uv.y;
  const std::vector<float> f = ComputeTangentValues(flipped);
  for (std::size_t v = 0; v < 4; ++v) {
    EXPECT_EQ(TangentOf(f, v), glm::vec3(1, 0, 0));
    EXPECT_EQ(f[v * 4 + 3], 1.0f);  // dP/dv = -y: u right, v down, as an upright image
  }
}

// A cylinder of radius r around +y, `sides` columns with a seam (the first column repeated at
// u = 1), u = angle / 2 pi, v = height: at angle a, dP/du points along (-sin a, 0, cos a).
TriMesh Cylinder(int sides, float radius, float height) {
  TriMesh m;
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i <= sides; ++i) {
      const double a = 2 * kPi * i / sides;
      m.positions.push_back({static_cast<float>(radius * std::cos(a)),
                             static_cast<float>(row) * height,
                             static_cast<float>(radius * std::sin(a))});
      m.normals.push_back({static_cast<float>(std::cos(a)), 0, static_cast<float>(std::sin(a))});
      m.uvs.push_back({static_cast<float>(i) / static_cast<float>(sides), static_cast<float>(row)});
    }
  }
  const uint32_t stride = static_cast<uint32_t>(sides) + 1;
  for (uint32_t i = 0; i < static_cast<uint32_t>(sides); ++i) {
    m.indices.insert(m.indices.end(), {i, i + stride, i + 1, i + 1, i + stride, i + 1 + stride});
  }
  return m;
}

TEST(Tangents, CylinderTangentFollowsTheAngle) {
  const int sides = 24;
  TriMesh m = Cylinder(sides, 0.3f, 2.0f);
  const std::vector<float> t = ComputeTangentValues(m);
  ExpectWellFormed(m, t);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const double a = 2 * kPi * static_cast<double>(v % (sides + 1)) / sides;
    const glm::vec3 expected(static_cast<float>(-std::sin(a)), 0, static_cast<float>(std::cos(a)));
    EXPECT_NEAR(glm::dot(TangentOf(t, v), expected), 1.0f, 1e-5f) << "vertex " << v;
    // cross(n, dP/du) = -y = -dP/dv: the map's +Y runs down the cylinder, as v = 0 is its base
    // row and glTF's images have row 0 at the top.
    EXPECT_EQ(t[v * 4 + 3], 1.0f) << "vertex " << v;
  }
}

// Random triangles on a tilted plane with an affine uv map uv = M (x, y) + c in the plane's
// frame (x, y): dP/du is the same on every triangle, the first column of M's inverse mapped back,
// and w is minus the sign of det M (glTF's v grows down the image).
TEST(Tangents, AffineUvMapsOnAPlaneGiveTheExactDirection) {
  Pcg32 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const glm::vec3 n = test::RandomDirection(rng);
    const glm::vec3 x = glm::normalize(
        glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 y = glm::cross(n, x);
    const double m00 = test::UniformF(rng, -2, 2), m01 = test::UniformF(rng, -2, 2);
    const double m10 = test::UniformF(rng, -2, 2), m11 = test::UniformF(rng, -2, 2);
    const double det = m00 * m11 - m01 * m10;
    if (std::abs(det) < 0.2) continue;
    TriMesh m;
    for (int i = 0; i < 30; ++i) {
      const double a = test::UniformF(rng, -1, 1), b = test::UniformF(rng, -1, 1);
      m.positions.push_back(x * static_cast<float>(a) + y * static_cast<float>(b));
      m.normals.push_back(n);
      m.uvs.push_back({static_cast<float>(m00 * a + m01 * b + 0.5),
                       static_cast<float>(m10 * a + m11 * b - 0.25)});
    }
    for (uint32_t i = 0; i + 2 < 30; ++i) m.indices.insert(m.indices.end(), {i, i + 1, i + 2});
    const std::vector<float> t = ComputeTangentValues(m);
    ExpectWellFormed(m, t);
    // (a, b) = M^-1 (uv - c): d(a, b)/du = (m11, -m10) / det.
    const glm::vec3 expected =
        glm::normalize(x * static_cast<float>(m11 / det) - y * static_cast<float>(m10 / det));
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      EXPECT_NEAR(glm::dot(TangentOf(t, v), expected), 1.0f, 1e-4f) << "trial " << trial;
      EXPECT_EQ(t[v * 4 + 3], det > 0 ? -1.0f : 1.0f) << "trial " << trial;
    }
  }
}

TEST(Tangents, DegenerateUvsAndNormalsAreNeverNan) {
  TriMesh m = Quad(false);
  m.uvs.assign(4, {0.5f, 0.5f});  // every triangle's uvs collapse to a point
  ExpectWellFormed(m, ComputeTangentValues(m));
  m.uvs = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};  // collinear uvs
  ExpectWellFormed(m, ComputeTangentValues(m));
  // A tangent along the normal (the uv map's u runs along z at a tilted normal) and a zero normal.
  TriMesh tilted = Quad(false);
  tilted.normals = {{1, 0, 0}, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}};
  std::vector<float> t = ComputeTangentValues(tilted);
  ExpectWellFormed(tilted, t);
  EXPECT_EQ(TangentOf(t, 2), glm::vec3(1, 0, 0));
  // Zero-area triangles and an unused vertex.
  TriMesh flat = Quad(false);
  flat.positions[2] = flat.positions[0];
  flat.positions.push_back({5, 5, 5});
  flat.normals.push_back({0, 1, 0});
  flat.uvs.push_back({0, 0});
  ExpectWellFormed(flat, ComputeTangentValues(flat));
  // Random soups with random normals and uvs.
  Pcg32 rng(11);
  TriMesh soup = test::RandomSoup(200, 3);
  for (std::size_t v = 0; v < soup.vertex_count(); ++v) {
    soup.normals.push_back(test::RandomDirection(rng));
    soup.uvs.push_back({test::UniformF(rng, 0, 1), test::UniformF(rng, 0, 1)});
  }
  ExpectWellFormed(soup, ComputeTangentValues(soup));
}

TEST(Tangents, NeedsNormalsAndUvs) {
  TriMesh m = Quad(false);
  m.uvs.clear();
  EXPECT_TRUE(ComputeTangentValues(m).empty());
  EXPECT_FALSE(ComputeTangents(&m));
  EXPECT_EQ(m.FindAttribute(kTangentAttribute), nullptr);
  m = Quad(false);
  m.normals.clear();
  EXPECT_FALSE(ComputeTangents(&m));
  m = Quad(false);
  ASSERT_TRUE(ComputeTangents(&m));
  const VertexAttribute* a = m.FindAttribute(kTangentAttribute);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->components, 4);
  EXPECT_EQ(a->values, ComputeTangentValues(m));
  ASSERT_TRUE(ComputeTangents(&m));  // again: overwritten, not added twice
  EXPECT_EQ(m.attributes.size(), 1u);
}

}  // namespace
}  // namespace niwa::geom
