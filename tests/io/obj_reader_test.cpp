// OBJ reader tests: fan triangulation, negative indices and v/vt/vn forms, against tinyobjloader as
// an independent twin on a valid file, and one line naming the OBJ line for each kind of bad input.
#include "io/obj_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <sstream>
#include <vector>

#include "support/files.h"

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

namespace niwa::io {
namespace {

using ::niwa::testing::MeshPath;

std::vector<std::array<float, 9>> Triangles(const geom::TriMesh& m) {
  std::vector<std::array<float, 9>> out;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    std::array<float, 9> tri;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3& p = m.positions[m.indices[3 * t + static_cast<std::size_t>(k)]];
      tri[3 * k] = p.x;
      tri[3 * k + 1] = p.y;
      tri[3 * k + 2] = p.z;
    }
    out.push_back(tri);
  }
  return out;
}

TEST(ObjReader, ShapesFanTriangulatedWithNegativeIndicesAndAllCornerForms) {
  MeshReadStats stats;
  Result<geom::TriMesh> mesh = ReadObjFile(MeshPath("shapes.obj"), &stats);
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  EXPECT_EQ(mesh->vertex_count(), 12u);
  EXPECT_EQ(mesh->triangle_count(), 6u);  // quad 2 + pentagon 3 + triangle 1
  EXPECT_EQ(stats.primitives, 4u);        // four f lines
  EXPECT_EQ(stats.degenerate, 1u);        // f 10 10 11
  EXPECT_EQ(stats.skipped_points_lines, 1u);
  const std::vector<std::array<float, 9>> want = {
      {0, 0, 0, 0, 0, 1, 1, 0, 1},  {0, 0, 0, 1, 0, 1, 1, 0, 0},  // quad 1 4 3 2 as (1 4 3) (1 3 2)
      {0, 1, 0, 2, 1, 0, 3, 1, 1},  {0, 1, 0, 3, 1, 1, 1, 1, 2},  // pentagon -5..-1 = 5..9
      {0, 1, 0, 1, 1, 2, -1, 1, 1}, {0, 5, 0, 0, 5, 1, 1, 5, 0},
  };
  EXPECT_EQ(Triangles(*mesh), want);
}

// tinyobjloader, untriangulated, fanned and filtered the same way: the independent twin.
TEST(ObjReader, MatchesTinyObjLoaderOnAValidFile) {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  ASSERT_TRUE(tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err,
                               MeshPath("shapes.obj").c_str(), nullptr, false))
      << err;
  std::vector<std::array<float, 9>> twin;
  auto at = [&](int i) {
    const std::size_t k = static_cast<std::size_t>(i);
    return glm::vec3(attrib.vertices[3 * k], attrib.vertices[3 * k + 1],
                     attrib.vertices[3 * k + 2]);
  };
  for (const tinyobj::shape_t& s : shapes) {
    std::size_t offset = 0;
    for (unsigned char n : s.mesh.num_face_vertices) {
      for (std::size_t k = 1; k + 1 < n; ++k) {
        int ia = s.mesh.indices[offset].vertex_index, ib = s.mesh.indices[offset + k].vertex_index,
            ic = s.mesh.indices[offset + k + 1].vertex_index;
        if (ia == ib || ib == ic || ia == ic || DegenerateTriangle(at(ia), at(ib), at(ic)))
          continue;
        glm::vec3 a = at(ia), b = at(ib), c = at(ic);
        twin.push_back({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z});
      }
      offset += n;
    }
  }
  Result<geom::TriMesh> mesh = ReadObjFile(MeshPath("shapes.obj"));
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  EXPECT_EQ(Triangles(*mesh), twin);
}

TEST(ObjReader, BadInputNamesTheLine) {
  const std::pair<std::string, std::string> cases[] = {
      {"", "t.obj: the file is empty"},
      {"v 0 0 nan\n", "t.obj: line 1: vertex position is NaN or infinite"},
      {"v 0 0 inf\n", "t.obj: line 1: vertex position is NaN or infinite"},
      {"v 0 0\n", "t.obj: line 1: a vertex needs three numbers: v x y z"},
      {"v 1 2 3abc\n", "t.obj: line 1: vertex coordinate '3abc' is not a number"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n",
       "t.obj: line 4: a face needs at least 3 vertices, got 2"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
       "t.obj: line 4: vertex index 0 is out of range; must be in [1, 3] or [-3, -1]"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n",
       "t.obj: line 4: vertex index -4 is out of range; must be in [1, 3] or [-3, -1]"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n",
       "t.obj: line 5: texture index 2 is out of range; must be in [1, 1] or [-1, -1]"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n",
       "t.obj: line 4: normal index 1 is out of range; none are defined yet"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n",
       "t.obj: line 4: texture index 'x' is not a whole number; none are defined yet"},
      {"hello world\n", "t.obj: line 1: unknown statement 'hello' (not an OBJ file?)"},
      {std::string("v 0\0 0 0\n", 9), "t.obj: not OBJ text: the file holds binary data"},
      {"v 0 0 0\nv 1 0 0\nl 1 2\np 1\n", "t.obj: only points or lines (2 statements), no faces"},
      {"v 0 0 0\n", "t.obj: no faces (f lines)"},
      {"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "t.obj: every triangle is degenerate (zero area)"},
      // Issue 34: indices past 32 bits give the same line natively and in WASM (long is 32 bits
      // there: this index was "not a whole number" in WASM, "out of range" natively).
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3000000000\n",
       "t.obj: line 4: vertex index 3000000000 is out of range; must be in [1, 3] or [-3, -1]"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4294967297\n",
       "t.obj: line 4: vertex index -4294967297 is out of range; must be in [1, 3] or [-3, -1]"},
  };
  for (const auto& [text, line] : cases) {
    Result<geom::TriMesh> mesh = ReadObjMesh(text, "t.obj");
    ASSERT_FALSE(mesh.ok()) << text;
    EXPECT_EQ(mesh.status().Line(), line);
  }
  Result<geom::TriMesh> file = ReadObjFile(MeshPath("bad_index.obj"));
  ASSERT_FALSE(file.ok());
  EXPECT_EQ(file.status().Line(),
            "bad_index.obj: line 5: vertex index 9 is out of range; must be in [1, 3] or [-3, -1]");
  Result<geom::TriMesh> via_dispatch = ReadMeshFile(MeshPath("bad_index.obj"));
  EXPECT_EQ(via_dispatch.status().Line(), file.status().Line());
}

TEST(ObjReader, CrlfAndCommentsAreAccepted) {
  Result<geom::TriMesh> mesh =
      ReadObjMesh("# a comment\r\nv 0 0 0\r\nv 1 0 0 # x\r\nv 0 1 0\r\nf 1 2 3\r\n", "crlf.obj");
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  EXPECT_EQ(mesh->triangle_count(), 1u);
}

}  // namespace
}  // namespace niwa::io
