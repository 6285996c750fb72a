// Tests of 'niwa tree sway': --stats JSON, --csv and --svg files, one-line errors with exit code 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"
#include "support/expect_error.h"
#include "support/files.h"

namespace niwa {
namespace {



TEST(SwayCli, StatsHasTheCounts) {
  CliResult r = RunNiwa({"tree", "sway", "--preset", "sakura-thesis", "--years", "5", "--wind", "10",
                      "--gust", "0.2:1", "--duration", "2", "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"node_points", "moving", "followers", "fixed", "internodes",
                          "ns_per_internode", "max_tip_displacement", "steps", "jittering_tips"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["node_points"].get<int>(),
            j["moving"].get<int>() + j["followers"].get<int>() + j["fixed"].get<int>());
  EXPECT_EQ(j["steps"].get<int>(), 60);
  EXPECT_GT(j["max_tip_displacement"].get<double>(), 0.0);
  EXPECT_TRUE(j["finite"].get<bool>());
  EXPECT_EQ(j["jittering_tips"].get<int>(), 0);  // over the gust's last 2 s (here 0.2-1 s)
}

TEST(SwayCli, WritesCsvAndSvg) {
  std::string csv = ::testing::TempDir() + "niwa_sway_test.csv";
  std::string svg = ::testing::TempDir() + "niwa_sway_test.svg";
  CliResult r = RunNiwa({"tree", "sway", "--preset", "binary", "--years", "6", "--duration", "1",
                      "--dt", "0.05", "--tips", "2", "--csv", csv, "--svg", svg});
  ASSERT_EQ(r.code, 0) << r.err;
  std::string text = testing::Slurp(csv);
  EXPECT_EQ(text.rfind("time,node,x,y,z\n", 0), 0u);
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n';
  EXPECT_EQ(lines, 1u + 2u * 21u);  // header + 2 tips × (t = 0 and 20 steps)
  std::string plot = testing::Slurp(svg);
  EXPECT_NE(plot.find("<svg"), std::string::npos);
  EXPECT_NE(plot.find("<polyline"), std::string::npos);
  std::remove(csv.c_str());
  std::remove(svg.c_str());
}

TEST(SwayCli, BadInputIsOneLine) {
  ExpectOneLineError(RunNiwa({"tree", "sway", "--wind", "200"}),
                     "--wind: 200 is out of range; must be a number in [0, 100]");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--gust", "5:2"}), "--gust:");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--gust", "soon"}), "must be ON_S:OFF_S");
  // Sway rows of the one parameter table, through --set and its old alias --set-sway.
  ExpectOneLineError(RunNiwa({"tree", "sway", "--set", "K_rev=2"}),
                     "--set: K_rev: 2 is out of range; must be a number in [0, 1]");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--set", "wind_variation=-0.5"}),
                     "--set: wind_variation: -0.5 is out of range; must be a number in [0, 1]");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--set-sway", "K_rev=2"}),
                     "--set-sway: K_rev: 2 is out of range; must be a number in [0, 1]");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--set", "nope=1"}), "unknown parameter 'nope'");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--set", "gust_on=8"}),
                     "--set: gust_off: 6 must be greater than gust_on (8)");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--dt", "1"}), "--dt: 1 is out of range");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--csv", "out.txt"}), "must end in .csv");
  ExpectOneLineError(RunNiwa({"tree", "sway", "--tips", "0"}), "--tips");
}

TEST(SwayCli, SetReachesTheSwayAndWindRows) {
  auto stats = [](std::vector<std::string> extra) {
    std::vector<std::string> args = {"tree", "sway",       "--preset", "binary", "--years",
                                     "6",    "--duration", "2",        "--stats"};
    args.insert(args.end(), extra.begin(), extra.end());
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out.empty() ? "{}" : r.out);
  };
  nlohmann::json base = stats({});
  nlohmann::json flag = stats({"--wind", "12"});
  nlohmann::json set = stats({"--set", "wind_speed=12"});
  nlohmann::json alias = stats({"--set-sway", "wind_speed=12"});
  nlohmann::json url = stats({"--url", "preset=binary&years=6&wind_speed=12"});
  EXPECT_EQ(set["wind"].get<double>(), 12.0);
  EXPECT_EQ(set["max_tip_displacement"], flag["max_tip_displacement"]);
  EXPECT_EQ(alias["max_tip_displacement"], flag["max_tip_displacement"]);
  EXPECT_EQ(url["max_tip_displacement"], flag["max_tip_displacement"]);
  EXPECT_NE(set["max_tip_displacement"], base["max_tip_displacement"]);
  // A model row too: stiffer twigs move less.
  nlohmann::json stiff = stats({"--set", "K_dir_tip=150000"});
  EXPECT_LT(stiff["max_tip_displacement"].get<double>(),
            base["max_tip_displacement"].get<double>());
  // The flag wins over --set.
  nlohmann::json both = stats({"--set", "wind_speed=3", "--wind", "12"});
  EXPECT_EQ(both["max_tip_displacement"], flag["max_tip_displacement"]);
}

TEST(SwayCli, ParamsListsTheSwayAndWindGroups) {
  CliResult r = RunNiwa({"params", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json table = nlohmann::json::parse(r.out);
  int sway = 0, wind = 0;
  for (const auto& row : table) {
    sway += row["group"] == "sway";
    wind += row["group"] == "wind";
  }
  EXPECT_EQ(sway, 13);
  EXPECT_EQ(wind, 9);
  CliResult text = RunNiwa({"params"});
  for (const char* key : {"K_wind", "K_dir_trunk", "wood_density", "sway_alpha", "wind_speed",
                          "gust_front_speed", "wind_variation", "duration"}) {
    EXPECT_NE(text.out.find(std::string("\n") + key + "\t"), std::string::npos) << key;
  }
}

TEST(SwayCli, HelpListsTheOptions) {
  CliResult r = RunNiwa({"tree", "sway", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* option : {"--wind", "--wind-dir", "--gust", "--dt", "--duration", "--set-sway",
                             "--csv", "--svg", "--stats", "--preset"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
}

}  // namespace
}  // namespace niwa
