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

// Break checks and forces of the springs [begin, end) of one family: four springs a batch
// (indexed loads into lanes, the arithmetic lane by lane, the forces scattered in spring order),
// the rest one by one with the same operations, so the bits do not depend on the batching.
int SpringPass(const Lattice& L, int begin, int end, float k, float c, float l0, const Growth& g,
               Surface* s) {
  using simd::Float4;
  using simd::Int4;
  const int32_t* A = L.a.data();
  const int32_t* B = L.b.data();
  const float* OX = L.ox.data();
  const float* OZ = L.oz.data();
  const float* ux = s->ux.data();
  const float* uz = s->uz.data();
  const float* wx = s->wx.data();
  const float* wz = s->wz.data();
  float* fx = s->fx.data();
  float* fz = s->fz.data();
  float* limit2 = s->limit2.data();
  float* on = s->on.data();
  const float st = g.s_theta, sz = g.s_z, rt = g.rate_theta, rz = g.rate_z;
  int broke = 0;
  auto record_break = [&](int i) {
    limit2[i] = kNever;
    on[i] = 0.0f;
    s->broken[i] = 1;
    ++broke;
  };
  int i = begin;
  const Float4 vst = simd::Splat4(st), vsz = simd::Splat4(sz), vrt = simd::Splat4(rt),
               vrz = simd::Splat4(rz), vk = simd::Splat4(k), vc = simd::Splat4(c),
               vl0 = simd::Splat4(l0), tiny = simd::Splat4(kTinyLength2), zero = simd::Splat4(0.0f),
               one = simd::Splat4(1.0f);
  for (; i + 4 <= end; i += 4) {
    const int a0 = A[i], a1 = A[i + 1], a2 = A[i + 2], a3 = A[i + 3];
    const int b0 = B[i], b1 = B[i + 1], b2 = B[i + 2], b3 = B[i + 3];
    Float4 ox, oz, lim, alive;
    std::memcpy(&ox, OX + i, sizeof ox);
    std::memcpy(&oz, OZ + i, sizeof oz);
    std::memcpy(&lim, limit2 + i, sizeof lim);
    std::memcpy(&alive, on + i, sizeof alive);
    const Float4 dux =
        Float4{ux[b0], ux[b1], ux[b2], ux[b3]} - Float4{ux[a0], ux[a1], ux[a2], ux[a3]};
    const Float4 duz =
        Float4{uz[b0], uz[b1], uz[b2], uz[b3]} - Float4{uz[a0], uz[a1], uz[a2], uz[a3]};
    const Float4 dwx =
        Float4{wx[b0], wx[b1], wx[b2], wx[b3]} - Float4{wx[a0], wx[a1], wx[a2], wx[a3]};
    const Float4 dwz =
        Float4{wz[b0], wz[b1], wz[b2], wz[b3]} - Float4{wz[a0], wz[a1], wz[a2], wz[a3]};
    const Float4 dx = ox * vst + dux, dz = oz * vsz + duz;
    const Float4 l2 = dx * dx + dz * dz;
    const Int4 breaks = l2 > lim;
    const Float4 l = simd::Sqrt(simd::Select(l2 > tiny, l2, tiny));
    const Float4 inv = one / l;
    const Float4 nx = dx * inv, nz = dz * inv;
    const Float4 rel = (dwx + ox * vrt) * nx + (dwz + oz * vrz) * nz;
    const Float4 f = simd::Select(breaks, zero, alive) * (vk * (l - vl0) + vc * rel);
    const Float4 gx = f * nx, gz = f * nz;
    if (breaks[0] | breaks[1] | breaks[2] | breaks[3]) {
      for (int q = 0; q < 4; ++q)
        if (breaks[q]) record_break(i + q);
    }
    const int av[4] = {a0, a1, a2, a3}, bv[4] = {b0, b1, b2, b3};
    for (int q = 0; q < 4; ++q) {
      fx[av[q]] += gx[q];
      fz[av[q]] += gz[q];
      fx[bv[q]] -= gx[q];
      fz[bv[q]] -= gz[q];
    }
  }
  for (; i < end; ++i) {
    const int a = A[i], b = B[i];
    const float dx = OX[i] * st + (ux[b] - ux[a]);
    const float dz = OZ[i] * sz + (uz[b] - uz[a]);
    const float l2 = dx * dx + dz * dz;
    const bool breaks = l2 > limit2[i];
    const float l = std::sqrt(l2 > kTinyLength2 ? l2 : kTinyLength2);
    const float inv = 1.0f / l;
    const float nx = dx * inv, nz = dz * inv;
    const float rel = ((wx[b] - wx[a]) + OX[i] * rt) * nx + ((wz[b] - wz[a]) + OZ[i] * rz) * nz;
    const float f = (breaks ? 0.0f : on[i]) * (k * (l - l0) + c * rel);
    const float gx = f * nx, gz = f * nz;
    if (breaks) record_break(i);
    fx[a] += gx;
    fz[a] += gz;
    fx[b] -= gx;
    fz[b] -= gz;
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
  s.limit2.resize(L.a.size());
  s.on.assign(L.a.size(), 1.0f);
  s.broken.assign(L.a.size(), 0);

  TruncatedNormal normal(seed, stream);
  for (int i = 0; i < L.springs(); ++i) {
    const int f = static_cast<int>(L.family(i));
    double excess = (mech.kappa_mean[f] - 1.0) * (1.0 + mech.sigma * normal.Next());
    if (excess < 1e-4) excess = 1e-4;
    const double limit = (1.0 + excess) * rest[f];
    s.limit2[i] = static_cast<float>(limit * limit);
  }
  return s;
}

int Step(const Lattice& L, const Mechanics& mech, const Growth& g, Surface* s) {
  const float l0 = static_cast<float>(L.l_o);
  int broke = SpringPass(L, 0, L.axial_count, static_cast<float>(mech.k[0]),
                         static_cast<float>(mech.c[0]), l0, g, s);
  s->broken_count[0] += broke;
  const int diag = SpringPass(L, L.axial_count, L.springs(), static_cast<float>(mech.k[1]),
                              static_cast<float>(mech.c[1]), l0, g, s);
  s->broken_count[1] += diag;
  broke += diag;
  // Nodes: shear spring and dashpot to the anchor, then symplectic Euler.
  const float dt = static_cast<float>(mech.dt);
  const float inv_m = static_cast<float>(1.0 / mech.mass);
  const float ks = static_cast<float>(mech.k_s), cs = static_cast<float>(mech.c_s);
  float* ux = s->ux.data();
  float* uz = s->uz.data();
  float* wx = s->wx.data();
  float* wz = s->wz.data();
  float* fx = s->fx.data();
  float* fz = s->fz.data();
  const int n = L.nodes();
  for (int i = 0; i < n; ++i) {
    const float ax = (fx[i] - ks * ux[i] - cs * wx[i]) * inv_m;
    const float az = (fz[i] - ks * uz[i] - cs * wz[i]) * inv_m;
    wx[i] += dt * ax;
    wz[i] += dt * az;
    ux[i] += dt * wx[i];
    uz[i] += dt * wz[i];
    fx[i] = 0.0f;
    fz[i] = 0.0f;
  }
  return broke;
}

int SpringForces(const Lattice& L, const float k[2], const float c[2], const float rest[2],
                 const Growth& g, Surface* s) {
  const int axial = SpringPass(L, 0, L.axial_count, k[0], c[0], rest[0], g, s);
  s->broken_count[0] += axial;
  const int diag = SpringPass(L, L.axial_count, L.springs(), k[1], c[1], rest[1], g, s);
  s->broken_count[1] += diag;
  return axial + diag;
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
