// The surface from the contour tree (our choice, docs/terrain-model.md): each cell lies in one band
// (inside contour C, outside C's children) and gets h = h_C + Δh·a/(a + b), a = distance to C,
// b = distance to C's children (in a top band: to the summit, Δh -> h_s − h_C), then its
// depressions filled within each band (band_fill.h; sub-cell slots of a band first given to the
// child around them). Continuous, every level set on its contour as far as the grid resolves it,
// no interior pits (docs/terrain-model.md). Also the terrain's
// statistics. Does not: write files (terrain_output.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "terrain/contour.h"

namespace niwa::terrain {

// Row 0 is the north (largest y); cell (i, j) has its centre at (x0 + (i + ½)·cell,
// y1 − (j + ½)·cell).
struct Heightfield {
  int width = 0, height = 0;
  double x0 = 0, y1 = 0, cell = 1;
  std::vector<double> h;  // width·height elevations (m)
  std::vector<int> band;  // contour whose band holds the cell; −1 outside the lowest contour
  std::size_t cells_filled = 0;  // cells the band fill raised (0 without the fill)
  std::size_t slot_cells = 0;    // cells of sub-cell slots given to a child's band (band_fill.h)
  double At(int i, int j) const { return h[static_cast<std::size_t>(j) * width + i]; }
  Vec2 Centre(int i, int j) const { return {x0 + (i + 0.5) * cell, y1 - (j + 0.5) * cell}; }
};

// The heightfield with `res` cells along the longer side of the lowest contour's box (plus one
// cell of margin each side); cells outside it get the lowest elevation.
// Distances stamped by each segment into its slab and vertex wedges, the far cells through a
// SegmentGrid per contour (segment_grid.h): O(cells), not O(cells·vertices).
// fill_depressions: AssignSubCellSlots on the painted band map, then FillHeightfieldWithinBands
// (band_fill.h) on the band heights; false gives the band distance-ratio surface alone on the
// painted map.
Heightfield BuildHeightfield(const Terrain& terrain, int res, bool fill_depressions = true);
// The same on another grid's cells (its width, height, x0, y1, cell; e.g. a real DEM's).
Heightfield BuildHeightfieldOn(const Terrain& terrain, const Heightfield& grid,
                               bool fill_depressions = true);
// The same by brute force over every segment: the test oracle (equal bit for bit).
Heightfield BuildHeightfieldBruteForce(const Terrain& terrain, int res,
                                       bool fill_depressions = true);

struct TerrainStats {
  int levels = 0, contours = 0, peaks = 0, splits = 0;
  std::size_t vertices = 0;
  int self_intersections = 0;  // contours that are not simple (always 0)
  int nesting_violations = 0;  // children crossing or outside their parent, siblings meeting (0)
  double relief = 0;           // highest summit − lowest contour (m)
  double hypsometric_integral = 0;  // (mean − min)/(max − min) of the cells inside the lowest one
  double mean_slope_deg = 0;        // central differences, inside cells with inside neighbours
  int pits = 0;                     // interior cells below all 8 neighbours (strictly)
};

// Counts and exact checks of the contours; surface metrics when hf is given.
TerrainStats ComputeStats(const Terrain& terrain, const Heightfield* hf);

}  // namespace niwa::terrain
