// The polygon shrinking algorithm: exact predicates against brute force, the Fig 5 and Fig 7 join
// points, convex offsets against the closed-form area, the Fig 4 split, and robustness.
#include <gtest/gtest.h>

#include <cmath>

#include "random/pcg32.h"
#include "terrain/offset.h"
#include "terrain/polygon.h"
#include "terrain/seeds.h"

namespace niwa::terrain {
namespace {

constexpr double kPi = 3.14159265358979323846;

Ring Square(double x0, double y0, double s) {
  return {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
}

TEST(Polygon, SelfIntersectionsMatchBruteForceOnRandomRings) {
  Pcg32 rng(7, 3);
  int nonsimple = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 3 + static_cast<int>(rng.NextU32() % 20);
    IRing r;
    for (int i = 0; i < n; ++i)
      r.push_back(
          {static_cast<int64_t>(rng.NextU32() % 40), static_cast<int64_t>(rng.NextU32() % 40)});
    EXPECT_EQ(SelfIntersections(r), SelfIntersectionsBruteForce(r)) << "trial " << trial;
    if (!IsSimple(r)) ++nonsimple;
  }
  EXPECT_GT(nonsimple, 100);  // the oracle saw many crossing cases
}

IRing RandomRing(Pcg32* rng, int64_t x0, int64_t span) {
  const int n = 3 + static_cast<int>(rng->NextU32() % 20);
  IRing r;
  for (int i = 0; i < n; ++i)
    r.push_back({x0 + static_cast<int64_t>(rng->NextU32() % static_cast<uint32_t>(span)),
                 static_cast<int64_t>(rng->NextU32() % static_cast<uint32_t>(span))});
  return r;
}

// The nesting checks' pruning (issue 34: children against a large parent, siblings by the
// thousand) gives the answers of the unpruned tests.
TEST(Polygon, EdgeIndexMeetsAsRingsIntersect) {
  Pcg32 rng(11, 5);
  int met = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const IRing big = RandomRing(&rng, 0, 60);
    const EdgeIndex index(big);
    for (int k = 0; k < 4; ++k) {
      const IRing small = RandomRing(&rng, static_cast<int64_t>(rng.NextU32() % 60), 15);
      const bool want = RingsIntersect(small, big);
      EXPECT_EQ(index.Meets(small), want) << "trial " << trial;
      met += want;
    }
  }
  EXPECT_GT(met, 200);  // both answers seen many times
  EXPECT_LT(met, 1100);
}

TEST(Polygon, MeetingBoxPairsAsAllPairs) {
  Pcg32 rng(12, 5);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<IBox> boxes;
    const int n = static_cast<int>(rng.NextU32() % 60);
    for (int i = 0; i < n; ++i) boxes.push_back(BoxOf(RandomRing(&rng, rng.NextU32() % 200, 20)));
    std::vector<std::pair<int, int>> all;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (BoxesMeet(boxes[static_cast<std::size_t>(i)], boxes[static_cast<std::size_t>(j)]))
          all.push_back({i, j});
    EXPECT_EQ(MeetingBoxPairs(boxes), all) << "trial " << trial;
  }
}

// A counted sweep stops past its most, with `stopped`; without a most it only counts.
TEST(Polygon, CountedSweepsStopPastTheirMost) {
  // A comb turned on its side (simple): 400 teeth 990 long in x, so every pair of its long edges
  // overlaps in x and the sweep along x tries them all.
  const int64_t n = 400;
  IRing comb = {{0, 0}, {1000, 0}};
  for (int64_t i = 0; i < n; ++i) {
    comb.push_back({1000, 4 * i + 2});
    if (i + 1 < n) {
      comb.push_back({10, 4 * i + 2});
      comb.push_back({10, 4 * i + 4});
      comb.push_back({1000, 4 * i + 4});
    }
  }
  comb.push_back({0, 4 * (n - 1) + 2});
  ASSERT_TRUE(IsSimple(comb));
  SweepWork counted;
  EXPECT_TRUE(IsSimple(comb, &counted));
  EXPECT_FALSE(counted.stopped);
  EXPECT_GT(counted.tests, kSweepWorkPerTry * 0.4 * n * n);
  SweepWork tight;
  tight.max_tests = 100;
  SelfIntersections(comb, 1 << 30, &tight);
  EXPECT_TRUE(tight.stopped);
  EXPECT_LE(tight.tests, 101.0);
  SweepWork meets;
  meets.max_tests = 10;
  IRing far = comb;  // the same x ranges, 100 km away in y: every pair tried, none meets
  for (IPoint& q : far) q.y += 100000;
  EXPECT_FALSE(EdgeIndex(comb).Meets(far));
  EdgeIndex(comb).Meets(far, &meets);
  EXPECT_TRUE(meets.stopped);
  SweepWork rings;
  rings.max_tests = 10;
  RingsIntersect(comb, far, &rings);
  EXPECT_TRUE(rings.stopped);
}

TEST(Polygon, SimplicityAndInsideOnKnownShapes) {
  EXPECT_TRUE(IsSimple(ToGrid(Square(0, 0, 10))));
  const Ring bowtie{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  EXPECT_FALSE(IsSimple(ToGrid(bowtie)));
  const Ring touching{{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}};  // repeated vertex
  EXPECT_FALSE(IsSimple(ToGrid(touching)));
  EXPECT_TRUE(Inside(ToGrid(Square(0, 0, 10)), ToGrid(Vec2{5, 5})));
  EXPECT_FALSE(Inside(ToGrid(Square(0, 0, 10)), ToGrid(Vec2{10, 5})));  // on the boundary
  EXPECT_FALSE(Inside(ToGrid(Square(0, 0, 10)), ToGrid(Vec2{11, 5})));
}

// Fig 7: P = V + min(c·d, d/cos(ψ/2))·b. An edge along +x into V = 0 turning right by ψ.
Vec2 JoinPointAt(double psi_deg, double d, double c) {
  double s, co;
  const double psi = psi_deg * kPi / 180;
  s = std::sin(-psi);
  co = std::cos(-psi);
  const Vec2 n1{0, 1};    // left normal of +x
  const Vec2 n2{-s, co};  // left normal of (cos −ψ, sin −ψ)
  return CappedJoinPoint({0, 0}, n1, n2, d, c);
}

TEST(Joins, Fig7CapAndMiterPoints) {
  const double d = 1;
  // ψ = 60°: the miter point d/cos 30° = 1.1547d is nearer than 1.4d, so it is kept.
  Vec2 p = JoinPointAt(60, d, 1.4);
  EXPECT_NEAR(std::hypot(p.x, p.y), d / std::cos(kPi / 6), 1e-12);
  EXPECT_NEAR(p.x, d * std::tan(kPi / 6), 1e-12);  // (d·tan(ψ/2), d)
  EXPECT_NEAR(p.y, d, 1e-12);
  // ψ = 120°: the miter lies at 2d, capped at 1.4d on the bisector.
  p = JoinPointAt(120, d, 1.4);
  EXPECT_NEAR(std::hypot(p.x, p.y), 1.4 * d, 1e-12);
  // ψ = 90°: miter at d·√2 (Fig 5a); c = 1 puts P on the arc at distance d (Fig 5c).
  p = JoinPointAt(90, d, kMiterLimit);
  EXPECT_NEAR(std::hypot(p.x, p.y), d * std::sqrt(2.0), 1e-12);
  p = JoinPointAt(90, d, 1.0);
  EXPECT_NEAR(std::hypot(p.x, p.y), d, 1e-12);
}

TEST(Shrink, ConvexSquareGivesTheExactInsetSquare) {
  ShrinkCounts counts;
  for (Join join : {Join::kMiter, Join::kBevel, Join::kRound, Join::kCapped}) {
    ShrinkOptions o;
    o.d = 10;
    o.join = join;
    std::vector<Ring> out = Shrink(Square(0, 0, 100), o, &counts);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(Area(out[0]), 80.0 * 80.0, 1e-6);  // A' = A − P·d + d²·Σcot(β/2) = 6400
    EXPECT_NEAR(Perimeter(out[0]), 320.0, 1e-6);
  }
}

// The L shape has one reflex vertex: the joins differ there and only there (Fig 5).
TEST(Shrink, LShapeJoinsOrderTheirAreas) {
  const Ring l{{0, 0}, {100, 0}, {100, 40}, {40, 40}, {40, 100}, {0, 100}};
  double area[4];
  for (int j = 0; j < 4; ++j) {
    ShrinkOptions o;
    o.d = 10;
    o.join = static_cast<Join>(j);
    o.c = 1.4;
    ShrinkCounts counts;
    std::vector<Ring> out = Shrink(l, o, &counts);
    ASSERT_EQ(out.size(), 1u) << j;
    EXPECT_TRUE(IsSimple(ToGrid(out[0])));
    area[j] = Area(out[0]);
  }
  // Gap filled least by the miter (the corner stays sharp), most by the bevel.
  EXPECT_LT(area[static_cast<int>(Join::kMiter)], area[static_cast<int>(Join::kCapped)]);
  EXPECT_LT(area[static_cast<int>(Join::kCapped)], area[static_cast<int>(Join::kRound)]);
  EXPECT_LT(area[static_cast<int>(Join::kRound)], area[static_cast<int>(Join::kBevel)]);
  // Miter: the inset L (10, 10), (90, 10), (90, 30), (30, 30), (30, 90), (10, 90).
  const double miter_exact = 80.0 * 20.0 + 20.0 * 60.0;
  EXPECT_NEAR(area[static_cast<int>(Join::kMiter)], miter_exact, 1e-6);
}

TEST(Shrink, Fig4DumbbellNeckSplitsIntoTwoIslands) {
  Result<Ring> seed = BuiltinSeed("dumbbell");
  ASSERT_TRUE(seed.ok());
  ShrinkOptions o;
  o.d = 20;
  o.join = Join::kMiter;  // the miter wedges at the neck's four corners leave the exact squares
  ShrinkCounts counts;
  std::vector<Ring> out = Shrink(*seed, o, &counts);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(Area(out[0]), 160.0 * 160.0, 1e-6);
  EXPECT_NEAR(Area(out[1]), 160.0 * 160.0, 1e-6);
}

TEST(Shrink, CircleShrinksToOneSmallerCircleThenVanishes) {
  Ring circle;
  for (int i = 0; i < 512; ++i)
    circle.push_back({15 * std::cos(2 * kPi * i / 512), 15 * std::sin(2 * kPi * i / 512)});
  ShrinkOptions o;
  o.d = 10;
  ShrinkCounts counts;
  std::vector<Ring> out = Shrink(circle, o, &counts);
  ASSERT_EQ(out.size(), 1u);
  double rmin = 1e9, rmax = 0;
  for (const Vec2& v : out[0]) {
    rmin = std::min(rmin, std::hypot(v.x, v.y));
    rmax = std::max(rmax, std::hypot(v.x, v.y));
  }
  EXPECT_NEAR(rmin, 5.0, 0.05);
  EXPECT_NEAR(rmax, 5.0, 0.05);
  o.d = 16;
  EXPECT_TRUE(Shrink(circle, o, &counts).empty());
}

TEST(Shrink, OutwardGrowthEnlarges) {
  ShrinkOptions o;
  o.d = 10;
  o.outward = true;
  o.join = Join::kMiter;
  ShrinkCounts counts;
  std::vector<Ring> out = Shrink(Square(0, 0, 100), o, &counts);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(Area(out[0]), 120.0 * 120.0, 1e-6);
}

TEST(Shrink, RandomStarsNeverGiveANonSimpleRing) {
  Pcg32 rng(11, 5);
  int rings = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Ring star;
    const int n = 8 + static_cast<int>(rng.NextU32() % 60);
    for (int i = 0; i < n; ++i) {
      const double r = rng.Uniform(20, 100);
      star.push_back({r * std::cos(2 * kPi * i / n), r * std::sin(2 * kPi * i / n)});
    }
    for (double d : {1.0, 5.0, 12.0}) {
      for (int j = 0; j < 4; ++j) {
        ShrinkOptions o;
        o.d = d;
        o.join = static_cast<Join>(j);
        ShrinkCounts counts;
        for (const Ring& q : Shrink(star, o, &counts)) {
          ++rings;
          EXPECT_TRUE(IsSimple(ToGrid(q))) << trial;
          EXPECT_GT(Area(q), 0);
          // Round join = the exact erosion: every vertex at least d inside (arc sagitta 1 %).
        }
        // The raw path's faces equal the exact swept-piece twin's (same rings, same area).
        ShrinkOptions exact = o;
        exact.swept = true;
        std::vector<Ring> a = Shrink(star, o, &counts), b = Shrink(star, exact, &counts);
        ASSERT_EQ(a.size(), b.size()) << trial << " d " << d << " join " << j;
        double area_a = 0, area_b = 0;
        for (const Ring& q : a) area_a += Area(q);
        for (const Ring& q : b) area_b += Area(q);
        // Crossings rounded onto the 1/1024 m grid move the area by at most ~perimeter/1024.
        EXPECT_NEAR(area_a, area_b, 2 * Perimeter(star) / kGridPerMetre)
            << trial << " d " << d << " join " << j;
        if (o.join == Join::kRound) {
          for (const Ring& q : b)
            for (const Vec2& v : q) EXPECT_GT(RingDistance(star, v), d * (1 - 0.01) - 2e-3);
        }
      }
    }
  }
  EXPECT_GT(rings, 300);
}

}  // namespace
}  // namespace niwa::terrain
