// `niwa ivy grow` outputs added with the page: --tree-preset (ivy on a Niwa tree's bark), --out
// .svg (every internode and leaf drawn in both views), --with-support (the .glb holds the support
// only when asked), and the state's scene= and at= (the page's share link) growing what the flags
// grow. In-process, natively and under node on WASM.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ivy/ivy_state.h"
#include "support/cli_runner.h"
#include "support/files.h"

namespace niwa {
namespace {

using ::niwa::testing::Slurp;

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

nlohmann::json WithoutMs(nlohmann::json j) {
  for (const char* key : {"ms", "ms_bvh", "ms_rules", "ms_search", "ms_mesh"}) j.erase(key);
  return j;
}

// The node names of a .glb's JSON chunk.
std::vector<std::string> GlbNodeNames(const std::string& glb) {
  uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  nlohmann::json j = nlohmann::json::parse(glb.substr(20, length));
  std::vector<std::string> names;
  for (const auto& node : j["nodes"]) names.push_back(node.value("name", ""));
  return names;
}

TEST(IvyOutputs, TreePresetClimbsTheBark) {
  CliResult r = RunNiwa({"ivy", "grow", "--tree-preset", "sakura", "--tree-years", "6", "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["tri_count"].get<int>(), 1000);  // the bark, not a built-in scene
  EXPECT_GT(j["internodes"].get<int>(), 10);
  EXPECT_EQ(j["frac_nodes_within_d"], 1.0);
  EXPECT_EQ(j["internode_hits"], 0);
  EXPECT_GT(j["rise"].get<double>(), 0.2);  // metres up the trunk (metric preset: L = 5 cm)
  EXPECT_GE(j["up_min"].get<double>(), 0.0);
}

TEST(IvyOutputs, TreePresetBadInputNamesItsFlag) {
  for (auto [args, field] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--tree-preset", "oak"}, "--tree-preset"},
           {{"--tree-preset", "sakura", "--tree-years", "0"}, "--tree-years"},
           {{"--tree-preset", "sakura", "--tree-years", "2.5"}, "--tree-years"},
           {{"--tree-preset", "sakura", "--scene", "wall"}, "--scene"}}) {
    std::vector<std::string> full = {"ivy", "grow"};
    full.insert(full.end(), args.begin(), args.end());
    CliResult r = RunNiwa(full);
    EXPECT_EQ(r.code, 2) << args[0];
    EXPECT_EQ(r.err.find("niwa: error: " + field + ":"), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
}

TEST(IvyOutputs, SvgDrawsEveryInternodeAndLeafInBothViews) {
  const std::string svg = "ivy_outputs_test.svg";
  CliResult r = RunNiwa({"ivy", "grow", "--seed", "3", "--out", svg, "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  const std::string text = Slurp(svg);
  EXPECT_EQ(text.rfind("<svg ", 0), 0u);
  EXPECT_EQ(Count(text, "<line "), 2 * j["internodes"].get<std::size_t>());
  EXPECT_EQ(Count(text, "<circle "), 2 * j["leaves"].get<std::size_t>());
  EXPECT_EQ(Count(text, "<path "), 2 * j["tri_count"].get<std::size_t>());  // cubes4's 20 faces
  // Fewer steps draw fewer internodes (Fig. 3's steps 10 to 50).
  ASSERT_EQ(RunNiwa({"ivy", "grow", "--seed", "3", "--steps", "10", "--out", svg}).code, 0);
  EXPECT_LT(Count(Slurp(svg), "<line "), 2 * j["internodes"].get<std::size_t>());
  std::remove(svg.c_str());
}

TEST(IvyOutputs, SupportIsInTheGlbOnlyWithSupportFlag) {
  const std::string glb = "ivy_outputs_test.glb";
  ASSERT_EQ(RunNiwa({"ivy", "grow", "--out", glb}).code, 0);
  std::vector<std::string> plain = GlbNodeNames(Slurp(glb));
  EXPECT_EQ(std::count(plain.begin(), plain.end(), "support"), 0);
  EXPECT_EQ(std::count(plain.begin(), plain.end(), "ivy_stems"), 1);
  ASSERT_EQ(RunNiwa({"ivy", "grow", "--out", glb, "--with-support"}).code, 0);
  std::vector<std::string> with = GlbNodeNames(Slurp(glb));
  EXPECT_EQ(std::count(with.begin(), with.end(), "support"), 1);
  std::remove(glb.c_str());
}

TEST(IvyOutputs, HashSceneAndAtGrowWhatTheFlagsGrow) {
  CliResult flags = RunNiwa({"ivy", "grow", "--scene", "wall", "--seed-point", "100,10,10",
                             "--seed-point", "-300,10,10", "--steps", "30", "--stats"});
  CliResult url =
      RunNiwa({"ivy", "grow", "--url", "steps=30&scene=wall&at=100,10,10;-300,10,10", "--stats"});
  ASSERT_EQ(flags.code, 0) << flags.err;
  ASSERT_EQ(url.code, 0) << url.err;
  EXPECT_EQ(WithoutMs(nlohmann::json::parse(flags.out)), WithoutMs(nlohmann::json::parse(url.out)));
  // --scene wins over the hash's scene.
  CliResult both =
      RunNiwa({"ivy", "grow", "--url", "scene=sphere", "--scene", "wall", "--seed-point",
               "100,10,10", "--seed-point", "-300,10,10", "--steps", "30", "--stats"});
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_EQ(WithoutMs(nlohmann::json::parse(both.out)),
            WithoutMs(nlohmann::json::parse(flags.out)));
}

TEST(IvyOutputs, StateCarriesSceneAndSeedPoints) {
  ivy::IvyState s;
  std::vector<std::string> notices;
  ivy::ApplyIvyHash("preset=improved&scene=stairs&at=1.5,2,-3;0,1e3,4", "", &s, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(s.scene, "stairs");
  ASSERT_EQ(s.seed_points.size(), 2u);
  EXPECT_EQ(s.seed_points[1].y, 1000.0);
  EXPECT_EQ(ivy::EncodeIvyHash(s),
            "preset=improved&seed=1&steps=50&scene=stairs&at=1.5,2,-3;0,1000,4");
  // Round trip through the page's JSON.
  ivy::IvyState t;
  ASSERT_TRUE(
      ivy::ApplyIvyStateJson(R"({"scene":"stairs","seed_points":"1.5,2,-3;0,1000,4"})", &t).ok());
  EXPECT_EQ(t.seed_points, s.seed_points);
  // Hostile values are dropped with a notice naming the key; the state keeps its old values.
  ivy::IvyState u;
  // A repeated key refuses the whole link (docs/input-rules.md): one notice, nothing read.
  ivy::ApplyIvyHash("scene=moon&at=1,2&at=1,2,nan", "", &u, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0], "at: given 2 times; must be given once, nothing was read");
  notices.clear();
  ivy::ApplyIvyHash("scene=moon&at=1,2", "", &u, &notices);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_EQ(notices[0].rfind("scene: 'moon' is unknown; must be one of cubes4", 0), 0u)
      << notices[0];
  EXPECT_EQ(notices[1].rfind("at: '1,2' is not X,Y,Z", 0), 0u) << notices[1];
  notices.clear();
  ivy::ApplyIvyHash("at=1,2,nan", "", &u, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0].rfind("at: '1,2,nan' is out of range", 0), 0u) << notices[0];
  EXPECT_TRUE(u.scene.empty());
  EXPECT_TRUE(u.seed_points.empty());
  EXPECT_EQ(ivy::ApplyIvyStateJson(R"({"seed_points":[1,2,3]})", &u).field(), "seed_points");
  std::string many;
  for (int i = 0; i < 65; ++i) many += (i ? ";" : "") + std::string("0,0,0");
  EXPECT_EQ(ivy::SetIvySeedPoints(many, &u).field(), "at");
}

}  // namespace
}  // namespace niwa
