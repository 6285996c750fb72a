// The photon pass and gather (core/moss/photons.h): eq 3.1's sampler, the emission against its
// literal rejection form, the light's power, the open plane's direct irradiance, indirect off,
// bounces on the thesis scene, the soil's spread (per photon and by counts), and the mosses' grid
// as occluders.
#include "moss/photons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <string>

#include "moss/sampling.h"

namespace niwa::moss {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Lit {
  SoilCells cells;
  PhotonLight light;
};
Lit LitScene(const std::string& scene, MossParams params) {
  Lit lit{*MakeSoilCells(*BuildScene(scene), SoilCellOptions{}), {}};
  lit.light = *PhotonLightOf(params, lit.cells);
  return lit;
}
MossParams Params() { return *MossPreset("nomura2010"); }

TEST(MossPhotons, Eq31MeanCosineIsTwoThirds) {
  Pcg32 rng(11, 3);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
  double sum = 0;
  const int count = 200000;
  for (int i = 0; i < count; ++i) {
    const double c = glm::dot(CosineDirection(n, &rng), n);
    ASSERT_GE(c, 0.0);
    sum += c;
  }
  // E[cos θ] under p(θ) ∝ cos θ sin θ is 2/3; σ of the mean ≈ 0.24/√200000 = 5e-4.
  EXPECT_NEAR(sum / count, 2.0 / 3.0, 0.01);
}

TEST(MossPhotons, ConeEmissionIsEq31ConditionedOnTheSphere) {
  const Lit lit = LitScene("plane", Params());
  const PhotonLight& L = lit.light;
  // Where the rays cross the horizontal plane through C, in 4 bands of r²/R² (and the mean cosine
  // to the light's normal), from both samplers.
  auto histogram = [&](bool cone, double* mean_cos) {
    Pcg32 rng(cone ? 5 : 6, 1);
    std::vector<double> bins(4, 0.0);
    const int count = 40000;
    *mean_cos = 0;
    for (int i = 0; i < count; ++i) {
      glm::dvec3 o, d;
      if (cone)
        EmitSunPhoton(L, &rng, &o, &d);
      else
        EmitSunPhotonByRejection(L, &rng, &o, &d);
      *mean_cos += glm::dot(d, -L.sun) / count;
      // Every ray meets the sphere.
      const glm::dvec3 m = L.centre - o;
      const double t = glm::dot(m, d);
      EXPECT_LE(glm::dot(m, m) - t * t, L.R * L.R * (1 + 1e-12));
      const double s = (L.centre.y - o.y) / d.y;
      const glm::dvec3 p = o + s * d - L.centre;
      const double q = (p.x * p.x + p.z * p.z) / (L.R * L.R);
      bins[std::min(3, static_cast<int>(q * 4 / 1.05))] += 1.0;
    }
    return bins;
  };
  double cos_cone, cos_reject;
  const std::vector<double> cone = histogram(true, &cos_cone);
  const std::vector<double> reject = histogram(false, &cos_reject);
  for (int b = 0; b < 4; ++b) {
    const double sigma = std::sqrt(cone[b] + reject[b]);
    EXPECT_LT(std::abs(cone[b] - reject[b]), 5 * sigma) << b;
  }
  EXPECT_NEAR(cos_cone, cos_reject, 2e-4);
}

TEST(MossPhotons, EmittedPowerIsTheLightsPower) {
  MossParams params = Params();
  Lit lit = LitScene("plane", params);
  MossOccluders none;
  PhotonMap map;
  Pcg32 rng(1, 1);
  TracePhotons(lit.cells, none, lit.light, 8192, &rng, &map);
  const double piR2 = kPi * lit.light.R * lit.light.R;
  EXPECT_DOUBLE_EQ(lit.light.S_sun, 250.0);  // I_beam·N/24 = 1000·6/24
  EXPECT_EQ(map.emitted_sun, 8192);
  EXPECT_EQ(map.emitted_sky, 0);
  EXPECT_NEAR(map.power_emitted, 250.0 * piR2, 1e-9 * 250.0 * piR2);
  // With the sky: f_sky = 2·68/(250 + 2·68) of the budget, each photon the same power (±1/N).
  ASSERT_TRUE(params.Set(MossParam::kSSky, 68).ok());
  lit.light = *PhotonLightOf(params, lit.cells);
  TracePhotons(lit.cells, none, lit.light, 8192, &rng, &map);
  EXPECT_EQ(map.emitted_sky, std::lround(8192 * 136.0 / 386.0));
  EXPECT_NEAR(map.dPhi_sky / map.dPhi_sun, 1.0, 1.0 / 1000);
  EXPECT_NEAR(map.power_emitted, (250.0 + 2 * 68.0) * piR2, 1e-9 * 386.0 * piR2);
}

// Fig 3.3-3.5's energy check: on the open plane under a zenith sun, with first hits only, the
// gathered irradiance of 50 central cells over 10 days is S_sun within 5 % (the light's cosine
// falloff over the sphere, 10 R away, is about 2 % at its rim).
TEST(MossPhotons, OpenPlaneGathersTheDirectIrradiance) {
  MossParams params = Params();
  ASSERT_TRUE(params.Set(MossParam::kIndirect, 0).ok());
  const Lit lit = LitScene("plane", params);
  std::vector<std::size_t> central;
  for (std::size_t i = 0; i < lit.cells.size() && central.size() < 50; i += 23)
    if (std::abs(lit.cells.centroid[i].x) < 0.6 && std::abs(lit.cells.centroid[i].z) < 0.6)
      central.push_back(i);
  ASSERT_EQ(central.size(), 50u);
  MossOccluders none;
  PhotonMap map;
  Pcg32 rng(2, 7);
  double sum = 0;
  for (int day = 0; day < 10; ++day) {
    TracePhotons(lit.cells, none, lit.light, 8192, &rng, &map);
    for (const Photon& p : map.photons) ASSERT_EQ(p.depth, 0);
    Result<PhotonGather> built = PhotonGather::Build(map, lit.light.r_gather);
    const PhotonGather& gather = *built;
    for (std::size_t i : central) sum += gather.Soil(lit.cells.centroid[i], lit.cells.normal[i]);
  }
  const double ratio = sum / (500 * lit.light.S_sun);
  EXPECT_NEAR(ratio, 1.0, 0.05);
}

TEST(MossPhotons, OnThePlaneEveryBounceEscapes) {
  const Lit lit = LitScene("plane", Params());
  MossOccluders none;
  PhotonMap map;
  Pcg32 rng(3, 1);
  TracePhotons(lit.cells, none, lit.light, 20000, &rng, &map);
  EXPECT_GT(map.stored_by_depth[0], 10000);  // 4 m² of the 2π m² cross-section: about 64 %
  for (std::size_t d = 1; d < map.stored_by_depth.size(); ++d) EXPECT_EQ(map.stored_by_depth[d], 0);
  // Every path ends once: at a miss, or absorbed (roulette), or reflected and then missing.
  EXPECT_EQ(map.escaped + map.absorbed, 20000);
}

TEST(MossPhotons, IndirectOffStoresOnlyFirstHitsAndNoSky) {
  MossParams params = *MossPreset("nomura2010-sky");
  ASSERT_TRUE(params.Set(MossParam::kIndirect, 0).ok());
  const Lit off = LitScene("thesis", params);
  ASSERT_TRUE(params.Set(MossParam::kIndirect, 1).ok());
  const Lit on = LitScene("thesis", params);
  MossOccluders none;
  PhotonMap map_off, map_on;
  Pcg32 rng_off(4, 1), rng_on(4, 1);
  TracePhotons(off.cells, none, off.light, 8192, &rng_off, &map_off);
  TracePhotons(on.cells, none, on.light, 8192, &rng_on, &map_on);
  EXPECT_EQ(map_off.emitted_sky, 0);
  EXPECT_GT(map_on.emitted_sky, 0);
  for (const Photon& p : map_off.photons) ASSERT_EQ(p.depth, 0);
  // A zenith sun reaches no downward face: the roof's underside gets only bounced photons.
  const uint8_t roof_under = 2;
  ASSERT_EQ(on.cells.region_names[roof_under], "roof_under");
  int under_off = 0, under_on = 0;
  for (const Photon& p : map_off.photons) under_off += on.cells.region[p.target] == roof_under;
  for (const Photon& p : map_on.photons)
    if (on.cells.region[p.target] == roof_under) {
      ++under_on;
      EXPECT_GE(p.depth, 1);
    }
  EXPECT_EQ(under_off, 0);
  EXPECT_GT(under_on, 0);
  // Each depth holds at most ρ_mesh of the power of the one before (some bounces escape).
  for (std::size_t d = 1; d < 4; ++d)
    EXPECT_LT(map_on.power_by_depth[d], 0.5 * map_on.power_by_depth[d - 1] * 1.1) << d;
  EXPECT_GT(map_on.stored_by_depth[1], 0);
}

// The spread onto the cells (SoilPhotonSpread) is the grid's radius query from every photon, bit
// for bit: the cells' lists on the thesis and walls scenes with bounces and the sky, and on made-up
// photons at random points of random cells on either side, the grid alone for a photon moved off
// its cell (the fallback), and the sum divided by πr² is PhotonGather::Soil at each centroid to
// rounding (its sum runs in the grid's order).
TEST(MossPhotons, TheSpreadIsTheGridsRadiusQueryBitForBit) {
  for (const char* scene : {"thesis", "walls"}) {
    const Lit lit = LitScene(scene, *MossPreset("nomura2010-sky"));
    MossOccluders none;
    PhotonMap map;
    Pcg32 rng(5, 9);
    TracePhotons(lit.cells, none, lit.light, 8192, &rng, &map);
    ASSERT_GT(map.stored_by_depth[1], 0) << scene;
    // Photons on either side of random cells at random points of them (the back's lists too).
    for (int i = 0; i < 4000; ++i) {
      Photon p;
      p.target = rng.NextU32() % static_cast<uint32_t>(lit.cells.size());
      const double r1 = std::sqrt(rng.Uniform()), r2 = rng.Uniform();
      const glm::dvec3 a(lit.cells.mesh.positions[3 * p.target]),
          b(lit.cells.mesh.positions[3 * p.target + 1]),
          c(lit.cells.mesh.positions[3 * p.target + 2]);
      p.position = glm::dvec3(glm::vec3((1 - r1) * a + (r1 * (1 - r2)) * b + (r1 * r2) * c));
      p.normal = i % 2 ? lit.cells.normal[p.target] : -lit.cells.normal[p.target];
      p.power = 1.0 + i;
      p.depth = 1;
      p.on_moss = false;
      map.photons.push_back(p);
    }
    // A photon far off its own cell: the lists cannot serve it.
    std::size_t moved = 0;
    while (map.photons[moved].on_moss) ++moved;
    map.photons[moved].position += glm::dvec3(0.3, 0.0, 0.2);
    const SoilPhotonSpread spread(lit.cells, lit.light.r_gather);
    EXPECT_TRUE(spread.listed()) << scene;
    std::vector<double> S(lit.cells.size(), 0.0), grid(lit.cells.size(), 0.0);
    spread.Spread(lit.cells, map, &S);
    const geom::RadiusGrid centroids(lit.cells.centroid, lit.light.r_gather);
    int front = 0, back = 0;
    for (const Photon& ph : map.photons) {
      if (ph.on_moss) continue;
      (ph.normal == lit.cells.normal[ph.target] ? front : back)++;
      centroids.ForEachWithin(ph.position, [&](uint32_t c, double) {
        if (glm::dot(ph.normal, lit.cells.normal[c]) > 0.5) grid[c] += ph.power;
      });
    }
    EXPECT_GT(front, 0);
    EXPECT_GT(back, 1000) << scene;
    int lit_cells = 0;
    for (std::size_t c = 0; c < S.size(); ++c) {
      ASSERT_EQ(S[c], grid[c]) << scene << " cell " << c;
      lit_cells += S[c] > 0;
    }
    EXPECT_GT(lit_cells, 1000) << scene;
    const Result<PhotonGather> gather = PhotonGather::Build(map, lit.light.r_gather);
    const double area = kPi * lit.light.r_gather * lit.light.r_gather;
    for (std::size_t c = 0; c < S.size(); c += 7)
      ASSERT_NEAR(S[c] / area, gather->Soil(lit.cells.centroid[c], lit.cells.normal[c]),
                  1e-9 * (1 + S[c] / area))
          << scene << " cell " << c;
  }
}

// A day's own map, whose land photons carry one power (nomura2010: the sun's) or two in two runs
// (nomura2010-sky: the sun's, then the sky's), is spread by counting: the same bits as one
// addition a photon (the grid's query from every photon), from zero and from sums already there.
TEST(MossPhotons, TheSpreadsCountsAreTheAdditionsBitForBit) {
  for (const char* preset : {"nomura2010", "nomura2010-sky"})
    for (const char* scene : {"thesis", "walls"}) {
      const Lit lit = LitScene(scene, *MossPreset(preset));
      MossOccluders none;
      PhotonMap map;
      Pcg32 rng(3, 4);
      TracePhotons(lit.cells, none, lit.light, 8192, &rng, &map);
      const bool sky = std::string(preset) == "nomura2010-sky";
      EXPECT_EQ(map.emitted_sky > 0, sky);
      ASSERT_GT(map.stored_by_depth[1], 0) << scene;
      const SoilPhotonSpread spread(lit.cells, lit.light.r_gather);
      const geom::RadiusGrid centroids(lit.cells.centroid, lit.light.r_gather);
      for (double start : {0.0, 3.25}) {
        std::vector<double> S(lit.cells.size(), 0.0), grid(lit.cells.size(), 0.0);
        for (std::size_t c = 0; c < S.size(); c += 3) S[c] = grid[c] = start;
        spread.Spread(lit.cells, map, &S);
        for (const Photon& ph : map.photons) {
          if (ph.on_moss) continue;
          centroids.ForEachWithin(ph.position, [&](uint32_t c, double) {
            if (glm::dot(ph.normal, lit.cells.normal[c]) > 0.5) grid[c] += ph.power;
          });
        }
        int lit_cells = 0;
        for (std::size_t c = 0; c < S.size(); ++c) {
          ASSERT_EQ(std::memcmp(&S[c], &grid[c], sizeof(double)), 0)
              << preset << " " << scene << " cell " << c << " start " << start;
          lit_cells += S[c] > start;
        }
        EXPECT_GT(lit_cells, 1000) << preset << " " << scene;
      }
    }
}

TEST(MossPhotons, TheMossGridFindsWhatEverySphereTestFinds) {
  Pcg32 rng(9, 2);
  std::vector<glm::dvec3> centres;
  for (int i = 0; i < 600; ++i)
    centres.push_back({rng.Uniform(-0.15, 0.15), rng.Uniform(0, 0.1), rng.Uniform(-0.15, 0.15)});
  MossOccluders grid;
  grid.Build(centres, 0.005);
  int hits = 0;
  for (int r = 0; r < 5000; ++r) {
    const glm::dvec3 o(rng.Uniform(-0.3, 0.3), rng.Uniform(-0.1, 0.3), rng.Uniform(-0.3, 0.3));
    glm::dvec3 d(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1));
    if (r % 5 == 0) d = glm::dvec3(0, -1, 0);  // straight down, the axis-aligned case
    d = glm::normalize(d);
    const double max_t = r % 3 == 0 ? 0.2 : 10.0;
    double t1 = -1, t2 = -1;
    uint32_t i1 = 0, i2 = 0;
    const bool a = grid.FirstHit(o, d, max_t, &t1, &i1);
    const bool b = grid.FirstHitLinear(o, d, max_t, &t2, &i2);
    ASSERT_EQ(a, b) << r;
    if (a) {
      ++hits;
      ASSERT_EQ(i1, i2) << r;
      ASSERT_EQ(t1, t2) << r;
    }
  }
  EXPECT_GT(hits, 200);
}

// A 16 × 16 patch of 1 cm mosses touching the plane at 1 cm spacing covers π/4 of the patch seen
// from above: under a zenith sun (first hits only) about 21 % of the patch's photons reach the
// soil, the rest are stored on the mosses; the soil gather counts land hits only.
TEST(MossPhotons, MossesShadeTheSoilBeneathThem) {
  MossParams params = Params();
  ASSERT_TRUE(params.Set(MossParam::kIndirect, 0).ok());
  const Lit lit = LitScene("plane", params);
  std::vector<glm::dvec3> centres;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) centres.push_back({-0.075 + 0.01 * i, 0.005, -0.075 + 0.01 * j});
  MossOccluders mosses;
  mosses.Build(centres, 0.005);
  PhotonMap map;
  Pcg32 rng(5, 5);
  TracePhotons(lit.cells, mosses, lit.light, 400000, &rng, &map);
  int soil = 0, moss = 0;
  for (const Photon& p : map.photons) {
    if (p.on_moss) {
      ++moss;
      EXPECT_NEAR(glm::length(p.position - centres[p.target]), 0.005, 1e-9);  // 14 m of travel
    } else if (std::abs(p.position.x) < 0.08 && std::abs(p.position.z) < 0.08) {
      ++soil;
    }
  }
  ASSERT_GT(moss + soil, 1000);
  EXPECT_NEAR(static_cast<double>(soil) / (soil + moss), 1.0 - kPi / 4, 0.03);
  Result<PhotonGather> built = PhotonGather::Build(map, 0.05);
  const PhotonGather& gather = *built;
  const glm::dvec3 up(0, 1, 0);
  EXPECT_LT(gather.Soil({0, 0, 0}, up), 0.5 * gather.Moss({0, 0.01, 0}, up));
}

TEST(MossPhotons, RefusedLights) {
  MossParams params = Params();
  const SoilCells cells = *MakeSoilCells(*BuildScene("plane"), SoilCellOptions{});
  ASSERT_TRUE(params.Set(MossParam::kSunPath, 1).ok());
  EXPECT_EQ(PhotonLightOf(params, cells).status().field(), "sun_path");
}

}  // namespace
}  // namespace niwa::moss
