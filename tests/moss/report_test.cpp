// The moss reports (core/moss/moss_report): the soil cell's terms in the spec's order with the
// balance closed, and the fitness of each species asked for, as the CLI prints them.
#include "moss/moss_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "moss/fitness.h"
#include "moss/moss_params.h"

namespace niwa::moss {
namespace {

TEST(MossReport, SoilTermsInTheSpecsOrderWithTheBalanceClosed) {
  MossState state;
  ASSERT_TRUE(SetMossPreset("nomura2010", &state).ok());
  SoilCell cell;
  cell.law = GeologyLawOf(state.params, Geology::kHumus);
  cell.theta = 0.2;
  cell.S = 25;
  const nlohmann::ordered_json j = SoilReport(state, Geology::kHumus, cell);
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  const std::vector<std::string> want = {
      "preset", "geology", "delta_form", "longwave", "T", "rh", "U", "S", "m_over_M", "V_sky",
      "theta_SAT", "A", "C", "sigma_T4", "L", "R", "C_H", "theta", "F", "beta", "e_SAT", "q_SAT",
      "Delta", "dT", "T_s", "H", "iota_E", "E", "E_mm_day", "rh_s", "latent_share",
      "residual_linear", "residual_nonlinear"};
  EXPECT_EQ(keys, want);
  EXPECT_EQ(j["geology"], "humus");
  EXPECT_EQ(j["delta_form"], "corrected");
  EXPECT_LT(std::fabs(j["residual_linear"].get<double>()), 1e-9);  // the linearised balance holds
  const double share = j["latent_share"].get<double>();
  EXPECT_NEAR(share, j["iota_E"].get<double>() / (j["iota_E"].get<double>() + j["H"].get<double>()),
              1e-15);
}

TEST(MossReport, FitnessOfEachSpeciesAskedFor) {
  MossState state;
  ASSERT_TRUE(SetMossPreset("nomura2010", &state).ok());
  const nlohmann::ordered_json all =
      FitnessReport(state, {Species::kGingoke, Species::kHaigoke, Species::kSugigoke}, 286, 1, 20);
  ASSERT_EQ(all["species"].size(), 3u);
  EXPECT_EQ(all["species"][1]["species"], "haigoke");
  const nlohmann::ordered_json one = FitnessReport(state, {Species::kHaigoke}, 286, 1, 20);
  ASSERT_EQ(one["species"].size(), 1u);
  EXPECT_EQ(one["species"][0], all["species"][1]);  // the same numbers alone or among the three
  const SpeciesRanges r = SpeciesOf(state.params, Species::kHaigoke);
  const Fitness f = FitnessOf(r, 286, 1, 20, GForm::kClamped);
  EXPECT_EQ(one["species"][0]["G"].get<double>(), f.G);
  EXPECT_EQ(one["species"][0]["growing"].get<bool>(), DailyGrowth(r, f.G) > 0);
}

}  // namespace
}  // namespace niwa::moss
