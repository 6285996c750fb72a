// Tests of the leaf-sphere light model: unshaded and shaded cases, and the grid against the
// reference.
#include "tree/light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <utility>

#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

Sky DefaultSky() { return MakeSky(60.0f, 0.0f, 0.3f); }

TEST(Sky, WeightsSumToOneAndDirectionsPointUp) {
  Sky sky = MakeSky(45.0f, 30.0f, 0.25f);
  float total = 0.0f;
  for (std::size_t k = 0; k < sky.directions.size(); ++k) {
    total += sky.weights[k];
    EXPECT_GT(sky.directions[k].y, 0.0f);
    EXPECT_NEAR(glm::length(sky.directions[k]), 1.0f, 1e-5f);
  }
  EXPECT_NEAR(total, 1.0f, 1e-5f);
  EXPECT_NEAR(sky.weights.back(), 0.25f, 1e-6f);
  EXPECT_NEAR(sky.directions.back().y, std::sin(45.0f * 3.14159265f / 180.0f), 1e-5f);
}

TEST(Light, LoneSphereGetsFullLightTowardsTheBrightSky) {
  std::vector<LeafSphere> one = {{glm::vec3(0, 10, 0), 2.0f}};
  Sky sky = DefaultSky();
  auto exact = ComputeLightReference(one, sky, 0.5f);
  EXPECT_NEAR(exact[0].light, 1.0f, 1e-4f);
  // The grid removes the shoot's own sphere approximately (its rasterized share, not the chord).
  auto grid = ComputeLightGrid(one, sky, 0.5f);
  EXPECT_NEAR(grid[0].light, 1.0f, 1e-2f);
  // Strongest light of an unshaded shoot: the sun (weight 0.3 against ~0.044 per sky patch).
  for (const auto& samples : {exact, grid}) {
    EXPECT_NEAR(glm::dot(samples[0].direction, sky.directions.back()), 1.0f, 1e-6f);
  }
  // Without a sun, the zenith (first sky direction) wins the tie of open directions.
  auto overcast = ComputeLightReference(one, MakeSky(60.0f, 0.0f, 0.0f), 0.5f);
  EXPECT_NEAR(overcast[0].direction.y, 1.0f, 1e-6f);
}

TEST(Light, SphereBelowAnotherIsShadedAndLeansAway) {
  // Reference by hand for the zenith ray: the lower centre sees one full diameter of the upper
  // sphere.
  std::vector<LeafSphere> pair = {{glm::vec3(0, 0, 0), 1.0f}, {glm::vec3(0, 3, 0), 1.0f}};
  Sky zenith;
  zenith.directions = {glm::vec3(0, 1, 0)};
  zenith.weights = {1.0f};
  auto exact = ComputeLightReference(pair, zenith, 0.5f);
  EXPECT_NEAR(exact[0].light, 0.5f, 1e-5f);  // (1 - opacity) after one diameter
  EXPECT_NEAR(exact[1].light, 1.0f, 1e-6f);
  auto sky = ComputeLightReference(pair, DefaultSky(), 0.5f);
  EXPECT_LT(sky[0].light, sky[1].light);
  auto grid = ComputeLightGrid(pair, DefaultSky(), 0.5f);
  EXPECT_LT(grid[0].light, grid[1].light);
}

// The growth loop reuses one LightGridBuffers from year to year: what an earlier grid left in it
// must not leak into the next call. A grid one cell thick is the case to watch: its lookups reach
// the border cells beyond it, where a thicker grid before it had depths.
TEST(Light, ReusedBuffersGiveTheSameLightAsFreshOnes) {
  // A pole 200 cm tall of dense spheres (r 1.5 cm) on the y axis with small ones on its +x side,
  // one cell (3.6 cm) thick in x and z; `thick` adds a copy 3 cm further along x: two cells thick,
  // the same cells in y and z.
  std::vector<LeafSphere> pole;
  for (int i = 0; i <= 200; ++i) {
    pole.push_back({glm::vec3(0.0f, static_cast<float>(i), 0.0f), 1.5f});
    pole.push_back({glm::vec3(1.5f, static_cast<float>(i) + 0.5f, 0.0f), 0.05f});
  }
  std::vector<LeafSphere> thick = pole;
  for (const LeafSphere& s : pole) thick.push_back({s.center + glm::vec3(3.0f, 0, 0), s.radius});
  for (float x : {-1.0f, 1.0f}) {  // one low sun alone, from -x (the bad case) and from +x
    Sky sky;
    sky.directions = {glm::normalize(glm::vec3(x, 0.2f, 0.0f))};
    sky.weights = {1.0f};
    LightGridBuffers reused;
    ComputeLightGrid(thick, sky, 0.5f, reused);
    const auto again = ComputeLightGrid(pole, sky, 0.5f, reused);
    const auto fresh = ComputeLightGrid(pole, sky, 0.5f);
    ASSERT_EQ(again.size(), fresh.size());
    for (std::size_t i = 0; i < fresh.size(); ++i) {
      ASSERT_EQ(again[i].light, fresh[i].light) << "sun x " << x << ", sphere " << i;
    }
  }
}

double Pearson(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= static_cast<double>(a.size());
  mb /= static_cast<double>(b.size());
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST(Light, GridAgreesWithReferenceOnEveryPresetAt8Years) {
  for (const Preset& preset : Presets()) {
    GrowRequest r;
    r.preset = preset.name;
    r.params = preset.params;
    r.years = 8;
    Tree tree = GrowTree(r);
    std::vector<LeafSphere> spheres;
    float leaf = static_cast<float>(preset.params.Get(ParamId::kLeafSize));
    for (const Branch& b : tree.branches) {  // the same spheres the growth model uses
      if (!b.alive || b.year != tree.years) continue;
      spheres.push_back({0.5f * (b.nodes.front() + b.nodes.back()),
                         0.5f * glm::length(b.nodes.back() - b.nodes.front()) + 0.5f * leaf});
    }
    if (spheres.size() < 10) continue;  // too few shoots to correlate
    // Twice: under the light the preset grows in (its own sky, sun and leaf-sphere opacity), and
    // under a strong sun (weight 0.3) with denser spheres (opacity 0.5).
    const Sky own_sky = GrowthSky(preset.params);
    const float own_opacity = static_cast<float>(preset.params.Get(ParamId::kSphereOpacity));
    const std::pair<Sky, float> settings[] = {{own_sky, own_opacity}, {DefaultSky(), 0.5f}};
    for (const auto& [sky, opacity] : settings) {
      auto exact = ComputeLightReference(spheres, sky, opacity);
      auto fast = ComputeLightGrid(spheres, sky, opacity);
      std::vector<double> a, b;
      for (std::size_t i = 0; i < spheres.size(); ++i) {
        a.push_back(exact[i].light);
        b.push_back(fast[i].light);
      }
      double r_value = Pearson(a, b);
      EXPECT_GE(r_value, 0.95) << preset.name << " with " << spheres.size() << " spheres, opacity "
                               << opacity;
    }
  }
}

}  // namespace
}  // namespace niwa
