// det_math's functions on SIMD lanes (simd::Double2, and simd::Float4 for the float conveniences):
// every lane gives the scalar function's bits. The series are det_math.h's own templates
// (ExpSeriesOf, SinCosSeriesOf, AtanUnitOf: one set of coefficients); what differs is written here
// once: std::floor becomes adding and subtracting 1.5·2^52, the branches become masks, the
// quadrant comes from the low bits of the rounded value. tests/math/det_math_lanes_test.cpp checks
// lane against scalar, bit for bit.
// Not here: Log (no lane version yet), arguments outside each function's stated range (NaN, or
// |x| of 2^51 and beyond for Floor), any batching policy (callers pick where lanes pay, NIWA_SIMD).
#pragma once

#include <cstddef>
#include <cstdint>

#include "math/det_math.h"
#include "math/simd4.h"

namespace niwa {
namespace det {

using simd::Double2;
using simd::Float4;
using simd::Long2;

constexpr double kRoundToInteger = 6755399441055744.0;  // 1.5·2^52: y + it - it rounds y

// std::floor(y) for |y| < 2^51, lane by lane, bit for bit (also -0.0).
inline Double2 Floor(Double2 y) {
  const Double2 nearest = (y + kRoundToInteger) - kRoundToInteger;
  const Long2 one = {0x3FF0000000000000, 0x3FF0000000000000};  // 1.0
  const Double2 floor = nearest - (Double2)((Long2)(nearest > y) & one);
  return simd::Select((Long2)(y == 0.0), y, floor);  // keeps -0.0 (floor gives +0.0 there)
}

// det::Exp for finite x.
inline Double2 Exp(Double2 x) {
  const Long2 tiny = (Long2)(x < -700.0);  // Exp: 0
  x = simd::Select((Long2)(x > 700.0), simd::Splat2(700.0), x);
  const Double2 k = Floor(x / kLn2 + 0.5);
  const Double2 r = x - k * kLn2;
  const Double2 sum = ExpSeriesOf(r);
  // Pow2(k): k + 1023 into the exponent field, from the low bits of k + 1023 + 1.5·2^52.
  const Long2 biased = (Long2)(k + (1023.0 + kRoundToInteger)) & 0x7FF;
  const Double2 scaled = sum * (Double2)(biased << 52);
  return (Double2)((Long2)scaled & ~tiny);
}

// det::SinCos for |x| < 2^51·π/2.
inline void SinCos(Double2 x, Double2* s, Double2* c) {
  const Double2 q = Floor(x / (kPi / 2.0) + 0.5);
  const Double2 r = x - q * (kPi / 2.0);
  Double2 sin_r, cos_r;
  SinCosSeriesOf(r, &sin_r, &cos_r);
  // Quadrant q & 3 from the low bits of q + 1.5·2^52 (2^51 is a multiple of 4).
  const Long2 quadrant = (Long2)(q + kRoundToInteger) & 3;
  const Long2 swap = -(quadrant & 1), sin_negative = -((quadrant >> 1) & 1);
  const Long2 cos_negative = -((quadrant ^ (quadrant >> 1)) & 1);
  const Double2 s0 = simd::Select(swap, cos_r, sin_r), c0 = simd::Select(swap, sin_r, cos_r);
  *s = simd::Select(sin_negative, -s0, s0);
  *c = simd::Select(cos_negative, -c0, c0);
}

inline Double2 AtanUnit(Double2 x) {
  return AtanUnitOf(x, [](Double2 v) { return simd::Sqrt(v); });
}

// det::Atan2 for finite y and x.
inline Double2 Atan2(Double2 y, Double2 x) {
  const Long2 abs_mask = {0x7FFFFFFFFFFFFFFF, 0x7FFFFFFFFFFFFFFF};
  const Double2 ax = (Double2)((Long2)x & abs_mask), ay = (Double2)((Long2)y & abs_mask);
  const Long2 flat = (Long2)(ay <= ax);
  const Double2 a = AtanUnit(simd::Select(flat, ay, ax) / simd::Select(flat, ax, ay));
  Double2 angle = simd::Select(flat, a, kPi / 2.0 - a);
  angle = simd::Select((Long2)(x < 0.0), kPi - angle, angle);
  angle = simd::Select((Long2)(y < 0.0), -angle, angle);
  return simd::Select((Long2)(x == 0.0) & (Long2)(y == 0.0), simd::Splat2(0.0), angle);
}

// det::Acos for finite x (x >= 1 gives 0, x <= -1 gives π, as the scalar).
inline Double2 Acos(Double2 x) {
  const Double2 angle = Atan2(simd::Sqrt((1.0 - x) * (1.0 + x)), x);
  const Double2 low = simd::Select((Long2)(x >= 1.0), simd::Splat2(0.0), angle);
  return simd::Select((Long2)(x <= -1.0), simd::Splat2(kPi), low);
}

// The float conveniences (det::Acosf, det::Sinf and det::Cosf) on four lanes: each lane widened to
// double, the double function, rounded back to float, as the scalar ones.
inline Float4 Acosf(Float4 x) {
  const Double2 low = Acos(Double2{x[0], x[1]}), high = Acos(Double2{x[2], x[3]});
  return Float4{static_cast<float>(low[0]), static_cast<float>(low[1]), static_cast<float>(high[0]),
                static_cast<float>(high[1])};
}
inline void SinCosf(Float4 x, Float4* s, Float4* c) {
  Double2 s_low, c_low, s_high, c_high;
  SinCos(Double2{x[0], x[1]}, &s_low, &c_low);
  SinCos(Double2{x[2], x[3]}, &s_high, &c_high);
  *s = Float4{static_cast<float>(s_low[0]), static_cast<float>(s_low[1]),
              static_cast<float>(s_high[0]), static_cast<float>(s_high[1])};
  *c = Float4{static_cast<float>(c_low[0]), static_cast<float>(c_low[1]),
              static_cast<float>(c_high[0]), static_cast<float>(c_high[1])};
}

// Atan2(y[i], 1.0) in place for finite y[i] >= 0 (a slope angle from a gradient length), two
// lanes at a time where there is SIMD.
inline void AtanOfNonNegativeInPlace(double* y, std::size_t n) {
  std::size_t i = 0;
#if NIWA_SIMD
  for (; i + 2 <= n; i += 2) {
    const Double2 r = Atan2(Double2{y[i], y[i + 1]}, simd::Splat2(1.0));
    y[i] = r[0];
    y[i + 1] = r[1];
  }
#endif
  for (; i < n; ++i) y[i] = det::Atan2(y[i], 1.0);
}

// values[i] = Expf(values[i]) for finite values[i], i < n, two at a time where there is SIMD.
inline void ExpfInPlace(float* values, std::size_t n) {
  std::size_t i = 0;
#if NIWA_SIMD
  for (; i + 2 <= n; i += 2) {
    const Double2 out =
        Exp(Double2{static_cast<double>(values[i]), static_cast<double>(values[i + 1])});
    values[i] = static_cast<float>(out[0]);
    values[i + 1] = static_cast<float>(out[1]);
  }
#endif
  for (; i < n; ++i) values[i] = Expf(values[i]);
}

}  // namespace det
}  // namespace niwa
