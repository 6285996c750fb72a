// Bird's-eye pictures of any heightfield (issue 31 item 1, the paper's Fig 17 as renders): a
// perspective view of the surface, hypsometric tint lit by a sun, over a sky.
// Why no library: the core has no GL, and what is needed is one z-buffered triangle rasteriser
// (about 150 lines) whose bytes must match natively and in WASM; it is tested against a
// brute-force ray caster (RenderReliefIds vs CastReliefIds). Does not: read or write files, draw
// contours or labels, shadow (a cell in a neighbour's shade is lit by its own slope only), or
// know what made the heights (a grown mountain and a real DEM are drawn alike).
#pragma once

#include <cstdint>
#include <vector>

#include "base/status.h"
#include "image/image.h"

namespace niwa::image {

// Samples of a surface on a square grid: row 0 is the north, sample (i, j) stands at x = x0 +
// i·cell (east), y = y1 − j·cell (north), at height heights[j·width + i] (m). A non-finite height
// is a hole: the cells touching it are not drawn.
struct ReliefGrid {
  int width = 0, height = 0;
  double x0 = 0, y1 = 0, cell = 1;
  std::vector<double> heights;
};

// The camera and light. The camera stands towards compass bearing `view_from_deg` (0 north, 90
// east, 180 south) from the framed box's centre, `elevation_deg` above the horizon, far enough
// that the box (with its heights) fills the picture's height at a vertical field of view fov_deg.
struct ReliefView {
  int width = 960, height = 600;  // pixels, 16..4096 each
  double view_from_deg = 200, elevation_deg = 35, fov_deg = 30;
  double exaggeration = 1.0;                          // vertical scale, 0.1..20
  double sun_from_deg = 315, sun_elevation_deg = 40;  // the cartographers' north-west light
  // The box framed and drawn (x_min, y_min, x_max, y_max, m; samples outside it are not drawn):
  // all zero frames the grid's own extent. One box for several grids gives them one camera and one
  // footprint (side-by-side comparisons).
  double frame[4] = {0, 0, 0, 0};
  // Heights below floor are drawn at floor (a real DEM cut at a seed contour's level, as a grown
  // mountain stands on a plain at that level); -inf draws every height as it is.
  double floor = -1.0 / 0.0;
  // Heights mapped to the ends of the tint ramp; tint_min >= tint_max takes the grid's range.
  double tint_min = 0, tint_max = 0;
};

// The picture (RGBA, opaque). Errors name "grid" (fewer than 2 × 2 samples, more than 4097 ×
// 4097, a cell that is not finite and positive, heights not width·height, no finite sample) or
// "view" (a size or angle out of range).
Result<Rgba8Image> RenderRelief(const ReliefGrid& grid, const ReliefView& view);

// Which triangle each pixel shows (cell (i, j) has triangles 2·(j·(width−1) + i) and +1; −1 sky),
// row 0 at the top: the rasteriser's answer, and the same by casting one ray per pixel against
// every triangle (the test oracle; O(pixels·triangles)). The view must be valid.
std::vector<int64_t> RenderReliefIds(const ReliefGrid& grid, const ReliefView& view);
std::vector<int64_t> CastReliefIds(const ReliefGrid& grid, const ReliefView& view);

// A pixel's triangle (−1 sky) and the barycentrics of its corners 1 and 2 where the ray through the
// pixel centre meets it: the rasteriser's perspective-corrected edge weights, and the same by ray
// (the test oracle, as above; 0 for the sky).
struct ReliefHit {
  int64_t triangle = -1;
  double b1 = 0, b2 = 0;
};
std::vector<ReliefHit> RenderReliefHits(const ReliefGrid& grid, const ReliefView& view);
std::vector<ReliefHit> CastReliefHits(const ReliefGrid& grid, const ReliefView& view);

}  // namespace niwa::image
