// The polygon shrinking algorithm traced step by step for the paper's method figures (Figs 2-8,
// 12). For each step it keeps what the figures show: the naive edge offsets of Fig 2 (each edge
// moved by d, no joins: gaps at valleys, crossings at ridges), the raw offset path with its joins
// (Figs 5-7, Fig 6(b)), and the simple rings the union keeps (Fig 6(d)); steps > 1 shrink every
// ring again (Fig 3's corners, Fig 4's islands); the seed can first be midpoint-displaced (Fig 12).
// Each step carries the measures the figures name. Does not: grow a mountain (generate.h), choose
// elevations, or perturb shrunk contours (§4's methods apply only to the seed here).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "terrain/contour.h"
#include "terrain/offset.h"

namespace niwa::terrain {

struct EdgeOffset {
  Vec2 a, b;  // one edge of a ring moved by d along its offset-side normal
};

struct ShrinkTraceOptions {
  ShrinkOptions shrink;
  int steps = 1;  // successive shrinks of every ring, 0..kMaxTraceSteps
  // Fig 12: the seed midpoint-displaced first (every edge ≥ 2·d0 split at s·min(d'', |l·tan θ|)).
  bool displace = false;
  double d0 = 1, d2 = 0.3, theta_min_deg = 0, theta_max_deg = 30;
  uint64_t rng_seed = 1;
};
constexpr int kMaxTraceSteps = 64;
constexpr std::size_t kMaxTracePoints = 20000;  // a figure, not a mountain

struct ShrinkTraceStep {
  std::vector<Ring> input;                     // the rings shrunk in this step (normalised)
  std::vector<std::vector<EdgeOffset>> naive;  // Fig 2: per input ring, its edges moved by d
  std::vector<Ring> raw;                       // Fig 6(b): the raw offset path of each input ring
  std::vector<Ring> rings;                     // Fig 6(d): the rings kept
  int convex = 0, reflex = 0;  // vertices of the input rings (reflex: a valley when shrinking)
  int gaps = 0;                // Fig 2(a): naive offsets that leave a gap (at every reflex vertex)
  int crossings = 0;           // Fig 2(b): convex vertices whose two naive offsets cross
  int raw_self_intersections =
      0;                       // crossing segment pairs of the raw paths (the union removes them)
  int points = 0;              // vertices of the kept rings
  double min_angle_deg = 180;  // smallest interior angle of the kept rings (Fig 3's "corner")
  ShrinkCounts counts;         // Fig 8 pre-clean, holes, dropped slivers
};

struct ShrinkTrace {
  Ring seed;                    // normalised
  Ring displaced;               // Fig 12's displaced seed (empty without options.displace)
  double max_displacement = 0;  // largest distance of a displaced point from the seed (m)
  std::vector<ShrinkTraceStep> steps;
};

// Traces options.steps shrinks of the seed (checked: 3..kMaxTracePoints points, simple). Errors
// name "steps", "d", "c" or "contour" with the allowed range.
Result<ShrinkTrace> TraceShrink(const Ring& seed, const ShrinkTraceOptions& options);

// Smallest interior angle (degrees, 0..360) of a counter-clockwise ring.
double MinInteriorAngleDeg(const Ring& ring);

// One SVG of the trace: the seed (black; the displaced seed over it in green), naive offsets (thin
// orange), raw paths (dashed red) and kept rings (blue, darker with each step).
std::string ShrinkTraceToSvg(const ShrinkTrace& trace);

}  // namespace niwa::terrain
