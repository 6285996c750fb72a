// Real terrain against a grown one (issue 19 item 4, the paper's Fig 17 claim as numbers): a DEM
// read from a 16-bit heightmap PNG and its sidecar, and the measures taken on both over the cells
// inside the seed contour: hypsometric integral, slope distribution, relief, peaks and each
// level's area overlap (IoU). Does not: grow (generate.h), read files (callers pass the bytes).
#pragma once

#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "terrain/contour.h"
#include "terrain/heightfield.h"

namespace niwa::terrain {

// Slope histogram bins, degrees: [0, 5), [5, 10), ... [40, 45), [45, 90].
constexpr int kSlopeBins = 10;

struct SurfaceMeasures {
  int cells = 0;                    // inside the seed contour
  double relief = 0;                // max − h0 (m)
  double hypsometric_integral = 0;  // (mean − h0)/(max − h0)
  double mean_slope_deg = 0;        // central differences, cells with all 4 neighbours inside
  double slope_p90_deg = 0;         // 90th percentile of those slopes
  std::vector<double> slope_share;  // kSlopeBins shares of those cells
  int peaks = 0;  // cells above h0 + Δh that are the highest within d (ties: the first in rows)
};

struct LevelOverlap {
  int level = 0;
  double elevation = 0;
  int real_cells = 0, grown_cells = 0;
  double iou = 0;  // |real ∩ grown| / |real ∪ grown| of the cells at or above the elevation
};

struct Comparison {
  SurfaceMeasures real, grown;
  // The grown levels above the lowest contour at their own heights (h0 + kΔh when dh_ratio = 1;
  // generate.h LevelElevation), while either surface has cells at or above one.
  std::vector<LevelOverlap> levels;
  double mean_iou = 0;
  double slope_share_l1 = 0;  // Σ |share_real − share_grown| over the bins (0 same, 2 disjoint)
};

// A DEM from `niwa terrain grow --heightmap` bytes: the PNG (16-bit grey) and its sidecar JSON
// (width, height, min_elevation, max_elevation, cell_size, origin {x, y}). Errors name `field`.
Result<Heightfield> ReadHeightmap(const std::vector<unsigned char>& png, const std::string& sidecar,
                                  const std::string& field);

// The measures of `surface` over `inside` (1 per cell) with seed elevation h0, interval dh and
// peak radius d (m).
SurfaceMeasures MeasureSurface(const Heightfield& surface, const std::vector<char>& inside,
                               double h0, double dh, double d);

// The grown terrain sampled on the DEM's cells and both measured over the cells inside the seed.
Comparison CompareTerrain(const Heightfield& dem, const Terrain& grown);

// The peak search's cell tests at most (MeasureSurface: each cell against the disc of radius
// r = round(d / cell) cells around it, twice): a DEM of small cells under a large d makes r huge.
double ComparePeakTests(const Heightfield& dem, double d);
// Those tests against the budget's seconds, before anything grows: ok, or {"dem", "cells of C m
// under d = D m make each peak test look R cells around (T cell tests, about S s); must take at
// most L s (limit); use coarser cells or a smaller d"}.
Status CheckCompareCost(const Heightfield& dem, double d, const Budget& budget);

}  // namespace niwa::terrain
