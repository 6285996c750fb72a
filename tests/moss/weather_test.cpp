// Weather files (core/moss/weather.h) and the run's use of them: JSON and CSV rows parsed with the
// table's ranges, a left-out field taken from the table, hostile rows refused naming the day and
// field with its range; a run whose file repeats the table's climate grows the same bytes as
// without it, a warmer file changes the soil, and the rows cycle past the file's last day.
#include "moss/weather.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "moss/moss_run.h"

namespace niwa::moss {
namespace {

TEST(MossWeather, CsvAndJsonGiveTheSameDays) {
  const MossParams params;
  Result<std::vector<WeatherDay>> csv =
      ParseWeather("T,rh,P\r\n293.15,0.8,5\r\n283.15,0.6,0\r\n\r\n", true, params);
  Result<std::vector<WeatherDay>> json = ParseWeather(
      R"({"days": [{"T": 293.15, "rh": 0.8, "P": 5}, {"P": 0, "rh": 0.6, "T": 283.15}]})", false,
      params);
  ASSERT_TRUE(csv.ok()) << csv.status().Line();
  ASSERT_TRUE(json.ok()) << json.status().Line();
  ASSERT_EQ(csv->size(), 2u);
  ASSERT_EQ(json->size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ((*csv)[i].T, (*json)[i].T);
    EXPECT_EQ((*csv)[i].rh, (*json)[i].rh);
    EXPECT_EQ((*csv)[i].P, (*json)[i].P);
    EXPECT_TRUE(std::isnan((*csv)[i].U));
    EXPECT_TRUE(std::isnan((*json)[i].N0));
  }
  // A left-out field keeps the climate's value; a given one replaces it.
  const Weather climate = ClimateOf(params);
  const Weather day =
      WeatherOfDay({climate.T, climate.rh, climate.U, climate.N, climate.N_0, 7.0}, (*csv)[1]);
  EXPECT_EQ(day.T, 283.15);
  EXPECT_EQ(day.rh, 0.6);
  EXPECT_EQ(day.U, climate.U);
  EXPECT_EQ(day.N, climate.N);
  EXPECT_EQ(day.P, 0.0);
}

TEST(MossWeather, HostileRowsNameTheDayAndFieldWithItsRange) {
  const MossParams params;
  const std::pair<const char*, const char*> csv_cases[] = {
      {"", "is empty"},
      {"T\n", "has 0 days"},
      {"T,Tmax\n1,2\n", "column 'Tmax' is unknown; must be T, rh, U, N, N0 or P"},
      {"T,T\n290,290\n", "column 'T' is given twice"},
      {"T\n400\n", "day 1: T: 400 is out of range; must be a number in [233.15, 323.15]"},
      {"T,rh\n290,0.5\n290\n", "day 2: has 1 fields; must have 2"},
      {"rh\nnan\n", "day 1: rh: 'nan' is not a decimal number"},
      {"P\n0x10\n", "day 1: P: '0x10'"},
      {"P\n2001\n", "day 1: P: 2001 is out of range; must be a number in [0, 2000]"},
      {"U\n\n5\n", "day 1: U: empty"},
      {"N,N0\n9,8\n", "day 1: N: 9 is above N0 8"},
      {"N0\n5\n", "day 1: N: 6 is above N0 5"},  // the table's N against the file's N0
  };
  for (const auto& [text, want] : csv_cases) {
    Result<std::vector<WeatherDay>> r = ParseWeather(text, true, params);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.status().field(), "weather") << text;
    EXPECT_NE(r.status().message().find(want), std::string::npos)
        << text << " -> " << r.status().message();
  }
  const std::pair<const char*, const char*> json_cases[] = {
      {"[1]", "is not a JSON object"},
      {"{\"days\": []}", "has 0 days"},
      {"{\"days\": [{}], \"year\": 1}", "key 'year' is unknown"},
      {"{\"days\": [{\"T\": \"hot\"}]}", "day 1: T: must be a number in [233.15, 323.15]"},
      {"{\"days\": [{\"T\": 290}, {\"T\": 290, \"T\": 291}]}", "T: given twice"},
      {"{\"days\": [{\"T\": 290}, 3]}", "day 2: is not an object"},
      {"{\"days\": [{\"wind\": 3}]}", "day 1: 'wind' is unknown"},
      {"{\"days\": [{\"rh\": 1.5}]}", "day 1: rh: 1.5 is out of range; must be a number in [0, 1]"},
      {"{\"days\": [{\"U\": -1}]}", "day 1: U: -1 is out of range"},
      {"{\"days\": [{\"T\": 1e999}]}", "is not a JSON object"},
  };
  for (const auto& [text, want] : json_cases) {
    Result<std::vector<WeatherDay>> r = ParseWeather(text, false, params);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.status().field(), "weather") << text;
    EXPECT_NE(r.status().message().find(want), std::string::npos)
        << text << " -> " << r.status().message();
  }
  std::string many = "T\n";
  for (int i = 0; i < kMaxWeatherDays + 1; ++i) many += "290\n";
  EXPECT_NE(ParseWeather(many, true, params).status().message().find("has 3651 days"),
            std::string::npos);
}

std::string StatsWithoutMsOrWeather(const MossRun& run) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(run.StatsJson());
  for (auto it = j.begin(); it != j.end();)
    it = (it.key().rfind("ms", 0) == 0 || it.key() == "weather") ? j.erase(it) : std::next(it);
  return j.dump();
}

MossRun PlaneRun(int days) {
  MossState state;
  EXPECT_TRUE(SetMossScene("thesis", &state).ok());
  state.days = days;
  EXPECT_TRUE(state.params.Set(MossParam::kPhotons, 1024).ok());
  return *MossRun::Start(state, Budget{});
}

TEST(MossWeather, ATableClimateFileGrowsTheSameBytesAndAWarmOneDoesNot) {
  MossRun plain = PlaneRun(6);
  ASSERT_TRUE(plain.Advance(nullptr).ok());
  // The table's climate written out, rain included (180 even rain days a year: days 3 and 5).
  const MossParams params;
  std::string csv = "T,rh,U,N,N0,P\n";
  for (int d = 1; d <= 6; ++d)
    csv += "288.15,0.73,0.2,6,8," + std::string(EvenRainOfDay(d, 1861.2, 180) > 0 ? "10.34" : "0") +
           "\n";
  // 1861.2 / 180 is 10.34 exactly in decimal but not in binary: give the quotient's own text.
  const double P_i = 1861.2 / 180;
  char rain[64];
  std::snprintf(rain, sizeof rain, "%.17g", P_i);
  std::string exact;
  for (std::size_t at = 0; at < csv.size();) {
    const std::size_t found = csv.find("10.34", at);
    exact += csv.substr(at, found - at);
    if (found == std::string::npos) break;
    exact += rain;
    at = found + 5;
  }
  Result<std::vector<WeatherDay>> days = ParseWeather(exact, true, params);
  ASSERT_TRUE(days.ok()) << days.status().Line();
  MossRun same = PlaneRun(6);
  ASSERT_TRUE(same.UseWeather(*days, "table.csv").ok());
  ASSERT_TRUE(same.Advance(nullptr).ok());
  EXPECT_EQ(StatsWithoutMsOrWeather(same), StatsWithoutMsOrWeather(plain));
  EXPECT_EQ(same.MossesJson(), plain.MossesJson());
  EXPECT_EQ(nlohmann::json::parse(same.StatsJson())["weather"]["days"], 6);

  // One warm day, cycled over six: every day at 300 K, the soil warmer than the table's.
  MossRun warm = PlaneRun(6);
  ASSERT_TRUE(warm.UseWeather(*ParseWeather("T\n300\n", true, params), "warm.csv").ok());
  ASSERT_TRUE(warm.Advance(nullptr).ok());
  double plain_T = 0, warm_T = 0;
  for (std::size_t i = 0; i < plain.cells().size(); ++i)
    plain_T += plain.world().T_s[i], warm_T += warm.world().T_s[i];
  EXPECT_GT(warm_T, plain_T + 5.0 * static_cast<double>(plain.cells().size()));
  EXPECT_EQ(warm.world().days.size(), 6u);
  // Given after a day was grown: refused naming weather.
  EXPECT_EQ(warm.UseWeather(*days, "late.csv").field(), "weather");
}

// A row's N sets that day's sun: no sunshine, no sun photons' power.
TEST(MossWeather, ADayWithoutSunshineStoresNoSunPower) {
  MossRun dark = PlaneRun(1);
  ASSERT_TRUE(dark.UseWeather(*ParseWeather("N\n0\n", true, MossParams()), "dark.csv").ok());
  ASSERT_TRUE(dark.Advance(nullptr).ok());
  EXPECT_EQ(dark.photon_map().dPhi_sun, 0.0);
  MossRun lit = PlaneRun(1);
  ASSERT_TRUE(lit.Advance(nullptr).ok());
  EXPECT_GT(lit.photon_map().dPhi_sun, 0.0);
}

}  // namespace
}  // namespace niwa::moss
