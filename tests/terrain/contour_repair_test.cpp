// RepairContour (core/terrain/contour_repair.h): a valid seed comes back as given, a contour with a
// small self-crossing loop is cut by §4.4 method 2 into a valid seed, a bow-tie is repaired to a
// valid seed, bad points are CheckSeed's error; and `niwa terrain grow --repair` grows the repaired
// seed (the one the page's drawing becomes); FitContourToLink makes a drawn contour fit its link.
#include "terrain/contour_repair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <utility>
#include <vector>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/hash_codec.h"
#include "support/cli_runner.h"
#include "terrain/generate.h"
#include "terrain/offset.h"
#include "terrain/polygon.h"
#include "terrain/seeds.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {
namespace {

// A square of 100 m whose bottom edge makes one small loop crossing itself near x = 46.7.
Ring Kinked() {
  return {{0, 0}, {52, 0}, {56, -6}, {50, -10}, {44, -6}, {48, 3}, {100, 3}, {100, 100}, {0, 100}};
}

TEST(ContourRepair, AValidSeedComesBackAsGiven) {
  const Ring clockwise = {{0, 0}, {0, 50}, {80, 50}, {80, 0}};  // CheckSeed takes it (normalises)
  Result<ContourRepair> r = RepairContour(clockwise);
  ASSERT_TRUE(r.ok()) << r.status().Line();
  EXPECT_FALSE(r->repaired);
  EXPECT_EQ(r->ring, clockwise);
  EXPECT_EQ(r->method, "");
  EXPECT_EQ(r->loops_removed, 0);
}

TEST(ContourRepair, CutsASmallLoopByMethodTwo) {
  ASSERT_FALSE(CheckSeed(Kinked()).ok());
  Result<ContourRepair> r = RepairContour(Kinked());
  ASSERT_TRUE(r.ok()) << r.status().Line();
  EXPECT_TRUE(r->repaired);
  EXPECT_EQ(r->method, "loops");
  EXPECT_EQ(r->loops_removed, 1);
  EXPECT_EQ(r->reason, CheckSeed(Kinked()).status().Line());
  Result<Ring> checked = CheckSeed(r->ring);
  ASSERT_TRUE(checked.ok()) << checked.status().Line();
  EXPECT_GT(Area(r->ring), 0);  // counter-clockwise
  // The big square is kept (the loop is ~60 m² of it), on the 1/1024 m grid.
  EXPECT_GT(Area(r->ring), 9000);
  for (const Vec2& v : r->ring) EXPECT_EQ(v.x * kGridPerMetre, std::round(v.x * kGridPerMetre));
}

TEST(ContourRepair, ABowTieBecomesOneSimpleLoop) {
  const Ring bow = {{0, 0}, {100, 100}, {100, 0}, {0, 100}};
  Result<ContourRepair> r = RepairContour(bow);
  ASSERT_TRUE(r.ok()) << r.status().Line();
  EXPECT_TRUE(r->repaired);
  EXPECT_TRUE(r->method == "loops" || r->method == "union") << r->method;
  EXPECT_TRUE(CheckSeed(r->ring).ok());
}

TEST(ContourRepair, BadPointsAreCheckSeedsError) {
  for (const Ring& bad :
       {Ring{{0, 0}, {1, 1}}, Ring{{0, 0}, {NAN, 1}, {2, 0}}, Ring{{0, 0}, {2e6, 1}, {2, 0}}}) {
    Result<ContourRepair> r = RepairContour(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.status().field(), "contour");
    EXPECT_EQ(r.status().Line(), CheckSeed(bad).status().Line());
  }
}

TEST(ContourRepair, TheCliGrowsTheRepairedSeedWithRepair) {
  const std::string file = ::testing::TempDir() + "kinked_contour.json";
  {
    nlohmann::json pts = nlohmann::json::array();
    for (const Vec2& v : Kinked()) pts.push_back({v.x, v.y});
    std::ofstream(file) << nlohmann::json{{"points", pts}}.dump();
  }
  CliResult refused = RunNiwa({"terrain", "grow", "--contour", file, "--stats"});
  EXPECT_EQ(refused.code, 2);
  EXPECT_EQ(refused.err,
            "niwa: error: --contour: self-intersects or has no area; must be a simple closed "
            "polygon\n");
  CliResult r = RunNiwa({"terrain", "grow", "--contour", file, "--repair", "--stats"});
  ASSERT_EQ(r.code, 0) << r.err;  // its notice goes to the process's stderr, as truncation's
  // The state carries the repaired ring (what the page's link carries after its repair).
  TerrainState state;
  std::vector<std::string> notices;
  ApplyTerrainHash(nlohmann::json::parse(r.out)["url"].get<std::string>(), "", &state, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(state.points, RepairContour(Kinked())->ring);
  std::remove(file.c_str());
}

// Issue 34: a drawn 2,000-point contour wrote a 32,618-character link, over the page's own 16,384
// limit. Fitted, its link fits and reads back to the same points, and it is still a valid seed.
TEST(FitContourToLink, ADrawnTwoThousandPointContourFitsItsLinkAndReadsBack) {
  Ring drawn;
  for (int i = 0; i < 2000; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 2000;
    const double r = 300 + 40 * std::sin(7 * a) + 3 * std::sin(53 * a);
    drawn.push_back({r * std::cos(a) + 0.123456789, r * std::sin(a) - 0.987654321});
  }
  TerrainState state;
  ASSERT_TRUE(SetTerrainPoints(drawn, &state).ok());
  ASSERT_GT(EncodeTerrainHash(state).size(), kMaxHashLength);  // what the page wrote before
  const LinkFit fit = FitContourToLink(drawn, kMaxLinkContourChars);
  ASSERT_TRUE(fit.changed);
  EXPECT_LE(EncodeContourPoints(fit.ring).size(), kMaxLinkContourChars);
  EXPECT_GT(fit.ring.size(), 500u);  // thinned, not gutted
  ASSERT_TRUE(CheckSeed(fit.ring).ok());
  ASSERT_TRUE(SetTerrainPoints(fit.ring, &state).ok());
  ASSERT_TRUE(SetTerrainSeed(4294967295.0, &state).ok());
  const std::string hash = EncodeTerrainHash(state);
  EXPECT_LE(hash.size(), kMaxHashLength);
  TerrainState back;
  std::vector<std::string> notices;
  ApplyTerrainHash(hash, "", &back, &notices);
  EXPECT_TRUE(notices.empty()) << notices[0];
  EXPECT_EQ(back.points, fit.ring);
  EXPECT_EQ(EncodeTerrainHash(back), hash);
  // A contour that fits is left as it is.
  EXPECT_FALSE(FitContourToLink(*BuiltinSeed("lobes7"), kMaxLinkContourChars).changed);
}

// A comb whose teeth run along (1, 1) from a base along (1, -1): every tooth is long against the
// base, so its edges overlap every other tooth's on both axes (a simple polygon, exact on the
// 1/1024 m grid). Issue 34: such a seed made CheckSeed's simplicity sweep quadratic before any
// budget (20,000 teeth: 3.2 G pairs).
Ring DiagonalComb(int teeth, int64_t height) {
  std::vector<std::pair<int64_t, int64_t>> th = {{0, 0}, {3 * int64_t{teeth} - 1, 0}};
  for (int i = teeth - 1; i >= 0; --i) {
    const int64_t t0 = 3 * int64_t{i}, t1 = t0 + 2;
    if (i < teeth - 1) th.push_back({t1, 10});
    th.push_back({t1, height});
    th.push_back({t0, height});
    if (i > 0) th.push_back({t0, 10});
  }
  Ring r;
  for (const auto& [t, h] : th)
    r.push_back({static_cast<double>(t + h) / 1024.0, static_cast<double>(h - t) / 1024.0});
  return r;
}

TEST(ContourRepair, ASeedWhoseEdgesOverlapOnBothAxesIsRefusedBeforeItsCheck) {
  // Small: the same shape is a valid seed (the cap is not in the way of an ordinary check).
  const Ring small = DiagonalComb(200, 1000);
  EXPECT_LT(SimplicityPairs(ToGrid(Normalise(small))), kMaxSimplicityPairs);
  EXPECT_TRUE(CheckSeed(small).ok());
  // 20,000 long teeth: refused by the count of pairs, in O(n log n), naming the contour.
  const Ring big = DiagonalComb(20000, 100000);
  const std::clock_t c0 = std::clock();
  const Result<Ring> checked = CheckSeed(big);
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.status().field(), "contour");
  EXPECT_NE(checked.status().message().find("overlap on both axes"), std::string::npos)
      << checked.status().Line();
  std::printf("diagonal comb of 20,000 teeth refused in %.2f s of CPU: %s\n", cpu,
              checked.status().Line().c_str());
  // The repair does not try it either: CheckSeed's line.
  const Result<ContourRepair> repaired = RepairContour(big);
  ASSERT_FALSE(repaired.ok());
  EXPECT_EQ(repaired.status().Line(), checked.status().Line());
}

}  // namespace
}  // namespace niwa::terrain
