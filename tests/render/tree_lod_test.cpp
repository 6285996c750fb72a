// core/render/tree_lod: a budgeted .glb stays within its triangles, keeps the thickest wood as
// tubes, turns foliage into textured leaf-cluster cards, and LOD levels keep their ratios.
#include "render/tree_lod.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <string>
#include <vector>

#include "support/glb_parse.h"
#include "support/grow.h"
#include "tree/mesh.h"

namespace niwa {
namespace {

const Tree& Sakura15() {
  static const Tree tree = testing::GrowPreset("sakura", 15);
  return tree;
}

// The 20,000-triangle level and the three LOD levels of Sakura15, built once for the tests that
// only read them (each build took 0.5-1 s; eight tests built the same ones).
const Result<LodMesh>& Lod20k() {
  static const Result<LodMesh> lod = BuildLodMesh(Sakura15(), 20000);
  return lod;
}
const Result<std::vector<LodMesh>>& Levels20k() {
  static const Result<std::vector<LodMesh>> levels = BuildLodLevels(Sakura15(), 20000);
  return levels;
}

// Triangles of the TRIANGLES primitives (mode 4 or absent) of one mesh of a parsed .glb.
long Triangles(const MeshBuffers& b) { return static_cast<long>(b.indices.size() / 3); }

long GlbTriangles(const testing::Glb& glb, std::size_t mesh) {
  long sum = 0;
  for (const auto& p : glb.gltf["meshes"][mesh]["primitives"]) {
    if (p.value("mode", 4) != 4) continue;
    sum += glb.gltf["accessors"][p["indices"].get<std::size_t>()]["count"].get<long>() / 3;
  }
  return sum;
}

TEST(TreeLod, FullMeshWhenItFits) {
  const long full = FullTriangles(BuildTreeMesh(Sakura15()));
  Result<LodMesh> lod = BuildLodMesh(Sakura15(), full);
  ASSERT_TRUE(lod.ok()) << lod.status().Line();
  EXPECT_TRUE(lod->choice.full);
  EXPECT_EQ(lod->choice.triangles, full);
  EXPECT_TRUE(lod->cards.indices.empty());
  EXPECT_TRUE(lod->twigs.indices.empty());
}

TEST(TreeLod, TwentyThousandTrianglesAndTheGlbAgrees) {
  const long full = FullTriangles(BuildTreeMesh(Sakura15()));
  ASSERT_GT(full, 100000);  // the 489 k tree: the budget has work to do
  const Result<LodMesh>& lod = Lod20k();
  ASSERT_TRUE(lod.ok()) << lod.status().Line();
  const LodChoice& c = lod->choice;
  EXPECT_FALSE(c.full);
  EXPECT_TRUE(c.leaf_clusters);
  EXPECT_LE(c.triangles, 20000);
  EXPECT_GE(c.triangles, 10000);  // the wood takes what the foliage leaves (at most half)
  EXPECT_GT(c.tubes, 0);
  EXPECT_GT(c.clusters, 0);
  EXPECT_GT(c.twigs, 0);
  EXPECT_TRUE(lod->parts.leaves.indices.empty());
  std::vector<unsigned char> bytes;
  ASSERT_TRUE(WriteLodGlb({*lod}, &bytes).ok());
  testing::Glb glb = testing::ParseGlb(bytes);
  ASSERT_EQ(glb.gltf["nodes"].size(), 1u);
  EXPECT_EQ(glb.gltf["nodes"][0]["name"], "tree");
  EXPECT_EQ(GlbTriangles(glb, 0), c.triangles);
  // Twigs are cones of 3 triangles (4 vertices) a branch, and nothing is drawn as lines.
  EXPECT_EQ(Triangles(lod->twigs), 3L * c.twigs);
  EXPECT_EQ(lod->twigs.vertex_count(), 4u * static_cast<std::size_t>(c.twigs));
  for (const auto& p : glb.gltf["meshes"][0]["primitives"]) EXPECT_EQ(p.value("mode", 4), 4);
}

// Wind data on every primitive of the budget and LOD .glb (issue 32 item 2, as on the sway .glb):
// _WIND_LEVEL, _WIND_ALONG and _WIND_PHASE one a vertex; a twig cone's base ring at 0 along its
// branch and its apex at 1; leaf-cluster cards free (along 1) at the deepest level; whole levels,
// phases in [0, 1), alongs in [0, 1]; the full-mesh level carries them too.
TEST(TreeLod, EveryPrimitiveCarriesWindData) {
  const Result<LodMesh>& lod = Lod20k();
  ASSERT_TRUE(lod.ok()) << lod.status().Line();
  ASSERT_EQ(lod->twig_wind.size(), 3u);
  const std::vector<float>& twig_along = lod->twig_wind[1].values;
  ASSERT_EQ(twig_along.size(), lod->twigs.vertex_count());
  for (std::size_t v = 0; v < twig_along.size(); ++v) {
    EXPECT_NEAR(twig_along[v], v % 4 == 3 ? 1.0 : 0.0, 1e-5) << v;
  }
  const std::size_t cards = lod->cards.vertex_count();
  ASSERT_EQ(lod->card_wind[0].values.size(), cards);
  float deepest = 0;
  for (float l : lod->card_wind[0].values) deepest = std::max(deepest, l);
  // The cluster cards come after the branch cards: free at the deepest level.
  const std::size_t cluster_vertices = static_cast<std::size_t>(2 * lod->cluster_triangles);
  ASSERT_GT(cluster_vertices, 0u);
  for (std::size_t v = cards - cluster_vertices; v < cards; ++v) {
    ASSERT_EQ(lod->card_wind[1].values[v], 1.0f) << v;
    ASSERT_EQ(lod->card_wind[0].values[v], deepest) << v;
  }
  {
    std::vector<unsigned char> bytes;
    ASSERT_TRUE(WriteLodGlb({*lod}, &bytes).ok());
    const testing::Glb glb = testing::ParseGlb(bytes);
    int primitives = 0;
    for (const auto& p : glb.gltf["meshes"][0]["primitives"]) {
      const long n = glb.gltf["accessors"][p["attributes"]["POSITION"].get<std::size_t>()]["count"];
      for (const char* name : {"_WIND_LEVEL", "_WIND_ALONG", "_WIND_PHASE"}) {
        ASSERT_TRUE(p["attributes"].contains(name)) << name;
        const std::vector<float> values =
            testing::ReadAccessor<float>(glb, p["attributes"][name].get<int>());
        ASSERT_EQ(static_cast<long>(values.size()), n) << name;
        for (float x : values) {
          if (name[6] == 'L') {
            ASSERT_EQ(x, std::floor(x));
          } else if (name[6] == 'A') {
            ASSERT_TRUE(x >= 0.0f && x <= 1.0f) << x;
          } else {
            ASSERT_TRUE(x >= 0.0f && x < 1.0f) << x;
          }
        }
      }
      ++primitives;
    }
    EXPECT_EQ(primitives, 3);  // bark tubes, cards, twigs
  }
  const long full = FullTriangles(BuildTreeMesh(Sakura15()));
  Result<LodMesh> whole = BuildLodMesh(Sakura15(), full);
  ASSERT_TRUE(whole.ok());
  ASSERT_TRUE(whole->choice.full);
  EXPECT_EQ(whole->parts_wind[0][0].values.size(), whole->parts.bark.vertex_count());
  EXPECT_EQ(whole->parts_wind[1][0].values.size(), whole->parts.leaves.vertex_count());
}

// Twig cones face outward: each triangle's normal points away from the twig's axis.
TEST(TreeLod, TwigConesFaceOutward) {
  const Result<LodMesh>& lod = Lod20k();
  ASSERT_TRUE(lod.ok());
  const MeshBuffers& t = lod->twigs;
  ASSERT_GT(t.indices.size(), 0u);
  auto at = [&](uint32_t v) {
    return glm::vec3(t.positions[3 * v], t.positions[3 * v + 1], t.positions[3 * v + 2]);
  };
  int outward = 0, total = 0;
  for (std::size_t k = 0; k + 2 < t.indices.size(); k += 3) {
    const uint32_t first = t.indices[k] - t.indices[k] % 4;  // 4 vertices a cone: 3 base, apex
    const glm::vec3 centre = (at(first) + at(first + 1) + at(first + 2)) / 3.0f;
    const glm::vec3 a = at(t.indices[k]), b = at(t.indices[k + 1]), c = at(t.indices[k + 2]);
    const glm::vec3 n = glm::cross(b - a, c - a);
    ++total;
    outward += glm::dot(n, (a + b) * 0.5f - centre) > 0 ? 1 : 0;
  }
  EXPECT_EQ(outward, total);
}

// Below a budgeted LOD0 no kind of primitive grows: bark, cards and twigs (vertices and
// triangles) shrink level by level, and each level's tubes are at least as thick as above.
TEST(TreeLod, LevelsShrinkInEveryKind) {
  const Result<std::vector<LodMesh>>& levels = Levels20k();
  ASSERT_TRUE(levels.ok()) << levels.status().Line();
  for (std::size_t l = 1; l < levels->size(); ++l) {
    const LodMesh& a = (*levels)[l - 1];
    const LodMesh& b = (*levels)[l];
    EXPECT_LE(b.parts.bark.vertex_count(), a.parts.bark.vertex_count()) << l;
    EXPECT_LE(Triangles(b.parts.bark), Triangles(a.parts.bark)) << l;
    EXPECT_LE(b.cards.vertex_count(), a.cards.vertex_count()) << l;
    EXPECT_LE(Triangles(b.cards), Triangles(a.cards)) << l;
    EXPECT_LE(b.twigs.vertex_count(), a.twigs.vertex_count()) << l;
    EXPECT_LE(Triangles(b.twigs), Triangles(a.twigs)) << l;
    EXPECT_LE(b.cluster_triangles, a.cluster_triangles) << l;
    EXPECT_GE(b.choice.tube_radius_cm, a.choice.tube_radius_cm) << l;
  }
  EXPECT_GT((*levels)[2].twigs.vertex_count(), 0u);  // the thinnest wood is still drawn at LOD2
}

TEST(TreeLod, SmallerBudgetsNeverAddTrianglesOrTubes) {
  long last_triangles = std::numeric_limits<long>::max();  // long is 32 bits in WASM
  int last_tubes = 1 << 30;
  for (long budget : {60000L, 20000L, 8000L, 2000L, 400L}) {
    Result<LodMesh> lod = BuildLodMesh(Sakura15(), budget);
    ASSERT_TRUE(lod.ok()) << budget << ": " << lod.status().Line();
    EXPECT_LE(lod->choice.triangles, budget);
    EXPECT_LE(lod->choice.triangles, last_triangles);
    EXPECT_LE(lod->choice.tubes, last_tubes) << budget;
    last_triangles = lod->choice.triangles;
    last_tubes = lod->choice.tubes;
  }
}

// The thickest branches stay tubes: every tube is at least as thick as every card and line.
TEST(TreeLod, TubesAreTheThickestBranches) {
  const Result<LodMesh>& lod = Lod20k();
  ASSERT_TRUE(lod.ok());
  std::vector<bool> tube(Sakura15().branches.size(), false);
  for (uint32_t b : lod->parts.bark_branch_id) tube[b] = true;
  float thinnest_tube = 1e30f, thickest_other = 0;
  for (std::size_t i = 0; i < tube.size(); ++i) {
    const Branch& b = Sakura15().branches[i];
    if (!b.alive || b.nodes.size() < 2) continue;
    if (tube[i]) {
      thinnest_tube = std::min(thinnest_tube, BranchRadius(b));
    } else {
      thickest_other = std::max(thickest_other, BranchRadius(b));
    }
  }
  EXPECT_GE(thinnest_tube, lod->choice.tube_radius_cm);
  EXPECT_LT(thickest_other, lod->choice.tube_radius_cm);
}

// Every card's uv rectangle holds painted texels (leaves, flowers or bark), and the atlas is
// otherwise transparent.
TEST(TreeLod, CardsAreTexturedFromTheAtlas) {
  const Result<LodMesh>& lod = Lod20k();
  ASSERT_TRUE(lod.ok());
  const image::Rgba8Image& atlas = lod->atlas;
  ASSERT_FALSE(atlas.empty());
  long opaque = 0;
  for (std::size_t k = 3; k < atlas.pixels.size(); k += 4) opaque += atlas.pixels[k] > 0;
  EXPECT_GT(opaque, 1000);
  EXPECT_LT(opaque, static_cast<long>(atlas.pixels.size() / 4));
  const MeshBuffers& cards = lod->cards;
  int painted_cards = 0, total = 0;
  for (std::size_t v = 0; v + 3 < cards.vertex_count(); v += 4) {
    ++total;
    auto texel = [&](float t, int size) { return static_cast<int>(t * static_cast<float>(size)); };
    const int x0 = texel(cards.uvs[2 * v], atlas.width);
    const int y0 = texel(cards.uvs[2 * v + 1], atlas.height);
    const int x1 = texel(cards.uvs[2 * (v + 2)], atlas.width);
    const int y1 = texel(cards.uvs[2 * (v + 2) + 1], atlas.height);
    bool any = false;
    for (int y = y0; y < y1 && !any; ++y) {
      for (int x = x0; x < x1 && !any; ++x) any = atlas.At(x, y)[3] > 0;
    }
    painted_cards += any ? 1 : 0;
  }
  EXPECT_GT(total, 0);
  EXPECT_GE(painted_cards, total * 9 / 10);
}

TEST(TreeLod, TooFewTrianglesIsOneLineNamingTheFlag) {
  Result<LodMesh> lod = BuildLodMesh(Sakura15(), 3);
  ASSERT_FALSE(lod.ok());
  EXPECT_EQ(lod.status().Line(), "max_triangles: 3 is too few; must be at least 6");
}

TEST(TreeLod, LevelsAreSiblingNodesWithinTheirShares) {
  const Result<std::vector<LodMesh>>& levels = Levels20k();
  ASSERT_TRUE(levels.ok()) << levels.status().Line();
  ASSERT_EQ(levels->size(), 3u);
  const long lod0 = (*levels)[0].choice.triangles;
  EXPECT_LE(lod0, 20000);
  EXPECT_LE((*levels)[1].choice.triangles * 100, lod0 * 25);
  EXPECT_LE((*levels)[2].choice.triangles * 100, lod0 * 5);
  EXPECT_GT((*levels)[2].choice.triangles, 0);
  std::vector<unsigned char> bytes;
  ASSERT_TRUE(WriteLodGlb(*levels, &bytes).ok());
  testing::Glb glb = testing::ParseGlb(bytes);
  const auto& scene = glb.gltf["scenes"][0]["nodes"];
  ASSERT_EQ(scene.size(), 3u);
  for (std::size_t l = 0; l < 3; ++l) {
    const auto& node = glb.gltf["nodes"][scene[l].get<std::size_t>()];
    EXPECT_EQ(node["name"], "tree_LOD" + std::to_string(l));
    EXPECT_EQ(GlbTriangles(glb, node["mesh"].get<std::size_t>()), (*levels)[l].choice.triangles);
  }
}

TEST(TreeLod, MsftLodLayoutPutsLod0InTheSceneAndNamesTheOthers) {
  const Result<std::vector<LodMesh>>& levels = Levels20k();
  ASSERT_TRUE(levels.ok()) << levels.status().Line();
  std::vector<unsigned char> bytes;
  ASSERT_TRUE(WriteLodGlb(*levels, &bytes, "tree", LodLayout::kMsftLod).ok());
  testing::Glb glb = testing::ParseGlb(bytes);
  ASSERT_EQ(glb.gltf["scenes"][0]["nodes"], nlohmann::json::array({0}));
  const auto& lod0 = glb.gltf["nodes"][0];
  EXPECT_EQ(lod0["extensions"]["MSFT_lod"]["ids"], nlohmann::json::array({1, 2}));
  EXPECT_EQ(glb.gltf["extensionsUsed"], nlohmann::json::array({"MSFT_lod"}));
  EXPECT_FALSE(glb.gltf.contains("extensionsRequired"));  // a client without it shows LOD0
  const auto& coverage = lod0["extras"]["MSFT_screencoverage"];
  ASSERT_EQ(coverage.size(), 3u);
  const double lod0_triangles = static_cast<double>((*levels)[0].choice.triangles);
  for (std::size_t l = 0; l < 3; ++l) {
    const auto& node = glb.gltf["nodes"][l];
    EXPECT_EQ(node["name"], "tree_LOD" + std::to_string(l));
    EXPECT_EQ(GlbTriangles(glb, node["mesh"].get<std::size_t>()), (*levels)[l].choice.triangles);
    if (l > 0) {  // level l starts at the coverage of its triangle share
      EXPECT_NEAR(coverage[l - 1].get<double>(),
                  static_cast<double>((*levels)[l].choice.triangles) / lod0_triangles, 1e-4);
    }
  }
  EXPECT_LT(coverage[2].get<double>(), coverage[1].get<double>());
  EXPECT_LT(coverage[1].get<double>(), coverage[0].get<double>());
  EXPECT_LE(coverage[0].get<double>(), 0.25);
}

TEST(TreeLod, SameTreeSameBytes) {
  std::vector<unsigned char> a, b;
  Result<LodMesh> one = BuildLodMesh(Sakura15(), 5000);
  Result<LodMesh> two = BuildLodMesh(Sakura15(), 5000);
  ASSERT_TRUE(one.ok() && two.ok());
  ASSERT_TRUE(WriteLodGlb({*one}, &a).ok());
  ASSERT_TRUE(WriteLodGlb({*two}, &b).ok());
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace niwa
