// The moss table: the thesis's tables 3.4-3.6, 4.2 and 4.3 as rows, the two presets through the
// one embed step, the typed views and the cross-row checks.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "moss/moss_params.h"
#include "params/param_json.h"

namespace niwa::moss {
namespace {

using P = MossParam;

double Row(const char* key) { return MossTable().row(*MossTable().Find(key)).default_value; }

TEST(MossParams, EveryEnumValueIsItsRow) {
  EXPECT_EQ(MossTable().name(), "moss");
  EXPECT_EQ(MossTable().size(), static_cast<std::size_t>(P::kCount));
  EXPECT_STREQ(MossTable().row(static_cast<std::size_t>(P::kT)).key, "T");
  EXPECT_STREQ(MossTable().row(static_cast<std::size_t>(P::kCpRho)).key, "cp_rho");
  EXPECT_STREQ(MossTable().row(static_cast<std::size_t>(P::kSSky)).key, "S_sky");
  EXPECT_STREQ(MossTable().row(static_cast<std::size_t>(P::kSoilEdge)).key, "soil_edge");
  EXPECT_STREQ(MossTable().row(static_cast<std::size_t>(SpeciesRow(Species::kGingoke, 0))).key,
               "gingoke_T0");
  EXPECT_STREQ(MossTable().row(static_cast<std::size_t>(SpeciesRow(Species::kSugigoke, 12))).key,
               "sugigoke_tau_d");
  EXPECT_EQ(static_cast<int>(SpeciesRow(Species::kSugigoke, 12)) + 1, static_cast<int>(P::kCount));
  std::set<std::string> groups;
  for (const ParamSpec& s : MossTable()) {
    groups.insert(s.group);
    EXPECT_EQ(s.stage, Stage::kGrow) << s.key;  // nothing is drawn from the table yet
    EXPECT_GT(std::string(s.help).size(), 10u) << s.key;
  }
  EXPECT_EQ(groups.size(), MossTable().groups().size());
}

TEST(MossParams, TheThesisTablesAreTheDefaults) {
  // Table 4.3 (climate).
  EXPECT_EQ(Row("T"), 288.15);
  EXPECT_EQ(Row("rh"), 0.73);
  EXPECT_EQ(Row("P_year"), 1861.2);
  EXPECT_EQ(Row("P_days"), 180);
  EXPECT_EQ(Row("U"), 0.2);
  EXPECT_EQ(Row("N0"), 8.0);
  EXPECT_EQ(Row("N"), 6.0);
  EXPECT_EQ(Row("sun_altitude"), 90.0);
  // Tables 3.5 and 3.6 (constants), §3.5.2 (C_H).
  EXPECT_EQ(Row("sigma"), 5.67e-8);
  EXPECT_EQ(Row("p"), 1013);
  EXPECT_EQ(Row("ref"), 0.2);
  EXPECT_EQ(Row("D_ATM"), 2.54e-5);
  EXPECT_EQ(Row("iota"), 2.543e6);
  EXPECT_EQ(Row("rho"), 1.19);
  EXPECT_EQ(Row("cp_rho"), 1.21e3);
  EXPECT_EQ(Row("CH_min"), 0.0015);
  EXPECT_EQ(Row("CH_max"), 0.0030);
  // Table 3.4 (soil) through the typed view.
  const MossParams p;
  const GeologyLaw humus = GeologyLawOf(p, Geology::kHumus);
  const GeologyLaw sandy = GeologyLawOf(p, Geology::kSandy);
  const GeologyLaw asphalt = GeologyLawOf(p, Geology::kAsphalt);
  EXPECT_EQ(humus.F_1, 2.16e2);
  EXPECT_EQ(humus.F_2, 10.0);
  EXPECT_EQ(humus.theta_SAT, 0.490);
  EXPECT_EQ(sandy.F_1, 8.32e5);
  EXPECT_EQ(sandy.F_2, 16.6);
  EXPECT_EQ(sandy.theta_SAT, 0.392);
  EXPECT_EQ(asphalt.F_1, 7.25e7);
  EXPECT_EQ(asphalt.F_2, 19.4);
  EXPECT_EQ(asphalt.theta_SAT, 0.012);
  EXPECT_EQ(Row("h_max"), 1000);
  EXPECT_EQ(Row("h_wall"), 1);
  // §3.8 and §4.1.
  EXPECT_EQ(Row("photons"), 8192);
  EXPECT_EQ(Row("max_mosses"), 16384);
  EXPECT_EQ(Row("moss_size"), 0.01);
  EXPECT_EQ(Row("gemma_step"), 0.5);
  EXPECT_EQ(Row("spore_G"), 2.0);
  EXPECT_EQ(Row("L_spore_0"), 60);
  EXPECT_EQ(Row("L_spore_1"), 365);
  EXPECT_EQ(Row("L_gemma_0"), -60);
  EXPECT_EQ(Row("L_gemma_1"), 60);
}

TEST(MossParams, TheThreeSpeciesOfTable42) {
  const MossParams p;
  const SpeciesRanges g = SpeciesOf(p, Species::kGingoke);
  const SpeciesRanges h = SpeciesOf(p, Species::kHaigoke);
  const SpeciesRanges s = SpeciesOf(p, Species::kSugigoke);
  const double want[3][13] = {
      {274.15, 299.15, 1, 0.8, 1.2, 0.5, 0.0, 60.0, 1, 0.3, 0.1, 0.4, 0.1},
      {276.15, 295.15, 1, 0.9, 1.1, 0.5, 0.0, 40.0, 1, 0.25, 0.1, 0.35, 0.15},
      {278.15, 297.15, 1, 0.85, 1.15, 1, 0.0, 50.0, 1, 0.3, 0.075, 0.37, 0.12}};
  int k = 0;
  for (const SpeciesRanges& r : {g, h, s}) {
    const double got[13] = {r.T_0, r.T_1, r.n_T,     r.rh_0,  r.rh_1,  r.n_rh, r.S_0,
                            r.S_1, r.n_S, r.alpha_g, r.tau_g, r.tau_b, r.tau_d};
    for (int c = 0; c < 13; ++c) EXPECT_EQ(got[c], want[k][c]) << k << " column " << c;
    ++k;
  }
  Species sp;
  EXPECT_TRUE(SpeciesFromName("haigoke", &sp));
  EXPECT_EQ(sp, Species::kHaigoke);
  EXPECT_FALSE(SpeciesFromName("zenigoke", &sp));
  Geology geo;
  EXPECT_TRUE(GeologyFromName("asphalt", &geo));
  EXPECT_EQ(geo, Geology::kAsphalt);
  EXPECT_FALSE(GeologyFromName("clay", &geo));
}

TEST(MossParams, PresetsComeFromTheEmbeddedJson) {
  ASSERT_EQ(MossPresetNames(), (std::vector<std::string>{"nomura2010", "nomura2010-sky"}));
  Result<MossParams> literal = MossPreset("nomura2010");
  ASSERT_TRUE(literal.ok());
  EXPECT_EQ(static_cast<const ParamSet&>(*literal), static_cast<const ParamSet&>(MossParams()));
  Result<MossParams> sky = MossPreset("nomura2010-sky");
  ASSERT_TRUE(sky.ok());
  EXPECT_EQ(sky->GetInt(P::kLongwave), static_cast<int>(Longwave::kSkyView));
  EXPECT_EQ(sky->Get(P::kSSky), 68.0);
  EXPECT_EQ(sky->Get(P::kT), 288.15);
  EXPECT_NE(MossPresetSource("nomura2010-sky").find("sky"), std::string::npos);
  EXPECT_EQ(MossPreset("nomura").status().Line(),
            "preset: 'nomura' is unknown; must be nomura2010 or nomura2010-sky");
}

TEST(MossParams, CrossRowChecksNameTheRow) {
  MossParams p;
  EXPECT_TRUE(CheckMossParams(p).ok());
  ASSERT_TRUE(p.Set(P::kN, 9).ok());
  EXPECT_EQ(CheckMossParams(p).field(), "N");
  p = MossParams();
  ASSERT_TRUE(p.Set(P::kCHMin, 0.004).ok());
  EXPECT_EQ(CheckMossParams(p).field(), "CH_min");
  p = MossParams();
  ASSERT_TRUE(p.Set(SpeciesRow(Species::kHaigoke, 0), 296).ok());  // T_0 over T_1 = 295.15
  EXPECT_EQ(CheckMossParams(p).Line(),
            "haigoke_T0: 296 is not below haigoke_T1 = 295.15; must be less than haigoke_T1");
  p = MossParams();
  ASSERT_TRUE(p.Set(SpeciesRow(Species::kSugigoke, 7), 0).ok());  // S_1 = S_0 = 0
  EXPECT_EQ(CheckMossParams(p).field(), "sugigoke_S0");
  p = MossParams();
  ASSERT_TRUE(p.Set(P::kLGemma0, 60).ok());
  EXPECT_EQ(CheckMossParams(p).field(), "L_gemma_0");
  // Ranges of single rows are the table's.
  EXPECT_EQ(p.SetFromText("rh", "1.5").Line(),
            "rh: 1.5 is out of range; must be a number in [0, 1]");
}

TEST(MossParams, TheTableAsJsonHasEveryRowWithItsStage) {
  nlohmann::json table = nlohmann::json::parse(ParamTableJson(MossTable()));
  ASSERT_EQ(table.size(), MossTable().size());
  EXPECT_EQ(table[0]["key"], "T");
  EXPECT_EQ(table[0]["stage"], "grow");
  EXPECT_EQ(table[0]["group_title"], "Climate (table 4.3)");
}

}  // namespace
}  // namespace niwa::moss
