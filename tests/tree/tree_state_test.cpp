// Tests of the tree state resolver: the same state from flags (setters), state JSON and a
// share-link hash; old links and JSON decode unchanged; hostile hashes clamped with notices.
#include "tree/tree_state.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tree/presets.h"

namespace niwa {
namespace {

TEST(TreeHash, RoundTripKeepsOnlyChangedParameters) {
  TreeState state;
  state.preset = "keyaki-thesis";
  state.params = FindPreset("keyaki-thesis")->params;
  state.seed = 9;
  state.years = 7;
  EXPECT_TRUE(state.params.Set(ParamId::kGamma, 0.35).ok());
  state.prunes.push_back({5, 12, -1});
  state.prunes.push_back({6, -1, 3});
  std::string hash = EncodeTreeHash(state);
  EXPECT_EQ(hash, "preset=keyaki-thesis&seed=9&years=7&gamma=0.35&prune=5:b12&prune=6:since3");
  std::vector<std::string> notices;
  TreeState back = DecodeTreeHash("#" + hash, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.preset, "keyaki-thesis");
  EXPECT_EQ(back.seed, 9u);
  EXPECT_EQ(back.years, 7);
  EXPECT_EQ(back.params, state.params);
  ASSERT_EQ(back.prunes.size(), 2u);
  EXPECT_EQ(back.prunes[0].branch, 12);
  EXPECT_EQ(back.prunes[1].since_year, 3);
}

TEST(TreeHash, RoundTripsSwayAndWindParameters) {
  TreeState state;
  state.preset = "sakura-thesis";
  state.params = FindPreset("sakura-thesis")->params;
  EXPECT_TRUE(state.params.Set(ParamId::kWindSpeed, 12.5).ok());
  EXPECT_TRUE(state.params.Set(ParamId::kWindVariation, 0.3).ok());
  EXPECT_TRUE(state.params.Set(ParamId::kSwayDt, 1.0 / 60.0).ok());
  std::string hash = EncodeTreeHash(state);
  // Only the changed rows, in table order, with the shortest exact number text.
  EXPECT_NE(hash.find("&dt=0.016666666666666666&wind_speed=12.5&wind_variation=0.3"),
            std::string::npos)
      << hash;
  EXPECT_EQ(hash.find("K_wind"), std::string::npos) << hash;
  EXPECT_EQ(hash.find("gust_on"), std::string::npos) << hash;
  std::vector<std::string> notices;
  TreeState back = DecodeTreeHash(hash, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.params, state.params);
  EXPECT_EQ(back.params.Get(ParamId::kSwayDt), 1.0 / 60.0);
  // Out of range: clamped with a notice naming the key and its range.
  back = DecodeTreeHash("wind_variation=3", &notices);
  EXPECT_EQ(back.params.Get(ParamId::kWindVariation), 1.0);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0], "wind_variation: clamped to 1, must be a number in [0, 1]");
}

TEST(TreeHash, HostileInputIsClampedOrDroppedWithNotices) {
  std::vector<std::string> notices;
  TreeState s = DecodeTreeHash(
      "preset=%3Cscript%3E&years=1e9&seed=-5&gamma=abc&alpha_t=7&evil=1&N_high=2.6&prune=x&cam=<b>",
      &notices);
  EXPECT_EQ(s.preset, kDefaultPreset);
  EXPECT_EQ(s.years, kMaxYears);
  EXPECT_EQ(s.seed, 0u);
  EXPECT_EQ(s.params.Get(ParamId::kGamma), FindPreset(kDefaultPreset)->params.Get(ParamId::kGamma));
  EXPECT_EQ(s.params.Get(ParamId::kAlphaT), 1.0);
  EXPECT_EQ(s.params.Get(ParamId::kNHigh), 3.0);
  EXPECT_TRUE(s.prunes.empty());
  EXPECT_TRUE(s.camera.empty());
  ASSERT_EQ(notices.size(), 9u);
  for (const std::string& n : notices) {
    EXPECT_EQ(n.find('<'), std::string::npos) << n;
    EXPECT_EQ(n.find('\n'), std::string::npos) << n;
  }
}

TEST(TreeHash, EmptyHashGivesTheDefaultPreset) {
  std::vector<std::string> notices;
  TreeState s = DecodeTreeHash("", &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(s.preset, kDefaultPreset);
  EXPECT_EQ(s.years, FindPreset(kDefaultPreset)->years);
}

// One state given three ways, as the CLI flags, the page's state JSON and a share link give it.
TEST(TreeState, FlagsJsonAndHashResolveToTheSameState) {
  TreeState by_setters;  // what 'niwa tree grow --preset keyaki --years 7 --seed 3 ...' does
  ASSERT_TRUE(SetStatePreset("keyaki-thesis", &by_setters).ok());
  ASSERT_TRUE(SetStateYears(7, &by_setters).ok());
  ASSERT_TRUE(SetStateSeed(3, &by_setters).ok());
  ASSERT_TRUE(by_setters.params.SetFromAssignment("gamma=0.3").ok());
  ASSERT_TRUE(by_setters.params.SetFromAssignment("wind_speed=12").ok());
  ASSERT_TRUE(AddStatePrune("6:b2", &by_setters).ok());
  ASSERT_TRUE(AddStatePrune("7:since5", &by_setters).ok());
  ASSERT_TRUE(SetStateCamera("0.6,0.25,10,0,1,0", &by_setters).ok());

  TreeState by_json;
  ASSERT_EQ(ApplyStateJson(R"({"preset": "keyaki-thesis", "years": 7, "seed": 3,
      "params": {"gamma": 0.3, "wind_speed": 12}, "prunes": ["6:b2", "7:since5"],
      "camera": "0.6,0.25,10,0,1,0"})",
                           &by_json)
                .Line(),
            "");
  std::vector<std::string> notices;
  TreeState by_hash = DecodeTreeHash(
      "#preset=keyaki-thesis&seed=3&years=7&gamma=0.3&wind_speed=12&prune=6:b2&prune=7:since5&cam="
      "0.6,"
      "0.25,10,0,1,0",
      &notices);
  EXPECT_TRUE(notices.empty());
  for (const TreeState* s : {&by_json, &by_hash}) {
    EXPECT_EQ(s->preset, by_setters.preset);
    EXPECT_EQ(s->years, by_setters.years);
    EXPECT_EQ(s->seed, by_setters.seed);
    EXPECT_EQ(s->params, by_setters.params);
    EXPECT_EQ(s->camera, by_setters.camera);
    ASSERT_EQ(s->prunes.size(), 2u);
    EXPECT_EQ(FormatPrune(s->prunes[0]), "6:b2");
    EXPECT_EQ(FormatPrune(s->prunes[1]), "7:since5");
  }
  // And back: the state JSON and the hash read back to the same state.
  TreeState again;
  ASSERT_TRUE(ApplyStateJson(TreeStateJson(by_setters), &again).ok());
  EXPECT_EQ(EncodeTreeHash(again), EncodeTreeHash(by_setters));
  EXPECT_EQ(
      EncodeTreeHash(by_setters),
      "preset=keyaki-thesis&seed=3&years=7&gamma=0.3&wind_speed=12&prune=6:b2&prune=7:since5&cam=0."
      "6,0.25,10,0,1,0");
  // The same tree grows from each.
  EXPECT_EQ(ComputeStats(GrowTree(by_json)).internodes,
            ComputeStats(GrowTree(by_setters)).internodes);
}

// What the tree page (web/tree/tree_page.js) sends: numbers or numeric strings, booleans for 0/1
// rows.
TEST(TreeState, TheStateJsonOfThePageReadsAsBefore) {
  TreeState state;
  ASSERT_EQ(ApplyStateJson(R"({"preset":"maple","seed":"12","years":"4",
      "params":{"gamma":"0.25","use_light":false,"N_high":9},"prunes":[],"camera":""})",
                           &state)
                .Line(),
            "");
  EXPECT_EQ(state.preset, "maple");
  EXPECT_EQ(state.seed, 12u);
  EXPECT_EQ(state.years, 4);
  EXPECT_EQ(state.params.Get(ParamId::kGamma), 0.25);
  EXPECT_EQ(state.params.Get(ParamId::kUseLight), 0.0);
  EXPECT_EQ(state.params.Get(ParamId::kNHigh), 9.0);
  EXPECT_EQ(state.params.Get(ParamId::kAlphaT), FindPreset("maple")->params.Get(ParamId::kAlphaT));
  // Missing fields keep the default preset's values.
  TreeState empty;
  ASSERT_TRUE(ApplyStateJson("{}", &empty).ok());
  EXPECT_EQ(empty.preset, kDefaultPreset);
  EXPECT_EQ(empty.years, FindPreset(kDefaultPreset)->years);
  EXPECT_EQ(empty.params, FindPreset(kDefaultPreset)->params);
}

TEST(TreeState, BadStateJsonIsOneLineNamingTheFieldAndChangesNothing) {
  const TreeState before;
  auto error = [&](const std::string& text) {
    TreeState state;
    Status status = ApplyStateJson(text, &state);
    EXPECT_EQ(EncodeTreeHash(state), EncodeTreeHash(before)) << text;  // unchanged
    EXPECT_EQ(status.Line().find('\n'), std::string::npos);
    return status.Line();
  };
  EXPECT_EQ(error("{"), "state: malformed JSON");
  EXPECT_EQ(error("[]"), "state: must be a JSON object");
  EXPECT_EQ(error(R"({"preset": "oak"})").rfind("preset: unknown 'oak', must be one of binary", 0),
            0u);
  EXPECT_EQ(error(R"({"years": 101})"),
            "years: 101 is out of range; must be a whole number in [0, 100]");
  EXPECT_EQ(error(R"({"years": 2.5})"),
            "years: 2.5 is out of range; must be a whole number in [0, 100]");
  EXPECT_EQ(error(R"({"seed": "x"})"), "seed: must be a whole number in [0, 4294967295]");
  EXPECT_EQ(error(R"({"seed": 1, "params": {"gamma": 2}})"),
            "gamma: 2 is out of range; must be a number in [0, 1]");
  EXPECT_EQ(error(R"({"params": {"nope": 1}})"), "unknown parameter 'nope'");
  EXPECT_EQ(error(R"({"params": {"gamma": [1]}})"), "gamma: must be a number in [0, 1]");
  EXPECT_EQ(error(R"({"params": 3})"), "params: must be an object of key: value");
  EXPECT_EQ(error(R"({"prunes": "6:b2"})"),
            "prunes: must be an array of \"YEAR:bID\" or \"YEAR:sinceY\"");
  EXPECT_EQ(error(R"({"prunes": ["6:x"]})"),
            "prune: '6:x' must be YEAR:bID or YEAR:sinceY with YEAR in [1, 100]");
  EXPECT_EQ(error(R"({"camera": "<b>"})").rfind("camera: must be yaw,pitch,distance,tx,ty,tz", 0),
            0u);
  // Issue 16 item 9: a far or infinite camera is refused, not drawn as a blank canvas.
  EXPECT_NE(error(R"({"camera": "0,0.3,10,1e39,0,0"})"), "");
  EXPECT_NE(error(R"({"camera": "0,0.3,10,20000,0,0"})"), "");
}

TEST(TreeState, SettersCheckTheirRangesAndKeepTheStateOnError) {
  TreeState state;
  EXPECT_EQ(SetStateYears(-1, &state).Line(),
            "years: -1 is out of range; must be a whole number in [0, 100]");
  EXPECT_EQ(SetStateSeed(4294967296.0, &state).Line(),
            "seed: 4294967296 is out of range; must be a whole number in [0, 4294967295]");
  EXPECT_EQ(state.years, FindPreset(kDefaultPreset)->years);
  EXPECT_EQ(state.seed, FindPreset(kDefaultPreset)->seed);
  for (std::size_t i = 0; i < kMaxPrunes; ++i) ASSERT_TRUE(AddStatePrune("1:b0", &state).ok());
  EXPECT_EQ(AddStatePrune("1:b0", &state).Line(), "prune: at most 256 prunes");
  EXPECT_EQ(state.prunes.size(), kMaxPrunes);
}

// On a composed page the tree's keys carry a prefix; other studies' keys are not the tree's.
TEST(TreeHash, APrefixKeepsTheTreeKeysApartFromOtherStudies) {
  TreeState state;
  ASSERT_TRUE(SetStatePreset("pine", &state).ok());
  ASSERT_TRUE(state.params.Set(ParamId::kGamma, 0.3).ok());
  ASSERT_TRUE(AddStatePrune("3:b1", &state).ok());
  std::string hash = EncodeTreeHash(state, "tree.");
  EXPECT_EQ(hash.rfind("tree.preset=pine&tree.seed=", 0), 0u) << hash;
  EXPECT_NE(hash.find("&tree.gamma=0.3&tree.prune=3:b1"), std::string::npos) << hash;
  std::vector<std::string> notices;
  TreeState back = DecodeTreeHash(hash + "&ivy.t1=4&gamma=0.9&mode=full", &notices, "tree.");
  EXPECT_TRUE(notices.empty()) << notices.front();
  EXPECT_EQ(back.preset, "pine");
  EXPECT_EQ(back.params, state.params);
  ASSERT_EQ(back.prunes.size(), 1u);
  back = DecodeTreeHash("tree.gamma=7&tree.nope=1", &notices, "tree.");
  EXPECT_EQ(back.params.Get(ParamId::kGamma), 1.0);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_EQ(notices[0], "tree.gamma: clamped to 1, must be a number in [0, 1]");
  EXPECT_EQ(notices[1], "unknown key 'tree.nope' dropped");
}

}  // namespace
}  // namespace niwa
