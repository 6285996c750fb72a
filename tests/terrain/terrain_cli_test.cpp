// 'niwa terrain grow|shrink|seeds' and 'niwa params terrain' in-process: stats of every method, bad
// input as one line with exit code 2 and no file left.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/files.h"

namespace niwa {
namespace {

TEST(TerrainCli, GrowPrintsStatsForEveryMethod) {
  for (const char* method : {"simple", "midpoint", "fourier", "improved"}) {
    CliResult r = RunNiwa({"terrain", "grow", "--builtin", "lobes7", "--method", method, "--seed",
                           "3", "--stats", "--set", "res=64"});
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], method);
    EXPECT_GE(j["levels"].get<int>(), 8) << method;  // lobes7 at d = 20 m: about 12 levels
    EXPECT_EQ(j["self_intersections"], 0);
    EXPECT_EQ(j["nesting_violations"], 0);
    EXPECT_EQ(j["pits"], 0);
  }
}

TEST(TerrainCli, ContoursFileAndSeedsList) {
  const std::string path = ::testing::TempDir() + "terrain_contours.json";
  std::remove(path.c_str());
  CliResult r = RunNiwa(
      {"terrain", "grow", "--builtin", "dumbbell", "--method", "simple", "--contours", path});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(path);
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["contours"][0]["children"].size(), 2u);
  EXPECT_EQ(j["summits"].size(), 2u);
  CliResult seeds = RunNiwa({"terrain", "seeds"});
  ASSERT_EQ(seeds.code, 0);
  EXPECT_EQ(nlohmann::json::parse(seeds.out).size(),
            5u);  // disk, dumbbell, lobes7, jacksboro, valleys
  CliResult params = RunNiwa({"params", "terrain"});
  ASSERT_EQ(params.code, 0);
  EXPECT_NE(params.out.find("f0"), std::string::npos);
}

TEST(TerrainCli, ShrinkTracesTheFigureAndRefusesBadSteps) {
  const std::string svg = ::testing::TempDir() + "terrain_shrink.svg";
  std::remove(svg.c_str());
  CliResult r = RunNiwa({"terrain", "shrink", "--builtin", "dumbbell", "--steps", "4", "--join",
                         "round", "--svg", svg});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["join"], "round");
  EXPECT_EQ(j["d"], 20);  // the built-in's d
  ASSERT_EQ(j["steps"].size(), 4u);
  EXPECT_EQ(j["steps"][0]["rings"], 2);  // the neck is narrower than 2d: two islands at once
  EXPECT_GT(j["steps"][0]["raw_self_intersections"].get<int>(), 0);
  const std::string text = testing::Slurp(svg);
  EXPECT_NE(text.find("class=\"ring\""), std::string::npos);
  const std::string never = ::testing::TempDir() + "terrain_shrink_never.svg";
  std::remove(never.c_str());
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--steps", "65"},
        {"--d", "-1"},
        {"--join", "sharp"},
        {"--displace", "1,2,3"},
        {"--displace", "10,5,30,10"}}) {  // θ min > max: the core's check
    std::vector<std::string> args = {"terrain", "shrink", "--builtin", "disk", "--svg", never};
    args.insert(args.end(), bad.begin(), bad.end());
    CliResult b = RunNiwa(args);
    EXPECT_EQ(b.code, 2) << bad[0];
    EXPECT_NE(b.err.find("niwa: error: " + bad[0] + ": "), std::string::npos) << b.err;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
    EXPECT_FALSE(std::ifstream(never).good()) << bad[0];
  }
}

TEST(TerrainCli, BadInputIsOneLineExitTwoAndNoFile) {
  const std::string out = ::testing::TempDir() + "terrain_never.json";
  const std::string bowtie = ::testing::TempDir() + "terrain_bowtie.json";
  std::ofstream(bowtie) << R"({"points": [[0, 0], [10, 10], [10, 0], [0, 10]]})";
  const std::string nan = ::testing::TempDir() + "terrain_nan.json";
  std::ofstream(nan) << R"({"points": [[0, 0], [1, 0], "x"]})";
  struct Case {
    std::vector<std::string> args;
    std::string line;
  };
  const std::vector<Case> cases = {
      {{"--contour", bowtie},
       "niwa: error: --contour: self-intersects or has no area; must be a simple closed polygon\n"},
      {{"--contour", nan},
       "niwa: error: --contour: contour: a point is not [x, y] numbers; must be {\"points\": [[x, "
       "y], ...]} in metres or a GeoJSON Polygon or LineString\n"},
      {{"--builtin", "disk", "--set", "c=0.9"},
       "niwa: error: --set: c: 0.9 is out of range; must be a number in [1, 100]\n"},
      {{"--builtin", "disk", "--set", "d=0"},
       "niwa: error: --set: d: 0 is out of range; must be a number in [0.01, 100000]\n"},
      {{"--builtin", "disk", "--set", "f0=600"},
       "niwa: error: f0: 600 is out of range; must be a whole number in [1, nfft/2 = 512]\n"},
      {{"--builtin", "nope"},
       "niwa: error: --builtin: 'nope' is unknown; must be disk, dumbbell, lobes7, jacksboro or "
       "valleys\n"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"terrain", "grow"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.push_back("--contours");
    args.push_back(out);
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 2) << c.line;
    EXPECT_EQ(r.err, c.line);
    EXPECT_FALSE(std::ifstream(out).good()) << c.line;
  }
}

// Issue 34: every numeric flag through the one strict parser with the table row's range (decimal
// only, never hex or empty, in range), and a flag refused where its output is not written.
TEST(TerrainCli, NumericFlagsAreStrictAndApplyOnlyWhereRead) {
  struct Case {
    std::vector<std::string> args;
    std::string line;
  };
  const std::vector<Case> cases = {
      {{"grow", "--builtin", "disk", "--stats", "--res", "0x40"},
       "niwa: error: --res: '0x40' is not a decimal number; must be a whole number in [8, 4096]\n"},
      {{"grow", "--builtin", "disk", "--stats", "--res", "0"},
       "niwa: error: --res: 0 is out of range; must be a whole number in [8, 4096]\n"},
      {{"grow", "--builtin", "disk", "--stats", "--res", ""},
       "niwa: error: --res: empty; must be a whole number in [8, 4096]\n"},
      {{"grow", "--builtin", "disk", "--stats", "--seed", "0x10"},
       "niwa: error: --seed: '0x10' is not a decimal number; must be a whole number in [0, "
       "4294967295]\n"},
      {{"grow", "--builtin", "disk", "--stats", "--seed", "4294967296"},
       "niwa: error: --seed: 4294967296 is out of range; must be a whole number in [0, "
       "4294967295]\n"},
      {{"compare", "--dem", "none.png", "--builtin", "disk", "--seed", "1.5"},
       "niwa: error: --seed: 1.5 is out of range; must be a whole number in [0, 4294967295]\n"},
      {{"shrink", "--builtin", "disk", "--seed", "3"},
       "niwa: error: --seed: only applies with --displace D0,D2,THETA_MIN,THETA_MAX or --fourier "
       "F0[,N]\n"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"terrain"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 2) << c.line;
    EXPECT_EQ(r.err, c.line);
  }
}

// Issue 34: a terrain link with a repeated key, or longer than 16,384 characters, is refused with
// one line under --url (both were read before: the last value, or nothing, silently).
TEST(TerrainCli, RepeatedOrOverlongLinksAreRefused) {
  for (const std::string url :
       {"builtin=disk&builtin=lobes7", "builtin=disk&d=5&d=50", "builtin=disk&res=64&res=128"}) {
    CliResult r = RunNiwa({"terrain", "grow", "--url", url, "--stats"});
    EXPECT_EQ(r.code, 2) << url;
    const std::string key = url.substr(url.rfind('&') + 1, url.rfind('=') - url.rfind('&') - 1);
    EXPECT_EQ(r.err, "niwa: error: --url: " + key +
                         ": given 2 times; must be given once, nothing was read\n");
  }
  const std::string long_url = "builtin=disk&d=5" + std::string(16384, '0');
  CliResult r = RunNiwa({"terrain", "grow", "--url", long_url, "--stats"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err,
            "niwa: error: --url: hash: 16400 characters; the limit is 16384, nothing was read\n");
}

// The seed row's whole range is taken exactly: 2^32 − 1 is not converted to int (UBSan).
TEST(TerrainCli, LargestSeedIsTakenExactly) {
  CliResult r = RunNiwa({"terrain", "grow", "--builtin", "dumbbell", "--method", "midpoint",
                         "--seed", "4294967295", "--stats", "--res", "32"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["seed"].get<uint64_t>(), 4294967295u);
  EXPECT_NE(nlohmann::json::parse(r.out)["url"].get<std::string>().find("seed=4294967295"),
            std::string::npos);
}

}  // namespace
}  // namespace niwa
