// The 2-layer model's springs, dashpots, integration and breaking.
#include "bark/springs.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "math/det_math.h"
#include "math/simd4.h"
#include "random/pcg32.h"

namespace niwa::bark {

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

// Break checks and forces of one sub-family of springs (0: the axial springs; 1, 2: each node's
// first and second diagonal), the spring of node n joining a = n to b = slot_b: four nodes a
// batch, b loaded as a run where slot_run4 says so, else lane by lane, and the arithmetic lane by
// lane; a tail of fewer than four one by one with the same operations, so the bits do not depend
// on the batching. The forces go to the slots (gx, gz); a node pass sums them (NodeForce,
// NodeForce4). A batch of four broken springs only writes its zero forces. The reference vector of
// a sub-family is one (lattice.h: axial (0, L_o), diagonals (pitch, ±L_o/2)). Only the springs of
// nodes [begin, end) (begin a multiple of four): each spring's arithmetic is its own, so a pass
// split into ranges gives the bits of the whole.
int SubFamilyPass(const Lattice& L, int sub, float k, float c, float l0, const Growth& g,
                  Surface* s, int begin, int end) {
  using simd::Float4;
  using simd::Int4;
  const int n_nodes = end;
  const int base = sub * L.nodes();
  const int first = sub == 0 ? 0 : L.axial_count + (sub - 1), stride = sub == 0 ? 1 : 2;
  const float ox = L.ox[first], oz = L.oz[first];
  const int32_t* B = L.slot_b.data() + base;
  const uint8_t* run4 = L.slot_run4.data() + base;
  const float* ux = s->ux.data();
  const float* uz = s->uz.data();
  const float* wx = s->wx.data();
  const float* wz = s->wz.data();
  float* gx = s->gx.data() + base;
  float* gz = s->gz.data() + base;
  float* limit2 = s->limit2.data() + base;
  float* on = s->on.data() + base;
  const float st = g.s_theta, sz = g.s_z, rt = g.rate_theta, rz = g.rate_z;
  int broke = 0;
  auto record_break = [&](int n) {
    limit2[n] = kNever;
    on[n] = 0.0f;
    s->broken[first + stride * n] = 1;
    ++broke;
  };
  // The products of the constant reference vector (as the per-spring ox·s_θ etc. were).
  const float dx0 = ox * st, dz0 = oz * sz, rx0 = ox * rt, rz0 = oz * rz;
  const Float4 vdx0 = simd::Splat4(dx0), vdz0 = simd::Splat4(dz0), vrx0 = simd::Splat4(rx0),
               vrz0 = simd::Splat4(rz0), vk = simd::Splat4(k), vc = simd::Splat4(c),
               vl0 = simd::Splat4(l0), tiny = simd::Splat4(kTinyLength2), zero = simd::Splat4(0.0f),
               one = simd::Splat4(1.0f);
  auto load = [](const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  int n = begin;
  for (; n + 4 <= n_nodes; n += 4) {
    const Float4 alive = load(on + n);
    if (!simd::AnyTrue(alive != zero)) {
      // Broken before this step: no force, no break.
      std::memcpy(gx + n, &zero, sizeof zero);
      std::memcpy(gz + n, &zero, sizeof zero);
      continue;
    }
    Float4 bux, buz, bwx, bwz;
    if (run4[n]) {
      const int b = B[n];
      bux = load(ux + b);
      buz = load(uz + b);
      bwx = load(wx + b);
      bwz = load(wz + b);
    } else {
      const int b0 = B[n], b1 = B[n + 1], b2 = B[n + 2], b3 = B[n + 3];
      bux = Float4{ux[b0], ux[b1], ux[b2], ux[b3]};
      buz = Float4{uz[b0], uz[b1], uz[b2], uz[b3]};
      bwx = Float4{wx[b0], wx[b1], wx[b2], wx[b3]};
      bwz = Float4{wz[b0], wz[b1], wz[b2], wz[b3]};
    }
    const Float4 dx = vdx0 + (bux - load(ux + n)), dz = vdz0 + (buz - load(uz + n));
    const Float4 l2 = dx * dx + dz * dz;
    const Int4 breaks = l2 > load(limit2 + n);
    const Float4 l = simd::Sqrt(simd::Select(l2 > tiny, l2, tiny));
    const Float4 inv = one / l;
    const Float4 nx = dx * inv, nz = dz * inv;
    const Float4 rel = ((bwx - load(wx + n)) + vrx0) * nx + ((bwz - load(wz + n)) + vrz0) * nz;
    const Float4 f = simd::Select(breaks, zero, alive) * (vk * (l - vl0) + vc * rel);
    const Float4 fx = f * nx, fz = f * nz;
    std::memcpy(gx + n, &fx, sizeof fx);
    std::memcpy(gz + n, &fz, sizeof fz);
    if (simd::AnyTrue(breaks)) {
      for (int q = 0; q < 4; ++q)
        if (breaks[q]) record_break(n + q);
    }
  }
  for (; n < n_nodes; ++n) {
    const int a = n, b = B[n];
    const float dx = dx0 + (ux[b] - ux[a]);
    const float dz = dz0 + (uz[b] - uz[a]);
    const float l2 = dx * dx + dz * dz;
    const bool breaks = l2 > limit2[n];
    const float l = std::sqrt(l2 > kTinyLength2 ? l2 : kTinyLength2);
    const float inv = 1.0f / l;
    const float nx = dx * inv, nz = dz * inv;
    const float rel = ((wx[b] - wx[a]) + rx0) * nx + ((wz[b] - wz[a]) + rz0) * nz;
    const float f = (breaks ? 0.0f : on[n]) * (k * (l - l0) + c * rel);
    gx[n] = f * nx;
    gz[n] = f * nz;
    if (breaks) record_break(n);
  }
  return broke;
}

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
  s.on.assign(L.a.size(), 1.0f);
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
  // Nodes: the springs' forces, the shear spring and dashpot to the anchor, then symplectic Euler
  // (four nodes a batch where their springs lie in runs, lane by lane as one by one; the rest, at
  // the seams where a node's springs come in another order, one by one).
  const float dt = static_cast<float>(mech.dt);
  const float inv_m = static_cast<float>(1.0 / mech.mass);
  const float ks = static_cast<float>(mech.k_s), cs = static_cast<float>(mech.c_s);
  float* ux = s->ux.data();
  float* uz = s->uz.data();
  float* wx = s->wx.data();
  float* wz = s->wz.data();
  const int n = L.nodes();
  using simd::Float4;
  const Float4 vdt = simd::Splat4(dt), vinv = simd::Splat4(inv_m), vks = simd::Splat4(ks),
               vcs = simd::Splat4(cs);
  int i = 0;
  while (i < n) {
    if (i + 4 <= n && L.node_run4[i]) {
      Float4 fx, fz, x, z, vx, vz;
      NodeForce4(L, *s, i, &fx, &fz);
      std::memcpy(&x, ux + i, sizeof x);
      std::memcpy(&z, uz + i, sizeof z);
      std::memcpy(&vx, wx + i, sizeof vx);
      std::memcpy(&vz, wz + i, sizeof vz);
      const Float4 ax = (fx - vks * x - vcs * vx) * vinv;
      const Float4 az = (fz - vks * z - vcs * vz) * vinv;
      vx += vdt * ax;
      vz += vdt * az;
      x += vdt * vx;
      z += vdt * vz;
      std::memcpy(ux + i, &x, sizeof x);
      std::memcpy(uz + i, &z, sizeof z);
      std::memcpy(wx + i, &vx, sizeof vx);
      std::memcpy(wz + i, &vz, sizeof vz);
      i += 4;
      continue;
    }
    float fx, fz;
    NodeForce(L, *s, i, &fx, &fz);
    const float ax = (fx - ks * ux[i] - cs * wx[i]) * inv_m;
    const float az = (fz - ks * uz[i] - cs * wz[i]) * inv_m;
    wx[i] += dt * ax;
    wz[i] += dt * az;
    ux[i] += dt * wx[i];
    uz[i] += dt * wz[i];
    ++i;
  }
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
  broke[0] += SubFamilyPass(L, 0, k[0], c[0], rest[0], g, s, begin, end);
  broke[1] += SubFamilyPass(L, 1, k[1], c[1], rest[1], g, s, begin, end) +
              SubFamilyPass(L, 2, k[1], c[1], rest[1], g, s, begin, end);
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
