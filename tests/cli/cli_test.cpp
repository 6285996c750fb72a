// Tests of the CLI library: commands, --stats, outputs, and one-line errors with exit code 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/expect_error.h"
#include "tree/tree_simple.h"

namespace niwa {
namespace {


std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "niwa_cli_test_" + name;
}

bool Exists(const std::string& path) { return static_cast<bool>(std::ifstream(path)); }

TEST(Cli, PresetsListsEveryPreset) {
  CliResult r = RunNiwa({"presets"});
  EXPECT_EQ(r.code, 0);
  for (const char* name : {"binary", "sakura-thesis", "keyaki-thesis", "tsutsuji-thesis", "sakura",
                           "keyaki", "tsutsuji", "weeping", "pine", "maple", "ginkgo"}) {
    EXPECT_NE(r.out.find(std::string(name) + "\t"), std::string::npos) << name;
  }
}

TEST(Cli, HelpOnEveryCommand) {
  for (auto args : std::vector<std::vector<std::string>>{{"--help"},
                                                         {"presets", "--help"},
                                                         {"params", "--help"},
                                                         {"tree", "--help"},
                                                         {"tree", "grow", "--help"}}) {
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 0) << args.back();
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << r.out;
  }
  EXPECT_NE(RunNiwa({"tree", "grow", "--help"}).out.find("--stats"), std::string::npos);
}

TEST(Cli, StatsPrintsOneJsonObjectWithTheRequiredFields) {
  CliResult r = RunNiwa(
      {"tree", "grow", "--preset", "tsutsuji-thesis", "--years", "6", "--seed", "4", "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"internodes", "branches", "leaves", "flowers", "height", "years", "seed",
                          "preset", "ms", "ms_light", "ms_hormone", "ms_branching", "crown_width",
                          "crown_base_height", "drooping_tips_share"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["years"], 6);
  EXPECT_EQ(j["seed"], 4);
  EXPECT_EQ(j["preset"], "tsutsuji-thesis");
  EXPECT_GT(j["internodes"].get<int>(), 0);
}

TEST(Cli, SetAndParamsFileChangeTheTree) {
  CliResult base = RunNiwa({"tree", "grow", "--preset", "sakura-thesis", "--years", "5", "--stats"});
  CliResult set = RunNiwa({"tree", "grow", "--preset", "sakura-thesis", "--years", "5", "--set",
                        "N_high=10", "--stats"});
  std::string file = TempPath("params.json");
  std::ofstream(file) << R"({"N_high": 10})";
  CliResult json = RunNiwa(
      {"tree", "grow", "--preset", "sakura-thesis", "--years", "5", "--params", file, "--stats"});
  ASSERT_EQ(set.code, 0);
  auto a = nlohmann::json::parse(base.out), b = nlohmann::json::parse(set.out),
       c = nlohmann::json::parse(json.out);
  EXPECT_NE(a["internodes"], b["internodes"]);
  EXPECT_EQ(b["internodes"], c["internodes"]);
}

TEST(Cli, BadInputGivesOneLineNamingTheFieldAndExit2) {
  ExpectOneLineError(RunNiwa({"tree", "grow", "--preset", "oak"}),
                     "--preset: unknown 'oak', must be one of");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--set", "alpha_t=3"}),
                     "alpha_t: 3 is out of range; must be a number in [0, 1]");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--set", "nope=1"}), "unknown parameter 'nope'");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--set", "gamma"}),
                     "--set: 'gamma' must be key=value");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--years", "500"}), "--years: 500 is out of range");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--years", "abc"}), "--years");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--prune", "x"}), "prune");
  // Prunes that cut nothing: no output file is written.
  std::string pruned = TempPath("pruned.json");
  std::remove(pruned.c_str());
  ExpectOneLineError(RunNiwa({"tree", "grow", "--preset", "binary", "--years", "10", "--prune",
                              "99:b1", "--out", pruned}),
                     "--prune: 99:b1: year 99 is after the last year grown (10)");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--preset", "binary", "--years", "10", "--prune",
                              "10:b999999", "--out", pruned}),
                     "--prune: 10:b999999: the tree had no branch b999999 by year 10 (ids 0 to");
  EXPECT_FALSE(std::ifstream(pruned).good());
  ExpectOneLineError(RunNiwa({"tree", "grow", "--out", "tree.obj"}),
                     "must end in .glb, .json or .svg");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--bogus"}), "--bogus");
  ExpectOneLineError(RunNiwa({"frobnicate"}), "frobnicate");
  std::string bad = TempPath("bad.json");
  std::ofstream(bad) << "{\"gamma\": ";
  ExpectOneLineError(RunNiwa({"tree", "grow", "--params", bad}), "malformed JSON");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--params", TempPath("missing.json")}),
                     "cannot read");
}

TEST(Cli, UnwritablePathFailsCleanlyAndLeavesNoFile) {
  std::string path = "/nonexistent-dir/tree.json";
  ExpectOneLineError(RunNiwa({"tree", "grow", "--years", "2", "--out", path}), "cannot write");
  EXPECT_FALSE(Exists(path));
  EXPECT_FALSE(Exists(path + ".niwa-partial"));
}

TEST(Cli, WritesJsonAndSvg) {
  for (std::string ext : {".json", ".svg"}) {
    std::string path = TempPath("tree" + ext);
    std::remove(path.c_str());
    CliResult r = RunNiwa({"tree", "grow", "--preset", "binary", "--years", "5", "--out", path});
    ASSERT_EQ(r.code, 0) << r.err;
    std::stringstream content;
    content << std::ifstream(path).rdbuf();
    if (ext == ".json") {
      auto j = nlohmann::json::parse(content.str());
      EXPECT_EQ(j["preset"], "binary");
      EXPECT_GT(j["branches"].size(), 1u);
    } else {
      EXPECT_EQ(content.str().rfind("<svg", 0), 0u);
      EXPECT_NE(content.str().find("<polyline"), std::string::npos);
    }
    EXPECT_FALSE(Exists(path + ".niwa-partial"));
  }
}

TEST(Cli, SvgOptionsChangeTheDrawing) {
  std::string path = TempPath("options.svg");
  CliResult r =
      RunNiwa({"tree", "grow", "--preset", "binary", "--years", "4", "--out", path, "--svg-width",
               "300", "--svg-height", "200", "--svg-leaves", "0", "--caption", "(a) P<1"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::stringstream content;
  content << std::ifstream(path).rdbuf();
  EXPECT_NE(content.str().find("width=\"300\" height=\"200\""), std::string::npos);
  EXPECT_EQ(content.str().find("stroke=\"#3f8f3a\""), std::string::npos);  // no leaf group
  EXPECT_NE(content.str().find("(a) P&lt;1</text>"), std::string::npos);
  ExpectOneLineError(RunNiwa({"tree", "grow", "--svg-width", "300", "--out", TempPath("t.json")}),
                     "--svg-width: only applies with --out FILE.svg");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--caption", "x"}), "--caption: only applies");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--svg-width", "5", "--out", path}),
                     "--svg-width: 5 is out of range; must be a whole number in [100, 10000]");
  ExpectOneLineError(RunNiwa({"tree", "grow", "--svg-leaves", "maybe", "--out", path}),
                     "--svg-leaves");
}

TEST(Cli, UrlGrowsTheSameTreeAsTheFlags) {
  CliResult flags = RunNiwa({"tree", "grow", "--preset", "keyaki-thesis", "--years", "7", "--seed",
                          "3", "--set", "gamma=0.3", "--prune", "6:b2", "--stats"});
  CliResult url = RunNiwa({"tree", "grow", "--url",
                        "#preset=keyaki-thesis&seed=3&years=7&gamma=0.3&prune=6:b2", "--stats"});
  ASSERT_EQ(url.code, 0) << url.err;
  auto a = nlohmann::json::parse(flags.out), b = nlohmann::json::parse(url.out);
  EXPECT_EQ(a["internodes"], b["internodes"]);
  EXPECT_EQ(a["leaves"], b["leaves"]);
  ExpectOneLineError(RunNiwa({"tree", "grow", "--url", "preset=keyaki-thesis&gamma=9"}),
                     "--url: gamma");
}

}  // namespace
}  // namespace niwa

namespace niwa {
namespace {

TEST(Cli, MappingsPrintTheHormoneAndAgeRangesAsCsv) {
  std::ostringstream out, err;
  ASSERT_EQ(RunCli({"tree", "mappings", "--preset", "sakura-thesis"}, out, err), 0) << err.str();
  std::istringstream lines(out.str());
  std::string header, first, line;
  std::getline(lines, header);
  EXPECT_EQ(header,
            "hormone,N_long,N_dwarf,D_long_cm,D_dwarf_cm,b_L,b_g,P_terminal,P_tl,"
            "P_lateral_at_age_P_l_years");
  std::getline(lines, first);
  // H = 0: N_low 6, D_low 0.2 (table 2.2); the dwarf shoot's D is D_s_ratio 0.17 of that.
  EXPECT_EQ(first.rfind("0,6,6,0.2,0.034", 0), 0u) << first;
  int rows = 1;
  while (std::getline(lines, line) && !line.empty()) ++rows;
  EXPECT_EQ(rows, 61);
  std::getline(lines, line);
  EXPECT_EQ(line, "year,P_l_max");
  std::getline(lines, line);
  EXPECT_EQ(line, "1,0.1");  // P_l young
  std::ostringstream bad_out, bad_err;
  EXPECT_EQ(RunCli({"tree", "mappings", "--set", "H_sat=0"}, bad_out, bad_err), 2);
}

// ---- tree render-stats (thesis ch. 4 hybrid rendering counts) ----

TEST(CliRenderStats, PrintsOneJsonObjectWithTheTable41Keys) {
  CliResult r = RunNiwa({"tree", "render-stats", "--preset", "sakura-thesis", "--years", "6"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1);
  nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"lines", "branch_polygons", "leaf_polygons", "total_polygons", "textures",
                          "full_polygons", "primitives", "cam", "width", "height", "mode"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["width"], 512);
  EXPECT_EQ(j["total_polygons"].get<int>(),
            j["branch_polygons"].get<int>() + j["leaf_polygons"].get<int>());
  EXPECT_GT(j["full_polygons"].get<int>(), 20 * j["primitives"].get<int>());
  // Full mode reports the full mesh; a closer camera makes more cards.
  CliResult full = RunNiwa(
      {"tree", "render-stats", "--preset", "sakura-thesis", "--years", "6", "--mode", "full"});
  ASSERT_EQ(full.code, 0) << full.err;
  nlohmann::json f = nlohmann::json::parse(full.out);
  EXPECT_EQ(f["lines"], 0);
  EXPECT_EQ(f["total_polygons"], j["full_polygons"]);
  std::string cam = j["cam"].get<std::string>();
  CliResult same =
      RunNiwa({"tree", "render-stats", "--preset", "sakura-thesis", "--years", "6", "--cam", cam});
  ASSERT_EQ(same.code, 0) << same.err;
  EXPECT_EQ(nlohmann::json::parse(same.out)["lines"], j["lines"]);
  CliResult close = RunNiwa({"tree", "render-stats", "--preset", "sakura-thesis", "--years", "6",
                          "--cam", cam, "--distance", "0.5"});
  ASSERT_EQ(close.code, 0) << close.err;
  EXPECT_GT(nlohmann::json::parse(close.out)["branch_polygons"].get<int>(),
            j["branch_polygons"].get<int>());
}

TEST(CliRenderStats, RenderRowsOfTheParameterTableSetTheOptions) {
  auto run = [](std::vector<std::string> extra) {
    std::vector<std::string> args = {"tree",          "render-stats", "--preset",
                                     "sakura-thesis", "--years",      "6"};
    args.insert(args.end(), extra.begin(), extra.end());
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  nlohmann::json plain = run({});
  nlohmann::json by_set = run({"--set", "line_threshold=12"});
  nlohmann::json by_flag = run({"--threshold", "12"});
  nlohmann::json by_url = run({"--url", "preset=sakura-thesis&years=6&line_threshold=12"});
  EXPECT_EQ(by_set["threshold"], 12.0);
  EXPECT_EQ(by_set["lines"], by_flag["lines"]);
  EXPECT_EQ(by_url["lines"], by_flag["lines"]);
  EXPECT_GT(by_set["lines"].get<int>(), plain["lines"].get<int>());  // fewer cards
  // The flag wins over the parameter.
  EXPECT_EQ(run({"--set", "line_threshold=12", "--threshold", "4"})["lines"], plain["lines"]);
  nlohmann::json branch_cards = run({"--set", "leaf_cluster_cards=0"});
  EXPECT_EQ(branch_cards["leaf_mode"], "branch");
  EXPECT_EQ(branch_cards["leaf_clusters"], 0);
  EXPECT_GT(run({"--set", "card_planes=3"})["textures"].get<int>(), plain["textures"].get<int>());
}

TEST(CliRenderStats, BadFlagsAreOneLineErrorsWithExitCode2) {
  std::vector<std::string> base = {"tree", "render-stats", "--preset", "binary", "--years", "3"};
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return RunNiwa(args);
  };
  ExpectOneLineError(run({"--width", "0"}),
                     "--width: 0 is out of range; must be a whole number in [16, 16384]");
  ExpectOneLineError(run({"--height", "99999"}), "--height");
  ExpectOneLineError(run({"--mode", "fast"}), "--mode");
  ExpectOneLineError(run({"--threshold", "-1"}),
                     "--threshold: -1 is out of range; must be a number in [0.1, 1000]");
  ExpectOneLineError(run({"--card-planes", "1"}), "--card-planes");
  ExpectOneLineError(run({"--cam", "1,2,3"}), "--cam");
  ExpectOneLineError(run({"--pitch", "3"}),
                     "--pitch: 3 is out of range; must be a number in [-0.1, 1.5]");
  ExpectOneLineError(run({"--distance", "0"}), "--distance");
  ExpectOneLineError(run({"--target", "1,2"}), "--target");
  ExpectOneLineError(run({"--leaf-mode", "none"}), "--leaf-mode");
}

// 'niwa params' lists the tree table as before; a study name picks a study's table.
TEST(Cli, ParamsListsAStudysTableWithStagesAndGroupTitlesInJson) {
  CliResult plain = RunNiwa({"params"});
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(plain.out.rfind("alpha_t\tα_t\t-\tdefault 0.7\ta number in [0, 1]\t", 0), 0u);
  EXPECT_EQ(RunNiwa({"params", "tree"}).out, plain.out);
  CliResult json = RunNiwa({"params", "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  nlohmann::json rows = nlohmann::json::parse(json.out);
  ASSERT_GT(rows.size(), 80u);
  for (const auto& row : rows) {
    EXPECT_TRUE(row.contains("stage")) << row["key"];
    EXPECT_TRUE(row.contains("group_title")) << row["key"];
  }
  EXPECT_EQ(rows[0]["stage"], "grow");
  EXPECT_EQ(RunNiwa({"presets", "tree"}).out, RunNiwa({"presets"}).out);
  ExpectOneLineError(RunNiwa({"params", "bark-beetle"}),
                     "study: unknown 'bark-beetle', must be one of tree");
}

// 'niwa params tree --json' carries the Getting started group the page's panel shows (issue 17
// item 8): the same JSON the page's worker gets (TreeParamTableJsonWithSimple), with the plain
// name and help on exactly the group's rows; other studies' tables have no such group.
TEST(Cli, ParamsJsonCarriesTheGettingStartedGroup) {
  CliResult json = RunNiwa({"params", "tree", "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  EXPECT_EQ(json.out, TreeParamTableJsonWithSimple() + "\n");
  nlohmann::json rows = nlohmann::json::parse(json.out);
  std::vector<std::string> simple;
  for (const auto& row : rows) {
    if (!row.contains("simple")) {
      EXPECT_FALSE(row.contains("simple_help")) << row["key"];
      continue;
    }
    simple.push_back(row["key"].get<std::string>());
    EXPECT_FALSE(row["simple"].get<std::string>().empty()) << row["key"];
    EXPECT_GT(row["simple_help"].get<std::string>().size(), 20u) << row["key"];
  }
  std::vector<std::string> expected;
  for (const SimpleControl& c : TreeSimpleControls()) {
    expected.push_back(Spec(c.row).key);
    EXPECT_EQ(rows[static_cast<std::size_t>(c.row)]["simple"], c.name);
  }
  EXPECT_EQ(simple, expected);
  EXPECT_GE(simple.size(), 5u);
  CliResult ivy = RunNiwa({"params", "ivy", "--json"});
  ASSERT_EQ(ivy.code, 0) << ivy.err;
  EXPECT_EQ(ivy.out.find("\"simple\""), std::string::npos);
}

// Every command file's commands are registered (the list is generated from the glob), in the order
// of their cli-order lines.
TEST(Cli, CommandsOfEveryStudyFileAreRegistered) {
  ExpectOneLineError(
      RunNiwa({"tree", "frob"}),
      "unknown command 'frob', must be one of grow, state, mappings, sway, render-stats");
  CliResult help = RunNiwa({"tree", "--help"});
  ASSERT_EQ(help.code, 0);
  for (const char* command : {"grow", "state", "mappings", "sway", "render-stats"}) {
    EXPECT_NE(help.out.find(command), std::string::npos) << command;
  }
}

// Each flag's range is written once: the help text shows the range the check enforces.
TEST(Cli, FlagHelpAndCheckShowTheSameRange) {
  std::string sway_help = RunNiwa({"tree", "sway", "--help"}).out;
  EXPECT_NE(sway_help.find("1..50 (default 4)"), std::string::npos);
  ExpectOneLineError(RunNiwa({"tree", "sway", "--tips", "51"}),
                     "--tips: 51 is out of range; must be a whole number in [1, 50]");
  EXPECT_NE(sway_help.find("m/s, 0..100 (default 5)"), std::string::npos);
  ExpectOneLineError(RunNiwa({"tree", "sway", "--wind", "101"}),
                     "--wind: 101 is out of range; must be a number in [0, 100]");
  std::string render_help = RunNiwa({"tree", "render-stats", "--help"}).out;
  EXPECT_NE(render_help.find("radians, -0.1..1.5"), std::string::npos);
  EXPECT_NE(render_help.find("metres, 0.2..400"), std::string::npos);
  std::string grow_help = RunNiwa({"tree", "grow", "--help"}).out;
  EXPECT_NE(grow_help.find("Years to grow, 0..100"), std::string::npos);
  EXPECT_NE(grow_help.find("SVG width in pixels, 100..10000"), std::string::npos);
  ExpectOneLineError(RunNiwa({"tree", "grow", "--seed", "4294967296"}),
                     "--seed: 4294967296 is out of range; must be a whole number in [0, "
                     "4294967295]");
}

// A --params file may carry a preset's own fields (name, years, ...) beside the values.
TEST(Cli, ParamsFileMayBeAPresetFile) {
  std::string file = TempPath("preset_like.json");
  std::ofstream(file) << R"({"name": "mine", "years": 3, "N_high": 10})";
  CliResult r = RunNiwa({"tree", "grow", "--years", "3", "--params", file, "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  CliResult set = RunNiwa({"tree", "grow", "--years", "3", "--set", "N_high=10", "--stats"});
  EXPECT_EQ(nlohmann::json::parse(r.out)["internodes"],
            nlohmann::json::parse(set.out)["internodes"]);
}

}  // namespace
}  // namespace niwa
