// core/compose/tree_neighbours: two trees 3 m apart lean their crowns apart against the same trees
// grown alone; with the switch off each is its lone run, bit for bit; the order of the trees
// changes nothing; the Grower without foreign shade is today's (a pinned tree).
#include "compose/tree_neighbours.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <glm/geometric.hpp>
#include <memory>
#include <string>

#include "base/budget.h"
#include "tree/presets.h"
#include "tree/tree_json.h"
#include "tree/tree_state.h"

namespace niwa::compose {
namespace {

// Sakura grows wide early (3.6 m across at 10 years): two of them 3 m apart meet.
constexpr const char* kPreset = "sakura";
constexpr int kYears = 10;
constexpr double kApart = 3.0;  // m

TreeState StateOf(const std::string& preset, int years) {
  TreeState state;
  EXPECT_TRUE(SetStatePreset(preset, &state).ok());
  EXPECT_TRUE(SetStateYears(years, &state).ok());
  return state;
}

std::unique_ptr<TreeRun> StartRun(const TreeState& state) {
  Result<TreeRun> run = TreeRun::Start(state, Budget());
  EXPECT_TRUE(run.ok());
  return std::make_unique<TreeRun>(std::move(run.value()));
}

uint64_t Fnv1a(const std::string& bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

// Grows two runs of `state` at x = ∓kApart/2 (z = 0) together with `shade`; `swap` lists them
// the other way round. Returns them in x order.
std::pair<std::unique_ptr<TreeRun>, std::unique_ptr<TreeRun>> GrowPair(const TreeState& state,
                                                                       const NeighbourShade& shade,
                                                                       bool swap = false) {
  auto west = StartRun(state), east = StartRun(state);
  TreeAt a{west.get(), -0.5 * kApart, 0.0, 0.0}, b{east.get(), 0.5 * kApart, 0.0, 0.0};
  const std::vector<TreeAt> trees = swap ? std::vector<TreeAt>{b, a} : std::vector<TreeAt>{a, b};
  EXPECT_TRUE(GrowTreesTogether(trees, shade, nullptr).ok());
  return {std::move(west), std::move(east)};
}

// One tree's shape is chaotic (a shoot that dies or lives changes all that grows from it), so the
// lean is measured over seeds 1..8: the pair of each seed together against that seed's tree alone.
TEST(TreeNeighbours, TwoTreesThreeMetresApartLeanTheirCrownsApart) {
  constexpr int kSeeds = 8;
  double west_sum = 0, east_sum = 0, apart_sum = 0, apart_least = 1e9;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    TreeState state = StateOf(kPreset, kYears);
    ASSERT_TRUE(SetStateSeed(seed, &state).ok());
    std::unique_ptr<TreeRun> alone = StartRun(state);
    ASSERT_TRUE(alone->Advance(nullptr).ok());
    const auto [west, east] = GrowPair(state, NeighbourShade());
    ASSERT_EQ(west->done(), kYears);
    ASSERT_EQ(east->done(), kYears);
    // The lean away from the neighbour: the leaves' centre's offset from the trunk foot along the
    // line between the trees, positive away from the other tree (west: -x, east: +x), cm; its gain
    // is together minus alone.
    const float lone_x = LeafCentroid(alone->tree()).x;
    const double west_gain = -(LeafCentroid(west->tree()).x - lone_x);
    const double east_gain = LeafCentroid(east->tree()).x - lone_x;
    const double apart =
        west_gain + east_gain;  // how much further apart the two crowns' centres are
    std::printf(
        "%s %d years, seed %d, %.1f m apart: alone leans %.1f cm along +x; together the "
        "west tree leans %.1f cm further west, the east one %.1f cm further east\n",
        kPreset, kYears, seed, kApart, lone_x, west_gain, east_gain);
    EXPECT_GT(apart, 10.0) << "seed " << seed;  // measured: 13.7 cm at the least (seed 1)
    west_sum += west_gain;
    east_sum += east_gain;
    apart_sum += apart;
    apart_least = std::min(apart_least, apart);
  }
  const double west_mean = west_sum / kSeeds, east_mean = east_sum / kSeeds;
  std::printf(
      "mean over %d seeds: west %.1f cm, east %.1f cm, the crowns' centres %.1f cm further "
      "apart (least %.1f cm)\n",
      kSeeds, west_mean, east_mean, apart_sum / kSeeds, apart_least);
  // Measured (native): west 11.0, east 41.3, apart 52.2 cm on average.
  EXPECT_GT(west_mean, 0.0);
  EXPECT_GT(east_mean, 0.0);
  EXPECT_GT(apart_sum / kSeeds, 30.0);
}

TEST(TreeNeighbours, SwitchedOffEachTreeIsItsLoneRun) {
  const TreeState state = StateOf(kPreset, 6);
  std::unique_ptr<TreeRun> alone = StartRun(state);
  ASSERT_TRUE(alone->Advance(nullptr).ok());
  NeighbourShade off;
  off.shade_each_other = false;
  const auto [west, east] = GrowPair(state, off);
  const std::string lone = TreeToJson(alone->tree());
  EXPECT_EQ(TreeToJson(west->tree()), lone);
  EXPECT_EQ(TreeToJson(east->tree()), lone);
}

TEST(TreeNeighbours, TheOrderOfTheTreesChangesNothing) {
  const TreeState state = StateOf(kPreset, 6);
  const auto [west, east] = GrowPair(state, NeighbourShade());
  const auto [west2, east2] = GrowPair(state, NeighbourShade(), true);
  EXPECT_EQ(TreeToJson(west->tree()), TreeToJson(west2->tree()));
  EXPECT_EQ(TreeToJson(east->tree()), TreeToJson(east2->tree()));
  EXPECT_NE(TreeToJson(west->tree()), TreeToJson(east->tree()));  // they did shade each other
  // For comparing builds (native and WASM print the same).
  std::printf("shaded pair, %s 6 years: FNV-1a of the trees' JSON %016llx %016llx\n", kPreset,
              static_cast<unsigned long long>(Fnv1a(TreeToJson(west->tree()))),
              static_cast<unsigned long long>(Fnv1a(TreeToJson(east->tree()))));
}

TEST(TreeNeighbours, BeyondTheReachATreeGrowsAsAlone) {
  const TreeState state = StateOf(kPreset, 6);
  std::unique_ptr<TreeRun> alone = StartRun(state);
  ASSERT_TRUE(alone->Advance(nullptr).ok());
  NeighbourShade near;
  near.reach_m = 0.5;  // the crowns (under 3 m across at 6 years) stay more than 0.5 m apart
  auto west = StartRun(state), east = StartRun(state);
  const std::vector<TreeAt> trees = {{west.get(), -3.0, 0.0, 0.0}, {east.get(), 3.0, 0.0, 0.0}};
  EXPECT_TRUE(ForeignShade(trees, 0, near).empty());
  ASSERT_TRUE(GrowTreesTogether(trees, near, nullptr).ok());
  EXPECT_EQ(TreeToJson(west->tree()), TreeToJson(alone->tree()));
  // Within the default reach the same pair does get shade.
  EXPECT_FALSE(ForeignShade(trees, 0, NeighbourShade()).empty());
}

TEST(TreeNeighbours, ForeignShadeIsInTheTreesFrameAndCulledBelow) {
  const TreeState state = StateOf(kPreset, 4);
  auto low = StartRun(state), high = StartRun(state);
  ASSERT_TRUE(low->Advance(nullptr).ok());
  ASSERT_TRUE(high->Advance(nullptr).ok());
  // `high` stands 1 m east and 20 m up (on a cliff): every sphere of it, moved by (100, 2000, 0)
  // cm into low's frame; low's spheres are all below high's lowest centre, so high gets none.
  const std::vector<TreeAt> trees = {{low.get(), 0.0, 0.0, 0.0}, {high.get(), 1.0, 20.0, 0.0}};
  const std::vector<LeafSphere> on_low = ForeignShade(trees, 0, NeighbourShade());
  const std::vector<LeafSphere>& own = high->leaf_spheres();
  ASSERT_EQ(on_low.size(), own.size());
  for (std::size_t i = 0; i < own.size(); ++i) {
    EXPECT_EQ(on_low[i].center, own[i].center + glm::vec3(100.0f, 2000.0f, 0.0f));
    EXPECT_EQ(on_low[i].radius, own[i].radius);
  }
  EXPECT_TRUE(ForeignShade(trees, 1, NeighbourShade()).empty());
}

// The whole garden turned a quarter about y (every foot and every tree's rot): each tree's shade,
// in its own frame, is the same (to float rounding of the turns).
TEST(TreeNeighbours, TurningTheWholeGardenChangesNoTreesShade) {
  auto a = StartRun(StateOf(kPreset, 5)), b = StartRun(StateOf("keyaki", 6));
  auto c = StartRun(StateOf("pine", 6));
  ASSERT_TRUE(a->Advance(nullptr).ok());
  ASSERT_TRUE(b->Advance(nullptr).ok());
  ASSERT_TRUE(c->Advance(nullptr).ok());
  const std::vector<TreeAt> garden = {
      {a.get(), 0.0, 0.0, 0.0, 30.0}, {b.get(), 2.0, 0.5, -1.0, -45.0}, {c.get(), -1.5, 0.0, 2.0}};
  std::vector<TreeAt> turned = garden;
  for (TreeAt& t : turned) {  // +90 about y, counter-clockwise from above: (x, z) -> (z, -x)
    const double x = t.x;
    t.x = t.z;
    t.z = -x;
    t.rot += 90.0;
  }
  for (std::size_t i = 0; i < garden.size(); ++i) {
    const std::vector<LeafSphere> before = ForeignShade(garden, i, NeighbourShade());
    const std::vector<LeafSphere> after = ForeignShade(turned, i, NeighbourShade());
    ASSERT_FALSE(before.empty());
    ASSERT_EQ(before.size(), after.size()) << "tree " << i;
    float worst = 0.0f;
    for (std::size_t k = 0; k < before.size(); ++k) {
      worst = std::max(worst, glm::length(before[k].center - after[k].center));
      ASSERT_EQ(before[k].radius, after[k].radius);
    }
    EXPECT_LT(worst, 0.01f) << "tree " << i;  // cm
  }
  // And a turn moves the shade: tree 1 turned another 90 degrees casts it elsewhere on tree 0.
  std::vector<TreeAt> spun = garden;
  spun[1].rot += 90.0;
  const std::vector<LeafSphere> moved = ForeignShade(spun, 0, NeighbourShade());
  const std::vector<LeafSphere> still = ForeignShade(garden, 0, NeighbourShade());
  float farthest = 0.0f;
  for (std::size_t k = 0; k < std::min(moved.size(), still.size()); ++k) {
    farthest = std::max(farthest, glm::length(moved[k].center - still[k].center));
  }
  EXPECT_GT(farthest, 20.0f);  // cm (a quarter turn moves a sphere r from the trunk by r·√2)
}

TEST(TreeNeighbours, ProgressAndCancelPerYear) {
  const TreeState state = StateOf(kPreset, 3);
  auto a = StartRun(state), b = StartRun(StateOf(kPreset, 5));
  const std::vector<TreeAt> trees = {{a.get(), 0.0, 0.0, 0.0}, {b.get(), 2.0, 0.0, 0.0}};
  int calls = 0;
  Status cancelled = GrowTreesTogether(trees, NeighbourShade(), [&](const run::Progress& p) {
    EXPECT_EQ(p.phase, "trees");
    EXPECT_EQ(p.total, 5.0);
    return ++calls <= 2;  // two years, then cancel
  });
  EXPECT_TRUE(run::IsCancelled(cancelled));
  EXPECT_EQ(a->done(), 2);
  EXPECT_EQ(b->done(), 2);
  std::vector<double> seen;
  ASSERT_TRUE(GrowTreesTogether(trees, NeighbourShade(), [&](const run::Progress& p) {
                seen.push_back(p.done);
                return true;
              }).ok());
  EXPECT_EQ(seen, (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(a->done(), 3);
  EXPECT_EQ(b->done(), 5);
}

// A tree a limit stops keeps shading with its last spheres while the others grow on; the group
// ends when every tree is finished or stopped. Its stop line is its lone run's.
TEST(TreeNeighbours, ATreeALimitStopsLeavesTheOthersGrowing) {
  TreeState capped = StateOf(kPreset, 8);
  capped.limits.max_internodes = 2000;
  capped.limits.internode_limit = "max_internodes";
  auto small = StartRun(capped), big = StartRun(StateOf(kPreset, 8));
  const std::vector<TreeAt> trees = {{small.get(), 0.0, 0.0, 0.0}, {big.get(), 3.0, 0.0, 0.0}};
  ASSERT_TRUE(GrowTreesTogether(trees, NeighbourShade(), nullptr).ok());
  EXPECT_TRUE(small->stopped());
  EXPECT_LT(small->done(), 8);
  EXPECT_EQ(big->done(), 8);
  std::unique_ptr<TreeRun> lone = StartRun(capped);
  ASSERT_TRUE(lone->Advance(nullptr).ok());
  EXPECT_EQ(small->tree().truncated_by, lone->tree().truncated_by);
  EXPECT_EQ(GrowTogetherYear(trees, NeighbourShade()), 0);  // nothing left to grow
}

TEST(TreeNeighbours, BadGroupsAreRefusedByField) {
  NeighbourShade far;
  far.reach_m = -1;
  EXPECT_EQ(CheckTreesTogether({}, far).field(), "reach_m");
  const std::vector<TreeAt> no_run = {{nullptr, 0.0, 0.0, 0.0}};
  EXPECT_EQ(GrowTreesTogether(no_run, NeighbourShade(), nullptr).field(), "trees");
}

// Today's Grower: keyaki at 8 years from its preset seed, pinned by the FNV-1a of TreeToJson
// (the bytes `niwa tree grow --preset keyaki --years 8 --out t.json` wrote before foreign shade
// existed, 0xcb601799ce6fcd2b; since 2026-12-07 the JSON's params also hold the mesh rows
// leaf_spray 12 and leaf_card 1.4 of the keyaki preset: without the leaf_spray key and at
// leaf_card 1 the file hashes to the old pin, so the growth is the same; later that day the view
// rows bark 0 and bark_model 2 too: without them it hashes to 0x038adefe6243397e, the pin before
// them), grown with GrowYear, with StartYear and FinishYear, and with foreign spheres that lie
// below the whole tree (the second grid adds zero depth).
TEST(TreeNeighbours, TheGrowerWithoutForeignShadeIsTodays) {
  GrowRequest r;
  r.preset = "keyaki";
  r.params = FindPreset("keyaki")->params;
  r.seed = FindPreset("keyaki")->seed;
  r.years = 8;
  constexpr uint64_t kPinned = 0x61c9b3cf884305a6ull;
  Grower whole(r), halves(r), below(r);
  while (whole.year() < r.years) {
    whole.GrowYear();
    halves.StartYear();
    halves.FinishYear({});
    below.StartYear();
    std::vector<LeafSphere> under;
    for (const LeafSphere& s : below.leaf_spheres()) {
      under.push_back({s.center + glm::vec3(30.0f, -5000.0f, -20.0f), s.radius});
    }
    below.FinishYear(under);
  }
  EXPECT_EQ(Fnv1a(TreeToJson(whole.tree())), kPinned);
  EXPECT_EQ(Fnv1a(TreeToJson(halves.tree())), kPinned);
  EXPECT_EQ(Fnv1a(TreeToJson(below.tree())), kPinned);
}

}  // namespace
}  // namespace niwa::compose
