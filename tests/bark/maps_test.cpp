// The bark maps: sizes, a flat intact layer, the bevel's normals in the OpenGL convention (+y up
// the image), and tiling: a surface turned around the trunk draws the same map shifted (so the
// seam is no place of its own), and the step across the top/bottom seam is one like those inside.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "bark/bark_maps.h"
#include "bark/bark_run.h"
#include "bark/bark_state.h"

namespace niwa::bark {
namespace {

Surface CutColumns(const Lattice& L, int from, int to) {
  Surface s = InitialSurface(L, MechanicsOf(*BarkPreset("pine")), 1);
  for (int k = 0; k < L.springs(); ++k) {
    const int ia = L.a[k] / L.n_h, ib = L.b[k] / L.n_h;
    const bool a_in = ia >= from && ia < to, b_in = ib >= from && ib < to;
    if (a_in != b_in) s.broken[k] = 1;
  }
  return s;
}

Surface CutRows(const Lattice& L, int from, int to) {
  Surface s = InitialSurface(L, MechanicsOf(*BarkPreset("pine")), 1);
  for (int k = 0; k < L.springs(); ++k) {
    const int ja = L.a[k] % L.n_h, jb = L.b[k] % L.n_h;
    const bool a_in = ja >= from && ja < to, b_in = jb >= from && jb < to;
    if (a_in != b_in) s.broken[k] = 1;
  }
  return s;
}

TEST(BarkMaps, SizesArePowersOfTwo) {
  EXPECT_EQ(MapHeightPx(1024, 36.58, 21.12), 512);  // 591 wanted
  EXPECT_EQ(MapHeightPx(256, 36.58, 21.12), 256);   // at least 256
  EXPECT_EQ(MapHeightPx(4096, 10, 100), 4096);      // at most 4096
  const Lattice L = BuildLattice(32, 16, 0.33);
  const Surface s = CutColumns(L, 0, 0);
  const BarkMaps m = DrawBarkMaps(L, s, MeasureCracks(L, s, 1, 1), 1, 1, 1.0, 256);
  EXPECT_EQ(m.base_colour.width, 256);
  EXPECT_EQ(m.height.height, MapHeightPx(256, L.circumference(), L.height()));
  EXPECT_TRUE(m.normal.consistent() && m.orm.consistent() && m.height.consistent());
}

TEST(BarkMaps, AnIntactLayerIsFlatAndBevelsFaceAwayFromCracks) {
  const Lattice L = BuildLattice(32, 16, 0.33);
  const Surface intact = CutColumns(L, 0, 0);
  const BarkMaps flat = DrawBarkMaps(L, intact, MeasureCracks(L, intact, 1, 1), 1, 1, 1.0, 256);
  for (int y = 0; y < flat.height.height; ++y)
    for (int x = 0; x < flat.height.width; ++x) {
      ASSERT_EQ(flat.height.At(x, y), 65535) << x << "," << y;
      // Only the fibre grain (in the normal, not the height) tilts it, by a few degrees.
      ASSERT_GE(flat.normal.At(x, y)[2], 250);
    }
  // A crack band along the trunk (columns 8..15 cut out): the plate left of the left crack
  // slopes down towards +x, so its normal leans +x (red > 128).
  const Surface band = CutColumns(L, 8, 16);
  const BarkMaps m = DrawBarkMaps(L, band, MeasureCracks(L, band, 1, 1), 1, 1, 1.0, 512);
  int leaning_x = 0, crack_pixels = 0;
  for (int x = 1; x < m.height.width / 4; ++x) {
    const int y = 10;
    if (m.height.At(x, y) == 0) ++crack_pixels;
    if (m.height.At(x, y) > 0 && m.height.At(x + 1, y) == 0 && m.height.At(x - 1, y) > 0)
      leaning_x += m.normal.At(x, y)[0] > 128;
  }
  EXPECT_GT(crack_pixels, 0);
  EXPECT_GE(leaning_x, 1);
  // The crack has walls, not a step: from the plate's top down to the floor the height passes
  // through levels below half its top (the old maps stepped from 0.7·D straight to 0).
  int wall = 0;
  for (int x = 1; x < m.height.width / 2; ++x) {
    const int v = m.height.At(x, 10);
    wall += v > 1000 && v < 30000;  // below the old 0.7·D bevel: the wall reaches the floor
  }
  EXPECT_GE(wall, 2) << wall;
  // A crack band around the trunk (rows 4..7): the plate above it (smaller row index, higher on
  // the trunk) slopes down the image, so in OpenGL's +y-up convention its normal leans -y.
  const Surface ring = CutRows(L, 4, 8);
  const BarkMaps r = DrawBarkMaps(L, ring, MeasureCracks(L, ring, 1, 1), 1, 1, 1.0, 512);
  int down = 0, up = 0;
  for (int y = 1; y + 1 < r.height.height; ++y) {
    const int x = 40;
    if (r.height.At(x, y) > 0 && r.height.At(x, y + 1) == 0) down += r.normal.At(x, y)[1] < 128;
    if (r.height.At(x, y) > 0 && r.height.At(x, y - 1) == 0) up += r.normal.At(x, y)[1] > 128;
  }
  EXPECT_GE(down, 1);
  EXPECT_GE(up, 1);
}

// Mean absolute difference of the height map between rows y0 and y1.
double RowStep(const image::Gray16Image& h, int y0, int y1) {
  double sum = 0;
  for (int x = 0; x < h.width; ++x) sum += std::abs(h.At(x, y0) - h.At(x, y1));
  return sum / h.width;
}

TEST(BarkMaps, AGrownTileContinuesAcrossBothSeams) {
  BarkState state;
  ASSERT_TRUE(SetBarkSpecies("tallow", &state).ok());
  ASSERT_TRUE(SetBarkSize("32x32", &state).ok());
  ASSERT_TRUE(state.params.Set(BarkParam::kMapSize, 256).ok());
  Result<BarkRun> run = BarkRun::Start(state, Budget{});
  ASSERT_TRUE(run.ok());
  ASSERT_TRUE(run->Advance({}).ok());
  const BarkMaps& m = run->maps();
  ASSERT_GT(run->cracks().broken[0] + run->cracks().broken[1], 0);
  const image::Gray16Image& h = m.height;
  // Exact tiling around the trunk: the same surface turned by two columns (lattice parity kept)
  // draws the same height map shifted by 2·W/N_R pixels, so x = 0 is no different from any
  // other place; every pixel but a few on a plate's exact edge agrees.
  const Lattice& L = run->lattice();
  const Surface& s = run->surface();
  Surface turned = s;
  for (int n = 0; n < L.nodes(); ++n) {
    const int to = (n + 2 * L.n_h) % L.nodes();
    turned.ux[to] = s.ux[n];
    turned.uz[to] = s.uz[n];
    turned.broken[to] = s.broken[n];
    for (int k = 0; k < 2; ++k)
      turned.broken[L.axial_count + 2 * to + k] = s.broken[L.axial_count + 2 * n + k];
  }
  const Growth g = run->growth();
  const BarkMaps t = DrawBarkMaps(L, turned, MeasureCracks(L, turned, g.s_theta, g.s_z), g.s_theta,
                                  g.s_z, 1.0, 256);
  const int shift = 2 * h.width / L.n_r;
  int differ = 0;
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) differ += t.height.At((x + shift) % h.width, y) != h.At(x, y);
  EXPECT_LE(differ, h.width * h.height / 1000) << differ;
  // Along the trunk: the step from the bottom row to the top one is a step like those inside,
  // within the range of the steps at the other rows.
  double lo = 1e300, hi = 0;
  for (int y = 0; y + 1 < h.height; ++y) {
    lo = std::min(lo, RowStep(h, y, y + 1));
    hi = std::max(hi, RowStep(h, y, y + 1));
  }
  EXPECT_GE(RowStep(h, h.height - 1, 0), lo);
  EXPECT_LE(RowStep(h, h.height - 1, 0), hi);
}

}  // namespace
}  // namespace niwa::bark
