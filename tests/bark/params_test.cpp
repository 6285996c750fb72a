// The bark table and its species presets: Table 2's values exactly, the cross-row checks, the
// state's JSON and hash both ways.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bark/bark_params.h"
#include "bark/bark_state.h"

namespace niwa::bark {
namespace {

TEST(BarkParams, EveryRowHasAGroupAStageAndHelp) {
  const ParamTable& t = BarkTable();
  EXPECT_EQ(t.name(), "bark");
  EXPECT_EQ(t.size(), static_cast<std::size_t>(BarkParam::kCount));
  for (const ParamSpec& row : t) {
    EXPECT_NE(std::string(row.help), "") << row.key;
    EXPECT_NE(std::string(t.GroupTitle(row.group)), "") << row.key;
  }
  EXPECT_EQ(t.row(static_cast<std::size_t>(BarkParam::kMapSize)).stage, Stage::kMesh);
  EXPECT_EQ(t.row(static_cast<std::size_t>(BarkParam::kKappa1)).stage, Stage::kGrow);
}

TEST(BarkParams, ThePresetsAreTable2) {
  EXPECT_EQ(BarkPresetNames(), (std::vector<std::string>{"camphor", "tallow", "pine"}));
  struct Row {
    const char* name;
    double e1, e2, g, k1, k2, dh, dr, d;  // dR and D: Table 1's, tallow's calibrated (level B)
  };
  for (const Row& r : {Row{"camphor", 107.1e7, 117.3e7, 47.7e7, 1.040, 1.015, 0.028, 0.021, 1.0},
                       Row{"tallow", 117.3e7, 117.3e7, 53.3e7, 1.033, 1.015, 0.042, 0.009, 0.9},
                       Row{"pine", 117.3e7, 117.3e7, 53.3e7, 1.038, 1.023, 0.032, 0.021, 1.0}}) {
    Result<BarkParams> p = BarkPreset(r.name);
    ASSERT_TRUE(p.ok()) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kE1), r.e1) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kE2), r.e2) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kG), r.g) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kKappa1), r.k1) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kKappa2), r.k2) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kDeltaH), r.dh) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kDeltaR), r.dr) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kD), r.d) << r.name;
    EXPECT_DOUBLE_EQ(p->Get(BarkParam::kLo), 0.33) << r.name;  // Table 2: all three
    EXPECT_NE(BarkPresetSource(r.name).find("Table 2"), std::string::npos);
  }
  Result<BarkParams> bad = BarkPreset("oak");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().field(), "species");
  EXPECT_NE(bad.status().message().find("camphor, tallow or pine"), std::string::npos);
}

TEST(BarkParams, CrossRowChecksNameTheirRow) {
  BarkParams p = *BarkPreset("pine");
  EXPECT_TRUE(CheckBarkParams(p).ok());
  ASSERT_TRUE(p.Set(BarkParam::kNR, 63).ok());
  EXPECT_EQ(CheckBarkParams(p).field(), "N_R");
  ASSERT_TRUE(p.Set(BarkParam::kNR, 64).ok());
  ASSERT_TRUE(p.Set(BarkParam::kMapSize, 1000).ok());
  EXPECT_EQ(CheckBarkParams(p).field(), "map_size");
  ASSERT_TRUE(p.Set(BarkParam::kMapSize, 2048).ok());
  ASSERT_TRUE(p.Set(BarkParam::kNR, 2048).ok());
  ASSERT_TRUE(p.Set(BarkParam::kNH, 2048).ok());
  EXPECT_EQ(CheckBarkParams(p).field(), "N_H");  // 4 M nodes
}

TEST(BarkState, JsonRoundTripsAndRefusesBadFields) {
  BarkState s;
  ASSERT_TRUE(SetBarkSpecies("tallow", &s).ok());
  ASSERT_TRUE(SetBarkSeed(7, &s).ok());
  ASSERT_TRUE(SetBarkSize("64x32", &s).ok());
  ASSERT_TRUE(s.params.Set(BarkParam::kSigma, 0.2).ok());
  BarkState back;
  ASSERT_TRUE(ApplyBarkStateJson(BarkStateJson(s), &back).ok());
  EXPECT_EQ(back.species, "tallow");
  EXPECT_EQ(back.seed, 7u);
  EXPECT_TRUE(back.params == s.params);
  EXPECT_EQ(BarkStateJson(back), BarkStateJson(s));

  const BarkState before = back;
  EXPECT_EQ(ApplyBarkStateJson(R"({"seed": -5})", &back).field(), "seed");
  EXPECT_EQ(ApplyBarkStateJson(R"({"model": "3layer"})", &back).field(), "model");
  EXPECT_EQ(ApplyBarkStateJson(R"({"species": "oak"})", &back).field(), "species");
  EXPECT_EQ(ApplyBarkStateJson(R"({"params": {"N_R": 65}})", &back).field(), "N_R");
  EXPECT_EQ(ApplyBarkStateJson(R"({"params": {"kappa1": 3}})", &back).field(), "kappa1");
  EXPECT_EQ(BarkStateJson(back), BarkStateJson(before));  // unchanged on error
  EXPECT_EQ(SetBarkSize("64by32", &back).field(), "N_R");
  EXPECT_EQ(SetBarkSize("64x2", &back).field(), "N_H");
}

TEST(BarkState, HashRoundTripsUnderAPrefix) {
  BarkState s;
  ASSERT_TRUE(SetBarkSpecies("pine", &s).ok());
  ASSERT_TRUE(SetBarkSeed(3, &s).ok());
  ASSERT_TRUE(s.params.Set(BarkParam::kNR, 64).ok());
  const std::string hash = EncodeBarkHash(s, "bark.");
  EXPECT_EQ(hash, "bark.species=pine&bark.model=2layer&bark.seed=3&bark.N_R=64");
  BarkState back;
  std::vector<std::string> notices;
  ApplyBarkHash("tree.years=3&" + hash, "bark.", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(BarkStateJson(back), BarkStateJson(s));
}

TEST(BarkState, AHashIsForgivingWithANotice) {
  BarkState s;
  std::vector<std::string> notices;
  ApplyBarkHash("species=oak&N_R=65&map_size=1000&kappa2=9&seed=x&zz=1", "", &s, &notices);
  EXPECT_EQ(s.species, "camphor");
  EXPECT_EQ(s.params.GetInt(BarkParam::kNR), 64);
  EXPECT_EQ(s.params.GetInt(BarkParam::kMapSize), 512);
  EXPECT_DOUBLE_EQ(s.params.Get(BarkParam::kKappa2), 1.5);  // clamped
  EXPECT_EQ(notices.size(), 6u);
  EXPECT_TRUE(CheckBarkState(s).ok());
}

}  // namespace
}  // namespace niwa::bark
