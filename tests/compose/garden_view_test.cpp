// Tests of compose/garden_view (what a page draws of a garden run): each distinct tree's mesh at
// the page's detail has the tree's leaves and flowers as the tree study's full mesh has them, bark
// tubes of at most kGardenViewMaxSides sides (fewer triangles than the 12-sided default), and its
// trunk's foot at the origin.
#include "compose/garden_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "compose/garden_run.h"
#include "compose/garden_state.h"

namespace niwa::compose {
namespace {

TEST(GardenView, EachGroupsMeshIsTheTreesAtPageDetailAtTheOrigin) {
  GardenState s = DefaultGardenState();
  ASSERT_TRUE(s.params.Set(GardenParam::kSize, 30).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kGroundRes, 48).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 3).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kDensity, 0.01).ok());
  LayOutDefaults(&s);
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  ASSERT_TRUE(run->Advance({}).ok());
  ASSERT_FALSE(run->groups().empty());
  for (int g = 0; g < static_cast<int>(run->groups().size()); ++g) {
    const TreeMesh page = GardenGroupMesh(*run, g);
    const TreeMesh full = BuildTreeMesh(run->groups()[g].tree());
    const std::string& name = run->groups()[g].name;
    EXPECT_GT(page.bark.indices.size(), 0u) << name;
    EXPECT_LT(page.bark.indices.size(), full.bark.indices.size()) << name;
    EXPECT_EQ(page.leaves.positions, full.leaves.positions) << name;
    EXPECT_EQ(page.flowers.positions, full.flowers.positions) << name;
    // The trunk's first ring is around the origin (metres).
    ASSERT_GE(page.bark.positions.size(), 3u);
    EXPECT_LT(std::hypot(page.bark.positions[0], page.bark.positions[2]), 0.5) << name;
    EXPECT_LT(std::abs(page.bark.positions[1]), 0.5) << name;
  }
}

}  // namespace
}  // namespace niwa::compose
