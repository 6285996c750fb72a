// The 4-layer model: three spring layers with shear springs, role exchange, peeling, shedding.
#include "bark/four_layer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "bark/node_sums.h"
#include "bark/regions.h"
#include "math/det_math.h"
#include "math/simd4.h"
#include "math/simd8.h"

// The batch kernels are inlined into their four- and eight-lane loops (math/simd8.h), so no 256-bit
// value crosses a call: GCC's warning on that ABI does not apply (to the end of the file, where GCC
// places some of them).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace niwa::bark {
namespace {

constexpr float kNever = std::numeric_limits<float>::infinity();
constexpr double kThinFloor = 0.05;  // M2's mechanical thickness floor, a share of D
constexpr int kMaxChunks = 4;        // chunks of a pass on lanes (step_lanes.h)
// PCG32 streams of a layer born at cycle k: its springs' thresholds and its upper bond's κ_h.
constexpr uint64_t kLayerStream = 0x4c41594552000000ull;  // "LAYER"
uint64_t SpringStream(int born) { return kLayerStream + 2u * static_cast<uint64_t>(born + 2); }
uint64_t BondStream(int born) { return SpringStream(born) + 1u; }

// Shear stiffness between a layer of thickness share a and one of b (of D):
// G·A_n/D_s, D_s = max((a + b)/2, 0.1)·D.
double ShearK(const Mechanics& base, double a, double b) {
  return base.k_s / std::max((a + b) / 2.0, 0.1);
}

// Rest lengths of a layer born when its anchors are scaled by (s_θ, s_z).
void RestAt(const Lattice& L, double s_theta, double s_z, double rest[2]) {
  rest[0] = L.l_o * s_z;
  const double x = L.pitch() * s_theta, z = L.l_o / 2.0 * s_z;
  rest[1] = std::sqrt(x * x + z * z);
}

CorkLayer BornLayer(const Lattice& L, const FourLayerMechanics& m, uint64_t seed, int born,
                    double s_theta, double s_z) {
  CorkLayer c;
  c.born = born;
  RestAt(L, s_theta, s_z, c.rest);
  c.s = BornSurface(L, m.base, seed, SpringStream(born), c.rest);
  const std::size_t n = static_cast<std::size_t>(L.nodes());
  c.present.assign(n, 1);
  c.bonded.assign(n, 1);
  c.bond_x.assign(n, 0.0f);
  c.bond_z.assign(n, 0.0f);
  c.kappa_h.assign(n, static_cast<float>(m.kappa_h));
  c.dry_step.assign(n, -1);
  c.shear_limit2.assign(n, kNever);
  return c;
}

// A new bond of `upper` to a layer born at cycle `born` beneath it (whose u is 0): its slip now is
// its rest, its critical strains κ_h(1 + σξ) from the newborn layer's bond stream.
void FormBond(const FourLayerMechanics& m, uint64_t seed, int born, CorkLayer* upper) {
  TruncatedNormal normal(seed, BondStream(born));
  const std::size_t n = upper->present.size();
  for (std::size_t i = 0; i < n; ++i) {
    upper->bonded[i] = 1;
    upper->bond_x[i] = upper->s.ux[i];
    upper->bond_z[i] = upper->s.uz[i];
    double k = m.kappa_h * (1.0 + m.base.sigma * normal.Next());
    if (k < 1e-6) k = 1e-6;
    upper->kappa_h[i] = static_cast<float>(k);
    upper->dry_step[i] = -1;
    const double lim = k * m.d;
    upper->shear_limit2[i] = static_cast<float>(lim * lim);
  }
}

// The layout of cycle k at phase τ ∈ [0, 1], growing or frozen.
LayerGrowth LayoutAt(const FourLayerMechanics& m, int k, double tau, bool growing) {
  LayerGrowth lg;
  const double dc = m.cork;
  lg.r_inner = m.r_o + m.delta_r * (k + tau);
  lg.thickness_m2 = dc * tau;
  lg.stiffness_m2 = std::max(tau, kThinFloor);
  lg.mid[kM2] = lg.r_inner + dc * tau / 2.0;
  lg.mid[kM1] = lg.r_inner + dc * tau + dc / 2.0;
  lg.mid[kS] = lg.r_inner + dc * tau + 1.5 * dc;
  const double rate_in = m.delta_r / m.period;
  const double rate_mid[3] = {rate_in + dc / m.period, rate_in + dc / m.period,
                              rate_in + dc / (2.0 * m.period)};
  const double ez = m.base.strain_rate_z * (k + tau) * m.period;
  for (int r = 0; r < 3; ++r) {
    lg.g[r].s_theta = static_cast<float>(lg.mid[r] / m.r_o);
    lg.g[r].s_z = static_cast<float>(1.0 + ez);
    lg.g[r].rate_theta = growing ? static_cast<float>(rate_mid[r] / m.r_o) : 0.0f;
    lg.g[r].rate_z = growing ? static_cast<float>(m.base.strain_rate_z) : 0.0f;
  }
  return lg;
}

// Takes node i out of S: its springs off (marked broken without counting a crack), its bond cut.
void PeelNode(const Lattice& L, const FourLayer& f, int i, CorkLayer* s) {
  s->present[i] = 0;
  s->bonded[i] = 0;
  s->s.wx[i] = 0.0f;
  s->s.wz[i] = 0.0f;
  for (int q = f.node_spring_start[i]; q < f.node_spring_start[i + 1]; ++q) {
    const int sp = f.node_springs[q];
    s->s.broken[sp] = 1;
    s->s.limit2[L.slot(sp)] = kNever;
  }
}

// The node pass of a step (StepFourLayer): each node's spring forces (summed from the slots),
// the shear springs S→M1 (breakable), M1→M2 and M2→I, then symplectic Euler per layer. Raw
// pointers and constants, copied into the loops' locals (a byte store may alias anything it
// reaches through a reference, forcing reloads).
struct NodePass {
  const int32_t* inc_slot;
  const uint8_t *inc_a, *run4, *run8;
  float *ux[3], *uz[3], *wx[3], *wz[3];  // by role
  const float *gx[3], *gz[3];
  uint8_t* bonded;  // S's
  const uint8_t* present;
  const float *bond_x[2], *bond_z[2];  // S's and M1's
  const float* shear_limit2;
  float ks0, cs0, ks1, cs1, dt, inv_m, inv_m2;
};

// The constants in every lane, made once a loop.
template <class V>
struct NodeLanes {
  V ks0, cs0, ks1, cs1, dt, inv_m, inv_m2, zero;
  explicit NodeLanes(const NodePass& p)
      : ks0(simd::SplatLanes<V>(p.ks0)),
        cs0(simd::SplatLanes<V>(p.cs0)),
        ks1(simd::SplatLanes<V>(p.ks1)),
        cs1(simd::SplatLanes<V>(p.cs1)),
        dt(simd::SplatLanes<V>(p.dt)),
        inv_m(simd::SplatLanes<V>(p.inv_m)),
        inv_m2(simd::SplatLanes<V>(p.inv_m2)),
        zero(simd::SplatLanes<V>(0.0f)) {}
};

// The S→M1 bonds of nodes i + k snapped, k the bits of `bits` (rare: out of the loops' way).
// It takes S's bond flags, not the pass, so the pass's address does not escape the loops.
__attribute__((noinline)) void SnapBonds(uint8_t* bonded, int i, int bits, int* snapped) {
  for (int q = 0; bits != 0; ++q, bits >>= 1) {
    if (!(bits & 1)) continue;
    bonded[i + q] = 0;
    ++*snapped;
  }
}

// Node i's spring forces in layer r: its six springs in ascending index added to 0 (springs.cpp
// NodeForce2).
NIWA_LANES_INLINE void NodeForceOf(const NodePass& p, int r, int i, float* fx, float* fz) {
  NodeSums(p.gx[r], p.gz[r], p.inc_slot, p.inc_a, 6 * static_cast<std::size_t>(i), fx, fz);
}

// Nodes i..i+W−1 (W lanes of V, masks I): lane by lane what NodeOne does, selects in place of its
// branches. Each layer's springs are summed in ascending index from 0: as lanes where the nodes'
// springs lie in runs (`run`: node_run4 or node_run8 at i; springs.cpp NodeBatch2), else node by
// node.
template <class V, class I>
NIWA_LANES_INLINE void NodeBatch(const NodePass& p, const NodeLanes<V>& c, int i, bool run,
                                 int* snapped) {
  using simd::LoadLanes;
  using simd::StoreLanes;
  constexpr int W = sizeof(V) / sizeof(float);  // lanes
  V fx[3], fz[3];
  if (run) {
    const std::size_t e0 = 6 * static_cast<std::size_t>(i);
    for (int r = 0; r < 3; ++r)
      RunSums<V>(p.gx[r], p.gz[r], p.inc_slot, p.inc_a, e0, &fx[r], &fz[r]);
  } else {
    // At the seams each node's springs come in its own order: the sums one by one (into an array,
    // not lane by lane into the vector: WASM would spill it for each lane).
    for (int r = 0; r < 3; ++r) {
      float x[W], z[W];
      for (int q = 0; q < W; ++q) NodeForceOf(p, r, i + q, &x[q], &z[q]);
      fx[r] = LoadLanes<V>(x);
      fz[r] = LoadLanes<V>(z);
    }
  }
  const V sux = LoadLanes<V>(p.ux[kS] + i), suz = LoadLanes<V>(p.uz[kS] + i),
          swx = LoadLanes<V>(p.wx[kS] + i), swz = LoadLanes<V>(p.wz[kS] + i);
  V aux = LoadLanes<V>(p.ux[kM1] + i), auz = LoadLanes<V>(p.uz[kM1] + i),
    awx = LoadLanes<V>(p.wx[kM1] + i), awz = LoadLanes<V>(p.wz[kM1] + i);
  V bux = LoadLanes<V>(p.ux[kM2] + i), buz = LoadLanes<V>(p.uz[kM2] + i),
    bwx = LoadLanes<V>(p.wx[kM2] + i), bwz = LoadLanes<V>(p.wz[kM2] + i);
  const I bonded = simd::NonZeroBytes<I>(p.bonded + i);
  const I present = simd::NonZeroBytes<I>(p.present + i);
  const V slip_x = (sux - aux) - LoadLanes<V>(p.bond_x[0] + i);
  const V slip_z = (suz - auz) - LoadLanes<V>(p.bond_z[0] + i);
  const I snaps = bonded & (slip_x * slip_x + slip_z * slip_z > LoadLanes<V>(p.shear_limit2 + i));
  const I holds = bonded & ~snaps;
  if (simd::AnyTrue(snaps)) SnapBonds(p.bonded, i, simd::LaneBits(snaps), snapped);
  const V sx = simd::Select(holds, c.ks0 * slip_x + c.cs0 * (swx - awx), c.zero);
  const V sz = simd::Select(holds, c.ks0 * slip_z + c.cs0 * (swz - awz), c.zero);
  const V px = c.ks1 * ((aux - bux) - LoadLanes<V>(p.bond_x[1] + i)) + c.cs1 * (awx - bwx);
  const V pz = c.ks1 * ((auz - buz) - LoadLanes<V>(p.bond_z[1] + i)) + c.cs1 * (awz - bwz);
  const V qx = c.ks1 * bux + c.cs1 * bwx;
  const V qz = c.ks1 * buz + c.cs1 * bwz;
  const V nwx = swx + c.dt * ((fx[kS] - sx) * c.inv_m);
  const V nwz = swz + c.dt * ((fz[kS] - sz) * c.inv_m);
  StoreLanes(p.wx[kS] + i, simd::Select(present, nwx, swx));
  StoreLanes(p.wz[kS] + i, simd::Select(present, nwz, swz));
  StoreLanes(p.ux[kS] + i, simd::Select(present, sux + c.dt * nwx, sux));
  StoreLanes(p.uz[kS] + i, simd::Select(present, suz + c.dt * nwz, suz));
  awx += c.dt * ((fx[kM1] + sx - px) * c.inv_m);
  awz += c.dt * ((fz[kM1] + sz - pz) * c.inv_m);
  aux += c.dt * awx;
  auz += c.dt * awz;
  bwx += c.dt * ((fx[kM2] + px - qx) * c.inv_m2);
  bwz += c.dt * ((fz[kM2] + pz - qz) * c.inv_m2);
  bux += c.dt * bwx;
  buz += c.dt * bwz;
  StoreLanes(p.wx[kM1] + i, awx);
  StoreLanes(p.wz[kM1] + i, awz);
  StoreLanes(p.ux[kM1] + i, aux);
  StoreLanes(p.uz[kM1] + i, auz);
  StoreLanes(p.wx[kM2] + i, bwx);
  StoreLanes(p.wz[kM2] + i, bwz);
  StoreLanes(p.ux[kM2] + i, bux);
  StoreLanes(p.uz[kM2] + i, buz);
}

// Node i alone (at the seams, where a node's springs come in another order).
NIWA_LANES_INLINE void NodeOne(const NodePass& p, int i, int* snapped) {
  float fx[3], fz[3];
  for (int r = 0; r < 3; ++r) NodeForceOf(p, r, i, &fx[r], &fz[r]);
  float* sux = p.ux[kS];
  float* suz = p.uz[kS];
  float* swx = p.wx[kS];
  float* swz = p.wz[kS];
  float* aux = p.ux[kM1];
  float* auz = p.uz[kM1];
  float* awx = p.wx[kM1];
  float* awz = p.wz[kM1];
  float* bux = p.ux[kM2];
  float* buz = p.uz[kM2];
  float* bwx = p.wx[kM2];
  float* bwz = p.wz[kM2];
  // S → M1, breaking past the node's shear limit (checked on the positions the step starts from,
  // as the springs are).
  float sx = 0.0f, sz = 0.0f;
  if (p.bonded[i]) {
    const float slip_x = (sux[i] - aux[i]) - p.bond_x[0][i];
    const float slip_z = (suz[i] - auz[i]) - p.bond_z[0][i];
    if (slip_x * slip_x + slip_z * slip_z > p.shear_limit2[i]) {
      p.bonded[i] = 0;
      ++*snapped;
    } else {
      sx = p.ks0 * slip_x + p.cs0 * (swx[i] - awx[i]);
      sz = p.ks0 * slip_z + p.cs0 * (swz[i] - awz[i]);
    }
  }
  // M1 → M2 (never breaks).
  const float px = p.ks1 * ((aux[i] - bux[i]) - p.bond_x[1][i]) + p.cs1 * (awx[i] - bwx[i]);
  const float pz = p.ks1 * ((auz[i] - buz[i]) - p.bond_z[1][i]) + p.cs1 * (awz[i] - bwz[i]);
  // M2 → I (the anchor; never breaks).
  const float qx = p.ks1 * bux[i] + p.cs1 * bwx[i];
  const float qz = p.ks1 * buz[i] + p.cs1 * bwz[i];
  const float dt = p.dt;
  if (p.present[i]) {
    swx[i] += dt * ((fx[kS] - sx) * p.inv_m);
    swz[i] += dt * ((fz[kS] - sz) * p.inv_m);
    sux[i] += dt * swx[i];
    suz[i] += dt * swz[i];
  }
  awx[i] += dt * ((fx[kM1] + sx - px) * p.inv_m);
  awz[i] += dt * ((fz[kM1] + sz - pz) * p.inv_m);
  aux[i] += dt * awx[i];
  auz[i] += dt * awz[i];
  bwx[i] += dt * ((fx[kM2] + px - qx) * p.inv_m2);
  bwz[i] += dt * ((fz[kM2] + pz - qz) * p.inv_m2);
  bux[i] += dt * bwx[i];
  buz[i] += dt * bwz[i];
}

// Nodes [begin, end): four a batch (their sums as lanes where their springs lie in runs), a tail of
// fewer than four one by one; returns the S→M1 bonds snapped (the nodes' arithmetic is their own:
// any split of the range gives the same bits).
int NodeLoop4(const NodePass& pass, int begin, int end) {
  const NodePass p = pass;
  const NodeLanes<simd::Float4> c4(p);
  int snapped = 0, i = begin;
  for (; i + 4 <= end; i += 4) NodeBatch<simd::Float4, simd::Int4>(p, c4, i, p.run4[i], &snapped);
  for (; i < end; ++i) NodeOne(p, i, &snapped);
  return snapped;
}

#if NIWA_BARK_EIGHT
// The same with eight a batch where eight nodes' springs lie in runs (else two of four), in AVX2
// natively.
NIWA_BARK_EIGHT_TARGET int NodeLoop8(const NodePass& pass, int begin, int end) {
  const NodePass p = pass;
  const NodeLanes<simd::Float4> c4(p);
  const NodeLanes<simd::Float8> c8(p);
  int snapped = 0, i = begin;
  for (; i + 8 <= end; i += 8) {
    if (p.run8[i]) {
      NodeBatch<simd::Float8, simd::Int8>(p, c8, i, true, &snapped);
    } else {
      NodeBatch<simd::Float4, simd::Int4>(p, c4, i, p.run4[i], &snapped);
      NodeBatch<simd::Float4, simd::Int4>(p, c4, i + 4, p.run4[i + 4], &snapped);
    }
  }
  for (; i + 4 <= end; i += 4) NodeBatch<simd::Float4, simd::Int4>(p, c4, i, p.run4[i], &snapped);
  for (; i < end; ++i) NodeOne(p, i, &snapped);
  return snapped;
}
#endif

}  // namespace

FourLayerMechanics FourLayerMechanicsOf(const BarkParams& p, const Lattice& L) {
  FourLayerMechanics m;
  m.base = MechanicsOf(p);
  const Mechanics& b = m.base;
  m.r_o = L.radius();
  m.delta_r = p.Get(BarkParam::kDeltaR) * m.r_o;
  m.d = p.Get(BarkParam::kD);
  m.cork = m.d * p.Get(BarkParam::kCork);
  m.period = p.Get(BarkParam::kT);
  m.kappa_h = p.Get(BarkParam::kKappaH);
  m.eta = p.Get(BarkParam::kEta);
  m.gamma = p.Get(BarkParam::kGamma);
  m.area_ratio = p.Get(BarkParam::kA);
  // The stiffest layer per unit mass: M2 at its floor (mass and springs × 0.05, two shear springs
  // to thick neighbours), or M1 (three shear springs' worth), or S.
  const double intra = 2.0 * b.k[0] + 4.0 * b.k[1];
  const double f = kThinFloor;
  const double k_thin = ShearK(b, 1.0, f);
  const double w_m2 = (2.0 * k_thin + f * intra) / (f * b.mass);
  const double w_m1 = (b.k_s + k_thin + intra) / b.mass;
  const double w_s = (b.k_s + intra) / b.mass;
  const double w = std::max({w_m2, w_m1, w_s});
  const double dt0 = 0.3 / std::sqrt(w);
  m.steps_per_cycle = static_cast<int>(std::ceil(m.period / dt0));
  m.dt = m.period / m.steps_per_cycle;
  return m;
}

FourLayer StartFourLayer(const Lattice& L, const FourLayerMechanics& m, uint64_t seed, int cycles) {
  FourLayer f;
  f.m = m;
  f.growth_steps = cycles * m.steps_per_cycle;
  const LayerGrowth lg = LayoutAt(m, 0, 0.0, true);
  // S was born at cycle −2, M1 at −1, M2 at 0 (Fig. 7's roles at t = 0).
  for (int r = 0; r < 3; ++r)
    f.layer[r] = BornLayer(L, m, seed, r - 2, lg.g[r].s_theta, lg.g[r].s_z);
  FormBond(m, seed, f.layer[kM1].born, &f.layer[kS]);
  FormBond(m, seed, f.layer[kM2].born, &f.layer[kM1]);
  // The node -> springs index (each spring listed at both its ends).
  const int n = L.nodes();
  f.node_spring_start.assign(n + 1, 0);
  for (int s = 0; s < L.springs(); ++s) {
    ++f.node_spring_start[L.a[s] + 1];
    ++f.node_spring_start[L.b[s] + 1];
  }
  for (int i = 0; i < n; ++i) f.node_spring_start[i + 1] += f.node_spring_start[i];
  f.node_springs.resize(f.node_spring_start[n]);
  std::vector<int32_t> fill(f.node_spring_start.begin(), f.node_spring_start.end() - 1);
  for (int s = 0; s < L.springs(); ++s) {
    f.node_springs[fill[L.a[s]]++] = s;
    f.node_springs[fill[L.b[s]]++] = s;
  }
  return f;
}

LayerGrowth LayerGrowthAt(const FourLayer& f) {
  const bool growing = f.step < f.growth_steps;
  const int t = std::min(f.step, f.growth_steps);
  const double tau = static_cast<double>(t - f.cycle * f.m.steps_per_cycle) / f.m.steps_per_cycle;
  return LayoutAt(f.m, f.cycle, tau, growing);
}

bool StepFourLayer(const Lattice& L, FourLayer* f, StepLanes* lanes) {
  const FourLayerMechanics& m = f->m;
  const Mechanics& b = m.base;
  const LayerGrowth lg = LayerGrowthAt(*f);
  const double th = lg.stiffness_m2;
  const int n = L.nodes();
  // With lanes, the passes' chunks: nodes [bound(k), bound(k + 1)), quarters (halves below 512
  // nodes), each bound but the last a multiple of eight (the passes' batches start there). Few and
  // large: 128-node chunks made the two threads' steps ~1.1× slower than quarters (pine 128 × 64;
  // docs/bark-model.md choice 16), the layers' state streamed in short runs and moved between
  // the cores' caches; with quarters each thread keeps its half in its own cache when both run.
  const int chunks = !lanes ? 1 : n >= 512 ? kMaxChunks : 2;
  auto bound = [&](int k) {
    return k == chunks ? n : static_cast<int>(static_cast<int64_t>(k) * n / chunks) / 8 * 8;
  };
  // Springs of the three layers (M2's constants scaled by its thickness share).
  float k[3][2], c[3][2], rest[3][2];
  for (int r = 0; r < 3; ++r) {
    const double share = r == kM2 ? th : 1.0;
    for (int t = 0; t < 2; ++t) {
      k[r][t] = static_cast<float>(b.k[t] * share);
      c[r][t] = static_cast<float>(b.c[t] * share);
      rest[r][t] = static_cast<float>(f->layer[r].rest[t]);
    }
    Surface& s = f->layer[r].s;
    if (s.gx.size() != static_cast<std::size_t>(L.springs())) {
      s.gx.assign(L.springs(), 0.0f);
      s.gz.assign(L.springs(), 0.0f);
    }
  }
  int broke[kMaxChunks][3][2] = {};  // chunk, layer, family
  auto spring_pass = [&](int chunk) {
    for (int r = 0; r < 3; ++r)
      SpringSlotForcesRange(L, k[r], c[r], rest[r], lg.g[r], &f->layer[r].s, bound(chunk),
                            bound(chunk + 1), broke[chunk][r]);
  };
  if (lanes) {
    lanes->Run(chunks, spring_pass);
  } else {
    spring_pass(0);
  }
  int cracked = 0;
  for (int r = 0; r < 3; ++r) {
    for (int t = 0; t < 2; ++t) {
      int count = 0;
      for (int q = 0; q < chunks; ++q) count += broke[q][r][t];
      f->layer[r].s.broken_count[t] += count;
      cracked += count;
    }
  }
  if (cracked > 0 && f->first_crack_step < 0) f->first_crack_step = f->step;
  // Nodes: the shear springs S→M1 (breakable), M1→M2, M2→I, then symplectic Euler per layer.
  const double m2_mass = b.mass * th;
  const double k_low = ShearK(b, 1.0, th);  // M1→M2 and M2→I (I counted thickness D)
  const float ks0_all = static_cast<float>(b.k_s), cs0_all = static_cast<float>(b.c_s);
  const float ks1_all = static_cast<float>(k_low);
  const float cs1_all = static_cast<float>(2.0 * (b.c_s / (2.0 * std::sqrt(b.k_s * b.mass))) *
                                           std::sqrt(k_low * m2_mass));
  const float dt_all = static_cast<float>(m.dt);
  const float inv_m_all = static_cast<float>(1.0 / b.mass);
  const float inv_m2_all = static_cast<float>(1.0 / m2_mass);
  NodePass p;
  p.inc_slot = L.inc_slot.data();
  p.inc_a = L.inc_a.data();
  p.run4 = L.node_run4.data();
  p.run8 = L.node_run8.data();
  for (int r = 0; r < 3; ++r) {
    Surface& s = f->layer[r].s;
    p.ux[r] = s.ux.data();
    p.uz[r] = s.uz.data();
    p.wx[r] = s.wx.data();
    p.wz[r] = s.wz.data();
    p.gx[r] = s.gx.data();
    p.gz[r] = s.gz.data();
  }
  CorkLayer& S = f->layer[kS];
  CorkLayer& M1 = f->layer[kM1];
  p.bonded = S.bonded.data();
  p.present = S.present.data();
  p.bond_x[0] = S.bond_x.data();
  p.bond_z[0] = S.bond_z.data();
  p.bond_x[1] = M1.bond_x.data();
  p.bond_z[1] = M1.bond_z.data();
  p.shear_limit2 = S.shear_limit2.data();
  p.ks0 = ks0_all;
  p.cs0 = cs0_all;
  p.ks1 = ks1_all;
  p.cs1 = cs1_all;
  p.dt = dt_all;
  p.inv_m = inv_m_all;
  p.inv_m2 = inv_m2_all;
  const bool eight = BatchLanes() == 8;
  auto node_pass = [&](int begin, int end, int* snapped) {
#if NIWA_BARK_EIGHT
    if (eight) {
      *snapped += NodeLoop8(p, begin, end);
      return;
    }
#endif
    static_cast<void>(eight);
    *snapped += NodeLoop4(p, begin, end);
  };
  int snapped[kMaxChunks] = {};
  if (lanes) {
    lanes->Run(chunks,
               [&](int chunk) { node_pass(bound(chunk), bound(chunk + 1), &snapped[chunk]); });
  } else {
    node_pass(0, n, &snapped[0]);
  }
  for (int q = 0; q < chunks; ++q) f->bonds_broken += snapped[q];
  ++f->step;
  if (f->step % kPeelCheckSteps == 0) CheckPeeling(L, f, lanes);
  return f->step <= f->growth_steps && f->step % m.steps_per_cycle == 0;
}

void ExchangeRoles(const Lattice& L, uint64_t seed, FourLayer* f) {
  // What is left of S is shed: its plates (of two triangles or more, as the region measure
  // counts them) and its nodes.
  f->shed_regions += MeasurePlates(L, f->layer[kS].s, 1.0, 1.0).count;
  f->shed_nodes += PresentNodes(*f);
  f->layer[kS] = std::move(f->layer[kM1]);
  f->layer[kM1] = std::move(f->layer[kM2]);
  ++f->cycle;
  // The new S starts its drying clock afresh (its limits are its bond's κ_h until the next check).
  CorkLayer& s = f->layer[kS];
  for (std::size_t i = 0; i < s.dry_step.size(); ++i) {
    s.dry_step[i] = -1;
    const double lim = static_cast<double>(s.kappa_h[i]) * f->m.d;
    s.shear_limit2[i] = static_cast<float>(lim * lim);
  }
  const LayerGrowth lg = LayoutAt(f->m, f->cycle, 0.0, true);
  f->layer[kM2] = BornLayer(L, f->m, seed, f->cycle, lg.g[kM2].s_theta, lg.g[kM2].s_z);
  FormBond(f->m, seed, f->cycle, &f->layer[kM1]);
}

namespace {

// The drying half of CheckPeeling: onsets (t_i) of S's nodes within η of a drying source and
// their shear limits now. Reads S's springs and flags, writes only dry_step and shear_limit2.
void Dry(const Lattice& L, FourLayer* f) {
  const FourLayerMechanics& m = f->m;
  CorkLayer& S = f->layer[kS];
  const int n = L.nodes();
  // Drying sources: peeled nodes and the ends of broken S springs.
  std::vector<uint8_t> source(n, 0);
  for (int i = 0; i < n; ++i) source[i] = !S.present[i];
  for (int s = 0; s < L.springs(); ++s) {
    if (!S.s.broken[s]) continue;
    source[L.a[s]] = 1;
    source[L.b[s]] = 1;
  }
  // Node offsets within η at S's current scale, for even and odd columns.
  const LayerGrowth lg = LayerGrowthAt(*f);
  const double st = lg.g[kS].s_theta, sz = lg.g[kS].s_z;
  const double pitch = L.pitch() * st, lo = L.l_o * sz;
  const int reach_c = static_cast<int>(std::floor(m.eta / pitch)),
            reach_z = static_cast<int>(std::floor(m.eta / lo)) + 1;
  std::vector<std::pair<int, int>> offsets[2];
  for (int parity = 0; parity < 2; ++parity) {
    for (int dc = -std::min(reach_c, L.n_r / 2); dc <= std::min(reach_c, (L.n_r - 1) / 2); ++dc) {
      const int other = ((parity + dc) % 2 + 2) % 2;
      for (int dj = -std::min(reach_z, L.n_h / 2); dj <= std::min(reach_z, (L.n_h - 1) / 2); ++dj) {
        const double dx = dc * pitch, dz = (dj + (other - parity) * 0.5) * lo;
        if (dx * dx + dz * dz <= m.eta * m.eta) offsets[parity].push_back({dc, dj});
      }
    }
  }
  std::vector<uint8_t> near(n, 0);
  for (int i = 0; i < n; ++i) {
    if (!source[i]) continue;
    const int c = i / L.n_h, j = i % L.n_h;
    for (const auto& [dc, dj] : offsets[c % 2]) {
      const int c2 = ((c + dc) % L.n_r + L.n_r) % L.n_r;
      const int j2 = ((j + dj) % L.n_h + L.n_h) % L.n_h;
      near[L.node(c2, j2)] = 1;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (!S.present[i] || !S.bonded[i]) continue;
    if (S.dry_step[i] < 0 && near[i]) S.dry_step[i] = f->step;
    double lim = S.kappa_h[i];
    if (S.dry_step[i] >= 0) lim *= det::Exp(-m.gamma * (f->step - S.dry_step[i]) * m.dt / m.period);
    lim *= m.d;
    S.shear_limit2[i] = static_cast<float>(lim * lim);
  }
}

}  // namespace

void CheckPeeling(const Lattice& L, FourLayer* f, StepLanes* lanes) {
  const FourLayerMechanics& m = f->m;
  CorkLayer& S = f->layer[kS];
  const int n = L.nodes();
  // The drying and the plates of S read the same state and write apart: one a lane.
  CrackMeasures plates;
  auto part = [&](int k) {
    if (k == 0) {
      plates = MeasurePlates(L, S.s, 1.0, 1.0);
    } else {
      Dry(L, f);
    }
  };
  if (lanes) {
    lanes->Run(2, part);
  } else {
    part(1);
    part(0);
  }
  // The area rule: closed regions (plates: S's triangles with three intact springs joined
  // across their edges, not wrapping the torus, as the maps draw them) with S_r/S_b > A, S_r and
  // S_b counted in nodes (its nodes, and those still bonded), or with no bond at all, peel. A node
  // in no plate (every triangle around it cracked) is a fragment of its own: it peels unbonded.
  std::vector<std::vector<int>> members(plates.regions.size());
  std::vector<int> stamp(n, -1);
  std::vector<uint8_t> in_plate(n, 0);
  for (std::size_t t = 0; t < plates.tri_region.size(); ++t) {
    const int id = plates.tri_region[t];
    if (id < 0) continue;
    for (int v : L.tri_nodes[t]) {
      in_plate[v] = 1;
      if (stamp[v] == id) continue;
      stamp[v] = id;
      members[id].push_back(v);
    }
  }
  std::vector<int> peel;
  for (std::size_t id = 0; id < members.size(); ++id) {
    if (!plates.regions[id].closed()) continue;
    int bonded = 0;
    for (int v : members[id]) bonded += S.bonded[v];
    if (bonded == 0 || static_cast<double>(members[id].size()) > m.area_ratio * bonded) {
      peel.insert(peel.end(), members[id].begin(), members[id].end());
      ++f->peel_events;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (S.present[i] && !in_plate[i] && !S.bonded[i]) {
      peel.push_back(i);
      ++f->peel_events;
    }
  }
  // A node of two peeling plates is peeled once.
  std::sort(peel.begin(), peel.end());
  peel.erase(std::unique(peel.begin(), peel.end()), peel.end());
  if (!peel.empty() && f->first_peel_step < 0) f->first_peel_step = f->step;
  for (int v : peel) PeelNode(L, *f, v, &S);
  f->peeled_nodes += static_cast<int>(peel.size());
}

int PresentNodes(const FourLayer& f) {
  int n = 0;
  for (uint8_t p : f.layer[kS].present) n += p;
  return n;
}

std::vector<uint8_t> VisibleLayer(const Lattice& L, const FourLayer& f) {
  std::vector<uint8_t> v(L.tri_nodes.size(), 3);
  for (std::size_t t = 0; t < v.size(); ++t) {
    const auto& sp = L.tri_springs[t];
    for (int r = 0; r < 3; ++r) {
      const std::vector<uint8_t>& br = f.layer[r].s.broken;
      if (!(br[sp[0]] || br[sp[1]] || br[sp[2]])) {
        v[t] = static_cast<uint8_t>(r);
        break;
      }
    }
  }
  return v;
}

}  // namespace niwa::bark
