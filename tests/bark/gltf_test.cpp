// The bark run's .glb: a trunk segment of the grown patch's radius and height (metres, y up), the
// tile once around with the seam's vertices on one another at whole u, once along, an exact
// tangent frame, triangles facing out, and the three maps embedded as the same PNG bytes MapPng
// gives; refused before the run has grown; Parts() is the same mesh and material.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "bark/bark_gltf.h"
#include "bark/bark_run.h"

namespace niwa::bark {
namespace {

constexpr double kPi = 3.14159265358979323846;

BarkState SmallBark(const char* model) {
  BarkState s;
  EXPECT_TRUE(SetBarkSpecies("tallow", &s).ok());
  EXPECT_TRUE(SetBarkSize("32x16", &s).ok());
  EXPECT_TRUE(SetBarkModel(model, &s).ok());
  EXPECT_TRUE(s.params.Set(BarkParam::kMapSize, 256).ok());
  if (std::string(model) == "4layer") {
    EXPECT_TRUE(s.params.Set(BarkParam::kCycles, 2).ok());
    EXPECT_TRUE(s.params.SetFromAssignment("T=0.002").ok());
  }
  return s;
}

TEST(BarkGltf, TheTileWrapsWholeTimesAround) {
  EXPECT_EQ(TileWraps(0.05, 2 * kPi * 0.05), 1);
  EXPECT_EQ(TileWraps(0.05, 2 * kPi * 0.05 / 3.2), 3);
  EXPECT_EQ(TileWraps(0.001, 1.0), 1);  // a twig thinner than the tile wears one
  EXPECT_EQ(TileWraps(0.05, 0), 1);
}

TEST(BarkGltf, TheSegmentIsACylinderWithItsTileFrame) {
  const double r = 0.061, h = 0.215, tile = 2 * kPi * r / 2;  // two wraps
  const geom::TriMesh m = TrunkSegmentMesh(r, h, tile);
  const int ring = kTrunkSides + 1;
  ASSERT_EQ(m.vertex_count(), static_cast<std::size_t>(2 * ring));
  ASSERT_EQ(m.triangle_count(), static_cast<std::size_t>(2 * kTrunkSides));
  const geom::VertexAttribute* t = m.FindAttribute("TANGENT");
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->components, 4);
  for (std::size_t i = 0; i < m.vertex_count(); ++i) {
    const glm::vec3 p = m.positions[i], n = m.normals[i];
    EXPECT_NEAR(std::hypot(p.x, p.z), r, 1e-7);
    EXPECT_TRUE(p.y == 0.0f || p.y == static_cast<float>(h));
    EXPECT_NEAR(m.uvs[i].y, p.y == 0.0f ? 1.0 : 0.0, 0.0);  // v: 0 at the top, 1 at the base
    EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
    EXPECT_NEAR(n.x * r, p.x, 1e-7);  // outward
    EXPECT_NEAR(n.z * r, p.z, 1e-7);
    const glm::vec3 tan(t->values[4 * i], t->values[4 * i + 1], t->values[4 * i + 2]);
    EXPECT_NEAR(glm::length(tan), 1.0, 1e-6);
    EXPECT_NEAR(glm::dot(tan, n), 0.0, 1e-6);
    EXPECT_EQ(t->values[4 * i + 3], 1.0f);
    // The bitangent cross(n, t)·w points up the trunk: the normal map's +y (the image's up).
    EXPECT_NEAR(glm::cross(n, tan).y, 1.0, 1e-6);
  }
  // The seam: the last column sits on the first, u a whole number of wraps further.
  for (int r0 : {0, ring}) {
    EXPECT_EQ(m.positions[r0], m.positions[r0 + kTrunkSides]);
    EXPECT_EQ(m.uvs[r0].x, 0.0f);
    EXPECT_EQ(m.uvs[r0 + kTrunkSides].x, 2.0f);
  }
  // u grows with the angle, evenly: no stretch around.
  for (int k = 1; k <= kTrunkSides; ++k)
    EXPECT_NEAR(m.uvs[k].x - m.uvs[k - 1].x, 2.0 / kTrunkSides, 1e-6);
  // Every triangle faces out (its winding's normal along the vertex normals).
  for (std::size_t k = 0; k < m.indices.size(); k += 3) {
    const glm::vec3 a = m.positions[m.indices[k]], b = m.positions[m.indices[k + 1]],
                    c = m.positions[m.indices[k + 2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    EXPECT_GT(glm::dot(face, m.normals[m.indices[k]] + m.normals[m.indices[k + 1]]), 0.0f);
  }
}

TEST(BarkGltf, AGrownRunIsATrunkOfItsRadiusWearingItsMaps) {
  for (const char* model : {"2layer", "4layer"}) {
    SCOPED_TRACE(model);
    Result<BarkRun> run = BarkRun::Start(SmallBark(model), Budget{});
    ASSERT_TRUE(run.ok());
    Result<gltf::Document> before = run->Document();
    ASSERT_FALSE(before.ok());
    EXPECT_EQ(before.status().field(), "bark");
    EXPECT_TRUE(run->Parts().empty());
    ASSERT_TRUE(run->Advance({}).ok());
    Result<gltf::Document> doc = run->Document();
    ASSERT_TRUE(doc.ok()) << doc.status().Line();
    const Growth g = run->growth();
    const double radius = run->lattice().radius() * g.s_theta / 100;
    const double height = run->lattice().height() * g.s_z / 100;
    EXPECT_GT(g.s_theta, 1.0f);  // the grown radius, not R_o
    ASSERT_EQ(doc->meshes.size(), 1u);
    const geom::TriMesh& m = doc->meshes[0].primitives[0].mesh;
    float top = 0;
    for (const glm::vec3& p : m.positions) {
      EXPECT_NEAR(std::hypot(p.x, p.z), radius, 1e-6);
      top = std::max(top, p.y);
    }
    EXPECT_NEAR(top, height, 1e-6);
    EXPECT_EQ(m.uvs[kTrunkSides].x, 1.0f);  // the real circumference: the tile once around
    ASSERT_EQ(doc->textures.size(), 3u);
    const gltf::Material& mat = doc->materials.at(0);
    EXPECT_EQ(mat.base_color_texture, 0);
    EXPECT_EQ(mat.normal_texture, 1);
    EXPECT_EQ(mat.occlusion_texture, 2);
    EXPECT_EQ(mat.metallic_roughness_texture, 2);
    const char* maps[3] = {"base_colour", "normal", "orm"};
    for (int k = 0; k < 3; ++k) {
      Result<std::string> png = run->MapPng(maps[k]);
      ASSERT_TRUE(png.ok());
      EXPECT_EQ(std::string(doc->textures[k].png.begin(), doc->textures[k].png.end()), *png)
          << maps[k];
      EXPECT_EQ(doc->textures[k].wrap_s, gltf::Wrap::kRepeat);
    }
    const nlohmann::json extras = nlohmann::json::parse(doc->asset_extras_json);
    EXPECT_EQ(extras["hash"], run->Hash(""));
    EXPECT_EQ(extras["wraps"], 1);
    Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
    ASSERT_TRUE(glb.ok()) << glb.status().Line();
    Result<Estimate> e = run->ExportEstimate("glb");
    ASSERT_TRUE(e.ok());
    EXPECT_GT(e->memory_bytes, static_cast<double>(glb->size()));
    const std::vector<run::Part> parts = run->Parts();
    ASSERT_EQ(parts.size(), 1u);
    EXPECT_EQ(parts[0].mesh.positions, m.positions);
    EXPECT_EQ(parts[0].textures.size(), 3u);
    EXPECT_EQ(parts[0].material.normal_texture, 1);
  }
  Result<BarkRun> run = BarkRun::Start(SmallBark("2layer"), Budget{});
  ASSERT_TRUE(run.ok());
  EXPECT_EQ(run->ExportEstimate("obj").status().field(), "format");
}

}  // namespace
}  // namespace niwa::bark
