// core/compose/bark_support: a grown tree's bark as one TriMesh with the trunk-foot seed on it, its
// errors naming tree or tree_years, and its budget (the tree's limits, the bark's estimate
// against the heap this binary's metered operator new saw).
#define NIWA_ALLOC_METER_DEFINE
#include "compose/bark_support.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/mesh_metrics.h"
#include "support/alloc_meter.h"

namespace niwa::compose {
namespace {

TEST(BarkSupport, IsTheBarkWithASeedAtTheTrunkFoot) {
  Result<BarkSupport> bark = GrowBarkSupport("sakura", 6);
  ASSERT_TRUE(bark.ok()) << bark.status().Line();
  EXPECT_GT(bark->mesh.triangle_count(), 1000u);
  EXPECT_EQ(bark->mesh.normals.size(), bark->mesh.positions.size());
  EXPECT_TRUE(geom::ValidateMesh(bark->mesh, "bark").ok());
  // On the +z side of the trunk, near the ground.
  EXPECT_GT(bark->trunk_seed.z, 0.0);
  EXPECT_LT(bark->trunk_seed.y, 0.3);
  EXPECT_LT(std::fabs(bark->trunk_seed.x), 0.2);
  // The same request, the same bits.
  Result<BarkSupport> again = GrowBarkSupport("sakura", 6);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->mesh.positions, bark->mesh.positions);
  EXPECT_EQ(again->trunk_seed, bark->trunk_seed);
}

TEST(BarkSupport, BadInputNamesTreeOrTreeYears) {
  Result<BarkSupport> oak = GrowBarkSupport("oak", 6);
  ASSERT_FALSE(oak.ok());
  EXPECT_EQ(oak.status().field(), "tree");
  EXPECT_NE(oak.status().message().find("sakura"), std::string::npos) << oak.status().Line();
  for (double years : {0.0, 2.5, 101.0, std::nan("")}) {
    Result<BarkSupport> r = GrowBarkSupport("sakura", years);
    ASSERT_FALSE(r.ok()) << years;
    EXPECT_EQ(r.status().field(), "tree_years") << r.status().Line();
  }
}

// A budget that holds the tree grows the same bark as none; the estimate holds the heap the
// growth and the bark took (at most 6 × it).
TEST(BarkSupport, ARoomyBudgetGrowsTheSameBarkAndItsEstimateHoldsThePeak) {
  BarkBudget roomy;
  const long long base = test::AllocMeter::Reset();
  Result<BarkSupport> bark = GrowBarkSupport("sakura", 12, &roomy);
  const long long peak = test::AllocMeter::PeakAbove(base);
  ASSERT_TRUE(bark.ok()) << bark.status().Line();
  EXPECT_EQ(bark->truncated_by, "");
  Result<BarkSupport> unbudgeted = GrowBarkSupport("sakura", 12);
  ASSERT_TRUE(unbudgeted.ok());
  EXPECT_EQ(bark->mesh.positions, unbudgeted->mesh.positions);
  const double above_process = bark->estimate.memory_bytes - 64.0 * 1024 * 1024;
  EXPECT_GE(above_process, static_cast<double>(peak));
  EXPECT_LE(above_process, 6.0 * static_cast<double>(peak));
  EXPECT_NE(bark->estimate.what.find("growing the sakura tree (12 of 12 years) and building its "
                                     "bark ("),
            std::string::npos)
      << bark->estimate.what;
}

// Beyond the budget: the tree stops in a year with the tree's own line naming --tree-years, and
// what it grew fits; at the same budget the bark is the smaller tree's.
TEST(BarkSupport, ATightBudgetStopsTheTreeWithTheLine) {
  BarkBudget tight;
  tight.budget.memory_bytes = uint64_t{128} << 20;
  Result<BarkSupport> bark = GrowBarkSupport("sakura", 40, &tight);
  ASSERT_TRUE(bark.ok()) << bark.status().Line();
  EXPECT_EQ(bark->truncated_by.rfind("max_memory: stopped in year ", 0), 0u) << bark->truncated_by;
  EXPECT_NE(bark->truncated_by.find(" of 40: "), std::string::npos) << bark->truncated_by;
  EXPECT_NE(bark->truncated_by.find("lower tree_years"), std::string::npos) << bark->truncated_by;
  EXPECT_LE(bark->estimate.memory_bytes, static_cast<double>(tight.budget.memory_bytes));
  EXPECT_GT(bark->mesh.triangle_count(), 0u);
  // A time budget names its own limit and what to lower (the page's names too).
  BarkBudget quick;
  quick.budget.seconds = 1;
  quick.budget.seconds_limit = "page time budget";
  quick.years_name = "tree_years";
  // The tree stops within its own time check; its bark (3 µs a triangle) then crosses the second,
  // and is refused before it is built.
  Result<BarkSupport> timed = GrowBarkSupport("sakura", 100, &quick);
  ASSERT_FALSE(timed.ok());
  EXPECT_EQ(timed.status().field(), "page time budget") << timed.status().Line();
  EXPECT_NE(timed.status().Line().find(" of 100 years) and building its bark ("), std::string::npos)
      << timed.status().Line();
  EXPECT_NE(timed.status().Line().find("more than the 1 s allowed; lower tree_years"),
            std::string::npos)
      << timed.status().Line();
}

}  // namespace
}  // namespace niwa::compose
