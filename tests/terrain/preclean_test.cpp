// PreClean (core/terrain/offset.h) over a linked list against its vector twin: the same points
// dropped in the same order (the twin is the vector walk it replaced, whose erase made a dense
// contour quadratic), on random rings with short edges and spikes, and a dense circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "math/det_math.h"
#include "random/pcg32.h"
#include "terrain/offset.h"

namespace niwa::terrain {
namespace {

// The vector walk PreClean had (erase per drop), kept as the twin.
Ring PreCleanVectorTwin(const Ring& ring, double min_len, double min_angle_deg, int* dropped) {
  Ring r = ring;
  const double min_angle = min_angle_deg * 3.14159265358979323846 / 180.0;
  auto sub = [](const Vec2& a, const Vec2& b) { return Vec2{a.x - b.x, a.y - b.y}; };
  auto len = [](const Vec2& a) { return std::sqrt(a.x * a.x + a.y * a.y); };
  for (std::size_t pass = 0; pass < ring.size() && r.size() > 3; ++pass) {
    bool changed = false;
    for (std::size_t i = 0; i < r.size() && r.size() > 3;) {
      const std::size_t n = r.size();
      const Vec2& prev = r[(i + n - 1) % n];
      const Vec2& cur = r[i];
      const Vec2& next = r[(i + 1) % n];
      const Vec2 e1 = sub(cur, prev), e2 = sub(next, cur);
      const double l1 = len(e1), l2 = len(e2);
      bool drop = l2 < min_len && min_len > 0;
      std::size_t victim = (i + 1) % n;
      if (!drop && min_angle > 0 && l1 > 0 && l2 > 0) {
        const double cosang = -(e1.x * e2.x + e1.y * e2.y) / (l1 * l2);
        const double angle = det::Acos(std::clamp(cosang, -1.0, 1.0));
        if (angle < min_angle) {
          drop = true;
          victim = i;
        }
      }
      if (drop) {
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(victim));
        if (dropped) ++*dropped;
        changed = true;
        if (victim < i) --i;
      } else {
        ++i;
      }
    }
    if (!changed) break;
  }
  return r;
}

// Returns the points dropped.
int ExpectSame(const Ring& ring, double min_len, double min_angle, const char* what) {
  int a = 0, b = 0;
  const Ring got = PreClean(ring, min_len, min_angle, &a);
  const Ring want = PreCleanVectorTwin(ring, min_len, min_angle, &b);
  EXPECT_EQ(got.size(), want.size()) << what;
  if (got.size() != want.size()) return a;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].x, want[i].x) << what << " point " << i;
    EXPECT_EQ(got[i].y, want[i].y) << what << " point " << i;
  }
  EXPECT_EQ(a, b) << what;
  return a;
}

TEST(PreClean, EqualsItsVectorTwinOnRandomRings) {
  Pcg32 rng(34);
  int drops = 0;
  auto unit = [&]() { return static_cast<double>(rng.NextU32()) / 4294967296.0; };
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 4 + static_cast<int>(rng.NextU32() % 200);
    Ring ring;
    for (int k = 0; k < n; ++k) {
      // A wobbly circle with bunched points (short edges) and the odd spike in or out.
      const double a = 2 * 3.14159265358979 * (k + 0.9 * unit()) / n;
      double radius = 10 + unit();
      if (rng.NextU32() % 7 == 0) radius *= rng.NextU32() % 2 ? 1.8 : 0.3;
      ring.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    const double min_len = (trial % 4) * 0.25;           // 0 (off) to 0.75 m
    const double min_angle = (trial % 3 == 0) ? 0 : 25;  // off, or 25°
    drops += ExpectSame(ring, min_len, min_angle, "random");
  }
  EXPECT_GT(drops, 1000);  // the rings exercise both rules, not only the walk
}

TEST(PreClean, EqualsItsVectorTwinOnADenseCircle) {
  Ring circle;
  for (int k = 0; k < 20000; ++k) {
    const double a = 2 * 3.14159265358979 * k / 20000;
    circle.push_back({100 * std::cos(a), 100 * std::sin(a)});
  }
  EXPECT_GT(ExpectSame(circle, 2.0, 15, "dense circle"), 19000);  // nearly every point dropped
}

}  // namespace
}  // namespace niwa::terrain
