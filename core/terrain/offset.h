// The polygon shrinking algorithm (Fig 6) with the four joins of Figs 5 and 7, the Fig 8 pre-clean,
// and the positive-winding union that turns a raw offset path into simple rings (steps 3-4).
// Written here (no library): Clipper, the usual choice, is a native-only .so in Debian, and the
// union must run on exact integer coordinates so that no self-intersecting ring ever leaves it.
// Does not: perturb (generate.h) or decide elevations.
#pragma once

#include <vector>

#include "terrain/contour.h"
#include "terrain/polygon.h"

namespace niwa::terrain {

// How the gap at a valley (reflex) vertex is closed: Fig 5(a) miter, 5(b) bevel, 5(c) round, and
// the Fig 7 capped polyline A1 -> P -> A2 with P = V + min(c·d, d/cos(ψ/2))·b.
enum class Join : int { kMiter = 0, kBevel = 1, kRound = 2, kCapped = 3 };
// The plain miter is the capped join with this c (Fig 5(a) up to ψ = 2·acos(1/10) ≈ 168.5°).
constexpr double kMiterLimit = 10.0;

struct ShrinkOptions {
  double d = 1;  // offset distance (m), > 0
  Join join = Join::kCapped;
  double c = 1.4;              // Fig 7 cap, ≥ 1
  double clean_len = 0;        // Fig 8 pre-clean: drop a point of an edge shorter than this (m)
  double clean_angle_deg = 0;  // Fig 8 pre-clean: drop a vertex with interior angle below this
  bool outward = false;        // grow toward the foot (clockwise offset, holes filled)
  bool swept = false;          // exact swept-piece union instead of the raw path (the test twin)
  // The points of straight runs kept (only repeated points and spikes dropped), in the input and
  // in the union's rings: Grow's (issue 31), so that a straight run sampled at d/4 keeps its
  // edges whether its points are exactly collinear on the grid (an axis-parallel side) or a
  // millimetre off (any other side, or a jittered copy); dropped, the first became one edge of
  // hundreds of metres that the midpoint displacement split, and the second none.
  bool keep_straight = false;
};

struct ShrinkCounts {
  int cleaned_points = 0;
  int holes_filled = 0;
  int dropped_rings = 0;
  // The union sweep's work (ray_windings.h: pieces, cell entries and exact edge tests; linear for
  // a comb, n·√n at worst), and the most allowed (< 0: no limit). Past it the union stops at once
  // with `stopped` and no rings (before the cells' lists are allocated): a budget counted, so
  // both builds stop alike.
  double sweep_tests = 0;
  double max_sweep_tests = -1;
  bool stopped = false;
};

// The sweep work (ShrinkCounts::sweep_tests) a split point costs: its pieces, their merge into the
// weighted edges (a map node) and their share of the windings and the chaining, about 6 µs and
// 400 bytes a split point on a 10,000-tooth comb (native release, loaded host) against 30 ns a
// counted test (terrain_budget.cpp). Counted as the points are found, so a shape whose offset
// path crosses itself millions of times stops before their pieces are made.
inline constexpr double kSweepWorkPerSplit = 200;
// And a pair of segments the split sweep tries (polygon.h kSweepWorkPerTry) is counted too, so
// edges stacked across one x range (a comb turned on its side, whose pairs are quadratic) stop at
// the budget.

// The join point P of Fig 7 for a reflex vertex V with left unit normals n1, n2 of its edges.
Vec2 CappedJoinPoint(const Vec2& v, const Vec2& n1, const Vec2& n2, double d, double c);

// Fig 8 pre-clean of a counter-clockwise ring (returns the ring; counts the points dropped).
Ring PreClean(const Ring& ring, double min_len, double min_angle_deg, int* dropped);

// Step 1-2: the raw offset path (offset edges plus the join pieces), unsnapped.
Ring RawOffsetPath(const Ring& ring, const ShrinkOptions& options);

// The region within d of the ring on the offset side as pieces (a rectangle per edge, a join
// wedge V, A1, join points, A2 per gap vertex), oriented clockwise when shrinking.
std::vector<Ring> SweptPieces(const Ring& ring, const ShrinkOptions& options);

// The first shrink's split sweep, forecast from the ring before it is made (terrain_budget's
// estimate; Shrink's pre-clean and raw offset path are made, not their union): the raw path's
// segments, the pairs the split sweep tries (x ranges overlapping: SplitAtIntersections walks
// them all, `tried`), and the pairs whose bounding boxes overlap (every crossing is one, so twice
// this bounds the first pass's split points; neighbours sharing a vertex are left out). Counted by
// sorting and Fenwick trees in O(s log s) for s segments, whatever the shape.
struct SplitForecast {
  double segments = 0, tried_pairs = 0, box_pairs = 0;
};
// The pairs the seed's simplicity check tries over the ring's own edges (polygon.h
// IsSimpleEitherAxis: the cheaper of the sweeps along x and y).
double TriedEdgePairs(const Ring& ring);
SplitForecast ForecastSplits(const Ring& ring, const ShrinkOptions& options);

// Steps 3-4: the regions of winding number ≥ 1 of a set of closed paths, as simple
// counter-clockwise rings on the grid (clockwise rings = holes are dropped and counted).
std::vector<Ring> PositiveUnion(const std::vector<Ring>& paths, ShrinkCounts* counts,
                                bool keep_straight = false);
// The work (ShrinkCounts::sweep_tests) of the union sweep over the ring's own edges, counted
// without the exact tests: terrain_budget's estimate of a shrink's sweep from its seed.
double UnionSweepWork(const Ring& ring);

// The whole Fig 6 algorithm: 0, 1 or several simple counter-clockwise rings at distance d inside
// the ring (outside when options.outward).
std::vector<Ring> Shrink(const Ring& ring, const ShrinkOptions& options, ShrinkCounts* counts);

// Ring made counter-clockwise, snapped, without repeated or collinear points (with keep_straight,
// the points of straight runs kept: ShrinkOptions::keep_straight).
Ring Normalise(const Ring& ring, bool keep_straight = false);

}  // namespace niwa::terrain
