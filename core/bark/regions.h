// The crack measures of a surface layer (../shared/specs/bark.md §4.1): regions (the plates the
// maps draw: the lattice's triangles whose three springs are intact, joined across shared edges,
// on the torus; extents by an unwrapped breadth-first walk; a plate that wraps around or along
// the trunk is a strip; the spec's 4-connected raster components at the lattice's resolution),
// lattice intercepts (crack spacing around and along), broken fractions per family and the
// vertical-crack share. Does not: draw (bark_maps.h) or read pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "bark/lattice.h"
#include "bark/springs.h"

namespace niwa::bark {

struct Region {
  int triangles = 0;
  double width = 0, height = 0;  // cm, around and along the trunk (a wrapped side: C or H)
  bool wraps_around = false, wraps_along = false;
  bool closed() const { return !wraps_around && !wraps_along; }
};

// Crack spacing along scan lines (the paper's Table 3: 「縦横のひびの間隔を計測した」, the spacing
// of the vertical and the horizontal cracks; lattice.h's lines). On a line a crack is a run of
// halves whose triangle is in no counted plate (a cracked triangle or a plate under two
// triangles); a line's spacing is its length / the cracks it crosses, as a line drawn across a
// picture and its crossings counted. Along the trunk a run crosses only if it holds a broken axial
// spring (a horizontal crack; a vertical one lying on the line is run along, not crossed).
struct Spacing {
  double mean = 0;  // cm: the mean of the lines' spacings
  double max = 0;   // cm: the largest line spacing (a line crossing no crack: its length)
  double gap_mean = 0, gap_max = 0;  // cm: over single gaps between neighbouring cracks' middles
  int lines = 0;  // lines with a plate on them (the others are all crack and not counted)
  int open = 0;   // of those, lines crossing no crack (the paper's "(>20)")
};

struct CrackMeasures {
  int springs[2] = {0, 0}, broken[2] = {0, 0};
  double broken_fraction[2] = {0, 0};
  double vertical_crack_share = 0;  // broken diagonals / all broken (0 when none broke)
  std::vector<int> tri_region;      // region id of each triangle, -1 when a spring of it broke
  std::vector<Region> regions;      // every plate, in order of its lowest triangle
  // Over plates of at least two triangles (area A_n, a node's):
  int count = 0, strips = 0;
  double mean_width = 0, mean_height = 0, max_width = 0, max_height = 0;
  double plate_fraction = 0;   // triangles in plates / all triangles
  double closed_fraction = 0;  // area in closed plates / area in counted plates
  // Intercepts: C / mean crack crossings of a row, H / mean broken axial springs of a column
  // (0 when no crack crosses: the spacing is over the patch).
  double intercept_width = 0, intercept_height = 0;
  // Crack spacing around the trunk (width: the vertical cracks) and along it (height: the
  // horizontal cracks, runs holding a broken axial spring; regions.cpp). spacing_height_all_runs:
  // along it with every crack run a crossing (the measure before 2026-12-06, which counts the ends
  // of vertical cracks lying on a line as crossings), for comparison.
  Spacing spacing_width, spacing_height, spacing_height_all_runs;
};

// The measures of the surface at the growth factors (s_θ, s_z scale the reference lattice).
CrackMeasures MeasureCracks(const Lattice& lattice, const Surface& surface, double s_theta,
                            double s_z);
// Its plates alone (tri_region, regions, count, strips, their extents and fractions; the other
// fields zero): what the 4-layer model's peeling and shedding read, every kPeelCheckSteps steps.
CrackMeasures MeasurePlates(const Lattice& lattice, const Surface& surface, double s_theta,
                            double s_z);

}  // namespace niwa::bark
