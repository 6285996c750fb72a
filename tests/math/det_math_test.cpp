// Tests of the deterministic math functions against the platform's libm.
#include "math/det_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

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

// The series are truncated for the widest reduced argument: check there, where the first left-out
// term is largest (|r| = ln2/2 for exp, m = √2 for log, |r| = π/4 for sin and cos, |x| = 1 for
// atan before its two halvings).
TEST(DetMath, SeriesHoldAtTheEdgesOfTheirReducedRanges) {
  for (int k = -20; k <= 20; ++k) {
    for (double r : {-0.5 * det::kLn2, 0.5 * det::kLn2}) {
      for (double nudge : {-1e-9, 0.0, 1e-9}) {
        double x = k * det::kLn2 + r + nudge;
        EXPECT_NEAR(det::Exp(x), std::exp(x), 2e-15 * std::exp(x)) << x;
      }
    }
  }
  for (double m : {0.70710678118654752440, 1.41421356237309504880, 1.0 + 1e-12, 1.0 - 1e-12}) {
    for (int e = -30; e <= 30; e += 3) {
      double x = std::ldexp(m, e);
      EXPECT_NEAR(det::Log(x), std::log(x), 2e-15 * std::max(1.0, std::fabs(std::log(x)))) << x;
    }
  }
  for (int q = -4; q <= 4; ++q) {  // small |q|: little argument-reduction error
    for (double nudge : {-1e-9, 0.0, 1e-9}) {
      double x = (q + 0.5) * det::kPi / 2.0 + nudge;
      double s = 0, c = 0;
      det::SinCos(x, &s, &c);
      EXPECT_NEAR(s, std::sin(x), 1e-15) << x;
      EXPECT_NEAR(c, std::cos(x), 1e-15) << x;
    }
  }
  for (double x : {-1.0, -0.999999, 0.999999, 1.0}) {
    EXPECT_NEAR(det::Atan2(x, 1.0), std::atan2(x, 1.0), 1e-15) << x;
  }
}

}  // namespace
}  // namespace niwa

namespace niwa {
namespace {

// The batched exp (SIMD where available) gives Expf's result bit for bit.
TEST(DetMath, ExpfInPlaceMatchesExpf) {
  std::vector<float> inputs = {0.0f,       -0.0f,       1e-30f,   -1e-30f, 0.5f,   -0.5f,
                               0.3465736f, -0.3465736f, 1.0f,     -1.0f,   -88.0f, 88.0f,
                               -699.9f,    -700.0f,     -700.1f,  -800.0f, 699.9f, 700.0f,
                               700.1f,     800.0f,      -103.97f, -87.33f, 1e-8f,  -3.0f};
  uint64_t state = 12345;
  for (int i = 0; i < 200000; ++i) {  // spread over [-800, 800] and densely over [-20, 0]
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    float u = static_cast<float>(state >> 40) / static_cast<float>(1 << 24);
    inputs.push_back(i % 2 == 0 ? -800.0f + 1600.0f * u : -20.0f * u);
  }
  std::vector<float> batch = inputs;
  det::ExpfInPlace(batch.data(), batch.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    float expected = det::Expf(inputs[i]);
    uint32_t a, b;
    std::memcpy(&a, &batch[i], sizeof a);
    std::memcpy(&b, &expected, sizeof b);
    ASSERT_EQ(a, b) << "x = " << inputs[i];
  }
}

// The batched slope angle (SIMD where available) gives Atan2(y, 1)'s bits, on both sides of 1.
TEST(DetMath, AtanOfNonNegativeInPlaceMatchesAtan2) {
  std::vector<double> inputs = {0.0,          1e-300,
                                1e-12,        0.25,
                                0.5,          std::nextafter(1.0, 0.0),
                                1.0,          std::nextafter(1.0, 2.0),
                                1.5,          4.0,
                                1e6,          1e300,
                                0.41421356237};
  uint64_t state = 987;
  for (int i = 0; i < 200000; ++i) {  // gradients of real terrain (0..3) and far beyond
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = static_cast<double>(state >> 11) / 9007199254740992.0;
    inputs.push_back(i % 4 == 0 ? u * 1e4 : 3.0 * u);
  }
  std::vector<double> batch = inputs;
  det::AtanOfNonNegativeInPlace(batch.data(), batch.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const double expected = det::Atan2(inputs[i], 1.0);
    uint64_t a, b;
    std::memcpy(&a, &batch[i], sizeof a);
    std::memcpy(&b, &expected, sizeof b);
    ASSERT_EQ(a, b) << "y = " << inputs[i];
  }
}

}  // namespace
}  // namespace niwa
