// Exact polygon predicates on the 1/1024 m grid (see polygon.h).
#include "terrain/polygon.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace niwa::terrain {

IPoint ToGrid(const Vec2& p) {
  return {static_cast<int64_t>(std::llround(p.x * kGridPerMetre)),
          static_cast<int64_t>(std::llround(p.y * kGridPerMetre))};
}
Vec2 FromGrid(const IPoint& p) {
  return {static_cast<double>(p.x) / kGridPerMetre, static_cast<double>(p.y) / kGridPerMetre};
}
IRing ToGrid(const Ring& ring) {
  IRing out;
  out.reserve(ring.size());
  for (const Vec2& p : ring) out.push_back(ToGrid(p));
  return out;
}
Ring FromGrid(const IRing& ring) {
  Ring out;
  out.reserve(ring.size());
  for (const IPoint& p : ring) out.push_back(FromGrid(p));
  return out;
}
Ring Snap(const Ring& ring) { return FromGrid(ToGrid(ring)); }

int Orient(const IPoint& a, const IPoint& b, const IPoint& c) {
  Int128 cross =
      static_cast<Int128>(b.x - a.x) * (c.y - a.y) - static_cast<Int128>(b.y - a.y) * (c.x - a.x);
  return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
}

Int128 TwiceArea(const IRing& ring) {
  Int128 sum = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint& a = ring[i];
    const IPoint& b = ring[(i + 1) % n];
    sum += static_cast<Int128>(a.x) * b.y - static_cast<Int128>(b.x) * a.y;
  }
  return sum;
}

double Area(const Ring& ring) {
  double sum = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    sum += a.x * b.y - b.x * a.y;
  }
  return 0.5 * sum;
}

double Perimeter(const Ring& ring) {
  double sum = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    sum += std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
  }
  return sum;
}

namespace {
bool OnSegment(const IPoint& a, const IPoint& b, const IPoint& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
}  // namespace

bool SegmentsIntersect(const IPoint& a, const IPoint& b, const IPoint& c, const IPoint& d) {
  const int o1 = Orient(a, b, c), o2 = Orient(a, b, d), o3 = Orient(c, d, a), o4 = Orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // a proper crossing
  if (o1 == 0 && OnSegment(a, b, c)) return true;
  if (o2 == 0 && OnSegment(a, b, d)) return true;
  if (o3 == 0 && OnSegment(c, d, a)) return true;
  if (o4 == 0 && OnSegment(c, d, b)) return true;
  return false;
}

namespace {
// Edges i and j of an n-ring meet in a way a simple ring forbids.
bool EdgesConflict(const IRing& r, std::size_t i, std::size_t j) {
  const std::size_t n = r.size();
  const IPoint &a = r[i], &b = r[(i + 1) % n], &c = r[j], &d = r[(j + 1) % n];
  const bool adjacent_next = (i + 1) % n == j;
  const bool adjacent_prev = (j + 1) % n == i;
  if (adjacent_next || adjacent_prev) {
    // Neighbours share one vertex; they conflict when they overlap (collinear, folding back).
    const IPoint& shared = adjacent_next ? b : a;
    const IPoint& p = adjacent_next ? a : b;  // the far end of edge i
    const IPoint& q = adjacent_next ? d : c;  // the far end of edge j
    if (Orient(p, shared, q) != 0) return false;
    // Collinear: a fold-back when the far ends lie on the same side of the shared vertex.
    const Int128 dot = static_cast<Int128>(p.x - shared.x) * (q.x - shared.x) +
                       static_cast<Int128>(p.y - shared.y) * (q.y - shared.y);
    return dot > 0;
  }
  return SegmentsIntersect(a, b, c, d);
}
}  // namespace

std::vector<std::pair<int, int>> SelfIntersectionsBruteForce(const IRing& ring) {
  std::vector<std::pair<int, int>> out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (EdgesConflict(ring, i, j)) out.push_back({static_cast<int>(i), static_cast<int>(j)});
  return out;
}

std::vector<std::pair<int, int>> SelfIntersections(const IRing& ring, int max_pairs,
                                                   SweepWork* work) {
  std::vector<std::pair<int, int>> out;
  const std::size_t n = ring.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto lo = [&](std::size_t i) { return std::min(ring[i].x, ring[(i + 1) % n].x); };
  auto hi = [&](std::size_t i) { return std::max(ring[i].x, ring[(i + 1) % n].x); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return lo(a) < lo(b) || (lo(a) == lo(b) && a < b);
  });
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t i = order[s];
    const int64_t end = hi(i);
    const int64_t ylo = std::min(ring[i].y, ring[(i + 1) % n].y);
    const int64_t yhi = std::max(ring[i].y, ring[(i + 1) % n].y);
    for (std::size_t t = s + 1; t < n && lo(order[t]) <= end; ++t) {
      const std::size_t j = order[t];
      if (SweepOver(work, kSweepWorkPerTry)) return out;
      if (std::max(ring[j].y, ring[(j + 1) % n].y) < ylo ||
          std::min(ring[j].y, ring[(j + 1) % n].y) > yhi)
        continue;
      if (SweepOver(work, 1.0)) return out;
      if (EdgesConflict(ring, i, j)) {
        out.push_back({static_cast<int>(std::min(i, j)), static_cast<int>(std::max(i, j))});
        if (static_cast<int>(out.size()) >= max_pairs) return out;
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool IsSimple(const IRing& ring, SweepWork* work) {
  if (ring.size() < 3) return false;
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (ring[i] == ring[(i + 1) % ring.size()]) return false;
  if (TwiceArea(ring) == 0) return false;
  IRing sorted = ring;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  return SelfIntersections(ring, 1, work).empty() && !(work != nullptr && work->stopped);
}

double SweepPairs(const IRing& ring, bool along_y) {
  // In the order of the low end, each edge with the later ones whose low end is within its range:
  // Σ_s #{t > s : lo(t) ≤ hi(s)} = Σ_i #{j : lo(j) ≤ hi(i)} − n(n + 1)/2 (any order of ties).
  const std::size_t n = ring.size();
  auto at = [&](std::size_t i) { return along_y ? ring[i].y : ring[i].x; };
  std::vector<int64_t> lo(n);
  for (std::size_t i = 0; i < n; ++i) lo[i] = std::min(at(i), at((i + 1) % n));
  std::sort(lo.begin(), lo.end());
  double pairs = 0;
  for (std::size_t i = 0; i < n; ++i)
    pairs += static_cast<double>(
        std::upper_bound(lo.begin(), lo.end(), std::max(at(i), at((i + 1) % n))) - lo.begin());
  const double m = static_cast<double>(n);
  return pairs - m * (m + 1) / 2;
}

double SimplicityPairs(const IRing& ring) {
  return std::min(SweepPairs(ring, false), SweepPairs(ring, true));
}

bool IsSimpleEitherAxis(const IRing& ring) {
  if (ring.size() < 3 || SweepPairs(ring, false) <= SweepPairs(ring, true)) return IsSimple(ring);
  IRing turned(ring.size());  // x and y swapped: a mirror, which keeps every meeting of edges
  for (std::size_t i = 0; i < ring.size(); ++i) turned[i] = {ring[i].y, ring[i].x};
  return IsSimple(turned);
}

bool RingsIntersect(const IRing& a, const IRing& b, SweepWork* work) {
  // Concatenated edges, sorted on x, tested only across the two rings.
  struct Edge {
    IPoint p, q;
    int owner;
  };
  std::vector<Edge> edges;
  edges.reserve(a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) edges.push_back({a[i], a[(i + 1) % a.size()], 0});
  for (std::size_t i = 0; i < b.size(); ++i) edges.push_back({b[i], b[(i + 1) % b.size()], 1});
  auto lo = [](const Edge& e) { return std::min(e.p.x, e.q.x); };
  std::sort(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) {
    return lo(x) < lo(y) ||
           (lo(x) == lo(y) && (x.owner < y.owner || (x.owner == y.owner && x.p < y.p)));
  });
  for (std::size_t s = 0; s < edges.size(); ++s) {
    const int64_t end = std::max(edges[s].p.x, edges[s].q.x);
    for (std::size_t t = s + 1; t < edges.size() && lo(edges[t]) <= end; ++t) {
      if (SweepOver(work, kSweepWorkPerTry)) return false;
      if (edges[t].owner == edges[s].owner) continue;
      if (SweepOver(work, 1.0)) return false;
      if (SegmentsIntersect(edges[s].p, edges[s].q, edges[t].p, edges[t].q)) return true;
    }
  }
  return false;
}

EdgeIndex::EdgeIndex(const IRing& ring) {
  const std::size_t n = ring.size();
  edges_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint& p = ring[i];
    const IPoint& q = ring[(i + 1) % n];
    edges_.push_back({std::min(p.x, q.x), std::max(p.x, q.x), p, q});
    widest_ = std::max(widest_, edges_.back().hi - edges_.back().lo);
  }
  std::sort(edges_.begin(), edges_.end(), [](const Edge& a, const Edge& b) {
    return a.lo < b.lo || (a.lo == b.lo && (a.p < b.p || (a.p == b.p && a.q < b.q)));
  });
}

bool EdgeIndex::Meets(const IRing& other, SweepWork* work) const {
  const std::size_t n = other.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint& p = other[i];
    const IPoint& q = other[(i + 1) % n];
    const int64_t lo = std::min(p.x, q.x), hi = std::max(p.x, q.x);
    if (SweepOver(work, kSweepWorkPerTry)) return false;  // the search
    auto it = std::lower_bound(edges_.begin(), edges_.end(), lo - widest_,
                               [](const Edge& e, int64_t x) { return e.lo < x; });
    for (; it != edges_.end() && it->lo <= hi; ++it) {
      if (SweepOver(work, kSweepWorkPerTry)) return false;
      if (it->hi < lo) continue;
      if (SweepOver(work, 1.0)) return false;
      if (SegmentsIntersect(p, q, it->p, it->q)) return true;
    }
  }
  return false;
}

IBox BoxOf(const IRing& ring) {
  IBox b;
  if (ring.empty()) return b;
  b = {ring[0].x, ring[0].y, ring[0].x, ring[0].y};
  for (const IPoint& q : ring) {
    b.x0 = std::min(b.x0, q.x);
    b.y0 = std::min(b.y0, q.y);
    b.x1 = std::max(b.x1, q.x);
    b.y1 = std::max(b.y1, q.y);
  }
  return b;
}

std::vector<std::pair<int, int>> MeetingBoxPairs(const std::vector<IBox>& boxes) {
  std::vector<int> order(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const int64_t xa = boxes[static_cast<std::size_t>(a)].x0;
    const int64_t xb = boxes[static_cast<std::size_t>(b)].x0;
    return xa < xb || (xa == xb && a < b);
  });
  std::vector<std::pair<int, int>> out;
  for (std::size_t s = 0; s < order.size(); ++s) {
    const IBox& a = boxes[static_cast<std::size_t>(order[s])];
    for (std::size_t t = s + 1;
         t < order.size() && boxes[static_cast<std::size_t>(order[t])].x0 <= a.x1; ++t) {
      if (BoxesMeet(a, boxes[static_cast<std::size_t>(order[t])]))
        out.push_back({std::min(order[s], order[t]), std::max(order[s], order[t])});
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool Inside(const IRing& ring, const IPoint& p) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint& a = ring[i];
    const IPoint& b = ring[(i + 1) % n];
    if (Orient(a, b, p) == 0 && OnSegment(a, b, p)) return false;
    if ((a.y > p.y) != (b.y > p.y)) {
      // Crossing of the ray to +x: p is left of the upward edge (or right of a downward one).
      const int o = Orient(a, b, p);
      if ((b.y > a.y) ? o > 0 : o < 0) inside = !inside;
    }
  }
  return inside;
}

bool InsideDouble(const Ring& ring, const Vec2& p) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x;
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

double SegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double ex = b.x - a.x, ey = b.y - a.y;
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = a.x + t * ex - p.x, dy = a.y + t * ey - p.y;
  return std::sqrt(dx * dx + dy * dy);
}

double RingDistance(const Ring& ring, const Vec2& p) {
  double best = 1e300;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    best = std::min(best, SegmentDistance(p, ring[i], ring[(i + 1) % n]));
  return best;
}

}  // namespace niwa::terrain
