// Ivy state: the table (Table 2 values with their symbols), presets, JSON and hash round trips,
// the "ivy." prefix on a composed page, and hostile values naming their field.
#include <gtest/gtest.h>

#include "ivy/ivy_params.h"
#include "ivy/ivy_state.h"

namespace niwa::ivy {
namespace {

TEST(IvyTable, HoldsTable2WithItsSymbols) {
  const ParamTable& t = IvyTable();
  EXPECT_EQ(t.name(), "ivy");
  EXPECT_EQ(t.size(), static_cast<std::size_t>(IvyParam::kCount));
  IvyParams p;
  EXPECT_EQ(p.Get(IvyParam::kL), 50.0);
  EXPECT_EQ(p.Get(IvyParam::kD), 20.0);
  EXPECT_EQ(p.Get(IvyParam::kT1), 0.2);
  EXPECT_EQ(p.Get(IvyParam::kT2), 0.8);
  EXPECT_EQ(std::string(t[*t.Find("t1")].symbol), "t₁");
  EXPECT_EQ(std::string(t[*t.Find("d")].unit), "px");
  EXPECT_TRUE(ValidateIvyParams(p).ok());
}

TEST(IvyTable, PresetsChangeWhatTheySay) {
  // metric: the paper's rows at 1000 px per unit; scaled, they are the old metric lengths exactly
  // (a division: 50 / 1000 == 0.05 as written).
  IvyParams metric = *IvyPreset("metric");
  EXPECT_EQ(metric.Get(IvyParam::kScale), 1000.0);
  IvyParams scaled = *IvyScaledParams(metric, metric.Get(IvyParam::kScale));
  EXPECT_EQ(scaled.Get(IvyParam::kL), 0.05);
  EXPECT_EQ(scaled.Get(IvyParam::kD), 0.02);
  EXPECT_EQ(scaled.Get(IvyParam::kEps), 0.002);
  EXPECT_EQ(scaled.Get(IvyParam::kRTip), 0.0015);
  EXPECT_EQ(scaled.Get(IvyParam::kLeafSize), 0.05);
  EXPECT_EQ(scaled.Get(IvyParam::kPetiole), 0.02);
  EXPECT_EQ(scaled.Get(IvyParam::kScale), 1.0);  // now per scene unit
  EXPECT_TRUE(ValidateIvyParams(metric).ok());
  IvyParams improved = *IvyPreset("improved");
  EXPECT_EQ(improved.Get(IvyParam::kMaxBend), 60.0);
  EXPECT_EQ(improved.Get(IvyParam::kAvoid), 10.0);
  IvyParams literal = *IvyPreset("literal");
  EXPECT_EQ(literal.Get(IvyParam::kKappa), 0.0);
  EXPECT_EQ(literal.Get(IvyParam::kLambda), 1.0);
  EXPECT_EQ(IvyPresetNames().size(), 5u);
}

TEST(IvyTable, CrossRowChecksNameTheField) {
  IvyParams p;
  ASSERT_TRUE(p.Set(IvyParam::kT1, 0.8).ok());
  EXPECT_EQ(ValidateIvyParams(p).Line(),
            "t1: 0.8 is not below t2 = 0.8; must be in [0, t2) (§3.1: t1 < t2)");
  IvyParams q;
  ASSERT_TRUE(q.Set(IvyParam::kEps, 25).ok());
  EXPECT_EQ(ValidateIvyParams(q).field(), "eps");
  IvyParams r;
  ASSERT_TRUE(r.Set(IvyParam::kAlpha, 0.5).ok());
  EXPECT_EQ(ValidateIvyParams(r).field(), "alpha");
}

TEST(IvyState, JsonAppliesPresetThenValues) {
  IvyState s;
  EXPECT_EQ(
      ApplyIvyStateJson(R"({"preset":"improved","seed":4,"steps":30,"params":{"t1":0.3}})", &s)
          .Line(),
      "");
  EXPECT_EQ(s.preset, "improved");
  EXPECT_EQ(s.seed, 4u);
  EXPECT_EQ(s.steps, 30);
  EXPECT_EQ(s.params.Get(IvyParam::kT1), 0.3);
  EXPECT_EQ(s.params.Get(IvyParam::kMaxBend), 60.0);
  IvyState before = s;
  EXPECT_EQ(ApplyIvyStateJson(R"({"steps":-1})", &s).Line(),
            "steps: -1 is out of range; must be a whole number in [0, 10000]");
  EXPECT_EQ(ApplyIvyStateJson(R"({"t1":"nan"})", &s).field(), "t1");
  EXPECT_EQ(ApplyIvyStateJson("[1]", &s).field(), "params");
  // Issue 34: a key repeated after a nested object was accepted (the last value used).
  EXPECT_EQ(ApplyIvyStateJson(R"({"seed":1,"params":{"t1":0.3},"seed":2})", &s).Line(),
            "seed: given twice in one object");
  EXPECT_EQ(s.params, before.params);
  EXPECT_EQ(s.steps, 30);
}

TEST(IvyState, HashRoundTripsWithAndWithoutPrefix) {
  IvyState s;
  ASSERT_TRUE(SetIvyPreset("improved", &s).ok());
  ASSERT_TRUE(SetIvySeed(9, &s).ok());
  ASSERT_TRUE(s.params.Set(IvyParam::kT2, 0.7).ok());
  for (std::string prefix : {"", "ivy."}) {
    const std::string hash = EncodeIvyHash(s, prefix);
    IvyState back;
    std::vector<std::string> notices;
    ApplyIvyHash(hash, prefix, &back, &notices);
    EXPECT_TRUE(notices.empty()) << notices[0];
    EXPECT_EQ(back.preset, "improved");
    EXPECT_EQ(back.seed, 9u);
    EXPECT_EQ(back.params, s.params);
  }
  EXPECT_EQ(EncodeIvyHash(s, "ivy."), "ivy.preset=improved&ivy.seed=9&ivy.steps=50&ivy.t2=0.7");
}

TEST(IvyState, HostileHashValuesGiveNotices) {
  IvyState s;
  std::vector<std::string> notices;
  ApplyIvyHash("#preset=nope&steps=-4&t1=abc&zzz=1&gamma=2", "", &s, &notices);
  ASSERT_EQ(notices.size(), 5u);
  EXPECT_EQ(notices[0],
            "preset: 'nope' is unknown; must be one of paper, literal, improved, metric, artist");
  EXPECT_NE(notices[1].find("steps"), std::string::npos);
  EXPECT_EQ(s.steps, 50);
  // On a composed page the tree's keys are not the ivy's business.
  notices.clear();
  ApplyIvyHash("#gamma=2&ivy.t1=0.1", "ivy.", &s, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(s.params.Get(IvyParam::kT1), 0.1);
}

// IvyStateJson (the page's decoded state) is what ApplyIvyStateJson reads back, field for field.
TEST(IvyState, StateJsonRoundTrips) {
  IvyState state;
  ASSERT_TRUE(SetIvyPreset("metric", &state).ok());
  ASSERT_TRUE(SetIvySeed(7, &state).ok());
  ASSERT_TRUE(SetIvySteps(120, &state).ok());
  ASSERT_TRUE(SetIvyScene("tree", &state).ok());
  ASSERT_TRUE(SetIvyTree("maple", &state).ok());
  ASSERT_TRUE(SetIvyTreeYears(9, &state).ok());
  ASSERT_TRUE(SetIvySeedPoints("0.1,0.2,0.3;-1,2,3.5", &state).ok());
  ASSERT_TRUE(state.params.SetFromAssignment("t1=0.15").ok());
  const std::string json = IvyStateJson(state);
  EXPECT_EQ(
      json.rfind(R"({"preset":"metric","seed":7,"steps":120,"scene":"tree","seed_points":)", 0), 0u)
      << json;
  IvyState back;
  ASSERT_TRUE(ApplyIvyStateJson(json, &back).ok()) << json;
  EXPECT_EQ(EncodeIvyHash(back), EncodeIvyHash(state));
  EXPECT_EQ(back.seed_points, state.seed_points);
  EXPECT_EQ(IvyStateJson(back), json);
}

}  // namespace
}  // namespace niwa::ivy
