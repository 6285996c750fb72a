// Tests of det_math's lane versions (math/det_math_lanes.h) and the simd4 helpers: every lane gives
// the scalar function's bits, on edge cases and on many random inputs.
#include "math/det_math_lanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "math/rotation.h"
#include "math/simd4.h"

namespace niwa {
namespace {

using simd::Double2;
using simd::Float4;

uint64_t Bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
uint32_t Bits(float v) {
  uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// A fixed pseudo-random stream (PCG's LCG step): u in [0, 1).
struct Stream {
  uint64_t state;
  double Next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  }
};

// Edge cases shared by the tests: zeros of both signs, integers and halves (floor and rounding
// boundaries, up to Floor's range 2^51), multiples of π/4 and π/2 (quadrant edges), ±1 and just
// inside and outside.
std::vector<double> EdgeCases() {
  std::vector<double> v = {0.0,
                           -0.0,
                           1e-300,
                           -1e-300,
                           0.5,
                           -0.5,
                           1.0,
                           -1.0,
                           1.5,
                           -1.5,
                           2.0,
                           -2.0,
                           std::nextafter(1.0, 0.0),
                           std::nextafter(1.0, 2.0),
                           std::nextafter(-1.0, 0.0),
                           std::nextafter(-1.0, -2.0),
                           0.49999999999999994,
                           -0.49999999999999994,
                           1e6 + 0.5,
                           -1e6 - 0.5,
                           2251799813685247.5,
                           -2251799813685247.5,
                           1e15,
                           -1e15,
                           det::kLn2 / 2.0,
                           -det::kLn2 / 2.0};
  for (int q = -16; q <= 16; ++q) {
    const double x = q * det::kPi / 4.0;
    v.push_back(x);
    v.push_back(std::nextafter(x, 1e9));
    v.push_back(std::nextafter(x, -1e9));
  }
  return v;
}

// Inputs: the edge cases, then n uniform in [lo, hi).
std::vector<double> Inputs(double lo, double hi, int n, uint64_t seed) {
  std::vector<double> v = EdgeCases();
  Stream s{seed};
  for (int i = 0; i < n; ++i) v.push_back(lo + (hi - lo) * s.Next());
  return v;
}

// Runs lane(x) on pairs of inputs (each input once in lane 0 and once in lane 1) and compares
// each lane with scalar(x) bit for bit.
template <typename Lane, typename Scalar>
void ExpectLanesMatch(const std::vector<double>& inputs, Lane lane, Scalar scalar,
                      const char* name) {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const double a = inputs[i], b = inputs[(i * 7 + 3) % inputs.size()];
    const Double2 out = lane(Double2{a, b});
    ASSERT_EQ(Bits(out[0]), Bits(scalar(a))) << name << " lane 0, x = " << a;
    ASSERT_EQ(Bits(out[1]), Bits(scalar(b))) << name << " lane 1, x = " << b;
  }
}

TEST(DetMathLanes, FloorIsStdFloorBitForBit) {
  std::vector<double> inputs = Inputs(-1e6, 1e6, 50000, 1);
  Stream s{2};
  for (int i = 0; i < 50000; ++i) inputs.push_back(-4.0 + 8.0 * s.Next());
  for (int k = -2000; k <= 2000; ++k) inputs.push_back(0.25 * k);  // integers, halves, quarters
  ExpectLanesMatch(
      inputs, [](Double2 x) { return det::Floor(x); }, [](double x) { return std::floor(x); },
      "Floor");
}

TEST(DetMathLanes, ExpMatchesScalar) {
  std::vector<double> inputs = Inputs(-760.0, 760.0, 100000, 3);
  for (double x :
       {-700.0, std::nextafter(-700.0, 0.0), std::nextafter(-700.0, -1e9), 700.0,
        std::nextafter(700.0, 0.0), std::nextafter(700.0, 1e9), -745.0, 800.0, -1e30, 1e30}) {
    inputs.push_back(x);
  }
  Stream s{4};
  for (int i = 0; i < 100000; ++i) inputs.push_back(-20.0 * s.Next());
  ExpectLanesMatch(
      inputs, [](Double2 x) { return det::Exp(x); }, [](double x) { return det::Exp(x); }, "Exp");
}

TEST(DetMathLanes, SinCosMatchScalar) {
  std::vector<double> inputs = Inputs(-100.0, 100.0, 100000, 5);
  Stream s{6};
  for (int i = 0; i < 50000; ++i) inputs.push_back(-1e6 + 2e6 * s.Next());
  for (int i = 0; i < 50000; ++i) inputs.push_back(-7.0 + 14.0 * s.Next());
  ExpectLanesMatch(
      inputs,
      [](Double2 x) {
        Double2 sin, cos;
        det::SinCos(x, &sin, &cos);
        return sin;
      },
      [](double x) { return det::Sin(x); }, "Sin");
  ExpectLanesMatch(
      inputs,
      [](Double2 x) {
        Double2 sin, cos;
        det::SinCos(x, &sin, &cos);
        return cos;
      },
      [](double x) { return det::Cos(x); }, "Cos");
}

TEST(DetMathLanes, AcosMatchesScalarInsideAndOutsideItsDomain) {
  std::vector<double> inputs = Inputs(-1.0, 1.0, 100000, 7);
  Stream s{8};
  for (int i = 0; i < 20000; ++i) inputs.push_back(-3.0 + 6.0 * s.Next());
  for (int i = 0; i < 20000; ++i) inputs.push_back(1.0 - 1e-6 * s.Next());  // near the ends
  for (int i = 0; i < 20000; ++i) inputs.push_back(-1.0 + 1e-6 * s.Next());
  ExpectLanesMatch(
      inputs, [](Double2 x) { return det::Acos(x); }, [](double x) { return det::Acos(x); },
      "Acos");
}

TEST(DetMathLanes, AtanUnitAndAtan2MatchScalar) {
  std::vector<double> inputs = Inputs(-1.0, 1.0, 50000, 9);
  ExpectLanesMatch(
      inputs, [](Double2 x) { return det::AtanUnit(x); }, [](double x) { return det::AtanUnit(x); },
      "AtanUnit");
  // Atan2 on pairs (y, x): every sign, zeros of both signs, the diagonals |y| = |x|.
  std::vector<double> ys = Inputs(-5.0, 5.0, 3000, 10), xs = Inputs(-5.0, 5.0, 3000, 11);
  for (std::size_t i = 0; i < ys.size(); ++i) {
    for (std::size_t j = i % 17; j < xs.size(); j += 17) {
      const double y0 = ys[i], x0 = xs[j], y1 = -xs[j], x1 = ys[i];
      const Double2 out = det::Atan2(Double2{y0, y1}, Double2{x0, x1});
      ASSERT_EQ(Bits(out[0]), Bits(det::Atan2(y0, x0))) << y0 << ", " << x0;
      ASSERT_EQ(Bits(out[1]), Bits(det::Atan2(y1, x1))) << y1 << ", " << x1;
    }
  }
  for (double v : {0.0, -0.0, 1.0, -1.0, 3.5, -3.5}) {
    for (double w : {0.0, -0.0, 1.0, -1.0, 3.5, -3.5}) {
      const Double2 out = det::Atan2(Double2{v, w}, Double2{w, v});
      ASSERT_EQ(Bits(out[0]), Bits(det::Atan2(v, w))) << v << ", " << w;
      ASSERT_EQ(Bits(out[1]), Bits(det::Atan2(w, v))) << w << ", " << v;
    }
  }
}

TEST(DetMathLanes, FloatLanesMatchTheFloatConveniences) {
  std::vector<float> inputs = {0.0f,  -0.0f,      1.0f,        -1.0f,      1.5f,   -1.5f,   0.5f,
                               -0.5f, 3.1415927f, -3.1415927f, 1.5707964f, 100.0f, -100.0f, 1e-30f};
  Stream s{12};
  for (int i = 0; i < 100000; ++i) inputs.push_back(static_cast<float>(-2.0 + 4.0 * s.Next()));
  for (int i = 0; i < 20000; ++i) inputs.push_back(static_cast<float>(-50.0 + 100.0 * s.Next()));
  for (std::size_t i = 0; i + 4 <= inputs.size(); ++i) {
    const Float4 x = {inputs[i], inputs[(i + 5) % inputs.size()], inputs[(i + 11) % inputs.size()],
                      inputs[(i + 3) % inputs.size()]};
    const Float4 a = det::Acosf(x);
    Float4 sin, cos;
    det::SinCosf(x, &sin, &cos);
    for (int k = 0; k < 4; ++k) {
      ASSERT_EQ(Bits(a[k]), Bits(det::Acosf(x[k]))) << "Acosf " << x[k];
      ASSERT_EQ(Bits(sin[k]), Bits(det::Sinf(x[k]))) << "Sinf " << x[k];
      ASSERT_EQ(Bits(cos[k]), Bits(det::Cosf(x[k]))) << "Cosf " << x[k];
    }
  }
}

// The lane types' helpers do glm's operations in glm's order: same bits as glm and as
// math/rotation.h's scalar RotateAbout.
TEST(Simd4, Vec3LanesMatchGlm) {
  Stream s{13};
  auto next_vec = [&s]() {
    return glm::vec3(static_cast<float>(-2.0 + 4.0 * s.Next()),
                     static_cast<float>(-2.0 + 4.0 * s.Next()),
                     static_cast<float>(-2.0 + 4.0 * s.Next()));
  };
  for (int i = 0; i < 20000; ++i) {
    glm::vec3 a[4], b[4];
    float c[4], sn[4];
    for (int k = 0; k < 4; ++k) {
      a[k] = next_vec();
      b[k] = glm::normalize(next_vec());
      const float angle = static_cast<float>(-3.0 + 6.0 * s.Next());
      c[k] = det::Cosf(angle);
      sn[k] = det::Sinf(angle);
    }
    const simd::Vec3x4 va = simd::Gather(a[0], a[1], a[2], a[3]);
    const simd::Vec3x4 vb = simd::Gather(b[0], b[1], b[2], b[3]);
    const simd::Vec3x4 cross = simd::Cross(va, vb), unit = simd::Normalize(va);
    const Float4 dot = simd::Dot(va, vb), root = simd::Sqrt(dot * dot);
    const simd::Vec3x4 turned =
        RotateAbout(va, vb, Float4{c[0], c[1], c[2], c[3]}, Float4{sn[0], sn[1], sn[2], sn[3]});
    for (int k = 0; k < 4; ++k) {
      const glm::vec3 gc = glm::cross(a[k], b[k]), gn = glm::normalize(a[k]);
      const glm::vec3 gt = RotateAbout(a[k], b[k], c[k], sn[k]);
      const float gd = glm::dot(a[k], b[k]);
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_EQ(Bits(simd::Lane(cross, k)[axis]), Bits(gc[axis]));
        ASSERT_EQ(Bits(simd::Lane(unit, k)[axis]), Bits(gn[axis]));
        ASSERT_EQ(Bits(simd::Lane(turned, k)[axis]), Bits(gt[axis]));
      }
      ASSERT_EQ(Bits(dot[k]), Bits(gd));
      ASSERT_EQ(Bits(root[k]), Bits(std::sqrt(gd * gd)));
    }
  }
  const Double2 roots = simd::Sqrt(Double2{2.0, 1e-300});
  EXPECT_EQ(Bits(roots[0]), Bits(std::sqrt(2.0)));
  EXPECT_EQ(Bits(roots[1]), Bits(std::sqrt(1e-300)));
  const Float4 chosen =
      simd::Select(simd::Int4{-1, 0, -1, 0}, Float4{1, 2, 3, 4}, Float4{5, 6, 7, 8});
  EXPECT_EQ(chosen[0], 1.0f);
  EXPECT_EQ(chosen[1], 6.0f);
  EXPECT_EQ(chosen[2], 3.0f);
  EXPECT_EQ(chosen[3], 8.0f);
}

}  // namespace
}  // namespace niwa
