// P-type Fourier descriptors and phase randomisation (§4.2; see fourier.h).
#include "terrain/fourier.h"

#include <cmath>
#include <kissfft/kissfft.hh>

#include "math/det_math.h"

namespace niwa::terrain {

Ring ResampleEqual(const Ring& ring, int n) {
  const std::size_t m = ring.size();
  std::vector<double> cum(m + 1, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % m];
    cum[i + 1] = cum[i] + std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
  }
  const double total = cum[m];
  Ring out;
  out.reserve(static_cast<std::size_t>(n));
  std::size_t seg = 0;
  for (int j = 0; j < n; ++j) {
    const double s = total * j / n;
    while (seg + 1 < m && cum[seg + 1] <= s) ++seg;
    const double len = cum[seg + 1] - cum[seg];
    const double t = len > 0 ? (s - cum[seg]) / len : 0.0;
    const Vec2& a = ring[seg];
    const Vec2& b = ring[(seg + 1) % m];
    out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
  }
  return out;
}

std::vector<std::complex<double>> PTypeDescriptor(const Ring& z, double* h) {
  const std::size_t n = z.size();
  double per = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2& a = z[j];
    const Vec2& b = z[(j + 1) % n];
    per += std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
  }
  *h = per / static_cast<double>(n);
  std::vector<std::complex<double>> w(n), c(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2& a = z[j];
    const Vec2& b = z[(j + 1) % n];
    w[j] = {(b.x - a.x) / *h, (b.y - a.y) / *h};
  }
  kissfft<double> fft(n, false);
  fft.transform(w.data(), c.data());
  for (auto& v : c) v /= static_cast<double>(n);
  return c;
}

Ring CurveFromDescriptor(const std::vector<std::complex<double>>& c, double h, const Vec2& z0) {
  const std::size_t n = c.size();
  std::vector<std::complex<double>> w(n);
  kissfft<double> ifft(n, true);
  ifft.transform(c.data(), w.data());  // Σ c(k)·e^{+2πijk/n}
  Ring out;
  out.reserve(n);
  std::complex<double> z{z0.x, z0.y};
  for (std::size_t m = 0; m < n; ++m) {
    out.push_back({z.real(), z.imag()});
    z += h * w[m];
  }
  return out;
}

void RandomisePhases(std::vector<std::complex<double>>* c, int f0, double amp, Pcg32* rng) {
  const int n = static_cast<int>(c->size());
  for (int idx = 0; idx < n; ++idx) {
    const int k = idx < n / 2 ? idx : idx - n;  // k in [−n/2, n/2 − 1]
    if (std::abs(k) < f0) continue;
    std::complex<double>& v = (*c)[static_cast<std::size_t>(idx)];
    const double mag =
        std::sqrt(v.real() * v.real() + v.imag() * v.imag());  // not hypot: libc-free
    const double phase = det::Atan2(v.imag(), v.real()) + rng->Uniform(-amp, amp);
    double s, co;
    det::SinCos(phase, &s, &co);
    v = {mag * co, mag * s};
  }
}

Ring FourierPerturb(const Ring& ring, int n, int f0, double amp, Pcg32* rng) {
  const Ring z = ResampleEqual(ring, n);
  double h = 0;
  std::vector<std::complex<double>> c = PTypeDescriptor(z, &h);
  RandomisePhases(&c, f0, amp, rng);
  return CurveFromDescriptor(c, h, z[0]);
}

}  // namespace niwa::terrain
