// Tests of JSON parameter reading (strict, one-line errors) and tree JSON writing.
#include "io/json_io.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

TEST(ParamsJson, AppliesValidValuesAndRejectsBadOnesWithoutChanges) {
  ParamSet p;
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": 0.3, "N_high": 12})", &p), "");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.3);
  EXPECT_EQ(ApplyParamsJson(R"({"params": {"gamma": 0.4}})", &p), "");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.4);
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": 0.1, "alpha_t": 2})", &p),
            "alpha_t: 2 is out of range; must be a number in [0, 1]");
  EXPECT_EQ(p.Get(ParamId::kGamma), 0.4);  // all or nothing
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": "high"})", &p), "gamma: must be a number in [0, 1]");
  EXPECT_EQ(ApplyParamsJson(R"({"bogus": 1})", &p), "unknown parameter 'bogus'");
  EXPECT_EQ(ApplyParamsJson("{\"gamma\": ", &p), "params: malformed JSON");
  EXPECT_EQ(ApplyParamsJson("[1,2]", &p), "params: the JSON must be an object of key: number");
}

TEST(ParamsJson, WriteThenReadIsIdentity) {
  ParamSet p = FindPreset("tsutsuji")->params;
  ParamSet q;
  EXPECT_EQ(ApplyParamsJson(ParamsToJson(p), &q), "");
  EXPECT_EQ(p, q);
}

TEST(ParamsJson, SwayAndWindRowsRoundTrip) {
  ParamSet p;
  EXPECT_EQ(ApplyParamsJson(R"({"wind_speed": 20, "K_rev": 0.7, "gust_front_speed": 4})", &p), "");
  EXPECT_EQ(p.Get(ParamId::kWindSpeed), 20.0);
  EXPECT_EQ(p.Get(ParamId::kKRev), 0.7);
  EXPECT_EQ(p.Get(ParamId::kGustFrontSpeed), 4.0);
  ParamSet q;
  EXPECT_EQ(ApplyParamsJson(ParamsToJson(p), &q), "");
  EXPECT_EQ(p, q);
  EXPECT_EQ(ApplyParamsJson(R"({"K_vdel": 1.5})", &p),
            "K_vdel: 1.5 is out of range; must be a number in [0, 1]");
}

TEST(TreeJson, HoldsEveryLivingBranchWithItsNodesBudsAndLeaves) {
  GrowRequest r;
  r.preset = "sakura";
  r.params = FindPreset("sakura")->params;
  r.years = 4;
  Tree tree = GrowTree(r);
  nlohmann::json j = nlohmann::json::parse(TreeToJson(tree));
  TreeStats stats = ComputeStats(tree);
  EXPECT_EQ(j["branches"].size(), static_cast<std::size_t>(stats.branches));
  std::size_t internodes = 0, leaves = 0;
  for (const auto& b : j["branches"]) {
    internodes += b["nodes"].size() - 1;
    leaves += b["leaves"].size();
  }
  EXPECT_EQ(internodes, static_cast<std::size_t>(stats.internodes));
  EXPECT_EQ(leaves, static_cast<std::size_t>(stats.leaves));
  EXPECT_EQ(j["params"]["alpha_t"], 0.7);
  EXPECT_EQ(nlohmann::json::parse(ParamTableJson()).size(), kParamCount);
}

}  // namespace
}  // namespace niwa
