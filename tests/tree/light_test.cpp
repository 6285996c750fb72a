// Tests of the leaf-sphere light model: unshaded and shaded cases, and the grid against the
// reference.
#include "tree/light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

// Foreign spheres (another tree's leaves, compose/tree_neighbours) shade and are not lit.
TEST(Light, ForeignSpheresShadeButReceiveNoLight) {
  std::vector<LeafSphere> own = {{glm::vec3(0, 0, 0), 1.0f}};
  std::vector<LeafSphere> above = {{glm::vec3(0, 3, 0), 1.0f}};
  Sky zenith;
  zenith.directions = {glm::vec3(0, 1, 0)};
  zenith.weights = {1.0f};
  auto exact = ComputeLightReference(own, above, zenith, 0.5f);
  ASSERT_EQ(exact.size(), 1u);
  EXPECT_NEAR(exact[0].light, 0.5f, 1e-5f);  // one diameter of the foreign sphere, as an own one
  LightGridBuffers buffers;
  auto alone = ComputeLightGrid(own, zenith, 0.5f, buffers);
  auto shaded = ComputeLightGrid(own, above, zenith, 0.5f, buffers);
  ASSERT_EQ(shaded.size(), 1u);
  // The grid takes the own sphere off approximately (LoneSphereGetsFullLight...).
  EXPECT_NEAR(alone[0].light, 1.0f, 0.03f);
  EXPECT_NEAR(shaded[0].light, 0.5f, 0.1f);
  // The same sphere as an own one: the lower sphere's light is about the same.
  std::vector<LeafSphere> both = {own[0], above[0]};
  auto as_own = ComputeLightGrid(both, zenith, 0.5f);
  EXPECT_NEAR(shaded[0].light, as_own[0].light, 0.05f);
}

// Foreign spheres below every own one add an optical depth of exactly zero (every sky direction
// points up): the same bits as with none, through the second grid.
TEST(Light, ForeignSpheresBelowChangeNoBit) {
  GrowRequest r;
  r.preset = "sakura";
  r.params = FindPreset("sakura")->params;
  r.years = 6;
  Grower grower(r);
  while (grower.year() < 6) grower.GrowYear();
  const std::vector<LeafSphere>& spheres = grower.leaf_spheres();
  ASSERT_GT(spheres.size(), 100u);
  std::vector<LeafSphere> below;
  for (const LeafSphere& s : spheres)
    below.push_back({s.center + glm::vec3(40, -900, 70), s.radius});
  const Sky sky = GrowthSky(r.params);
  LightGridBuffers buffers;
  const auto alone = ComputeLightGrid(spheres, sky, 0.3f, buffers);
  const auto with = ComputeLightGrid(spheres, below, sky, 0.3f, buffers);
  ASSERT_EQ(alone.size(), with.size());
  for (std::size_t i = 0; i < alone.size(); ++i) {
    ASSERT_EQ(alone[i].light, with[i].light) << i;
    ASSERT_EQ(alone[i].direction, with[i].direction) << i;
  }
}

// A neighbour's crown 2.5 m to the side (the same sakura, 8 years): the grid's light with it as
// foreign shade follows the pairwise reference's, and so does the light it takes away; better than
// one grid over both crowns' spheres (as if one tree), whose cells the wider box coarsens.
TEST(Light, ForeignGridAgreesWithReferenceForANeighbour) {
  GrowRequest r;
  r.preset = "sakura";
  r.params = FindPreset("sakura")->params;
  r.years = 8;
  Grower grower(r);
  while (grower.year() < r.years) grower.GrowYear();
  const std::vector<LeafSphere>& spheres = grower.leaf_spheres();
  ASSERT_GT(spheres.size(), 500u);
  std::vector<LeafSphere> neighbour;
  for (const LeafSphere& s : spheres) {
    neighbour.push_back({s.center + glm::vec3(250.0f, 0.0f, 0.0f), s.radius});
  }
  std::vector<LeafSphere> both = spheres;
  both.insert(both.end(), neighbour.begin(), neighbour.end());
  const Sky sky = GrowthSky(r.params);
  const float opacity = static_cast<float>(r.params.Get(ParamId::kSphereOpacity));
  const auto exact_alone = ComputeLightReference(spheres, sky, opacity);
  const auto exact = ComputeLightReference(spheres, neighbour, sky, opacity);
  LightGridBuffers buffers;
  const auto fast_alone = ComputeLightGrid(spheres, sky, opacity, buffers);
  const auto fast = ComputeLightGrid(spheres, neighbour, sky, opacity, buffers);
  const auto joint = ComputeLightGrid(both, sky, opacity, buffers);
  std::vector<double> a, b, drop_exact, drop_fast, drop_joint;
  double mean_exact = 0, mean_fast = 0;
  const double n = static_cast<double>(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    a.push_back(exact[i].light);
    b.push_back(fast[i].light);
    drop_exact.push_back(exact_alone[i].light - exact[i].light);
    drop_fast.push_back(fast_alone[i].light - fast[i].light);
    drop_joint.push_back(fast_alone[i].light - joint[i].light);
    mean_exact += drop_exact.back() / n;
    mean_fast += drop_fast.back() / n;
  }
  const double r_light = Pearson(a, b), r_drop = Pearson(drop_exact, drop_fast);
  const double r_joint = Pearson(drop_exact, drop_joint);
  std::printf(
      "foreign shade, sakura 8 years, %zu spheres, neighbour 2.5 m: light r %.3f, drop r "
      "%.3f (one joint grid %.3f), mean drop %.4f (reference) %.4f (grid)\n",
      spheres.size(), r_light, r_drop, r_joint, mean_exact, mean_fast);
  // Measured: light r 0.991, drop r 0.988 (joint 0.874), mean drop 0.0198 and 0.0234.
  EXPECT_GE(r_light, 0.95);
  EXPECT_GE(r_drop, 0.95);
  EXPECT_GT(r_drop, r_joint);
  EXPECT_GT(mean_exact, 0.01);  // the neighbour does shade
  EXPECT_NEAR(mean_fast, mean_exact, 0.25 * mean_exact);
}

}  // namespace
}  // namespace niwa
