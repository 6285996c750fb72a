// Per-level measures of a grown mountain's contours (issue 31 item 2: the paper's, in --stats).
#ifndef NIWA_CORE_TERRAIN_LEVEL_MEASURES_H_
#define NIWA_CORE_TERRAIN_LEVEL_MEASURES_H_

#include <vector>

#include "terrain/contour.h"

namespace niwa::terrain {

// One level's contours (the spec's §3 metrics, /work/shared/specs/mountains.md): how much area
// each level keeps of the one below (the paper's shrinking by d), how round its rings are, how
// many edges §4.3 step 1.3 left long enough for the next midpoint displacement ("about 20 % of
// all segments are ≥ 2·d0"), and how rough the line is (the divider dimension, §5's ref 16).
struct LevelMeasures {
  int level = 0;
  double elevation = 0;
  int rings = 0;
  std::size_t vertices = 0;
  double area = 0;       // Σ ring areas (m²)
  double perimeter = 0;  // Σ ring perimeters (m)
  // area / the level below's area (NaN on the lowest level).
  double area_ratio = 0;
  // 4π·A/P² of each ring, the mean weighted by area (1 for a circle).
  double compactness = 0;
  // Edges ≥ 2·d0 over all edges of the level (§4.3's "about 20 %").
  double long_edge_share = 0;
  // Divider (compass) dimension of the level's longest ring: steps s = 2·d0·2^i while s < P/8,
  // D = 1 − slope of log L(s) against log s (1 a smooth line; NaN with fewer than 2 steps).
  double fractal_dimension = 0;
};

std::vector<LevelMeasures> ComputeLevelMeasures(const Terrain& t);

// The divider length of a closed ring walked from vertex 0 with compass opening s: the count of
// whole steps times s plus the last point's distance back to vertex 0.
double DividerLength(const Ring& ring, double s);

}  // namespace niwa::terrain

#endif  // NIWA_CORE_TERRAIN_LEVEL_MEASURES_H_
