// The contour generation methods: the cone of the disk seed, the Fig 4 split, the valleys seed's
// valleys up the mountain, Fig 18's loop sequence, the Fourier invariants, and no self-intersection
// or nesting violation for every built-in seed × method; bad seeds and parameters give one line
// naming the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "terrain/fourier.h"
#include "terrain/generate.h"
#include "terrain/heightfield.h"
#include "terrain/loops.h"
#include "terrain/polygon.h"
#include "terrain/seeds.h"

namespace niwa::terrain {
namespace {

using P = TerrainParam;

TerrainParams For(const std::string& method) {
  TerrainParams p;
  EXPECT_TRUE(ApplyPreset(method, &p).ok());
  return p;
}

TEST(Grow, DiskSeedGivesAConeWithTheSimpleMethod) {
  Result<Ring> seed = BuiltinSeed("disk");
  ASSERT_TRUE(seed.ok());
  TerrainParams p = For("simple");
  Result<Terrain> t = Grow(*seed, p, kDefaultTerrainSeed);
  ASSERT_TRUE(t.ok()) << t.status().Line();
  EXPECT_EQ(t->summits.size(), 1u);
  // Summit = h0 + Δh·R/d = 10·200/20 = 100 m (the 256-gon's inscribed radius is 199.985 m).
  EXPECT_NEAR(t->summits[0].elevation, 100.0, 0.5);
  Heightfield hf = BuildHeightfield(*t, 128);
  TerrainStats s = ComputeStats(*t, &hf);
  EXPECT_NEAR(s.hypsometric_integral, 1.0 / 3.0, 0.02);
  EXPECT_EQ(s.self_intersections, 0);
  EXPECT_EQ(s.nesting_violations, 0);
  EXPECT_EQ(s.pits, 0);
  EXPECT_EQ(s.peaks, 1);
  EXPECT_NEAR(s.mean_slope_deg, std::atan(10.0 / 20.0) * 180 / 3.14159265358979, 1.5);
}

TEST(Grow, DumbbellSplitsIntoTwoPeaksEachGrownOn) {
  Result<Ring> seed = BuiltinSeed("dumbbell");
  ASSERT_TRUE(seed.ok());
  Result<Terrain> t = Grow(*seed, For("simple"), kDefaultTerrainSeed);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t->contours[0].children.size(), 2u);
  TerrainStats s = ComputeStats(*t, nullptr);
  EXPECT_EQ(s.peaks, 2);
  EXPECT_EQ(s.splits, 1);
  for (int c : t->contours[0].children)
    EXPECT_FALSE(t->contours[static_cast<std::size_t>(c)].children.empty());
}

// The outermost distance from the origin at which a ring of `rings` crosses the ray at angle phi
// (0 when none does).
double OutermostAlong(const std::vector<const Ring*>& rings, double phi) {
  const double ux = std::cos(phi), uy = std::sin(phi);
  double best = 0;
  for (const Ring* ring : rings) {
    const std::size_t n = ring->size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = (*ring)[i], b = (*ring)[(i + 1) % n];
      // a + s·(b − a) = t·u with s in [0, 1], t > 0.
      const double ex = b.x - a.x, ey = b.y - a.y;
      const double den = ex * uy - ey * ux;
      if (den == 0) continue;
      const double s = (a.y * ux - a.x * uy) / den;
      if (s < 0 || s > 1) continue;
      const double t = (a.x + s * ex) * ux + (a.y + s * ey) * uy;
      if (t > 0) best = std::max(best, t);
    }
  }
  return best;
}

// Valleys cut into the outline of a level's contours: the outline's distance from the origin,
// R(φ), at 1440 angles; a valley floor is a sample that is the lowest within ±5° and lies at least
// `depth` below the highest outline within 10° on each side.
int ValleysAtLevel(const Terrain& t, int level, double depth) {
  std::vector<const Ring*> rings;
  for (const ContourNode& c : t.contours)
    if (c.level == level) rings.push_back(&c.ring);
  if (rings.empty()) return 0;
  constexpr int kM = 1440, kFloor = kM / 72, kSide = kM / 36;
  std::vector<double> r(kM);
  for (int i = 0; i < kM; ++i) r[i] = OutermostAlong(rings, 2 * 3.14159265358979323846 * i / kM);
  const auto at = [&](int i) { return r[static_cast<std::size_t>(((i % kM) + kM) % kM)]; };
  int valleys = 0;
  for (int i = 0; i < kM; ++i) {
    if (r[i] <= 0) continue;
    bool lowest = true;
    for (int k = 1; k <= kFloor && lowest; ++k)
      lowest = r[i] < at(i - k) && r[i] <= at(i + k);  // ties: the first sample counts
    if (!lowest) continue;
    double left = 0, right = 0;
    for (int k = 1; k <= kSide; ++k) {
      left = std::max(left, at(i - k));
      right = std::max(right, at(i + k));
    }
    if (r[i] + depth <= left && r[i] + depth <= right) ++valleys;
  }
  return valleys;
}

// The "many valleys" seed: 18 valleys (seeds.cpp's table) cut its outline, and they run up the
// mountain: levels above the seed still have many valleys cut at least d deep, with the pure shrink
// and with the improved method's perturbations; lobes7, for scale, has seven.
TEST(Grow, ValleysSeedKeepsManyValleysUpTheMountain) {
  Result<Ring> seed = BuiltinSeed("valleys");
  ASSERT_TRUE(seed.ok());
  EXPECT_TRUE(IsSimple(ToGrid(*seed)));
  EXPECT_GT(Area(*seed), 0);
  const double d = 20;
  TerrainParams simple = For("simple"), improved = For("improved");
  ASSERT_TRUE(simple.Set(P::kD, d).ok());
  ASSERT_TRUE(improved.Set(P::kD, d).ok());
  Result<Terrain> a = Grow(*seed, simple, kDefaultTerrainSeed),
                  b = Grow(*seed, improved, kDefaultTerrainSeed);
  Result<Terrain> lobes = Grow(*BuiltinSeed("lobes7"), simple, kDefaultTerrainSeed);
  ASSERT_TRUE(a.ok() && b.ok() && lobes.ok());
  EXPECT_EQ(ValleysAtLevel(*a, 0, d), 18);
  EXPECT_EQ(ValleysAtLevel(*lobes, 0, d), 7);
  std::printf("valleys per level (valleys simple / improved, lobes7 simple):");
  for (int level = 0; level <= 8; ++level) {
    std::printf(" %d: %d / %d, %d", level, ValleysAtLevel(*a, level, d),
                ValleysAtLevel(*b, level, d), ValleysAtLevel(*lobes, level, d));
  }
  std::printf("\n");
  // Measured on 2026-12-02: simple 18 18 18 11 6 4 0, improved 18 18 14 4 1 0 (the Fig 7 join
  // incises the V floors by up to c·d a level, so the valleys cut the massif into several peaks by
  // level 7); lobes7's seven smooth valleys fail the 10° test from level 2 on.
  EXPECT_GE(ValleysAtLevel(*a, 1, d), 16);
  EXPECT_GE(ValleysAtLevel(*a, 2, d), 16);
  EXPECT_GE(ValleysAtLevel(*a, 3, d), 8);
  EXPECT_GE(ValleysAtLevel(*b, 1, d), 16);
  EXPECT_GE(ValleysAtLevel(*b, 2, d), 10);
  EXPECT_GE(ComputeStats(*b, nullptr).peaks, 3);  // the valleys split the massif
  // Loop removal keeps the body: a perturbation that pinches a valley shut once made §4.4's cut
  // delete the large side (improved, seed 3: level 1 kept 6 of the seed's 496 points, 2 levels in
  // all); the first level keeps most of the seed's area and the massif grows on, for every seed.
  for (int rng_seed = 1; rng_seed <= 5; ++rng_seed) {
    Result<Terrain> t = Grow(*seed, improved, static_cast<uint64_t>(rng_seed));
    ASSERT_TRUE(t.ok());
    double level1 = 0;
    for (const ContourNode& c : t->contours)
      if (c.level == 1) level1 += Area(c.ring);
    EXPECT_GE(level1, 0.5 * Area(*seed)) << "seed " << rng_seed;
    EXPECT_GE(ComputeStats(*t, nullptr).levels, 6) << "seed " << rng_seed;
  }
}

TEST(Grow, NoSelfIntersectionOrNestingViolationForEverySeedAndMethod) {
  int sliver_seen = 0;
  for (const SeedInfo& info : BuiltinSeeds()) {
    Result<Ring> seed = BuiltinSeed(info.name);
    ASSERT_TRUE(seed.ok());
    for (const char* method : {"simple", "midpoint", "fourier", "improved"}) {
      for (uint64_t rng_seed : {1, 7}) {
        TerrainParams p = For(method);
        ASSERT_TRUE(p.Set(P::kD, info.d).ok());
        Result<Terrain> t = Grow(*seed, p, rng_seed);
        ASSERT_TRUE(t.ok()) << info.name << " " << method << ": " << t.status().Line();
        TerrainStats s = ComputeStats(*t, nullptr);
        EXPECT_EQ(s.self_intersections, 0) << info.name << " " << method;
        EXPECT_EQ(s.nesting_violations, 0) << info.name << " " << method;
        EXPECT_GE(s.levels, 2) << info.name << " " << method;
        EXPECT_FALSE(t->counts.truncated);
        // No sliver kept as a contour (issue 31: jacksboro's improved grow kept rings of
        // 2.3e-5 and 0.06 m² at d = 70 as peaks); every summit inside its top contour.
        for (std::size_t i = 1; i < t->contours.size(); ++i)
          EXPECT_GE(std::fabs(Area(t->contours[i].ring)), kSliverAreaShare * info.d * info.d)
              << info.name << " " << method << " contour " << i;
        for (const Summit& sm : t->summits)
          EXPECT_TRUE(
              InsideDouble(t->contours[static_cast<std::size_t>(sm.contour)].ring, sm.position))
              << info.name << " " << method << " summit of contour " << sm.contour;
        sliver_seen += t->counts.slivers_dropped;
        // Same input, same contours.
        Result<Terrain> again = Grow(*seed, p, rng_seed);
        ASSERT_TRUE(again.ok());
        ASSERT_EQ(again->contours.size(), t->contours.size());
        for (std::size_t i = 0; i < t->contours.size(); ++i)
          EXPECT_EQ(again->contours[i].ring, t->contours[i].ring);
      }
    }
  }
  EXPECT_GT(sliver_seen, 0);  // the floor met slivers (it is not idle on these seeds)
}

TEST(Grow, HeightfieldLevelSetsLieOnTheirContours) {
  Result<Ring> seed = BuiltinSeed("lobes7");
  ASSERT_TRUE(seed.ok());
  Result<Terrain> t = Grow(*seed, For("improved"), kDefaultTerrainSeed);
  ASSERT_TRUE(t.ok());
  Heightfield hf = BuildHeightfield(*t, 96);
  int checked = 0;
  for (int j = 0; j < hf.height; ++j)
    for (int i = 0; i < hf.width; ++i) {
      const int b = hf.band[static_cast<std::size_t>(j) * hf.width + i];
      if (b < 0) continue;
      const ContourNode& c = t->contours[static_cast<std::size_t>(b)];
      double top = c.elevation + t->dh;
      for (const Summit& s : t->summits)
        if (s.contour == b) top = s.elevation;
      // Inside contour C and outside its children: between h_C and the next level.
      EXPECT_GE(hf.At(i, j), c.elevation - 1e-9);
      EXPECT_LE(hf.At(i, j), top + 1e-9);
      ++checked;
    }
  EXPECT_GT(checked, 1000);
  EXPECT_EQ(ComputeStats(*t, &hf).pits, 0);
}

// Fig 18: …1-2-3-④-⑤-6-7-8-⑤-9-④-10-11-12-13-⑭-15-16-⑭-17… -> …1-2-3-④-10-11-12-13-⑭-17…
std::vector<SeqItem> Fig18() {
  std::vector<SeqItem> s;
  for (int id : {1, 2, 3}) s.push_back({-1, id});
  s.push_back({4, 4});
  s.push_back({5, 5});
  for (int id : {6, 7, 8}) s.push_back({-1, id});
  s.push_back({5, 5});
  s.push_back({-1, 9});
  s.push_back({4, 4});
  for (int id : {10, 11, 12, 13}) s.push_back({-1, id});
  s.push_back({14, 14});
  for (int id : {15, 16}) s.push_back({-1, id});
  s.push_back({14, 14});
  s.push_back({-1, 17});
  return s;
}

// The ids of a closed sequence, rotated to start at id 1 (the walk's start is its own choice).
std::vector<int> Ids(const std::vector<SeqItem>& s) {
  std::vector<int> out;
  for (const SeqItem& it : s) out.push_back(it.id);
  auto one = std::find(out.begin(), out.end(), 1);
  if (one != out.end()) std::rotate(out.begin(), one, out.end());
  return out;
}

// Issue 31: a summit inside its top contour however thin or concave (the grid of the pole search
// can miss a thin L entirely; its vertex centroid, the old fallback, lies outside it).
TEST(Grow, EverySummitLiesInsideItsTopContour) {
  const Ring thin_l = {{0, 0}, {100, 0}, {100, 0.5}, {0.5, 0.5}, {0.5, 100}, {0, 100}};
  double r = 0;
  Vec2 pole = PoleOfInaccessibility(thin_l, &r);
  EXPECT_TRUE(InsideDouble(thin_l, pole)) << pole.x << ", " << pole.y;
  EXPECT_GT(r, 0.25);  // the L's corner: 0.5 / (1 + 1/√2) = 0.293
  EXPECT_LT(r, 0.3);
  // Thin rotated crosses, zigzags and Ls: the pole inside each, at least half the best radius a
  // fine brute-force grid finds.
  for (int t = 0; t < 40; ++t) {
    const double a = 0.15 * t, c = std::cos(a), sn = std::sin(a), w = 0.05 + 0.02 * (t % 5);
    const double h = 60.0 + t;
    Ring ring;
    const std::vector<Vec2> shape = {{0, 0}, {80, 0}, {80, w}, {w, w}, {w, h}, {0, h}};
    for (const Vec2& v : shape) ring.push_back({c * v.x - sn * v.y + t, sn * v.x + c * v.y});
    pole = PoleOfInaccessibility(ring, &r);
    ASSERT_TRUE(InsideDouble(ring, pole)) << "shape " << t;
    EXPECT_GT(r, 0.25 * w) << "shape " << t;
  }
}

// Mean slope (degrees, central differences) of the inside cells whose height lies in [lo, hi).
double MeanSlopeBetween(const Heightfield& hf, double lo, double hi) {
  double sum = 0;
  int n = 0;
  for (int j = 1; j + 1 < hf.height; ++j) {
    for (int i = 1; i + 1 < hf.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * hf.width + i;
      if (hf.band[k] < 0 || hf.h[k] < lo || hf.h[k] >= hi) continue;
      const double gx = (hf.At(i + 1, j) - hf.At(i - 1, j)) / (2 * hf.cell);
      const double gy = (hf.At(i, j + 1) - hf.At(i, j - 1)) / (2 * hf.cell);
      sum += std::atan(std::sqrt(gx * gx + gy * gy)) * 180 / 3.14159265358979323846;
      ++n;
    }
  }
  return n > 0 ? sum / n : 0;
}

// Issue 31 item 3: the profile row dh_ratio = q makes the interval from level k to k + 1 Δh·q^k.
// On the disk (simple: a cone at q = 1, every slope atan(Δh/d)) q = 1.15 makes the upper third of
// the relief steeper than the lower third and q = 0.87 the reverse, the first band keeping
// atan(Δh/d); the levels' elevations follow the formula and the surface has no pits.
TEST(Grow, ProfileRatioMakesPeaksSteeperThanFoothills) {
  const Ring disk = *BuiltinSeed("disk");
  struct Run {
    double q, lower, upper, base;
  };
  std::vector<Run> runs;
  for (double q : {1.0, 1.15, 0.87}) {
    TerrainParams p = For("simple");
    ASSERT_TRUE(p.Set(P::kD, 20).ok());
    ASSERT_TRUE(p.Set(P::kDh, 10).ok());
    ASSERT_TRUE(p.Set(P::kDhRatio, q).ok());
    Result<Terrain> t = Grow(disk, p, kDefaultTerrainSeed);
    ASSERT_TRUE(t.ok());
    for (const ContourNode& c : t->contours) {
      double h = 0, s = 10;
      for (int k = 0; k < c.level; ++k) {
        h += s;
        s *= q;
      }
      EXPECT_NEAR(c.elevation, h, 1e-9 * (1 + h)) << q << " level " << c.level;
    }
    const Heightfield hf = BuildHeightfield(*t, 256);
    double top = 0;
    for (const Summit& s : t->summits) top = std::max(top, s.elevation);
    const Run r{q, MeanSlopeBetween(hf, 0.05 * top, top / 3),
                MeanSlopeBetween(hf, 2 * top / 3, 0.95 * top), MeanSlopeBetween(hf, 1, 9)};
    std::printf(
        "disk q %.2f: relief %.1f m, mean slope lower third %.1f deg, upper third %.1f, first "
        "band %.1f\n",
        q, top, r.lower, r.upper, r.base);
    EXPECT_EQ(ComputeStats(*t, &hf).pits, 0) << q;
    runs.push_back(r);
  }
  // q = 1: a cone, atan(10/20) = 26.6° in both thirds.
  EXPECT_NEAR(runs[0].lower, 26.6, 1.5);
  EXPECT_NEAR(runs[0].upper, 26.6, 1.5);
  EXPECT_GT(runs[1].upper, runs[1].lower + 15);                     // peaks steep, foothills gentle
  for (const Run& r : runs) EXPECT_NEAR(r.base, 26.6, 1.5) << r.q;  // the first band: Δh still
  EXPECT_LT(runs[2].upper, runs[2].lower - 10);                     // the reverse
  // The row is refused outside [0.5, 2], naming it.
  TerrainParams p;
  const Status bad = p.Set(P::kDhRatio, 3);
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.Line().find("dh_ratio"), std::string::npos) << bad.Line();
}

TEST(Loops, Fig18SequenceWithBothMethods) {
  const std::vector<int> expected{1, 2, 3, 4, 10, 11, 12, 13, 14, 17};
  int removed = 0;
  // The walk starts on a run of ≥ 4 plain points (10-11-12-13; 6-7-8 inside the loop is too short).
  EXPECT_EQ(Ids(RemoveLoopsMethod2(Fig18(), 4, &removed)), expected);
  EXPECT_EQ(removed, 2);  // ④…④ (with ⑤…⑤ inside) and ⑭…⑭
  removed = 0;
  EXPECT_EQ(Ids(RemoveLoopsMethod1(Fig18(), 5, &removed)), expected);
  EXPECT_EQ(removed, 3);  // faces C (4 segments), B (3), D (3)
  // Threshold 4 keeps face C (4 segments): its loop stays.
  removed = 0;
  std::vector<int> kept = Ids(RemoveLoopsMethod1(Fig18(), 4, &removed));
  EXPECT_EQ(removed, 1);  // only D; B encloses C's twist, so it is no longer innermost-small
  EXPECT_GT(kept.size(), expected.size());
}

TEST(Loops, TwistedRingIsUntwisted) {
  // A square with a figure-eight twist on its top edge.
  const Ring r{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {4, 12}, {4, 11}, {6, 11}, {4, 10}, {0, 10}};
  EXPECT_FALSE(IsSimple(ToGrid(r)));
  int removed = 0;
  Ring u = UntwistRing(r, 2, 3, &removed);
  EXPECT_EQ(removed, 1);
  EXPECT_TRUE(IsSimple(ToGrid(Snap(u))));
}

TEST(Fourier, PhaseRandomisationKeepsMagnitudesLowFrequenciesAndClosure) {
  Result<Ring> seed = BuiltinSeed("lobes7");
  ASSERT_TRUE(seed.ok());
  const Ring z = ResampleEqual(*seed, 1024);
  double h = 0;
  std::vector<std::complex<double>> c = PTypeDescriptor(z, &h);
  std::vector<std::complex<double>> c2 = c;
  Pcg32 rng(3, 9);
  RandomisePhases(&c2, 128, 3.14159265358979, &rng);
  int changed = 0;
  for (int idx = 0; idx < 1024; ++idx) {
    const int k = idx < 512 ? idx : idx - 1024;
    EXPECT_NEAR(std::abs(c2[static_cast<std::size_t>(idx)]),
                std::abs(c[static_cast<std::size_t>(idx)]), 1e-12);
    if (std::abs(k) < 128) {
      EXPECT_EQ(c2[static_cast<std::size_t>(idx)], c[static_cast<std::size_t>(idx)]);
    } else if (c2[static_cast<std::size_t>(idx)] != c[static_cast<std::size_t>(idx)]) {
      ++changed;
    }
  }
  EXPECT_GT(changed, 700);  // 768 randomised
  const Ring back = CurveFromDescriptor(c, h, z[0]);
  for (std::size_t i = 0; i < z.size(); i += 97) {
    EXPECT_NEAR(back[i].x, z[i].x, 1e-9);
    EXPECT_NEAR(back[i].y, z[i].y, 1e-9);
  }
  // The mean step c(0) (which closes the curve) keeps its magnitude under the phase shake.
  EXPECT_NEAR(std::abs(c2[0]), std::abs(c[0]), 1e-15);
}

TEST(Midpoint, Fig12DeltaIsTheSmallerOfCapAndLTanTheta) {
  EXPECT_NEAR(MidpointDelta(10, 45, 3), 3.0, 1e-12);
  EXPECT_NEAR(MidpointDelta(10, 10, 3), 10 * std::tan(10 * 3.14159265358979323846 / 180), 1e-12);
}

TEST(BadInput, SeedsAndParametersGiveOneLineNamingTheField) {
  TerrainParams p;
  EXPECT_EQ(Grow({{0, 0}, {1, 1}}, p, kDefaultTerrainSeed).status().Line(),
            "contour: 2 points; must have 3 to 1000000 points");
  EXPECT_EQ(Grow({{0, 0}, {10, 10}, {10, 0}, {0, 10}}, p, kDefaultTerrainSeed).status().Line(),
            "contour: self-intersects or has no area; must be a simple closed polygon");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Grow({{0, 0}, {nan, 0}, {0, 1}}, p, kDefaultTerrainSeed).status().Line(),
            "contour: point 1 is not a finite coordinate; each must be a number in [-1e6, 1e6] m");
  Ring huge(1000001, Vec2{0, 0});
  EXPECT_EQ(Grow(huge, p, kDefaultTerrainSeed).status().Line(),
            "contour: 1000001 points; must have 3 to 1000000 points");
  EXPECT_EQ(p.Set(P::kC, 0.5).Line(), "c: 0.5 is out of range; must be a number in [1, 100]");
  EXPECT_EQ(p.Set(P::kD, 0).Line(), "d: 0 is out of range; must be a number in [0.01, 100000]");
  ASSERT_TRUE(p.Set(P::kNfft, 256).ok());
  ASSERT_TRUE(p.Set(P::kF0, 200).ok());
  EXPECT_EQ(Grow(*BuiltinSeed("disk"), p, kDefaultTerrainSeed).status().Line(),
            "f0: 200 is out of range; must be a whole number in [1, nfft/2 = 128]");
}

}  // namespace
}  // namespace niwa::terrain
