// The traced shrinking algorithm behind Figs 2-8 and 12: each figure's measured effect on a small
// contour (naive gaps and crossings, the raw path's crossings removed, islands, corners, joins,
// the Fig 8 pre-clean, midpoint displacement bounded by d'', Fig 14's phase randomisation of the
// kept rings) and its bad input.
#include "terrain/shrink_trace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "terrain/polygon.h"
#include "terrain/seeds.h"

namespace niwa::terrain {
namespace {

// An L: five convex corners and one valley (reflex) corner, 100 m arms 40 m wide.
Ring LShape() { return {{0, 0}, {100, 0}, {100, 40}, {40, 40}, {40, 100}, {0, 100}}; }

Ring Ellipse(double a, double b, int n) {
  Ring r;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * 3.14159265358979323846 * k / n;
    r.push_back(
        {std::round(a * std::cos(t) * 1024) / 1024, std::round(b * std::sin(t) * 1024) / 1024});
  }
  return r;
}

ShrinkTraceOptions Options(double d, Join join, int steps) {
  ShrinkTraceOptions o;
  o.shrink.d = d;
  o.shrink.join = join;
  o.steps = steps;
  return o;
}

TEST(ShrinkTrace, Fig2NaiveOffsetsGapAtTheValleyCrossAtRidges) {
  Result<ShrinkTrace> t = TraceShrink(LShape(), Options(5, Join::kCapped, 1));
  ASSERT_TRUE(t.ok()) << t.status().message();
  const ShrinkTraceStep& s = t->steps[0];
  EXPECT_EQ(s.convex, 5);
  EXPECT_EQ(s.reflex, 1);
  EXPECT_EQ(s.gaps, 1);       // the valley: its two moved edges part
  EXPECT_EQ(s.crossings, 5);  // every ridge: its two moved edges overlap and cross
  // A ridge on edges shorter than d: the moved edges no longer reach each other.
  const Ring notch = {{0, 0}, {100, 0}, {100, 100}, {52, 100}, {50, 103}, {48, 100}, {0, 100}};
  Result<ShrinkTrace> n = TraceShrink(notch, Options(10, Join::kCapped, 1));
  ASSERT_TRUE(n.ok());
  EXPECT_LT(n->steps[0].crossings, n->steps[0].convex);
}

TEST(ShrinkTrace, Fig6RawPathCrossesItselfAndTheKeptRingsDoNot) {
  Result<Ring> seed = BuiltinSeed("lobes7");
  ASSERT_TRUE(seed.ok());
  Result<ShrinkTrace> t = TraceShrink(*seed, Options(40, Join::kCapped, 1));
  ASSERT_TRUE(t.ok());
  const ShrinkTraceStep& s = t->steps[0];
  EXPECT_GT(s.raw_self_intersections, 100);  // the overshoots of Fig 6(b) at the lobes' ridges
  ASSERT_EQ(s.rings.size(), 1u);
  EXPECT_TRUE(IsSimple(ToGrid(s.rings[0])));
  // Every kept vertex is at least d from the contour (joins and cuts lie farther), and some at d.
  double nearest = 1e9;
  for (const Vec2& p : s.rings[0]) {
    const double a = RingDistance(s.input[0], p);
    EXPECT_GE(a, 40 - 0.01);
    nearest = std::min(nearest, a);
  }
  EXPECT_NEAR(nearest, 40, 0.01);
}

TEST(ShrinkTrace, Fig3RepeatedShrinksOfASmoothEllipseMakeCorners) {
  const Ring e = Ellipse(120, 50, 96);
  EXPECT_GT(MinInteriorAngleDeg(Normalise(e)), 170);
  Result<ShrinkTrace> t = TraceShrink(e, Options(10, Join::kCapped, 3));
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t->steps.size(), 3u);
  // The ends' curvature radius is b²/a ≈ 21 m: shrinking past it leaves a sharp corner.
  EXPECT_LT(t->steps[2].min_angle_deg, 150);
  EXPECT_LT(t->steps[2].min_angle_deg, t->steps[0].min_angle_deg);
}

TEST(ShrinkTrace, Fig4ANarrowNeckSplitsIntoIslands) {
  Result<Ring> seed = BuiltinSeed("dumbbell");
  ASSERT_TRUE(seed.ok());
  Result<ShrinkTrace> t = TraceShrink(*seed, Options(5, Join::kCapped, 12));
  ASSERT_TRUE(t.ok());
  std::size_t most = 0;
  for (const ShrinkTraceStep& s : t->steps) most = std::max(most, s.rings.size());
  EXPECT_EQ(t->steps[0].rings.size(), 1u);
  EXPECT_EQ(most, 2u);
}

TEST(ShrinkTrace, Fig5JoinsDifferAtTheValley) {
  int points[4];
  for (int j = 0; j < 4; ++j) {
    Result<ShrinkTrace> t = TraceShrink(LShape(), Options(10, static_cast<Join>(j), 1));
    ASSERT_TRUE(t.ok());
    ASSERT_EQ(t->steps[0].rings.size(), 1u);
    points[j] = t->steps[0].points;
  }
  // Round (5c) replaces the valley by an arc of many points; miter (5a) by one point; bevel (5b)
  // and the Fig 7 cap by two.
  EXPECT_GT(points[static_cast<int>(Join::kRound)], points[static_cast<int>(Join::kBevel)] + 2);
  EXPECT_EQ(points[static_cast<int>(Join::kMiter)], 6);
  EXPECT_EQ(points[static_cast<int>(Join::kBevel)], 7);
}

TEST(ShrinkTrace, Fig12DisplacementIsBoundedByD2) {
  ShrinkTraceOptions o = Options(5, Join::kCapped, 0);
  o.displace = true;
  o.d0 = 5;
  o.d2 = 3;
  o.theta_max_deg = 30;
  Result<ShrinkTrace> t = TraceShrink(LShape(), o);
  ASSERT_TRUE(t.ok()) << t.status().message();
  EXPECT_TRUE(t->steps.empty());
  EXPECT_GT(t->displaced.size(), 40u);  // edges of 40-100 m split down to < 10 m
  EXPECT_GT(t->max_displacement, 0.5);
  EXPECT_LE(t->max_displacement, 3 * 6 + 0.01);  // each of ≤ 6 halvings moves a point ≤ d''
}

// Fig 14 as the paper shows it: the simple method's contours, each phase-randomised on its own.
// Nothing is fed back (the kept rings are those of the trace without it, point for point), the
// closure holds, and a lower f0 (more frequencies shaken) moves the contours farther.
TEST(ShrinkTrace, Fig14RandomisesEachKeptRingWithoutFeedingItBack) {
  Result<Ring> seed = BuiltinSeed("jacksboro");
  ASSERT_TRUE(seed.ok());
  ShrinkTraceOptions plain = Options(70, Join::kCapped, 4);
  Result<ShrinkTrace> base = TraceShrink(*seed, plain);
  ASSERT_TRUE(base.ok()) << base.status().message();
  double shift[2] = {0, 0};
  const int f0s[2] = {64, 256};
  for (int k = 0; k < 2; ++k) {
    ShrinkTraceOptions o = plain;
    o.fourier = true;
    o.fd_f0 = f0s[k];
    Result<ShrinkTrace> t = TraceShrink(*seed, o);
    ASSERT_TRUE(t.ok()) << t.status().message();
    ASSERT_EQ(t->steps.size(), base->steps.size());
    for (std::size_t s = 0; s < t->steps.size(); ++s) {
      const ShrinkTraceStep& a = t->steps[s];
      const ShrinkTraceStep& b = base->steps[s];
      ASSERT_EQ(a.rings.size(), b.rings.size());
      for (std::size_t r = 0; r < a.rings.size(); ++r) {
        ASSERT_EQ(a.rings[r].size(), b.rings[r].size());
        for (std::size_t i = 0; i < a.rings[r].size(); ++i) {
          EXPECT_EQ(a.rings[r][i].x, b.rings[r][i].x);
          EXPECT_EQ(a.rings[r][i].y, b.rings[r][i].y);
        }
      }
      ASSERT_EQ(a.fourier.size(), a.rings.size());
      for (const Ring& z : a.fourier) EXPECT_EQ(z.size(), 1024u);  // n samples, closed by c(0)
      EXPECT_GT(a.fourier_max_shift, 0);
      shift[k] = std::max(shift[k], a.fourier_max_shift);
    }
    EXPECT_TRUE(base->steps[0].fourier.empty());
  }
  EXPECT_GT(shift[0], 2 * shift[1]) << "f0 64: " << shift[0] << " m, f0 256: " << shift[1] << " m";
  EXPECT_LT(shift[0], 70) << "a shake of the high frequencies stays within d of the ring";
}

TEST(ShrinkTrace, BadInputNamesTheField) {
  EXPECT_EQ(TraceShrink(LShape(), Options(0, Join::kCapped, 1)).status().field(), "d");
  EXPECT_EQ(TraceShrink(LShape(), Options(5, Join::kCapped, 65)).status().field(), "steps");
  ShrinkTraceOptions c = Options(5, Join::kCapped, 1);
  c.shrink.c = 0.5;
  EXPECT_EQ(TraceShrink(LShape(), c).status().field(), "c");
  const Ring bowtie = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  EXPECT_EQ(TraceShrink(bowtie, Options(1, Join::kCapped, 1)).status().field(), "contour");
  ShrinkTraceOptions f = Options(5, Join::kCapped, 1);
  f.fourier = true;
  f.fd_f0 = 513;  // above n / 2
  EXPECT_EQ(TraceShrink(LShape(), f).status().field(), "fd_f0");
  f.fd_f0 = 64;
  f.fd_n = 8;
  EXPECT_EQ(TraceShrink(LShape(), f).status().field(), "fd_n");
}

TEST(ShrinkTrace, SvgDrawsEveryLayer) {
  Result<ShrinkTrace> t = TraceShrink(LShape(), Options(10, Join::kCapped, 1));
  ASSERT_TRUE(t.ok());
  const std::string svg = ShrinkTraceToSvg(*t);
  EXPECT_NE(svg.find("class=\"seed\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"naive\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"raw\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"ring\""), std::string::npos);
}

}  // namespace
}  // namespace niwa::terrain
