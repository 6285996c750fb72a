// Deterministic exp, log, sin, cos, acos, atan2: only +, -, *, / and sqrt (exact in IEEE 754), so
// the native and WASM builds give bit-identical results, unlike glibc's and musl's libm.
#pragma once

#include <cmath>
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

// e^x for |x| < ~700: x = k·ln2 + r, |r| <= ln2/2, Taylor series of e^r (error < 1e-15 relative).
inline double Exp(double x) {
  if (x < -700.0) return 0.0;
  if (x > 700.0) x = 700.0;  // |k| <= 1010: Pow2 stays in range
  double k = std::floor(x / kLn2 + 0.5);
  double r = x - k * kLn2;
  double term = 1.0, sum = 1.0;
  for (int i = 1; i <= 17; ++i) {
    term *= r / i;
    sum += term;
  }
  return sum * Pow2(static_cast<int>(k));  // exact scaling by 2^k
}

// ln x for x > 0: x = m·2^e with m in [√½, √2), ln m = 2·atanh((m-1)/(m+1)) by its series.
inline double Log(double x) {
  if (!(x > 0.0)) return -HUGE_VAL;
  int e = 0;
  double m = std::frexp(x, &e);  // exact: m in [0.5, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  double t = (m - 1.0) / (m + 1.0), t2 = t * t, term = t, sum = t;
  for (int i = 3; i <= 41; i += 2) {
    term *= t2;
    sum += term / i;
  }
  return 2.0 * sum + e * kLn2;
}

// sin and cos of x (radians) by reduction to [-π/4, π/4] and Taylor series.
inline void SinCos(double x, double* s, double* c) {
  double q = std::floor(x / (kPi / 2.0) + 0.5);
  double r = x - q * (kPi / 2.0);
  double r2 = r * r;
  double sin_r = r, cos_r = 1.0, ts = r, tc = 1.0;
  for (int i = 1; i <= 11; ++i) {
    ts *= -r2 / ((2 * i) * (2 * i + 1));
    tc *= -r2 / ((2 * i - 1) * (2 * i));
    sin_r += ts;
    cos_r += tc;
  }
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

// atan of |x| <= 1 after two argument halvings, atan(x) = 2·atan(x / (1 + √(1 + x²))).
inline double AtanUnit(double x) {
  for (int i = 0; i < 2; ++i) x = x / (1.0 + std::sqrt(1.0 + x * x));
  double x2 = x * x, term = x, sum = x;
  for (int i = 3; i <= 31; i += 2) {
    term *= -x2;
    sum += term / i;
  }
  return 4.0 * sum;
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
