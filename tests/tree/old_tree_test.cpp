// Issue 17 item 5: a tree stopped by a limit keeps its leaves and flowers (the growth is cut, not
// the foliage), both for the table's max_internodes (the growth goes on at the cap) and for a
// budget that stops the growth (the page's internode budget).
#include <gtest/gtest.h>

#include "support/grow.h"
#include "tree/growth.h"
#include "tree/tree_budget.h"
#include "tree/tree_state.h"

namespace niwa {
namespace {

TreeState Sakura(int years) { return testing::PresetState("sakura", years); }

TEST(OldTree, HundredYearsAtTheInternodeCapKeepsLeavesAndFlowers) {
  TreeState state = Sakura(100);
  ASSERT_TRUE(state.params.Set(ParamId::kMaxInternodes, 4000).ok());
  Tree tree = GrowTree(state);
  ASSERT_TRUE(tree.truncated);
  EXPECT_NE(tree.truncated_by.find("max_internodes"), std::string::npos) << tree.truncated_by;
  const TreeStats stats = ComputeStats(tree);
  EXPECT_EQ(tree.years, 100);
  EXPECT_LE(stats.internodes, 4000);
  EXPECT_GT(stats.leaves, 1000);
  EXPECT_GT(stats.flowers, 0);
}

TEST(OldTree, AStoppedGrowthKeepsLastYearsFoliage) {
  TreeState state = Sakura(100);
  Budget roomy;
  roomy.memory_bytes = uint64_t{8} << 30;
  roomy.seconds = 3600;
  state.limits = TreeGrowLimits(state.params, roomy);
  state.limits.max_internodes = 3000;
  state.limits.internode_limit = "page internode budget";
  Grower grower(state);
  while (grower.year() < state.years && !grower.stopped()) grower.GrowYear();
  const int stopped_in = grower.year();
  Tree tree = grower.TakeTree();
  ASSERT_TRUE(tree.truncated);
  EXPECT_LT(stopped_in, 100);
  const TreeStats stats = ComputeStats(tree);
  // The year before the stop, grown without a limit: the stopped tree has at least half its
  // leaves (last year's foliage stays; only the shoots that did not fit are missing).
  TreeState before = Sakura(stopped_in - 1);
  const TreeStats full = ComputeStats(GrowTree(before));
  EXPECT_GT(full.leaves, 0);
  EXPECT_GE(stats.leaves * 2, full.leaves) << tree.truncated_by;
  EXPECT_GT(stats.flowers, 0);
}

}  // namespace
}  // namespace niwa
