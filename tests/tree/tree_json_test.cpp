// Tests of the tree JSON writer (format niwa-tree-1).
#include "tree/tree_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "params/param_json.h"
#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

TEST(TreeJson, HoldsEveryLivingBranchWithItsNodesBudsAndLeaves) {
  GrowRequest r;
  r.preset = "sakura-thesis";
  r.params = FindPreset("sakura-thesis")->params;
  r.years = 4;
  Tree tree = GrowTree(r);
  nlohmann::json j = nlohmann::json::parse(TreeToJson(tree));
  TreeStats stats = ComputeStats(tree);
  EXPECT_EQ(j["branches"].size(), static_cast<std::size_t>(stats.branches));
  std::size_t internodes = 0, leaves = 0;
  for (const auto& b : j["branches"]) {
    internodes += b["nodes"].size() - 1;
    leaves += b["leaves"].size();
  }
  EXPECT_EQ(internodes, static_cast<std::size_t>(stats.internodes));
  EXPECT_EQ(leaves, static_cast<std::size_t>(stats.leaves));
  EXPECT_EQ(j["params"]["alpha_t"], 0.7);
  EXPECT_EQ(nlohmann::json::parse(ParamTableJson(TreeParamTable())).size(), kParamCount);
}

}  // namespace
}  // namespace niwa
