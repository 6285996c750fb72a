// Unit tests of the tree mesh: counts, normals, joints, untwisted frames, leaves and flowers.
#include "tree/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <string>

#include "support/grow.h"
#include "tree/growth.h"
#include "tree/presets.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

constexpr float kScale = 0.01f;  // default cm_to_units

Tree GrowForMesh(const std::string& preset, int years) {
  return testing::GrowPreset(preset, years, 1);
}

glm::vec3 Vec(const std::vector<float>& data, std::size_t vertex) {
  return {data[3 * vertex], data[3 * vertex + 1], data[3 * vertex + 2]};
}

// A hand-made branch: nodes in cm, azimuth across the first internode.
Branch MakeBranch(int id, int parent, int parent_node, std::vector<glm::vec3> nodes,
                  glm::vec3 azimuth, float cross_section) {
  Branch b{};
  b.id = id;
  b.parent = parent;
  b.parent_node = parent_node;
  b.year = 1;
  b.alive = true;
  b.nodes = std::move(nodes);
  b.bud_direction = glm::vec3(0, 1, 0);
  b.azimuth = azimuth;
  b.cross_section = cross_section;
  return b;
}

// Vertices of each branch's block in the bark buffer (blocks are contiguous).
std::map<uint32_t, std::pair<std::size_t, std::size_t>> BarkBlocks(const TreeMesh& mesh) {
  std::map<uint32_t, std::pair<std::size_t, std::size_t>> blocks;  // id -> (first, count)
  for (std::size_t v = 0; v < mesh.bark_branch_id.size(); ++v) {
    auto it = blocks.find(mesh.bark_branch_id[v]);
    if (it == blocks.end()) {
      blocks[mesh.bark_branch_id[v]] = {v, 1};
    } else {
      EXPECT_EQ(it->second.first + it->second.second, v) << "bark block of a branch is split";
      ++it->second.second;
    }
  }
  return blocks;
}

// Sides of a branch's tube from its vertex count: N rings of (sides + 1) plus a cap of sides + 1.
int SidesOf(std::size_t count, std::size_t rings) {
  if (count % (rings + 1) != 0) return -1;
  return static_cast<int>(count / (rings + 1)) - 1;
}

void ExpectWellFormed(const MeshBuffers& m, const char* what) {
  SCOPED_TRACE(what);
  std::size_t n = m.vertex_count();
  ASSERT_EQ(m.positions.size(), 3 * n);
  ASSERT_EQ(m.normals.size(), 3 * n);
  ASSERT_EQ(m.uvs.size(), 2 * n);
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (float x : m.positions) ASSERT_TRUE(std::isfinite(x));
  for (float x : m.uvs) ASSERT_TRUE(std::isfinite(x));
  for (std::size_t v = 0; v < n; ++v) {
    glm::vec3 normal = Vec(m.normals, v);
    ASSERT_TRUE(std::isfinite(normal.x) && std::isfinite(normal.y) && std::isfinite(normal.z));
    ASSERT_NEAR(glm::length(normal), 1.0f, 1e-4f) << "vertex " << v;
  }
  for (uint32_t index : m.indices) ASSERT_LT(index, n);
  // Winding agrees with the normals: every non-degenerate triangle faces its vertex normals.
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    glm::vec3 face = glm::cross(Vec(m.positions, b) - Vec(m.positions, a),
                                Vec(m.positions, c) - Vec(m.positions, a));
    if (glm::length(face) < 1e-12f) continue;
    glm::vec3 mean = Vec(m.normals, a) + Vec(m.normals, b) + Vec(m.normals, c);
    ASSERT_GT(glm::dot(face, mean), 0.0f) << "triangle " << t / 3 << " is wound inside out";
  }
}

TEST(MeshTest, EmptyTreeGivesEmptyBuffers) {
  for (const Tree& tree : {Tree{}, GrowForMesh("sakura-thesis", 0)}) {
    TreeMesh mesh = BuildTreeMesh(tree);
    EXPECT_EQ(mesh.bark.vertex_count(), 0u);
    EXPECT_TRUE(mesh.bark.indices.empty());
    EXPECT_TRUE(mesh.bark_branch_id.empty());
    EXPECT_EQ(mesh.leaves.vertex_count(), 0u);
    EXPECT_TRUE(mesh.leaves.indices.empty());
    EXPECT_EQ(mesh.flowers.vertex_count(), 0u);
    EXPECT_TRUE(mesh.flowers.indices.empty());
  }
}

TEST(MeshTest, CountsMatchTheFormulaWithFixedSides) {
  Tree tree = GrowForMesh("sakura-thesis", 8);
  MeshOptions options;
  options.min_sides = options.max_sides = 6;
  TreeMesh mesh = BuildTreeMesh(tree, options);
  std::size_t vertices = 0, indices = 0, leaves = 0, flowers = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    vertices += b.nodes.size() * 7 + 7;               // rings of 6 + seam, cap hub + 6
    indices += (b.nodes.size() - 1) * 6 * 6 + 6 * 3;  // two triangles per side, cap fan
    leaves += b.leaves.size();
    flowers += b.flowers.size();
  }
  ASSERT_GT(leaves, 0u);
  ASSERT_GT(flowers, 0u) << "sakura should flower by its 8th year";
  EXPECT_EQ(mesh.bark.vertex_count(), vertices);
  EXPECT_EQ(mesh.bark.indices.size(), indices);
  EXPECT_EQ(mesh.bark_branch_id.size(), vertices);
  // Two quads (front and back) per leaf: 8 vertices, 4 triangles.
  EXPECT_EQ(mesh.leaves.vertex_count(), 8 * leaves);
  EXPECT_EQ(mesh.leaves.indices.size(), 12 * leaves);
  // Two 10-triangle fans (front and back) of hub + 10 outline vertices per flower.
  EXPECT_EQ(mesh.flowers.vertex_count(), 22 * flowers);
  EXPECT_EQ(mesh.flowers.indices.size(), 60 * flowers);
}

TEST(MeshTest, BuffersAreWellFormedForEveryPreset) {
  for (const Preset& preset : Presets()) {
    SCOPED_TRACE(preset.name);
    Tree tree = GrowForMesh(preset.name, 6);
    TreeMesh mesh = BuildTreeMesh(tree);
    EXPECT_GT(mesh.bark.vertex_count(), 0u);
    EXPECT_GT(mesh.leaves.vertex_count(), 0u);
    EXPECT_EQ(mesh.bark_branch_id.size(), mesh.bark.vertex_count());
    ExpectWellFormed(mesh.bark, "bark");
    ExpectWellFormed(mesh.leaves, "leaves");
    ExpectWellFormed(mesh.flowers, "flowers");
  }
  TreeMesh flowering = BuildTreeMesh(GrowForMesh("sakura-thesis", 8));
  ASSERT_GT(flowering.flowers.vertex_count(), 0u);
  ExpectWellFormed(flowering.flowers, "sakura flowers");
}

// The per-vertex branch/node ids (used for sway skinning) name the node each vertex hangs on:
// a ring vertex lies one radius from its node, a leaf's base corners and a flower's hub near it.
TEST(MeshTest, VertexNodeIdsNameTheNodeEachVertexHangsOn) {
  Tree tree = GrowForMesh("sakura-thesis", 8);
  TreeMesh mesh = BuildTreeMesh(tree);
  ASSERT_EQ(mesh.bark_node_index.size(), mesh.bark.vertex_count());
  ASSERT_EQ(mesh.leaf_branch_id.size(), mesh.leaves.vertex_count());
  ASSERT_EQ(mesh.leaf_node_index.size(), mesh.leaves.vertex_count());
  ASSERT_EQ(mesh.flower_branch_id.size(), mesh.flowers.vertex_count());
  ASSERT_EQ(mesh.flower_node_index.size(), mesh.flowers.vertex_count());
  ASSERT_GT(mesh.flowers.vertex_count(), 0u);
  auto node_of = [&](uint32_t branch, uint32_t node) {
    EXPECT_LT(branch, tree.branches.size());
    const Branch& b = tree.branches[branch];
    EXPECT_TRUE(b.alive);
    EXPECT_LT(node, b.nodes.size());
    return b.nodes[std::min<std::size_t>(node, b.nodes.size() - 1)] * kScale;
  };
  for (std::size_t v = 0; v < mesh.bark.vertex_count(); ++v) {
    const Branch& b = tree.branches[mesh.bark_branch_id[v]];
    float radius = BranchRadius(b) * kScale;  // the base radius bounds every ring
    glm::vec3 node = node_of(mesh.bark_branch_id[v], mesh.bark_node_index[v]);
    ASSERT_LE(glm::length(Vec(mesh.bark.positions, v) - node), radius * 1.001f + 1e-6f) << v;
  }
  const float leaf_size = static_cast<float>(tree.params.Get(ParamId::kLeafSize)) * kScale;
  for (std::size_t v = 0; v < mesh.leaves.vertex_count(); ++v) {
    glm::vec3 node = node_of(mesh.leaf_branch_id[v], mesh.leaf_node_index[v]);
    ASSERT_LE(glm::length(Vec(mesh.leaves.positions, v) - node), 1.1f * leaf_size) << v;
    if (v % 4 < 2) {  // the two base corners: a quarter of the size across the node
      ASSERT_LE(glm::length(Vec(mesh.leaves.positions, v) - node), 0.26f * leaf_size) << v;
    }
  }
  for (std::size_t v = 0; v < mesh.flowers.vertex_count(); ++v) {
    glm::vec3 node = node_of(mesh.flower_branch_id[v], mesh.flower_node_index[v]);
    // The blossom card's rim is 4 cm out from the hub, which sits 0.3 cm off the node.
    ASSERT_LE(glm::length(Vec(mesh.flowers.positions, v) - node), 4.02f * kScale) << v;
  }
}

TEST(MeshTest, SidesStayInRangeAndGrowWithRadius) {
  Tree tree = GrowForMesh("sakura-thesis", 8);
  MeshOptions options;
  options.min_sides = 4;
  options.max_sides = 10;
  TreeMesh mesh = BuildTreeMesh(tree, options);
  auto blocks = BarkBlocks(mesh);
  std::map<float, int> sides_by_radius;
  int alive = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) {
      EXPECT_EQ(blocks.count(static_cast<uint32_t>(b.id)), 0u) << "dead branch " << b.id;
      continue;
    }
    ++alive;
    ASSERT_EQ(blocks.count(static_cast<uint32_t>(b.id)), 1u) << "branch " << b.id;
    int sides = SidesOf(blocks[static_cast<uint32_t>(b.id)].second, b.nodes.size());
    ASSERT_GE(sides, options.min_sides) << "branch " << b.id;
    ASSERT_LE(sides, options.max_sides) << "branch " << b.id;
    sides_by_radius[BranchRadius(b)] = sides;
  }
  EXPECT_EQ(static_cast<int>(blocks.size()), alive);
  int previous = 0;
  for (const auto& entry : sides_by_radius) {
    EXPECT_GE(entry.second, previous) << "thicker tube with fewer sides at r=" << entry.first;
    previous = entry.second;
  }
  EXPECT_GT(sides_by_radius.rbegin()->second, sides_by_radius.begin()->second)
      << "the trunk should have more sides than the thinnest twig";
}

TEST(MeshTest, FirstRingOfAChildSitsOnItsParentsNode) {
  Tree tree = GrowForMesh("sakura-thesis", 6);
  TreeMesh mesh = BuildTreeMesh(tree);
  auto blocks = BarkBlocks(mesh);
  int checked = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    auto [first, count] = blocks[static_cast<uint32_t>(b.id)];
    int sides = SidesOf(count, b.nodes.size());
    ASSERT_GT(sides, 2);
    glm::vec3 expected = b.nodes[0] * kScale;
    if (b.parent >= 0) {
      const Branch& parent = tree.branches[static_cast<std::size_t>(b.parent)];
      expected = parent.nodes[static_cast<std::size_t>(b.parent_node)] * kScale;
      ++checked;
    }
    glm::vec3 centroid(0.0f);
    for (int j = 0; j < sides; ++j) centroid += Vec(mesh.bark.positions, first + j);
    centroid /= static_cast<float>(sides);
    EXPECT_NEAR(glm::length(centroid - expected), 0.0f, 1e-5f) << "branch " << b.id;
    float radius = BranchRadius(b) * kScale;
    for (int j = 0; j <= sides; ++j) {
      EXPECT_NEAR(glm::length(Vec(mesh.bark.positions, first + j) - expected), radius, 1e-5f)
          << "branch " << b.id << " vertex " << j;
    }
    // The seam vertex closes the ring where it started, with u = 1.
    EXPECT_NEAR(
        glm::length(Vec(mesh.bark.positions, first + sides) - Vec(mesh.bark.positions, first)),
        0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(mesh.bark.uvs[2 * (first + sides)], 1.0f);
  }
  EXPECT_GT(checked, 10);
}

TEST(MeshTest, RingFramesDoNotTwistAlongABentBranch) {
  // A branch bending in the x-y plane: parallel transport keeps the first radial direction on +z.
  Tree tree;
  tree.branches.push_back(MakeBranch(
      0, -1, 0, {{0, 0, 0}, {0, 10, 0}, {5, 18, 0}, {12, 22, 0}, {20, 22, 0}}, {0, 0, 1}, 3.0f));
  MeshOptions options;
  options.min_sides = options.max_sides = 8;
  TreeMesh mesh = BuildTreeMesh(tree, options);
  ASSERT_EQ(mesh.bark.vertex_count(), 5u * 9u + 9u);
  for (std::size_t ring = 0; ring < 5; ++ring) {
    glm::vec3 seam_normal = Vec(mesh.bark.normals, ring * 9);
    EXPECT_NEAR(seam_normal.z, 1.0f, 1e-5f) << "ring " << ring;
    // Opposite vertex (j = 4) points the other way.
    EXPECT_NEAR(Vec(mesh.bark.normals, ring * 9 + 4).z, -1.0f, 1e-5f) << "ring " << ring;
  }
  // v runs along the wood in metres: 10 + sqrt(89) + sqrt(65) + 8 cm to the tip ring.
  float length = (10.0f + std::sqrt(89.0f) + std::sqrt(65.0f) + 8.0f) * kScale;
  EXPECT_NEAR(mesh.bark.uvs[2 * (4 * 9) + 1], length, 1e-5f);
  // The end cap faces along the last internode (+x).
  glm::vec3 cap_normal = Vec(mesh.bark.normals, 5 * 9);
  EXPECT_NEAR(cap_normal.x, 1.0f, 1e-5f);
  ExpectWellFormed(mesh.bark, "bent branch");
}

TEST(MeshTest, DegenerateBranchesGiveNoNaN) {
  // Coinciding nodes, a zero azimuth and a zero leaf direction must not produce NaN.
  Tree tree;
  tree.branches.push_back(
      MakeBranch(0, -1, 0, {{0, 0, 0}, {0, 0, 0}, {0, 5, 0}, {0, 5, 0}}, {0, 0, 0}, 0.0f));
  tree.branches[0].leaves.push_back({2, {0, 0, 0}});
  tree.branches[0].leaves.push_back({3, {0, 1, 0}});  // straight up: no horizontal width axis
  tree.branches[0].flowers.push_back(3);
  TreeMesh mesh = BuildTreeMesh(tree);
  EXPECT_GT(mesh.bark.vertex_count(), 0u);
  EXPECT_EQ(mesh.leaves.vertex_count(), 16u);
  EXPECT_EQ(mesh.flowers.vertex_count(), 22u);
  ExpectWellFormed(mesh.bark, "bark");
  ExpectWellFormed(mesh.leaves, "leaves");
  ExpectWellFormed(mesh.flowers, "flowers");
}

TEST(MeshTest, LeafQuadsLieAlongTheLeafDirection) {
  Tree tree = GrowForMesh("keyaki-thesis", 5);
  const float size = static_cast<float>(tree.params.Get(ParamId::kLeafSize));
  TreeMesh mesh = BuildTreeMesh(tree);
  std::size_t quad = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const Leaf& leaf : b.leaves) {
      std::size_t v = 8 * quad++;
      glm::vec3 node = b.nodes[static_cast<std::size_t>(leaf.node)] * kScale;
      glm::vec3 base = 0.5f * (Vec(mesh.leaves.positions, v) + Vec(mesh.leaves.positions, v + 1));
      glm::vec3 tip =
          0.5f * (Vec(mesh.leaves.positions, v + 2) + Vec(mesh.leaves.positions, v + 3));
      EXPECT_NEAR(glm::length(base - node), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::length(tip - (node + leaf.direction * size * kScale)), 0.0f, 1e-5f);
      float width = glm::length(Vec(mesh.leaves.positions, v + 1) - Vec(mesh.leaves.positions, v));
      EXPECT_NEAR(width, 0.5f * size * kScale, 1e-5f);
      for (std::size_t k = 0; k < 4; ++k) {
        // Back copy: same corner, opposite normal; the front faces up rather than down.
        EXPECT_EQ(Vec(mesh.leaves.positions, v + k), Vec(mesh.leaves.positions, v + 4 + k));
        EXPECT_EQ(Vec(mesh.leaves.normals, v + k), -Vec(mesh.leaves.normals, v + 4 + k));
        EXPECT_GE(Vec(mesh.leaves.normals, v + k).y, 0.0f);
        float u = mesh.leaves.uvs[2 * (v + k)], w = mesh.leaves.uvs[2 * (v + k) + 1];
        EXPECT_TRUE(u >= 0.0f && u <= 1.0f && w >= 0.0f && w <= 1.0f);
      }
    }
  }
  ASSERT_GT(quad, 0u);
  EXPECT_EQ(mesh.leaves.vertex_count(), 8 * quad);
}

TEST(MeshTest, FlowerCardsAreEightCentimetresAcrossAndFaceUp) {
  Tree tree = GrowForMesh("sakura-thesis", 8);
  TreeMesh mesh = BuildTreeMesh(tree);
  ASSERT_GT(mesh.flowers.vertex_count(), 0u);
  for (std::size_t f = 0; f < mesh.flowers.vertex_count(); f += 22) {
    glm::vec3 hub = Vec(mesh.flowers.positions, f);
    float widest = 0.0f;
    for (std::size_t k = 1; k <= 10; ++k) {
      widest = std::max(widest, glm::length(Vec(mesh.flowers.positions, f + k) - hub));
    }
    EXPECT_NEAR(2.0f * widest, 8.0f * kScale, 1e-5f);  // a blossom cluster (mesh.h)
    EXPECT_GT(Vec(mesh.flowers.normals, f).y, 0.5f);
    EXPECT_EQ(Vec(mesh.flowers.normals, f + 11), -Vec(mesh.flowers.normals, f));
  }
}

TEST(MeshTest, UnitsScaleEveryPosition) {
  Tree tree = GrowForMesh("tsutsuji-thesis", 4);
  MeshOptions cm;
  cm.cm_to_units = 1.0f;
  TreeMesh in_cm = BuildTreeMesh(tree, cm);
  TreeMesh in_m = BuildTreeMesh(tree);
  ASSERT_EQ(in_cm.bark.positions.size(), in_m.bark.positions.size());
  for (std::size_t i = 0; i < in_cm.bark.positions.size(); ++i) {
    ASSERT_NEAR(in_cm.bark.positions[i] * kScale, in_m.bark.positions[i], 1e-5f);
  }
  ASSERT_EQ(in_cm.leaves.positions.size(), in_m.leaves.positions.size());
  for (std::size_t i = 0; i < in_cm.leaves.positions.size(); ++i) {
    ASSERT_NEAR(in_cm.leaves.positions[i] * kScale, in_m.leaves.positions[i], 1e-5f);
  }
  EXPECT_EQ(in_cm.bark.normals, in_m.bark.normals);
}

}  // namespace
}  // namespace niwa

namespace niwa {
namespace {

TreeMesh MeshIn(const Tree& tree, LeafShape shape, Season season, AutumnColour autumn) {
  MeshOptions options;
  TreeLook look;
  look.leaf_shape = shape;
  look.season = season;
  look.autumn = autumn;
  options.look = look;
  return BuildTreeMesh(tree, options);
}

TEST(MeshSeasons, WinterIsBareSpringCherriesBlossomOnBareWoodAutumnHasNoFlowers) {
  Tree sakura = GrowForMesh("sakura-thesis", 8);
  const TreeMesh summer = BuildTreeMesh(sakura);
  ASSERT_GT(summer.leaves.vertex_count(), 0u);
  ASSERT_GT(summer.flowers.vertex_count(), 0u);
  EXPECT_EQ(summer.look.season, Season::kSummer);  // the table's default
  const AutumnColour red_orange = AutumnColour::kRedOrange;
  TreeMesh winter = MeshIn(sakura, LeafShape::kBroad, Season::kWinter, red_orange);
  EXPECT_EQ(winter.leaves.vertex_count(), 0u);
  EXPECT_EQ(winter.flowers.vertex_count(), 0u);
  EXPECT_EQ(winter.bark.positions, summer.bark.positions);  // the same wood
  TreeMesh spring = MeshIn(sakura, LeafShape::kBroad, Season::kSpring, red_orange);
  EXPECT_EQ(spring.leaves.vertex_count(), 0u);
  EXPECT_EQ(spring.flowers.positions, summer.flowers.positions);
  TreeMesh autumn = MeshIn(sakura, LeafShape::kBroad, Season::kAutumn, red_orange);
  EXPECT_EQ(autumn.leaves.positions, summer.leaves.positions);
  EXPECT_EQ(autumn.flowers.vertex_count(), 0u);
  // A tree without flowers keeps its leaves in spring; an evergreen keeps them in winter.
  Tree keyaki = GrowForMesh("keyaki-thesis", 4);
  ASSERT_EQ(BuildTreeMesh(keyaki).flowers.vertex_count(), 0u);
  EXPECT_GT(MeshIn(keyaki, LeafShape::kBroad, Season::kSpring, AutumnColour::kOrangeBrown)
                .leaves.vertex_count(),
            0u);
  TreeMesh evergreen =
      MeshIn(keyaki, LeafShape::kNeedle, Season::kWinter, AutumnColour::kEvergreen);
  EXPECT_EQ(evergreen.leaves.vertex_count(), BuildTreeMesh(keyaki).leaves.vertex_count());
}

TEST(MeshSeasons, TheSeasonRowOfTheTreeIsUsedWhenNoLookIsGiven) {
  Tree sakura = GrowForMesh("sakura-thesis", 6);
  ASSERT_TRUE(sakura.params.Set(TreeParam::kSeason, 3).ok());
  TreeMesh mesh = BuildTreeMesh(sakura);
  EXPECT_EQ(mesh.look.season, Season::kWinter);
  EXPECT_EQ(mesh.leaves.vertex_count(), 0u);
}

TEST(MeshLeafShapes, QuadWidthFollowsTheShape) {
  Tree tree = GrowForMesh("keyaki-thesis", 3);
  const float size = static_cast<float>(tree.params.Get(ParamId::kLeafSize)) * kScale;
  for (LeafShape shape :
       {LeafShape::kBroad, LeafShape::kNeedle, LeafShape::kPalmate, LeafShape::kFan}) {
    TreeMesh mesh = MeshIn(tree, shape, Season::kSummer, AutumnColour::kRedOrange);
    ASSERT_GT(mesh.leaves.vertex_count(), 0u);
    EXPECT_EQ(mesh.leaves.vertex_count(), BuildTreeMesh(tree).leaves.vertex_count());
    float width = glm::length(Vec(mesh.leaves.positions, 1) - Vec(mesh.leaves.positions, 0));
    EXPECT_NEAR(width, LeafQuadAspect(shape) * size, 1e-5f) << LeafShapeName(shape);
  }
  EXPECT_FLOAT_EQ(LeafQuadAspect(LeafShape::kBroad), 0.5f);
  EXPECT_FLOAT_EQ(LeafQuadAspect(LeafShape::kFan), 1.2f);
}

TEST(MeshLeafShapes, SpeciesPresetsCarryTheirShapeAndAutumnColour) {
  auto look = [](const char* preset) { return LookFromParams(FindPreset(preset)->params); };
  EXPECT_EQ(look("pine").leaf_shape, LeafShape::kNeedle);
  EXPECT_EQ(look("pine").autumn, AutumnColour::kEvergreen);
  EXPECT_EQ(look("maple").leaf_shape, LeafShape::kPalmate);
  EXPECT_EQ(look("maple").autumn, AutumnColour::kRed);
  EXPECT_EQ(look("ginkgo").leaf_shape, LeafShape::kFan);
  EXPECT_EQ(look("ginkgo").autumn, AutumnColour::kYellow);
  EXPECT_EQ(look("keyaki").autumn, AutumnColour::kOrangeBrown);
  EXPECT_EQ(look("sakura").leaf_shape, LeafShape::kBroad);
  EXPECT_EQ(look("sakura").autumn, AutumnColour::kRedOrange);
  EXPECT_EQ(look("tsutsuji").autumn, AutumnColour::kEvergreen);
}

// FNV-1a over the bytes of the leaf buffers (positions, normals, uvs, indices).
std::string LeafBytesDigest(const TreeMesh& mesh) {
  uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&h](const void* data, std::size_t bytes) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  };
  const MeshBuffers& m = mesh.leaves;
  mix(m.positions.data(), m.positions.size() * sizeof(float));
  mix(m.normals.data(), m.normals.size() * sizeof(float));
  mix(m.uvs.data(), m.uvs.size() * sizeof(float));
  mix(m.indices.data(), m.indices.size() * sizeof(uint32_t));
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

// leaf_spray (a mesh row): 1 is the leaf quad as before the row (the digest is that of the mesh
// built before it existed); n > 1 draws the same quads, as many triangles, each the spray card
// LeafCardOf gives, from the same base along the same direction.
TEST(MeshLeafSpray, OneIsTodaysQuadAndASprayIsTheSameQuadsOnALargerCard) {
  Tree tree = GrowForMesh("keyaki-thesis", 4);
  ASSERT_EQ(tree.params.GetInt(TreeParam::kLeafSpray), 1);
  const TreeMesh plain = BuildTreeMesh(tree);
  EXPECT_EQ(LeafBytesDigest(plain), "d2187914aa581af1");
  ASSERT_TRUE(tree.params.Set(TreeParam::kLeafSpray, 5).ok());
  const TreeMesh spray = BuildTreeMesh(tree);
  EXPECT_EQ(spray.look.leaf_spray, 5);
  ASSERT_GT(plain.leaves.vertex_count(), 100u);
  EXPECT_EQ(spray.leaves.indices.size(), plain.leaves.indices.size());
  EXPECT_EQ(spray.leaves.uvs, plain.leaves.uvs);
  EXPECT_EQ(spray.bark.positions, plain.bark.positions);
  const LeafCardSize card = LeafCardOf(spray.look);
  const float size = static_cast<float>(tree.params.Get(ParamId::kLeafSize)) * kScale;
  for (std::size_t q = 0; q < plain.leaves.vertex_count(); q += 4) {
    // Corners 0, 1 at the base, 2, 3 at the far end: same base midpoint, same direction.
    const glm::vec3 base_a =
        0.5f * (Vec(plain.leaves.positions, q) + Vec(plain.leaves.positions, q + 1));
    const glm::vec3 base_b =
        0.5f * (Vec(spray.leaves.positions, q) + Vec(spray.leaves.positions, q + 1));
    EXPECT_LT(glm::length(base_a - base_b), 1e-6f);
    const glm::vec3 along_b = Vec(spray.leaves.positions, q + 3) - Vec(spray.leaves.positions, q);
    const glm::vec3 across_b = Vec(spray.leaves.positions, q + 1) - Vec(spray.leaves.positions, q);
    EXPECT_NEAR(glm::length(along_b), card.length * size, 1e-5f);
    EXPECT_NEAR(glm::length(across_b), card.width * size, 1e-5f);
    const glm::vec3 along_a = Vec(plain.leaves.positions, q + 3) - Vec(plain.leaves.positions, q);
    EXPECT_GT(glm::dot(glm::normalize(along_a), glm::normalize(along_b)), 0.9999f);
  }
}

}  // namespace
}  // namespace niwa
