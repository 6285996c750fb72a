// Moss on a grown tree (core/compose/moss_on_tree.h): the land is the tree's bark (sandy, region
// bark) over a humus square (region ground) wide enough for the crown, its soil cells land in both
// regions, moss grows on it through MossRun::StartOnScene, the same bytes twice, and a bad preset
// or age is refused naming its field.
#include "compose/moss_on_tree.h"

#include <gtest/gtest.h>

#include <cmath>

#include "compose/bark_support.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "moss/soil_cells.h"

namespace niwa::compose {
namespace {

TEST(MossOnTree, BarkOverAHumusSquare) {
  std::string truncated = "unset";
  Result<moss::MossScene> land = MossTreeLand("sakura", 4, Budget{}, "tree_years", &truncated);
  ASSERT_TRUE(land.ok()) << land.status().Line();
  EXPECT_EQ(truncated, "");
  EXPECT_EQ(land->name, "tree:sakura");
  const BarkSupport bark = GrowBarkSupport("sakura", 4).value();
  ASSERT_EQ(land->mesh.triangle_count(), bark.mesh.triangle_count() + 2);
  ASSERT_EQ(land->geology.size(), land->mesh.triangle_count());
  ASSERT_EQ(land->region.size(), land->mesh.triangle_count());
  for (std::size_t t = 0; t < bark.mesh.triangle_count(); ++t) {
    ASSERT_EQ(land->geology[t], moss::Geology::kSandy);
    ASSERT_EQ(land->region[t], 0);
  }
  EXPECT_EQ(land->geology.back(), moss::Geology::kHumus);
  EXPECT_EQ(land->region_names[land->region.back()], "ground");
  // The ground reaches past every bark point by the margin.
  float reach = 0, half = 0;
  for (const glm::vec3& p : bark.mesh.positions)
    reach = std::max(reach, std::max(std::abs(p.x), std::abs(p.z)));
  for (std::size_t v = bark.mesh.positions.size(); v < land->mesh.positions.size(); ++v) {
    EXPECT_EQ(land->mesh.positions[v].y, 0.0f);
    half = std::max(half, std::abs(land->mesh.positions[v].x));
  }
  EXPECT_GE(half, std::max(static_cast<float>(kMossGroundMinHalf), reach));

  const moss::SoilCells cells = moss::MakeSoilCells(*land, moss::SoilCellOptions{}).value();
  std::size_t in[2] = {0, 0};
  for (uint8_t r : cells.region) ++in[r];
  EXPECT_GT(in[0], 0u);
  EXPECT_GT(in[1], 0u);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells.region[i] == 1) {
      ASSERT_GT(cells.normal[i].y, 0.999);  // the ground faces up
    }
  }

  moss::MossState state;
  ASSERT_TRUE(moss::SetMossDays(3, &state).ok());
  ASSERT_TRUE(state.params.Set(moss::MossParam::kPhotons, 512).ok());
  std::string stats;
  auto grown = [&]() {
    moss::MossRun run = moss::MossRun::StartOnScene(state, *land, Budget{}, land->name).value();
    EXPECT_TRUE(run.Advance({}).ok());
    stats = run.StatsJson();
    return run.MossesJson();  // no timings
  };
  const std::string first = grown();
  EXPECT_EQ(first, grown());
  EXPECT_NE(stats.find("\"bark\""), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"ground\""), std::string::npos) << stats;
}

TEST(MossOnTree, BadTreeIsRefusedNamingTheField) {
  Result<moss::MossScene> land = MossTreeLand("baobab", 4, Budget{}, "tree_years", nullptr);
  ASSERT_FALSE(land.ok());
  EXPECT_EQ(land.status().field(), "tree");
  land = MossTreeLand("sakura", 0, Budget{}, "tree_years", nullptr);
  ASSERT_FALSE(land.ok());
  EXPECT_EQ(land.status().field(), "tree_years");
}

}  // namespace
}  // namespace niwa::compose
