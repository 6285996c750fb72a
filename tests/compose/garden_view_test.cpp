// Tests of compose/garden_view (what a page draws of a garden run): each distinct tree's mesh at
// the page's detail has the tree's leaves and flowers as the tree study's full mesh has them, bark
// tubes of at most kGardenViewMaxSides sides (fewer triangles than the 12-sided default), and its
// trunk's foot at the origin; a run that records its years (the page's year scrubber) keeps, for
// year k of an N-year run, the picture of the same garden grown to k years: every distinct tree's
// mesh and the moss's light and count the same, bit for bit.
#include "compose/garden_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "compose/garden_moss.h"
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

// A small flat garden (the default's objects, hand-placed keyaki and rules' trees, close enough
// to shade each other) with a little moss and no ivy.
GardenState SmallGarden(int years) {
  GardenState s = DefaultGardenState();
  s.ground = GroundKind::kFlat;
  s.ivy_on.clear();  // the ivy is grown after the clock: not recorded
  EXPECT_TRUE(s.params.Set(GardenParam::kSize, 20).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kGroundRes, 16).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kYears, years).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kDensity, 0.02).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMossDays, 1).ok());
  LayOutDefaults(&s);
  return s;
}

TEST(GardenView, YearKOfARecordedRunIsTheGardenGrownToK) {
  constexpr int kYears = 4, kShown = 2;
  Result<GardenRun> whole = GardenRun::Start(SmallGarden(kYears), Budget{}, true);
  ASSERT_TRUE(whole.ok()) << whole.status().Line();
  ASSERT_TRUE(whole->Advance({}).ok());
  Result<GardenRun> grown = GardenRun::Start(SmallGarden(kShown), Budget{});
  ASSERT_TRUE(grown.ok()) << grown.status().Line();
  ASSERT_TRUE(grown->Advance({}).ok());
  ASSERT_EQ(whole->years().size(), static_cast<std::size_t>(kYears + 1));  // years 0..N
  EXPECT_TRUE(whole->record_stopped_by().empty()) << whole->record_stopped_by();
  EXPECT_TRUE(grown->years().empty());  // nothing recorded without record_years
  ASSERT_EQ(whole->groups().size(), grown->groups().size());
  int shaded = 0;
  for (int g = 0; g < static_cast<int>(grown->groups().size()); ++g) {
    shaded += grown->groups()[g].shaded ? 1 : 0;
    const TreeMesh at = GardenGroupMeshAt(*whole, g, kShown);
    const TreeMesh want = GardenGroupMesh(*grown, g);
    const std::string& name = grown->groups()[g].name;
    EXPECT_GT(want.bark.indices.size(), 0u) << name;
    EXPECT_EQ(at.bark.positions, want.bark.positions) << name;
    EXPECT_EQ(at.bark.indices, want.bark.indices) << name;
    EXPECT_EQ(at.leaves.positions, want.leaves.positions) << name;
    EXPECT_EQ(at.flowers.positions, want.flowers.positions) << name;
    // Year k is not year N: the trees grew since.
    EXPECT_LT(at.bark.indices.size(), GardenGroupMesh(*whole, g).bark.indices.size()) << name;
  }
  EXPECT_GT(shaded, 0);  // neighbours' shade is part of what is replayed
  // The moss of year k: its light on the ground and its count.
  const GardenYearRecord& k = whole->years()[kShown];
  EXPECT_EQ(k.year, kShown);
  ASSERT_NE(grown->moss(), nullptr);
  EXPECT_EQ(k.moss_light, GardenMossGroundLight(*grown->moss(), grown->scene().ground));
  EXPECT_EQ(k.mosses, static_cast<long>(grown->moss()->world().mosses.size()));
  // Every year is drawable; a year past the clock is not.
  for (int y = 0; y <= kYears; ++y) EXPECT_TRUE(GardenYearShown(*whole, y)) << y;
  EXPECT_FALSE(GardenYearShown(*whole, kYears + 1));
  EXPECT_GT(whole->record_bytes(), 0);
  // The last grown year is the run's own trees.
  EXPECT_EQ(whole->TreeAtYear(0, kYears), &whole->groups()[0].tree());
}

// Records that outgrow their share stop, say why, and change nothing else: a share that holds
// years 0..1 of a 3-year garden keeps those two, names year 2 in the line, and leaves the trees,
// the moss and the .glb those of the run that recorded every year.
TEST(GardenView, RecordsOverTheirShareStopAndSayWhy) {
  constexpr int kYears = 3, kKept = 2;
  const Budget budget{};
  Result<GardenRun> all = GardenRun::Start(SmallGarden(kYears), budget, true);
  ASSERT_TRUE(all.ok()) << all.status().Line();
  ASSERT_TRUE(all->Advance({}).ok());
  ASSERT_EQ(all->years().size(), static_cast<std::size_t>(kYears + 1));
  double kept_bytes = 0;
  for (int y = 0; y < kKept; ++y) kept_bytes += all->years()[y].bytes;
  const double next = all->years()[kKept].bytes;
  ASSERT_GT(next, 0);
  const double share = (kept_bytes + next / 2) / static_cast<double>(budget.memory_bytes);
  Result<GardenRun> part = GardenRun::Start(SmallGarden(kYears), budget, true, share);
  ASSERT_TRUE(part.ok()) << part.status().Line();
  ASSERT_TRUE(part->Advance({}).ok());
  EXPECT_EQ(part->years().size(), static_cast<std::size_t>(kKept));
  EXPECT_NE(part->record_stopped_by().find("year " + std::to_string(kKept)), std::string::npos)
      << part->record_stopped_by();
  for (int y = 0; y < kKept; ++y) EXPECT_TRUE(GardenYearShown(*part, y)) << y;
  EXPECT_FALSE(GardenYearShown(*part, kKept));  // not recorded: the page says it regrows
  EXPECT_TRUE(GardenYearShown(*part, kYears));  // the last year is the run's own
  EXPECT_EQ(part->TreeAtYear(0, kKept), nullptr);
  EXPECT_TRUE(GardenGroupMeshAt(*part, 0, kKept).bark.positions.empty());
  EXPECT_EQ(GardenGroupMeshAt(*part, 0, 1).bark.positions,
            GardenGroupMeshAt(*all, 0, 1).bark.positions);
  Result<std::string> part_glb = part->Export("glb"), all_glb = all->Export("glb");
  ASSERT_TRUE(part_glb.ok() && all_glb.ok());
  EXPECT_TRUE(*part_glb == *all_glb);
  // A share outside (0, 1) is refused, naming it.
  EXPECT_EQ(GardenRun::Start(SmallGarden(kYears), budget, true, 0).status().field(),
            "record_share");
}

}  // namespace
}  // namespace niwa::compose
