// The union sweep's winding numbers (offset.cpp UnionOnce): for many points at once, the sum of
// the edges crossing each point's +x ray (Sunday's crossing rule), exactly equal to testing every
// edge, through a grid of cells and a Fenwick tree instead of every edge against every point.
// Does not: split edges, merge them or chain rings (offset.cpp); know contours.
//
// Why written here and no library: the answer must be the exact integer count of the brute
// force (the rings kept, and so every valid output's bytes, depend on it), on the 1/1024 m grid's
// int64 coordinates, natively and in WASM. nanoflann (../shared/TOOLCHAIN.md) answers
// nearest-point queries on float points, not crossing counts along rays; Clipper is native-only.
//
// How: cells of about equal sides, about one per edge. An edge is cut at the rows it crosses
// (pieces); a piece covers the columns of its x range (widened by one unit: conservative). For a
// point in cell (row, col), a piece of its row whose first column is right of col crosses the ray
// iff its y range holds the point's y (a Fenwick tree over y, filled while the columns are swept
// right to left); pieces that cover col are tested exactly; the rest lie left and cannot cross.
// The work is pieces + cell entries + exact tests: linear for a comb whose teeth are short
// against its width, n·√n at worst (long edges crossing many cells), and counted before the
// cells' lists are allocated (RayWindings stops at max_work).
#pragma once

#include <vector>

#include "terrain/polygon.h"

namespace niwa::terrain {

// An edge for the crossing rule: adds `weight` at a point p with lo.y <= p.y < hi.y lying strictly
// left of lo -> hi. lo.y < hi.y (edges of equal y cross no +x ray and are left out).
struct RayEdge {
  IPoint lo, hi;
  int weight = 0;
};

// How the sums are filled once the work is counted: kAuto takes the row scan when its exact tests
// (each point against the pieces of its row: the strips of the sweep before the grid) are at most
// a few times the counted work, as for the seeds people draw, and the column sweep with the
// Fenwick tree otherwise (combs: rows crowded with teeth). Both give the brute force's integers;
// the returned work is the count pass's either way, so budgets do not depend on the choice.
enum class RayWindingsFill { kAuto, kRows, kColumns };

// Fills (*out)[k] with the winding sum at points[k] and returns the work done (see above). When
// max_work >= 0 and the counted work passes it, returns that count at once (> max_work) with *out
// unfilled. With out == nullptr only counts (the estimate of terrain_budget's ShrinkSweepTests).
double RayWindings(const std::vector<RayEdge>& edges, const std::vector<IPoint>& points,
                   double max_work, std::vector<int>* out,
                   RayWindingsFill fill = RayWindingsFill::kAuto);

// The same sums by testing every edge against every point (the test twin).
std::vector<int> RayWindingsBruteForce(const std::vector<RayEdge>& edges,
                                       const std::vector<IPoint>& points);

}  // namespace niwa::terrain
