// Moss on a grown terrain (core/compose/moss_on_terrain.h) and on the state's land
// (core/compose/moss_land.h): the mountain's surface in metres with y up, geology by slope and
// height as choice 30 says, regions by height thirds, the run through the state's scene the same
// bytes twice and its hash regrowing the same land; a bad preset or seed refused naming its field,
// and a run over the budget refused before anything grows.
#include "compose/moss_on_terrain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "compose/moss_land.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"

namespace niwa::compose {
namespace {

TEST(MossOnTerrain, TheMountainWithGeologyBySlopeAndHeight) {
  std::string truncated = "unset";
  Result<moss::MossScene> land = MossTerrainLand("improved", 1, Budget{}, &truncated);
  ASSERT_TRUE(land.ok()) << land.status().Line();
  EXPECT_EQ(truncated, "");
  EXPECT_EQ(land->name, "terrain:improved");
  const std::size_t n = land->mesh.triangle_count();
  ASSERT_GT(n, 1000u);
  ASSERT_EQ(land->geology.size(), n);
  ASSERT_EQ(land->region.size(), n);
  float lo = 1e30f, hi = -1e30f;
  for (const glm::vec3& p : land->mesh.positions) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
  EXPECT_EQ(lo, 0.0f);   // the disk's seed contour at h0 = 0
  EXPECT_GT(hi, 50.0f);  // a mountain in metres (the disk's relief is about 97 m)
  std::size_t by_geology[3] = {0, 0, 0};
  const double rock_cos = std::cos(kMossRockSlopeDeg * 3.14159265358979323846 / 180.0);
  for (std::size_t t = 0; t < n; ++t) {
    const glm::dvec3 a(land->mesh.positions[land->mesh.indices[3 * t]]),
        b(land->mesh.positions[land->mesh.indices[3 * t + 1]]),
        c(land->mesh.positions[land->mesh.indices[3 * t + 2]]);
    const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
    ASSERT_GT(normal.y, 0.0) << t;  // every face turned up (y up, counter-clockwise)
    const double share = ((a.y + b.y + c.y) / 3.0 - lo) / (hi - lo);
    const moss::Geology want = normal.y < rock_cos        ? moss::Geology::kAsphalt
                               : share > kMossUplandShare ? moss::Geology::kSandy
                                                          : moss::Geology::kHumus;
    ASSERT_EQ(land->geology[t], want) << t;
    ASSERT_EQ(land->region[t], share > 2.0 / 3.0 ? 2 : share > 1.0 / 3.0 ? 1 : 0) << t;
    ++by_geology[static_cast<int>(land->geology[t])];
  }
  EXPECT_GT(by_geology[0], 0u);  // humus below
  EXPECT_GT(by_geology[1], 0u);  // sandy on top
}

TEST(MossOnTerrain, TheStatesLandRunsAndItsHashRegrowsIt) {
  moss::MossState state;
  ASSERT_TRUE(moss::SetMossScene("terrain", &state).ok());
  ASSERT_TRUE(moss::SetMossTerrain("fig13b", &state).ok());
  ASSERT_TRUE(moss::SetMossTerrainSeed(3, &state).ok());
  ASSERT_TRUE(moss::SetMossDays(2, &state).ok());
  ASSERT_TRUE(state.params.Set(moss::MossParam::kPhotons, 256).ok());
  ASSERT_TRUE(state.params.Set(moss::MossParam::kSoilEdge, 2.0).ok());
  auto grown = [](const moss::MossState& s, std::string* hash) {
    Result<moss::MossRun> run = StartMossOnLand(s, Budget{}, {}, nullptr);
    EXPECT_TRUE(run.ok()) << run.status().Line();
    EXPECT_TRUE(run->Advance({}).ok());
    *hash = run->Hash("");
    return run->MossesJson();
  };
  std::string hash;
  const std::string first = grown(state, &hash);
  EXPECT_NE(hash.find("terrain=fig13b&terrain_seed=3"), std::string::npos) << hash;
  moss::MossState from_link;
  std::vector<std::string> notices;
  moss::ApplyMossHash(hash, "", &from_link, &notices);
  ASSERT_TRUE(notices.empty());
  std::string hash2;
  EXPECT_EQ(grown(from_link, &hash2), first);
  EXPECT_EQ(hash2, hash);
  // Another terrain seed grows another land.
  ASSERT_TRUE(moss::SetMossTerrainSeed(4, &from_link).ok());
  EXPECT_NE(grown(from_link, &hash2), first);
}

TEST(MossOnTerrain, BadTerrainAndBudgetAreRefusedNamingTheField) {
  Result<moss::MossScene> land = MossTerrainLand("everest", 1, Budget{}, nullptr);
  ASSERT_FALSE(land.ok());
  EXPECT_EQ(land.status().field(), "terrain");
  land = MossTerrainLand("improved", -1, Budget{}, nullptr);
  ASSERT_FALSE(land.ok());
  EXPECT_EQ(land.status().field(), "terrain_seed");
  // The default 300 days on the mountain's cells are over a 60 s budget: refused at the start,
  // naming the budget's limit.
  moss::MossState state;
  ASSERT_TRUE(moss::SetMossScene("terrain", &state).ok());
  Budget budget;
  budget.seconds = 60;
  Result<moss::MossRun> run = StartMossOnLand(state, budget, {}, nullptr);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.status().field(), "max_seconds") << run.status().Line();
  // Through the state, the tree's errors name its fields.
  ASSERT_TRUE(moss::SetMossScene("tree", &state).ok());
  ASSERT_TRUE(moss::SetMossTree("baobab", &state).ok());
  run = StartMossOnLand(state, Budget{}, {}, nullptr);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.status().field(), "tree");
  // core/moss alone refuses the lands it cannot grow.
  run = moss::MossRun::Start(state, Budget{});
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.status().field(), "scene");
}

}  // namespace
}  // namespace niwa::compose
