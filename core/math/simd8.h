// Eight-float lanes (256 bits) for the hot loops that x86-64 GCC builds also compile for AVX2 and
// pick at run time (__attribute__((target("avx2"))) on the caller, __builtin_cpu_supports): the
// same IEEE operations as math/simd4.h's four lanes, lane by lane, so an eight-lane batch gives the
// bits of two four-lane ones. The helpers are generic vector code (square root and the any-lane
// test through the two 128-bit halves) forced inline, so they take the caller's AVX2 encoding and
// no 256-bit value crosses a call (whose ABI differs with and without AVX; the helpers take
// references, and -Wpsabi is quiet for their returns). Without AVX the
// compiler splits the types into halves; so does WASM simd128 (two v128 an operation), where the
// bark passes take eight lanes too (bark/springs.h NIWA_BARK_EIGHT).
// Not here: the dispatch (the study's, e.g. bark/springs.h BatchLanes).
#pragma once

#include <cstdint>

#include "math/simd4.h"

namespace niwa {
namespace simd {

typedef float Float8 __attribute__((vector_size(32)));
typedef int32_t Int8 __attribute__((vector_size(32)));  // a Float8 comparison's mask
typedef uint8_t Byte8 __attribute__((vector_size(8)));
typedef uint8_t Byte4 __attribute__((vector_size(4)));

#define NIWA_LANES_INLINE inline __attribute__((always_inline))

#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
NIWA_LANES_INLINE Float8 Splat8(float v) { return Float8{v, v, v, v, v, v, v, v}; }
NIWA_LANES_INLINE Float4 Low(const Float8& v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }
NIWA_LANES_INLINE Float4 High(const Float8& v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }
NIWA_LANES_INLINE Int4 Low(const Int8& v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }
NIWA_LANES_INLINE Int4 High(const Int8& v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }
NIWA_LANES_INLINE Float8 Join(Float4 lo, Float4 hi) {
  return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
}
// Correctly rounded square roots, as std::sqrt in every lane (simd4.h's Sqrt on each half).
NIWA_LANES_INLINE Float8 Sqrt(const Float8& v) { return Join(Sqrt(Low(v)), Sqrt(High(v))); }
// mask ? yes : no, lane by lane.
NIWA_LANES_INLINE Float8 Select(const Int8& mask, const Float8& yes, const Float8& no) {
  return (Float8)(((Int8)yes & mask) | ((Int8)no & ~mask));
}
// Whether any lane of a mask is set.
NIWA_LANES_INLINE bool AnyTrue(const Int8& mask) { return AnyTrue(Low(mask) | High(mask)); }
// A bit per lane of a mask (lane k: bit k).
NIWA_LANES_INLINE int LaneBits(const Int8& mask) {
  return LaneBits(Low(mask)) | (LaneBits(High(mask)) << 4);
}

// Four- or eight-lane code written once (V = Float4 or Float8, I its mask type): a load, a gather
// and a store of W floats, a constant in every lane, and the mask "byte != 0" of W bytes.
template <class V>
NIWA_LANES_INLINE V LoadLanes(const float* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
NIWA_LANES_INLINE void StoreLanes(float* p, const V& v) {
  __builtin_memcpy(p, &v, sizeof v);
}
// W floats from base[idx[0]], .., base[idx[W − 1]], each lane named (a lane loop with a variable
// index makes clang's WASM spill the vector to the stack and store lane by lane).
template <class V>
NIWA_LANES_INLINE V GatherLanes(const float* base, const int32_t* idx) {
  if constexpr (sizeof(V) == sizeof(Float4)) {
    return V{base[idx[0]], base[idx[1]], base[idx[2]], base[idx[3]]};
  } else {
    return V{base[idx[0]], base[idx[1]], base[idx[2]], base[idx[3]],
             base[idx[4]], base[idx[5]], base[idx[6]], base[idx[7]]};
  }
}
template <class V>
NIWA_LANES_INLINE V SplatLanes(float x) {
  if constexpr (sizeof(V) == sizeof(Float4)) {
    return Splat4(x);
  } else {
    return Splat8(x);
  }
}
// (Each lane ANDs its own byte out of the word the bytes make, little-endian as x86-64 and WASM.)
template <class I>
NIWA_LANES_INLINE I NonZeroBytes(const uint8_t* p) {
  if constexpr (sizeof(I) == sizeof(Int4)) {
    int32_t w;
    __builtin_memcpy(&w, p, sizeof w);
    const Int4 v{w, w, w, w};
    return (v & Int4{0xff, 0xff00, 0xff0000, static_cast<int32_t>(0xff000000u)}) != Int4{};
  } else {
    int32_t w[2];
    __builtin_memcpy(w, p, sizeof w);
    const Int8 v{w[0], w[0], w[0], w[0], w[1], w[1], w[1], w[1]};
    const int32_t top = static_cast<int32_t>(0xff000000u);
    return (v & Int8{0xff, 0xff00, 0xff0000, top, 0xff, 0xff00, 0xff0000, top}) != Int8{};
  }
}
#pragma GCC diagnostic pop

}  // namespace simd
}  // namespace niwa
