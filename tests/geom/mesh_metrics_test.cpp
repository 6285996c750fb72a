// Mesh metrics: areas, bounds, degenerate triangles and ValidateMesh's one-line errors.
#include "geom/mesh_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geom/primitives.h"
#include "support/test_meshes.h"

namespace niwa::geom {
namespace {

TriMesh TwoTriangles() {
  TriMesh m;
  m.positions = {{0, 0, 0}, {3, 0, 0}, {0, 4, 0}, {0, 0, 2}};
  m.indices = {0, 1, 2, 0, 1, 3};
  return m;
}

TEST(MeshMetrics, AreaAndBounds) {
  TriMesh m = TwoTriangles();
  EXPECT_DOUBLE_EQ(TriangleArea(m, 0), 6.0);
  EXPECT_DOUBLE_EQ(TriangleArea(m, 1), 3.0);
  EXPECT_DOUBLE_EQ(SurfaceArea(m), 9.0);
  m.positions.push_back({100, 100, 100});  // unused: not in the bounds
  Bounds3 b = MeshBounds(m);
  EXPECT_EQ(b.min, glm::vec3(0, 0, 0));
  EXPECT_EQ(b.max, glm::vec3(3, 4, 2));
  EXPECT_EQ(b.centre(), glm::vec3(1.5f, 2.0f, 1.0f));
  EXPECT_EQ(b.diagonal(), glm::vec3(3, 4, 2));
  EXPECT_TRUE(MeshBounds(TriMesh{}).empty());
}

TEST(MeshMetrics, Bounds3Basics) {
  Bounds3 b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.diagonal(), glm::vec3(0));
  EXPECT_EQ(b.SurfaceArea(), 0.0f);
  b.Extend(glm::vec3(1, 2, 3));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.SurfaceArea(), 0.0f);
  Bounds3 c;
  c.Extend(glm::vec3(-1, 0, 0));
  b.Extend(c);
  b.Extend(Bounds3{});  // empty: no change
  EXPECT_EQ(b.min, glm::vec3(-1, 0, 0));
  EXPECT_EQ(b.max, glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(b.SurfaceArea(), 2.0f * (2 * 2 + 2 * 3 + 3 * 2));
  EXPECT_TRUE(b.Contains(glm::vec3(0, 1, 1)));
  EXPECT_FALSE(b.Contains(glm::vec3(0, 1, 4)));
}

TEST(MeshMetrics, DegenerateTrianglesAreCountedAndRemoved) {
  TriMesh m = TwoTriangles();
  m.positions.push_back({6, 0, 0});                                // collinear with 0 and 1
  m.indices.insert(m.indices.end(), {0, 1, 4, 2, 2, 3, 3, 0, 1});  // zero area, repeated, fine
  EXPECT_TRUE(IsDegenerateTriangle(m, 2));
  EXPECT_TRUE(IsDegenerateTriangle(m, 3));
  EXPECT_FALSE(IsDegenerateTriangle(m, 4));
  EXPECT_EQ(CountDegenerateTriangles(m), 2u);
  EXPECT_EQ(RemoveDegenerateTriangles(&m), 2u);
  ASSERT_EQ(m.triangle_count(), 3u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 1, 3, 3, 0, 1}));  // order kept
  EXPECT_EQ(CountDegenerateTriangles(m), 0u);
  TriMesh thin = test::ThinDegenerateMesh(1);
  std::size_t before = thin.triangle_count(), degenerate = CountDegenerateTriangles(thin);
  EXPECT_GT(degenerate, 20u);
  EXPECT_EQ(RemoveDegenerateTriangles(&thin), degenerate);
  EXPECT_EQ(thin.triangle_count(), before - degenerate);
}

TEST(MeshMetrics, ValidateMeshNamesTheProblem) {
  EXPECT_TRUE(ValidateMesh(MakeIcosphere(1, 2)).ok());
  TriMesh nan = TwoTriangles();
  nan.positions[2].y = std::nanf("");
  Status s = ValidateMesh(nan, "wall.glb");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.Line(),
            "wall.glb: position of vertex 2 is NaN or infinite; every coordinate must be finite");
  TriMesh inf = TwoTriangles();
  inf.positions[0].x = std::numeric_limits<float>::infinity();
  EXPECT_NE(ValidateMesh(inf).Line().find("vertex 0 is NaN or infinite"), std::string::npos);
  TriMesh range = TwoTriangles();
  range.indices[4] = 9;
  EXPECT_EQ(ValidateMesh(range).Line(),
            "mesh: index 9 of triangle 1 is out of range; must be in [0, 3]");
  EXPECT_EQ(ValidateMesh(TriMesh{}).Line(), "mesh: has no triangles; must have at least 1");
  TriMesh ragged = TwoTriangles();
  ragged.indices.push_back(0);
  EXPECT_EQ(ValidateMesh(ragged).Line(),
            "mesh: index count 7 is not a multiple of 3 (three indices per triangle)");
  TriMesh normals = TwoTriangles();
  normals.normals.resize(3);
  EXPECT_EQ(ValidateMesh(normals).Line(),
            "mesh: 3 normals for 4 vertices; must be 0 or one per vertex");
  TriMesh attr = TwoTriangles();
  attr.AddAttribute("birth_step", 1).values.pop_back();
  EXPECT_EQ(ValidateMesh(attr).Line(),
            "mesh: attribute birth_step has 3 values; must be 1 per vertex (components >= 1)");
  for (const Status& e : {ValidateMesh(nan), ValidateMesh(range), ValidateMesh(TriMesh{})})
    EXPECT_EQ(e.Line().find('\n'), std::string::npos);
}

// FaceNormals (a support without normals, as the ivy page draws it): each vertex its triangles'
// unit face normal from the winding; a shared vertex the area-weighted sum; an unused one +y.
TEST(MeshMetrics, FaceNormalsFollowTheWinding) {
  TriMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
  mesh.indices = {0, 1, 2, 0, 3, 1};  // +z face (area 1/2), then +y face (z × x, area 1/2)
  const std::vector<glm::vec3> n = FaceNormals(mesh);
  ASSERT_EQ(n.size(), 5u);
  EXPECT_EQ(n[2], glm::vec3(0, 0, 1));
  EXPECT_EQ(n[3], glm::vec3(0, 1, 0));
  const float h = 1.0f / std::sqrt(2.0f);
  for (int v : {0, 1}) {  // shared by both faces
    EXPECT_NEAR(n[static_cast<std::size_t>(v)].x, 0.0f, 1e-6f);
    EXPECT_NEAR(n[static_cast<std::size_t>(v)].y, h, 1e-6f);
    EXPECT_NEAR(n[static_cast<std::size_t>(v)].z, h, 1e-6f);
  }
  EXPECT_EQ(n[4], glm::vec3(0, 1, 0));  // in no triangle
}

}  // namespace
}  // namespace niwa::geom
