// 'niwa terrain compare': a DEM that is the grown mountain's own heightmap compares as (almost)
// identical, the shipped real DEM and its contour give sane measures, the built-in jacksboro seed
// is the checked-in contour file, bad DEMs are one line with exit code 2; the command is an adapter
// over the core's CompareWithDem (the same JSON from the run's own heightmap bytes).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/files.h"
#include "terrain/contour_io.h"
#include "terrain/seeds.h"
#include "terrain/terrain_run.h"

namespace niwa {
namespace {

const std::string kData = std::string(NIWA_SOURCE_DIR) + "/tests/data/terrain/";

TEST(TerrainCompare, OwnHeightmapComparesAsTheSameMountain) {
  const std::string png = ::testing::TempDir() + "t_cmp_self.png";
  ASSERT_EQ(RunNiwa({"terrain", "grow", "--builtin", "dumbbell", "--method", "improved", "--seed",
                     "4", "--res", "120", "--heightmap", png})
                .code,
            0);
  CliResult r = RunNiwa({"terrain", "compare", "--dem", png, "--builtin", "dumbbell", "--method",
                         "improved", "--seed", "4"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["real"]["cells"].get<int>(), 1000);
  EXPECT_EQ(j["real"]["cells"], j["grown"]["cells"]);
  EXPECT_NEAR(j["real"]["hypsometric_integral"].get<double>(),
              j["grown"]["hypsometric_integral"].get<double>(), 1e-3);
  EXPECT_EQ(j["real"]["peaks"], j["grown"]["peaks"]);
  EXPECT_LT(j["slope_share_l1"].get<double>(), 0.01);
  ASSERT_GE(j["levels"].size(), 3u);
  for (const auto& level : j["levels"]) EXPECT_GT(level["iou"].get<double>(), 0.97) << level;
  // Another method grown from the same contour differs.
  CliResult other =
      RunNiwa({"terrain", "compare", "--dem", png, "--builtin", "dumbbell", "--method", "simple"});
  ASSERT_EQ(other.code, 0);
  EXPECT_LT(nlohmann::json::parse(other.out)["mean_iou"].get<double>(),
            j["mean_iou"].get<double>());
}

// Issue 31 item 3: under a profile ratio (dh_ratio = q ≠ 1) the levels are cut at the grown
// contours' own heights, h0 + Δh·(1 + q + … + q^(k−1)), not at h0 + k·Δh.
TEST(TerrainCompare, LevelsAreCutAtTheGrownLevelsHeights) {
  const std::string png = ::testing::TempDir() + "t_cmp_ratio.png";
  const std::vector<std::string> state = {"--builtin", "disk",  "--method",
                                          "simple",    "--set", "dh_ratio=1.3"};
  std::vector<std::string> grow = {"terrain", "grow", "--res", "100", "--heightmap", png};
  grow.insert(grow.end(), state.begin(), state.end());
  ASSERT_EQ(RunNiwa(grow).code, 0);
  std::vector<std::string> compare = {"terrain", "compare", "--dem", png};
  compare.insert(compare.end(), state.begin(), state.end());
  CliResult r = RunNiwa(compare);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const double h0 = j["h0"].get<double>(), dh = 10, q = 1.3;  // the disk's Δh
  ASSERT_GE(j["levels"].size(), 4u);
  double h = h0, step = dh;
  for (std::size_t k = 0; k < j["levels"].size(); ++k) {
    h += step;
    step *= q;
    EXPECT_EQ(j["levels"][k]["level"], static_cast<int>(k) + 1);
    EXPECT_NEAR(j["levels"][k]["elevation"].get<double>(), h, 1e-9 * h) << k;
    EXPECT_GT(j["levels"][k]["iou"].get<double>(), 0.9) << j["levels"][k];
  }
}

// Issue 28 item 2: the whole comparison is the core's; the CLI prints its JSON as it is, and its
// errors name state fields ("dem"), the CLI's the flags.
TEST(TerrainCompare, TheCommandIsAnAdapterOverCompareWithDem) {
  terrain::TerrainState state;
  ASSERT_TRUE(terrain::SetTerrainBuiltin("lobes7", &state).ok());
  ASSERT_TRUE(terrain::SetTerrainPreset("improved", &state).ok());
  ASSERT_TRUE(terrain::SetTerrainSeed(6, &state).ok());
  ASSERT_TRUE(state.params.Set(terrain::TerrainParam::kRes, 64).ok());
  const Budget budget;
  Result<terrain::TerrainRun> run = terrain::TerrainRun::Start(state, budget);
  ASSERT_TRUE(run.ok());
  ASSERT_TRUE(run->Advance({}).ok());
  Result<terrain::Heightmap> hm = run->EncodeHeightmapFiles();
  ASSERT_TRUE(hm.ok());
  Result<terrain::DemComparison> c =
      terrain::CompareWithDem(state, hm->png, hm->sidecar_json, budget);
  ASSERT_TRUE(c.ok()) << c.status().Line();
  EXPECT_TRUE(c->truncated_by.empty());
  nlohmann::json j = nlohmann::json::parse(c->json);
  EXPECT_EQ(j["seed"], 6);
  EXPECT_EQ(j["url"], "preset=improved&builtin=lobes7&seed=6&res=64");
  EXPECT_EQ(j["real"]["cells"], j["grown"]["cells"]);
  // The CLI on the same files prints the same object.
  const std::string png = ::testing::TempDir() + "t_cmp_core.png";
  std::ofstream(png, std::ios::binary)
      .write(reinterpret_cast<const char*>(hm->png.data()),
             static_cast<std::streamsize>(hm->png.size()));
  std::ofstream(::testing::TempDir() + "t_cmp_core.json") << hm->sidecar_json;
  CliResult r = RunNiwa({"terrain", "compare", "--dem", png, "--url", j["url"].get<std::string>()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, c->json + "\n");
  Result<terrain::DemComparison> bad =
      terrain::CompareWithDem(state, {'n', 'o'}, hm->sidecar_json, budget);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().field(), "dem");
}

TEST(TerrainCompare, RealDemAndItsContour) {
  CliResult r = RunNiwa({"terrain", "compare", "--dem", kData + "jacksboro_dem.png", "--contour",
                         kData + "jacksboro_800.json", "--set", "d=70", "--set", "dh=20",
                         "--method", "improved"});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["h0"], 800);  // the file's elevation
  const auto& real = j["real"];
  EXPECT_GT(real["cells"].get<int>(), 1000);
  EXPECT_GT(real["hypsometric_integral"].get<double>(), 0.2);
  EXPECT_LT(real["hypsometric_integral"].get<double>(), 0.6);
  EXPECT_GT(real["relief"].get<double>(), 100);  // the DEM tops out at 1072 m
  EXPECT_GT(j["mean_iou"].get<double>(), 0.2);
  EXPECT_LT(j["mean_iou"].get<double>(), 0.95);
  double share = 0;
  for (double s : real["slope_share"]) share += s;
  EXPECT_NEAR(share, 1.0, 1e-9);
}

TEST(TerrainCompare, BuiltinJacksboroIsTheCheckedInContour) {
  const std::string text = testing::Slurp(kData + "jacksboro_800.json");
  Result<terrain::SeedFile> file = terrain::ParseContourJson(text);
  ASSERT_TRUE(file.ok());
  Result<terrain::Ring> builtin = terrain::BuiltinSeed("jacksboro");
  ASSERT_TRUE(builtin.ok());
  EXPECT_EQ(file->ring, *builtin);
  EXPECT_EQ(file->elevation, 800);
}

TEST(TerrainCompare, BadDemIsOneLine) {
  const std::string dir = ::testing::TempDir();
  const std::string lone = dir + "t_cmp_lone.png";
  std::remove((dir + "t_cmp_lone.json").c_str());
  std::ofstream(lone) << "not a png";
  CliResult missing = RunNiwa({"terrain", "compare", "--dem", lone, "--builtin", "disk"});
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.err, "niwa: error: --dem: cannot read '" + dir + "t_cmp_lone.json'\n");
  std::ofstream(dir + "t_cmp_lone.json") << "{}";
  CliResult bad = RunNiwa({"terrain", "compare", "--dem", lone, "--builtin", "disk"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err.rfind("niwa: error: --dem: not a PNG file", 0), 0u) << bad.err;
  // A contour 5 km south-west of the real DEM's corner.
  const std::string away = dir + "t_cmp_away.json";
  std::ofstream(away) << R"({"points": [[-5000, -5000], [-4000, -5000], [-4500, -4000]]})";
  CliResult off =
      RunNiwa({"terrain", "compare", "--dem", kData + "jacksboro_dem.png", "--contour", away});
  EXPECT_EQ(off.code, 2) << off.out.substr(0, 300);
  EXPECT_EQ(off.err,
            "niwa: error: --dem: no DEM cell lies inside the seed contour; must cover it\n");
}

}  // namespace
}  // namespace niwa
