// The 2-layer mechanics: a spring's force against the formula, no force at rest, pre-break strain
// against §1.4's formula, a stretched lattice breaking at its threshold, energy that only falls
// once growth stops, breaks that stay, and one seed one broken set.
#include "bark/springs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "bark/bark_state.h"

namespace niwa::bark {
namespace {

BarkParams Params(const char* species, int n_r, int n_h) {
  BarkParams p = *BarkPreset(species);
  EXPECT_TRUE(p.Set(BarkParam::kNR, n_r).ok());
  EXPECT_TRUE(p.Set(BarkParam::kNH, n_h).ok());
  return p;
}

// One growth cycle of steps from `s`, the strains growing at the mechanics' rates.
void GrowOneCycle(const Lattice& L, const Mechanics& m, Surface* s) {
  for (int k = 0; k < m.steps_per_cycle; ++k) {
    const double t = k * m.dt;
    Step(L, m,
         Growth{static_cast<float>(1 + m.strain_rate_theta * t),
                static_cast<float>(1 + m.strain_rate_z * t),
                static_cast<float>(m.strain_rate_theta), static_cast<float>(m.strain_rate_z)},
         s);
  }
}

TEST(Springs, MechanicsFollowTheSpec) {
  // The spec's prototype grew tallow at Table 1's D = 1 cm (the preset's is 0.9 since its level B
  // calibration, docs/bark-model.md).
  BarkParams tallow = *BarkPreset("tallow");
  ASSERT_TRUE(tallow.Set(BarkParam::kD, 1.0).ok());
  const Mechanics m = MechanicsOf(tallow);
  EXPECT_NEAR(m.node_area, 0.09431, 1e-5);
  EXPECT_NEAR(m.mass, 0.5 * 0.09431, 1e-5);
  EXPECT_NEAR(m.k[0], std::sqrt(3.0) / 2 * 117.3e7, 1);
  EXPECT_NEAR(m.k_s, 53.3e7 * m.node_area, 1e-3);
  // Spec §1.5's prototype: dt = 8.31e-7 s, 12,034 steps for T = 0.01 s.
  EXPECT_NEAR(m.dt, 8.31e-7, 0.01e-7);
  EXPECT_EQ(m.steps_per_cycle, 12034);
  EXPECT_DOUBLE_EQ(m.dt * m.steps_per_cycle, 0.01);
}

TEST(Springs, OneSpringsForceIsTheFormula) {
  const Lattice L = BuildLattice(8, 4, 0.33);
  Mechanics m = MechanicsOf(Params("pine", 8, 4));
  m.k_s = 0;
  m.c_s = 0;
  m.c[0] = m.c[1] = 0;
  Surface s = InitialSurface(L, m, 1);
  // Only spring 0 (axial, node 0 -> node 1) left: every other one broken.
  for (int i = 1; i < L.springs(); ++i) {
    s.limit2[L.slot(i)] = std::numeric_limits<float>::infinity();
  }
  s.uz[1] = 0.002f;  // stretched by 2e-3 cm (strain 0.6 %, below κ̄_1 − 1)
  s.ux[1] = 0.001f;
  const double dx = 0.001, dz = 0.33 + static_cast<double>(0.002f);
  const double l = std::hypot(dx, dz), f = m.k[0] * (l - 0.33);
  Step(L, m, Growth{}, &s);
  // After one step the node's rate is dt·F/m: F on node 0 pulls it towards node 1.
  const double rate = m.dt / m.mass;
  EXPECT_NEAR(s.wz[0], rate * f * dz / l, 1e-4 * rate * f);
  EXPECT_NEAR(s.wx[0], rate * f * dx / l, 1e-4 * rate * f);
  EXPECT_NEAR(s.wz[1], -rate * f * dz / l, 1e-4 * rate * f);
  EXPECT_EQ(s.broken_count[0] + s.broken_count[1], 0);
}

TEST(Springs, NoForceAtRestAndThePreBreakStrainFormula) {
  const BarkParams p = Params("tallow", 16, 8);
  const Lattice L = BuildLattice(16, 8, 0.33);
  const Mechanics m = MechanicsOf(p);
  Surface s = InitialSurface(L, m, 1);
  Step(L, m, Growth{}, &s);
  for (int n = 0; n < L.nodes(); ++n) {  // the float rest lengths of the diagonals: < 1e-9 cm
    EXPECT_LT(std::fabs(s.ux[n]), 1e-9f);
    EXPECT_LT(std::fabs(s.uz[n]), 1e-9f);
  }
  // Uniform growth below every threshold: axial strain ε_z, diagonal 0.75·ε_θ + 0.25·ε_z.
  const double eps_t = 0.004, eps_z = 0.006;
  const Growth g{static_cast<float>(1 + eps_t), static_cast<float>(1 + eps_z), 0, 0};
  for (int k = 0; k < 200; ++k) Step(L, m, g, &s);
  EXPECT_EQ(s.broken_count[0] + s.broken_count[1], 0);
  for (int i = 0; i < L.springs(); ++i) {
    const double want = L.family(i) == Family::kAxial ? eps_z : 0.75 * eps_t + 0.25 * eps_z;
    EXPECT_NEAR(SpringStrain(L, s, g, i), want, 1e-5) << i;
  }
}

TEST(Springs, AStretchedLatticeBreaksAtItsThreshold) {
  // σ = 0: every diagonal breaks at κ̄_2; growth around only (ε_z = 0): diagonal strain 0.75·ε_θ.
  BarkParams p = Params("pine", 16, 8);
  ASSERT_TRUE(p.Set(BarkParam::kSigma, 0).ok());
  const Lattice L = BuildLattice(16, 8, 0.33);
  const Mechanics m = MechanicsOf(p);
  Surface s = InitialSurface(L, m, 1);
  const double kappa2 = p.Get(BarkParam::kKappa2);
  // The hoop strain at which the diagonals reach κ̄_2: 0.75·(1 + ε_θ)² + 0.25 = κ̄_2² (to first
  // order 0.75·ε_θ = κ̄_2 − 1, spec §1.4).
  const double eps_break = std::sqrt((kappa2 * kappa2 - 0.25) / 0.75) - 1.0;
  double first = -1;
  for (int k = 0; k <= 400 && first < 0; ++k) {
    const double eps = eps_break * (0.9 + 0.2 * k / 400.0);
    Step(L, m, Growth{static_cast<float>(1 + eps), 1.0f, 0, 0}, &s);
    if (s.broken_count[1] > 0) first = eps;
  }
  ASSERT_GT(first, 0);
  EXPECT_NEAR(first, eps_break, eps_break * 0.0015);  // within one growth increment (5e-4)
  EXPECT_EQ(s.broken_count[0], 0);                    // axial springs see no strain
}

TEST(Springs, EnergyFallsOnceGrowthStopsAndBreaksStay) {
  const BarkParams p = Params("tallow", 32, 16);
  const Lattice L = BuildLattice(32, 16, 0.33);
  const Mechanics m = MechanicsOf(p);
  Surface s = InitialSurface(L, m, 5);
  const int steps = m.steps_per_cycle;
  GrowOneCycle(L, m, &s);
  ASSERT_GT(s.broken_count[0] + s.broken_count[1], 0);  // it cracked
  const Growth frozen{static_cast<float>(1 + m.strain_rate_theta * steps * m.dt),
                      static_cast<float>(1 + m.strain_rate_z * steps * m.dt), 0, 0};
  std::vector<uint8_t> broken = s.broken;
  double e = Energy(L, m, frozen, s);
  for (int block = 0; block < 20; ++block) {
    for (int k = 0; k < 100; ++k) Step(L, m, frozen, &s);
    const double next = Energy(L, m, frozen, s);
    EXPECT_LE(next, e * (1 + 1e-6)) << "block " << block;
    e = next;
    for (std::size_t i = 0; i < broken.size(); ++i)
      ASSERT_LE(broken[i], s.broken[i]) << "spring " << i << " healed";
    broken = s.broken;
  }
}

TEST(Springs, OneSeedOneBrokenSet) {
  const BarkParams p = Params("camphor", 16, 16);
  const Lattice L = BuildLattice(16, 16, 0.33);
  const Mechanics m = MechanicsOf(p);
  auto run = [&](uint64_t seed) {
    Surface s = InitialSurface(L, m, seed);
    GrowOneCycle(L, m, &s);
    return s.broken;
  };
  const std::vector<uint8_t> a = run(1), b = run(1), c = run(2);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

// Eight springs a batch (AVX2, where the CPU has it) and four give the same bits: a tallow
// lattice of 32 × 20 (columns of 20 nodes, so batches of eight run within a column and fall back
// to four at its seams, and the tail of the last column is one by one) over a growth cycle that
// cracks it.
TEST(Springs, EightLanesGiveTheBitsOfFour) {
  if (!EightLanesAvailable()) GTEST_SKIP() << "no AVX2 path in this build or CPU";
  const BarkParams p = Params("tallow", 32, 20);
  const Lattice L = BuildLattice(32, 20, 0.33);
  const Mechanics m = MechanicsOf(p);
  auto run = [&](int lanes) {
    const int before = SetBatchLanes(lanes);
    EXPECT_EQ(BatchLanes(), lanes);
    Surface s = InitialSurface(L, m, 5);
    GrowOneCycle(L, m, &s);
    SetBatchLanes(before);
    return s;
  };
  const Surface four = run(4), eight = run(8);
  ASSERT_GT(four.broken_count[0] + four.broken_count[1], 0);
  auto same_bits = [](const std::vector<float>& x, const std::vector<float>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * 4) == 0;
  };
  EXPECT_TRUE(same_bits(four.ux, eight.ux));
  EXPECT_TRUE(same_bits(four.uz, eight.uz));
  EXPECT_TRUE(same_bits(four.wx, eight.wx));
  EXPECT_TRUE(same_bits(four.wz, eight.wz));
  // The slots' forces: the same bits for the intact springs; zeros for the broken ones (a batch
  // of springs all broken writes +0, a broken spring in a batch with an intact one 0·f, ±0: the
  // batching decides which, and a node's sum is the same with either).
  auto same_forces = [&](const std::vector<float>& x, const std::vector<float>& y) {
    for (std::size_t q = 0; q < x.size(); ++q) {
      const bool broken = four.limit2[q] == std::numeric_limits<float>::infinity();
      if (broken ? !(x[q] == 0.0f && y[q] == 0.0f) : std::memcmp(&x[q], &y[q], 4) != 0)
        return false;
    }
    return x.size() == y.size();
  };
  EXPECT_TRUE(same_forces(four.gx, eight.gx));
  EXPECT_TRUE(same_forces(four.gz, eight.gz));
  EXPECT_TRUE(same_bits(four.limit2, eight.limit2));
  EXPECT_EQ(four.broken, eight.broken);
  EXPECT_EQ(four.broken_count[0], eight.broken_count[0]);
  EXPECT_EQ(four.broken_count[1], eight.broken_count[1]);
}

}  // namespace
}  // namespace niwa::bark
