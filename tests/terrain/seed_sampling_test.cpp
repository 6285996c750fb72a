// ResampleSeed (issue 31, not yet applied by Grow): the seed at a uniform arc length tied to d,
// the same points for the same outline however densely it was given, a jittered copy within its
// jitter, counter-clockwise, straight runs keeping their points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "random/pcg32.h"
#include "terrain/generate.h"
#include "terrain/polygon.h"

namespace niwa::terrain {
namespace {

// Every edge split into `k` equal parts (the same outline, k times the points).
Ring Densified(const Ring& r, int k) {
  Ring out;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Vec2& a = r[i];
    const Vec2& b = r[(i + 1) % r.size()];
    for (int j = 0; j < k; ++j) {
      const double t = static_cast<double>(j) / k;
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  return out;
}

// Every point moved by up to ±amp on each axis (a fixed RNG stream).
Ring Jittered(const Ring& r, double amp) {
  Pcg32 rng(7, 11);
  Ring out;
  for (const Vec2& v : r)
    out.push_back({v.x + rng.Uniform(-amp, amp), v.y + rng.Uniform(-amp, amp)});
  return out;
}

// A straight-edged outline as a user draws it: an L given by its 6 corners.
Ring LSeed() { return {{0, 0}, {400, 0}, {400, 160}, {160, 160}, {160, 300}, {0, 300}}; }

TEST(SeedSampling, ResampleSeedSpacesPointsByAQuarterOfD) {
  const Ring square{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  const Ring r = ResampleSeed(square, square, 20);  // spacing 5 m: 400 m / 5 = 80 points
  EXPECT_EQ(r.size(), 80u);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Vec2& a = r[i];
    const Vec2& b = r[(i + 1) % r.size()];
    EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y), 5.0, 1e-2);
  }
  // The same square given with 16 times the points resamples to the same points.
  EXPECT_EQ(ResampleSeed(Densified(square, 16), square, 20), r);
  // A tiny seed keeps kMinSeedSamples points.
  const Ring tiny{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(ResampleSeed(tiny, tiny, 20).size(), kMinSeedSamples);
}

TEST(SeedSampling, DensifiedAndJitteredCopiesResampleToTheSameOutline) {
  const Ring l = LSeed();
  const Ring r = ResampleSeed(l, l, 20);  // perimeter 1,400 m at 5 m: 280 points
  ASSERT_EQ(r.size(), 280u);
  EXPECT_EQ(ResampleSeed(Densified(l, 4), l, 20), r);
  // Jittered by ±5 cm on each axis: the same count, every point within the jitter's reach (the
  // arc length of the jittered line differs by millimetres over 1,400 m).
  const Ring shaken = Jittered(Densified(l, 4), 0.05);
  const Ring rs = ResampleSeed(shaken, l, 20);
  ASSERT_EQ(rs.size(), r.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    EXPECT_LT(std::hypot(rs[i].x - r[i].x, rs[i].y - r[i].y), 0.2) << "point " << i;
  // Given clockwise, the same points counter-clockwise.
  Ring cw(l.rbegin(), l.rend());
  const Ring rcw = ResampleSeed(cw, l, 20);
  ASSERT_EQ(rcw.size(), r.size());
  EXPECT_GT(TwiceArea(ToGrid(rcw)), 0);
  Ring sorted_a = r, sorted_b = rcw;
  const auto less = [](const Vec2& a, const Vec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::sort(sorted_a.begin(), sorted_a.end(), less);
  std::sort(sorted_b.begin(), sorted_b.end(), less);
  EXPECT_EQ(sorted_a, sorted_b);
}

}  // namespace
}  // namespace niwa::terrain
