// Tests of compose/garden_wind (Blow on the garden page): two copies of one distinct tree, 16 m
// apart along the wind, sway apart while the gust front is between them (the upwind one moves,
// the downwind one is still at rest) and both sway once it has passed; a turned copy meets the
// front where its foot is; no wind keeps every pose at rest; the wind rows are checked (a key that
// is not a wind row, a value out of range); the skin covers the page mesh's vertices; the state's
// wind (JSON, link, checks) and its direction: a wind towards −x reaches the east copy first, and
// the run's SetWind changes the link, not the garden; StatsJson (the CLI's --wind-time) per tree.
#include "compose/garden_wind.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "compose/garden_state.h"
#include "compose/garden_view.h"

namespace niwa::compose {
namespace {

// A flat 30 m garden with no objects and no rules' trees: three hand-placed sakura of one seed and
// age, grown alone (shade off), so one distinct tree drawn at three places: x = −8 and x = +8 on
// the z = 0 line, and one at x = −8, z = 8 turned 90°.
GardenRun ThreeCopies() {
  GardenState s = DefaultGardenState();
  s.ground = GroundKind::kFlat;
  s.objects.clear();
  s.ivy_on.clear();
  s.default_layout = false;
  EXPECT_TRUE(s.params.Set(GardenParam::kSize, 30).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kGroundRes, 16).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kYears, 3).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kShade, 0).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());
  s.plants = {{"sakura", 1, 2, -8, 0, 0}, {"sakura", 1, 2, 8, 0, 0}, {"sakura", 1, 2, -8, 8, 90}};
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  EXPECT_TRUE(run.ok()) << run.status().Line();
  EXPECT_TRUE(run->Advance({}).ok());
  return std::move(run).value();
}

// The sum over a copy's node points of |M_j| (eq. 3.15 tip offsets, m) and of |R_j − I|.
double Offset(const std::vector<float>& poses, std::size_t first, int nodes) {
  double sum = 0;
  for (int j = 0; j < nodes; ++j) {
    const float* p = poses.data() + (first + static_cast<std::size_t>(j)) * kSwayPoseFloats;
    sum += std::hypot(p[3], p[7], p[11]);
    sum += std::abs(p[0] - 1) + std::abs(p[5] - 1) + std::abs(p[10] - 1) + std::abs(p[1]) +
           std::abs(p[2]) + std::abs(p[4]);
  }
  return sum;
}

// The copy of `run`'s one group standing at garden point (x, z).
int CopyAt(const GardenRun& run, double x, double z) {
  const std::vector<int>& trees = run.groups()[0].trees;
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const PlacedTree& p = run.planting().trees[trees[k]];
    if (std::abs(p.x - x) < 1e-9 && std::abs(p.z - z) < 1e-9) return static_cast<int>(k);
  }
  return -1;
}

TEST(GardenWind, TheFrontReachesTheUpwindCopyFirst) {
  const GardenRun run = ThreeCopies();
  ASSERT_EQ(run.groups().size(), 1u);
  ASSERT_EQ(run.groups()[0].trees.size(), 3u);
  // Wind 8 m/s towards +x, front 4 m/s entering the 30 m garden's upwind edge (x = −15) at t = 0:
  // at x = −8 after 1.75 s, at x = +8 after 5.75 s.
  Result<ParamSet> rows = GardenWindRows(30, "{}");
  ASSERT_TRUE(rows.ok()) << rows.status().Line();
  EXPECT_DOUBLE_EQ(rows->Get(TreeParam::kGustOn), 15.0 / 4.0);
  Result<GardenWind> wind = GardenWind::Start(run, *rows, Budget{});
  ASSERT_TRUE(wind.ok()) << wind.status().Line();
  const int nodes = wind->nodes(0);
  ASSERT_GT(nodes, 10);
  EXPECT_EQ(wind->blocks(), 3u * static_cast<std::size_t>(nodes));
  const int up = CopyAt(run, -8, 0), down = CopyAt(run, 8, 0), turned = CopyAt(run, -8, 8);
  ASSERT_GE(up, 0);
  ASSERT_GE(down, 0);
  ASSERT_GE(turned, 0);
  std::vector<float> poses(wind->blocks() * kSwayPoseFloats);
  const auto offset = [&](int copy) { return Offset(poses, wind->first_block(0, copy), nodes); };

  // t = 4 s: the front (at x = +1) has passed the upwind copies, not the downwind one.
  const int steps4 = static_cast<int>(std::lround(4.0 / wind->dt()));
  wind->Step(steps4);
  wind->WritePoses(poses.data());
  EXPECT_NEAR(wind->time(), 4.0, wind->dt());
  EXPECT_GT(offset(up), 0.05) << "the upwind copy sways";
  EXPECT_GT(offset(turned), 0.05) << "the turned copy at x = -8 sways";
  // At rest up to rounding (the gravity preload balances the weight to ~1e-17 m a node point).
  EXPECT_LT(offset(down), 1e-9) << "the downwind copy is still at rest";
  // Each sways downwind (+x in the garden): the turned copy's tip offsets, in its own frame, turned
  // back by 90° (garden.vert's turn: world x = local z) point along +x too.
  const auto along = [&](int copy, int axis) {
    double sum = 0;
    for (int j = 0; j < nodes; ++j)
      sum += poses[(wind->first_block(0, copy) + j) * kSwayPoseFloats + 3 + 4 * axis];
    return sum;
  };
  EXPECT_GT(along(up, 0), 2 * std::abs(along(up, 2)));
  EXPECT_GT(along(turned, 2), 2 * std::abs(along(turned, 0)));
  EXPECT_GT(wind->SpeedAt(-8, 0), 1.0);
  EXPECT_EQ(wind->SpeedAt(8, 0), 0.0);

  // t = 9 s: the front is past both; both sway, each in its own wind (not the same poses).
  wind->Step(static_cast<int>(std::lround(9.0 / wind->dt())) - steps4);
  wind->WritePoses(poses.data());
  EXPECT_GT(offset(down), 0.05) << "the downwind copy sways once the front passed";
  EXPECT_GT(offset(up), 0.05);
  bool differ = false;
  for (int i = 0; i < nodes * kSwayPoseFloats && !differ; ++i)
    differ = poses[wind->first_block(0, up) * kSwayPoseFloats + i] !=
             poses[wind->first_block(0, down) * kSwayPoseFloats + i];
  EXPECT_TRUE(differ);
}

TEST(GardenWind, NoWindKeepsEveryPoseAtRest) {
  const GardenRun run = ThreeCopies();
  Result<ParamSet> rows = GardenWindRows(30, R"({"wind_speed": 0})");
  ASSERT_TRUE(rows.ok()) << rows.status().Line();
  Result<GardenWind> wind = GardenWind::Start(run, *rows, Budget{});
  ASSERT_TRUE(wind.ok()) << wind.status().Line();
  wind->Step(60);
  std::vector<float> poses(wind->blocks() * kSwayPoseFloats), rest(poses.size());
  wind->WritePoses(poses.data());
  RestSwayPoses(wind->blocks(), rest.data());
  double most = 0;
  for (std::size_t i = 0; i < poses.size(); ++i)
    most = std::max(most, static_cast<double>(std::abs(poses[i] - rest[i])));
  EXPECT_LT(most, 1e-9) << "every pose at rest up to rounding";
}

TEST(GardenWind, TheWindRowsAreChecked) {
  Result<ParamSet> bad_key = GardenWindRows(30, R"({"K_wind": 1})");
  ASSERT_FALSE(bad_key.ok());
  EXPECT_EQ(bad_key.status().field(), "wind");
  Result<ParamSet> bad_value = GardenWindRows(30, R"({"wind_speed": 500})");
  ASSERT_FALSE(bad_value.ok());
  EXPECT_EQ(bad_value.status().field(), "wind_speed");
  Result<ParamSet> order = GardenWindRows(30, R"({"gust_on": 10, "gust_off": 5})");
  ASSERT_FALSE(order.ok());
  EXPECT_EQ(order.status().field(), "gust_off");
  // A front that would take 15 m / 0.001 m/s = 15000 s to the centre: past gust_on's range.
  Result<ParamSet> slow = GardenWindRows(30, R"({"gust_front_speed": 0.001})");
  ASSERT_FALSE(slow.ok());
  EXPECT_EQ(slow.status().field(), "gust_front_speed");
  Result<ParamSet> instant = GardenWindRows(30, R"({"gust_front_speed": 0})");
  ASSERT_TRUE(instant.ok());
  EXPECT_EQ(instant->Get(TreeParam::kGustOn), 0.0);
}

TEST(GardenWind, TheStateCarriesTheWind) {
  GardenState s = DefaultGardenState();
  EXPECT_EQ(GardenWindJson(s), "{}");
  EXPECT_EQ(EncodeGardenHash(s).find("wind."), std::string::npos) << "the defaults: no wind keys";
  ASSERT_TRUE(ApplyGardenStateJson(R"({"wind": {"wind_speed": 12, "wind_dir": 90}})", &s).ok());
  EXPECT_EQ(s.wind.Get(TreeParam::kWindSpeed), 12.0);
  EXPECT_EQ(s.wind.Get(TreeParam::kWindDir), 90.0);
  EXPECT_EQ(GardenWindJson(s), R"({"wind_speed":12.0,"wind_dir":90.0})");
  // The JSON and the link read back to the same wind.
  GardenState back = DefaultGardenState();
  ASSERT_TRUE(ApplyGardenStateJson(GardenStateJson(s), &back).ok());
  EXPECT_TRUE(back.wind == s.wind);
  const std::string hash = EncodeGardenHash(s);
  EXPECT_NE(hash.find("wind.wind_speed=12"), std::string::npos) << hash;
  EXPECT_NE(hash.find("wind.wind_dir=90"), std::string::npos) << hash;
  GardenState linked = DefaultGardenState();
  std::vector<std::string> notices;
  ApplyGardenHash(hash, "", &linked, &notices);
  EXPECT_TRUE(notices.empty()) << notices.front();
  EXPECT_TRUE(linked.wind == s.wind);
  // Bad values: one line naming wind.<key>, the state unchanged.
  const Status big = ApplyGardenStateJson(R"({"wind": {"wind_speed": 500}})", &s);
  EXPECT_EQ(big.field(), "wind.wind_speed");
  EXPECT_NE(big.message().find("100"), std::string::npos) << big.Line();
  EXPECT_EQ(ApplyGardenStateJson(R"({"wind": {"gust_on": 3}})", &s).field(), "wind.gust_on");
  EXPECT_EQ(ApplyGardenWindJson(R"({"K_wind": 1})", &s).field(), "wind.K_wind");
  // gust_off before the derived gust_on (the front reaches the centre of the 40 m garden at 5 s).
  EXPECT_EQ(ApplyGardenWindJson(R"({"gust_off": 2})", &s).field(), "wind.gust_off");
  EXPECT_EQ(s.wind.Get(TreeParam::kWindSpeed), 12.0) << "unchanged by the refusals";
  // A link's bad wind values: clamped or dropped with a notice each, as every table's.
  GardenState clamped = DefaultGardenState();
  notices.clear();
  ApplyGardenHash("wind.wind_speed=500&wind.K_wind=1&wind.gust_on=2", "", &clamped, &notices);
  ASSERT_EQ(notices.size(), 3u);
  EXPECT_NE(notices[0].find("wind.wind_speed: clamped to 100"), std::string::npos) << notices[0];
  EXPECT_EQ(clamped.wind.Get(TreeParam::kWindSpeed), 100.0);
  GardenState late = DefaultGardenState();
  notices.clear();
  ApplyGardenHash("wind.gust_off=1", "", &late, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("wind.gust_off"), std::string::npos) << notices[0];
  EXPECT_TRUE(late.wind == GardenWindBase());
}

TEST(GardenWind, TheDirectionChoosesWhichTreeSwaysFirst) {
  GardenRun run = ThreeCopies();
  const std::string before = run.Hash("");
  // Towards −x (180°): the front enters at the east edge and reaches x = +8 first.
  ASSERT_TRUE(run.SetWind(R"({"wind_dir": 180})").ok());
  EXPECT_NE(run.Hash(""), before);
  EXPECT_NE(run.Hash("").find("wind.wind_dir=180"), std::string::npos);
  EXPECT_EQ(run.SetWind(R"({"wind_dir": 400})").field(), "wind.wind_dir");
  EXPECT_EQ(run.state().wind.Get(TreeParam::kWindDir), 180.0);
  Result<ParamSet> rows = GardenWindRows(30, run.state().wind, "");
  ASSERT_TRUE(rows.ok()) << rows.status().Line();
  Result<GardenWind> wind = GardenWind::Start(run, *rows, Budget{});
  ASSERT_TRUE(wind.ok()) << wind.status().Line();
  wind->Step(static_cast<int>(std::lround(4.0 / wind->dt())));
  std::vector<float> poses(wind->blocks() * kSwayPoseFloats);
  wind->WritePoses(poses.data());
  const int nodes = wind->nodes(0);
  const int west = CopyAt(run, -8, 0), east = CopyAt(run, 8, 0);
  EXPECT_GT(Offset(poses, wind->first_block(0, east), nodes), 0.05) << "the east copy sways";
  EXPECT_LT(Offset(poses, wind->first_block(0, west), nodes), 1e-9) << "the west one is still";
  // The CLI's stats: per planted tree in planting order, the east one swaying, the west at rest.
  const nlohmann::json stats = nlohmann::json::parse(wind->StatsJson(run));
  EXPECT_EQ(stats["steps"], 120);
  ASSERT_EQ(stats["trees"].size(), run.planting().trees.size());
  int seen = 0;
  for (const nlohmann::json& t : stats["trees"]) {
    if (t["z"] != 0.0) continue;
    if (t["x"] == -8.0) {
      EXPECT_LT(t["sway"].get<double>(), 1e-9);
      ++seen;
    }
    if (t["x"] == 8.0) {
      EXPECT_GT(t["sway"].get<double>(), 0.05);
      ++seen;
    }
  }
  EXPECT_EQ(seen, 2) << stats.dump();
}

TEST(GardenWind, TheSkinCoversThePageMesh) {
  const GardenRun run = ThreeCopies();
  Result<ParamSet> rows = GardenWindRows(30, "");
  ASSERT_TRUE(rows.ok());
  Result<GardenWind> wind = GardenWind::Start(run, *rows, Budget{});
  ASSERT_TRUE(wind.ok()) << wind.status().Line();
  const TreeSkin skin = wind->Skin(run, 0);
  const TreeMesh mesh = GardenGroupMesh(run, 0);
  EXPECT_EQ(skin.bark.joint.size(), mesh.bark.vertex_count());
  EXPECT_EQ(skin.leaves.joint.size(), mesh.leaves.vertex_count());
  EXPECT_EQ(skin.flowers.weight.size(), mesh.flowers.vertex_count());
  uint32_t most = 0;
  for (uint32_t j : skin.leaves.joint) most = std::max(most, j);
  EXPECT_LT(most, static_cast<uint32_t>(wind->nodes(0)));
  EXPECT_GT(most, 0u);
}

}  // namespace
}  // namespace niwa::compose
