// Deterministic exp, log, sin, cos, acos, atan2: only +, -, *, / and sqrt (exact in IEEE 754), so
// the native and WASM builds give bit-identical results, unlike glibc's and musl's libm. The series
// are evaluated by Estrin's scheme (pairs of terms combined with x², x⁴, x⁸: a short dependency
// chain) with their coefficients written out as double literals (1/n! and 1/n rounded once, by the
// compiler): multiplications and additions only, no division per term. Each series is written once,
// as a template over the scalar or lane type, so det_math_lanes.h's lanes use the same coefficients
// and operations.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace niwa {
namespace det {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLn2 = 0.69314718055994530942;

// 2^k for -1022 <= k <= 1023, built from its bit pattern (exact).
inline double Pow2(int k) {
  uint64_t bits = static_cast<uint64_t>(k + 1023) << 52;
  double out;
  std::memcpy(&out, &bits, sizeof out);
  return out;
}

// The series of e^r on |r| <= ln2/2: 1 + r + r²/2! + ... + r^14/14! (its next term is below 4e-18
// relative). Written once for a scalar and for SIMD lanes (T = double or simd::Double2,
// math/det_math_lanes.h): each lane does the scalar's IEEE operations in the same order.
template <typename T>
inline T ExpSeriesOf(T r) {
  // p = Σ r^(n-2)/n! for n = 2..14, by Estrin's scheme.
  T r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  T q0 = 0.5 + 0.16666666666666666 * r, q1 = 0.041666666666666664 + 0.008333333333333333 * r;
  T q2 = 0.001388888888888889 + 0.0001984126984126984 * r;
  T q3 = 2.48015873015873e-05 + 2.7557319223985893e-06 * r;
  T q4 = 2.755731922398589e-07 + 2.505210838544172e-08 * r;
  T q5 = 2.08767569878681e-09 + 1.6059043836821613e-10 * r;
  const double q6 = 1.1470745597729725e-11;
  T p = ((q0 + q1 * r2) + (q2 + q3 * r2) * r4) + ((q4 + q5 * r2) + q6 * r4) * r8;
  return 1.0 + r * (1.0 + r * p);
}

// e^x for |x| < ~700: x = k·ln2 + r, |r| <= ln2/2, then ExpSeriesOf(r)·2^k.
inline double Exp(double x) {
  if (x < -700.0) return 0.0;
  if (x > 700.0) x = 700.0;  // |k| <= 1010: Pow2 stays in range
  double k = std::floor(x / kLn2 + 0.5);
  double r = x - k * kLn2;
  double sum = ExpSeriesOf(r);
  return sum * Pow2(static_cast<int>(k));  // exact scaling by 2^k
}

// ln x for x > 0: x = m·2^e with m in [√½, √2), ln m = 2·atanh((m-1)/(m+1)) by its series
// t + t³/3 + ... + t²³/23, |t| <= 0.172 (next term below 1e-18 relative).
inline double Log(double x) {
  if (!(x > 0.0)) return -HUGE_VAL;
  int e = 0;
  double m = std::frexp(x, &e);  // exact: m in [0.5, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  double t = (m - 1.0) / (m + 1.0), t2 = t * t;
  // p = Σ t2^(k-1)/(2k+1) for k = 1..11, by Estrin's scheme.
  double t4 = t2 * t2, t8 = t4 * t4;
  double p =
      (((0.3333333333333333 + 0.2 * t2) + (0.14285714285714285 + 0.1111111111111111 * t2) * t4) +
       ((0.09090909090909091 + 0.07692307692307693 * t2) +
        (0.06666666666666667 + 0.058823529411764705 * t2) * t4) *
           t8) +
      ((0.05263157894736842 + 0.047619047619047616 * t2) + 0.043478260869565216 * t4) * (t8 * t8);
  double sum = t + t * (t2 * p);
  return 2.0 * sum + e * kLn2;
}

// sin r and cos r on |r| <= π/4 by their Taylor series to r^19 and r^20 (next terms below 1e-19).
// Written once for a scalar and for SIMD lanes, as ExpSeriesOf.
template <typename T>
inline void SinCosSeriesOf(T r, T* sin_r, T* cos_r) {
  T r2 = r * r;
  // ps = Σ (-1)^n r2^(n-1)/(2n+1)! for n = 1..9, pc = Σ (-1)^n r2^(n-1)/(2n)! for n = 1..10, by
  // Estrin's scheme.
  T r4 = r2 * r2, r8 = r4 * r4;
  T ps = ((-0.16666666666666666 + 0.008333333333333333 * r2) +
          (-0.0001984126984126984 + 2.7557319223985893e-06 * r2) * r4) +
         ((-2.505210838544172e-08 + 1.6059043836821613e-10 * r2) +
          (-7.647163731819816e-13 + 2.8114572543455206e-15 * r2) * r4) *
             r8 +
         -8.22063524662433e-18 * (r8 * r8);
  T pc = ((-0.5 + 0.041666666666666664 * r2) +
          (-0.001388888888888889 + 2.48015873015873e-05 * r2) * r4) +
         ((-2.755731922398589e-07 + 2.08767569878681e-09 * r2) +
          (-1.1470745597729725e-11 + 4.779477332387385e-14 * r2) * r4) *
             r8 +
         (-1.5619206968586225e-16 + 4.110317623312165e-19 * r2) * (r8 * r8);
  *sin_r = r + r * (r2 * ps);
  *cos_r = 1.0 + r2 * pc;
}

// sin and cos of x (radians) by reduction to r in [-π/4, π/4] (x = q·π/2 + r), SinCosSeriesOf(r),
// and the quadrant q mod 4.
inline void SinCos(double x, double* s, double* c) {
  double q = std::floor(x / (kPi / 2.0) + 0.5);
  double r = x - q * (kPi / 2.0);
  double sin_r, cos_r;
  SinCosSeriesOf(r, &sin_r, &cos_r);
  int quadrant = static_cast<int>(static_cast<int64_t>(q) & 3);  // two's complement: also for q < 0
  switch (quadrant) {
    case 0:
      *s = sin_r;
      *c = cos_r;
      break;
    case 1:
      *s = cos_r;
      *c = -sin_r;
      break;
    case 2:
      *s = -sin_r;
      *c = -cos_r;
      break;
    default:
      *s = -cos_r;
      *c = sin_r;
      break;
  }
}
inline double Sin(double x) {
  double s, c;
  SinCos(x, &s, &c);
  return s;
}
inline double Cos(double x) {
  double s, c;
  SinCos(x, &s, &c);
  return c;
}

// atan of |x| <= 1 after two argument halvings, atan(x) = 2·atan(x / (1 + √(1 + x²))), then its
// series x - x³/3 + ... + x²⁵/25 on |x| <= tan(π/16) (next term below 1e-18 relative).
// Written once for a scalar and for SIMD lanes (T = double, or simd::Double2 with its lane-wise
// square root `sqrt`), as ExpSeriesOf.
template <typename T, typename Sqrt>
inline T AtanUnitOf(T x, Sqrt sqrt) {
  for (int i = 0; i < 2; ++i) x = x / (1.0 + sqrt(1.0 + x * x));
  T x2 = x * x;
  // p = Σ (-1)^n x2^(n-1)/(2n+1) for n = 1..12, by Estrin's scheme.
  T x4 = x2 * x2, x8 = x4 * x4;
  T p =
      (((-0.3333333333333333 + 0.2 * x2) + (-0.14285714285714285 + 0.1111111111111111 * x2) * x4) +
       ((-0.09090909090909091 + 0.07692307692307693 * x2) +
        (-0.06666666666666667 + 0.058823529411764705 * x2) * x4) *
           x8) +
      ((-0.05263157894736842 + 0.047619047619047616 * x2) +
       (-0.043478260869565216 + 0.04 * x2) * x4) *
          (x8 * x8);
  return 4.0 * (x + x * (x2 * p));
}
inline double AtanUnit(double x) {
  return AtanUnitOf(x, [](double v) { return std::sqrt(v); });
}

inline double Atan2(double y, double x) {
  if (x == 0.0 && y == 0.0) return 0.0;
  double ax = std::fabs(x), ay = std::fabs(y);
  double angle = ay <= ax ? AtanUnit(ay / ax) : kPi / 2.0 - AtanUnit(ax / ay);
  if (x < 0.0) angle = kPi - angle;
  return y < 0.0 ? -angle : angle;
}

inline double Acos(double x) {
  if (x >= 1.0) return 0.0;
  if (x <= -1.0) return kPi;
  return Atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

// Float conveniences for the geometry code.
inline float Expf(float x) { return static_cast<float>(Exp(x)); }
inline float Logf(float x) { return static_cast<float>(Log(x)); }
inline float Sinf(float x) { return static_cast<float>(Sin(x)); }
inline float Cosf(float x) { return static_cast<float>(Cos(x)); }
inline float Acosf(float x) { return static_cast<float>(Acos(x)); }
inline float Atan2f(float y, float x) { return static_cast<float>(Atan2(y, x)); }

}  // namespace det
}  // namespace niwa

// The same functions on SIMD lanes, and the in-place batches built on them (ExpfInPlace,
// AtanOfNonNegativeInPlace), which callers of this header use.
#include "math/det_math_lanes.h"  // IWYU pragma: export
