// The 2-layer model's springs, dashpots, integration and breaking.
#include "bark/springs.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

#include "bark/node_sums.h"
#include "math/det_math.h"
#include "math/simd4.h"
#include "math/simd8.h"
#include "random/pcg32.h"

// The batch kernels are inlined into their four- and eight-lane loops (math/simd8.h), so no 256-bit
// value crosses a call: GCC's warning on that ABI does not apply (to the end of the file, where GCC
// places some of them).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace niwa::bark {

namespace {
std::atomic<int> g_batch_lanes{0};  // 0: not yet decided
}  // namespace

int BatchLanes() {
  int lanes = g_batch_lanes.load(std::memory_order_relaxed);
  if (lanes == 0) {
    lanes = EightLanesAvailable() ? 8 : 4;
    g_batch_lanes.store(lanes, std::memory_order_relaxed);
  }
  return lanes;
}

int SetBatchLanes(int lanes) {
  const int before = BatchLanes();
  g_batch_lanes.store(lanes == 8 && EightLanesAvailable() ? 8 : 4, std::memory_order_relaxed);
  return before;
}

bool EightLanesAvailable() {
#if NIWA_BARK_AVX2
  return __builtin_cpu_supports("avx2");
#elif NIWA_BARK_EIGHT
  return true;
#else
  return false;
#endif
}

Mechanics MechanicsOf(const BarkParams& p) {
  Mechanics m;
  const double lo = p.Get(BarkParam::kLo), d = p.Get(BarkParam::kD);
  const double root3_2 = std::sqrt(3.0) / 2.0;
  m.node_area = root3_2 * lo * lo;
  m.mass = p.Get(BarkParam::kRho) * m.node_area * d;
  m.k[0] = root3_2 * p.Get(BarkParam::kE1) * d;
  m.k[1] = root3_2 * p.Get(BarkParam::kE2) * d;
  const double zeta_t = p.Get(BarkParam::kZetaT), zeta_s = p.Get(BarkParam::kZetaS);
  for (int f = 0; f < 2; ++f) m.c[f] = zeta_t * 2.0 * std::sqrt(m.k[f] * m.mass / 2.0);
  m.k_s = p.Get(BarkParam::kG) * m.node_area / d;
  m.c_s = zeta_s * 2.0 * std::sqrt(m.k_s * m.mass);
  const double dt0 = 0.3 * std::sqrt(m.mass / (m.k_s + 2.0 * m.k[0] + 4.0 * m.k[1]));
  const double period = p.Get(BarkParam::kT);
  m.steps_per_cycle = static_cast<int>(std::ceil(period / dt0));
  m.dt = period / m.steps_per_cycle;
  m.kappa_mean[0] = p.Get(BarkParam::kKappa1);
  m.kappa_mean[1] = p.Get(BarkParam::kKappa2);
  m.sigma = p.Get(BarkParam::kSigma);
  m.strain_rate_theta = p.Get(BarkParam::kDeltaR) / period;
  m.strain_rate_z = p.Get(BarkParam::kDeltaH) / period;
  return m;
}

namespace {

constexpr float kNever = std::numeric_limits<float>::infinity();

constexpr float kTinyLength2 = 1e-12f;  // a floor under l² (two nodes on one point)

// One layer's spring pass over the three sub-families (0: the axial springs; 1, 2: each node's
// first and second diagonal), the spring of sub-family t at node n joining a = n to b = slot_b:
// raw pointers and constants, copied into the loops' locals (a byte store may alias anything it
// reaches through a reference, forcing reloads). The reference vector of a sub-family is one
// (lattice.h: axial (0, L_o), diagonals (pitch, ±L_o/2)), so its products with the growth factors
// are constants of the pass (as the per-spring ox·s_θ etc. were). A spring is broken when its
// limit is +inf (Surface::limit2).
struct SpringPass {
  const int32_t* b[3];
  const uint8_t* run4[3];
  const uint8_t* run8[3];
  const float *ux, *uz, *wx, *wz;
  float *gx[3], *gz[3], *limit2[3];
  uint8_t* broken;  // by spring: first[t] + stride[t]·n
  int first[3], stride[3];
  float dx0[3], dz0[3], rx0[3], rz0[3], k[3], c[3], l0[3];  // k, c, l0 by sub-family's family
};

// Spring n of sub-family t broke in this step: never again, no force from the next step on.
NIWA_LANES_INLINE void RecordBreak(const SpringPass& p, int t, int n, int* broke) {
  p.limit2[t][n] = kNever;
  p.broken[p.first[t] + p.stride[t] * n] = 1;
  ++*broke;
}
// Springs n + k of sub-family t broke for the bits k of `bits` (rare: out of the loops' way). It
// takes the sub-family's arrays, not the pass, so the pass's address does not escape the loops
// (clang keeps it in registers then, not in WASM's stack memory reloaded every batch).
__attribute__((noinline)) void RecordBreaks(float* limit2, uint8_t* broken, int stride, int n,
                                            int bits, int* broke) {
  for (int q = 0; bits != 0; ++q, bits >>= 1) {
    if (!(bits & 1)) continue;
    limit2[n + q] = kNever;
    broken[stride * (n + q)] = 1;
    ++*broke;
  }
}

using simd::LoadLanes;
using simd::SplatLanes;
using simd::StoreLanes;

// A pass's constants in every lane, made once a loop.
template <class V>
struct SpringLanes {
  V dx0[3], dz0[3], rx0[3], rz0[3], k[3], c[3], l0[3];
  V tiny, one, zero, never;
  explicit SpringLanes(const SpringPass& p)
      : tiny(SplatLanes<V>(kTinyLength2)),
        one(SplatLanes<V>(1.0f)),
        zero(SplatLanes<V>(0.0f)),
        never(SplatLanes<V>(kNever)) {
    for (int t = 0; t < 3; ++t) {
      dx0[t] = SplatLanes<V>(p.dx0[t]);
      dz0[t] = SplatLanes<V>(p.dz0[t]);
      rx0[t] = SplatLanes<V>(p.rx0[t]);
      rz0[t] = SplatLanes<V>(p.rz0[t]);
      k[t] = SplatLanes<V>(p.k[t]);
      c[t] = SplatLanes<V>(p.c[t]);
      l0[t] = SplatLanes<V>(p.l0[t]);
    }
  }
};

// x > floor ? x : floor, lane by lane (a NaN x gives floor): WASM's pmax(floor, x) = floor < x ? x
// : floor is that very choice in one operation a v128 (the select is three in V8's code: and,
// andnot, or); natively the select.
template <class V>
NIWA_LANES_INLINE V AtLeast(const V& x, const V& floor) {
#if defined(__wasm_simd128__)
  if constexpr (sizeof(V) == sizeof(simd::Float4)) {
    return (V)wasm_f32x4_pmax((v128_t)floor, (v128_t)x);
  } else {
    const simd::Float4 lo =
        (simd::Float4)wasm_f32x4_pmax((v128_t)simd::Low(floor), (v128_t)simd::Low(x));
    const simd::Float4 hi =
        (simd::Float4)wasm_f32x4_pmax((v128_t)simd::High(floor), (v128_t)simd::High(x));
    return simd::Join(lo, hi);
  }
#else
  return simd::Select(x > floor, x, floor);
#endif
}

// 1 in the lanes a mask sets (all ones), +0 in the others: natively the AND with 1; in WASM the
// mask shifted (all ones >> 25 << 23 are 1.0f's bits, 0x3f800000), which clang emits as a shift and
// an AND, where of the AND with 1 it made a select that V8 turns into three operations a v128
// (and, andnot, or) with 1 and 0 reloaded from its frame. The same bits either way.
template <class V, class I>
NIWA_LANES_INLINE V OneWhere(const I& mask, const V& one) {
#if defined(__wasm_simd128__)
  typedef uint32_t Bits __attribute__((vector_size(sizeof(I))));
  (void)one;
  return (V)(((Bits)mask >> 25) << 23);
#else
  return (V)((I)one & mask);
#endif
}

// Node a's state in lanes n..n+W−1.
template <class V>
struct NodeState {
  V ux, uz, wx, wz;
};
template <class V>
NIWA_LANES_INLINE NodeState<V> LoadState(const SpringPass& p, int n) {
  return NodeState<V>{LoadLanes<V>(p.ux + n), LoadLanes<V>(p.uz + n), LoadLanes<V>(p.wx + n),
                      LoadLanes<V>(p.wz + n)};
}

// Springs n..n+W−1 of sub-family t (W lanes of V, masks I; a: their nodes a's state): b loaded as a
// run where `run` says so, else lane by lane; the arithmetic lane by lane, the very operations of
// SpringOne (a broken spring's factor 0 where SpringOne's `on` was). A batch of springs all broken
// before the step only writes its zero forces.
template <class V, class I>
NIWA_LANES_INLINE void SpringBatch(const SpringPass& p, const SpringLanes<V>& v, int t, int n,
                                   bool run, const NodeState<V>& a, int* broke) {
  const V limit2 = LoadLanes<V>(p.limit2[t] + n);
  const I intact = limit2 != v.never;
  if (!simd::AnyTrue(intact)) {
    StoreLanes(p.gx[t] + n, v.zero);
    StoreLanes(p.gz[t] + n, v.zero);
    return;
  }
  V bux, buz, bwx, bwz;
  if (run) {
    const int b = p.b[t][n];
    bux = LoadLanes<V>(p.ux + b);
    buz = LoadLanes<V>(p.uz + b);
    bwx = LoadLanes<V>(p.wx + b);
    bwz = LoadLanes<V>(p.wz + b);
  } else {
    const int32_t* b = p.b[t] + n;
    bux = simd::GatherLanes<V>(p.ux, b);
    buz = simd::GatherLanes<V>(p.uz, b);
    bwx = simd::GatherLanes<V>(p.wx, b);
    bwz = simd::GatherLanes<V>(p.wz, b);
  }
  const V dx = v.dx0[t] + (bux - a.ux);
  const V dz = v.dz0[t] + (buz - a.uz);
  const V l2 = dx * dx + dz * dz;
  const I breaks = l2 > limit2;
  const V l = simd::Sqrt(AtLeast(l2, v.tiny));
  const V inv = v.one / l;
  const V nx = dx * inv, nz = dz * inv;
  const V rel = ((bwx - a.wx) + v.rx0[t]) * nx + ((bwz - a.wz) + v.rz0[t]) * nz;
  const V alive = OneWhere<V>(intact & ~breaks, v.one);  // 1 where intact and unbroken, else +0
  const V f = alive * (v.k[t] * (l - v.l0[t]) + v.c[t] * rel);
  StoreLanes(p.gx[t] + n, f * nx);
  StoreLanes(p.gz[t] + n, f * nz);
  if (simd::AnyTrue(breaks)) {
    RecordBreaks(p.limit2[t], p.broken + p.first[t], p.stride[t], n, simd::LaneBits(breaks), broke);
  }
}

// Spring n of sub-family t alone (the tail of fewer than four), with SpringBatch's operations.
NIWA_LANES_INLINE void SpringOne(const SpringPass& p, int t, int n, int* broke) {
  const int a = n, b = p.b[t][n];
  const float dx = p.dx0[t] + (p.ux[b] - p.ux[a]);
  const float dz = p.dz0[t] + (p.uz[b] - p.uz[a]);
  const float l2 = dx * dx + dz * dz;
  const float limit2 = p.limit2[t][n];
  const bool breaks = l2 > limit2;
  const float l = std::sqrt(l2 > kTinyLength2 ? l2 : kTinyLength2);
  const float inv = 1.0f / l;
  const float nx = dx * inv, nz = dz * inv;
  const float rel = ((p.wx[b] - p.wx[a]) + p.rx0[t]) * nx + ((p.wz[b] - p.wz[a]) + p.rz0[t]) * nz;
  const float f =
      (breaks || limit2 == kNever ? 0.0f : 1.0f) * (p.k[t] * (l - p.l0[t]) + p.c[t] * rel);
  p.gx[t][n] = f * nx;
  p.gz[t][n] = f * nz;
  if (breaks) RecordBreak(p, t, n, broke);
}

// The springs of nodes [begin, end), the three sub-families of a batch of nodes together (their
// node a's state loaded once): four nodes a batch, then one by one. broke: per family.
void SpringLoop4(const SpringPass& pass, int begin, int end, int broke[2]) {
  const SpringPass p = pass;
  const SpringLanes<simd::Float4> v4(p);
  int n = begin;
  for (; n + 4 <= end; n += 4) {
    const NodeState<simd::Float4> a = LoadState<simd::Float4>(p, n);
#pragma GCC unroll 3
    for (int t = 0; t < 3; ++t)
      SpringBatch<simd::Float4, simd::Int4>(p, v4, t, n, p.run4[t][n], a, &broke[t > 0]);
  }
  for (; n < end; ++n) {
    for (int t = 0; t < 3; ++t) SpringOne(p, t, n, &broke[t > 0]);
  }
}

#if NIWA_BARK_EIGHT
// The same with eight nodes a batch (a sub-family whose eight b do not run on: two batches of
// four), in AVX2 natively.
NIWA_BARK_EIGHT_TARGET void SpringLoop8(const SpringPass& pass, int begin, int end, int broke[2]) {
  const SpringPass p = pass;
  const SpringLanes<simd::Float4> v4(p);
  const SpringLanes<simd::Float8> v8(p);
  int n = begin;
  for (; n + 8 <= end; n += 8) {
    const NodeState<simd::Float8> a = LoadState<simd::Float8>(p, n);
#pragma GCC unroll 3
    for (int t = 0; t < 3; ++t) {
      if (p.run8[t][n]) {
        SpringBatch<simd::Float8, simd::Int8>(p, v8, t, n, true, a, &broke[t > 0]);
      } else {
        for (int h = n; h < n + 8; h += 4) {
          SpringBatch<simd::Float4, simd::Int4>(p, v4, t, h, p.run4[t][h],
                                                LoadState<simd::Float4>(p, h), &broke[t > 0]);
        }
      }
    }
  }
  SpringLoop4(pass, n, end, broke);  // the rest: four nodes a batch, then one by one
}
#endif

// The 2-layer model's node pass (Step): raw pointers and constants, copied into the loops' locals.
struct NodePass2 {
  const int32_t* inc_slot;
  const uint8_t *inc_a, *run4, *run8;
  const float *gx, *gz;
  float *ux, *uz, *wx, *wz;
  float dt, inv_m, ks, cs;
};

// Node i's spring forces: its six springs in ascending index added to 0.
NIWA_LANES_INLINE void NodeForce2(const NodePass2& p, int i, float* fx, float* fz) {
  NodeSums(p.gx, p.gz, p.inc_slot, p.inc_a, 6 * static_cast<std::size_t>(i), fx, fz);
}

// Nodes i..i+W−1 (W lanes of V): the springs' sums as lanes where `run` (node_run4 or node_run8
// at i), else node by node into an array (not lane by lane into the vector: WASM
// would spill it for each lane); then the shear spring and dashpot and symplectic Euler lane by
// lane, the operations of the one-by-one tail.
template <class V>
NIWA_LANES_INLINE void NodeBatch2(const NodePass2& p, const V& dt, const V& inv_m, const V& ks,
                                  const V& cs, int i, bool run) {
  constexpr int W = sizeof(V) / sizeof(float);
  V fx, fz;
  if (run) {
    RunSums<V>(p.gx, p.gz, p.inc_slot, p.inc_a, 6 * static_cast<std::size_t>(i), &fx, &fz);
  } else {
    float sx[W], sz[W];
    for (int q = 0; q < W; ++q) NodeForce2(p, i + q, &sx[q], &sz[q]);
    fx = LoadLanes<V>(sx);
    fz = LoadLanes<V>(sz);
  }
  V x = LoadLanes<V>(p.ux + i), z = LoadLanes<V>(p.uz + i);
  V vx = LoadLanes<V>(p.wx + i), vz = LoadLanes<V>(p.wz + i);
  const V ax = (fx - ks * x - cs * vx) * inv_m;
  const V az = (fz - ks * z - cs * vz) * inv_m;
  vx += dt * ax;
  vz += dt * az;
  x += dt * vx;
  z += dt * vz;
  StoreLanes(p.ux + i, x);
  StoreLanes(p.uz + i, z);
  StoreLanes(p.wx + i, vx);
  StoreLanes(p.wz + i, vz);
}

// Node i alone, with NodeBatch2's operations.
NIWA_LANES_INLINE void NodeOne2(const NodePass2& p, int i) {
  float fx, fz;
  NodeForce2(p, i, &fx, &fz);
  const float ax = (fx - p.ks * p.ux[i] - p.cs * p.wx[i]) * p.inv_m;
  const float az = (fz - p.ks * p.uz[i] - p.cs * p.wz[i]) * p.inv_m;
  p.wx[i] += p.dt * ax;
  p.wz[i] += p.dt * az;
  p.ux[i] += p.dt * p.wx[i];
  p.uz[i] += p.dt * p.wz[i];
}

// Nodes [begin, n): four a batch, then one by one.
void NodeLoop2Four(const NodePass2& pass, int n, int begin = 0) {
  const NodePass2 p = pass;
  using simd::Float4;
  const Float4 dt = simd::Splat4(p.dt), inv_m = simd::Splat4(p.inv_m), ks = simd::Splat4(p.ks),
               cs = simd::Splat4(p.cs);
  int i = begin;
  for (; i + 4 <= n; i += 4) NodeBatch2<Float4>(p, dt, inv_m, ks, cs, i, p.run4[i]);
  for (; i < n; ++i) NodeOne2(p, i);
}

#if NIWA_BARK_EIGHT
// Eight a batch where eight nodes' springs lie in runs (else two of four), then NodeLoop2Four.
NIWA_BARK_EIGHT_TARGET void NodeLoop2Eight(const NodePass2& pass, int n) {
  const NodePass2 p = pass;
  using simd::Float4;
  using simd::Float8;
  const Float4 dt4 = simd::Splat4(p.dt), inv_m4 = simd::Splat4(p.inv_m), ks4 = simd::Splat4(p.ks),
               cs4 = simd::Splat4(p.cs);
  const Float8 dt8 = simd::Splat8(p.dt), inv_m8 = simd::Splat8(p.inv_m), ks8 = simd::Splat8(p.ks),
               cs8 = simd::Splat8(p.cs);
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    if (p.run8[i]) {
      NodeBatch2<Float8>(p, dt8, inv_m8, ks8, cs8, i, true);
    } else {
      NodeBatch2<Float4>(p, dt4, inv_m4, ks4, cs4, i, p.run4[i]);
      NodeBatch2<Float4>(p, dt4, inv_m4, ks4, cs4, i + 4, p.run4[i + 4]);
    }
  }
  NodeLoop2Four(p, n, i);
}
#endif

}  // namespace

TruncatedNormal::TruncatedNormal(uint64_t seed, uint64_t stream) : rng_(seed, stream) {}

double TruncatedNormal::Next() {
  for (;;) {
    if (!has_spare_) {
      const double u1 = (static_cast<double>(rng_.NextU32()) + 1.0) * (1.0 / 4294967296.0);
      const double u2 = rng_.Uniform();
      const double r = std::sqrt(-2.0 * det::Log(u1));
      double s, c;
      det::SinCos(2.0 * det::kPi * u2, &s, &c);
      spare_ = r * s;
      has_spare_ = true;
      const double x = r * c;
      if (std::fabs(x) <= 3.0) return x;
    } else {
      has_spare_ = false;
      if (std::fabs(spare_) <= 3.0) return spare_;
    }
  }
}

Surface InitialSurface(const Lattice& L, const Mechanics& mech, uint64_t seed) {
  const double rest[2] = {L.l_o, L.l_o};
  return BornSurface(L, mech, seed, 0xba5eba11u, rest);
}

Surface BornSurface(const Lattice& L, const Mechanics& mech, uint64_t seed, uint64_t stream,
                    const double rest[2]) {
  Surface s;
  const std::size_t n = static_cast<std::size_t>(L.nodes());
  s.ux.assign(n, 0.0f);
  s.uz.assign(n, 0.0f);
  s.wx.assign(n, 0.0f);
  s.wz.assign(n, 0.0f);
  s.fx.assign(n, 0.0f);
  s.fz.assign(n, 0.0f);
  s.gx.assign(L.a.size(), 0.0f);
  s.gz.assign(L.a.size(), 0.0f);
  s.limit2.resize(L.a.size());
  s.broken.assign(L.a.size(), 0);

  TruncatedNormal normal(seed, stream);
  for (int i = 0; i < L.springs(); ++i) {
    const int f = static_cast<int>(L.family(i));
    double excess = (mech.kappa_mean[f] - 1.0) * (1.0 + mech.sigma * normal.Next());
    if (excess < 1e-4) excess = 1e-4;
    const double limit = (1.0 + excess) * rest[f];
    s.limit2[L.slot(i)] = static_cast<float>(limit * limit);
  }
  return s;
}

int Step(const Lattice& L, const Mechanics& mech, const Growth& g, Surface* s) {
  const float l0 = static_cast<float>(L.l_o);
  const float k[2] = {static_cast<float>(mech.k[0]), static_cast<float>(mech.k[1])};
  const float c[2] = {static_cast<float>(mech.c[0]), static_cast<float>(mech.c[1])};
  const float rest[2] = {l0, l0};
  const int broke = SpringSlotForces(L, k, c, rest, g, s);
  // Nodes: the springs' forces, the shear spring and dashpot to the anchor, then symplectic Euler,
  // four or eight nodes a batch (BatchLanes; their sums as lanes where their springs lie in runs,
  // else node by node; the rest of the arithmetic lane by lane as one by one), a tail of fewer
  // than four one by one.
  NodePass2 p;
  p.inc_slot = L.inc_slot.data();
  p.inc_a = L.inc_a.data();
  p.run4 = L.node_run4.data();
  p.run8 = L.node_run8.data();
  p.gx = s->gx.data();
  p.gz = s->gz.data();
  p.ux = s->ux.data();
  p.uz = s->uz.data();
  p.wx = s->wx.data();
  p.wz = s->wz.data();
  p.dt = static_cast<float>(mech.dt);
  p.inv_m = static_cast<float>(1.0 / mech.mass);
  p.ks = static_cast<float>(mech.k_s);
  p.cs = static_cast<float>(mech.c_s);
#if NIWA_BARK_EIGHT
  if (BatchLanes() == 8) {
    NodeLoop2Eight(p, L.nodes());
    return broke;
  }
#endif
  NodeLoop2Four(p, L.nodes());
  return broke;
}

int SpringSlotForces(const Lattice& L, const float k[2], const float c[2], const float rest[2],
                     const Growth& g, Surface* s) {
  const std::size_t slots = static_cast<std::size_t>(L.springs());
  if (s->gx.size() != slots) {
    s->gx.assign(slots, 0.0f);
    s->gz.assign(slots, 0.0f);
  }
  int broke[2] = {0, 0};
  SpringSlotForcesRange(L, k, c, rest, g, s, 0, L.nodes(), broke);
  s->broken_count[0] += broke[0];
  s->broken_count[1] += broke[1];
  return broke[0] + broke[1];
}

void SpringSlotForcesRange(const Lattice& L, const float k[2], const float c[2],
                           const float rest[2], const Growth& g, Surface* s, int begin, int end,
                           int broke[2]) {
  // Break checks and forces of the three sub-families, four or eight nodes a batch (BatchLanes),
  // the arithmetic lane by lane; a tail of fewer than four one by one with the same operations,
  // so the bits do not depend on the batching. The forces go to the slots (gx, gz); a node pass
  // sums them (NodeBatch2, NodeOne2). Each spring's arithmetic is its own, so a pass split into
  // ranges gives the bits of the whole.
  SpringPass p;
  const int n = L.nodes();
  p.ux = s->ux.data();
  p.uz = s->uz.data();
  p.wx = s->wx.data();
  p.wz = s->wz.data();
  p.broken = s->broken.data();
  for (int t = 0; t < 3; ++t) {
    const int base = t * n, family = t > 0;
    p.first[t] = t == 0 ? 0 : L.axial_count + (t - 1);
    p.stride[t] = t == 0 ? 1 : 2;
    const float ox = L.ox[p.first[t]], oz = L.oz[p.first[t]];
    p.b[t] = L.slot_b.data() + base;
    p.run4[t] = L.slot_run4.data() + base;
    p.run8[t] = L.slot_run8.data() + base;
    p.gx[t] = s->gx.data() + base;
    p.gz[t] = s->gz.data() + base;
    p.limit2[t] = s->limit2.data() + base;
    p.dx0[t] = ox * g.s_theta;
    p.dz0[t] = oz * g.s_z;
    p.rx0[t] = ox * g.rate_theta;
    p.rz0[t] = oz * g.rate_z;
    p.k[t] = k[family];
    p.c[t] = c[family];
    p.l0[t] = rest[family];
  }
#if NIWA_BARK_EIGHT
  if (BatchLanes() == 8) {
    SpringLoop8(p, begin, end, broke);
    return;
  }
#endif
  SpringLoop4(p, begin, end, broke);
}

int SpringForces(const Lattice& L, const float k[2], const float c[2], const float rest[2],
                 const Growth& g, Surface* s) {
  const int broke = SpringSlotForces(L, k, c, rest, g, s);
  for (int i = 0; i < L.nodes(); ++i) {
    // The accumulators plus the springs in ascending index: what adding spring by spring gave.
    const std::size_t e0 = 6 * static_cast<std::size_t>(i);
    for (std::size_t e = e0; e < e0 + 6; ++e) {
      const int q = L.inc_slot[e];
      if (L.inc_a[e]) {
        s->fx[i] += s->gx[q];
        s->fz[i] += s->gz[q];
      } else {
        s->fx[i] -= s->gx[q];
        s->fz[i] -= s->gz[q];
      }
    }
  }
  return broke;
}

double SpringStrain(const Lattice& L, const Surface& s, const Growth& g, int i) {
  const int a = L.a[i], b = L.b[i];
  const double dx = static_cast<double>(L.ox[i]) * g.s_theta + (s.ux[b] - s.ux[a]);
  const double dz = static_cast<double>(L.oz[i]) * g.s_z + (s.uz[b] - s.uz[a]);
  return std::sqrt(dx * dx + dz * dz) / L.l_o - 1.0;
}

double Energy(const Lattice& L, const Mechanics& mech, const Growth& g, const Surface& s) {
  double e = 0;
  for (int i = 0; i < L.springs(); ++i) {
    if (s.broken[i]) continue;
    const double dl = SpringStrain(L, s, g, i) * L.l_o;
    e += 0.5 * mech.k[static_cast<int>(L.family(i))] * dl * dl;
  }
  for (int n = 0; n < L.nodes(); ++n) {
    const double ux = s.ux[n], uz = s.uz[n], wx = s.wx[n], wz = s.wz[n];
    e += 0.5 * mech.k_s * (ux * ux + uz * uz) + 0.5 * mech.mass * (wx * wx + wz * wz);
  }
  return e;
}

}  // namespace niwa::bark
