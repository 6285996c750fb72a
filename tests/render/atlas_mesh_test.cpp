// Unit tests of the card-atlas geometry (every projected triangle lands in its tile, counts per
// leaf mode) and of the sway skin of hybrid draw lists.
#include "render/atlas_mesh.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/grow.h"
#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

Tree GrowForAtlas(const std::string& preset, int years) {
  return testing::GrowPreset(preset, years);
}

// True when clip point (x, y) lies in some tile (half a texel of slack).
bool InSomeTile(const HybridScene& scene, float x, float y) {
  const float s = static_cast<float>(scene.atlas_size);
  const float tx = (x + 1.0f) * 0.5f * s, ty = (y + 1.0f) * 0.5f * s;
  auto inside = [&](const AtlasTile& t) {
    const float x0 = static_cast<float>(t.x), x1 = static_cast<float>(t.x + t.w);
    const float y0 = static_cast<float>(t.y), y1 = static_cast<float>(t.y + t.h);
    return tx >= x0 - 0.5f && tx <= x1 + 0.5f && ty >= y0 - 0.5f && ty <= y1 + 0.5f;
  };
  for (const auto& g : scene.group_tiles)
    for (const AtlasTile& t : g)
      if (inside(t)) return true;
  for (const auto& c : scene.cluster_tiles)
    for (const AtlasTile& t : c)
      if (inside(t)) return true;
  return false;
}

void ExpectInTiles(const HybridScene& scene, const MeshBuffers& part, const char* name) {
  int outside = 0;
  for (std::size_t i = 0; i + 2 < part.positions.size(); i += 3) {
    if (!InSomeTile(scene, part.positions[i], part.positions[i + 1])) ++outside;
    EXPECT_GE(part.positions[i + 2], -1.0f);
    EXPECT_LE(part.positions[i + 2], 1.0f);
  }
  EXPECT_EQ(outside, 0) << name << ": vertices outside every tile";
}

TEST(AtlasMesh, EveryProjectedVertexLandsInATileInBothLeafModes) {
  Tree tree = GrowForAtlas("sakura-thesis", 6);
  TreeMesh mesh = BuildTreeMesh(tree);
  for (LeafMode mode : {LeafMode::kBranchCards, LeafMode::kClusterCards}) {
    RenderOptions options;
    options.leaf_mode = mode;
    HybridScene scene = BuildHybridScene(tree, options);
    ASSERT_TRUE(scene.atlas_fits);
    AtlasMesh atlas = BuildAtlasMesh(mesh, scene);
    EXPECT_GT(atlas.bark.indices.size(), 0u);
    EXPECT_GT(atlas.leaves.indices.size(), 0u);
    EXPECT_GT(atlas.tiles, 0);
    ExpectInTiles(scene, atlas.bark, "bark");
    ExpectInTiles(scene, atlas.leaves, "leaves");
    ExpectInTiles(scene, atlas.flowers, "flowers");
  }
}

// Given bark uvs (a simulated bark's wrapped tile) are the atlas bark's texture coordinates, corner
// by corner, and leave the positions and the leaves alone; the mesh's own uvs without them.
TEST(AtlasMesh, GivenBarkUvsAreTheCardsBarkUvs) {
  Tree tree = GrowForAtlas("sakura-thesis", 4);
  TreeMesh mesh = BuildTreeMesh(tree);
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  std::vector<float> uvs(mesh.bark.uvs.size());
  for (std::size_t i = 0; i < uvs.size(); ++i) uvs[i] = 1000.0f + static_cast<float>(i);
  const AtlasMesh plain = BuildAtlasMesh(mesh, scene);
  const AtlasMesh wrapped = BuildAtlasMesh(mesh, scene, &uvs);
  ASSERT_GT(plain.bark.uvs.size(), 0u);
  EXPECT_EQ(wrapped.bark.positions, plain.bark.positions);
  EXPECT_EQ(wrapped.leaves.uvs, plain.leaves.uvs);
  // Each atlas vertex's uv is the override at the mesh vertex its plain uv came from: the pairs
  // map one to one (the plain uvs of distinct mesh vertices may coincide, so compare through u).
  ASSERT_EQ(wrapped.bark.uvs.size(), plain.bark.uvs.size());
  int from_override = 0;
  for (std::size_t k = 0; k < wrapped.bark.uvs.size(); k += 2) {
    const float u = wrapped.bark.uvs[k], v = wrapped.bark.uvs[k + 1];
    const std::size_t i = static_cast<std::size_t>(u - 1000.0f);  // 2 × the mesh vertex
    if (i % 2 == 0 && i + 1 < uvs.size() && v == uvs[i + 1] &&
        plain.bark.uvs[k] == mesh.bark.uvs[i] && plain.bark.uvs[k + 1] == mesh.bark.uvs[i + 1])
      ++from_override;
  }
  EXPECT_EQ(from_override, static_cast<int>(wrapped.bark.uvs.size() / 2));
  // Of another length (not this mesh's bark): the mesh's own.
  const std::vector<float> short_uvs(2, 5.0f);
  EXPECT_EQ(BuildAtlasMesh(mesh, scene, &short_uvs).bark.uvs, plain.bark.uvs);
}

// Bark triangles in the atlas = the representatives' triangles times the planes per card.
TEST(AtlasMesh, BarkTrianglesAreTheRepresentativesOnEveryPlane) {
  Tree tree = GrowForAtlas("keyaki-thesis", 6);
  TreeMesh mesh = BuildTreeMesh(tree);
  RenderOptions options;
  options.card_planes = 3;
  HybridScene scene = BuildHybridScene(tree, options);
  std::vector<std::size_t> per_branch(tree.branches.size(), 0);
  for (std::size_t t = 0; t < mesh.bark.indices.size(); t += 3)
    ++per_branch[mesh.bark_branch_id[mesh.bark.indices[t]]];
  std::size_t expected = 0;
  for (int rep : scene.group_representative)
    expected += per_branch[static_cast<std::size_t>(rep)] * 3;
  AtlasMesh atlas = BuildAtlasMesh(mesh, scene);
  EXPECT_EQ(atlas.bark.indices.size() / 3, expected);
  // Cluster mode: the leaves of every cluster's branches on each of its planes.
  std::vector<std::size_t> leaves_of(tree.branches.size(), 0);
  for (std::size_t t = 0; t < mesh.leaves.indices.size(); t += 3)
    ++leaves_of[mesh.leaf_branch_id[mesh.leaves.indices[t]]];
  std::size_t expected_leaves = 0;
  for (const LeafCluster& c : scene.clusters)
    for (int b : c.branches)
      expected_leaves += leaves_of[static_cast<std::size_t>(b)] * c.planes.size();
  EXPECT_EQ(atlas.leaves.indices.size() / 3, expected_leaves);
}

// A vertical straight branch seen on a plane: its projection is centred on the tile's width and
// its base is at the bottom of the tile (v0 side), its tip near the top.
TEST(AtlasMesh, StraightBranchIsUprightInItsTile) {
  Tree tree;
  Branch b{};
  b.id = 0;
  b.parent = -1;
  b.alive = true;
  b.year = 1;
  b.nodes = {{0, 0, 0}, {0, 50, 0}, {0, 100, 0}};
  b.bud_direction = glm::vec3(0, 1, 0);
  b.azimuth = glm::vec3(1, 0, 0);
  b.cross_section = 3.14159265f * 4.0f;  // radius 2 cm
  tree.branches.push_back(b);
  TreeMesh mesh = BuildTreeMesh(tree);
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  AtlasMesh atlas = BuildAtlasMesh(mesh, scene);
  ASSERT_FALSE(atlas.bark.positions.empty());
  const AtlasTile& tile = scene.group_tiles[0][0];
  const float s = static_cast<float>(scene.atlas_size);
  float lo_y = 1e9f, hi_y = -1e9f, sum_x = 0;
  int n = 0;
  const std::size_t plane0_vertices = atlas.bark.positions.size() / 3 / scene.group_tiles[0].size();
  for (std::size_t v = 0; v < plane0_vertices; ++v) {
    float tx = (atlas.bark.positions[3 * v] + 1) * 0.5f * s;
    float ty = (atlas.bark.positions[3 * v + 1] + 1) * 0.5f * s;
    lo_y = std::min(lo_y, ty);
    hi_y = std::max(hi_y, ty);
    sum_x += tx;
    ++n;
  }
  const CardPlane& p = scene.frames[0].planes[0];
  const float texels_per_m = static_cast<float>(tile.h) / (p.v1 - p.v0);
  const float tile_x = static_cast<float>(tile.x), tile_y = static_cast<float>(tile.y);
  // Base (v = 0) at tile.y + (0 - v0) texels; tip (v = 1 m) one metre higher.
  EXPECT_NEAR(lo_y, tile_y + (0.0f - p.v0) * texels_per_m, 1.0f);
  EXPECT_NEAR(hi_y, tile_y + (1.0f - p.v0) * texels_per_m, 1.0f);
  EXPECT_NEAR(sum_x / static_cast<float>(n), tile_x + (0.0f - p.u0) * texels_per_m, 1.0f);
}

TEST(DrawListSkin, CardCornersAndLineEndsFollowTheirNodes) {
  Tree tree = GrowForAtlas("sakura-thesis", 6);
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  OrbitView view = FrameOrbitView(MeshBounds(BuildTreeMesh(tree)));
  RenderCamera camera = CameraFromOrbit(view, 512, 512);
  HybridSelection selection = SelectHybrid(tree, scene, camera, nullptr);
  HybridDrawList list = BuildDrawList(tree, scene, selection, camera);
  SwayModel model = BuildSwayModel(tree, SwayParams());
  DrawListSkin skin = BuildDrawListSkin(tree, scene, list, model);
  ASSERT_EQ(skin.cards.joint.size(), list.card_branch.size() * 4);
  ASSERT_EQ(skin.lines.joint.size(), list.line_branch.size() * 2);
  ASSERT_GT(list.line_branch.size(), 0u);
  for (std::size_t s = 0; s < list.line_branch.size(); ++s) {
    const uint32_t b = static_cast<uint32_t>(list.line_branch[s]);
    SkinBinding tip = BindNode(model, b, static_cast<uint32_t>(list.line_nodes[2 * s + 1]));
    EXPECT_EQ(skin.lines.joint[2 * s + 1], tip.joint);
    EXPECT_EQ(skin.lines.weight[2 * s + 1], tip.weight);
  }
  for (std::size_t c = 0; c < list.card_branch.size(); ++c) {
    if (list.card_branch[c] < 0) continue;
    const uint32_t b = static_cast<uint32_t>(list.card_branch[c]);
    SkinBinding base = BindNode(model, b, 0);
    EXPECT_EQ(skin.cards.joint[4 * c], base.joint);
    EXPECT_EQ(skin.cards.weight[4 * c + 1], base.weight);
  }
}

}  // namespace
}  // namespace niwa
