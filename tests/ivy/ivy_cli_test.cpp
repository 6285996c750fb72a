// `niwa ivy` in-process (natively and under node on WASM): --stats carries every key the issue
// names, --out .lsys re-interprets to the .json's internodes, `niwa params ivy` lists Table 2, and
// bad input is one line with exit 2 and no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ivy/lstring.h"
#include "support/cli_runner.h"
#include "support/files.h"

namespace niwa {
namespace {

using ::niwa::testing::Slurp;

TEST(IvyCli, StatsHaveEveryNamedKey) {
  CliResult r = RunNiwa({"ivy", "grow", "--scene", "cubes4", "--seed-point", "column", "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"steps_run",
                          "internodes",
                          "buds",
                          "laterals",
                          "first_break_step",
                          "main_axis_internodes",
                          "rho",
                          "frac_nodes_within_d",
                          "internode_hits",
                          "up_min",
                          "bend_max",
                          "overlap_pairs",
                          "leaves",
                          "tri_count",
                          "queries",
                          "bvh_visits_per_query",
                          "ms",
                          "ms_bvh",
                          "ms_rules",
                          "ms_search",
                          "ms_mesh",
                          "ledger_err",
                          "lstring_ok"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["steps_run"], 50);
  EXPECT_EQ(j["tri_count"], 20);
  EXPECT_EQ(j["frac_nodes_within_d"], 1.0);
  EXPECT_EQ(j["internode_hits"], 0);
  EXPECT_EQ(j["lstring_ok"], true);
  EXPECT_GT(j["queries"]["closest"].get<int>(), 0);
  EXPECT_EQ(j["buds"]["A"].get<int>() + j["buds"]["D"].get<int>() + j["buds"]["Z"].get<int>(),
            j["internodes"].get<int>() + 1);
}

TEST(IvyCli, LsysAndJsonDescribeTheSameIvy) {
  const std::string lsys = "ivy_cli_test.lsys", json = "ivy_cli_test.json";
  ASSERT_EQ(RunNiwa({"ivy", "grow", "--seed", "4", "--out", lsys}).code, 0);
  ASSERT_EQ(RunNiwa({"ivy", "grow", "--seed", "4", "--out", json}).code, 0);
  auto drawn = ivy::InterpretLString(Slurp(lsys));
  ASSERT_TRUE(drawn.ok()) << drawn.status().Line();
  nlohmann::json j = nlohmann::json::parse(Slurp(json));
  ASSERT_EQ(drawn->size(), j["internodes"].size());
  EXPECT_EQ(j["params"]["L"], 50.0);
  EXPECT_EQ(j["buds"].size(), j["internodes"].size() + 1);
  EXPECT_EQ(j["buds"][0]["kind"].get<std::string>().size(), 1u);
  std::remove(lsys.c_str());
  std::remove(json.c_str());
}

TEST(IvyCli, ParamsAndScenesAreListed) {
  CliResult p = RunNiwa({"params", "ivy"});
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_NE(p.out.find("t1\tt₁"), std::string::npos);
  EXPECT_NE(p.out.find("default 0.8"), std::string::npos);
  CliResult s = RunNiwa({"ivy", "scenes"});
  ASSERT_EQ(s.code, 0);
  EXPECT_NE(s.out.find("cubes4\t20 tris"), std::string::npos);
}

TEST(IvyCli, ObstacleMaterialsAreNotSupports) {
  // materials.glb: a unit triangle of material noivy_glass at z = 0, soil at z = 1, bare at z = 2.
  const std::string mesh = std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/materials.glb";
  CliResult glass = RunNiwa({"ivy", "grow", "--mesh", mesh, "--preset", "metric", "--seed-point",
                             "0.2,0.2,0.01", "--steps", "5"});
  EXPECT_EQ(glass.code, 2);
  EXPECT_NE(glass.err.find("from the nearest face; must be within d = 0.02"), std::string::npos)
      << glass.err;
  CliResult soil = RunNiwa({"ivy", "grow", "--mesh", mesh, "--preset", "metric", "--seed-point",
                            "0.2,0.2,1.01", "--steps", "20", "--stats"});
  ASSERT_EQ(soil.code, 0) << soil.err;
  nlohmann::json j = nlohmann::json::parse(soil.out);
  EXPECT_GT(j["internodes"].get<int>(), 3);
  EXPECT_EQ(j["frac_nodes_within_d"], 1.0);
}

TEST(IvyCli, BadInputIsOneLineExit2NoFile) {
  const std::string out = "ivy_cli_bad.json";
  for (std::vector<std::string> args :
       std::vector<std::vector<std::string>>{{"--set", "t1=0.9"},
                                             {"--steps", "-1"},
                                             {"--set", "d=nan"},
                                             {"--seed-point", "600,10,450"},
                                             {"--url", "t2=x"}}) {
    std::vector<std::string> full = {"ivy", "grow"};
    full.insert(full.end(), args.begin(), args.end());
    full.push_back("--out");
    full.push_back(out);
    CliResult r = RunNiwa(full);
    EXPECT_EQ(r.code, 2) << args[0];
    EXPECT_EQ(r.err.find("niwa: error: "), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_FALSE(std::ifstream(out).good()) << args[0];
  }
}

// A run that grows nothing is an error naming why, with no file (issue 31 item 4: the pixel preset
// on a mesh in metres grew 0 internodes with exit 0 and wrote the file). The scale is the mesh's:
// read from its bounds unless --units gives it, so the paper preset grows on the 5 m mesh.
TEST(IvyCli, GrowingNothingIsAnErrorNamingWhy) {
  const std::string mesh = std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/shapes.obj";
  const std::string out = "ivy_cli_nothing.glb";
  CliResult px = RunNiwa(
      {"ivy", "grow", "--mesh", mesh, "--seed-point", "0,0,0", "--units", "px", "--out", out});
  EXPECT_EQ(px.code, 2);
  EXPECT_EQ(px.err,
            "niwa: error: --units: grew no internode in 50 steps: at 1 px per unit the internode "
            "length L = 50 and distance d = 20 scene units, and the support is 5 across; give the "
            "support's units (m, cm, mm, px) or 0 to read the scale from its bounds (240 px per "
            "unit)\n");
  EXPECT_FALSE(std::ifstream(out).good());
  CliResult set = RunNiwa({"ivy", "grow", "--mesh", mesh, "--seed-point", "0,0,0", "--preset",
                           "metric", "--set", "L=3000", "--stats"});
  EXPECT_EQ(set.code, 2);
  EXPECT_EQ(set.err.rfind("niwa: error: --set L: grew no internode", 0), 0u) << set.err;
  EXPECT_NE(set.err.find("set L and d below half its size"), std::string::npos) << set.err;
  for (const char* units : {"auto", "m"}) {
    CliResult grown = RunNiwa(
        {"ivy", "grow", "--mesh", mesh, "--seed-point", "0,0,0", "--units", units, "--stats"});
    EXPECT_EQ(grown.code, 0) << units << ": " << grown.err;
    EXPECT_GT(nlohmann::json::parse(grown.out).value("internodes", 0), 0) << units;
  }
  CliResult metric = RunNiwa(
      {"ivy", "grow", "--mesh", mesh, "--seed-point", "0,0,0", "--preset", "metric", "--stats"});
  EXPECT_EQ(metric.code, 0) << metric.err;
  EXPECT_EQ(RunNiwa({"ivy", "grow", "--units", "ft", "--stats"}).err,
            "niwa: error: --units: 'ft' is unknown; must be auto, px, mm, cm or m\n");
  // Zero steps asks for nothing: not an error.
  EXPECT_EQ(RunNiwa({"ivy", "grow", "--mesh", mesh, "--seed-point", "0,0,0", "--steps", "0"}).code,
            0);
}

}  // namespace
}  // namespace niwa

namespace niwa {
namespace {

// The tree's --url precedence (tree_cli.cpp): the link is the base and every other flag overrides
// it; --preset replaces the link's preset only when it names another one.
TEST(IvyCli, OtherFlagsOverrideTheLink) {
  const std::string path = ::testing::TempDir() + "ivy_url_precedence.json";
  auto grown = [&](std::vector<std::string> args) {
    std::remove(path.c_str());
    args.insert(args.begin(), {"ivy", "grow"});
    if (std::find(args.begin(), args.end(), "--steps") == args.end())
      args.insert(args.end(), {"--steps", "3"});
    args.insert(args.end(), {"--out", path});
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(std::ifstream(path));
  };
  const std::string link = "preset=improved&seed=3&steps=20&scene=wall&t1=0.3";
  nlohmann::json base = grown({"--url", link});
  EXPECT_EQ(base["seed"], 3);
  nlohmann::json seed = grown({"--url", link, "--seed", "5"});
  EXPECT_EQ(seed["seed"], 5);  // the flag, not the link
  nlohmann::json same = grown({"--url", link, "--preset", "improved"});
  EXPECT_EQ(same["params"]["t1"], 0.3);  // the link's own preset: its edits kept
  nlohmann::json other = grown({"--url", link, "--preset", "paper"});
  EXPECT_EQ(other["params"]["t1"], 0.2);       // another preset: its values
  EXPECT_EQ(base["params"]["max_bend"], 60);   // improved's
  EXPECT_NE(other["params"]["max_bend"], 60);  // paper's
  EXPECT_EQ(grown({"--url", link, "--steps", "2"})["steps"], 2);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace niwa
