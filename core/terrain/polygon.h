// Exact polygon predicates on the 1/1024 m grid: snapping, orientation, signed area, segment
// intersection, simplicity, point-in-ring, distances. Written here because no header-only library
// that builds for both targets gives exact integer predicates (Clipper is native-only in Debian);
// each routine is checked against a brute-force twin in tests/terrain/polygon_test.cpp.
// Does not: offset, union or perturb (core/terrain/offset, generate).
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/contour.h"

namespace niwa::terrain {

__extension__ typedef __int128 Int128;

struct IPoint {
  int64_t x = 0, y = 0;
  bool operator==(const IPoint& o) const { return x == o.x && y == o.y; }
  bool operator!=(const IPoint& o) const { return !(*this == o); }
  bool operator<(const IPoint& o) const { return x < o.x || (x == o.x && y < o.y); }
};
using IRing = std::vector<IPoint>;

// Largest coordinate accepted (m): keeps every product exact in __int128.
constexpr double kMaxCoordinate = 1e6;

IPoint ToGrid(const Vec2& p);
Vec2 FromGrid(const IPoint& p);
IRing ToGrid(const Ring& ring);
Ring FromGrid(const IRing& ring);
// The ring snapped onto the grid (Vec2 values that are exact multiples of 1/1024).
Ring Snap(const Ring& ring);

// Sign of the cross product (b − a) × (c − a): +1 left turn, −1 right turn, 0 collinear.
int Orient(const IPoint& a, const IPoint& b, const IPoint& c);
// Twice the signed area (positive for counter-clockwise).
Int128 TwiceArea(const IRing& ring);
double Area(const Ring& ring);  // signed, m²
double Perimeter(const Ring& ring);

// Closed segments ab and cd share at least one point.
bool SegmentsIntersect(const IPoint& a, const IPoint& b, const IPoint& c, const IPoint& d);
// The work of the sweeps below counted against a budget, in offset.h ShrinkCounts::sweep_tests's
// units (a pair tried kSweepWorkPerTry, an exact test 1): past max_tests (≥ 0) a sweep stops at
// once with `stopped`, and its answer means nothing (the caller stops too). The grow counts the
// perturbation's checks so (issue 34: they were the last uncounted sweeps of a grow).
struct SweepWork {
  double tests = 0;
  double max_tests = -1;
  bool stopped = false;
};
// A pair of segments a sweep tries (their x ranges overlap), most rejected on y: a few ns.
inline constexpr double kSweepWorkPerTry = 0.1;
// Adds `amount` to `work` (when counted); true once past its most (then work->stopped).
inline bool SweepOver(SweepWork* work, double amount) {
  if (work == nullptr) return false;
  work->tests += amount;
  if (work->max_tests < 0 || work->tests <= work->max_tests) return false;
  work->stopped = true;
  return true;
}

// Index pairs (i, j), i < j, of ring edges (edge i = p_i -> p_{i+1}) that meet other than at the
// shared vertex of two neighbouring edges. A sort on x prunes the pairs. With `work`, counted
// (and stopped past its most).
std::vector<std::pair<int, int>> SelfIntersections(const IRing& ring, int max_pairs = 1 << 30,
                                                   SweepWork* work = nullptr);
std::vector<std::pair<int, int>> SelfIntersectionsBruteForce(const IRing& ring);
// At least 3 distinct points, no repeated vertex, no two edges meeting except neighbours at
// their shared vertex, non-zero area.
bool IsSimple(const IRing& ring, SweepWork* work = nullptr);
// The pairs of edges SelfIntersections' sweep tries (their x ranges overlap; with along_y, their
// y ranges), counted by a sort in O(n log n) without trying them.
double SweepPairs(const IRing& ring, bool along_y);
// IsSimple with its sweep along x or y, whichever tries fewer pairs: the same answer (a crossing
// pair overlaps on both axes), linear where a ring's edges stack across one x range (a comb
// turned on its side: quadratic along x). For seeds (generate.h CheckSeed).
bool IsSimpleEitherAxis(const IRing& ring);
// The pairs IsSimpleEitherAxis would try (the fewer of SweepPairs along x and y), and the most a
// seed's check or repair may try: about a second of exact tests. Only edges that overlap on both
// axes in their thousands (long diagonal teeth) come near it; a drawn or surveyed contour of a
// million points tries a few million.
double SimplicityPairs(const IRing& ring);
constexpr double kMaxSimplicityPairs = 2e8;
// Any edge of a meets any edge of b. With `work`, counted (and stopped past its most).
bool RingsIntersect(const IRing& a, const IRing& b, SweepWork* work = nullptr);

// A ring's edges sorted on x, to test many small rings against one large one (a parent and its
// children): RingsIntersect's answer, trying only the edges whose x ranges overlap (RingsIntersect
// sorts both rings' edges for every pair: children × parent). Tested against it
// (polygon_test.cpp).
class EdgeIndex {
 public:
  explicit EdgeIndex(const IRing& ring);
  // RingsIntersect(ring, other). With `work`, counted (and stopped past its most).
  bool Meets(const IRing& other, SweepWork* work = nullptr) const;

 private:
  struct Edge {
    int64_t lo, hi;  // x range
    IPoint p, q;
  };
  std::vector<Edge> edges_;  // in the order of lo
  int64_t widest_ = 0;       // the widest x range (the search's margin)
};

// A grid ring's bounding box (closed). Two rings whose boxes do not meet neither intersect nor
// hold a point of each other, so the nesting checks of many rings test only the pairs whose boxes
// meet (siblings by the thousand were quadratic in their count).
struct IBox {
  int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};
IBox BoxOf(const IRing& ring);
inline bool BoxesMeet(const IBox& a, const IBox& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}
// The pairs (i, j), i < j, of `boxes` that meet, sorted: a sweep on x (O(n log n + pairs tried)).
// Why not a library: a sort and a scan; tested against the all-pairs twin (polygon_test.cpp).
std::vector<std::pair<int, int>> MeetingBoxPairs(const std::vector<IBox>& boxes);
// Point strictly inside (crossing rule; points on the boundary count as outside).
bool Inside(const IRing& ring, const IPoint& p);
bool InsideDouble(const Ring& ring, const Vec2& p);  // for cell centres (not on the grid)

// Distance from p to segment ab, and to a ring's boundary.
double SegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b);
double RingDistance(const Ring& ring, const Vec2& p);

}  // namespace niwa::terrain
