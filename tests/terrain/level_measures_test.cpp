// The per-level measures of --stats (level_measures.h): the divider length of a square and of a
// circle, a smooth line's dimension near 1 and a Koch curve's near log 4 / log 3, and on the disk
// grown by the simple method (concentric circles d apart) the area ratios ((r − d)/r)², round
// rings, and one entry per level in --stats' per_level.
#include "terrain/level_measures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "terrain/generate.h"
#include "terrain/seeds.h"

namespace niwa::terrain {
namespace {

Ring Circle(int n, double r) {
  Ring out;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    out.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return out;
}

// A Koch snowflake after `depth` refinements of a triangle of side `side` (counter-clockwise,
// bumps outward).
Ring Koch(int depth, double side) {
  Ring r = {{0, 0}, {side, 0}, {side / 2, side * std::sqrt(3.0) / 2}};
  for (int d = 0; d < depth; ++d) {
    Ring next;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec2 a = r[i], b = r[(i + 1) % r.size()];
      const Vec2 e{(b.x - a.x) / 3, (b.y - a.y) / 3};
      const Vec2 p{a.x + e.x, a.y + e.y}, q{a.x + 2 * e.x, a.y + 2 * e.y};
      // The bump on the outer (right-hand) side of a counter-clockwise edge.
      const Vec2 tip{p.x + e.x / 2 + e.y * std::sqrt(3.0) / 2,
                     p.y + e.y / 2 - e.x * std::sqrt(3.0) / 2};
      next.insert(next.end(), {a, p, tip, q});
    }
    r = next;
  }
  return r;
}

TEST(LevelMeasures, DividerLengthOfASquareAndACircle) {
  const Ring square = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  EXPECT_NEAR(DividerLength(square, 10), 400, 1e-9);
  EXPECT_NEAR(DividerLength(square, 25), 400, 1e-9);
  // s = 30: three steps along each side then across each corner; under the perimeter.
  const double l30 = DividerLength(square, 30);
  EXPECT_LT(l30, 400);
  EXPECT_GT(l30, 360);
  // A circle of radius 100 walked with chords of 10: the chord polygon's length, within a chord.
  const double lc = DividerLength(Circle(2048, 100), 10);
  EXPECT_NEAR(lc, 2 * M_PI * 100, 10);
  EXPECT_LT(lc, 2 * M_PI * 100);
}

TEST(LevelMeasures, DimensionOfASmoothRingAndOfAKochCurve) {
  Terrain t;
  t.d0 = 1;
  ContourNode c;
  c.ring = Circle(4096, 1000);
  t.contours.push_back(c);
  const std::vector<LevelMeasures> smooth = ComputeLevelMeasures(t);
  ASSERT_EQ(smooth.size(), 1u);
  EXPECT_NEAR(smooth[0].fractal_dimension, 1.0, 0.01);
  EXPECT_NEAR(smooth[0].compactness, 1.0, 1e-3);
  EXPECT_TRUE(std::isnan(smooth[0].area_ratio));
  // Koch: side 3^7 m refined 6 times (edges of 3 m); steps from 2·d0 = 3 m to P/8.
  t.d0 = 1.5;
  t.contours[0].ring = Koch(6, 2187);
  const std::vector<LevelMeasures> koch = ComputeLevelMeasures(t);
  EXPECT_NEAR(koch[0].fractal_dimension, std::log(4.0) / std::log(3.0), 0.08);
}

TEST(LevelMeasures, DiskGrownBySimpleShrinksBySquares) {
  Result<Ring> seed = BuiltinSeed("disk");  // r = 200 m; d = 20 m
  ASSERT_TRUE(seed.ok());
  TerrainParams p;
  ASSERT_TRUE(ApplyPreset("simple", &p).ok());
  ASSERT_TRUE(p.Set(TerrainParam::kD, 20).ok());
  Result<Terrain> t = Grow(*seed, p, 1);
  ASSERT_TRUE(t.ok());
  const std::vector<LevelMeasures> m = ComputeLevelMeasures(*t);
  ASSERT_GE(m.size(), 8u);
  for (std::size_t k = 0; k < m.size(); ++k) {
    EXPECT_EQ(m[k].level, static_cast<int>(k));
    EXPECT_EQ(m[k].rings, 1);
    EXPECT_NEAR(m[k].compactness, 1.0, 0.01) << k;
    EXPECT_GE(m[k].long_edge_share, 0.0);
    EXPECT_LE(m[k].long_edge_share, 1.0);
    if (k == 0 || k + 2 >= m.size()) continue;  // the last rings are a few grid cells across
    const double kd = static_cast<double>(k);
    const double r = 200 - 20 * kd, below = 200 - 20 * (kd - 1);
    EXPECT_NEAR(m[k].area_ratio, (r / below) * (r / below), 0.02) << k;
  }
}

}  // namespace
}  // namespace niwa::terrain
