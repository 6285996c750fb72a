// Tests of JSON parameter reading (strict, one-line errors) and the table as JSON, on the tree
// table.
#include "params/param_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tree/presets.h"
#include "tree/tree_params.h"

namespace niwa {
namespace {

TEST(ParamsJson, AppliesValidValuesAndRejectsBadOnesWithoutChanges) {
  TreeParams p;
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": 0.3, "N_high": 12})", &p).Line(), "");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.3);
  EXPECT_EQ(ApplyParamsJson(R"({"params": {"gamma": 0.4}})", &p).Line(), "");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.4);
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": 0.1, "alpha_t": 2})", &p).Line(),
            "alpha_t: 2 is out of range; must be a number in [0, 1]");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.4);  // all or nothing
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": "high"})", &p).Line(),
            "gamma: must be a number in [0, 1]");
  EXPECT_EQ(ApplyParamsJson(R"({"bogus": 1})", &p).Line(), "unknown parameter 'bogus'");
  EXPECT_EQ(ApplyParamsJson("{\"gamma\": ", &p).Line(), "params: malformed JSON");
  EXPECT_EQ(ApplyParamsJson("[1,2]", &p).Line(),
            "params: the JSON must be an object of key: number");
}

TEST(ParamsJson, WriteThenReadIsIdentity) {
  TreeParams p = FindPreset("tsutsuji-thesis")->params;
  TreeParams q;
  EXPECT_EQ(ApplyParamsJson(ParamsToJson(p), &q).Line(), "");
  EXPECT_EQ(p, q);
}

TEST(ParamsJson, TopLevelFieldsAreSkippedOnlyWhenListed) {
  TreeParams p;
  EXPECT_EQ(ApplyParamsJson(R"({"name": "x", "years": 3, "gamma": 0.3})", &p).Line(),
            "unknown parameter 'name'");
  EXPECT_EQ(
      ApplyParamsJson(R"({"name": "x", "years": 3, "gamma": 0.3})", &p, PresetFileFields()).Line(),
      "");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.3);
}

TEST(ParamTableJson, EveryRowCarriesItsStageAndGroupTitle) {
  nlohmann::json rows = nlohmann::json::parse(ParamTableJson(TreeParamTable()));
  ASSERT_EQ(rows.size(), kParamCount);
  for (const auto& row : rows) {
    for (const char* key : {"key", "symbol", "unit", "default", "min", "max", "integer", "group",
                            "group_title", "stage", "help"}) {
      EXPECT_TRUE(row.contains(key)) << key;
    }
  }
  EXPECT_EQ(rows[0]["key"], "alpha_t");
  EXPECT_EQ(rows[0]["group_title"], "Hormone");
  EXPECT_EQ(rows[0]["stage"], "grow");
  const auto wind = rows[static_cast<std::size_t>(TreeParam::kWindSpeed)];
  EXPECT_EQ(wind["group_title"], "Wind");
  EXPECT_EQ(wind["stage"], "sway");
  const auto threshold = rows[static_cast<std::size_t>(TreeParam::kLineThreshold)];
  EXPECT_EQ(threshold["group"], "render");
  EXPECT_EQ(threshold["stage"], "view");
}

TEST(ParamsJson, SwayAndWindRowsRoundTrip) {
  TreeParams p;
  EXPECT_EQ(
      ApplyParamsJson(R"({"wind_speed": 20, "K_rev": 0.7, "gust_front_speed": 4})", &p).Line(), "");
  EXPECT_EQ(p.Get(ParamId::kWindSpeed), 20.0);
  EXPECT_EQ(p.Get(ParamId::kKRev), 0.7);
  EXPECT_EQ(p.Get(ParamId::kGustFrontSpeed), 4.0);
  TreeParams q;
  EXPECT_EQ(ApplyParamsJson(ParamsToJson(p), &q).Line(), "");
  EXPECT_EQ(p, q);
  EXPECT_EQ(ApplyParamsJson(R"({"K_vdel": 1.5})", &p).Line(),
            "K_vdel: 1.5 is out of range; must be a number in [0, 1]");
}

}  // namespace
}  // namespace niwa
