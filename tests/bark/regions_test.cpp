// The crack measures on hand-built crack sets: blocks cut on every side are closed regions of the
// expected extent, cuts around the trunk leave strips, and the intercepts count the crossings.
#include "bark/regions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "bark/bark_state.h"

namespace niwa::bark {
namespace {

// Breaks every spring whose nodes have different labels (the triangles astride a cut drop out).
Surface CutBy(const Lattice& L, const std::function<int(int i, int j)>& label) {
  const BarkParams p = *BarkPreset("pine");
  Surface s = InitialSurface(L, MechanicsOf(p), 1);
  for (int k = 0; k < L.springs(); ++k) {
    const int a = L.a[k], b = L.b[k];
    if (label(a / L.n_h, a % L.n_h) != label(b / L.n_h, b % L.n_h)) {
      s.broken[k] = 1;
      ++s.broken_count[static_cast<int>(L.family(k))];
    }
  }
  return s;
}

TEST(Regions, BlocksCutOnEverySideAreClosedRegions) {
  const Lattice L = BuildLattice(12, 8, 0.33);
  const Surface s = CutBy(L, [](int i, int j) { return (i / 4) * 10 + j / 4; });
  const CrackMeasures m = MeasureCracks(L, s, 1.0, 1.0);
  EXPECT_EQ(m.count, 6);
  EXPECT_EQ(m.strips, 0);
  EXPECT_DOUBLE_EQ(m.closed_fraction, 1.0);
  // The plates are the triangles inside a block: columns 0-3 (3 pitches), rows 0-3 of even and
  // odd columns (z from 0 to 3.5·L_o).
  EXPECT_NEAR(m.mean_width, 3 * L.pitch(), 1e-12);
  EXPECT_NEAR(m.max_width, 3 * L.pitch(), 1e-12);
  EXPECT_NEAR(m.mean_height, 3.5 * 0.33, 1e-12);
  EXPECT_NEAR(m.max_height, 3.5 * 0.33, 1e-12);
  EXPECT_GT(m.broken[0], 0);
  EXPECT_GT(m.broken[1], 0);
}

TEST(Regions, CutsAlongTheTrunkLeaveStrips) {
  const Lattice L = BuildLattice(12, 8, 0.33);
  // Two vertical cuts (between columns 3|4 and 7|8... and the seam 11|0 joins 8-11 to 0-3).
  const Surface s = CutBy(L, [](int i, int) { return i >= 4 && i < 8 ? 1 : 0; });
  const CrackMeasures m = MeasureCracks(L, s, 1.0, 1.0);
  EXPECT_EQ(m.count, 2);
  EXPECT_EQ(m.strips, 2);
  EXPECT_DOUBLE_EQ(m.closed_fraction, 0.0);
  EXPECT_NEAR(m.max_height, L.height(), 1e-12);     // the paper's "(>20)": the whole patch
  EXPECT_NEAR(m.max_width, 7 * L.pitch(), 1e-12);   // columns 8..11 and 0..3, across the seam
  EXPECT_NEAR(m.mean_width, 5 * L.pitch(), 1e-12);  // and 4..7
  EXPECT_EQ(m.broken[0], 0);                        // no axial spring crosses a vertical cut
  EXPECT_DOUBLE_EQ(m.vertical_crack_share, 1.0);
  // Every row crosses 2 cracks: spacing C/2.
  EXPECT_NEAR(m.intercept_width, L.circumference() / 2, 1e-12);
  EXPECT_DOUBLE_EQ(m.intercept_height, 0.0);  // no horizontal crack: over the patch
}

TEST(Regions, AnIntactLayerIsOneRegionWrappingBothWays) {
  const Lattice L = BuildLattice(8, 6, 0.33);
  const Surface s = CutBy(L, [](int, int) { return 0; });
  const CrackMeasures m = MeasureCracks(L, s, 1.02, 1.03);
  ASSERT_EQ(m.regions.size(), 1u);
  EXPECT_TRUE(m.regions[0].wraps_around);
  EXPECT_TRUE(m.regions[0].wraps_along);
  EXPECT_NEAR(m.regions[0].width, L.circumference() * 1.02, 1e-12);
  EXPECT_NEAR(m.regions[0].height, L.height() * 1.03, 1e-12);
  EXPECT_DOUBLE_EQ(m.vertical_crack_share, 0.0);
}

// The crack spacing of the scan lines on the strips above: every line around crosses the two
// vertical cuts (spacing C/2; the cuts' middles 4 and 8 pitches apart), no line along crosses a
// crack (open lines, the paper's "(>20)": spacing H), the lines inside the cut strips are all
// crack and not counted.
TEST(Regions, ScanLinesAroundCrossTheVerticalCuts) {
  const Lattice L = BuildLattice(12, 8, 0.33);
  const Surface s = CutBy(L, [](int i, int) { return i >= 4 && i < 8 ? 1 : 0; });
  const CrackMeasures m = MeasureCracks(L, s, 1.0, 1.0);
  EXPECT_EQ(m.spacing_width.lines, 8);
  EXPECT_EQ(m.spacing_width.open, 0);
  EXPECT_NEAR(m.spacing_width.mean, L.circumference() / 2, 1e-12);
  EXPECT_NEAR(m.spacing_width.max, L.circumference() / 2, 1e-12);
  EXPECT_NEAR(m.spacing_width.gap_mean, L.circumference() / 2, 1e-12);
  EXPECT_NEAR(m.spacing_width.gap_max, 8 * L.pitch(), 1e-12);
  EXPECT_EQ(m.spacing_height.lines, 10);  // strips 3 and 7 (between the cut columns) all crack
  EXPECT_EQ(m.spacing_height.open, 10);
  EXPECT_NEAR(m.spacing_height.mean, L.height(), 1e-12);
  EXPECT_NEAR(m.spacing_height.max, L.height(), 1e-12);
}

// Horizontal cuts every 4 rows: every line along the trunk crosses two (spacing H/2, at the grown
// scale).
TEST(Regions, ScanLinesAlongCrossTheHorizontalCuts) {
  const Lattice L = BuildLattice(12, 8, 0.33);
  const Surface s = CutBy(L, [](int, int j) { return j / 4; });
  const CrackMeasures m = MeasureCracks(L, s, 1.0, 1.5);
  EXPECT_EQ(m.spacing_height.lines, 12);
  EXPECT_EQ(m.spacing_height.open, 0);
  EXPECT_NEAR(m.spacing_height.mean, L.height() * 1.5 / 2, 1e-12);
  EXPECT_NEAR(m.spacing_height.max, L.height() * 1.5 / 2, 1e-12);
  // Around: the four lines between the cuts (rows 1, 2, 5, 6) cross none; the four running along
  // a cut cross its zigzag back and forth.
  EXPECT_EQ(m.spacing_width.lines, 8);
  EXPECT_EQ(m.spacing_width.open, 4);
  EXPECT_NEAR(m.spacing_width.max, L.circumference(), 1e-12);
}

// A wavy band round the trunk whose unwrapped walk climbs further than the patch is tall (a
// triangle wave of 8·L_o on a patch 6·L_o tall) without closing a loop along it: on the torus it
// covers every height, so no region is taller than the patch (before, its height was the walk's).
TEST(Regions, ABandWavingRoundTheTrunkIsNoTallerThanThePatch) {
  const Lattice L = BuildLattice(24, 6, 0.33);
  const Surface s = CutBy(L, [&L](int i, int j) {
    const double wave = 8.0 * 0.33 * (i <= 12 ? i : 24 - i) / 12.0;
    double z = L.z_of(i, j) - wave;
    z -= L.height() * std::floor(z / L.height());
    return z < 3 * 0.33 ? 1 : 0;
  });
  const CrackMeasures m = MeasureCracks(L, s, 1.0, 1.0);
  ASSERT_GE(m.count, 1);
  bool band = false;
  for (const Region& r : m.regions) {
    EXPECT_LE(r.height, L.height() + 1e-12);
    EXPECT_LE(r.width, L.circumference() + 1e-12);
    if (r.wraps_around && !r.wraps_along && r.triangles > 20) {
      band = true;
      EXPECT_NEAR(r.height, L.height(), 1e-12);
    }
  }
  EXPECT_TRUE(band);
  EXPECT_LE(m.max_height, L.height() + 1e-12);
}

// Breaks both diagonals of the nodes (i, j0..j1−1) to the next column: a vertical crack lying in
// the column gap i | i+1 from about row j0 to j1, ending there (no axial spring breaks).
void BreakGap(const Lattice& L, int i, int j0, int j1, Surface* s) {
  for (int j = j0; j < j1; ++j) {
    const int n = L.node(i, j);
    for (int k = 0; k < 2; ++k) {
      const int spring = L.axial_count + 2 * n + k;
      ASSERT_EQ(L.a[spring], n);
      if (!s->broken[spring]) {
        s->broken[spring] = 1;
        ++s->broken_count[1];
      }
    }
  }
}

// Vertical cracks en échelon (each confined to one column gap, ending inside it, as camphor's
// furrows break up on this lattice; docs/bark-model.md choice 10a) lie on the lines along the
// trunk between their columns. The measure before counted each such run as a crossing (two runs
// on line 2: H/2; one on line 6: H); the paper's spacing of the horizontal cracks counts none of
// them: every line along is open. Two horizontal cuts (rows 7|8 and 15|0, axial springs broken)
// are crossed by every line under both measures, the old one adding the vertical runs.
TEST(Regions, VerticalCracksLyingOnALineAlongAreNoHorizontalCrossings) {
  const Lattice L = BuildLattice(12, 16, 0.33);
  const double H = L.height();
  Surface s = CutBy(L, [](int, int) { return 0; });
  BreakGap(L, 2, 2, 6, &s);
  BreakGap(L, 2, 10, 14, &s);
  BreakGap(L, 6, 3, 6, &s);
  CrackMeasures m = MeasureCracks(L, s, 1.0, 1.0);
  ASSERT_EQ(m.broken[0], 0);
  EXPECT_EQ(m.spacing_height.lines, 12);
  EXPECT_EQ(m.spacing_height.open, 12);
  EXPECT_NEAR(m.spacing_height.mean, H, 1e-12);
  EXPECT_NEAR(m.spacing_height.max, H, 1e-12);
  EXPECT_EQ(m.spacing_height_all_runs.lines, 12);
  EXPECT_EQ(m.spacing_height_all_runs.open, 10);
  EXPECT_NEAR(m.spacing_height_all_runs.mean, (10 * H + H / 2 + H) / 12, 1e-12);
  EXPECT_NEAR(m.spacing_height_all_runs.max, H, 1e-12);

  // The same with two horizontal cuts.
  const Surface cut = CutBy(L, [](int, int j) { return j < 8 ? 0 : 1; });
  for (int k = 0; k < L.springs(); ++k) {
    if (cut.broken[k] && !s.broken[k]) {
      s.broken[k] = 1;
      ++s.broken_count[static_cast<int>(L.family(k))];
    }
  }
  m = MeasureCracks(L, s, 1.0, 1.5);
  EXPECT_GT(m.broken[0], 0);
  EXPECT_EQ(m.spacing_height.lines, 12);
  EXPECT_EQ(m.spacing_height.open, 0);
  EXPECT_NEAR(m.spacing_height.mean, 1.5 * H / 2, 1e-12);
  EXPECT_NEAR(m.spacing_height.max, 1.5 * H / 2, 1e-12);
  EXPECT_NEAR(m.spacing_height.gap_max, 1.5 * H / 2, 1e-12);  // the cuts' middles half H apart
  EXPECT_EQ(m.spacing_height_all_runs.open, 0);
  EXPECT_NEAR(m.spacing_height_all_runs.mean, 1.5 * (10 * H / 2 + H / 4 + H / 3) / 12, 1e-12);
}

// A vertical crack that steps sideways across a column breaks an axial spring there: a line along
// between the columns it leaves and enters crosses it (the crack passes from one side of the line
// to the other), so it is a crossing under both measures.
TEST(Regions, AVerticalCrackSteppingAcrossAColumnIsCrossed) {
  const Lattice L = BuildLattice(12, 16, 0.33);
  Surface s = CutBy(L, [](int, int) { return 0; });
  BreakGap(L, 2, 0, 8, &s);   // in gap 2|3 over the lower half
  BreakGap(L, 3, 8, 16, &s);  // in gap 3|4 over the upper half
  for (int j : {7, 15}) {     // joined across column 3 at both ends (the torus along)
    const int axial = L.node(3, j);
    ASSERT_EQ(L.b[axial], L.node(3, (j + 1) % 16));
    s.broken[axial] = 1;
    ++s.broken_count[0];
  }
  const CrackMeasures m = MeasureCracks(L, s, 1.0, 1.0);
  // Lines 2 and 3 each hold one run of the crack with a broken axial edge at its ends.
  EXPECT_EQ(m.spacing_height.lines, 12);
  EXPECT_EQ(m.spacing_height.open, 10);
  EXPECT_EQ(m.spacing_height_all_runs.open, 10);
  EXPECT_NEAR(m.spacing_height.mean, m.spacing_height_all_runs.mean, 1e-12);
  EXPECT_NEAR(m.spacing_height.mean, L.height(), 1e-12);  // one crossing a line: spacing H
}

}  // namespace
}  // namespace niwa::bark
