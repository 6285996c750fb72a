// The band-capped priority-flood (band_fill.h) equals its Planchon-Darboux twin bit for bit on
// random small grids with random bands, keeps every cell in its band, is idempotent, and leaves
// only the pits band_fill.h says it must (a cell at its band's top below all 8 neighbours). The
// sub-cell slot rule (AssignSubCellSlots) equals its sweep twin on random contour trees and band
// maps, moves cells only into their band's subtree, and leaves no enclosed island.
#include "terrain/band_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "random/pcg32.h"
#include "terrain/contour.h"

namespace niwa::terrain {
namespace {

struct Grid {
  int width = 0, height = 0;
  std::vector<int> band;
  std::vector<double> floor, top;  // per band
  std::vector<double> h;
};

// Random bands (some cells outside every band, −1), heights in [floor, top] of their band; half
// the grids on a 1/4 m lattice so that ties and flats occur.
Grid RandomGrid(Pcg32* rng) {
  Grid g;
  g.width = 3 + static_cast<int>(rng->Uniform(0, 12));
  g.height = 3 + static_cast<int>(rng->Uniform(0, 12));
  const int bands = 1 + static_cast<int>(rng->Uniform(0, 5));
  for (int b = 0; b < bands; ++b) {
    const double lo = std::floor(rng->Uniform(0, 4)) * 10;
    g.floor.push_back(lo);
    g.top.push_back(lo + (rng->Uniform(0, 1) < 0.8 ? 10 : std::floor(rng->Uniform(1, 30))));
  }
  const bool lattice = rng->Uniform(0, 1) < 0.5;
  const double outside = rng->Uniform(0, 0.3);
  for (int k = 0; k < g.width * g.height; ++k) {
    const int b = rng->Uniform(0, 1) < outside ? -1 : static_cast<int>(rng->Uniform(0, bands));
    g.band.push_back(b);
    if (b < 0) {
      g.h.push_back(0);
      continue;
    }
    const std::size_t ub = static_cast<std::size_t>(b);
    double v = rng->Uniform(g.floor[ub], g.top[ub]);
    if (lattice) v = std::floor(v * 4) / 4;
    g.h.push_back(v);
  }
  return g;
}

bool Outlet(const Grid& g, int i, int j) {
  return g.band[static_cast<std::size_t>(j) * g.width + i] < 0 || i == 0 || j == 0 ||
         i + 1 == g.width || j + 1 == g.height;
}

TEST(BandFill, EqualsPlanchonDarbouxKeepsBandsIdempotent) {
  Pcg32 rng(2014);
  std::size_t raised_total = 0, capped_total = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Grid g = RandomGrid(&rng);
    std::vector<double> flood = g.h, pd = g.h;
    const std::size_t n_flood = FillWithinBands(g.width, g.height, g.band, g.top, &flood);
    const std::size_t n_pd = FillWithinBandsPlanchonDarboux(g.width, g.height, g.band, g.top, &pd);
    ASSERT_EQ(n_flood, n_pd) << "trial " << trial;
    std::size_t raised = 0;
    for (std::size_t k = 0; k < g.h.size(); ++k) {
      ASSERT_EQ(flood[k], pd[k]) << "trial " << trial << " cell " << k;
      if (flood[k] > g.h[k]) ++raised;
      if (g.band[k] < 0) {
        EXPECT_EQ(flood[k], g.h[k]);
        continue;
      }
      // Never lowered, never out of its band.
      const std::size_t b = static_cast<std::size_t>(g.band[k]);
      EXPECT_GE(flood[k], g.h[k]);
      EXPECT_GE(flood[k], g.floor[b]);
      EXPECT_LE(flood[k], g.top[b]);
    }
    EXPECT_EQ(raised, n_flood);
    raised_total += raised;
    // Idempotent.
    std::vector<double> again = flood;
    EXPECT_EQ(FillWithinBands(g.width, g.height, g.band, g.top, &again), 0u) << trial;
    EXPECT_EQ(again, flood) << trial;
    // Every cell off the outlets has a neighbour at or below it, or it is at its band's top with
    // all 8 neighbours above: the only pits left.
    for (int j = 1; j + 1 < g.height; ++j) {
      for (int i = 1; i + 1 < g.width; ++i) {
        if (Outlet(g, i, j)) continue;
        const std::size_t k = static_cast<std::size_t>(j) * g.width + i;
        double lowest = 1e300;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            if (di || dj)
              lowest = std::min(lowest, flood[static_cast<std::size_t>(j + dj) * g.width + i + di]);
        if (lowest > flood[k]) {
          EXPECT_EQ(flood[k], g.top[static_cast<std::size_t>(g.band[k])]) << trial;
          ++capped_total;
        }
      }
    }
  }
  // The random grids exercise both the fill and the cap.
  EXPECT_GT(raised_total, 400u);
  EXPECT_GT(capped_total, 10u);
  std::printf("band fill: %zu cells raised, %zu pits left at their band's top\n", raised_total,
              capped_total);
}

// A pit is raised to its lowest neighbour; a two-cell basin to its spill point; a pit whose spill
// lies above its band's top stops at the top (and stays a pit).
TEST(BandFill, HandCases) {
  // 5 × 5, one band of top 10, the edge is the outlet.
  const std::vector<int> band(25, 0);
  std::vector<double> h = {
      5, 5, 5, 5, 5,  //
      5, 6, 7, 6, 5,  //
      5, 7, 2, 8, 5,  //
      5, 6, 8, 7, 5,  //
      5, 5, 5, 5, 5,  //
  };
  std::vector<double> w = h;
  EXPECT_EQ(FillWithinBands(5, 5, band, {10}, &w), 1u);
  EXPECT_EQ(w[12], 6);  // the lowest neighbour; the edge at 5 drains the 6s
  w = h;
  EXPECT_EQ(FillWithinBands(5, 5, band, {4}, &w), 1u);
  EXPECT_EQ(w[12], 4);  // capped at the band's top
  // A basin of two cells (2 and 3) in a rim of 9 around an outlet ring of 1: both rise to 9.
  // A 2-cell basin (floor 2 and 3) inside a rim of 9 on a 6 x 5 grid.
  const std::vector<double> kBasin = {
      1, 1, 1, 1, 1, 1,  //
      1, 9, 9, 9, 9, 1,  //
      1, 9, 2, 3, 9, 1,  //
      1, 9, 9, 9, 9, 1,  //
      1, 1, 1, 1, 1, 1,  //
  };
  std::vector<double> basin = kBasin;
  const std::vector<int> band30(30, 0);
  EXPECT_EQ(FillWithinBands(6, 5, band30, {10}, &basin), 2u);
  EXPECT_EQ(basin[14], 9);
  EXPECT_EQ(basin[15], 9);
  // The same basin's floor in band 1 of top 4 (the rim in band 0 of top 10): the basin stops at 4.
  std::vector<double> capped = kBasin;
  std::vector<int> two_bands(30, 0);
  two_bands[14] = two_bands[15] = 1;
  EXPECT_EQ(FillWithinBands(6, 5, two_bands, {10, 4}, &capped), 2u);
  EXPECT_EQ(capped[14], 4);
  EXPECT_EQ(capped[15], 4);
  std::vector<double> pd = kBasin;
  EXPECT_EQ(FillWithinBandsPlanchonDarboux(6, 5, two_bands, {10, 4}, &pd), 2u);
  EXPECT_EQ(pd, capped);
}

// A random contour tree of 1-9 contours (each one's parent an earlier one; rings are not used).
Terrain RandomTree(Pcg32* rng) {
  Terrain t;
  const int n = 1 + static_cast<int>(rng->Uniform(0, 9));
  t.contours.resize(static_cast<std::size_t>(n));
  for (int c = 1; c < n; ++c) {
    const int p = static_cast<int>(rng->Uniform(0, c));
    t.contours[static_cast<std::size_t>(c)].parent = p;
    t.contours[static_cast<std::size_t>(c)].level =
        t.contours[static_cast<std::size_t>(p)].level + 1;
    t.contours[static_cast<std::size_t>(p)].children.push_back(c);
  }
  return t;
}

bool StrictDescendant(const Terrain& t, int d, int c) {
  while (d >= 0 && (d = t.contours[static_cast<std::size_t>(d)].parent) >= 0)
    if (d == c) return true;
  return false;
}

// Whether the band-b cell k reaches, through band-b cells, one that lies on the grid's edge or
// has a neighbour neither in band b nor inside b (a plain depth-first search from k).
bool ReachesTheWorld(const Terrain& t, int width, int height, const std::vector<int>& band,
                     std::size_t start) {
  const int b = band[start];
  std::vector<char> seen(band.size(), 0);
  std::vector<std::size_t> stack = {start};
  seen[start] = 1;
  while (!stack.empty()) {
    const std::size_t k = stack.back();
    stack.pop_back();
    const int i = static_cast<int>(k) % width, j = static_cast<int>(k) / width;
    if (i == 0 || j == 0 || i + 1 == width || j + 1 == height) return true;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const std::size_t n = static_cast<std::size_t>(j + dj) * width + (i + di);
        if (band[n] != b && !StrictDescendant(t, band[n], b)) return true;
        if (band[n] == b && !seen[n]) {
          seen[n] = 1;
          stack.push_back(n);
        }
      }
  }
  return false;
}

TEST(SubCellSlots, EqualsSweepTwinAndLeavesNoEnclosedIsland) {
  Pcg32 rng(1987);
  std::size_t relabelled_total = 0, trials_with_islands = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Terrain t = RandomTree(&rng);
    const int n = static_cast<int>(t.contours.size());
    const int width = 3 + static_cast<int>(rng.Uniform(0, 14));
    const int height = 3 + static_cast<int>(rng.Uniform(0, 14));
    // Blocks of random size so that bands form regions, with single cells sprinkled in.
    std::vector<int> band(static_cast<std::size_t>(width) * height);
    for (std::size_t k = 0; k < band.size(); ++k)
      band[k] = rng.Uniform(0, 1) < 0.1 ? -1 : static_cast<int>(rng.Uniform(0, n));
    const int blocks = static_cast<int>(rng.Uniform(0, 6));
    for (int q = 0; q < blocks; ++q) {
      const int i0 = static_cast<int>(rng.Uniform(0, width)),
                j0 = static_cast<int>(rng.Uniform(0, height));
      const int w = 1 + static_cast<int>(rng.Uniform(0, 6)),
                h = 1 + static_cast<int>(rng.Uniform(0, 6));
      const int b = static_cast<int>(rng.Uniform(0, n));
      for (int j = j0; j < std::min(height, j0 + h); ++j)
        for (int i = i0; i < std::min(width, i0 + w); ++i)
          band[static_cast<std::size_t>(j) * width + i] = b;
    }
    std::vector<int> fast = band, sweeps = band;
    const std::size_t n_fast = AssignSubCellSlots(width, height, t, &fast);
    const std::size_t n_sweeps = AssignSubCellSlotsBySweeps(width, height, t, &sweeps);
    ASSERT_EQ(n_fast, n_sweeps) << "trial " << trial;
    ASSERT_EQ(fast, sweeps) << "trial " << trial;
    std::size_t changed = 0;
    for (std::size_t k = 0; k < band.size(); ++k) {
      if (fast[k] == band[k]) continue;
      ++changed;
      EXPECT_TRUE(band[k] >= 0 && StrictDescendant(t, fast[k], band[k])) << "trial " << trial;
    }
    EXPECT_GE(n_fast, changed);
    EXPECT_EQ(n_fast == 0, changed == 0);
    if (n_fast > 0) ++trials_with_islands;
    relabelled_total += n_fast;
    for (std::size_t k = 0; k < fast.size(); ++k) {
      if (fast[k] < 0) continue;
      ASSERT_TRUE(ReachesTheWorld(t, width, height, fast, k)) << trial << " " << k;
    }
    // Idempotent.
    std::vector<int> again = fast;
    EXPECT_EQ(AssignSubCellSlots(width, height, t, &again), 0u);
    EXPECT_EQ(again, fast);
  }
  EXPECT_GT(trials_with_islands, 40u);
  std::printf("sub-cell slots: %zu cells relabelled in %zu of 400 grids\n", relabelled_total,
              trials_with_islands);
}

// A one-cell slot of band 0 inside its child 1 (whose child 2 holds the slot's south side): the
// slot goes to 1; a two-cell slot cut off between children 1 and 3 goes to the child with more
// neighbours; a slot of band 1 touching band 0 stays.
TEST(SubCellSlots, HandCases) {
  Terrain t;
  t.contours.resize(4);
  t.contours[1].parent = t.contours[3].parent = 0;
  t.contours[0].children = {1, 3};
  t.contours[2].parent = 1;
  t.contours[1].children = {2};
  std::vector<int> band = {
      -1, -1, -1, -1, -1, -1, -1,  //
      -1, 0,  0,  0,  0,  0,  -1,  //
      -1, 0,  1,  1,  1,  0,  -1,  //
      -1, 0,  1,  0,  1,  0,  -1,  //
      -1, 0,  2,  2,  2,  0,  -1,  //
      -1, 0,  0,  0,  0,  0,  -1,  //
      -1, -1, -1, -1, -1, -1, -1,  //
  };
  std::vector<int> expected = band;
  expected[3 * 7 + 3] = 1;  // 5 neighbours in 1, 3 in its child 2
  EXPECT_EQ(AssignSubCellSlots(7, 7, t, &band), 1u);
  EXPECT_EQ(band, expected);
  std::vector<int> split = {
      -1, -1, -1, -1, -1, -1, -1,  //
      -1, 0,  0,  0,  0,  0,  -1,  //
      -1, 0,  1,  1,  3,  0,  -1,  //
      -1, 0,  1,  0,  3,  0,  -1,  //
      -1, 0,  1,  0,  3,  0,  -1,  //
      -1, 0,  1,  1,  1,  0,  -1,  //
      -1, -1, -1, -1, -1, -1, -1,  //
  };
  expected = split;
  expected[3 * 7 + 3] = expected[4 * 7 + 3] = 1;  // 1 borders them 9 times, 3 five times
  EXPECT_EQ(AssignSubCellSlots(7, 7, t, &split), 2u);
  EXPECT_EQ(split, expected);
  std::vector<int> open = {
      -1, -1, -1, -1, -1,  //
      -1, 0,  0,  0,  -1,  //
      -1, 1,  2,  1,  -1,  //
      -1, 0,  2,  2,  -1,  //
      -1, -1, -1, -1, -1,  //
  };
  const std::vector<int> kept = open;
  EXPECT_EQ(AssignSubCellSlots(5, 5, t, &open), 0u);
  EXPECT_EQ(open, kept);
}

}  // namespace
}  // namespace niwa::terrain
