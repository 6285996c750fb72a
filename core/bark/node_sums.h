// The node passes' spring sums as lanes (springs.cpp NodeBatch2, four_layer.cpp NodeBatch) and one
// node at a time (NodeSums: the seams' node-by-node path): a node adds its six springs' slot forces
// in ascending spring index from 0, each with the sign of the node's end (lattice.h inc_a). Every
// node away from the seams has the same ends, entry by entry (InteriorEnds); in WASM
// (NIWA_BARK_FIXED_SIGNS) a batch of such nodes (whose springs lie in runs: lattice.h node_run4,
// node_run8) and such a node alone add and subtract with the signs known at compile time, any other
// node reads them entry by entry, as every node does natively. Both give the same operations in the
// same order (x + v or x − v), so the bits do not depend on which ran. Why: with the signs read
// from memory clang turns x − v into x + (−v) and V8 each negation into a branch and a sign mask
// made anew per vector (docs/bark-model.md choice 6). Does not: choose which nodes go as lanes (the
// passes do) or know the lattice beyond inc_slot and inc_a.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "math/simd8.h"

// Inlined into the passes' eight-lane loops (math/simd8.h): no 256-bit value crosses a call.
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

// Whether the sums take the fixed signs of InteriorEnds where they apply: in WASM, where V8 makes
// each sign read from memory a branch and a mask; not natively, where GCC's code for them took 5 %
// more instructions over the whole step (bench runner, camphor 64 × 32: 3,498 M against 3,325 M).
#if defined(__wasm__)
#define NIWA_BARK_FIXED_SIGNS 1
#else
#define NIWA_BARK_FIXED_SIGNS 0
#endif

namespace niwa::bark {

// inc_a of an interior node's six springs in ascending index: in from (i, j−1), out to (i, j+1),
// the two diagonals in from column i−1, the two out to column i+1 (lattice.h's spring order).
inline bool InteriorEnds(const uint8_t* inc_a) {
  uint32_t head;
  uint16_t tail;
  std::memcpy(&head, inc_a, sizeof head);
  std::memcpy(&tail, inc_a + 4, sizeof tail);
  // Bytes 0, 1, 0, 0 | 1, 1 (little-endian, as x86-64 and WASM).
  return head == 0x00000100u && tail == 0x0101u;
}

// The sums over the six entries e0..e0+5 (slots inc_slot[e], signs inc_a[e]) of the W-lane runs
// gx + inc_slot[e] and gz + inc_slot[e], from 0.
template <class V>
NIWA_LANES_INLINE void RunSums(const float* gx, const float* gz, const int32_t* inc_slot,
                               const uint8_t* inc_a, std::size_t e0, V* fx, V* fz) {
  using simd::LoadLanes;
  const int32_t* q = inc_slot + e0;
  V x = simd::SplatLanes<V>(0.0f), z = x;
  if (NIWA_BARK_FIXED_SIGNS && InteriorEnds(inc_a + e0)) {
    x -= LoadLanes<V>(gx + q[0]);
    z -= LoadLanes<V>(gz + q[0]);
    x += LoadLanes<V>(gx + q[1]);
    z += LoadLanes<V>(gz + q[1]);
    x -= LoadLanes<V>(gx + q[2]);
    z -= LoadLanes<V>(gz + q[2]);
    x -= LoadLanes<V>(gx + q[3]);
    z -= LoadLanes<V>(gz + q[3]);
    x += LoadLanes<V>(gx + q[4]);
    z += LoadLanes<V>(gz + q[4]);
    x += LoadLanes<V>(gx + q[5]);
    z += LoadLanes<V>(gz + q[5]);
  } else {
    for (int e = 0; e < 6; ++e) {
      const V vx = LoadLanes<V>(gx + q[e]);
      const V vz = LoadLanes<V>(gz + q[e]);
      if (inc_a[e0 + e]) {
        x += vx;
        z += vz;
      } else {
        x -= vx;
        z -= vz;
      }
    }
  }
  *fx = x;
  *fz = z;
}

// One node's sums (the seams' node-by-node path): RunSums of one lane.
NIWA_LANES_INLINE void NodeSums(const float* gx, const float* gz, const int32_t* inc_slot,
                                const uint8_t* inc_a, std::size_t e0, float* fx, float* fz) {
  const int32_t* q = inc_slot + e0;
  float x = 0.0f, z = 0.0f;
  if (NIWA_BARK_FIXED_SIGNS && InteriorEnds(inc_a + e0)) {
    x -= gx[q[0]];
    z -= gz[q[0]];
    x += gx[q[1]];
    z += gz[q[1]];
    x -= gx[q[2]];
    z -= gz[q[2]];
    x -= gx[q[3]];
    z -= gz[q[3]];
    x += gx[q[4]];
    z += gz[q[4]];
    x += gx[q[5]];
    z += gz[q[5]];
  } else {
    for (int e = 0; e < 6; ++e) {
      if (inc_a[e0 + e]) {
        x += gx[q[e]];
        z += gz[q[e]];
      } else {
        x -= gx[q[e]];
        z -= gz[q[e]];
      }
    }
  }
  *fx = x;
  *fz = z;
}

}  // namespace niwa::bark

#pragma GCC diagnostic pop
