// Tests of the share-link hash codec: round trips and hostile input.
#include "io/url_codec.h"

#include <gtest/gtest.h>

#include "tree/presets.h"

namespace niwa {
namespace {

TEST(UrlCodec, RoundTripKeepsOnlyChangedParameters) {
  TreeState state;
  state.preset = "keyaki";
  state.params = FindPreset("keyaki")->params;
  state.seed = 9;
  state.years = 7;
  state.params.Set(ParamId::kGamma, 0.35);
  state.prunes.push_back({5, 12, -1});
  state.prunes.push_back({6, -1, 3});
  std::string hash = EncodeStateHash(state);
  EXPECT_EQ(hash, "preset=keyaki&seed=9&years=7&gamma=0.35&prune=5:b12&prune=6:since3");
  std::vector<std::string> notices;
  TreeState back = DecodeStateHash("#" + hash, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.preset, "keyaki");
  EXPECT_EQ(back.seed, 9u);
  EXPECT_EQ(back.years, 7);
  EXPECT_EQ(back.params, state.params);
  ASSERT_EQ(back.prunes.size(), 2u);
  EXPECT_EQ(back.prunes[0].branch, 12);
  EXPECT_EQ(back.prunes[1].since_year, 3);
}

TEST(UrlCodec, RoundTripsSwayAndWindParameters) {
  TreeState state;
  state.preset = "sakura";
  state.params = FindPreset("sakura")->params;
  state.params.Set(ParamId::kWindSpeed, 12.5);
  state.params.Set(ParamId::kWindVariation, 0.3);
  state.params.Set(ParamId::kSwayDt, 1.0 / 60.0);
  std::string hash = EncodeStateHash(state);
  // Only the changed rows, in table order, with the shortest exact number text.
  EXPECT_NE(hash.find("&dt=0.016666666666666666&wind_speed=12.5&wind_variation=0.3"),
            std::string::npos)
      << hash;
  EXPECT_EQ(hash.find("K_wind"), std::string::npos) << hash;
  EXPECT_EQ(hash.find("gust_on"), std::string::npos) << hash;
  std::vector<std::string> notices;
  TreeState back = DecodeStateHash(hash, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.params, state.params);
  EXPECT_EQ(back.params.Get(ParamId::kSwayDt), 1.0 / 60.0);
  // Out of range: clamped with a notice naming the key and its range.
  back = DecodeStateHash("wind_variation=3", &notices);
  EXPECT_EQ(back.params.Get(ParamId::kWindVariation), 1.0);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0], "wind_variation: clamped to 1, must be a number in [0, 1]");
}

TEST(UrlCodec, HostileInputIsClampedOrDroppedWithNotices) {
  std::vector<std::string> notices;
  TreeState s = DecodeStateHash(
      "preset=%3Cscript%3E&years=1e9&seed=-5&gamma=abc&alpha_t=7&evil=1&N_high=2.6&prune=x&cam=<b>",
      &notices);
  EXPECT_EQ(s.preset, "sakura");
  EXPECT_EQ(s.years, kMaxYears);
  EXPECT_EQ(s.seed, 0u);
  EXPECT_EQ(s.params.Get(ParamId::kGamma), FindPreset("sakura")->params.Get(ParamId::kGamma));
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

TEST(UrlCodec, EmptyHashGivesTheDefaultPreset) {
  std::vector<std::string> notices;
  TreeState s = DecodeStateHash("", &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(s.preset, "sakura");
  EXPECT_EQ(s.years, FindPreset("sakura")->years);
}

}  // namespace
}  // namespace niwa
