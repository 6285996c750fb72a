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
};

// The measures of the surface at the growth factors (s_θ, s_z scale the reference lattice).
CrackMeasures MeasureCracks(const Lattice& lattice, const Surface& surface, double s_theta,
                            double s_z);

}  // namespace niwa::bark
