// The 4-layer model (spec §1.7-1.8): role exchange keeps the node counts and moves each layer one
// role outward, a new M2 is born stress free with fresh thresholds, the area rule peels a
// hand-cut block by A, the drying limit decays only with γ > 0 and only within η, whole runs
// repeat bit for bit, passes in chunks (step_lanes.h, threaded or not) give the bits of one, and
// the estimate counts the three spring layers.
#include "bark/four_layer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "bark/bark_run.h"

namespace niwa::bark {
namespace {

BarkParams Params(double a = 2.0, double gamma = 1.0) {
  BarkParams p = *BarkPreset("pine");
  EXPECT_TRUE(p.Set(BarkParam::kNR, 16).ok());
  EXPECT_TRUE(p.Set(BarkParam::kNH, 8).ok());
  EXPECT_TRUE(p.Set(BarkParam::kT, 0.001).ok());
  EXPECT_TRUE(p.Set(BarkParam::kCork, 0.1).ok());
  EXPECT_TRUE(p.Set(BarkParam::kA, a).ok());
  EXPECT_TRUE(p.Set(BarkParam::kGamma, gamma).ok());
  return p;
}

struct Model {
  Lattice lattice;
  FourLayer f;
};

Model Start(const BarkParams& p, int cycles = 2, uint64_t seed = 1) {
  Model m;
  m.lattice =
      BuildLattice(p.GetInt(BarkParam::kNR), p.GetInt(BarkParam::kNH), p.Get(BarkParam::kLo));
  m.f = StartFourLayer(m.lattice, FourLayerMechanicsOf(p, m.lattice), seed, cycles);
  return m;
}

// Steps to the end of the current cycle (true: a cycle ended there).
bool RunCycle(Model* m) {
  for (;;)
    if (StepFourLayer(m->lattice, &m->f)) return true;
}

// Two cycles (an exchange between) with cracks, snapped bonds and peeling, stepped without lanes,
// with the passes' chunks run one after the other here, and shared with a worker thread where the
// build has one, each with four nodes a batch and (where the build and CPU have AVX2) eight: every
// layer's state and every tally the same bits. 14 × 9 nodes: two chunks, split at node 56 inside a
// column, so a chunk's first batch is not where the one-lane pass has one; 14 × 20: batches of
// eight run within a column, and fall back to four at its seams.
void ExpectLanesGiveTheSameBits(int n_h) {
  BarkParams p = Params();
  ASSERT_TRUE(p.Set(BarkParam::kNR, 14).ok());
  ASSERT_TRUE(p.Set(BarkParam::kNH, n_h).ok());
  ASSERT_TRUE(p.Set(BarkParam::kT, 0.002).ok());
  ASSERT_TRUE(p.Set(BarkParam::kCork, 1.0).ok());
  auto run = [&](int variant, int batch) {
    const int before = SetBatchLanes(batch);
    Model m = Start(p, 2, 3);
    StepLanes lanes(variant == 2 ? 2 : 1);
    StepLanes* split = variant == 0 ? nullptr : &lanes;
    if (variant == 2) {
      EXPECT_EQ(lanes.threaded(), StepLanesHaveThreads());
    }
    while (m.f.step < m.f.growth_steps + 50) {
      if (StepFourLayer(m.lattice, &m.f, split) && m.f.step < m.f.growth_steps)
        ExchangeRoles(m.lattice, 3, &m.f);
    }
    SetBatchLanes(before);
    return m;
  };
  const Model one = run(0, 4);
  EXPECT_GT(one.f.layer[kS].s.broken_count[0] + one.f.layer[kS].s.broken_count[1], 0);
  EXPECT_GT(one.f.bonds_broken, 0);
  EXPECT_GT(one.f.peeled_nodes, 0);
  std::vector<std::pair<int, int>> variants = {{1, 4}, {2, 4}};
  if (EightLanesAvailable()) variants.insert(variants.end(), {{0, 8}, {1, 8}, {2, 8}});
  for (const auto& [variant, batch] : variants) {
    SCOPED_TRACE(testing::Message() << "variant " << variant << ", " << batch << " a batch");
    const Model two = run(variant, batch);
    EXPECT_EQ(two.f.step, one.f.step);
    EXPECT_EQ(two.f.bonds_broken, one.f.bonds_broken) << variant;
    EXPECT_EQ(two.f.peeled_nodes, one.f.peeled_nodes) << variant;
    EXPECT_EQ(two.f.peel_events, one.f.peel_events) << variant;
    EXPECT_EQ(two.f.shed_nodes, one.f.shed_nodes) << variant;
    EXPECT_EQ(two.f.first_crack_step, one.f.first_crack_step) << variant;
    for (int r = 0; r < 3; ++r) {
      const CorkLayer& a = one.f.layer[r];
      const CorkLayer& b = two.f.layer[r];
      auto same_bits = [](const std::vector<float>& x, const std::vector<float>& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * 4) == 0;
      };
      EXPECT_TRUE(same_bits(a.s.ux, b.s.ux)) << variant << " " << r;
      EXPECT_TRUE(same_bits(a.s.uz, b.s.uz)) << variant << " " << r;
      EXPECT_TRUE(same_bits(a.s.wx, b.s.wx)) << variant << " " << r;
      EXPECT_TRUE(same_bits(a.s.wz, b.s.wz)) << variant << " " << r;
      // The slots' forces: the same bits for the intact springs; zeros for the broken ones (a
      // batch of springs all broken writes +0, a broken spring beside an intact one 0·f, ±0: the
      // batching decides which, and a node's sum is the same with either).
      auto same_forces = [&](const std::vector<float>& x, const std::vector<float>& y) {
        for (std::size_t q = 0; q < x.size(); ++q) {
          const bool broken = a.s.limit2[q] == std::numeric_limits<float>::infinity();
          if (broken ? !(x[q] == 0.0f && y[q] == 0.0f) : std::memcmp(&x[q], &y[q], 4) != 0)
            return false;
        }
        return x.size() == y.size();
      };
      EXPECT_TRUE(same_forces(a.s.gx, b.s.gx)) << variant << " " << r;
      EXPECT_TRUE(same_forces(a.s.gz, b.s.gz)) << variant << " " << r;
      EXPECT_TRUE(same_bits(a.s.limit2, b.s.limit2)) << variant << " " << r;
      EXPECT_EQ(a.s.broken, b.s.broken) << variant << " " << r;
      EXPECT_EQ(a.s.broken_count[0], b.s.broken_count[0]);
      EXPECT_EQ(a.s.broken_count[1], b.s.broken_count[1]);
      EXPECT_EQ(a.bonded, b.bonded) << variant << " " << r;
      EXPECT_EQ(a.present, b.present) << variant << " " << r;
    }
  }
}

TEST(FourLayer, TwoLanesGiveTheSameBits) { ExpectLanesGiveTheSameBits(9); }

// 14 × 40 nodes: four chunks a pass (bounds 136, 280, 416, each inside a column), shared between
// this thread and the worker as they come (each claims half of what is left).
TEST(FourLayer, FourChunksGiveTheSameBits) { ExpectLanesGiveTheSameBits(40); }

TEST(FourLayer, EightNodesABatchGiveTheSameBits) {
  if (!EightLanesAvailable()) GTEST_SKIP() << "no AVX2 path in this build or CPU";
  ExpectLanesGiveTheSameBits(20);
}

TEST(FourLayer, RoleExchangeKeepsNodeCountsAndMovesRolesOutward) {
  Model m = Start(Params());
  const int n = m.lattice.nodes();
  EXPECT_EQ(m.f.layer[kS].born, -2);
  EXPECT_EQ(m.f.layer[kM1].born, -1);
  EXPECT_EQ(m.f.layer[kM2].born, 0);
  ASSERT_TRUE(RunCycle(&m));
  EXPECT_EQ(m.f.step, m.f.m.steps_per_cycle);
  const std::vector<float> m1_ux = m.f.layer[kM1].s.ux, m2_ux = m.f.layer[kM2].s.ux;
  const int m1_broken = m.f.layer[kM1].s.broken_count[0] + m.f.layer[kM1].s.broken_count[1];
  const int present = PresentNodes(m.f);
  ExchangeRoles(m.lattice, 1, &m.f);
  EXPECT_EQ(m.f.cycle, 1);
  // Every role moved one step outward: the old M1 is S (its state kept), the old M2 is M1.
  EXPECT_EQ(m.f.layer[kS].born, -1);
  EXPECT_EQ(m.f.layer[kM1].born, 0);
  EXPECT_EQ(m.f.layer[kM2].born, 1);
  EXPECT_EQ(m.f.layer[kS].s.ux, m1_ux);
  EXPECT_EQ(m.f.layer[kM1].s.ux, m2_ux);
  EXPECT_EQ(m.f.layer[kS].s.broken_count[0] + m.f.layer[kS].s.broken_count[1], m1_broken);
  // Node counts: every layer a full lattice, S whole again; what S had left is counted shed.
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(static_cast<int>(m.f.layer[r].s.ux.size()), n);
    EXPECT_EQ(static_cast<int>(m.f.layer[r].present.size()), n);
  }
  EXPECT_EQ(PresentNodes(m.f), n);
  EXPECT_EQ(m.f.shed_nodes, present);
  // The layout moved out: S's radius now is where M1's was (continuous through the exchange).
  const LayerGrowth after = LayerGrowthAt(m.f);
  EXPECT_NEAR(after.mid[kS], m.f.m.r_o + m.f.m.delta_r + 1.5 * m.f.m.cork, 1e-12);
  EXPECT_NEAR(after.mid[kM2], after.r_inner, 1e-12);
}

TEST(FourLayer, ANewLayerIsBornStressFreeWithFreshThresholds) {
  Model m = Start(Params());
  ASSERT_TRUE(RunCycle(&m));
  const std::vector<float> old_limits = m.f.layer[kM2].s.limit2;
  ExchangeRoles(m.lattice, 1, &m.f);
  const CorkLayer& born = m.f.layer[kM2];
  EXPECT_EQ(born.s.broken_count[0] + born.s.broken_count[1], 0);
  for (std::size_t i = 0; i < born.s.ux.size(); ++i) {
    EXPECT_EQ(born.s.ux[i], 0.0f);
    EXPECT_EQ(born.s.wz[i], 0.0f);
  }
  // Its springs at their rest lengths: the spring pass gives (next to) no force.
  const LayerGrowth lg = LayerGrowthAt(m.f);
  Surface copy = born.s;
  const float k[2] = {1e9f, 1e9f}, c[2] = {0, 0};
  const float rest[2] = {static_cast<float>(born.rest[0]), static_cast<float>(born.rest[1])};
  Growth still = lg.g[kM2];
  still.rate_theta = still.rate_z = 0;
  EXPECT_EQ(SpringForces(m.lattice, k, c, rest, still, &copy), 0);
  double worst = 0;
  for (float v : copy.fx) worst = std::max(worst, std::fabs(static_cast<double>(v)));
  for (float v : copy.fz) worst = std::max(worst, std::fabs(static_cast<double>(v)));
  EXPECT_LT(worst / (1e9 * m.lattice.l_o), 1e-6);  // force / (k·L_o): strain below 1e-6
  // Its bond to M1 is stress free too: M1's slip now is the bond's rest.
  const CorkLayer& m1 = m.f.layer[kM1];
  for (std::size_t i = 0; i < m1.bond_x.size(); ++i) EXPECT_EQ(m1.bond_x[i], m1.s.ux[i]);
  // Fresh thresholds from cycle 1's stream (not the old M2's, born at cycle 0).
  int same = 0;
  for (std::size_t i = 0; i < old_limits.size(); ++i) same += old_limits[i] == born.s.limit2[i];
  EXPECT_LT(same, static_cast<int>(old_limits.size()) / 10);
}

// Cuts every S spring with one end in the block of columns [2, 6) and rows [2, 6): a closed
// plate of 16 nodes.
std::vector<int> CutBlock(Model* m) {
  const Lattice& L = m->lattice;
  auto inside = [&L](int v) {
    const int i = v / L.n_h, j = v % L.n_h;
    return i >= 2 && i < 6 && j >= 2 && j < 6;
  };
  Surface& s = m->f.layer[kS].s;
  for (int sp = 0; sp < L.springs(); ++sp) {
    if (inside(L.a[sp]) != inside(L.b[sp])) {
      s.broken[sp] = 1;
      s.limit2[L.slot(sp)] = std::numeric_limits<float>::infinity();
    }
  }
  std::vector<int> block;
  for (int v = 0; v < L.nodes(); ++v)
    if (inside(v)) block.push_back(v);
  return block;
}

TEST(FourLayer, TheAreaRulePeelsABlockByA) {
  for (const double a : {1.0, 50.0}) {
    Model m = Start(Params(a));
    const std::vector<int> block = CutBlock(&m);
    ASSERT_EQ(block.size(), 16u);
    // One bond of the block broken: S_r/S_b = 16/15 > 1, not > 50.
    m.f.layer[kS].bonded[block[5]] = 0;
    CheckPeeling(m.lattice, &m.f);
    const bool peeled = m.f.layer[kS].present[block[0]] == 0;
    EXPECT_EQ(peeled, a == 1.0) << "A = " << a;
    // The rest of S (it wraps the torus) never peels by the rule.
    EXPECT_EQ(m.f.layer[kS].present[m.lattice.node(10, 1)], 1);
    if (peeled) {
      for (int v : block) EXPECT_EQ(m.f.layer[kS].present[v], 0);
      EXPECT_EQ(PresentNodes(m.f), m.lattice.nodes() - 16);
      // M1 shows where the block was.
      const std::vector<uint8_t> visible = VisibleLayer(m.lattice, m.f);
      int m1 = 0;
      for (uint8_t v : visible) m1 += v == kM1;
      EXPECT_GT(m1, 0);
    }
    // Every bond cut: the block peels whatever A is.
    for (int v : block) m.f.layer[kS].bonded[v] = 0;
    CheckPeeling(m.lattice, &m.f);
    EXPECT_EQ(m.f.layer[kS].present[block[0]], 0) << "A = " << a;
  }
}

TEST(FourLayer, TheShearLimitDecaysWithGammaNearACrackOnly) {
  for (const double gamma : {0.0, 1.0}) {
    Model m = Start(Params(2.0, gamma));
    const Lattice& L = m.lattice;
    CorkLayer& S = m.f.layer[kS];
    // One broken S spring: the axial spring of node (8, 4).
    const int sp = L.node(8, 4);
    S.s.broken[sp] = 1;
    const int near = L.node(8, 4), far = L.node(1, 0);
    CheckPeeling(L, &m.f);
    EXPECT_EQ(S.dry_step[near], 0);
    EXPECT_EQ(S.dry_step[far], -1);
    const float near0 = S.shear_limit2[near], far0 = S.shear_limit2[far];
    const double d = m.f.m.d;
    EXPECT_NEAR(std::sqrt(near0), S.kappa_h[near] * d, 1e-6);
    // One cycle later (the clock alone; nothing else moves).
    m.f.step += m.f.m.steps_per_cycle;
    CheckPeeling(L, &m.f);
    EXPECT_EQ(S.shear_limit2[far], far0);
    EXPECT_NEAR(std::sqrt(S.shear_limit2[near]), S.kappa_h[near] * d * std::exp(-gamma), 1e-6 * d)
        << "γ = " << gamma;
  }
}

BarkState FourLayerState(uint64_t seed = 1) {
  BarkState s;
  EXPECT_TRUE(SetBarkSpecies("pine", &s).ok());
  EXPECT_TRUE(SetBarkModel("4layer", &s).ok());
  EXPECT_TRUE(SetBarkSize("16x8", &s).ok());
  EXPECT_TRUE(SetBarkSeed(static_cast<double>(seed), &s).ok());
  EXPECT_TRUE(s.params.Set(BarkParam::kMapSize, 256).ok());
  EXPECT_TRUE(s.params.Set(BarkParam::kCycles, 3).ok());
  EXPECT_TRUE(s.params.Set(BarkParam::kT, 0.001).ok());
  EXPECT_TRUE(s.params.Set(BarkParam::kCork, 0.1).ok());
  EXPECT_TRUE(s.params.Set(BarkParam::kSettleSteps, 200).ok());
  return s;
}

TEST(FourLayer, ARunIsDeterministicAndReportsItsLayers) {
  auto grow = [](uint64_t seed) {
    Result<BarkRun> run = BarkRun::Start(FourLayerState(seed), Budget{});
    EXPECT_TRUE(run.ok());
    run->RecordFrames(true);
    EXPECT_TRUE(run->Advance({}).ok());
    return std::move(*run);
  };
  const BarkRun a = grow(1), b = grow(1), c = grow(2);
  EXPECT_EQ(a.StatsJson(), b.StatsJson());
  EXPECT_EQ(*a.MapPng("base_colour"), *b.MapPng("base_colour"));
  EXPECT_EQ(*a.MapPng("height"), *b.MapPng("height"));
  EXPECT_EQ(a.CyclesCsv(), b.CyclesCsv());
  EXPECT_NE(a.StatsJson(), c.StatsJson());
  const nlohmann::json j = nlohmann::json::parse(a.StatsJson());
  EXPECT_EQ(j["model"], "4layer");
  EXPECT_EQ(j["cycles"], 3);
  EXPECT_EQ(j["exchanges"], 2);
  EXPECT_EQ(j["springs"]["shear"], 3 * 128);
  const double exposed = j["exposed"]["S"].get<double>() + j["exposed"]["M1"].get<double>() +
                         j["exposed"]["M2"].get<double>() + j["exposed"]["I"].get<double>();
  EXPECT_NEAR(exposed, 1.0, 1e-12);
  EXPECT_GT(j["shed"]["area"].get<double>(), 0.0);
  EXPECT_EQ(j["layers"]["S"]["born"], 0);
  EXPECT_EQ(a.FramePngs().size(), 3u);
  EXPECT_EQ(a.steps(), 3 * a.layers().m.steps_per_cycle + 200);
  // Rows: the start, tenths, each cycle's end (and after each exchange), the end of settling.
  const std::string csv = a.CyclesCsv();
  EXPECT_EQ(csv.rfind("cycle,step,exchanges,", 0), 0u);
}

TEST(FourLayer, ACancelLeavesTheRunAsItWas) {
  Result<BarkRun> run = BarkRun::Start(FourLayerState(), Budget{});
  ASSERT_TRUE(run.ok());
  const std::string before = run->StatsJson();
  int calls = 0;
  EXPECT_TRUE(run::IsCancelled(run->Advance([&](const run::Progress&) { return ++calls < 9; })));
  EXPECT_EQ(run->steps(), 0);
  EXPECT_EQ(run->StatsJson(), before);
}

TEST(FourLayer, TheEstimateCountsThreeSpringLayers) {
  BarkState two = FourLayerState();
  two.model = "2layer";
  const BarkState four = FourLayerState();
  const Estimate e2 = EstimateBarkRun(two), e4 = EstimateBarkRun(four);
  EXPECT_GT(e4.memory_bytes, e2.memory_bytes);
  // Three layers and the shorter step of the stiffest layer: over three times the 2-layer's
  // spring-steps (the maps' share aside).
  BarkState big = FourLayerState();
  ASSERT_TRUE(SetBarkSize("128x64", &big).ok());
  ASSERT_TRUE(big.params.Set(BarkParam::kT, 0.01).ok());
  BarkState big2 = big;
  big2.model = "2layer";
  EXPECT_GT(EstimateBarkRun(big).seconds, 3.0 * EstimateBarkRun(big2).seconds * 0.9);
  // A long 4-layer run is refused up front, naming the budget.
  ASSERT_TRUE(big.params.Set(BarkParam::kCycles, 20).ok());
  const Result<BarkRun> refused = BarkRun::Start(big, Budget{});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().field(), "max_seconds");
}

}  // namespace
}  // namespace niwa::bark
