// Fig. 7 as equations (spec §4.4 E4): r_I linear, M2's thickness a saw-tooth 0 → D, every layer's
// boundaries continuous through the role exchange at t = kT, the outer surface r_I + D·τ + 2D, and
// the layers' identities moving one role outward a cycle.
#include "bark/layers.h"

#include <gtest/gtest.h>

#include "bark/bark_state.h"

namespace niwa::bark {
namespace {

TEST(Layers, Fig7AsEquations) {
  const BarkParams p = *BarkPreset("pine");
  const std::vector<LayerRadii> rows = LayerTimeline(p, 3, 10);
  ASSERT_EQ(rows.size(), 3u * 11 + 1);
  const double r_o = rows.front().r_inner, d = p.Get(BarkParam::kD), T = p.Get(BarkParam::kT);
  const double delta_r = p.Get(BarkParam::kDeltaR) * r_o;
  EXPECT_NEAR(r_o, 5.822033, 1e-6);
  for (const LayerRadii& r : rows) {
    EXPECT_NEAR(r.r_inner, r_o + delta_r * r.t / T, 1e-9) << r.t;  // linear: constant ring width
    EXPECT_NEAR(r.m2_out - r.r_inner, d * r.tau, 1e-12) << r.t;    // the saw-tooth
    EXPECT_NEAR(r.m1_out - r.m2_out, d, 1e-12);
    EXPECT_NEAR(r.s_out, r.r_inner + d * r.tau + 2 * d, 1e-12);  // the outer surface
  }
  // At each t = kT: the row before (τ = 1) and after (τ = 0) the exchange.
  for (int k = 1; k <= 3; ++k) {
    const LayerRadii& before = rows[k * 11 - 1];
    const LayerRadii& after = rows[k * 11];
    ASSERT_DOUBLE_EQ(before.tau, 1.0);
    ASSERT_DOUBLE_EQ(after.tau, 0.0);
    EXPECT_NEAR(before.t, after.t, 1e-15);
    EXPECT_NEAR(after.r_inner, before.r_inner, 1e-9);
    // The old M2 is the new M1, the old M1 the new S, with the same boundaries.
    EXPECT_EQ(after.born_m1, before.born_m2);
    EXPECT_EQ(after.born_s, before.born_m1);
    EXPECT_NEAR(after.m1_out, before.m2_out, 1e-9);    // its outer boundary
    EXPECT_NEAR(after.r_inner, before.r_inner, 1e-9);  // its inner boundary: r_I either side
    EXPECT_NEAR(after.s_out, before.m1_out, 1e-9);
    EXPECT_EQ(after.born_m2, k);  // a new M2, born now, thickness 0
    EXPECT_NEAR(after.m2_out, after.r_inner, 1e-12);
  }
  const LayerRadii mid = LayerRadiiAt(1.5 * T, r_o, delta_r, d, T);
  EXPECT_EQ(mid.cycle, 1);
  EXPECT_NEAR(mid.tau, 0.5, 1e-12);
  const std::string csv = LayerTimelineCsv(rows);
  EXPECT_EQ(csv.rfind("t,cycle,tau,r_I,M2_out,M1_out,S_out,born_M2,born_M1,born_S\n", 0), 0u);
}

}  // namespace
}  // namespace niwa::bark
