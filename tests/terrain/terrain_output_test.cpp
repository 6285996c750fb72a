// 'niwa terrain grow' outputs: the .glb surface (one vertex per cell at its height, unit normals
// facing up, contour lines at their elevations), the 16-bit heightmap and its sidecar (samples give
// the heights back), GeoJSON and SVG contours, --url regrowing the same bytes, all-or-none writes.
#include "terrain/terrain_output.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "image/png.h"
#include "support/cli_runner.h"
#include "support/glb_parse.h"
#include "terrain/generate.h"
#include "terrain/heightfield.h"
#include "terrain/seeds.h"
#include "terrain/terrain_state.h"

namespace niwa {
namespace {

std::vector<unsigned char> Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The heightfield the CLI builds for lobes7, improved, seed 3, res 48.
terrain::Heightfield Reference(terrain::Terrain* t) {
  terrain::TerrainState s;
  EXPECT_TRUE(terrain::SetTerrainBuiltin("lobes7", &s).ok());
  EXPECT_TRUE(terrain::SetTerrainPreset("improved", &s).ok());
  EXPECT_TRUE(terrain::SetTerrainSeed(3, &s).ok());
  Result<terrain::Terrain> grown = terrain::Grow(*terrain::StateSeed(s), s.params, s.seed);
  EXPECT_TRUE(grown.ok());
  *t = *grown;
  return terrain::BuildHeightfield(*t, 48);
}

TEST(TerrainOutput, GlbHeightmapAndContoursMatchTheHeightfield) {
  const std::string dir = ::testing::TempDir();
  const std::string glb = dir + "t_out.glb", png = dir + "t_out.png", side = dir + "t_out.json";
  const std::string geo = dir + "t_out.geojson", svg = dir + "t_out.svg";
  for (const std::string& p : {glb, png, side, geo}) std::remove(p.c_str());
  CliResult r = RunNiwa({"terrain", "grow", "--builtin", "lobes7", "--method", "improved", "--seed",
                         "3", "--res", "48", "--out", glb, "--heightmap", png, "--contours", geo});
  ASSERT_EQ(r.code, 0) << r.err;
  terrain::Terrain t;
  const terrain::Heightfield hf = Reference(&t);

  testing::Glb g = testing::ParseGlb(Slurp(glb));
  ASSERT_EQ(g.gltf["meshes"].size(), 2u);
  const auto& surface = g.gltf["meshes"][0]["primitives"][0];
  std::vector<float> pos = testing::ReadAccessor<float>(g, surface["attributes"]["POSITION"]);
  std::vector<float> nor = testing::ReadAccessor<float>(g, surface["attributes"]["NORMAL"]);
  ASSERT_EQ(pos.size(), hf.h.size() * 3);
  ASSERT_EQ(nor.size(), pos.size());
  EXPECT_TRUE(surface["attributes"].contains("COLOR_0"));  // tint row defaults on
  for (int j = 0; j < hf.height; ++j) {
    for (int i = 0; i < hf.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * hf.width + i;
      const terrain::Vec2 c = hf.Centre(i, j);
      EXPECT_EQ(pos[3 * k], static_cast<float>(c.x));
      EXPECT_EQ(pos[3 * k + 1], static_cast<float>(hf.h[k]));
      EXPECT_EQ(pos[3 * k + 2], static_cast<float>(-c.y));
      const double len = std::hypot(nor[3 * k], nor[3 * k + 1], nor[3 * k + 2]);
      EXPECT_NEAR(len, 1.0, 1e-5);
      EXPECT_GT(nor[3 * k + 1], 0.0f);
    }
  }
  const auto& lines = g.gltf["meshes"][1]["primitives"][0];
  EXPECT_EQ(lines["mode"], 1);
  std::vector<float> lp = testing::ReadAccessor<float>(g, lines["attributes"]["POSITION"]);
  std::size_t k = 0;
  for (const terrain::ContourNode& c : t.contours)
    for (const terrain::Vec2& v : c.ring) {
      ASSERT_LT(3 * k + 2, lp.size());
      EXPECT_EQ(lp[3 * k], static_cast<float>(v.x));
      EXPECT_EQ(lp[3 * k + 1], static_cast<float>(c.elevation));
      ++k;
    }
  EXPECT_EQ(3 * k, lp.size());

  std::vector<unsigned char> bytes = Slurp(png);
  image::PngInfo info;
  Result<image::Gray16Image> img = image::DecodeGray16Png(bytes.data(), bytes.size(), &info);
  ASSERT_TRUE(img.ok());
  EXPECT_EQ(info.bit_depth, 16);
  // The heightmap is the surface on a square 2^k + 1 grid (engines' size; res 48 -> 65) over the
  // heightfield's extent (issue 31 item 7: it was the heightfield's own 49 x 50).
  const terrain::Heightfield map = terrain::BuildHeightfieldOn(t, terrain::HeightmapGrid(hf, 48));
  EXPECT_EQ(img->width, 65);
  EXPECT_EQ(img->height, 65);
  ASSERT_EQ(map.width, 65);
  EXPECT_LE(map.x0, hf.x0);
  EXPECT_GE(map.y1, hf.y1);
  EXPECT_GE(map.x0 + map.width * map.cell, hf.x0 + hf.width * hf.cell - 1e-9);
  EXPECT_LE(map.y1 - map.height * map.cell, hf.y1 - hf.height * hf.cell + 1e-9);
  std::ifstream sidecar(side);
  nlohmann::json meta = nlohmann::json::parse(sidecar);
  const double lo = meta["min_elevation"], hi = meta["max_elevation"];
  EXPECT_EQ(meta["width"], 65);
  EXPECT_EQ(meta["cell_size"].get<double>(), map.cell);
  EXPECT_EQ(meta["origin"]["x"].get<double>(), map.x0);
  EXPECT_EQ(meta["origin"]["y"].get<double>(), map.y1);
  EXPECT_NE(meta["engine"].get<std::string>().find("64 x 64 quads"), std::string::npos);
  EXPECT_EQ(lo, 0.0);
  EXPECT_GT(hi, 50.0);
  for (std::size_t q = 0; q < map.h.size(); ++q)
    EXPECT_NEAR(lo + img->pixels[q] / 65535.0 * (hi - lo), map.h[q], (hi - lo) / 65535.0);

  std::ifstream gin(geo);
  nlohmann::json fc = nlohmann::json::parse(gin);
  EXPECT_EQ(fc["type"], "FeatureCollection");
  EXPECT_EQ(fc["features"].size(), t.contours.size() + t.summits.size());
  const auto& ring0 = fc["features"][0]["geometry"]["coordinates"][0];
  EXPECT_EQ(ring0.size(), t.contours[0].ring.size() + 1);
  EXPECT_EQ(ring0.front(), ring0.back());

  CliResult plan =
      RunNiwa({"terrain", "grow", "--builtin", "dumbbell", "--contours", svg, "--stats"});
  ASSERT_EQ(plan.code, 0);
  std::ifstream sin(svg);
  const std::string text((std::istreambuf_iterator<char>(sin)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.rfind("<svg", 0), 0u);
  std::size_t paths = 0, circles = 0;
  for (std::size_t at = text.find("<path"); at != std::string::npos;
       at = text.find("<path", at + 1))
    ++paths;
  for (std::size_t at = text.find("class=\"summit\""); at != std::string::npos;
       at = text.find("class=\"summit\"", at + 1))
    ++circles;
  EXPECT_EQ(paths, nlohmann::json::parse(plan.out)["contours"].get<std::size_t>());
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), 'Z')), paths);  // closed
  EXPECT_EQ(circles, 2u);  // the dumbbell's two peaks
}

TEST(TerrainOutput, UrlFromStatsRegrowsTheSameBytes) {
  const std::string a = ::testing::TempDir() + "t_url_a.glb",
                    b = ::testing::TempDir() + "t_url_b.glb";
  CliResult r = RunNiwa({"terrain", "grow", "--builtin", "dumbbell", "--method", "fig13c", "--seed",
                         "9", "--set", "d=15", "--res", "40", "--stats", "--out", a});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string url = nlohmann::json::parse(r.out)["url"];
  EXPECT_EQ(url, "preset=fig13c&builtin=dumbbell&d=15&seed=9&res=40");
  ASSERT_EQ(RunNiwa({"terrain", "grow", "--url", "#" + url, "--out", b}).code, 0);
  EXPECT_EQ(Slurp(a), Slurp(b));
  CliResult bad = RunNiwa({"terrain", "grow", "--url", "builtin=nope", "--out", b + ".glb"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err,
            "niwa: error: --url: builtin: 'nope' is unknown; must be disk, dumbbell, lobes7, "
            "jacksboro or valleys; dropped\n");
}

TEST(TerrainOutput, SeveralOutputsAreAllOrNone) {
  const std::string dir = ::testing::TempDir();
  const std::string png = dir + "t_none.png", side = dir + "t_none.json";
  std::remove(png.c_str());
  std::remove(side.c_str());
  CliResult r = RunNiwa({"terrain", "grow", "--builtin", "disk", "--res", "16", "--heightmap", png,
                         "--out", dir + "no/such/dir/x.glb"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "niwa: error: --out: cannot write '" + dir + "no/such/dir/x.glb'\n");
  EXPECT_FALSE(std::ifstream(png).good());
  EXPECT_FALSE(std::ifstream(side).good());
  EXPECT_FALSE(std::ifstream(png + ".niwa-stage").good());
  CliResult ext = RunNiwa({"terrain", "grow", "--builtin", "disk", "--heightmap", dir + "x.tif"});
  EXPECT_EQ(ext.code, 2);
  EXPECT_EQ(ext.err, "niwa: error: --heightmap: '" + dir + "x.tif' must end in .png\n");
}

}  // namespace
}  // namespace niwa

namespace niwa {
namespace {

TEST(TerrainOutput, ParamsFileGrowsWhatItsUrlGrows) {
  const std::string dir = ::testing::TempDir();
  const std::string state = dir + "t_state.json", a = dir + "t_state_a.json";
  const std::string b = dir + "t_state_b.json";
  std::ofstream(state) << R"({"preset": "fig13c", "contour": [[0, 0], [300, 0], [300, 120],
      [160, 120], [160, 260], [0, 260]], "params": {"seed": 4, "dh": 8}})";
  CliResult r = RunNiwa({"terrain", "grow", "--params", state, "--stats", "--contours", a});
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json stats = nlohmann::json::parse(r.out);
  const std::string url = stats["url"];
  EXPECT_EQ(url.rfind("preset=fig13c&contour=0,0;300,0;300,120;160,120;160,260;0,260", 0), 0u)
      << url;
  ASSERT_EQ(RunNiwa({"terrain", "grow", "--url", url, "--contours", b}).code, 0);
  EXPECT_EQ(Slurp(a), Slurp(b));
  EXPECT_GT(Slurp(a).size(), 1000u);
}

TEST(TerrainOutput, HostileUrlsAndFlagsAreOneLineExitTwoNoFile) {
  const std::string out = ::testing::TempDir() + "t_hostile.glb";
  struct Case {
    std::vector<std::string> args;
    std::string line;
  };
  const std::vector<Case> cases = {
      {{"--url", "contour=1,2;3,4"},
       "niwa: error: --url: contour: 2 points; must be 3 to 2000 (a longer one goes in a "
       "contour file); dropped\n"},
      {{"--url", "builtin=disk&d=abc"},
       "niwa: error: --url: d: 'abc' dropped, must be a number in [0.01, 100000]\n"},
      {{"--url", "builtin=disk&%3Cscript%3E=1"},
       "niwa: error: --url: unknown key '\\x3cscript\\x3e' dropped\n"},
      {{"--url", "contour=0,0;1e300,0;0,1"},
       "niwa: error: --url: contour: a point is not finite or beyond 1e6 m; must be numbers in "
       "[-1000000, 1000000]; dropped\n"},
      {{"--builtin", "disk", "--res", "2"},
       "niwa: error: --res: 2 is out of range; must be a whole number in [8, 4096]\n"},
      {{"--builtin", "disk", "--contours", "x.kml"},
       "niwa: error: --contours: 'x.kml' must end in .json, .geojson or .svg\n"},
  };
  for (const Case& c : cases) {
    std::remove(out.c_str());
    std::vector<std::string> args{"terrain", "grow"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.push_back("--out");
    args.push_back(out);
    CliResult r = RunNiwa(args);
    EXPECT_EQ(r.code, 2) << c.line;
    EXPECT_EQ(r.err, c.line);
    EXPECT_FALSE(std::ifstream(out).good()) << c.line;
  }
}

}  // namespace
}  // namespace niwa
