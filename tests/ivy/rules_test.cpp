// Ivy rules p0-p3 and the nutrient ledger (E1-E5) on the free scene (no support, RNG-free): the
// spec's replay numbers, the hand-computed arithmetic, the ledger, the binary-tree invariants.
#include <gtest/gtest.h>

#include "ivy/growth.h"
#include "ivy/ivy_report.h"
#include "ivy/lstring.h"

namespace niwa::ivy {
namespace {

struct RulesRun {
  IvyModel model;
  GrowLog log;
  IvyStats stats;
};

RulesRun GrowFree(const IvyParams& p, int steps) {
  RulesRun r;
  Result<IvyModel> m = Grow(Support{}, {glm::dvec3(0.0)}, p, steps, 1, &r.log);
  EXPECT_TRUE(m.ok()) << m.status().Line();
  r.model = *m;
  r.stats = MeasureIvy(r.model, r.log, nullptr, p);
  return r;
}

TEST(IvyRules, FreeReplayMatchesTheSpecTable) {
  RulesRun r = GrowFree(IvyParams(), 50);
  const int internodes[] = {4, 7, 14, 28, 50};
  const int laterals[] = {0, 0, 2, 6, 9};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(InternodesAt(r.model, 10 * (i + 1)), internodes[i]) << "step " << 10 * (i + 1);
    EXPECT_EQ(LateralsAt(r.model, 10 * (i + 1)), laterals[i]) << "step " << 10 * (i + 1);
  }
  EXPECT_EQ(r.stats.main_axis_internodes, 18);
  EXPECT_EQ(r.stats.buds_A, 10);
  EXPECT_EQ(r.stats.buds_D, 32);
  EXPECT_EQ(r.stats.buds_Z, 9);
  EXPECT_EQ(r.stats.first_break_step, 25);
  std::vector<int> p1_steps;
  for (std::size_t s = 0; s < r.log.steps.size(); ++s)
    for (int k = 0; k < r.log.steps[s].p1; ++k) p1_steps.push_back(static_cast<int>(s) + 1);
  EXPECT_EQ(p1_steps, (std::vector<int>{25, 28, 31, 34, 37, 39, 42, 45, 48}));
  // C4: the nine laterals' p0 internodes against the main axis's in the same steps after each
  // break (5/9, 4/8, 4/7, 3/6, 3/5, 2/4, 1/3, 1/2, 0/1 = 23/45).
  EXPECT_NEAR(r.stats.rho, 23.0 / 45.0, 1e-12);
  EXPECT_EQ(r.stats.rho_laterals, 9);
  EXPECT_EQ(r.stats.lateral_longer_than_parent, 0);
  EXPECT_LT(r.stats.ledger_err, 1e-12);
}

TEST(IvyRules, LiteralPresetLateralsOutgrowTheirParents) {
  RulesRun r = GrowFree(*IvyPreset("literal"), 50);
  EXPECT_EQ(r.stats.internodes, 279);
  EXPECT_EQ(r.stats.laterals, 30);
  EXPECT_EQ(r.stats.first_break_step, 24);
  // Without the cost and the per-order damping the laterals outgrow their parents (216 / 175).
  EXPECT_NEAR(r.stats.rho, 216.0 / 175.0, 1e-12);
  EXPECT_GT(r.stats.rho, 1.0);
  EXPECT_GT(r.stats.lateral_longer_than_parent, 0);
}

TEST(IvyRules, P0AndP1ArithmeticByHand) {
  // The seed starts at N0 = t1 = 0.2: p0 at step 1 leaves 0 for both. A then accumulates
  // 0.12 per step (steps 2, 3) to 0.24, and p0 at step 4 gives A 0.75 * 0.04, D 0.25 * 0.04.
  RulesRun r = GrowFree(IvyParams(), 4);
  ASSERT_EQ(r.model.internodes.size(), 2u);
  const Bud& apex = r.model.buds[2];
  const Bud& dormant = r.model.buds[1];
  EXPECT_EQ(apex.kind, BudKind::kApical);
  EXPECT_NEAR(apex.N, 0.03, 1e-12);
  EXPECT_EQ(dormant.kind, BudKind::kDormant);
  EXPECT_NEAR(dormant.N, 0.01, 1e-12);
  // The first D (bud 0) accumulated 0.035 in steps 2..4 from 0.
  EXPECT_NEAR(r.model.buds[0].N, 3 * 0.035, 1e-12);
  // At step 25 bud 0 holds 23 * 0.035 = 0.805 >= t2: p1 gives the lateral apex 0.005, Z gets 0.
  RulesRun r25 = GrowFree(IvyParams(), 25);
  const Bud& z = r25.model.buds[0];
  ASSERT_EQ(z.kind, BudKind::kEnding);
  ASSERT_GE(z.child[1], 0);
  EXPECT_EQ(z.N, 0.0);
  EXPECT_NEAR(r25.model.buds[static_cast<std::size_t>(z.child[1])].N, 0.005, 1e-12);
}

TEST(IvyRules, LedgerHoldsEveryStepAndIsNotVacuous) {
  for (const char* preset : {"paper", "literal"}) {
    RulesRun r = GrowFree(*IvyPreset(preset), std::string(preset) == "paper" ? 100 : 60);
    double prev = r.log.nutrient_start, in = 0, out = 0;
    for (const StepLog& st : r.log.steps) {
      EXPECT_NEAR(st.nutrient_total, prev + st.accumulated - st.spent - st.lost, 1e-12);
      prev = st.nutrient_total;
      in += st.accumulated;
      out += st.spent + st.lost;
    }
    // in = out + held, and all three are non-trivial.
    EXPECT_NEAR(r.log.nutrient_start + in, out + prev, 1e-9);
    EXPECT_GT(in, 1.0);
    EXPECT_GT(prev, 0.0);
  }
}

TEST(IvyRules, BinaryTreeInvariantsHold) {
  RulesRun r = GrowFree(IvyParams(), 80);
  const IvyModel& m = r.model;
  EXPECT_EQ(m.buds.size(), m.internodes.size() + 1);
  for (const Bud& b : m.buds) {
    if (b.kind == BudKind::kApical) {
      EXPECT_EQ(b.child[0], -1);
      EXPECT_EQ(b.child[1], -1);
    }
    if (b.kind == BudKind::kDormant) {
      EXPECT_GE(b.child[0], 0);
      EXPECT_EQ(b.child[1], -1);
    }
    if (b.child[1] >= 0) {
      EXPECT_EQ(b.kind, BudKind::kEnding);
    }
    for (int c : b.child) {
      if (c >= 0) {
        EXPECT_EQ(m.buds[static_cast<std::size_t>(c)].parent, b.id);
      }
    }
  }
}

TEST(IvyRules, HostileInputIsOneLineNamingTheField) {
  IvyParams p;
  ASSERT_TRUE(p.Set(IvyParam::kT1, 0.9).ok());
  Result<IvyModel> m = Grow(Support{}, {glm::dvec3(0.0)}, p, 10, 1, nullptr);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().field(), "t1");
  EXPECT_NE(m.status().Line().find("t2"), std::string::npos);
  m = Grow(Support{}, {glm::dvec3(0.0)}, IvyParams(), -1, 1, nullptr);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().Line(), "steps: -1 is out of range; must be a whole number in [0, 10000]");
  EXPECT_FALSE(IvyParams().Set(IvyParam::kL, std::nan("")).ok());
  EXPECT_EQ(IvyPreset("nope").status().field(), "preset");
}

TEST(IvyLString, RoundTripGivesTheStoredInternodes) {
  RulesRun r = GrowFree(IvyParams(), 50);
  const std::string text = PrintLString(r.model);
  LStringCounts c = CountSymbols(text);
  EXPECT_EQ(c.A, 10);
  EXPECT_EQ(c.D, 32);
  EXPECT_EQ(c.Z, 9);
  EXPECT_EQ(c.I, 50);
  EXPECT_EQ(c.open, c.close);
  EXPECT_EQ(c.open, 9);
  EXPECT_EQ(c.R, 9);
  EXPECT_TRUE(LStringMatchesModel(r.model));
  auto drawn = InterpretLString(text);
  ASSERT_TRUE(drawn.ok());
  EXPECT_EQ(drawn->size(), 50u);
  // A changed coordinate no longer matches; a broken string is an error.
  IvyModel changed = r.model;
  changed.buds[5].pos.x += 1e-9;
  std::string other = PrintLString(changed);
  EXPECT_NE(other, text);
  EXPECT_FALSE(InterpretLString("A(0,0,0;0)I[").ok());
  EXPECT_FALSE(InterpretLString("A(0,0,0;0)]").ok());
}

}  // namespace
}  // namespace niwa::ivy
