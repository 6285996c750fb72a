// Tests of the deterministic math functions against the platform's libm.
#include "math/det_math.h"

#include <gtest/gtest.h>

#include <cmath>

namespace niwa {
namespace {

TEST(DetMath, ExpAndLogMatchLibm) {
  for (double x = -30.0; x <= 30.0; x += 0.0137) {
    EXPECT_NEAR(det::Exp(x), std::exp(x), 1e-14 * std::exp(x)) << x;
  }
  EXPECT_EQ(det::Exp(-800.0), 0.0);
  for (double x = 1e-6; x < 1e6; x *= 1.37) {
    EXPECT_NEAR(det::Log(x), std::log(x), 1e-14 * std::max(1.0, std::fabs(std::log(x)))) << x;
  }
  EXPECT_EQ(det::Log(1.0), 0.0);
}

TEST(DetMath, TrigonometryMatchesLibm) {
  for (double x = -20.0; x <= 20.0; x += 0.0093) {
    EXPECT_NEAR(det::Sin(x), std::sin(x), 1e-14) << x;
    EXPECT_NEAR(det::Cos(x), std::cos(x), 1e-14) << x;
  }
  for (double x = -1.0; x <= 1.0; x += 0.001) {
    EXPECT_NEAR(det::Acos(x), std::acos(x), 1e-12) << x;
  }
  for (double y = -3.0; y <= 3.0; y += 0.25) {
    for (double x = -3.0; x <= 3.0; x += 0.25) {
      EXPECT_NEAR(det::Atan2(y, x), std::atan2(y, x), 1e-14) << y << "," << x;
    }
  }
  EXPECT_EQ(det::Acos(1.5), 0.0);
  EXPECT_DOUBLE_EQ(det::Acos(-1.0), det::kPi);
}

}  // namespace
}  // namespace niwa
