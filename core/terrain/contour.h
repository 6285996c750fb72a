// Terrain data types: a contour ring in metres, the contour tree (parent, children, elevation) and
// the summits of its top contours (Misawa, Chiba, Saito 1987, §3). Does not: shrink, perturb or
// interpolate anything (core/terrain/offset, generate, heightfield).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace niwa::terrain {

// A point in metres (x east, y north).
struct Vec2 {
  double x = 0, y = 0;
  bool operator==(const Vec2& o) const { return x == o.x && y == o.y; }
  bool operator!=(const Vec2& o) const { return !(*this == o); }
};

// A closed simple polygon p_0..p_{n-1} (the closing edge p_{n-1} -> p_0 is implied), counter-
// clockwise (interior on the left), every coordinate on the 1/kGridPerMetre m grid.
using Ring = std::vector<Vec2>;

// The axis-aligned box of a ring (not empty), in metres.
struct RingBox {
  double x0, y0, x1, y1;
  double span() const { return std::max(x1 - x0, y1 - y0); }  // its longer side
};
inline RingBox BoundsOf(const Ring& ring) {
  RingBox b{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
  for (const Vec2& v : ring) {
    b.x0 = std::min(b.x0, v.x);
    b.x1 = std::max(b.x1, v.x);
    b.y0 = std::min(b.y0, v.y);
    b.y1 = std::max(b.y1, v.y);
  }
  return b;
}

// Coordinates of every contour leaving the generator are multiples of 1/kGridPerMetre metres, so
// orientation tests on them are exact integer arithmetic (int64 with __int128 products).
constexpr double kGridPerMetre = 1024.0;

// One contour of the tree: a ring one interval above its parent.
struct ContourNode {
  Ring ring;
  int level = 0;         // 0 = the seed
  double elevation = 0;  // h_k = h0 + k·Δh (m)
  int parent = -1;       // index into Terrain::contours; -1 for the seed
  std::vector<int> children;
};

// The summit placed inside a top contour: its pole of inaccessibility (§1.9 of our reading).
struct Summit {
  int contour = -1;  // the top contour (a leaf)
  Vec2 position;
  double radius = 0;  // inscribed-circle radius r of the top contour at the summit (m)
  double elevation = 0;
};

// What the generator counted while growing.
struct GrowCounts {
  int loops_removed = 0;           // loops cut by §4.4 method 1 or 2
  int union_fallbacks = 0;         // contours whose loops needed the positive-winding union
  int perturbations_reverted = 0;  // perturbed contours that crossed their parent or a sibling
  int cleaned_points = 0;          // Fig 8 pre-clean: points dropped (short edges, acute angles)
  int holes_filled = 0;            // clockwise rings dropped by the union (holes)
  int dropped_rings = 0;           // rings the union could not make simple (never emitted)
  int slivers_dropped = 0;         // grown rings under the area floor (generate.h kSliverArea)
  bool truncated = false;          // stopped at the level or vertex cap, or a budget
  double vertices_worked = 0;  // Σ vertices of shrunk contours and their children (budget work)
  double sweep_tests = 0;      // Σ edge tests of the shrinks' union sweeps (terrain_budget.h)
  double largest_worked = 0;   // the most points of one contour shrunk (held with its copies)
  std::string truncated_by;    // the budget's line when one stopped the growth (terrain_budget)
  double ms_shrink = 0, ms_mpd = 0, ms_fd = 0, ms_loops = 0;
};

// A whole mountain: contours in breadth-first order (the seed first, parents before children).
struct Terrain {
  std::vector<ContourNode> contours;
  std::vector<Summit> summits;  // one per top contour, in contour order
  double h0 = 0, dh = 0, d = 0;
  // The profile (issue 31 item 3, the `dh_ratio` row q): the interval from level k to k + 1 is
  // Δh·q^k, so q > 1 makes the upper levels steeper than the foothills, q < 1 the reverse; q = 1
  // is the paper's equal intervals (generate.cpp LevelElevations).
  double dh_ratio = 1;
  // §4.1's d0 (the mean edge of the seed as grown: resampled at d/4, generate.h ResampleSeed) and
  // that resampled seed's points (held while growing, besides the seed as given).
  double d0 = 0;
  std::size_t seed_samples = 0;
  GrowCounts counts;
};

// The elevation interval of a contour's band: to its children (all one level up), or Δh when it
// has none (a top band then rises to its summit instead) or the intervals are equal.
inline double BandInterval(const Terrain& t, const ContourNode& node) {
  if (t.dh_ratio == 1 || node.children.empty()) return t.dh;
  return t.contours[static_cast<std::size_t>(node.children[0])].elevation - node.elevation;
}

}  // namespace niwa::terrain
