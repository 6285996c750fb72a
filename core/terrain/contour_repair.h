// A seed contour that crosses itself (a drawing, an imported file) made one simple closed loop: the
// paper's own loop removal (§4.4 method 2: cut from each crossing to its twin, walking from the
// longest run, as the generator untwists a perturbed contour), else the largest ring of the
// positive-winding union. The page repairs a fresh drawing with it, `niwa terrain grow --repair`
// the seed it is given, so a drawing grows the same mountain in both.
// Does not: grow, or change a contour that is already a valid seed (FitContourToLink, below,
// shortens one that is too long for a link; SetTerrainPoints caps the points a link carries).
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

// A contour made to fit a share link (issue 34: a drawn 2,000-point contour wrote a 32,618-
// character link that no page could read back): when the text of its points (terrain_state.h
// EncodeContourPoints) is longer than max_chars, its coordinates go onto a grid of `quantum`
// metres (a power of two ≥ 1/1024 m near a 4096th of its span, so the repair's snapping keeps
// them and their text is short), then points are dropped (Douglas-Peucker, its tolerance doubled
// from the quantum) until the text fits. The result may cross itself (RepairContour after it).
struct LinkFit {
  Ring ring;
  bool changed = false;  // false: the ring as given (it fitted)
  double quantum = 0;    // the grid (m) when changed
  double tolerance = 0;  // the Douglas-Peucker tolerance (m), 0 when no point was dropped
};
LinkFit FitContourToLink(const Ring& ring, std::size_t max_chars);

}  // namespace niwa::terrain
