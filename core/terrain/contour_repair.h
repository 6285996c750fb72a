// A seed contour that crosses itself (a drawing, an imported file) made one simple closed loop: the
// paper's own loop removal (§4.4 method 2: cut from each crossing to its twin, walking from the
// longest run, as the generator untwists a perturbed contour), else the largest ring of the
// positive-winding union. The page repairs a fresh drawing with it, `niwa terrain grow --repair`
// the seed it is given, so a drawing grows the same mountain in both.
// Does not: limit the points to what a link carries (terrain_state.h SetTerrainPoints), grow, or
// change a contour that is already a valid seed.
#pragma once

#include <string>

#include "base/status.h"
#include "terrain/contour.h"

namespace niwa::terrain {

struct ContourRepair {
  Ring ring;              // the points as given when nothing was wrong, else the repaired ring
                          // (snapped to the 1/1024 m grid, counter-clockwise)
  bool repaired = false;  // the given ring was not a valid seed (CheckSeed) and was repaired
  int loops_removed = 0;  // loops cut by §4.4 method 2
  std::string method;     // "" (not repaired), "loops" (§4.4 method 2) or "union" (largest piece)
  std::string reason;     // CheckSeed's line for the given ring when repaired
};

// The ring checked as Grow checks a seed (CheckSeed) and repaired when it crosses itself or has
// no area. Errors name "contour": CheckSeed's line when the points themselves are bad (fewer
// than 3, too many, not finite), or "crosses itself and could not be repaired".
Result<ContourRepair> RepairContour(const Ring& ring);

}  // namespace niwa::terrain
