// The one set of 128-bit lane types (four floats, two doubles) and their lane-wise helpers, for the
// SIMD paths of every study: each helper does, lane by lane, exactly the IEEE operation of its
// scalar counterpart, so a batched result is the scalar result's bits.
//
// GCC/Clang vector extensions: the arithmetic operators work lane by lane, a comparison gives a
// lane mask (all ones or all zeros) of the same-sized integer type. The types compile on every
// target (without SIMD the compiler splits them into scalars); NIWA_SIMD says whether the target
// has the 128-bit registers (SSE2 natively, simd128 in WASM), which is where batching pays.
// Not here: the det_math functions on lanes (math/det_math_lanes.h), any study's batching.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#if defined(__wasm_simd128__)
#include <wasm_simd128.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__SSE2__) || defined(__wasm_simd128__)
#define NIWA_SIMD 1
#else
#define NIWA_SIMD 0
#endif

namespace niwa {
namespace simd {

typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Int4 __attribute__((vector_size(16)));  // a Float4 comparison's mask
typedef double Double2 __attribute__((vector_size(16)));
typedef int64_t Long2 __attribute__((vector_size(16)));  // a Double2 comparison's mask

// Correctly rounded square roots (IEEE 754), as std::sqrt in every lane.
inline Float4 Sqrt(Float4 v) {
#if defined(__wasm_simd128__)
  return (Float4)wasm_f32x4_sqrt((v128_t)v);
#elif defined(__SSE2__)
  return (Float4)_mm_sqrt_ps((__m128)v);
#else
  return Float4{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}
inline Double2 Sqrt(Double2 v) {
#if defined(__wasm_simd128__)
  return (Double2)wasm_f64x2_sqrt((v128_t)v);
#elif defined(__SSE2__)
  return (Double2)_mm_sqrt_pd((__m128d)v);
#else
  return Double2{std::sqrt(v[0]), std::sqrt(v[1])};
#endif
}

// mask ? yes : no, lane by lane (mask lanes all ones or all zeros, as a comparison gives).
inline Float4 Select(Int4 mask, Float4 yes, Float4 no) {
  return (Float4)(((Int4)yes & mask) | ((Int4)no & ~mask));
}
inline Double2 Select(Long2 mask, Double2 yes, Double2 no) {
  return (Double2)(((Long2)yes & mask) | ((Long2)no & ~mask));
}

// std::max(a, b) = (a < b) ? b : a and std::min(a, b) = (b < a) ? b : a, lane by lane, their very
// choices (a NaN or an equal pair gives a): maxpd/minpd with the operands swapped, pmax/pmin in
// WASM.
inline Double2 Max(Double2 a, Double2 b) {
#if defined(__wasm_simd128__)
  return (Double2)wasm_f64x2_pmax((v128_t)a, (v128_t)b);
#elif defined(__SSE2__)
  return (Double2)_mm_max_pd((__m128d)b, (__m128d)a);
#else
  return Double2{a[0] < b[0] ? b[0] : a[0], a[1] < b[1] ? b[1] : a[1]};
#endif
}
inline Double2 Min(Double2 a, Double2 b) {
#if defined(__wasm_simd128__)
  return (Double2)wasm_f64x2_pmin((v128_t)a, (v128_t)b);
#elif defined(__SSE2__)
  return (Double2)_mm_min_pd((__m128d)b, (__m128d)a);
#else
  return Double2{b[0] < a[0] ? b[0] : a[0], b[1] < a[1] ? b[1] : a[1]};
#endif
}

inline Float4 Splat4(float v) { return Float4{v, v, v, v}; }

// The larger and the smaller of each lane pair, for lanes without NaNs (which one a NaN or an equal
// pair gives is not promised: maxps/minps natively, pmax/pmin in WASM).
inline Float4 MaxNoNaN(Float4 a, Float4 b) {
#if defined(__wasm_simd128__)
  return (Float4)wasm_f32x4_pmax((v128_t)a, (v128_t)b);
#elif defined(__SSE2__)
  return (Float4)_mm_max_ps((__m128)b, (__m128)a);
#else
  return Float4{a[0] < b[0] ? b[0] : a[0], a[1] < b[1] ? b[1] : a[1], a[2] < b[2] ? b[2] : a[2],
                a[3] < b[3] ? b[3] : a[3]};
#endif
}
inline Float4 MinNoNaN(Float4 a, Float4 b) {
#if defined(__wasm_simd128__)
  return (Float4)wasm_f32x4_pmin((v128_t)a, (v128_t)b);
#elif defined(__SSE2__)
  return (Float4)_mm_min_ps((__m128)b, (__m128)a);
#else
  return Float4{b[0] < a[0] ? b[0] : a[0], b[1] < a[1] ? b[1] : a[1], b[2] < a[2] ? b[2] : a[2],
                b[3] < a[3] ? b[3] : a[3]};
#endif
}
// A bit per lane of a mask (lane k: bit k), as _mm_movemask_ps.
inline int LaneBits(Int4 mask) {
#if defined(__wasm_simd128__)
  return static_cast<int>(wasm_i32x4_bitmask((v128_t)mask));
#elif defined(__SSE2__)
  return _mm_movemask_ps((__m128)mask);
#else
  return (mask[0] ? 1 : 0) | (mask[1] ? 2 : 0) | (mask[2] ? 4 : 0) | (mask[3] ? 8 : 0);
#endif
}

// Whether any lane of a mask (all ones or all zeros a lane) is set.
inline bool AnyTrue(Int4 mask) {
#if defined(__wasm_simd128__)
  return wasm_v128_any_true((v128_t)mask);
#elif defined(__SSE2__)
  return _mm_movemask_ps((__m128)mask) != 0;
#else
  return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
#endif
}
// Four bytes as four floats (exact: every byte is a float), lane k from q[k].
inline Float4 BytesToFloat4(const uint8_t q[4]) {
#if defined(__wasm_simd128__)
  uint32_t word;
  __builtin_memcpy(&word, q, 4);
  const v128_t b = wasm_i32x4_splat(static_cast<int32_t>(word));
  return (Float4)wasm_f32x4_convert_u32x4(
      wasm_u32x4_extend_low_u16x8(wasm_u16x8_extend_low_u8x16(b)));
#elif defined(__SSE2__)
  uint32_t word;
  __builtin_memcpy(&word, q, 4);
  const __m128i zero = _mm_setzero_si128();
  const __m128i b = _mm_cvtsi32_si128(static_cast<int>(word));
  return (Float4)_mm_cvtepi32_ps(_mm_unpacklo_epi16(_mm_unpacklo_epi8(b, zero), zero));
#else
  return Float4{static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2]),
                static_cast<float>(q[3])};
#endif
}
// Twenty-four bytes as six times four floats (exact), out[j] lane k from q[4j + k]: BytesToFloat4
// of q, q + 4, .., q + 20 with two loads.
inline void Bytes24ToFloat4(const uint8_t* q, Float4 out[6]) {
#if defined(__wasm_simd128__)
  uint64_t tail;
  __builtin_memcpy(&tail, q + 16, 8);
  const v128_t a = wasm_v128_load(q);
  const v128_t b = wasm_i64x2_splat(static_cast<int64_t>(tail));
  const v128_t a_lo = wasm_u16x8_extend_low_u8x16(a), a_hi = wasm_u16x8_extend_high_u8x16(a);
  const v128_t b_lo = wasm_u16x8_extend_low_u8x16(b);
  out[0] = (Float4)wasm_f32x4_convert_u32x4(wasm_u32x4_extend_low_u16x8(a_lo));
  out[1] = (Float4)wasm_f32x4_convert_u32x4(wasm_u32x4_extend_high_u16x8(a_lo));
  out[2] = (Float4)wasm_f32x4_convert_u32x4(wasm_u32x4_extend_low_u16x8(a_hi));
  out[3] = (Float4)wasm_f32x4_convert_u32x4(wasm_u32x4_extend_high_u16x8(a_hi));
  out[4] = (Float4)wasm_f32x4_convert_u32x4(wasm_u32x4_extend_low_u16x8(b_lo));
  out[5] = (Float4)wasm_f32x4_convert_u32x4(wasm_u32x4_extend_high_u16x8(b_lo));
#elif defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(q));
  const __m128i b = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(q + 16));
  const __m128i a_lo = _mm_unpacklo_epi8(a, zero), a_hi = _mm_unpackhi_epi8(a, zero);
  const __m128i b_lo = _mm_unpacklo_epi8(b, zero);
  out[0] = (Float4)_mm_cvtepi32_ps(_mm_unpacklo_epi16(a_lo, zero));
  out[1] = (Float4)_mm_cvtepi32_ps(_mm_unpackhi_epi16(a_lo, zero));
  out[2] = (Float4)_mm_cvtepi32_ps(_mm_unpacklo_epi16(a_hi, zero));
  out[3] = (Float4)_mm_cvtepi32_ps(_mm_unpackhi_epi16(a_hi, zero));
  out[4] = (Float4)_mm_cvtepi32_ps(_mm_unpacklo_epi16(b_lo, zero));
  out[5] = (Float4)_mm_cvtepi32_ps(_mm_unpackhi_epi16(b_lo, zero));
#else
  for (int j = 0; j < 6; ++j) out[j] = BytesToFloat4(q + 4 * j);
#endif
}
// Four floats from memory (16 bytes; lanes past what the caller uses are whatever lies there).
inline Float4 LoadFloat4(const float* p) {
  Float4 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
// 2^e[k] in lanes k = 0..2 for the exponents e[k] in [-126, 127] (BvhWideNode::Step's bits,
// (e + 127) << 23); lane 3 is not meant to be read.
inline Float4 ExponentBytesToPowers(const int8_t e[3]) {
  const Int4 v{e[0], e[1], e[2], 0};
  return (Float4)((v + 127) << 23);
}
// Lane k of v in every lane.
template <int k>
inline Float4 LaneSplat(Float4 v) {
  return __builtin_shufflevector(v, v, k, k, k, k);
}
// Lanes 0, 1 (Low) or 2, 3 (High) of v widened to double (exact).
inline Double2 LowToDouble2(Float4 v) {
  return Double2{static_cast<double>(v[0]), static_cast<double>(v[1])};
}
inline Double2 HighToDouble2(Float4 v) {
  return Double2{static_cast<double>(v[2]), static_cast<double>(v[3])};
}
inline Double2 Splat2(double v) { return Double2{v, v}; }

// Four glm::vec3, one per lane, and glm's cross, dot and normalize in glm's order of operations.
struct Vec3x4 {
  Float4 x, y, z;
};
inline Vec3x4 Gather(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                     const glm::vec3& d) {
  return Vec3x4{Float4{a.x, b.x, c.x, d.x}, Float4{a.y, b.y, c.y, d.y}, Float4{a.z, b.z, c.z, d.z}};
}
inline glm::vec3 Lane(const Vec3x4& v, int k) { return glm::vec3(v.x[k], v.y[k], v.z[k]); }
inline Vec3x4 Cross(const Vec3x4& a, const Vec3x4& b) {  // glm::cross
  return Vec3x4{a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
inline Float4 Dot(const Vec3x4& a, const Vec3x4& b) {  // glm::dot: (x + y) + z
  Float4 tx = a.x * b.x, ty = a.y * b.y, tz = a.z * b.z;
  return (tx + ty) + tz;
}
inline Vec3x4 Normalize(const Vec3x4& v) {  // glm::normalize: v · (1 / sqrt(dot(v, v)))
  Float4 inverse = 1.0f / Sqrt(Dot(v, v));
  return Vec3x4{v.x * inverse, v.y * inverse, v.z * inverse};
}
inline Vec3x4 Select(Int4 mask, const Vec3x4& yes, const Vec3x4& no) {
  return Vec3x4{Select(mask, yes.x, no.x), Select(mask, yes.y, no.y), Select(mask, yes.z, no.z)};
}

}  // namespace simd
}  // namespace niwa
