// The moss run's per-day record and its CSV (MossRun::DaysCsv): one row a grown day whose
// population is the stats' population, whose births and deaths add up to the stats' totals, whose
// last row's soil means are the stats' soil_last_day, and whose photons are the day's map.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "moss/moss_run.h"

namespace niwa::moss {
namespace {

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

TEST(MossDaysCsv, OneRowADayAgreeingWithTheStats) {
  MossState state;
  ASSERT_TRUE(SetMossScene("thesis", &state).ok());
  state.days = 14;
  ASSERT_TRUE(state.params.Set(MossParam::kPhotons, 2048).ok());
  MossRun run = *MossRun::Start(state, Budget{});
  ASSERT_TRUE(run.Advance(nullptr).ok());
  const nlohmann::json stats = nlohmann::json::parse(run.StatsJson());
  std::stringstream in(run.DaysCsv());
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const std::vector<std::string> header = SplitCsv(line);
  ASSERT_EQ(header.size(), 20u);
  EXPECT_EQ(header[0], "day");
  EXPECT_EQ(header[19], "asphalt_theta");
  int rows = 0;
  int64_t births = 0, deaths = 0;
  std::vector<std::string> last;
  while (std::getline(in, line)) {
    const std::vector<std::string> row = SplitCsv(line);
    ASSERT_EQ(row.size(), header.size()) << line;
    ++rows;
    EXPECT_EQ(std::stoi(row[0]), rows);
    for (int s = 0; s < 3; ++s)
      EXPECT_EQ(std::stoi(row[1 + s]), stats["population"]["by_day"][rows][s].get<int>());
    births += std::stoi(row[5]);
    deaths += std::stoi(row[6]);
    EXPECT_GT(std::stoll(row[7]), 0);
    last = row;
  }
  EXPECT_EQ(rows, 14);
  EXPECT_EQ(births, stats["births"].get<int64_t>());
  EXPECT_EQ(deaths, stats["deaths"]["declined"].get<int64_t>() +
                        stats["deaths"]["lost_contest"].get<int64_t>());
  EXPECT_EQ(std::stoi(last[4]), static_cast<int>(run.world().seeds.size()));
  int64_t stored = 0;
  for (int64_t n : run.world().stored_by_depth) stored += n;
  EXPECT_EQ(std::stoll(last[7]), stored);
  const char* geologies[3] = {"humus", "sandy", "asphalt"};
  const char* fields[4] = {"S", "T_s", "rh_s", "theta"};
  for (int g = 0; g < 3; ++g)
    for (int f = 0; f < 4; ++f)
      EXPECT_NEAR(
          std::stod(last[8 + 4 * g + f]),
          stats["soil_last_day"][geologies[g]][fields[f]].get<double>(),
          1e-9 * std::abs(stats["soil_last_day"][geologies[g]][fields[f]].get<double>()) + 1e-12);
}

// A geology without cells (the plane is humus alone) leaves its fields empty.
TEST(MossDaysCsv, AGeologyWithoutCellsIsEmpty) {
  MossState state;
  ASSERT_TRUE(SetMossScene("plane", &state).ok());
  state.days = 2;
  ASSERT_TRUE(state.params.Set(MossParam::kPhotons, 256).ok());
  MossRun run = *MossRun::Start(state, Budget{});
  ASSERT_TRUE(run.Advance(nullptr).ok());
  std::stringstream in(run.DaysCsv());
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  const std::vector<std::string> row = SplitCsv(line);
  ASSERT_EQ(row.size(), 20u);
  EXPECT_FALSE(row[8].empty());
  for (int k = 12; k < 20; ++k) EXPECT_TRUE(row[k].empty()) << k;
  EXPECT_EQ(run.world().days.size(), 2u);
}

}  // namespace
}  // namespace niwa::moss
