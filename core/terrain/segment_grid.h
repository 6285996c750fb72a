// Nearest-segment distance over a set of contour segments through a uniform bucket grid, exactly
// equal to the brute-force minimum (RingDistance): the heightfield's per-cell distances a and b.
// Does not: know contours' nesting or build surfaces (heightfield.h).
//
// Why not geom::Bvh: it holds triangles in 3-D (float) and answers closest-point on meshes; the
// heightfield needs the double distance bit-identical to polygon.h's SegmentDistance on 2-D rings
// with a coherent start (the previous cell's nearest segment), which a 60-line grid gives directly.
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/contour.h"

namespace niwa::terrain {

// polygon.cpp's SegmentDistance without the square root (sqrt is monotone and correctly rounded,
// so the root of the least square is the least root: the brute force's value, bit for bit).
inline double SegmentDist2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double ex = b.x - a.x, ey = b.y - a.y;
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2 : 0.0;
  t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
  const double dx = a.x + t * ex - p.x, dy = a.y + t * ey - p.y;
  return dx * dx + dy * dy;
}

class SegmentGrid {
 public:
  SegmentGrid() = default;
  // Adds every edge of the ring (closing edge included); call Build after the last ring.
  void AddRing(const Ring& ring);
  // min_bucket: the least bucket side (m). Queries far from every segment (the heightfield's, at
  // d and beyond) visit fewer buckets when they are about that distance wide.
  void Build(double min_bucket = 0);
  bool empty() const { return a_.empty(); }
  // min over segments of SegmentDistance(p, a, b); 1e300 when empty. `hint` (in/out, may be null)
  // is a segment index to start from (the last answer), which only changes the speed.
  double Distance(const Vec2& p, int* hint = nullptr) const;

 private:
  double Dist2(const Vec2& p, std::size_t s) const;
  std::vector<Vec2> a_, b_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<uint32_t> start_;  // nx·ny + 1 offsets into items_
  std::vector<uint32_t> items_;  // segment indices per bucket
};

}  // namespace niwa::terrain
