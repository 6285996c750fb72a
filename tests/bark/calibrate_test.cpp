// The bark calibration (core/bark/calibrate.h): the --vary form and its refusals naming "vary", the
// grid's order and values, the scores recomputed from the measures (the crack spacing along scan
// lines, the numbers `niwa bark table3` prints) against Table 3, the best
// candidate the lowest score, the same bytes twice, the estimate refused before any run, and the
// 4-layer search's peel share (less peeling at a larger κ_h, spec §4.6).
#include "bark/calibrate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "bark/bark_run.h"

namespace niwa::bark {
namespace {

CalibrateRequest Small(const std::string& species, const std::string& model) {
  CalibrateRequest r;
  EXPECT_TRUE(SetBarkSpecies(species, &r.base).ok());
  EXPECT_TRUE(SetBarkModel(model, &r.base).ok());
  EXPECT_TRUE(SetBarkSize("16x16", &r.base).ok());
  r.first_seed = r.last_seed = 1;
  return r;
}

TEST(Calibrate, AnAxisIsKeyLoHiPoints) {
  Result<CalibrateAxis> a = ParseCalibrateAxis("dH=0.02:0.05:4", "2layer");
  ASSERT_TRUE(a.ok()) << a.status().Line();
  EXPECT_EQ(a->key, "dH");
  ASSERT_EQ(a->Values().size(), 4u);
  EXPECT_DOUBLE_EQ(a->Values()[0], 0.02);
  EXPECT_DOUBLE_EQ(a->Values()[1], 0.03);
  EXPECT_DOUBLE_EQ(a->Values()[3], 0.05);
  Result<CalibrateAxis> one = ParseCalibrateAxis("kappa_h=0.1", "4layer");
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(one->Values(), std::vector<double>{0.1});
}

TEST(Calibrate, ABadAxisNamesVary) {
  for (const auto& [text, model] : std::vector<std::pair<std::string, std::string>>{
           {"dH", "2layer"},               // no '='
           {"kappa1=1.03", "2layer"},      // Table 2 is the paper's
           {"kappa_h=0.1", "2layer"},      // a 4-layer row
           {"dH=0.02", "4layer"},          // a 2-layer row
           {"dH=0.9", "2layer"},           // out of the row's range
           {"dH=0.05:0.02:3", "2layer"},   // hi below lo
           {"dH=0.02:0.05:10", "2layer"},  // too many points
           {"dH=0.02:0.05", "2layer"},     // two parts
           {"dH=x", "2layer"}}) {
    Result<CalibrateAxis> a = ParseCalibrateAxis(text, model);
    ASSERT_FALSE(a.ok()) << text;
    EXPECT_EQ(a.status().field(), "vary") << text;
  }
}

TEST(Calibrate, TheDefaultAxesAreCalibratable) {
  for (const char* model : {"2layer", "4layer"}) {
    const std::vector<std::string>& keys = CalibratableKeys(model);
    for (const CalibrateAxis& a : DefaultCalibrateAxes(model)) {
      EXPECT_NE(std::find(keys.begin(), keys.end(), a.key), keys.end()) << a.key;
      std::string text = a.key + "=" + std::to_string(a.lo) + ":" + std::to_string(a.hi) + ":" +
                         std::to_string(a.points);
      EXPECT_TRUE(ParseCalibrateAxis(text, model).ok()) << text;
    }
  }
}

TEST(Calibrate, TwoLayerScoresAgainstTable3AndPicksTheLowest) {
  CalibrateRequest r = Small("tallow", "2layer");
  r.vary = {{"dH", 0.02, 0.05, 3}, {"dR", 0.021, 0.03, 2}};
  Result<std::string> text = CalibrateJson(r, Budget{});
  ASSERT_TRUE(text.ok()) << text.status().Line();
  const nlohmann::json j = nlohmann::json::parse(*text);
  ASSERT_EQ(j["candidates"].size(), 6u);
  EXPECT_EQ(j["runs"], 6);
  // The first axis slowest.
  EXPECT_DOUBLE_EQ(j["candidates"][1]["values"]["dH"].get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(j["candidates"][1]["values"]["dR"].get<double>(), 0.03);
  EXPECT_DOUBLE_EQ(j["candidates"][2]["values"]["dH"].get<double>(), 0.035);
  const PaperTable3Row* paper = PaperTable3("tallow");
  double lowest = 1e300;
  for (const auto& c : j["candidates"]) {
    const auto& m = c["measures"];
    const double d_mw = std::fabs(m["mean_w"].get<double>() / paper->mean_w - 1) / 0.25;
    const double d_mh = std::fabs(m["mean_h"].get<double>() / paper->mean_h - 1) / 0.25;
    const double d_xw = std::fabs(m["max_w"].get<double>() / paper->max_w - 1) / 0.4;
    const double d_xh = std::fabs(m["max_h"].get<double>() / paper->max_h - 1) / 0.4;
    EXPECT_NEAR(c["score"].get<double>(), std::max({d_mw, d_mh, d_xw, d_xh}), 1e-12);
    EXPECT_GT(m["mean_w"].get<double>(), 0);
    EXPECT_GT(m["plates"]["mean_w"].get<double>(), 0);  // printed beside, not scored
    lowest = std::min(lowest, c["score"].get<double>());
  }
  EXPECT_EQ(j["best"]["score"].get<double>(), lowest);
  EXPECT_EQ(j["meets"]["means"].get<bool>(), j["best"]["deviations"]["means"].get<double>() <= 1);
  EXPECT_LE(j["best_means"]["deviations"]["means"].get<double>(),
            j["best"]["deviations"]["means"].get<double>());
  // The same request, the same bytes.
  EXPECT_EQ(*CalibrateJson(r, Budget{}), *text);
}

// The score reads the measure Table 3 is printed with: the crack spacing along scan lines, the same
// numbers (the seeds' means) `niwa bark table3` gives for the same state and seeds, and camphor's
// "(>20)" met exactly when table3's level_b_spacing says so.
TEST(Calibrate, TwoLayerMeasuresAreTable3sSpacing) {
  for (const char* species : {"camphor", "pine"}) {
    CalibrateRequest r = Small(species, "2layer");
    ASSERT_TRUE(SetBarkSize("32x32", &r.base).ok());
    r.first_seed = 1;
    r.last_seed = 2;
    r.vary = {{"dH", 0.02, 0.02, 1}};
    Result<std::string> text = CalibrateJson(r, Budget{});
    ASSERT_TRUE(text.ok()) << text.status().Line();
    const nlohmann::json c = nlohmann::json::parse(*text)["candidates"][0];
    BarkState state = r.base;
    ASSERT_TRUE(state.params.Set(BarkParam::kDeltaH, 0.02).ok());
    ASSERT_TRUE(state.params.Set(BarkParam::kMapSize, 256).ok());
    Result<std::string> table = Table3Json({state}, 1, 2, Budget{});
    ASSERT_TRUE(table.ok()) << table.status().Line();
    const nlohmann::json row = nlohmann::json::parse(*table)["rows"][0];
    const auto& ours = row["ours"];
    const auto& m = c["measures"];
    EXPECT_NEAR(m["mean_w"].get<double>(), ours["spacing_mean_w"]["mean"].get<double>(), 1e-12);
    EXPECT_NEAR(m["mean_h"].get<double>(), ours["spacing_mean_h"]["mean"].get<double>(), 1e-12);
    EXPECT_NEAR(m["max_w"].get<double>(), ours["spacing_max_w"]["mean"].get<double>(), 1e-12);
    EXPECT_NEAR(m["max_h"].get<double>(), ours["spacing_max_h"]["mean"].get<double>(), 1e-12);
    EXPECT_EQ(m["open_lines_h"].get<int>(), ours["spacing_open_lines_h"].get<int>());
    const auto& b = row["level_b_spacing"];
    EXPECT_EQ(c["score"].get<double>() <= 1.0, b["met"].get<bool>()) << *text << *table;
    if (std::string(species) == "camphor") {
      EXPECT_EQ(c["deviations"]["max_h"].get<double>() == 0.0, b["max_h"]["met"].get<bool>());
    }
  }
}

TEST(Calibrate, TheEstimateIsRefusedBeforeAnyRun) {
  CalibrateRequest r = Small("pine", "2layer");
  r.vary = {{"dH", 0.02, 0.05, 9}, {"dR", 0.01, 0.05, 9}};
  Budget tight;
  tight.seconds = 0.5;
  const Estimate e = EstimateCalibrate(r);
  EXPECT_GT(e.seconds, tight.seconds);
  // 81 runs of one's estimate (no maps: map_size 256 counted).
  BarkState one = r.base;
  ASSERT_TRUE(one.params.Set(BarkParam::kMapSize, 256).ok());
  EXPECT_GT(e.seconds, 40 * EstimateBarkRun(one).seconds);
  Result<std::string> refused = CalibrateJson(r, tight);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().field(), "max_seconds");
}

TEST(Calibrate, ABadRequestNamesItsField) {
  CalibrateRequest r = Small("camphor", "2layer");
  EXPECT_EQ(CalibrateJson(r, Budget{}).status().field(), "vary");  // nothing to vary
  r.vary = {{"dH", 0.02, 0.03, 2}, {"dH", 0.02, 0.03, 2}};
  EXPECT_EQ(CalibrateJson(r, Budget{}).status().field(), "vary");  // twice
  r.vary = {{"kappa1", 1.01, 1.02, 2}};
  EXPECT_EQ(CalibrateJson(r, Budget{}).status().field(), "vary");  // not calibratable
  r.vary = {{"dH", 0.02, 0.03, 2}};
  r.base.species = "oak";
  EXPECT_EQ(CalibrateJson(r, Budget{}).status().field(), "species");
  CalibrateRequest f = Small("pine", "4layer");
  f.vary = {{"kappa_h", 0.03, 0.3, 2}};
  EXPECT_EQ(CalibrateJson(f, Budget{}).status().field(), "cycles");  // one cycle
  f.first_seed = 3;
  f.last_seed = 1;
  ASSERT_TRUE(f.base.params.Set(BarkParam::kCycles, 2).ok());
  EXPECT_EQ(CalibrateJson(f, Budget{}).status().field(), "seeds");
}

TEST(Calibrate, FourLayerPeelsLessAtALargerCriticalShearStrain) {
  CalibrateRequest r = Small("pine", "4layer");
  ASSERT_TRUE(SetBarkSize("32x16", &r.base).ok());
  ASSERT_TRUE(r.base.params.Set(BarkParam::kCycles, 2).ok());
  ASSERT_TRUE(r.base.params.Set(BarkParam::kT, 0.002).ok());
  ASSERT_TRUE(r.base.params.Set(BarkParam::kCork, 0.1).ok());
  r.vary = {{"kappa_h", 0.03, 0.6, 2}};
  Result<std::string> text = CalibrateJson(r, Budget{});
  ASSERT_TRUE(text.ok()) << text.status().Line();
  const nlohmann::json j = nlohmann::json::parse(*text);
  ASSERT_EQ(j["candidates"].size(), 2u);
  const auto& low = j["candidates"][0]["measures"];
  const auto& high = j["candidates"][1]["measures"];
  EXPECT_GT(low["peeled_share"].get<double>(), high["peeled_share"].get<double>()) << *text;
  for (const auto& c : j["candidates"]) {
    const double p = c["measures"]["peeled_share"].get<double>();
    const double least = c["measures"]["peeled_share_least"].get<double>();
    const double d_band = std::fabs(p - kPeelShareCentre) / kPeelShareHalfWidth;
    const double d_every =
        least >= kPeelShareLeast ? 0.0 : 1.0 + (kPeelShareLeast - least) / kPeelShareLeast;
    EXPECT_NEAR(c["score"].get<double>(), std::max(d_band, d_every), 1e-12);
  }
  EXPECT_EQ(j["meets"]["peel"].get<bool>(), j["best"]["score"].get<double>() <= 1);
}

}  // namespace
}  // namespace niwa::bark
