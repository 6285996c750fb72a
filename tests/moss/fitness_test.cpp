// Eqs 3.17-3.21 against hand-computed values: the range score, the tolerance form (clamped and
// normalised), the fitness of table 4.2's species, growth and the death rule on scripted G series.
#include "moss/fitness.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "random/pcg32.h"

namespace niwa::moss {
namespace {

const SpeciesRanges& Of(Species s) {
  static const MossParams params;
  static const SpeciesRanges all[3] = {SpeciesOf(params, Species::kGingoke),
                                       SpeciesOf(params, Species::kHaigoke),
                                       SpeciesOf(params, Species::kSugigoke)};
  return all[static_cast<int>(s)];
}

TEST(MossFitness, RangeScoreIsHalfAtTheRangesEnds) {
  EXPECT_NEAR(RangeScore(274.15, 274.15, 299.15), 0.5, 1e-14);
  EXPECT_NEAR(RangeScore(299.15, 274.15, 299.15), 0.5, 1e-14);
  EXPECT_NEAR(RangeScore(286.65, 274.15, 299.15), 1.0, 1e-14);
  // exp(−4 ln2 / 25² · (278.1 − 286.65)²), by hand (Python's math.exp).
  EXPECT_NEAR(RangeScore(278.1, 274.15, 299.15), 0.7230383124346476, 1e-13);
  // Eq 3.24 uses g with n = 1: a spore's window L 60..365 scores 0.5 at 60 and 1 at its centre.
  EXPECT_NEAR(Suitability(60, 60, 365, 1, GForm::kClamped), 0.5, 1e-14);
  EXPECT_NEAR(Suitability(212.5, 60, 365, 1, GForm::kClamped), 1.0, 1e-14);
}

TEST(MossFitness, ToleranceOneIsTheScore) {
  for (double s : {0.0, 0.1, 0.5, 0.73, 1.0}) {
    EXPECT_EQ(Tolerance(s, 1, GForm::kClamped), s);
    EXPECT_NEAR(Tolerance(s, 1, GForm::kNormalized), s, 1e-15);
  }
}

TEST(MossFitness, ToleranceBelowOneIsClampedByDefault) {
  // Eq 3.19 with n 0.5 gives 1/2 + √(s − 1/2): 1.2071 at s = 1, −0.2071 at s = 0 (spec §4.14);
  // clamped: 1 for s ≥ 0.75, 0 for s ≤ 0.25, the printed curve between.
  EXPECT_EQ(Tolerance(1.0, 0.5, GForm::kClamped), 1.0);
  EXPECT_EQ(Tolerance(0.75, 0.5, GForm::kClamped), 1.0);
  EXPECT_NEAR(Tolerance(0.6, 0.5, GForm::kClamped), 0.5 + 0.31622776601683794, 1e-14);
  EXPECT_NEAR(Tolerance(0.4, 0.5, GForm::kClamped), 0.5 - 0.31622776601683794, 1e-14);
  EXPECT_EQ(Tolerance(0.5, 0.5, GForm::kClamped), 0.5);
  EXPECT_EQ(Tolerance(0.2, 0.5, GForm::kClamped), 0.0);
  EXPECT_EQ(Tolerance(0.0, 0.5, GForm::kClamped), 0.0);
  // The normalised option: 1/2 ± (1/2)·|2s − 1|^n stays in [0, 1] without a plateau.
  EXPECT_EQ(Tolerance(1.0, 0.5, GForm::kNormalized), 1.0);
  EXPECT_EQ(Tolerance(0.0, 0.5, GForm::kNormalized), 0.0);
  EXPECT_NEAR(Tolerance(0.6, 0.5, GForm::kNormalized), 0.5 + 0.5 * 0.4472135954999579, 1e-14);
  // A larger n is a gentler fall outside the range (the thesis: 許容度 n が大きいほど ...): at a
  // score below 1/2, g is higher for n 1 than for n 0.5.
  EXPECT_GT(Tolerance(0.4, 1, GForm::kClamped), Tolerance(0.4, 0.5, GForm::kClamped));
}

TEST(MossFitness, HaigokesHumidityByHand) {
  const SpeciesRanges& h = Of(Species::kHaigoke);  // rh 0.9..1.1, n_rh 0.5
  EXPECT_EQ(Suitability(1.01148, h.rh_0, h.rh_1, h.n_rh, GForm::kClamped), 1.0);
  EXPECT_NEAR(Suitability(1.08, h.rh_0, h.rh_1, h.n_rh, GForm::kClamped), 0.8764478035285261,
              1e-13);
  EXPECT_EQ(Suitability(1.15, h.rh_0, h.rh_1, h.n_rh, GForm::kClamped), 0.0);  // −0.0383 printed
}

TEST(MossFitness, FitnessIsTheProductOfTheThreeFactors) {
  // Sugigoke (every n 1, so g = s) at the spec's shaded humus cell: T_s 278.1, rh_s 1.01148, S 25.
  const SpeciesRanges& s = Of(Species::kSugigoke);
  const Fitness f = FitnessOf(s, 278.1, 1.01148, 25, GForm::kClamped);
  EXPECT_NEAR(f.g_T, 0.4963556030897116, 1e-13);
  EXPECT_NEAR(f.g_rh, 0.9959482242751577, 1e-13);
  EXPECT_NEAR(f.g_S, 1.0, 1e-14);
  EXPECT_NEAR(f.G, 0.4943444815062233, 1e-13);
  EXPECT_NEAR(DailyGrowth(s, f.G), 0.12580334445186697, 1e-13);  // 0.3·(G − 0.075)
  // Every species scores 1 at its optimum; darkness (S_0 = 0) scores g_S = 0.5, not 0.
  for (Species sp : {Species::kGingoke, Species::kHaigoke, Species::kSugigoke}) {
    const SpeciesRanges& r = Of(sp);
    const Fitness best =
        FitnessOf(r, (r.T_0 + r.T_1) / 2, 1.0, (r.S_0 + r.S_1) / 2, GForm::kClamped);
    EXPECT_NEAR(best.G, 1.0, 1e-14) << SpeciesName(sp);
    EXPECT_NEAR(FitnessOf(r, (r.T_0 + r.T_1) / 2, 1.0, 0, GForm::kClamped).g_S, 0.5, 1e-14);
  }
  // Full sun on open ground (S 250) is far outside every light range: g_S = s = 6.5e-17 (n 1; by
  // hand: exp(−4 ln2 / 60² · 220²)), kept exact rather than lost to 1/2 − (1/2 − s).
  EXPECT_NEAR(FitnessOf(Of(Species::kGingoke), 286.65, 1, 250, GForm::kClamped).g_S,
              6.47553699315637e-17, 1e-28);
}

// The run's memo gives FitnessOf's G bit for bit: every species and form, inputs asked again
// (hits), inputs that share a slot (more distinct values than slots), a memo whose slots were
// filled by other inputs, and the values a run asks most (S = 0, a cell's kept T_s and rh_s).
TEST(MossFitness, TheMemoIsFitnessOfBitForBit) {
  for (GForm form : {GForm::kClamped, GForm::kNormalized}) {
    FitnessMemo memo;
    Pcg32 rng(7, 3);
    std::vector<double> T, rh, S;
    for (int i = 0; i < 3000; ++i) {
      T.push_back(rng.Uniform(260, 320));
      rh.push_back(rng.Uniform(0, 1));
      S.push_back(i % 5 == 0 ? 0.0 : rng.Uniform(0, 300));
    }
    int different = 0;
    for (int pass = 0; pass < 3; ++pass)
      for (std::size_t i = 0; i < T.size(); ++i) {
        // Later passes ask each input again, mixed with other positions' inputs.
        const std::size_t j = pass == 0 ? i : (i * 7 + static_cast<std::size_t>(pass)) % T.size();
        for (int k = 0; k < kSpeciesCount; ++k) {
          const Species species = static_cast<Species>(k);
          const double want = FitnessOf(Of(species), T[i], rh[j], S[j], form).G;
          const double got = memo.G(species, Of(species), T[i], rh[j], S[j], form);
          different += std::memcmp(&want, &got, sizeof want) != 0;
        }
      }
    EXPECT_EQ(different, 0) << static_cast<int>(form);
  }
}

// The run skips a seed's light when g_T·g_rh·g(L) <= τ_b: TemperatureHumidity is FitnessOf's
// g_T·g_rh bit for bit, G (any light) times g is then at most τ_b too, and both outcomes occur.
TEST(MossFitness, TemperatureHumidityBoundsGWhateverTheLight) {
  for (GForm form : {GForm::kClamped, GForm::kNormalized}) {
    FitnessMemo memo;
    Pcg32 rng(11, 5);
    int bounded = 0, open = 0;
    for (int i = 0; i < 4000; ++i) {
      const Species species = static_cast<Species>(i % kSpeciesCount);
      const double T = rng.Uniform(260, 320), rh = rng.Uniform(0, 1), g = rng.Uniform(0, 1);
      const double tau_b = rng.Uniform(0, 0.6);
      const Fitness f = FitnessOf(Of(species), T, rh, 0.0, form);
      const double th = memo.TemperatureHumidity(species, Of(species), T, rh, form);
      const double want = f.g_T * f.g_rh;
      ASSERT_EQ(std::memcmp(&th, &want, sizeof th), 0);
      if (th * g > tau_b) {
        ++open;
        continue;
      }
      ++bounded;
      for (double S : {0.0, 1.0, 5.0, 20.0, 45.0, 100.0, 250.0, rng.Uniform(0, 300)})
        ASSERT_LE(memo.G(species, Of(species), T, rh, S, form) * g, tau_b) << T << " " << rh;
    }
    EXPECT_GT(bounded, 500);
    EXPECT_GT(open, 100);
  }
}

TEST(MossFitness, GrowthAndDeathOnAScriptedSeries) {
  const SpeciesRanges& h = Of(Species::kHaigoke);  // α_g 0.25, τ_g 0.1, τ_d 0.15
  MossGrowth m;
  GrowthDay d = AdvanceGrowth(h, 0.5, &m);  // D = 0.25·0.4 = 0.1
  EXPECT_NEAR(d.D, 0.1, 1e-15);
  EXPECT_TRUE(d.growing);
  EXPECT_FALSE(d.dies);  // below τ_d but growing
  EXPECT_NEAR(m.G_moss, 0.1, 1e-15);
  d = AdvanceGrowth(h, 0.05, &m);  // D = −0.0125: declining with G_moss 0.0875 < τ_d
  EXPECT_NEAR(d.D, -0.0125, 1e-15);
  EXPECT_FALSE(d.growing);
  EXPECT_TRUE(d.dies);
  EXPECT_EQ(m.days, 2);
  // Grown past τ_d, a declining day is survived: 3 days at G 1 (D 0.225) then G 0 (D −0.025).
  MossGrowth grown;
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(AdvanceGrowth(h, 1.0, &grown).dies);
  d = AdvanceGrowth(h, 0.0, &grown);
  EXPECT_NEAR(grown.G_moss, 0.65, 1e-14);
  EXPECT_FALSE(d.dies);
  // A new moss dies on its first declining day; G exactly τ_g neither grows nor declines.
  MossGrowth fresh;
  EXPECT_FALSE(AdvanceGrowth(h, 0.1, &fresh).dies);
  EXPECT_EQ(fresh.G_moss, 0.0);
  EXPECT_TRUE(AdvanceGrowth(h, 0.09, &fresh).dies);
}

}  // namespace
}  // namespace niwa::moss
