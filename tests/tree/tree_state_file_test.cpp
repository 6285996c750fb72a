// Tests of the tree's state file (TreeStateFileJson, read by ApplyStateJson) and of --url links
// (TreeHashOfLink over io/hash_codec's SplitShareLink): round trips, partial files, refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/hash_codec.h"
#include "tree/presets.h"
#include "tree/tree_report.h"
#include "tree/tree_state.h"

namespace niwa {
namespace {

// Every field of the state, compared one by one (TreeState has no operator==).
void ExpectSameState(const TreeState& a, const TreeState& b) {
  EXPECT_EQ(a.preset, b.preset);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.years, b.years);
  EXPECT_EQ(a.params, b.params);
  EXPECT_EQ(a.camera, b.camera);
  ASSERT_EQ(a.prunes.size(), b.prunes.size());
  for (std::size_t i = 0; i < a.prunes.size(); ++i) {
    EXPECT_EQ(FormatPrune(a.prunes[i]), FormatPrune(b.prunes[i]));
  }
}

TreeState EditedState() {
  TreeState state;
  EXPECT_TRUE(SetStatePreset("keyaki-thesis", &state).ok());
  EXPECT_TRUE(SetStateSeed(4000000000.0, &state).ok());
  EXPECT_TRUE(SetStateYears(6, &state).ok());
  EXPECT_TRUE(state.params.SetFromAssignment("gamma=0.3").ok());
  EXPECT_TRUE(state.params.SetFromAssignment("wind_speed=12.5").ok());
  EXPECT_TRUE(state.params.Set(ParamId::kSwayDt, 1.0 / 60.0).ok());  // no short decimal text
  EXPECT_TRUE(AddStatePrune("4:b2", &state).ok());
  EXPECT_TRUE(AddStatePrune("5:since3", &state).ok());
  EXPECT_TRUE(SetStateCamera("0.6,0.25,10,0,1,0", &state).ok());
  return state;
}

TEST(TreeStateFile, RoundTripGivesTheSameState) {
  const TreeState state = EditedState();
  const std::string text = TreeStateFileJson(state);
  TreeState back;  // the default state, as 'niwa tree grow --state' starts from
  ASSERT_EQ(ApplyStateJson(text, &back).Line(), "");
  ExpectSameState(back, state);
  EXPECT_EQ(TreeStateFileJson(back), text);  // and the same bytes again
}

TEST(TreeStateFile, HoldsOnlyTheChangedParameters) {
  const TreeState state = EditedState();
  const nlohmann::json file = nlohmann::json::parse(TreeStateFileJson(state));
  EXPECT_EQ(file["preset"], "keyaki-thesis");
  EXPECT_EQ(file["seed"], 4000000000u);
  EXPECT_EQ(file["years"], 6);
  ASSERT_TRUE(file["params"].is_object());
  EXPECT_EQ(file["params"].size(), 3u) << file["params"].dump();
  EXPECT_EQ(file["params"]["gamma"], 0.3);
  EXPECT_EQ(file["params"]["wind_speed"], 12.5);
  EXPECT_EQ(file["params"]["dt"].get<double>(), 1.0 / 60.0);
  EXPECT_EQ(file["prunes"], nlohmann::json::array({"4:b2", "5:since3"}));
  EXPECT_EQ(file["camera"], "0.6,0.25,10,0,1,0");
  // The preset as it is: no parameters at all.
  TreeState plain;
  ASSERT_TRUE(SetStatePreset("maple", &plain).ok());
  EXPECT_TRUE(nlohmann::json::parse(TreeStateFileJson(plain))["params"].empty());
}

TEST(TreeStateFile, MissingKeysTakeThePresetsValues) {
  TreeState state;
  ASSERT_EQ(
      ApplyStateJson(R"({"preset": "tsutsuji-thesis", "params": {"gamma": 0.31}})", &state).Line(),
      "");
  const Preset& preset = *FindPreset("tsutsuji-thesis");
  EXPECT_EQ(state.seed, preset.seed);
  EXPECT_EQ(state.years, preset.years);
  EXPECT_EQ(state.params.Get(ParamId::kGamma), 0.31);
  TreeParams expected = preset.params;
  ASSERT_TRUE(expected.Set(ParamId::kGamma, 0.31).ok());
  EXPECT_EQ(state.params, expected);
  EXPECT_TRUE(state.prunes.empty());
  EXPECT_TRUE(state.camera.empty());
  // No preset: the default preset's values, with the file's on top.
  TreeState years_only;
  ASSERT_TRUE(ApplyStateJson(R"({"years": 3})", &years_only).ok());
  EXPECT_EQ(years_only.preset, kDefaultPreset);
  EXPECT_EQ(years_only.years, 3);
  EXPECT_EQ(years_only.params, FindPreset(kDefaultPreset)->params);
}

TEST(TreeStateFile, UnknownAndBadKeysAreRefusedByName) {
  struct Case {
    const char* text;
    const char* line;
  };
  const Case cases[] = {
      {R"({"preset": "maple", "colour": "red"})",
       "colour: unknown state key; the keys are preset, seed, years, params, prunes, camera"},
      {R"({"Years": 3})",
       "Years: unknown state key; the keys are preset, seed, years, params, prunes, camera"},
      {R"({"params": {"gama": 0.3}})", "unknown parameter 'gama'"},
      {R"({"years": 101})", "years: 101 is out of range; must be a whole number in [0, 100]"},
      {R"({"prunes": "4:b2"})", "prunes: must be an array of \"YEAR:bID\" or \"YEAR:sinceY\""},
      {R"({"preset": "oak"})", nullptr},  // names the presets: checked by prefix below
      {"[1, 2]", "state: must be a JSON object"},
      {"{\"years\": 3", "state: malformed JSON"},
  };
  for (const Case& c : cases) {
    TreeState state = EditedState();
    const std::string before = TreeStateFileJson(state);
    const std::string line = ApplyStateJson(c.text, &state).Line();
    if (c.line) {
      EXPECT_EQ(line, c.line) << c.text;
    } else {
      EXPECT_EQ(line.rfind("preset: unknown 'oak', must be one of ", 0), 0u) << line;
    }
    EXPECT_EQ(TreeStateFileJson(state), before) << "state changed by " << c.text;
  }
}

// The same tree grows from the flags' state and from its state file.
TEST(TreeStateFile, TheFileGrowsTheSameTree) {
  TreeState state = EditedState();
  state.prunes.clear();  // ids of another tree would cut nothing
  TreeState from_file;
  ASSERT_TRUE(ApplyStateJson(TreeStateFileJson(state), &from_file).ok());
  const Tree a = GrowTree(state);
  const Tree b = GrowTree(from_file);
  const TreeStats sa = ComputeStats(a), sb = ComputeStats(b);
  EXPECT_GT(sa.internodes, 10);
  EXPECT_EQ(sa.internodes, sb.internodes);
  EXPECT_EQ(sa.leaves, sb.leaves);
  EXPECT_EQ(sa.height, sb.height);
}

TEST(TreeLink, WholeLinksAndBareHashesGiveTheSameHash) {
  const std::string hash = "preset=keyaki-thesis&seed=3&years=7&gamma=0.3&prune=6:b2";
  for (const std::string& url :
       {hash, "#" + hash, "http://127.0.0.1:8080/#" + hash,
        "https://example.org/niwa/index.html#" + hash,
        "HTTPS://example.org/niwa/index.html?lang=ja#" + hash, "http://host#" + hash}) {
    Result<std::string> got = TreeHashOfLink(url);
    ASSERT_TRUE(got.ok()) << url << ": " << got.status().Line();
    EXPECT_EQ(*got, url[0] == '#' || url.find("://") == std::string::npos ? url : hash) << url;
    std::vector<std::string> notices;
    const TreeState state = DecodeTreeHash(*got, &notices);
    EXPECT_TRUE(notices.empty()) << url;
    EXPECT_EQ(state.preset, "keyaki-thesis");
    EXPECT_EQ(state.years, 7);
    ASSERT_EQ(state.prunes.size(), 1u);
  }
  // A link without a hash is the default tree.
  Result<std::string> bare = TreeHashOfLink("http://host/");
  ASSERT_TRUE(bare.ok());
  EXPECT_EQ(*bare, "");
}

TEST(TreeLink, OtherPagesAndSchemesAreRefused) {
  EXPECT_EQ(TreeHashOfLink("http://host/grove.html#wind_speed=3").status().Line(),
            "url: 'grove.html' is the grove page, not a tree link; give a link to index.html (the "
            "tree page) or its hash");
  EXPECT_EQ(TreeHashOfLink("https://host/a/ivy.html#preset=paper").status().Line(),
            "url: 'ivy.html' is not the tree page; give a link to index.html (the tree page) or "
            "its hash");
  EXPECT_EQ(TreeHashOfLink("ftp://host/#preset=sakura").status().Line(),
            "url: 'ftp://host/#preset=sakura' must be an http(s):// link or a bare hash");
  // Hostile page names are echoed as printable text.
  const std::string line = TreeHashOfLink("http://h/<b>\x1b.html#x=1").status().Line();
  EXPECT_EQ(line.find('<'), std::string::npos) << line;
  EXPECT_EQ(line.find('\x1b'), std::string::npos) << line;
}

TEST(ShareLink, SplitsPageAndHash) {
  ShareLink link = SplitShareLink("http://host:8080/dir/sub/index.html?q=1&r=2#a=1&b=2");
  EXPECT_TRUE(link.is_link);
  EXPECT_EQ(link.page, "index.html");
  EXPECT_EQ(link.hash, "a=1&b=2");
  EXPECT_EQ(link.error, "");
  link = SplitShareLink("http://host/dir/");
  EXPECT_TRUE(link.is_link);
  EXPECT_EQ(link.page, "");
  EXPECT_EQ(link.hash, "");
  link = SplitShareLink("a=1&cam=0,1,2");
  EXPECT_FALSE(link.is_link);
  EXPECT_EQ(link.hash, "a=1&cam=0,1,2");
  // "://" after the '#' is part of a (bare) hash's value, not a scheme.
  link = SplitShareLink("#caption=x://y");
  EXPECT_FALSE(link.is_link);
  EXPECT_EQ(link.hash, "#caption=x://y");
}

}  // namespace
}  // namespace niwa
