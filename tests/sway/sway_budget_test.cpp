// The page's sway in time (core/sway/sway_budget: EstimatePageSwayTime, CheckPageSwayTime): the
// steps of one worker tick within the page's tick estimate, the share of real time, the refusal
// lines; the same numbers natively and in WASM (counts times constants).
#include "sway/sway_budget.h"

#include <gtest/gtest.h>

#include <string>

#include "support/grow.h"

namespace niwa {
namespace {

// A model with `internodes` internodes (the page's estimate reads only the count).
SwayModel ModelOf(int internodes) {
  SwayModel m;
  m.internodes = internodes;
  return m;
}

SwayParams ParamsAt(double dt) {
  SwayParams p;
  p.dt = dt;
  return p;
}

TEST(PageSwayTime, SmallTreeTakesEightStepsATickInRealTime) {
  const Tree tree = testing::GrowPreset("sakura", 8);
  const SwayParams params;  // dt 1/30 s
  const SwayModel model = BuildSwayModel(tree, params);
  const PageSwayTime t = EstimatePageSwayTime(model, params, 1);
  EXPECT_DOUBLE_EQ(t.step_seconds, 90e-9 * static_cast<double>(model.internodes));
  EXPECT_EQ(t.steps_per_tick, kPageSwayMaxStepsPerTick);
  EXPECT_EQ(t.speed, 1.0);
  EXPECT_TRUE(CheckPageSwayTime(t, model, params, 1, "page time budget", "raise dt").ok());
}

TEST(PageSwayTime, StepsATickAreLoweredToFitTheTick) {
  // 400,000 internodes (the page's cap): 36 ms a step, 8 steps would be 0.29 s > 0.25 s.
  const SwayModel model = ModelOf(400000);
  const PageSwayTime t = EstimatePageSwayTime(model, ParamsAt(1.0 / 30), 1);
  EXPECT_NEAR(t.step_seconds, 0.036, 1e-12);
  EXPECT_EQ(t.steps_per_tick, 6);  // floor(0.25 / 0.036)
  EXPECT_LE(t.steps_per_tick * t.step_seconds, kPageSwayTickSeconds);
  EXPECT_NEAR(t.speed, (1.0 / 30) / 0.036, 1e-12);  // 0.93 of real time: sways, a little slow
  EXPECT_TRUE(CheckPageSwayTime(t, model, ParamsAt(1.0 / 30), 1, "page time budget", "x").ok());
  // The 100-year sakura at the page budget (194,948 internodes): 17.5 ms, 8 steps = 0.14 s.
  const PageSwayTime big = EstimatePageSwayTime(ModelOf(194948), ParamsAt(1.0 / 30), 1);
  EXPECT_EQ(big.steps_per_tick, 8);
  EXPECT_EQ(big.speed, 1.0);
}

TEST(PageSwayTime, TooSlowForRealTimeIsRefusedWithTheLine) {
  // 40,000 internodes at dt 0.0005 s: 3.6 ms a step of 0.5 ms, 1/7 of real time.
  const SwayModel model = ModelOf(40000);
  const SwayParams params = ParamsAt(0.0005);
  const PageSwayTime t = EstimatePageSwayTime(model, params, 1);
  EXPECT_EQ(t.steps_per_tick, 8);
  const Status s =
      CheckPageSwayTime(t, model, params, 1, "page time budget", "raise dt, or lower years");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.Line(),
            "page time budget: swaying 1 tree of 40,000 internodes takes about 3.6 ms a step of dt "
            "0.0005 s: 1/7 of real time, slower than the 1/4 allowed; raise dt, or lower years");
  // At dt 0.001 s (1/3.6 of real time) it sways.
  const PageSwayTime quarter = EstimatePageSwayTime(model, ParamsAt(0.001), 1);
  EXPECT_TRUE(CheckPageSwayTime(quarter, model, ParamsAt(0.001), 1, "l", "c").ok());
}

TEST(PageSwayTime, AStepOverTheTickIsRefused) {
  // The grove's instances: 4,096 trees of 10,000 internodes, 3.7 s a step.
  const SwayModel model = ModelOf(10000);
  const SwayParams params = ParamsAt(0.1);
  const PageSwayTime t = EstimatePageSwayTime(model, params, 4096);
  EXPECT_EQ(t.steps_per_tick, 1);
  const Status s = CheckPageSwayTime(t, model, params, 4096, "page time budget",
                                     "raise dt, or lower years or the number of trees");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.Line(),
            "page time budget: swaying 4,096 trees of 10,000 internodes takes about 3.69 s a step, "
            "more than the 0.25 s a worker tick may take (a click must answer within 1 s); raise "
            "dt, or lower years or the number of trees");
  // The grove's own 10 instances of its largest tree (10,966 internodes): 9.9 ms, 8 a tick.
  const PageSwayTime grove = EstimatePageSwayTime(ModelOf(10966), ParamsAt(1.0 / 30), 10);
  EXPECT_EQ(grove.steps_per_tick, 8);
  EXPECT_TRUE(CheckPageSwayTime(grove, ModelOf(10966), ParamsAt(1.0 / 30), 10, "l", "c").ok());
}

}  // namespace
}  // namespace niwa
