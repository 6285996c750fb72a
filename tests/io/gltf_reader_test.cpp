// glTF reader tests: node transforms land where hand computation says,
// strips/fans/points/degenerate triangles, Draco equals its uncompressed twin, real ez-tree assets,
// and each hostile file's one line.
#include "io/gltf_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "support/files.h"

namespace niwa::io {
namespace {

using ::niwa::testing::MeshPath;

using Tri = std::array<glm::vec3, 3>;

Tri TriangleAt(const geom::TriMesh& m, std::size_t t) {
  return {m.positions[m.indices[3 * t]], m.positions[m.indices[3 * t + 1]],
          m.positions[m.indices[3 * t + 2]]};
}

bool Near(const glm::vec3& a, const glm::vec3& b, float tol) {
  return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol && std::fabs(a.z - b.z) <= tol;
}

// True when the mesh holds the triangle with this winding (any starting corner).
bool HasTriangle(const geom::TriMesh& m, const Tri& want, float tol = 1e-5f) {
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    Tri got = TriangleAt(m, t);
    for (int r = 0; r < 3; ++r) {
      if (Near(got[r], want[0], tol) && Near(got[(r + 1) % 3], want[1], tol) &&
          Near(got[(r + 2) % 3], want[2], tol)) {
        return true;
      }
    }
  }
  return false;
}

// Triangles as sorted, winding-preserving tuples of exact coordinates.
std::vector<std::array<float, 9>> CanonicalTriangles(const geom::TriMesh& m) {
  std::vector<std::array<float, 9>> out;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    Tri tri = TriangleAt(m, t);
    std::array<std::array<float, 9>, 3> rotations;
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) {
        const glm::vec3& v = tri[(r + k) % 3];
        rotations[r][3 * k] = v.x;
        rotations[r][3 * k + 1] = v.y;
        rotations[r][3 * k + 2] = v.z;
      }
    }
    out.push_back(*std::min_element(rotations.begin(), rotations.end()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

glm::vec3 FaceNormal(const Tri& t) {
  glm::vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  glm::vec3 n(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x);
  float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  return n / len;
}

TEST(GltfReader, HierarchyTransformsLandWhereHandComputationSays) {
  MeshReadStats stats;
  Result<geom::TriMesh> mesh = ReadGltfFile(MeshPath("hierarchy.glb"), &stats);
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  const geom::TriMesh& m = *mesh;
  // Default scene 1 (not the decoy scene 0): 7 mesh instances, 7 triangle primitives, one POINTS
  // primitive skipped, one degenerate triangle skipped.
  EXPECT_EQ(stats.meshes, 7u);
  EXPECT_EQ(stats.primitives, 7u);
  EXPECT_EQ(stats.skipped_points_lines, 1u);
  EXPECT_EQ(stats.degenerate, 1u);
  EXPECT_EQ(m.triangle_count(), 9u);
  EXPECT_EQ(m.vertex_count(), 24u);
  // root T(10,0,0) * rotated Rz(90): (x, y, z) -> (10 - y, x, z).
  EXPECT_TRUE(HasTriangle(m, {{{10, 0, 0}, {10, 1, 0}, {9, 0, 0}}}));
  // ... * scaled T(0,0,1) S(2,3,4): (1,0,0) -> (2,0,1) -> (10,2,1); (0,1,0) -> (0,3,1) -> (7,0,1).
  EXPECT_TRUE(HasTriangle(m, {{{10, 0, 1}, {10, 2, 1}, {7, 0, 1}}}));
  // matrix = T(0,5,0) S(2), a strip: {v0 v1 v2}, {v1 v3 v2}.
  EXPECT_TRUE(HasTriangle(m, {{{10, 5, 0}, {12, 5, 0}, {10, 7, 0}}}));
  EXPECT_TRUE(HasTriangle(m, {{{12, 5, 0}, {12, 7, 0}, {10, 7, 0}}}));
  // mirror T(0,-5,0) S(-1,1,1): corners (10,-5,0), (9,-5,0), (10,-4,0), winding flipped.
  EXPECT_TRUE(HasTriangle(m, {{{10, -5, 0}, {10, -4, 0}, {9, -5, 0}}}));
  EXPECT_FALSE(HasTriangle(m, {{{10, -5, 0}, {9, -5, 0}, {10, -4, 0}}}));
  // fan T(0,0,-3): {v1 v2 v0}, {v2 v3 v0}.
  EXPECT_TRUE(HasTriangle(m, {{{11, 0, -3}, {11, 1, -3}, {10, 0, -3}}}));
  EXPECT_TRUE(HasTriangle(m, {{{11, 1, -3}, {10, 1, -3}, {10, 0, -3}}}));
  // mixed, a scene root T(0,10,0): the one non-degenerate triangle.
  EXPECT_TRUE(HasTriangle(m, {{{0, 10, 0}, {1, 10, 0}, {0, 10, 1}}}));
  // squash T(0,0,20) S(1,1,2).
  EXPECT_TRUE(HasTriangle(m, {{{1, 0, 20}, {0, 1, 20}, {0, 0, 22}}}));
  for (const glm::vec3& p : m.positions) EXPECT_LT(p.x, 50.0f) << "decoy scene 0 was read";
  // Every vertex normal (by the inverse transpose, then normalized) agrees with its flat face:
  // the mirrored triangle's flipped winding, and squash's (1,1,1) becoming (2,2,1)/3.
  ASSERT_EQ(m.normals.size(), m.vertex_count());
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    glm::vec3 face = FaceNormal(TriangleAt(m, t));
    for (int k = 0; k < 3; ++k) {
      const glm::vec3& n = m.normals[m.indices[3 * t + static_cast<std::size_t>(k)]];
      EXPECT_GT(face.x * n.x + face.y * n.y + face.z * n.z, 0.99999f) << "triangle " << t;
    }
  }
}

TEST(GltfReader, EmbeddedAndExternalBuffers) {
  for (const char* name : {"embedded.gltf", "external.gltf"}) {
    Result<geom::TriMesh> mesh = ReadGltfFile(MeshPath(name));
    ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
    EXPECT_EQ(mesh->triangle_count(), 1u) << name;
    EXPECT_TRUE(HasTriangle(*mesh, {{{1, 2, 3}, {2, 2, 3}, {1, 3, 3}}}, 0.0f)) << name;
  }
}

TEST(GltfReader, ExternalBufferRefusedWithoutABaseFolder) {
  std::ifstream in(MeshPath("external.gltf"));
  std::stringstream text;
  text << in.rdbuf();
  Result<geom::TriMesh> mesh = ReadGltfMesh(text.str(), "external.gltf", "");
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.status().Line(),
            "external.gltf: external file 'external.bin' cannot be read here; "
            "embed buffers as data: URIs or use .glb");
}

TEST(GltfReader, DracoDecodesToItsUncompressedTwin) {
  Result<geom::TriMesh> twin = ReadGltfFile(MeshPath("draco_twin.glb"));
  ASSERT_TRUE(twin.ok()) << twin.status().Line();
  EXPECT_EQ(twin->triangle_count(), 72u);
  MeshReadStats stats;
  Result<geom::TriMesh> draco = ReadGltfFile(MeshPath("draco.glb"), &stats);
  if (!GltfReaderDecodesDraco()) {
    ASSERT_FALSE(draco.ok());
    EXPECT_EQ(draco.status().Line(),
              "draco.glb: mesh 0 'grid' primitive 0 is Draco-compressed "
              "(KHR_draco_mesh_compression); this build cannot decode Draco: the page decodes it "
              "before handing the mesh over");
    return;
  }
  ASSERT_TRUE(draco.ok()) << draco.status().Line();
  EXPECT_EQ(stats.draco_primitives, 1u);
  // Same triangles, same winding, same float positions (Draco without quantization is lossless);
  // only their order and the vertex numbering may differ.
  EXPECT_EQ(CanonicalTriangles(*draco), CanonicalTriangles(*twin));
}

TEST(GltfReader, RealEzTreeAssets) {
  // Index counts read from the files' JSON: flower_blue 2364 (7 primitives), grass 18, rock1 5268
  // (Draco, EXT_texture_webp required).
  struct Asset {
    const char* name;
    std::size_t triangles;
    bool draco;
  };
  for (const Asset& a : {Asset{"flower_blue.glb", 788, false}, Asset{"grass.glb", 6, false},
                         Asset{"rock1.glb", 1756, true}}) {
    MeshReadStats stats;
    Result<geom::TriMesh> mesh = ReadGltfFile(MeshPath(a.name), &stats);
    if (a.draco && !GltfReaderDecodesDraco()) {
      ASSERT_FALSE(mesh.ok());
      EXPECT_NE(mesh.status().Line().find("this build cannot decode Draco"), std::string::npos);
      continue;
    }
    ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
    EXPECT_EQ(mesh->triangle_count() + stats.degenerate, a.triangles) << a.name;
    EXPECT_GT(mesh->triangle_count(), 0u);
    for (const glm::vec3& p : mesh->positions) {
      ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << a.name;
    }
  }
}

TEST(GltfReader, HostileFilesGiveOneLine) {
  struct Case {
    const char* file;
    std::string line;
  };
  const Case cases[] = {
      {"empty.glb", "empty.glb: the file is empty"},
      {"truncated.glb",
       "truncated.glb: truncated: the .glb header says 3316 bytes, the file has 1989"},
      {"not_gltf.glb",
       "not_gltf.glb: not glTF: neither a binary .glb (magic 'glTF') nor glTF JSON"},
      {"nan.glb", "nan.glb: mesh 0 'nan' primitive 0 POSITION 1 is NaN or infinite"},
      {"lines_only.glb", "lines_only.glb: only points or lines (2 primitives), no triangles"},
      {"required_ext.glb",
       "required_ext.glb: required extension EXT_niwa_unknown is not supported"},
      {"too_many_triangles.glb",
       "too_many_triangles.glb: 4096000 triangles in the scene; the limit is 4000000 (4 M)"},
      {"cycle.glb", "cycle.glb: the node hierarchy has a cycle through node 0"},
  };
  for (const Case& c : cases) {
    Result<geom::TriMesh> mesh = ReadGltfFile(MeshPath(c.file));
    ASSERT_FALSE(mesh.ok()) << c.file;
    EXPECT_EQ(mesh.status().Line(), c.line);
  }
  Result<geom::TriMesh> missing = ReadGltfFile(MeshPath("no_such_mesh.glb"));
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().Line(), "no_such_mesh.glb: cannot open '" +
                                         MeshPath("no_such_mesh.glb") +
                                         "' (missing or unreadable)");
  Result<geom::TriMesh> no_bin = ReadGltfFile(MeshPath("missing_bin.gltf"));
  ASSERT_FALSE(no_bin.ok());
  const std::string line = no_bin.status().Line();
  EXPECT_EQ(line.rfind("missing_bin.gltf: cannot parse glTF: ", 0), 0u) << line;
  EXPECT_NE(line.find("no_such_file.bin"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
}

TEST(GltfReader, MaterialsAndVertexColours) {
  MeshReadStats stats;
  Result<geom::TriMesh> mesh = ReadGltfFile(MeshPath("materials.glb"), &stats);
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  ASSERT_EQ(stats.materials.size(), 2u);
  EXPECT_EQ(stats.materials[0].name, "noivy_glass");
  EXPECT_FALSE(stats.materials[0].ivy_support);
  EXPECT_EQ(stats.materials[0].base_color, glm::vec4(0.5f, 0.625f, 0.75f, 0.875f));
  EXPECT_EQ(stats.materials[1].name, "humus");
  EXPECT_TRUE(stats.materials[1].ivy_support);
  EXPECT_EQ(stats.materials[1].base_color, glm::vec4(1.0f));
  const geom::VertexAttribute* material = mesh->FindAttribute(kMaterialAttribute);
  const geom::VertexAttribute* color = mesh->FindAttribute(kColorAttribute);
  ASSERT_NE(material, nullptr);
  ASSERT_NE(color, nullptr);
  ASSERT_EQ(mesh->vertex_count(), 9u);
  ASSERT_EQ(material->values.size(), 9u);
  ASSERT_EQ(color->values.size(), 36u);
  // Vertices 0-2 glass (material 0, no COLOR_0: white), 3-5 soil (material 1, normalized bytes
  // 255 -> 1, 51 -> 0.2), 6-8 no material (-1).
  const std::vector<float> want_material = {0, 0, 0, 1, 1, 1, -1, -1, -1};
  EXPECT_EQ(material->values, want_material);
  for (int k = 0; k < 12; ++k) EXPECT_EQ(color->values[static_cast<std::size_t>(k)], 1.0f);
  const std::vector<float> soil(color->values.begin() + 12, color->values.begin() + 24);
  const std::vector<float> want_soil = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 0.2f};
  EXPECT_EQ(soil, want_soil);
}

TEST(GltfReader, MeshFileDispatchesByExtension) {
  Result<geom::TriMesh> glb = ReadMeshFile(MeshPath("hierarchy.glb"));
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  EXPECT_EQ(glb->triangle_count(), 9u);
  Result<geom::TriMesh> other = ReadMeshFile(MeshPath("README.md"));
  ASSERT_FALSE(other.ok());
  EXPECT_EQ(other.status().Line(),
            "README.md: unknown mesh file extension '.md'; must be .glb, .gltf or .obj");
}

// A dropped file's bytes by its name (the page's loadMesh): .obj/.OBJ is OBJ text, else glTF; the
// same mesh as the file read from disk.
TEST(GltfReader, MeshBytesDispatchByName) {
  const auto slurp = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  };
  for (const char* name : {"hierarchy.glb", "embedded.gltf", "shapes.obj"}) {
    MeshReadStats read_file, read_bytes;
    Result<geom::TriMesh> file = ReadMeshFile(MeshPath(name), &read_file);
    ASSERT_TRUE(file.ok()) << file.status().Line();
    Result<geom::TriMesh> bytes = ReadMeshBytes(slurp(MeshPath(name)), name, &read_bytes);
    ASSERT_TRUE(bytes.ok()) << bytes.status().Line();
    EXPECT_EQ(bytes->positions, file->positions) << name;
    EXPECT_EQ(bytes->indices, file->indices) << name;
    // glTF names its unit (metres, §3.4); OBJ none.
    const double metres = std::string(name) == "shapes.obj" ? 0 : 1;
    EXPECT_EQ(read_file.metres_per_unit, metres) << name;
    EXPECT_EQ(read_bytes.metres_per_unit, metres) << name;
  }
  Result<geom::TriMesh> upper = ReadMeshBytes(slurp(MeshPath("shapes.obj")), "SHAPES.OBJ");
  EXPECT_TRUE(upper.ok()) << upper.status().Line();
  // OBJ text under a glTF name is read as glTF and refused, naming the file.
  Result<geom::TriMesh> wrong = ReadMeshBytes(slurp(MeshPath("shapes.obj")), "shapes.glb");
  ASSERT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.status().field(), "shapes.glb");
}

}  // namespace
}  // namespace niwa::io
