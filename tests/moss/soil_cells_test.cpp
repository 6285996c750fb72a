// Soil cells on the land (core/moss/soil_cells.h): the split, the soil depth by face class on the
// thesis scene, the sky view, the cap, and geology from colours and material names.
#include "moss/soil_cells.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <map>

namespace niwa::moss {
namespace {

double Edge(const SoilCells& c, std::size_t t, int k) {
  const glm::dvec3 a(c.mesh.positions[c.mesh.indices[3 * t + k]]);
  const glm::dvec3 b(c.mesh.positions[c.mesh.indices[3 * t + (k + 1) % 3]]);
  return glm::length(a - b);
}

TEST(MossSoilCells, ThePlaneIsOpenGround) {
  SoilCellOptions options;
  options.sky_view = true;
  const SoilCells cells = *MakeSoilCells(*BuildScene("plane"), options);
  ASSERT_EQ(cells.size(), 3200u);  // the 5 cm squares' diagonals (7.07 cm) are below 7.5 cm
  double area = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    area += cells.area[i];
    EXPECT_EQ(cells.h[i], 1000.0);  // no hit below: open ground, h_max
    EXPECT_EQ(cells.V_sky[i], 1.0);
    EXPECT_GT(cells.normal[i].y, 0.999);
  }
  EXPECT_NEAR(area, 4.0, 1e-6);
  EXPECT_NEAR(cells.radius, std::sqrt(2.0), 1e-6);
  EXPECT_TRUE(cells.notices.empty());
}

TEST(MossSoilCells, SplittingKeepsTheAreaAndBoundsTheEdges) {
  SoilCellOptions options;
  options.soil_edge = 0.03;
  const SoilCells cells = *MakeSoilCells(*BuildScene("plane"), options);
  // Each right triangle (legs 5 cm) is halved three times: hypotenuses 7.07, 5, 3.54 cm.
  ASSERT_EQ(cells.size(), 3200u * 8);
  double area = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    area += cells.area[i];
    for (int k = 0; k < 3; ++k) ASSERT_LE(Edge(cells, i, k), 0.03 + 1e-7);
    ASSERT_GT(cells.normal[i].y, 0.999);  // the winding is kept
  }
  EXPECT_NEAR(area, 4.0, 1e-6);
}

TEST(MossSoilCells, OverTheCapTheEdgeDoublesOrTheSceneIsRefused) {
  SoilCellOptions options;
  options.soil_edge = 0.03;
  options.max_cells = 10000;  // 25,600 at 3 cm; 6,400 at 6 cm
  const SoilCells cells = *MakeSoilCells(*BuildScene("plane"), options);
  EXPECT_EQ(cells.size(), 6400u);
  EXPECT_DOUBLE_EQ(cells.soil_edge, 0.06);
  ASSERT_EQ(cells.notices.size(), 1u);
  // Fewer than the land's 3,200 triangles: each triangle is one cell (the cap is the land's own
  // count; the run's estimate decides whether it is grown), the edge doubled until none splits.
  options.max_cells = 1000;
  const SoilCells own = *MakeSoilCells(*BuildScene("plane"), options);
  EXPECT_EQ(own.size(), 3200u);
  EXPECT_DOUBLE_EQ(own.soil_edge, 0.12);
  ASSERT_EQ(own.notices.size(), 1u);
  EXPECT_NE(own.notices[0].find("the land's own triangles"), std::string::npos) << own.notices[0];
  // Refused when even 16 doublings leave a triangle split: one 1 km triangle at 5 mm.
  MossScene huge;
  huge.mesh.positions = {{0, 0, 0}, {0, 0, 1000}, {1000, 0, 0}};
  huge.mesh.indices = {0, 1, 2};
  huge.geology = {Geology::kHumus};
  huge.region = {0};
  huge.region_names = {"all"};
  options.soil_edge = 0.005;
  options.max_cells = 1;
  const Status refused = MakeSoilCells(huge, options).status();
  EXPECT_EQ(refused.field(), "scene");
  EXPECT_NE(refused.message().find("even at soil_edge"), std::string::npos) << refused.message();
}

TEST(MossSoilCells, ThesisSoilDepthByFaceClass) {
  SoilCellOptions options;
  options.sky_view = true;
  const MossScene scene = *BuildScene("thesis");
  const SoilCells cells = *MakeSoilCells(scene, options);
  ASSERT_EQ(cells.size(), scene.mesh.triangle_count());  // the 5 cm grid needs no split
  std::map<std::string, std::map<long, int>> depths;     // region -> rounded h -> cells
  std::map<std::string, double> mean_V, n_region;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::string& region = cells.region_names[cells.region[i]];
    if (std::abs(cells.normal[i].y) <= kVerticalNy) {
      ASSERT_EQ(cells.h[i], 1.0) << i;  // walls' sides: h_wall
    } else {
      depths[region][std::lround(cells.h[i])]++;
    }
    mean_V[region] += cells.V_sky[i];
    n_region[region] += 1;
  }
  // The slab (0.3 m) under the floor; the roof 5 cm thick; the wall top 1.8 m (clamped to 1000);
  // the stones' tops 0.4 + 0.3 and 0.25 + 0.3 m through the union of stone and slab.
  EXPECT_EQ(depths["floor_open"].size(), 1u);
  EXPECT_EQ(depths["floor_open"].begin()->first, 300);
  EXPECT_EQ(depths["floor_sheltered"].begin()->first, 300);
  EXPECT_EQ(depths["roof_under"].size(), 1u);
  EXPECT_EQ(depths["roof_under"].begin()->first, 50);
  EXPECT_EQ(depths["tops"], (std::map<long, int>{{50, 1120}, {550, 128}, {700, 128}, {1000, 160}}));
  EXPECT_EQ(depths["other"].begin()->first, 300);  // the slab's bottom, looking up
  for (auto& [region, v] : mean_V) v /= n_region[region];
  // Sky view: the roof's top sees the sky, its underside and the sheltered floor and wall little.
  EXPECT_GT(mean_V["tops"], 0.8);
  EXPECT_GT(mean_V["floor_open"], 0.6);  // the wall and roof hide the sky's back half near them
  auto V_near = [&](glm::dvec3 p) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (cells.normal[i].y > 0.5 &&
          glm::length(cells.centroid[i] - p) < glm::length(cells.centroid[best] - p))
        best = i;
    return cells.V_sky[best];
  };
  // The front edge sees the wall and roof low on the sky's back (about a tenth of the cosine
  // weight); under the roof's middle only rays below its edges escape: forward below 71° elevation
  // (z −0.2 is 0.35 m off at 1 m up) and sideways below 45° (about 0.4 of the weight).
  EXPECT_GT(V_near({0, 0, 0.97}), 0.85);
  EXPECT_GT(V_near({0, 0, -0.55}), 0.3);
  EXPECT_LT(V_near({0, 0, -0.55}), 0.45);
  EXPECT_LT(mean_V["roof_under"], 0.4);
  EXPECT_LT(mean_V["floor_sheltered"], 0.5);
  EXPECT_LT(mean_V["wall_sheltered"], 0.6);
  EXPECT_EQ(mean_V["other"], 1.0);  // the slab's bottom looks down at nothing
}

TEST(MossSoilCells, GeologyFromColoursAndNames) {
  EXPECT_EQ(GeologyOfColour({0x4A / 255.0, 0x33 / 255.0, 0x22 / 255.0}), Geology::kHumus);
  EXPECT_EQ(GeologyOfColour({0xC2 / 255.0, 0x9A / 255.0, 0x5B / 255.0}), Geology::kSandy);
  EXPECT_EQ(GeologyOfColour({0.5, 0.5, 0.5}), Geology::kAsphalt);
  EXPECT_EQ(GeologyOfColour({0.0, 0.0, 0.0}), Geology::kHumus);
  EXPECT_EQ(GeologyOfColour({1.0, 0.9, 0.6}), Geology::kSandy);
  Geology g;
  EXPECT_TRUE(GeologyOfMaterialName("Wet_Sand.001", &g));
  EXPECT_EQ(g, Geology::kSandy);
  EXPECT_TRUE(GeologyOfMaterialName("ASPHALT", &g));
  EXPECT_EQ(g, Geology::kAsphalt);
  EXPECT_FALSE(GeologyOfMaterialName("stone", &g));

  // Two triangles: the first grey by COLOR_0 (linear 0.2159 is sRGB 0x80), the second with a
  // material named humus over a sandy colour.
  geom::TriMesh mesh;
  mesh.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {3, 0, 0}};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  geom::VertexAttribute& colour = mesh.AddAttribute(io::kColorAttribute, 4);
  for (int v = 0; v < 6; ++v)
    for (int k = 0; k < 4; ++k) colour.values[4 * v + k] = v < 3 ? (k < 3 ? 0.2159f : 1.0f) : 1.0f;
  geom::VertexAttribute& material = mesh.AddAttribute(io::kMaterialAttribute, 1);
  for (int v = 0; v < 6; ++v) material.values[v] = v < 3 ? -1.0f : 0.0f;
  std::vector<io::MeshMaterial> materials(1);
  materials[0].name = "old humus";
  materials[0].base_color = glm::vec4(0.54f, 0.32f, 0.1f, 1.0f);
  const MossScene scene = SceneFromMesh(mesh, materials, "two.glb").value();
  EXPECT_EQ(scene.geology, (std::vector<Geology>{Geology::kAsphalt, Geology::kHumus}));
  materials[0].name = "plain";  // now the sandy colour (linear 0.54, 0.32, 0.1 ~ sRGB C29A5B) wins
  EXPECT_EQ(SceneFromMesh(mesh, materials, "two.glb")->geology[1], Geology::kSandy);
}

}  // namespace
}  // namespace niwa::moss
