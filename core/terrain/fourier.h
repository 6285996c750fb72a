// P-type Fourier descriptors (Uesaka 1984) and the §4.2 phase randomisation: a closed curve is
// resampled to n equal steps h, w(j) = (z(j+1) − z(j))/h, c(k) = (1/n)·Σ w(j)·e^{−2πijk/n}; the
// phases of |k| ≥ f0 are shaken, magnitudes and c(k) for |k| < f0 kept, so the curve still closes
// (z'(n) − z(0) = h·n·c(0)). FFT by kissfft (header-only kissfft.hh). Does not: remove the loops
// that randomisation can make (loops.h).
#pragma once

#include <complex>
#include <vector>

#include "random/pcg32.h"
#include "terrain/contour.h"

namespace niwa::terrain {

// The closed curve resampled at n points equally spaced in arc length from vertex 0.
Ring ResampleEqual(const Ring& ring, int n);
// c(k) stored at index k mod n (k in [−n/2, n/2 − 1]) of the P-type descriptor of an
// equal-step ring (as ResampleEqual makes), and h.
std::vector<std::complex<double>> PTypeDescriptor(const Ring& equal_ring, double* h);
// The curve of descriptor c with step h starting at z0: z'(m) = z0 + h·Σ_{j<m} w'(j), m < n.
Ring CurveFromDescriptor(const std::vector<std::complex<double>>& c, double h, const Vec2& z0);
// Phases of every |k| ≥ f0 set to arg c(k) + U(−amp, amp) (uniform from the project RNG).
void RandomisePhases(std::vector<std::complex<double>>* c, int f0, double amp, Pcg32* rng);
// The whole §4.2 step: resample to n, randomise, rebuild.
Ring FourierPerturb(const Ring& ring, int n, int f0, double amp, Pcg32* rng);

}  // namespace niwa::terrain
