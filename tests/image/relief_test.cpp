// Bird's-eye relief pictures (image/relief): the rasteriser shows the triangle a ray through each
// pixel meets first (brute-force twin), holes stay undrawn, the sunlit flank is the brighter one,
// the tint runs low green to high white, bad grids and views are refused naming the field, and the
// bytes are pinned (the same on the native and WASM builds, which both run this test).
#include "image/relief.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "random/pcg32.h"

namespace niwa::image {
namespace {

ReliefGrid Bumpy(int w, int h, uint64_t seed) {
  ReliefGrid g;
  g.width = w;
  g.height = h;
  g.x0 = 100;
  g.y1 = 500;
  g.cell = 10;
  Pcg32 rng(seed);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const double dx = i - 0.5 * (w - 1), dy = j - 0.5 * (h - 1);
      g.heights.push_back(60.0 - 2.0 * (dx * dx + dy * dy) + 8.0 * rng.Uniform());
    }
  }
  return g;
}

// A cone around the grid's centre sample, 4 m up per cell towards it.
ReliefGrid Cone(int side) {
  ReliefGrid g;
  g.width = g.height = side;
  g.cell = 1;
  const double c = 0.5 * (side - 1);
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      g.heights.push_back(4.0 * (c - std::sqrt((i - c) * (i - c) + (j - c) * (j - c))));
    }
  }
  return g;
}

double Luminance(const Rgba8Image& img, std::size_t q) {
  const unsigned char* p = img.pixels.data() + 4 * q;
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// The colour's barycentrics come from the rasteriser's edge weights corrected by 1/z: where both
// answers show the same triangle, they are the ray's own hit point's barycentrics.
TEST(Relief, RasterisedBarycentricsAreTheRaysHitPoint) {
  for (const double elevation : {20.0, 60.0, 90.0}) {
    ReliefGrid g = Bumpy(9, 7, 3);
    ReliefView v;
    v.width = 80;
    v.height = 60;
    v.elevation_deg = elevation;
    v.view_from_deg = 200;
    v.exaggeration = 2;
    const std::vector<ReliefHit> raster = RenderReliefHits(g, v), cast = CastReliefHits(g, v);
    ASSERT_EQ(raster.size(), cast.size());
    std::size_t compared = 0;
    double worst = 0;
    for (std::size_t q = 0; q < raster.size(); ++q) {
      if (raster[q].triangle < 0 || raster[q].triangle != cast[q].triangle) continue;
      ++compared;
      worst = std::max({worst, std::abs(raster[q].b1 - cast[q].b1), std::abs(raster[q].b2 - cast[q].b2)});
    }
    EXPECT_GT(compared, raster.size() / 8) << "elevation " << elevation;
    EXPECT_LT(worst, 1e-9) << "elevation " << elevation;
  }
}

TEST(Relief, RasteriserShowsWhatARayMeetsFirst) {
  for (const double elevation : {20.0, 35.0, 60.0, 90.0}) {
    for (const double from : {200.0, 45.0}) {
      ReliefGrid g = Bumpy(9, 7, 3);
      g.heights[3 * 9 + 4] = NAN;  // a hole
      ReliefView v;
      v.width = 80;
      v.height = 60;
      v.elevation_deg = elevation;
      v.view_from_deg = from;
      v.exaggeration = 2;
      const std::vector<int64_t> raster = RenderReliefIds(g, v);
      const std::vector<int64_t> cast = CastReliefIds(g, v);
      ASSERT_EQ(raster.size(), cast.size());
      std::size_t differ = 0, sky_differ = 0, surface = 0;
      for (std::size_t q = 0; q < raster.size(); ++q) {
        surface += raster[q] >= 0;
        if (raster[q] != cast[q]) ++differ;
        if ((raster[q] < 0) != (cast[q] < 0)) ++sky_differ;
      }
      // Only pixel centres on a shared edge may go either way.
      EXPECT_GT(surface, raster.size() / 8) << "elevation " << elevation;
      EXPECT_LE(differ, raster.size() / 100) << "elevation " << elevation << " from " << from;
      EXPECT_LE(sky_differ, raster.size() / 200) << "elevation " << elevation;
      // The six triangles touching the hole (sample (4, 3)) are never drawn.
      for (int64_t t : raster) {
        if (t < 0) continue;
        const int64_t cell = t / 2, i = cell % 8, j = cell / 8;
        const bool touches =
            (t % 2 == 0 && ((i == 4 && j == 3) || (i == 4 && j == 2) || (i == 3 && j == 3))) ||
            (t % 2 == 1 && ((i == 3 && j == 3) || (i == 3 && j == 2) || (i == 4 && j == 2)));
        EXPECT_FALSE(touches) << "triangle " << t;
      }
    }
  }
}

// Mean luminance of the pixels showing the cone's north-west and south-east quarters.
void Flanks(const ReliefView& v, double* nw, double* se) {
  const ReliefGrid g = Cone(21);
  Result<Rgba8Image> img = RenderRelief(g, v);
  ASSERT_TRUE(img.ok()) << img.status().Line();
  const std::vector<int64_t> ids = RenderReliefIds(g, v);
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  for (std::size_t q = 0; q < ids.size(); ++q) {
    if (ids[q] < 0) continue;
    const int64_t cell = ids[q] / 2, i = cell % 20, j = cell / 20;
    const int side = (i < 8 && j < 8) ? 0 : (i > 11 && j > 11) ? 1 : -1;  // row 0 is north
    if (side < 0) continue;
    sum[side] += Luminance(*img, q);
    ++count[side];
  }
  ASSERT_GT(count[0], 50);
  ASSERT_GT(count[1], 50);
  *nw = sum[0] / count[0];
  *se = sum[1] / count[1];
}

TEST(Relief, TheSunlitFlankIsBrighter) {
  ReliefView v;
  v.width = 160;
  v.height = 120;
  v.elevation_deg = 90;  // straight down: both flanks in view alike
  double nw = 0, se = 0;
  Flanks(v, &nw, &se);
  EXPECT_GT(nw, se + 20) << "sun from the north-west";
  v.sun_from_deg = 135;
  Flanks(v, &nw, &se);
  EXPECT_GT(se, nw + 20) << "sun from the south-east";
}

TEST(Relief, TintRunsFromLowGreenToHighWhite) {
  ReliefGrid g;
  g.width = 2;
  g.height = 2;
  g.heights = {0, 0, 0, 0};
  ReliefView v;
  v.width = v.height = 32;
  v.elevation_deg = 90;
  v.sun_elevation_deg = 90;
  v.tint_min = 0;
  v.tint_max = 100;
  Result<Rgba8Image> low = RenderRelief(g, v);
  g.heights = {100, 100, 100, 100};
  Result<Rgba8Image> high = RenderRelief(g, v);
  ASSERT_TRUE(low.ok() && high.ok());
  const unsigned char* l = low->At(16, 16);
  const unsigned char* h = high->At(16, 16);
  EXPECT_GT(l[1], l[0]);  // green over red
  EXPECT_GT(l[1], l[2]);
  EXPECT_GT(h[0], 230);  // white
  EXPECT_GT(h[1], 230);
  EXPECT_GT(h[2], 230);
}

TEST(Relief, BadGridsAndViewsNameTheirField) {
  const ReliefGrid ok = Bumpy(4, 4, 1);
  ReliefGrid g = ok;
  g.width = 1;
  EXPECT_EQ(RenderRelief(g, {}).status().field(), "grid");
  g = ok;
  g.heights.pop_back();
  EXPECT_EQ(RenderRelief(g, {}).status().field(), "grid");
  g = ok;
  g.cell = 0;
  EXPECT_EQ(RenderRelief(g, {}).status().field(), "grid");
  g = ok;
  for (double& z : g.heights) z = NAN;
  EXPECT_EQ(RenderRelief(g, {}).status().field(), "grid");
  ReliefView v;
  v.width = 8;
  EXPECT_EQ(RenderRelief(ok, v).status().field(), "view");
  v = {};
  v.elevation_deg = 2;
  EXPECT_EQ(RenderRelief(ok, v).status().field(), "view");
  v = {};
  v.exaggeration = NAN;
  EXPECT_EQ(RenderRelief(ok, v).status().field(), "view");
  v = {};
  v.frame[0] = INFINITY;
  EXPECT_EQ(RenderRelief(ok, v).status().field(), "view");
  v = {};
  v.frame[0] = 0, v.frame[1] = 0, v.frame[2] = 10, v.frame[3] = 10;  // beside the grid
  EXPECT_EQ(RenderRelief(ok, v).status().field(), "view");
  EXPECT_TRUE(RenderRelief(ok, {}).ok());
}

// A frame draws only the samples inside it; a floor lifts what lies below it.
TEST(Relief, FrameCropsAndFloorLifts) {
  const ReliefGrid g = Bumpy(9, 7, 5);  // x 100..180, y 440..500
  ReliefView v;
  v.width = 80;
  v.height = 60;
  v.frame[0] = 100, v.frame[1] = 440, v.frame[2] = 140, v.frame[3] = 500;  // the west half
  std::size_t shown = 0;
  for (int64_t t : RenderReliefIds(g, v)) {
    if (t < 0) continue;
    ++shown;
    EXPECT_LT((t / 2) % 8, 4) << "triangle " << t << " east of the frame";
  }
  EXPECT_GT(shown, 0u);
  ReliefView lifted;
  lifted.floor = 1e6;  // every sample on one plane: one flat colour under the overhead sun
  lifted.elevation_deg = 90;
  lifted.sun_elevation_deg = 90;
  lifted.tint_min = 0;
  lifted.tint_max = 1;
  Result<Rgba8Image> flat = RenderRelief(g, lifted);
  ASSERT_TRUE(flat.ok());
  const std::vector<int64_t> ids = RenderReliefIds(g, lifted);
  const unsigned char* first = nullptr;
  for (std::size_t q = 0; q < ids.size(); ++q) {
    if (ids[q] < 0) continue;
    const unsigned char* p = flat->pixels.data() + 4 * q;
    if (!first) first = p;
    EXPECT_TRUE(p[0] == first[0] && p[1] == first[1] && p[2] == first[2]) << "pixel " << q;
  }
  ASSERT_NE(first, nullptr);
}

TEST(Relief, BytesArePinned) {
  ReliefView v;
  v.width = 120;
  v.height = 90;
  Result<Rgba8Image> img = RenderRelief(Bumpy(33, 25, 9), v);
  ASSERT_TRUE(img.ok());
  uint64_t hash = 1469598103934665603ull;  // FNV-1a
  for (unsigned char b : img->pixels) hash = (hash ^ b) * 1099511628211ull;
  EXPECT_EQ(hash, 2061009976126404761ull) << "pinned picture";
}

}  // namespace
}  // namespace niwa::image
