// Tests of the tree table's stages: each row says what an edit of it invalidates, and a row that
// is not "grow" must not change the grown tree (nor, unless "mesh", its mesh).
#include "tree/tree_params.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_json.h"

namespace niwa {
namespace {

TEST(TreeParamStages, FollowTheGroups) {
  const ParamTable& table = TreeParamTable();
  EXPECT_EQ(table.name(), "tree");
  for (const ParamSpec& s : table) {
    const std::string group = s.group;
    const Stage expected = group == "sway" || group == "wind"     ? Stage::kSway
                           : group == "render" || group == "bark" ? Stage::kView
                           : s.key == std::string("leaf_shape") ||
                                   s.key == std::string("leaf_card") ||
                                   s.key == std::string("leaf_spray")
                               ? Stage::kMesh  // the three rows the mesh alone uses
                               : Stage::kGrow;
    EXPECT_EQ(s.stage, expected) << s.key;
    EXPECT_STRNE(table.GroupTitle(s.group), "") << s.key;
  }
  EXPECT_EQ(std::string(StageName(Spec(TreeParam::kLeafSize).stage)), "grow");
  EXPECT_EQ(std::string(StageName(Spec(TreeParam::kGravity).stage)), "sway");
  EXPECT_EQ(std::string(StageName(Spec(TreeParam::kCardPlanes).stage)), "view");
}

// Another valid value of a row: halfway to its max (or to its min when the default is the max),
// rounded for whole-number rows.
double OtherValue(const ParamSpec& s) {
  double target = s.default_value < s.max_value ? s.max_value : s.min_value;
  double v = 0.5 * (s.default_value + target);
  if (s.integer) v = s.default_value < s.max_value ? std::ceil(v) : std::floor(v);
  return v;
}

TEST(TreeParamStages, RowsAfterGrowLeaveTheTreeAndItsMeshUnchanged) {
  GrowRequest base;
  base.preset = "sakura-thesis";
  base.params = FindPreset("sakura-thesis")->params;
  base.years = 4;
  const Tree grown = GrowTree(base);
  const std::string tree_json = TreeToJson(grown);
  const TreeMesh mesh = BuildTreeMesh(grown);
  int checked = 0;
  for (const ParamSpec& s : TreeParamTable()) {
    if (s.stage == Stage::kGrow) continue;
    GrowRequest edited = base;
    ASSERT_TRUE(edited.params.Set(static_cast<std::size_t>(s.id), OtherValue(s)).ok()) << s.key;
    ASSERT_NE(edited.params, base.params) << s.key;
    Tree tree = GrowTree(edited);
    tree.params = base.params;  // the echo of the parameters is the only difference allowed
    EXPECT_EQ(TreeToJson(tree), tree_json) << s.key;
    if (s.stage != Stage::kMesh) {
      TreeMesh edited_mesh = BuildTreeMesh(GrowTree(edited));
      EXPECT_EQ(edited_mesh.bark.positions, mesh.bark.positions) << s.key;
      EXPECT_EQ(edited_mesh.leaves.positions, mesh.leaves.positions) << s.key;
    }
    ++checked;
  }
  // 13 sway, 9 wind, 8 render rows, leaf_shape, leaf_card, leaf_spray, bark, bark_model
  EXPECT_EQ(checked, 35);
}

TEST(TreeParamStages, LeafCardScalesTheDrawnLeavesAboutTheirBases) {
  // leaf_card (a mesh row) draws each leaf's card that many times longer and wider from the same
  // base: the tree is the same, the leaf quads' extent from their base grows by exactly the factor.
  GrowRequest base;
  base.preset = "pine";
  base.params = FindPreset("pine")->params;
  base.years = 4;
  ASSERT_EQ(base.params.Get(TreeParam::kLeafCard), 2.5);
  const Tree tree = GrowTree(base);
  Tree one = tree;
  ASSERT_TRUE(one.params.Set(TreeParam::kLeafCard, 1).ok());
  const TreeMesh drawn = BuildTreeMesh(tree), plain = BuildTreeMesh(one);
  ASSERT_EQ(drawn.leaves.positions.size(), plain.leaves.positions.size());
  ASSERT_GT(drawn.leaves.positions.size(), 300u);
  // positions: x, y, z per vertex; a leaf is two quads of 4 vertices (its two sides).
  auto at = [](const MeshBuffers& m, std::size_t v) {
    return glm::dvec3(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  };
  double drawn_extent = 0, plain_extent = 0;
  for (std::size_t v = 0; v < drawn.leaves.positions.size() / 3; ++v) {
    drawn_extent += glm::length(at(drawn.leaves, v) - at(drawn.leaves, v - v % 4));
    plain_extent += glm::length(at(plain.leaves, v) - at(plain.leaves, v - v % 4));
  }
  EXPECT_NEAR(drawn_extent / plain_extent, 2.5, 1e-3);
}

TEST(TreeParamStages, AGrowRowDoesChangeTheTree) {
  // The check above can fail: the same comparison on a grow row sees another tree.
  GrowRequest base;
  base.preset = "sakura-thesis";
  base.params = FindPreset("sakura-thesis")->params;
  base.years = 4;
  GrowRequest edited = base;
  ASSERT_TRUE(edited.params.Set(TreeParam::kGamma, OtherValue(Spec(TreeParam::kGamma))).ok());
  Tree tree = GrowTree(edited);
  tree.params = base.params;
  EXPECT_NE(TreeToJson(tree), TreeToJson(GrowTree(base)));
}

}  // namespace
}  // namespace niwa
