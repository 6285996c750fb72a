// The canopy's shade (core/moss/canopy.h): the grid's interceptions against a pass over every
// sphere, one sphere's depth against the formula, and the photon pass under a crown against
// Beer–Lambert's transmission.
#include "moss/canopy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "moss/photons.h"
#include "random/pcg32.h"

namespace niwa::moss {
namespace {

TEST(MossCanopy, TheGridFindsWhatEverySphereFinds) {
  Pcg32 rng(3, 9);
  std::vector<CanopySphere> spheres;
  for (int i = 0; i < 600; ++i)
    spheres.push_back({{rng.Uniform(-5, 5), rng.Uniform(2, 6), rng.Uniform(-5, 5)},
                       rng.Uniform(0.05, 0.8),
                       rng.Uniform(0.5, 4)});
  CanopyShade shade;
  shade.Build(spheres);
  ASSERT_EQ(shade.size(), 600u);
  int hits = 0, misses = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::dvec3 o(rng.Uniform(-7, 7), rng.Uniform(-1, 8), rng.Uniform(-7, 7));
    glm::dvec3 d(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
    if (k % 10 == 0) d = glm::dvec3(0, -1, 0);  // axis-aligned paths too
    if (glm::length(d) < 1e-3) continue;
    d = glm::normalize(d);
    const double max_t = k % 3 == 0 ? std::numeric_limits<double>::infinity() : rng.Uniform(1, 12);
    const double depth = -std::log(1.0 - rng.Uniform());
    double t_grid = -1, t_all = -1;
    const bool grid = shade.Intercept(o, d, max_t, depth, &t_grid);
    const bool all = shade.InterceptLinear(o, d, max_t, depth, &t_all);
    ASSERT_EQ(grid, all) << k;
    if (grid) {
      ASSERT_EQ(t_grid, t_all) << k;  // the same chords swept in the same order: the same bits
      ASSERT_GT(t_grid, 0.0);
      ASSERT_LE(t_grid, max_t);
      ++hits;
    } else {
      ++misses;
    }
  }
  EXPECT_GT(hits, 300);  // both answers are exercised
  EXPECT_GT(misses, 300);
}

TEST(MossCanopy, OneSpheresDepthIsSigmaTimesTheChord) {
  CanopyShade shade;
  shade.Build({{{0, 0, 0}, 1.0, 2.0}, {{5, 0, 0}, 0.0, 2.0}, {{7, 0, 0}, 1.0, 0.0}});
  EXPECT_EQ(shade.size(), 1u);  // empty spheres left out
  const glm::dvec3 o(0, 0, -3), d(0, 0, 1);
  EXPECT_NEAR(shade.OpticalDepth(o, d, 100), 4.0, 1e-12);  // σ·2r
  EXPECT_NEAR(shade.OpticalDepth(o, d, 3.0), 2.0, 1e-12);  // up to the centre
  double t = 0;
  ASSERT_TRUE(shade.Intercept(o, d, 100, 1.0, &t));
  EXPECT_NEAR(t, 2.5, 1e-12);                         // enters at 2, depth 1 after 1/σ
  EXPECT_FALSE(shade.Intercept(o, d, 100, 4.5, &t));  // deeper than the whole sphere
  EXPECT_FALSE(shade.Intercept(o, d, 2.2, 1.0, &t));  // stopped before
  // Two overlapping spheres add their extinction where they overlap.
  CanopyShade two;
  two.Build({{{0, 0, 0}, 1.0, 1.0}, {{0, 0, 0.5}, 1.0, 1.0}});
  EXPECT_NEAR(two.OpticalDepth(o, d, 100), 4.0, 1e-12);
  ASSERT_TRUE(two.Intercept(o, d, 100, 1.5, &t));
  // Depth 0.5 over [2, 2.5) at σ 1, then σ 2 from 2.5: the remaining 1 in 0.5.
  EXPECT_NEAR(t, 3.0, 1e-12);
}

// A crown (one sphere, radius 0.5 m, σ 2 /m, centre 1 m up) over the plane scene under a sun at
// the zenith, first hits only: the photons reaching the ground under its middle are the open
// ground's times Beer–Lambert's mean transmission over that disc.
TEST(MossCanopy, PhotonsUnderACrownFollowBeerLambert) {
  MossParams params = *MossPreset("nomura2010");
  ASSERT_TRUE(params.Set(MossParam::kIndirect, 0).ok());
  ASSERT_TRUE(params.Set(MossParam::kSunAltitude, 90).ok());
  const SoilCells cells = *MakeSoilCells(*BuildScene("plane"), SoilCellOptions{});
  PhotonLight light = *PhotonLightOf(params, cells);
  const double r = 0.5, sigma = 2.0, rho = 0.25;
  auto canopy = std::make_shared<CanopyShade>();
  canopy->Build({{{0, 1, 0}, r, sigma}});
  light.canopy = canopy;
  MossOccluders none;
  PhotonMap map;
  Pcg32 rng(5, 2);
  double under = 0, open = 0;
  for (int day = 0; day < 20; ++day) {
    TracePhotons(cells, none, light, 20000, &rng, &map);
    for (const Photon& p : map.photons) {
      const double d2 = p.position.x * p.position.x + p.position.z * p.position.z;
      if (d2 < rho * rho) under += 1;
      if (d2 > 0.7 * 0.7 && std::abs(p.position.x) < 0.95 && std::abs(p.position.z) < 0.95)
        open += 1;
    }
    EXPECT_GT(map.canopy_intercepted, 0);
    EXPECT_EQ(map.canopy_absorbed, map.canopy_intercepted);  // first hits only: none scattered
  }
  // The open band's area: the square |x|, |z| < 0.95 less the disc of 0.7.
  const double pi = 3.14159265358979323846;
  const double open_area = 1.9 * 1.9 - pi * 0.49;
  const double density_open = open / open_area, density_under = under / (pi * rho * rho);
  // Mean of exp(−σ·2√(r² − q²)) over the disc q < rho (area-weighted).
  double mean = 0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    const double q = (k + 0.5) / n * rho;
    mean += std::exp(-sigma * 2 * std::sqrt(r * r - q * q)) * 2 * q * (rho / n) / (rho * rho);
  }
  EXPECT_NEAR(density_under / density_open, mean, 0.08 * mean);
  EXPECT_LT(density_under / density_open, 0.5);  // the shade is there (mean ≈ 0.17)
}

}  // namespace
}  // namespace niwa::moss
