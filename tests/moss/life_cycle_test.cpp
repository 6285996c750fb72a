// Eqs 3.22-3.24 and the seed rules of spec §1.5.4-1.5.8 against hand values (Python's math and a
// Python PCG32): gemmae on scripted G_moss series, spores' cones, germination windows (the spec's
// day numbers for each species), resting on and falling onto mosses, and the contest for a place.
#include "moss/life_cycle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "moss/fitness.h"
#include "random/pcg32.h"

namespace niwa::moss {
namespace {

const MossParams& Defaults() {
  static const MossParams params;
  return params;
}
LifeRules Rules() { return LifeRulesOf(Defaults()); }
double TauB(Species s) { return SpeciesOf(Defaults(), s).tau_b; }
double Length(const glm::dvec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

TEST(MossLifeCycle, RulesAreTheTablesRows) {
  const LifeRules r = Rules();
  EXPECT_EQ(r.s, 0.01);
  EXPECT_EQ(r.gemma_step, 0.5);
  EXPECT_EQ(r.spore_G, 2.0);
  EXPECT_EQ(r.L_spore_0, 60);
  EXPECT_EQ(r.L_spore_1, 365);
  EXPECT_EQ(r.L_gemma_0, -60);
  EXPECT_EQ(r.L_gemma_1, 60);
  EXPECT_EQ(r.k, 0.01);
  EXPECT_EQ(r.l, 0.10);
  EXPECT_EQ(r.interior_count, 6);
  EXPECT_EQ(r.interior_radius, 1.5);
  EXPECT_EQ(r.overlap, 0.9);
}

TEST(MossLifeCycle, GemmaeOnAScriptedSeries) {
  // One gemma per 0.5 of G_moss above the running maximum (spec §1.5.4, §4.20).
  double G_max = 0;
  const double series[] = {0.2, 0.49, 0.5, 0.9, 1.2, 0.8, 1.1, 1.6, 2.7, -0.3};
  const int want[] = {0, 0, 1, 0, 1, 0, 0, 1, 2, 0};
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(GemmaeDue(series[i], 0.5, false, &G_max), want[i]) << "day " << i + 1;
  }
  EXPECT_EQ(G_max, 2.7);
  // Inside a mat: none, and the maximum still moves (3.1), so 3.4 makes none and 3.6 one.
  EXPECT_EQ(GemmaeDue(3.1, 0.5, true, &G_max), 0);
  EXPECT_EQ(G_max, 3.1);
  EXPECT_EQ(GemmaeDue(3.4, 0.5, false, &G_max), 0);
  EXPECT_EQ(GemmaeDue(3.6, 0.5, false, &G_max), 1);
}

TEST(MossLifeCycle, InsideAMatIsSixOthersWithinOneAndAHalfSizes) {
  const LifeRules r = Rules();
  const glm::dvec3 c(0.25, 0.5, -0.125);
  const double d = 0.99 * 1.5 * 0.01;
  std::vector<glm::dvec3> others = {c + glm::dvec3(d, 0, 0), c - glm::dvec3(d, 0, 0),
                                    c + glm::dvec3(0, d, 0), c - glm::dvec3(0, d, 0),
                                    c + glm::dvec3(0, 0, 0.5 * d)};
  EXPECT_FALSE(InsideMat(c, others, r));  // five
  others.push_back(c + glm::dvec3(0, 0, 1.02 * 1.5 * 0.01));
  EXPECT_FALSE(InsideMat(c, others, r));  // the sixth just outside
  others.push_back(c - glm::dvec3(0, 0, 0.75 * d));
  EXPECT_TRUE(InsideMat(c, others, r));
  // The radius itself counts (≤, as PointIndex::WithinRadius): six at exactly interior_radius·s.
  const double R = r.interior_radius * r.s;
  const std::vector<glm::dvec3> ring = {{R, 0, 0},  {-R, 0, 0}, {0, R, 0},
                                        {0, -R, 0}, {0, 0, R},  {0, 0, -R}};
  EXPECT_TRUE(InsideMat(glm::dvec3(0), ring, r));
}

TEST(MossLifeCycle, GemmaStartByHand) {
  // Seed 7, the default stream: u_1 = 0.8234376071486622, u_2 = 0.2688931974116713 (Python
  // PCG32); z = 1 − 2u_1, azimuth 2πu_2; B = M + 0.01·I (eq 3.22).
  Pcg32 rng(7);
  const glm::dvec3 M(1, 2, 3);
  const glm::dvec3 B = GemmaStart(M, 0.01, &rng);
  EXPECT_NEAR(B.x - 1, -0.0009031487609113681, 1e-15);
  EXPECT_NEAR(B.y - 2, 0.007572289483930427, 1e-15);
  EXPECT_NEAR(B.z - 3, -0.006468752142973245, 1e-15);
  // Uniform on the sphere: unit length, each coordinate's mean near 0 and mean square near 1/3.
  double sum[3] = {0, 0, 0}, sq[3] = {0, 0, 0};
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 I = RandomUnitVector(&rng);
    ASSERT_NEAR(Length(I), 1.0, 1e-14);
    for (int a = 0; a < 3; ++a) sum[a] += I[a], sq[a] += I[a] * I[a];
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(sum[a] / n, 0.0, 0.02) << a;
    EXPECT_NEAR(sq[a] / n, 1.0 / 3.0, 0.01) << a;
  }
}

TEST(MossLifeCycle, SporesNeedGrowthGrowingAndRain) {
  EXPECT_TRUE(MakesSpore(2.0, true, true, 2.0));  // G_moss ≥ 2.0 (§3.6)
  EXPECT_FALSE(MakesSpore(1.999, true, true, 2.0));
  EXPECT_FALSE(MakesSpore(3.0, false, true, 2.0));  // declining or still
  EXPECT_FALSE(MakesSpore(3.0, true, false, 2.0));  // a dry day (spec §4.19)
}

TEST(MossLifeCycle, SporeDirectionsStayInsideTheTwoCones) {
  // Eq 3.23: 0° < φ < 45° or 135° < φ < 180° to the face normal N, uniform over the solid angle.
  const double c45 = std::sqrt(0.5);
  const glm::dvec3 normals[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0.48, 0.6, 0.64}};
  for (const glm::dvec3& N : normals) {
    Pcg32 rng(11);
    int upper = 0;
    double upper_cos = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 I = SporeDirection(N, &rng);
      ASSERT_NEAR(Length(I), 1.0, 1e-14);
      const double c = I.x * N.x + I.y * N.y + I.z * N.z;
      ASSERT_TRUE((c > c45 && c < 1.0) || (c < -c45 && c > -1.0)) << c;
      if (c > 0) ++upper, upper_cos += c;
    }
    EXPECT_NEAR(static_cast<double>(upper) / n, 0.5, 0.02);
    EXPECT_NEAR(upper_cos / upper, (1.0 + c45) / 2.0, 0.005);  // mean cos φ over the cone
  }
  // Seed 7, N up: the first draw u = (k + 0.5)/2³² gives t = 2u > 1, the lower cone, and
  // cos φ = −(1 − (t − 1)(1 − √½)) = −0.8105346362456203 (Python).
  Pcg32 rng(7);
  const glm::dvec3 Q = SporeStart(glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0), 0.1, &rng);
  EXPECT_NEAR((Q.y - 1) / 0.1, -0.8105346362456203, 1e-14);
}

TEST(MossLifeCycle, GerminationWindowsOfTheSpec) {
  const LifeRules r = Rules();
  // Spec §6: a spore's g(L) is 0.5 at L 60 and 1 at 212.5; a gemma's is 1 at L 0.
  EXPECT_NEAR(GerminationScore(1, 60, SeedKind::kSpore, r), 0.5, 1e-14);
  EXPECT_NEAR(GerminationScore(0.7, 212.5, SeedKind::kSpore, r), 0.7, 1e-14);
  EXPECT_NEAR(GerminationScore(0.7, 0, SeedKind::kGemma, r), 0.7, 1e-14);
  EXPECT_NEAR(GerminationScore(0.8, 30, SeedKind::kGemma, r), 0.6727171322029717, 1e-13);
  // Spec §1.5.8: gemmae are dropped after ~69-74 days, spores after ~388-400, and spores cannot
  // germinate before day ~25-37. By hand: L = centre ± half·√(log₂(1/τ_b)) (gemma 0 ± 60,
  // spore 212.5 ± 152.5): gingoke τ_b 0.4: 68.985, 387.837, 37.163; haigoke 0.35: 73.841,
  // 400.179, 24.821; sugigoke 0.37: 71.860, 395.144, 29.856.
  struct Want {
    Species species;
    int gemma_last, spore_first, spore_last;
  };
  for (const Want& w : {Want{Species::kGingoke, 68, 38, 387}, Want{Species::kHaigoke, 73, 25, 400},
                        Want{Species::kSugigoke, 71, 30, 395}}) {
    const double tau_b = TauB(w.species);
    // With G = 1 (the best place): a gemma germinates through gemma_last, expires the day after.
    EXPECT_EQ(SeedDay(1, w.gemma_last, SeedKind::kGemma, tau_b, false, r), SeedFate::kGerminates);
    EXPECT_EQ(SeedDay(1, w.gemma_last + 1, SeedKind::kGemma, tau_b, false, r), SeedFate::kExpires);
    // A spore waits before spore_first (before its window's centre it never expires).
    EXPECT_EQ(SeedDay(1, w.spore_first - 1, SeedKind::kSpore, tau_b, false, r), SeedFate::kWaits);
    EXPECT_EQ(SeedDay(1, w.spore_first, SeedKind::kSpore, tau_b, false, r), SeedFate::kGerminates);
    EXPECT_EQ(SeedDay(1, w.spore_last, SeedKind::kSpore, tau_b, false, r), SeedFate::kGerminates);
    EXPECT_EQ(SeedDay(1, w.spore_last + 1, SeedKind::kSpore, tau_b, false, r), SeedFate::kExpires);
    // A poor place (G 0.3 < τ_b) never germinates; it waits until the same expiry day.
    EXPECT_EQ(SeedDay(0.3, w.gemma_last, SeedKind::kGemma, tau_b, false, r), SeedFate::kWaits);
    EXPECT_EQ(SeedDay(0.3, w.gemma_last + 1, SeedKind::kGemma, tau_b, false, r),
              SeedFate::kExpires);
  }
}

TEST(MossLifeCycle, AtTheCapASeedThatWouldGerminateWaits) {
  const LifeRules r = Rules();
  EXPECT_EQ(SeedDay(0.8, 30, SeedKind::kGemma, 0.4, true, r), SeedFate::kWaits);
  EXPECT_EQ(SeedDay(0.8, 30, SeedKind::kGemma, 0.4, false, r), SeedFate::kGerminates);
  EXPECT_EQ(SeedDay(0.8, 69, SeedKind::kGemma, 0.4, true, r), SeedFate::kExpires);
}

TEST(MossLifeCycle, AGemmaAtKEqualsSTouchesItsParent) {
  // k = s = 0.01 (the defaults): the gemma starts exactly s from its parent, which rounding could
  // put just outside s; the contact slack (1e-9 relative) makes it touch in every direction.
  const LifeRules r = Rules();
  const glm::dvec3 M(0.1234, 0.0567, -0.891);
  Pcg32 rng(3);
  for (int i = 0; i < 5000; ++i) {
    const glm::dvec3 B = GemmaStart(M, r.k, &rng);
    const MossRest rest = RestOnMoss(B, {M}, r);
    ASSERT_TRUE(rest.touches) << i;
    ASSERT_NEAR(Length(rest.position - M), r.s, 1e-15);
  }
}

TEST(MossLifeCycle, RestingOnTheNearestMoss) {
  const LifeRules r = Rules();
  const std::vector<glm::dvec3> centres = {{0, 0, 0}, {0.03, 0, 0}, {0.0, 0.03, 0}};
  // 0.0095 from moss 0: moved out to exactly s along the same line.
  MossRest rest = RestOnMoss({0.0095, 0, 0}, centres, r);
  EXPECT_TRUE(rest.touches);
  EXPECT_EQ(rest.moss, 0u);
  EXPECT_NEAR(rest.position.x, 0.01, 1e-17);
  EXPECT_EQ(rest.position.y, 0.0);
  // 0.005 from moss 0 (closer than 0.9 s): where a moss already is, it stays for the contest.
  rest = RestOnMoss({0, 0.005, 0}, centres, r);
  EXPECT_TRUE(rest.touches);
  EXPECT_EQ(rest.position, glm::dvec3(0, 0.005, 0));
  // The nearer of two it touches.
  rest = RestOnMoss({0.0205, 0, 0}, centres, r);
  EXPECT_EQ(rest.moss, 1u);
  EXPECT_NEAR(rest.position.x, 0.02, 1e-17);
  // Equidistant: the lower index.
  rest = RestOnMoss({0.015, 0.015, 0}, {{0.015, 0.006, 0}, {0.015, 0.024, 0}}, r);
  EXPECT_EQ(rest.moss, 0u);
  // Beyond s: no contact, unchanged.
  rest = RestOnMoss({0, 0, 0.0101}, centres, r);
  EXPECT_FALSE(rest.touches);
  EXPECT_EQ(rest.position, glm::dvec3(0, 0, 0.0101));
}

TEST(MossLifeCycle, FallingOntoTheHighestMossBelow) {
  const LifeRules r = Rules();
  // Horizontal offset 0.006 from a moss at the origin: contact at y = √(0.01² − 0.006²) = 0.008.
  MossRest rest = FallOntoMosses({0.006, 1, 0}, {{0, 0, 0}}, r);
  EXPECT_TRUE(rest.touches);
  EXPECT_NEAR(rest.position.y, 0.008, 1e-15);
  EXPECT_EQ(rest.position.x, 0.006);
  EXPECT_NEAR(Length(rest.position - glm::dvec3(0, 0, 0)), r.s, 1e-15);
  // A stack: the higher moss stops it first; a moss above the seed does not.
  rest = FallOntoMosses({0, 0.05, 0}, {{0, 0, 0}, {0.002, 0.01, 0}, {0, 0.2, 0}}, r);
  EXPECT_EQ(rest.moss, 1u);
  EXPECT_NEAR(rest.position.y, 0.01 + std::sqrt(0.0001 - 0.000004), 1e-15);
  // Horizontally more than s away: no moss below.
  rest = FallOntoMosses({0.0101, 1, 0}, {{0, 0, 0}}, r);
  EXPECT_FALSE(rest.touches);
}

// MatBuckets (the run's buckets of the mat mosses) against the passes over every centre: the same
// touch, moss and position bits for 4,000 seeds among 600 clustered centres with exact duplicates
// (ties go to the lower index), seeds exactly s above a centre, and a few grid sizes (coarse grids
// put many centres in a bucket; fine ones split a contact ball over many).
TEST(MossLifeCycle, MatBucketsAnswerAsThePassesOverEveryCentre) {
  const LifeRules r = Rules();
  Pcg32 rng(7, 3);
  std::vector<glm::dvec3> centres;
  for (int k = 0; k < 600; ++k) {
    if (k % 10 == 9) {  // an exact duplicate of an earlier centre
      centres.push_back(centres[static_cast<std::size_t>(rng.Uniform() * k)]);
      continue;
    }
    const double spread = k < 400 ? 0.05 : 0.6;  // a dense mat and scattered mosses
    centres.emplace_back(spread * rng.Uniform(), 0.02 * rng.Uniform(), spread * rng.Uniform());
  }
  int touched = 0, fell = 0;
  for (std::size_t buckets : {std::size_t{64}, std::size_t{4096}, std::size_t{1} << 18}) {
    const MatBuckets mats(centres, r, buckets);
    Pcg32 seeds(11, 5);
    for (int q = 0; q < 4000; ++q) {
      glm::dvec3 seed(0.06 * seeds.Uniform(), 0.04 * seeds.Uniform() - 0.01,
                      0.06 * seeds.Uniform());
      if (q % 50 == 0)
        seed = centres[static_cast<std::size_t>(q) % centres.size()] +
               glm::dvec3(0, r.s, 0);  // exactly s above: the contact's edge
      const MossRest a = RestOnMoss(seed, centres, r), b = mats.Rest(seed, r);
      ASSERT_EQ(a.touches, b.touches) << q;
      ASSERT_EQ(a.moss, b.moss) << q;
      ASSERT_EQ(a.position, b.position) << q;
      const MossRest c = FallOntoMosses(seed, centres, r), d = mats.Fall(seed, r);
      ASSERT_EQ(c.touches, d.touches) << q;
      ASSERT_EQ(c.moss, d.moss) << q;
      ASSERT_EQ(c.position, d.position) << q;
      touched += a.touches;
      fell += c.touches;
    }
  }
  EXPECT_GT(touched, 1000);  // the seeds met mosses often, and missed them often
  EXPECT_LT(touched, 11000);
  EXPECT_GT(fell, 1000);
  EXPECT_LT(fell, 11000);
}

// Outside its window (g(L) <= τ_b) a seed's fate does not depend on G in [0, 1] (the run then
// skips its gather and fitness): SeedDay(G) is SeedDay(0) for every species, kind and age.
TEST(MossLifeCycle, ASeedOutsideItsWindowHasTheFateOfGZero) {
  const LifeRules r = Rules();
  int skipped = 0, scored = 0;
  for (Species sp : {Species::kGingoke, Species::kHaigoke, Species::kSugigoke})
    for (SeedKind kind : {SeedKind::kGemma, SeedKind::kSpore})
      for (int L = 0; L <= 500; ++L) {
        const double tau_b = TauB(sp);
        if (SeedWindowScore(L, kind, r) > tau_b) {
          ++scored;
          continue;
        }
        ++skipped;
        for (double G : {0.0, 1e-9, 0.25, 0.5, 0.999, 1.0})
          for (bool at_cap : {false, true})
            ASSERT_EQ(SeedDay(G, L, kind, tau_b, at_cap, r),
                      SeedDay(0.0, L, kind, tau_b, at_cap, r))
                << L;
      }
  EXPECT_GT(skipped, 100);
  EXPECT_GT(scored, 100);
}

// SeedDayOfScore (the run's form: the window's score looked up by age) is eq 3.24's fate from
// GerminationScore, as SeedDay worked it out before: G·g is GerminationScore's bits, and the fate
// is the same for every kind, age, G, τ_b and cap.
TEST(MossLifeCycle, SeedDayOfScoreIsTheGerminationScoresFate) {
  const LifeRules r = Rules();
  int germinates = 0, expires = 0, waits = 0;
  for (Species sp : {Species::kGingoke, Species::kHaigoke, Species::kSugigoke})
    for (SeedKind kind : {SeedKind::kGemma, SeedKind::kSpore})
      for (int L = 0; L <= 400; ++L)
        for (double G : {0.0, 0.1, 0.45, 0.7, 0.999, 1.0})
          for (bool at_cap : {false, true}) {
            const double tau_b = TauB(sp);
            const double g = SeedWindowScore(L, kind, r);
            ASSERT_EQ(G * g, GerminationScore(G, L, kind, r));
            const double L_0 = kind == SeedKind::kSpore ? r.L_spore_0 : r.L_gemma_0;
            const double L_1 = kind == SeedKind::kSpore ? r.L_spore_1 : r.L_gemma_1;
            SeedFate want = SeedFate::kWaits;
            if (GerminationScore(G, L, kind, r) > tau_b)
              want = at_cap ? SeedFate::kWaits : SeedFate::kGerminates;
            else if (L > (L_0 + L_1) / 2.0 && RangeScore(L, L_0, L_1) <= tau_b)
              want = SeedFate::kExpires;
            ASSERT_EQ(SeedDayOfScore(G, g, L, kind, tau_b, at_cap, r), want) << L;
            ASSERT_EQ(SeedDay(G, L, kind, tau_b, at_cap, r), want) << L;
            germinates += want == SeedFate::kGerminates;
            expires += want == SeedFate::kExpires;
            waits += want == SeedFate::kWaits;
          }
  EXPECT_GT(germinates, 100);
  EXPECT_GT(expires, 100);
  EXPECT_GT(waits, 100);
}

TEST(MossLifeCycle, TheContestForAnOccupiedPlace) {
  const LifeRules r = Rules();
  const SpeciesRanges gin = SpeciesOf(Defaults(), Species::kGingoke);  // α_g 0.3
  const SpeciesRanges hai = SpeciesOf(Defaults(), Species::kHaigoke);  // α_g 0.25
  EXPECT_DOUBLE_EQ(PlacePriority(gin, 0), 0.3);
  EXPECT_DOUBLE_EQ(PlacePriority(hai, 0.1), 0.275);
  EXPECT_DOUBLE_EQ(PlacePriority(hai, -0.4), 0.25);  // max(G_moss, 0)
  // A gingoke seed (0.3) takes a haigoke's place at G_moss 0.1 (0.275), not at 0.2 (0.3: a tie
  // keeps the incumbent), and must beat every occupant.
  EXPECT_TRUE(WinsPlace(PlacePriority(gin, 0), {PlacePriority(hai, 0.1)}));
  EXPECT_FALSE(WinsPlace(PlacePriority(gin, 0), {0.25 * 1.2}));
  EXPECT_FALSE(WinsPlace(0.3, {0.275, 0.31}));
  EXPECT_TRUE(WinsPlace(0.3, {}));
  // Occupants: centres closer than 0.9 s = 0.009, strictly, in index order.
  const std::vector<glm::dvec3> centres = {{0.0089, 0, 0}, {0, 0.0095, 0}, {0, 0, -0.002}};
  EXPECT_EQ(Occupants({0, 0, 0}, centres, r), (std::vector<uint32_t>{0, 2}));
  EXPECT_TRUE(Occupants({0.5, 0, 0}, centres, r).empty());
}

}  // namespace
}  // namespace niwa::moss

namespace niwa::moss {
namespace {

// FNV-1a over the bytes of every coordinate of 1,000 gemma and 1,000 spore starts (seed 5).
uint64_t LifeCycleStartsDigest() {
  const LifeRules r = Rules();
  Pcg32 rng(5);
  uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xff)) * 1099511628211ULL;
  };
  const glm::dvec3 M(0.3, 0.01, -0.7), N(0.48, 0.6, 0.64);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 B = GemmaStart(M, r.k, &rng);
    const glm::dvec3 Q = SporeStart(M, N, r.l, &rng);
    for (int a = 0; a < 3; ++a) mix(B[a]), mix(Q[a]);
  }
  return h;
}

TEST(MossLifeCycle, SeedStartsAreTheSameBitsInEveryBuild) {
  // The golden digest was printed by the native build; the WASM build must give the same bits
  // (det_math's sine and cosine, no fast-math, no FMA contraction).
  EXPECT_EQ(LifeCycleStartsDigest(), 6523830122594562836ULL);
}

}  // namespace
}  // namespace niwa::moss
