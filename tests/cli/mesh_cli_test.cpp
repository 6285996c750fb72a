// `niwa mesh` in-process (both builds): hand-computed stats of hierarchy.glb, closest and ray
// answers on the built-in box, and one-line exit-2 errors for bad flags and bad meshes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace niwa {
namespace {

std::string MeshPath(const std::string& name) {
  return std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

TEST(MeshCli, StatsOfTheHierarchyAreTheHandComputedOnes) {
  CliResult r = RunNiwa({"mesh", "stats", "--mesh", MeshPath("hierarchy.glb")});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["triangles"], 9);
  EXPECT_EQ(j["vertices"], 24);
  EXPECT_EQ(j["degenerate"], 1);
  EXPECT_EQ(j["skipped_points_lines"], 1);
  // Areas: rotated 0.5, scaled 2 x 3 / 2 = 3, matrix strip 2 x 2 = 4, mirror 0.5, fan 1, mixed 0.5,
  // squash |(2, 2, 1)| / 2 = 1.5.
  EXPECT_DOUBLE_EQ(j["area"].get<double>(), 11.0);
  EXPECT_EQ(j["bounds"]["min"], nlohmann::json::array({0.0, -5.0, -3.0}));
  EXPECT_EQ(j["bounds"]["max"], nlohmann::json::array({12.0, 10.0, 22.0}));
  EXPECT_GE(j["bvh_nodes"].get<int>(), 1);
  EXPECT_GE(j["bvh_depth"].get<int>(), 1);
  EXPECT_TRUE(j.contains("ms_load") && j.contains("ms_bvh"));
  CliResult sub =
      RunNiwa({"mesh", "stats", "--mesh", MeshPath("hierarchy.glb"), "--subdivide", "2"});
  ASSERT_EQ(sub.code, 0) << sub.err;
  EXPECT_EQ(nlohmann::json::parse(sub.out)["triangles"], 9 * 16);
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(sub.out)["area"].get<double>(), 11.0);
}

TEST(MeshCli, ClosestAndRayOnTheUnitBox) {
  CliResult c = RunNiwa({"mesh", "closest", "--scene", "box", "--point", "2,0,0"});
  ASSERT_EQ(c.code, 0) << c.err;
  nlohmann::json j = nlohmann::json::parse(c.out);
  EXPECT_EQ(j["found"], true);
  EXPECT_DOUBLE_EQ(j["distance"].get<double>(), 1.5);
  EXPECT_EQ(j["point"], nlohmann::json::array({0.5, 0.0, 0.0}));
  CliResult far =
      RunNiwa({"mesh", "closest", "--scene", "box", "--point", "2,0,0", "--max-distance", "1"});
  ASSERT_EQ(far.code, 0) << far.err;
  EXPECT_EQ(nlohmann::json::parse(far.out), nlohmann::json::parse(R"({"found": false})"));
  CliResult ray =
      RunNiwa({"mesh", "ray", "--scene", "box", "--origin", "0.1,0.2,5", "--dir", "0,0,-3"});
  ASSERT_EQ(ray.code, 0) << ray.err;
  j = nlohmann::json::parse(ray.out);
  EXPECT_EQ(j["hit"], true);
  EXPECT_DOUBLE_EQ(j["distance"].get<double>(), 4.5);
  EXPECT_FLOAT_EQ(j["point"][2].get<float>(), 0.5f);
  CliResult miss =
      RunNiwa({"mesh", "ray", "--scene", "box", "--origin", "0,0,5", "--dir", "0,0,1"});
  ASSERT_EQ(miss.code, 0) << miss.err;
  EXPECT_EQ(nlohmann::json::parse(miss.out), nlohmann::json::parse(R"({"hit": false})"));
}

TEST(MeshCli, BadInputIsOneLineAndExitTwo) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"mesh", "stats", "--mesh", MeshPath("nan.glb")},
       "niwa: error: --mesh: nan.glb: mesh 0 'nan' primitive 0 POSITION 1 is NaN or infinite\n"},
      {{"mesh", "stats", "--mesh", MeshPath("shapes.obj"), "--subdivide", "1.5"},
       "niwa: error: --subdivide: 1.5 is out of range; must be a whole number in [0, 8]\n"},
      {{"mesh", "stats", "--mesh", MeshPath("too_many_triangles.glb")},
       "niwa: error: --mesh: too_many_triangles.glb: 4096000 triangles in the scene; the limit is "
       "4000000 (4 M)\n"},
      {{"mesh", "stats", "--scene", "icosphere", "--subdivide", "8"},  // 1280 x 4^8
       "niwa: error: --subdivide: 8 would make 83886080 triangles; the limit is 4000000 (4 M)\n"},
      {{"mesh", "closest", "--scene", "plane", "--point", "a,b,c"},
       "niwa: error: --point: 'a,b,c' is out of range; must be three numbers X,Y,Z, each in "
       "[-1e30, "
       "1e30]\n"},
      {{"mesh", "foo"}, "niwa: error: unknown command 'foo', must be one of stats, closest, ray\n"},
      {{"mesh", "ray", "--scene", "cylinder", "--origin", "0,0,0", "--dir", "0,0,0"},
       "niwa: error: --dir: '0,0,0' is zero; must be a non-zero direction X,Y,Z\n"},
  };
  for (const auto& [args, line] : cases) {
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 2) << line;
    EXPECT_EQ(r.err, line);
    EXPECT_EQ(r.out, "");
  }
  CliResult help = RunNiwa({"mesh", "--help"});
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("closest"), std::string::npos);
}

}  // namespace
}  // namespace niwa
