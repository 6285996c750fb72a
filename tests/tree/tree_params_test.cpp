// Tests of the tree table's stages: each row says what an edit of it invalidates, and a row that
// is not "grow" must not change the grown tree (nor, unless "mesh", its mesh).
#include "tree/tree_params.h"

#include <gtest/gtest.h>

#include <cmath>
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
    const Stage expected = group == "sway" || group == "wind" ? Stage::kSway
                           : group == "render"                ? Stage::kView
                           : s.key == std::string("leaf_shape")
                               ? Stage::kMesh  // the one row the mesh alone uses
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
  EXPECT_EQ(checked, 31);  // 13 sway, 9 wind, 8 render rows and leaf_shape (mesh)
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
