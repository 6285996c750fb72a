// The heightfield through segment grids equals its brute-force twin bit for bit (every built-in
// seed and method), SegmentGrid equals RingDistance on scattered points, and the surface is what
// heightfield.h promises: continuous across contours, each contour's level set on it, no pits on
// any built-in, method, RNG seed 1-5 and resolution 256-1024 (sub-cell slots given to the child
// first: band_fill.h).
#include "terrain/heightfield.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "random/pcg32.h"
#include "terrain/band_fill.h"
#include "terrain/generate.h"
#include "terrain/polygon.h"
#include "terrain/seeds.h"
#include "terrain/segment_grid.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {
namespace {

Terrain GrowBuiltin(const std::string& seed, const std::string& method, int rng) {
  TerrainState s;
  EXPECT_TRUE(SetTerrainBuiltin(seed, &s).ok());
  EXPECT_TRUE(SetTerrainPreset(method, &s).ok());
  EXPECT_TRUE(SetTerrainSeed(rng, &s).ok());
  Result<Terrain> t = Grow(*StateSeed(s), s.params, s.seed);
  EXPECT_TRUE(t.ok());
  return t.ok() ? *t : Terrain();
}

TEST(SegmentGrid, EqualsBruteForceDistance) {
  const Terrain t = GrowBuiltin("lobes7", "improved", 4);
  Pcg32 rng(9);
  for (std::size_t c = 0; c < t.contours.size(); c += 3) {
    const Ring& ring = t.contours[c].ring;
    SegmentGrid grid;
    grid.AddRing(ring);
    grid.Build();
    int hint = -1;
    for (int q = 0; q < 400; ++q) {
      // Inside, near and far outside the ring's box (the far points test the outside bound).
      const Vec2 p{rng.Uniform(-900, 900), rng.Uniform(-900, 900)};
      EXPECT_EQ(grid.Distance(p, q % 2 ? &hint : nullptr), RingDistance(ring, p));
    }
  }
}

TEST(Heightfield, GridEqualsBruteForceTwin) {
  double fast_ms = 0, brute_ms = 0;
  for (const SeedInfo& info : BuiltinSeeds()) {
    for (const char* method : {"simple", "improved"}) {
      const Terrain t = GrowBuiltin(info.name, method, 2);
      const auto t0 = std::chrono::steady_clock::now();
      const Heightfield fast = BuildHeightfield(t, 96);
      const auto t1 = std::chrono::steady_clock::now();
      const Heightfield brute = BuildHeightfieldBruteForce(t, 96);
      const auto t2 = std::chrono::steady_clock::now();
      fast_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
      brute_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
      ASSERT_EQ(fast.h.size(), brute.h.size());
      EXPECT_EQ(fast.band, brute.band);
      for (std::size_t k = 0; k < fast.h.size(); ++k)
        ASSERT_EQ(fast.h[k], brute.h[k]) << info.name << " " << method << " cell " << k;
    }
  }
  std::printf("heightfield 96: grid %.1f ms, brute force %.1f ms\n", fast_ms, brute_ms);
}

// The stamps' paths (heightfield.cpp StampRing): slabs, vertex wedges, and whole capsules next to
// edges shorter than the margin (a twentieth of a cell). A hand-made mountain: a seed cut by a
// narrow V notch whose tip (a reflex vertex) lies 15 m below a dent of the far side, so the cells
// past the tip have their nearest point at the tip (its wedge) while the dent's slab is within
// ρ = d = 20 m of them (without the wedges they took the dent's distance); a hairpin spike (turn
// near 180°), a run of 1/1024 m edges, every edge cut to about 4 m as grown contours are; a
// child whose corner has a 2 mm edge. It equals its brute-force twin at several resolutions.
// Without the wedges 2, 11, 69 and 310 cells differ at the four resolutions; the capsules and the
// margin guard against rounding only (removing either changed no cell here).
TEST(Heightfield, GridEqualsBruteForceOnNotchesHairpinsAndShortEdges) {
  const double mm = 1 / kGridPerMetre;
  const std::vector<Vec2> corners = {{-200, -100}, {-10, -100}, {0, 40},       {10, -100},
                                     {200, -100},  {200, 0},    {200, 3 * mm}, {200, 100},
                                     {30, 100},    {30, 55},    {-30, 55},     {-30, 100},
                                     {-200, 100},  {-200, 0.5}, {-260, 0.25},  {-200, 0}};
  Ring seed;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int parts = std::max(1, static_cast<int>(len / 4));
    for (int q = 0; q < parts; ++q) {
      const double f = static_cast<double>(q) / parts;
      seed.push_back({std::round((a.x + f * (b.x - a.x)) / mm) * mm,
                      std::round((a.y + f * (b.y - a.y)) / mm) * mm});
    }
    if (k == 5) {  // the millimetre run up the right side
      seed.push_back({200, mm});
      seed.push_back({200, 2 * mm});
    }
  }
  const Ring child = {{-120, -20},         {-80, -20}, {-80, 20},
                      {-100 + 2 * mm, 20}, {-100, 20}, {-120, 20}};
  Terrain t;
  t.d = 20;
  t.dh = 10;
  t.contours.resize(2);
  t.contours[0].ring = seed;
  t.contours[0].children = {1};
  t.contours[1].ring = child;
  t.contours[1].parent = 0;
  t.contours[1].level = 1;
  t.contours[1].elevation = 10;
  t.summits.push_back({1, {-100, 0}, 20, 18});
  for (const int res : {64, 150, 333, 700}) {
    const Heightfield fast = BuildHeightfield(t, res, false);
    const Heightfield brute = BuildHeightfieldBruteForce(t, res, false);
    ASSERT_EQ(fast.h.size(), brute.h.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < fast.h.size(); ++k) differ += fast.h[k] != brute.h[k];
    EXPECT_EQ(differ, 0u) << "res " << res;
  }
}

// Along a segment between two adjacent cell centres that crosses a contour of elevation e, the
// bilinear surface crosses e where the contour is (within the cell's slope), and no cell is a pit.
TEST(Heightfield, ContinuousLevelSetsOnContoursNoPits) {
  for (const char* seed : {"disk", "dumbbell", "lobes7"}) {
    const Terrain t = GrowBuiltin(seed, "improved", 5);
    const Heightfield hf = BuildHeightfield(t, 128);
    const TerrainStats s = ComputeStats(t, &hf);
    EXPECT_EQ(s.pits, 0) << seed;
    // Continuity: neighbours differ by at most the steepest band's slope times the cell size.
    double max_step = 0;
    for (int j = 0; j < hf.height; ++j)
      for (int i = 0; i + 1 < hf.width; ++i)
        max_step = std::max(max_step, std::fabs(hf.At(i + 1, j) - hf.At(i, j)));
    EXPECT_LT(max_step, t.dh) << seed;  // a jump would be a whole interval
    // Level sets: cells in the band of contour C lie in [h_C, h_C + Δh] (summit bands: to h_s),
    // and a cell next to a contour (within half a cell) is within one cell's slope of h_C.
    for (int j = 0; j < hf.height; ++j) {
      for (int i = 0; i < hf.width; ++i) {
        const int b = hf.band[static_cast<std::size_t>(j) * hf.width + i];
        if (b < 0) continue;
        const ContourNode& node = t.contours[static_cast<std::size_t>(b)];
        double top = node.elevation + t.dh;
        for (const Summit& sm : t.summits)
          if (sm.contour == b) top = sm.elevation;
        EXPECT_GE(hf.At(i, j), node.elevation);
        EXPECT_LE(hf.At(i, j), top + 1e-9);
        const double a = RingDistance(node.ring, hf.Centre(i, j));
        if (a < 0.5 * hf.cell) {
          EXPECT_LT(hf.At(i, j) - node.elevation, t.dh * 0.75) << seed;
        }
      }
    }
  }
}

// valleys with the improved method had 11-18 pits before the band fill (RNG seeds 1-5; 10-18
// since slivers are dropped, issue 31) and 1-3 after it: single cells of a band C whose 8
// neighbours all lie inside a child of C (a slot of C's band narrower than a cell).
// AssignSubCellSlots gives such islands to the child first; what it changes is exactly what its
// sweep twin changes on the painted map, only moves cells into their band's subtree, and no pit is
// left; the fill still raises and never lowers.
TEST(Heightfield, SubCellSlotsGoToTheChildAndLeaveNoPitOnValleys) {
  std::size_t slots_total = 0;
  for (int rng = 1; rng <= 5; ++rng) {
    const Terrain t = GrowBuiltin("valleys", "improved", rng);
    const Heightfield raw = BuildHeightfield(t, 256, false);
    const Heightfield hf = BuildHeightfield(t, 256);
    EXPECT_EQ(raw.cells_filled, 0u);
    EXPECT_EQ(raw.slot_cells, 0u);
    const TerrainStats before = ComputeStats(t, &raw), after = ComputeStats(t, &hf);
    EXPECT_GE(before.pits, 10) << rng;
    EXPECT_EQ(after.pits, 0) << rng;
    std::vector<int> twin = raw.band;
    EXPECT_EQ(AssignSubCellSlotsBySweeps(raw.width, raw.height, t, &twin), hf.slot_cells) << rng;
    EXPECT_EQ(twin, hf.band) << rng;
    slots_total += hf.slot_cells;
    std::size_t raised = 0, moved = 0;
    for (std::size_t k = 0; k < hf.h.size(); ++k) {
      ASSERT_GE(hf.h[k], raw.h[k]);
      if (hf.band[k] != raw.band[k]) {
        ++moved;
        // Into a child of the painted band (or deeper): at or above the child's elevation.
        int up = hf.band[k];
        while (up >= 0 && up != raw.band[k]) up = t.contours[static_cast<std::size_t>(up)].parent;
        EXPECT_EQ(up, raw.band[k]) << rng;
        EXPECT_GE(hf.h[k], t.contours[static_cast<std::size_t>(hf.band[k])].elevation);
        continue;
      }
      if (hf.h[k] > raw.h[k]) ++raised;
    }
    EXPECT_EQ(moved, hf.slot_cells) << rng;  // no cell moved twice here
    EXPECT_GT(hf.cells_filled, 0u) << rng;
    EXPECT_GE(hf.cells_filled, raised) << rng;
  }
  std::printf("valleys/improved res 256, RNG 1-5: %zu sub-cell slot cells\n", slots_total);
  // The case under test arises (RNG 3 and 5 since the seed is resampled at d/4, issue 31; every
  // RNG seed before).
  EXPECT_GT(slots_total, 0u);
}

// No interior cell below all 8 neighbours on any built-in seed with any method (RNG seeds 1-5) at
// the page's and the CLI's usual resolution 256, and 512 and 1024 on valleys (issue 19: "no
// pits").
TEST(Heightfield, NoPitsOnEveryBuiltinMethodAndResolution) {
  std::size_t grids = 0, with_slots = 0;
  for (const SeedInfo& info : BuiltinSeeds()) {
    for (const char* method : {"simple", "midpoint", "fourier", "improved"}) {
      // RNG 1-5 on valleys (the seed with sub-cell slots), 1-3 on the others (since the seed is
      // resampled at d/4 each grow carries about 5x the points; RNG 4-5 ran at 256 only).
      const bool slots = info.name == std::string("valleys");
      for (int rng = 1; rng <= (slots ? 5 : 3); ++rng) {
        const Terrain t = GrowBuiltin(info.name, method, rng);
        for (const int res : {256, 512, 1024}) {
          // 512 and 1024 (the slow ones: this test is in every CI run, natively and in WASM) on
          // valleys, the seed with sub-cell slots, with every method (1024: RNG 1-2); `niwa
          // terrain grow --stats` ran the whole matrix at 256/512/1024 (docs/terrain-model.md).
          const bool valleys = info.name == std::string("valleys");
          if (res > 256 && !valleys) continue;
          if (res == 1024 && rng > 2) continue;
          const Heightfield hf = BuildHeightfield(t, res);
          EXPECT_EQ(ComputeStats(t, &hf).pits, 0)
              << info.name << " " << method << " RNG " << rng << " res " << res;
          ++grids;
          if (hf.slot_cells > 0) ++with_slots;
        }
      }
    }
  }
  std::printf("no pits on %zu heightfields (%zu with sub-cell slots)\n", grids, with_slots);
}

}  // namespace
}  // namespace niwa::terrain
