// The moss state's preset and share-link hash: preset first, rows clamped with a notice, repeated
// and unknown keys refused, the prefix of a composed page, and encode -> apply round trips.
#include <gtest/gtest.h>

#include "moss/moss_state.h"

namespace niwa::moss {
namespace {

TEST(MossState, HashAppliesThePresetFirstThenTheRows) {
  MossState state;
  std::vector<std::string> notices;
  ApplyMossHash("T=293.15&preset=nomura2010-sky", "", &state, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(state.preset, "nomura2010-sky");
  EXPECT_EQ(state.params.Get(MossParam::kT), 293.15);
  EXPECT_EQ(state.params.Get(MossParam::kSSky), 68.0);
  EXPECT_EQ(EncodeMossHash(state), "preset=nomura2010-sky&T=293.15");
}

TEST(MossState, BadKeysAndValuesGiveNotices) {
  MossState state;
  std::vector<std::string> notices;
  ApplyMossHash("rh=2&preset=nope&zz=1", "", &state, &notices);
  ASSERT_EQ(notices.size(), 3u);
  EXPECT_NE(notices[0].find("preset: 'nope' is unknown; must be nomura2010 or nomura2010-sky"),
            std::string::npos);
  EXPECT_NE(notices[1].find("rh"), std::string::npos);  // clamped into [0, 1]
  EXPECT_EQ(state.params.Get(MossParam::kRh), 1.0);
  EXPECT_EQ(notices[2], "unknown key 'zz' dropped");
  notices.clear();
  MossState fresh;
  ApplyMossHash("T=290&T=291", "", &fresh, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("T: given 2 times"), std::string::npos);
  EXPECT_EQ(fresh.params.Get(MossParam::kT), 288.15);  // refused whole
}

TEST(MossState, PrefixedKeysOnAComposedPage) {
  MossState state;
  std::vector<std::string> notices;
  ApplyMossHash("moss.gingoke_tau_d=0.2&ivy.steps=3", "moss.", &state, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(state.params.Get(SpeciesRow(Species::kGingoke, 12)), 0.2);
  const std::string hash = EncodeMossHash(state, "moss.");
  EXPECT_EQ(hash, "moss.preset=nomura2010&moss.gingoke_tau_d=0.2");
  MossState back;
  ApplyMossHash(hash, "moss.", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(static_cast<const ParamSet&>(back.params), static_cast<const ParamSet&>(state.params));
  EXPECT_EQ(SetMossPreset("x", &back).field(), "preset");
}

// The land of another study is state: scene tree with tree and tree_years, scene terrain with
// terrain and terrain_seed, in the hash (on their scene only) and the state JSON, read back to the
// same state; bad values are refused naming their field.
TEST(MossState, TheLandIsStateAndItsHashRegrowsIt) {
  MossState state;
  ASSERT_TRUE(SetMossScene("tree", &state).ok());
  ASSERT_TRUE(SetMossTree("sakura", &state).ok());
  ASSERT_TRUE(SetMossTreeYears(4, &state).ok());
  ASSERT_TRUE(SetMossTerrainSeed(9, &state).ok());  // not on the tree's scene: not in the hash
  const std::string hash = EncodeMossHash(state, "moss.");
  EXPECT_EQ(hash, "moss.preset=nomura2010&moss.scene=tree&moss.tree=sakura&moss.tree_years=4");
  MossState back;
  std::vector<std::string> notices;
  ApplyMossHash(hash, "moss.", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.scene, "tree");
  EXPECT_EQ(back.tree, "sakura");
  EXPECT_EQ(back.tree_years, 4);
  MossState from_json;
  ASSERT_TRUE(ApplyMossStateJson(MossStateJson(back), &from_json).ok());
  EXPECT_EQ(EncodeMossHash(from_json), "preset=nomura2010&scene=tree&tree=sakura&tree_years=4");

  MossState terrain;
  ApplyMossHash("scene=terrain&terrain=fig16&terrain_seed=7", "", &terrain, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(terrain.terrain, "fig16");
  EXPECT_EQ(terrain.terrain_seed, 7u);
  EXPECT_EQ(EncodeMossHash(terrain),
            "preset=nomura2010&scene=terrain&terrain=fig16&terrain_seed=7");
  MossState terrain_back;
  ASSERT_TRUE(ApplyMossStateJson(MossStateJson(terrain), &terrain_back).ok());
  EXPECT_EQ(EncodeMossHash(terrain_back), EncodeMossHash(terrain));
  // A built-in scene writes no land fields (links of before keep their bytes).
  EXPECT_EQ(MossStateJson(MossState()).find("tree"), std::string::npos);

  EXPECT_EQ(SetMossTree("Sakura!", &state).field(), "tree");
  EXPECT_EQ(SetMossTreeYears(0, &state).field(), "tree_years");
  EXPECT_EQ(SetMossTreeYears(2.5, &state).field(), "tree_years");
  EXPECT_EQ(SetMossTerrain("", &state).field(), "terrain");
  EXPECT_EQ(SetMossTerrainSeed(-1, &state).field(), "terrain_seed");
  EXPECT_EQ(ApplyMossStateJson(R"({"tree_years": 200})", &state).field(), "tree_years");
  notices.clear();
  ApplyMossHash("tree_years=x", "", &state, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(state.tree_years, 4);
}

}  // namespace
}  // namespace niwa::moss
