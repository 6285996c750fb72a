// Polygon shrinking (Figs 5-8) and the positive-winding union (Fig 6 steps 3-4); see offset.h.
#include "terrain/offset.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "math/det_math.h"
#include "terrain/ray_windings.h"

namespace niwa::terrain {
namespace {

struct Seg {
  IPoint a, b;
};

bool OnSeg(const IPoint& a, const IPoint& b, const IPoint& p) {
  return Orient(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

constexpr double kWorkPerSplit = kSweepWorkPerSplit;  // offset.h

// Adds `work` to counts->sweep_tests; true (and counts->stopped) once past the most allowed.
bool OverSweepBudget(double work, ShrinkCounts* counts) {
  if (counts == nullptr) return false;
  counts->sweep_tests += work;
  if (counts->max_sweep_tests < 0 || counts->sweep_tests <= counts->max_sweep_tests) return false;
  counts->stopped = true;
  return true;
}

// Splits every segment at the points where it meets another (crossings rounded onto the grid),
// repeated while rounding makes new crossings (at most a few passes). Empty with
// counts->stopped when the split points pass the sweep budget.
std::vector<Seg> SplitAtIntersections(std::vector<Seg> segs, ShrinkCounts* counts) {
  for (int pass = 0; pass < 6; ++pass) {
    const std::size_t n = segs.size();
    std::vector<std::vector<IPoint>> splits(n);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    auto lo = [&](std::size_t i) { return std::min(segs[i].a.x, segs[i].b.x); };
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return lo(x) < lo(y) || (lo(x) == lo(y) && x < y);
    });
    bool any = false;
    std::size_t found = 0;  // split points found by the segments before this one
    std::size_t tried = 0;  // and the pairs they tried
    for (std::size_t s = 0; s < n; ++s) {
      if ((found > 0 || tried > 0) &&
          OverSweepBudget(kWorkPerSplit * static_cast<double>(found) +
                              kSweepWorkPerTry * static_cast<double>(tried),
                          counts))
        return {};
      found = 0;
      tried = 0;
      const std::size_t i = order[s];
      const Seg& si = segs[i];
      const int64_t end = std::max(si.a.x, si.b.x);
      const int64_t ylo = std::min(si.a.y, si.b.y), yhi = std::max(si.a.y, si.b.y);
      for (std::size_t t = s + 1; t < n && lo(order[t]) <= end; ++t) {
        ++tried;
        const std::size_t j = order[t];
        const Seg& sj = segs[j];
        if (std::max(sj.a.y, sj.b.y) < ylo || std::min(sj.a.y, sj.b.y) > yhi) continue;
        if (!SegmentsIntersect(si.a, si.b, sj.a, sj.b)) continue;
        // Endpoints of one lying inside the other.
        auto add_if_inside = [&](const Seg& host, std::size_t h, const IPoint& p) {
          if (p != host.a && p != host.b && OnSeg(host.a, host.b, p)) {
            splits[h].push_back(p);
            ++found;
            any = true;
          }
        };
        add_if_inside(si, i, sj.a);
        add_if_inside(si, i, sj.b);
        add_if_inside(sj, j, si.a);
        add_if_inside(sj, j, si.b);
        const int o1 = Orient(si.a, si.b, sj.a), o2 = Orient(si.a, si.b, sj.b);
        const int o3 = Orient(sj.a, sj.b, si.a), o4 = Orient(sj.a, sj.b, si.b);
        if (o1 * o2 < 0 && o3 * o4 < 0) {
          const double ax = static_cast<double>(si.a.x), ay = static_cast<double>(si.a.y);
          const double rx = static_cast<double>(si.b.x - si.a.x);
          const double ry = static_cast<double>(si.b.y - si.a.y);
          const double sx = static_cast<double>(sj.b.x - sj.a.x);
          const double sy = static_cast<double>(sj.b.y - sj.a.y);
          const double qx = static_cast<double>(sj.a.x) - ax, qy = static_cast<double>(sj.a.y) - ay;
          const double den = rx * sy - ry * sx;
          const double tpar = (qx * sy - qy * sx) / den;
          IPoint p{static_cast<int64_t>(std::llround(ax + tpar * rx)),
                   static_cast<int64_t>(std::llround(ay + tpar * ry))};
          if (p != si.a && p != si.b) splits[i].push_back(p);
          if (p != sj.a && p != sj.b) splits[j].push_back(p);
          found += 2;
          any = true;
        }
      }
    }
    if ((found > 0 || tried > 0) &&
        OverSweepBudget(kWorkPerSplit * static_cast<double>(found) +
                            kSweepWorkPerTry * static_cast<double>(tried),
                        counts))
      return {};
    if (!any) break;
    std::vector<Seg> out;
    out.reserve(n * 2);
    for (std::size_t i = 0; i < n; ++i) {
      if (splits[i].empty()) {
        out.push_back(segs[i]);
        continue;
      }
      const Seg& s = segs[i];
      std::vector<IPoint>& pts = splits[i];
      const int64_t dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
      auto key = [&](const IPoint& p) {
        return static_cast<Int128>(p.x - s.a.x) * dx + static_cast<Int128>(p.y - s.a.y) * dy;
      };
      std::sort(pts.begin(), pts.end(), [&](const IPoint& p, const IPoint& q) {
        const Int128 kp = key(p), kq = key(q);
        return kp < kq || (kp == kq && p < q);
      });
      pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
      IPoint prev = s.a;
      for (const IPoint& p : pts) {
        if (p != prev) out.push_back({prev, p});
        prev = p;
      }
      if (prev != s.b) out.push_back({prev, s.b});
    }
    segs.swap(out);
  }
  return segs;
}

struct WEdge {
  IPoint a, b;  // a < b
  int weight;   // net number of path edges a -> b minus b -> a: left winding = right + weight
};

// The winding numbers just beside the midpoints of the edges, on the +x side of a sloped edge and
// the +y side of a horizontal one (Sunday's crossing rule on doubled coordinates, a +y ray being a
// +x ray with x and y swapped and the weights negated), through ray_windings.h's grid: the same
// integers as testing every edge against every midpoint. Adds the work to counts->sweep_tests and
// returns false (counts->stopped) once it passes counts->max_sweep_tests.
// With beside == nullptr only counts the work (UnionSweepWork).
bool WindingsBeside(const std::vector<WEdge>& edges, std::vector<int>* beside,
                    ShrinkCounts* counts) {
  if (beside != nullptr) beside->assign(edges.size(), 0);
  for (const bool vertical_ray : {false, true}) {
    auto frame = [&](const IPoint& p) { return vertical_ray ? IPoint{p.y, p.x} : p; };
    std::vector<RayEdge> rays;
    std::vector<IPoint> points;
    std::vector<std::size_t> which;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const WEdge& f = edges[i];
      const IPoint a = frame({2 * f.a.x, 2 * f.a.y}), b = frame({2 * f.b.x, 2 * f.b.y});
      const int w = vertical_ray ? -f.weight : f.weight;
      if (a.y < b.y) rays.push_back({a, b, w});
      if (a.y > b.y) rays.push_back({b, a, -w});
      if ((f.a.y == f.b.y) == vertical_ray) {
        points.push_back(frame({f.a.x + f.b.x, f.a.y + f.b.y}));
        which.push_back(i);
      }
    }
    double max_work = -1;
    if (counts != nullptr && counts->max_sweep_tests >= 0)
      max_work = std::max(0.0, counts->max_sweep_tests - counts->sweep_tests);
    std::vector<int> sums;
    const double work = RayWindings(rays, points, max_work, beside ? &sums : nullptr);
    if (counts != nullptr) {
      counts->sweep_tests += work;
      if (max_work >= 0 && work > max_work) {
        counts->stopped = true;
        return false;
      }
    }
    if (beside != nullptr)
      for (std::size_t k = 0; k < which.size(); ++k) (*beside)[which[k]] = sums[k];
  }
  return true;
}

// Relative turn order at a vertex: true when w2 turns further left than w1 from direction u.
bool TurnsMoreLeft(const IPoint& u, const IPoint& w1, const IPoint& w2) {
  auto half = [&](const IPoint& w) {
    const Int128 cross = static_cast<Int128>(u.x) * w.y - static_cast<Int128>(u.y) * w.x;
    const Int128 dot = static_cast<Int128>(u.x) * w.x + static_cast<Int128>(u.y) * w.y;
    return (cross > 0 || (cross == 0 && dot < 0)) ? 1 : 0;
  };
  const int h1 = half(w1), h2 = half(w2);
  if (h1 != h2) return h2 > h1;
  const Int128 c = static_cast<Int128>(w1.x) * w2.y - static_cast<Int128>(w1.y) * w2.x;
  return c > 0;
}

// Repeated points and collinear ones dropped; with keep_straight only those where the ring turns
// back on itself (a spike), the points of a straight run kept.
IRing CleanRing(IRing r, bool keep_straight = false) {
  bool changed = true;
  while (changed && r.size() >= 3) {
    changed = false;
    IRing out;
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
      const IPoint& prev = out.empty() ? r[(i + n - 1) % n] : out.back();
      const IPoint& cur = r[i];
      const IPoint& next = r[(i + 1) % n];
      const auto straight = [&] {
        const Int128 dot = static_cast<Int128>(cur.x - prev.x) * (next.x - cur.x) +
                           static_cast<Int128>(cur.y - prev.y) * (next.y - cur.y);
        return keep_straight && dot > 0;
      };
      if (cur == prev || (Orient(prev, cur, next) == 0 && !straight())) {
        changed = true;
        continue;
      }
      out.push_back(cur);
    }
    r.swap(out);
  }
  return r;
}

std::vector<Ring> UnionOnce(const std::vector<IRing>& paths, ShrinkCounts* counts, int depth,
                            bool keep_straight = false);

std::vector<Ring> UnionOnce(const std::vector<IRing>& paths, ShrinkCounts* counts, int depth,
                            bool keep_straight) {
  std::vector<Seg> segs;
  for (const IRing& p : paths)
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p[i] != p[(i + 1) % p.size()]) segs.push_back({p[i], p[(i + 1) % p.size()]});
  segs = SplitAtIntersections(std::move(segs), counts);
  if (counts != nullptr && counts->stopped) return {};
  // Merge coincident edges into one weighted edge.
  std::map<std::pair<IPoint, IPoint>, int> merged;
  for (const Seg& s : segs) {
    if (s.a < s.b) {
      merged[{s.a, s.b}] += 1;
    } else {
      merged[{s.b, s.a}] -= 1;
    }
  }
  std::vector<WEdge> edges;
  for (const auto& [key, w] : merged)
    if (w != 0) edges.push_back({key.first, key.second, w});
  // Keep the edges between winding ≥ 1 and winding < 1, directed with the inside on the left.
  std::vector<int> beside;
  if (!WindingsBeside(edges, &beside, counts)) return {};
  std::vector<Seg> kept;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const WEdge& e = edges[i];
    const int64_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
    const int w = beside[i];
    int left = 0, right = 0;
    if (dy != 0) {
      if (dy > 0) {
        right = w;
        left = w + e.weight;
      } else {
        left = w;
        right = w - e.weight;
      }
    } else {
      if (dx > 0) {
        left = w;
        right = w - e.weight;
      } else {
        right = w;
        left = w + e.weight;
      }
    }
    const bool in_left = left >= 1, in_right = right >= 1;
    if (in_left && !in_right) kept.push_back({e.a, e.b});
    if (in_right && !in_left) kept.push_back({e.b, e.a});
  }
  // Chain the kept edges into rings, turning furthest left at shared vertices.
  std::multimap<IPoint, std::size_t> outgoing;
  for (std::size_t i = 0; i < kept.size(); ++i) outgoing.insert({kept[i].a, i});
  std::vector<bool> used(kept.size(), false);
  std::vector<Ring> result;
  for (std::size_t start = 0; start < kept.size(); ++start) {
    if (used[start]) continue;
    used[start] = true;
    IRing ring{kept[start].a};
    std::size_t cur = start;
    bool closed = false;
    for (std::size_t guard = 0; guard <= kept.size(); ++guard) {
      const IPoint v = kept[cur].b;
      const IPoint u{kept[cur].b.x - kept[cur].a.x, kept[cur].b.y - kept[cur].a.y};
      std::size_t best = kept.size();
      auto range = outgoing.equal_range(v);
      for (auto it = range.first; it != range.second; ++it) {
        const std::size_t cand = it->second;
        if (used[cand] && cand != start) continue;
        if (best == kept.size()) {
          best = cand;
          continue;
        }
        const IPoint w1{kept[best].b.x - v.x, kept[best].b.y - v.y};
        const IPoint w2{kept[cand].b.x - v.x, kept[cand].b.y - v.y};
        if (TurnsMoreLeft(u, w1, w2)) best = cand;
      }
      if (best == kept.size()) break;
      if (best == start) {
        closed = true;
        break;
      }
      used[best] = true;
      ring.push_back(v);
      cur = best;
    }
    if (!closed) {
      if (counts) ++counts->dropped_rings;
      continue;
    }
    ring = CleanRing(std::move(ring), keep_straight);
    if (ring.size() < 3) continue;
    const Int128 area = TwiceArea(ring);
    if (area <= 0) {
      if (area < 0 && counts) ++counts->holes_filled;
      continue;
    }
    if (!IsSimple(ring)) {
      if (depth < 2) {
        std::vector<Ring> again = UnionOnce({ring}, counts, depth + 1, keep_straight);
        if (counts != nullptr && counts->stopped) return {};
        result.insert(result.end(), again.begin(), again.end());
      } else if (counts) {
        ++counts->dropped_rings;
      }
      continue;
    }
    result.push_back(FromGrid(ring));
  }
  return result;
}

Vec2 Sub(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
double Len(const Vec2& a) { return std::sqrt(a.x * a.x + a.y * a.y); }
Vec2 LeftNormal(const Vec2& a, const Vec2& b) {
  const Vec2 e = Sub(b, a);
  const double l = Len(e);
  return {-e.y / l, e.x / l};
}

}  // namespace

Vec2 CappedJoinPoint(const Vec2& v, const Vec2& n1, const Vec2& n2, double d, double c) {
  const Vec2 s{n1.x + n2.x, n1.y + n2.y};
  const double len = Len(s);  // = 2·cos(ψ/2)
  if (len < 1e-12) {
    // ψ = 180°: the bisector is the incoming edge's direction (n1 turned right by 90°).
    return {v.x + c * d * n1.y, v.y - c * d * n1.x};
  }
  const double cos_half = 0.5 * len;
  const double dist = std::min(c * d, d / cos_half);  // Fig 7: min(c·d, d/cos(ψ/2))
  return {v.x + dist * s.x / len, v.y + dist * s.y / len};
}

Ring Normalise(const Ring& ring, bool keep_straight) {
  IRing r = ToGrid(ring);
  r = CleanRing(std::move(r), keep_straight);
  if (r.size() >= 3 && TwiceArea(r) < 0) std::reverse(r.begin(), r.end());
  return FromGrid(r);
}

Ring PreClean(const Ring& ring, double min_len, double min_angle_deg, int* dropped) {
  // The ring as a doubly linked list over its points (next/prev indices), so a drop is O(1): the
  // vector's erase made a dense contour quadratic (a 200,000-point circle: 5.5 s of CPU before any
  // budget). The walk is the vector's own, step for step: `cur` is the point at index `pos` of the
  // remaining ring, `head` its index 0, and the same points are dropped in the same order.
  const std::size_t total = ring.size();
  const double min_angle = min_angle_deg * 3.14159265358979323846 / 180.0;
  std::vector<std::size_t> next(total), prev(total);
  for (std::size_t i = 0; i < total; ++i) {
    next[i] = (i + 1) % total;
    prev[i] = (i + total - 1) % total;
  }
  std::size_t head = 0, size = total;
  for (std::size_t pass = 0; pass < total && size > 3; ++pass) {
    bool changed = false;
    std::size_t cur = head;
    for (std::size_t pos = 0; pos < size && size > 3;) {
      const Vec2& before = ring[prev[cur]];
      const Vec2& at = ring[cur];
      const Vec2& after = ring[next[cur]];
      const Vec2 e1 = Sub(at, before), e2 = Sub(after, at);
      const double l1 = Len(e1), l2 = Len(e2);
      bool drop = l2 < min_len && min_len > 0;  // drop the end point of a very short edge
      bool drop_cur = false;
      if (!drop && min_angle > 0 && l1 > 0 && l2 > 0) {
        // Interior (or exterior) angle at cur below the limit: an acute spike or notch.
        const double cosang = -(e1.x * e2.x + e1.y * e2.y) / (l1 * l2);
        const double angle = det::Acos(std::clamp(cosang, -1.0, 1.0));  // in [0, π]
        if (angle < min_angle) {
          drop = true;
          drop_cur = true;
        }
      }
      if (!drop) {
        cur = next[cur];
        ++pos;
        continue;
      }
      const std::size_t victim = drop_cur ? cur : next[cur];
      const bool wrapped = !drop_cur && pos + 1 == size;  // the vector's victim index 0 < pos
      next[prev[victim]] = next[victim];
      prev[next[victim]] = prev[victim];
      if (victim == head) head = next[victim];
      --size;
      if (dropped) ++*dropped;
      changed = true;
      if (drop_cur) cur = next[victim];  // the next point takes its index
      if (wrapped) --pos;                // the same point, one index lower
    }
    if (!changed) break;
  }
  Ring r;
  r.reserve(size);
  for (std::size_t k = 0, i = head; k < size; ++k, i = next[i]) r.push_back(ring[i]);
  return r;
}

namespace {

// The points strictly between A1 = V + d·u1 and A2 = V + d·u2 that close the gap at a vertex
// whose offset side normals are u1 (incoming edge) and u2 (outgoing edge).
void JoinPoints(const Vec2& v, const Vec2& u1, const Vec2& u2, const ShrinkOptions& o, Ring* out) {
  switch (o.join) {
    case Join::kBevel:
      return;
    case Join::kMiter:
    case Join::kCapped:
      out->push_back(CappedJoinPoint(v, u1, u2, o.d, o.join == Join::kMiter ? kMiterLimit : o.c));
      return;
    case Join::kRound: {
      // Arc of radius d around V from u1 to u2 (chord sagitta ≤ 1 % of d).
      const double cross = u1.x * u2.y - u1.y * u2.x;
      const double dot = u1.x * u2.x + u1.y * u2.y;
      const double psi = det::Atan2(cross, dot);  // signed
      const double step = 2.0 * det::Acos(1.0 - 0.01);
      const int m = std::max(1, static_cast<int>(std::ceil(std::fabs(psi) / step)));
      for (int k = 1; k < m; ++k) {
        double s, co;
        det::SinCos(psi * k / m, &s, &co);
        out->push_back({v.x + o.d * (co * u1.x - s * u1.y), v.y + o.d * (s * u1.x + co * u1.y)});
      }
      return;
    }
  }
}

Ring Oriented(Ring r, bool ccw) {
  if ((Area(r) > 0) != ccw) std::reverse(r.begin(), r.end());
  return r;
}

}  // namespace

Ring RawOffsetPath(const Ring& ring, const ShrinkOptions& o) {
  const std::size_t n = ring.size();
  const double side = o.outward ? -1.0 : 1.0;
  const IRing g = ToGrid(ring);
  // Per vertex: the offset side normals, whether a gap opens, and how far the crossing of the two
  // overlapping offset edges lies from A1 and A2 along them (d·tan(α/2), 0 at a gap vertex).
  std::vector<Vec2> u(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 nn = LeftNormal(ring[i], ring[(i + 1) % n]);
    u[i] = {side * nn.x, side * nn.y};
  }
  std::vector<double> shift(n, 0.0);
  std::vector<bool> gap(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& u1 = u[(i + n - 1) % n];
    const Vec2& u2 = u[i];
    const int turn = Orient(g[(i + n - 1) % n], g[i], g[(i + 1) % n]);
    gap[i] = o.outward ? turn > 0 : turn < 0;
    if (!gap[i]) {
      const double cosang = u1.x * u2.x + u1.y * u2.y;
      const double sinang = std::fabs(u1.x * u2.y - u1.y * u2.x);
      shift[i] = cosang > -1 + 1e-12 ? o.d * sinang / (1 + cosang) : 1e300;
    }
  }
  auto edge_len = [&](std::size_t i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
  };
  Ring path;
  path.reserve(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t ip = (i + n - 1) % n, in = (i + 1) % n;
    const Vec2& v = ring[i];
    const Vec2& u1 = u[ip];
    const Vec2& u2 = u[i];
    const double cosang = u1.x * u2.x + u1.y * u2.y;
    if (!gap[i] && cosang > 0 && edge_len(ip) > shift[ip] + shift[i] &&
        edge_len(i) > shift[i] + shift[in]) {
      // The two offset edges overlap (Fig 2(b)) and both keep a positive length after the cut:
      // their crossing V + d·(u1 + u2)/(1 + u1·u2) replaces A1, A2 and the tail between, which is
      // a clockwise loop the union drops anyway (and sub-grid when the turn is small).
      const double k = o.d / (1 + cosang);
      path.push_back({v.x + k * (u1.x + u2.x), v.y + k * (u1.y + u2.y)});
      continue;
    }
    path.push_back({v.x + o.d * u1.x, v.y + o.d * u1.y});
    // The gap of Fig 2(a) opens at a reflex vertex when shrinking, at a convex one when enlarging.
    if (gap[i]) JoinPoints(v, u1, u2, o, &path);
    path.push_back({v.x + o.d * u2.x, v.y + o.d * u2.y});
  }
  return path;
}

// The region swept within d of the ring on the offset side, as pieces: one rectangle per edge and
// one join wedge V, A1, join points, A2 per gap vertex. Shrinking keeps the ring minus these
// (winding: ring +1, pieces −1), enlarging the ring plus these (all +1).
std::vector<Ring> SweptPieces(const Ring& ring, const ShrinkOptions& o) {
  const std::size_t n = ring.size();
  const double side = o.outward ? -1.0 : 1.0;
  const IRing g = ToGrid(ring);
  std::vector<Ring> pieces;
  pieces.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    const Vec2 nn = LeftNormal(a, b);
    const Vec2 u{side * nn.x, side * nn.y};
    pieces.push_back(Oriented(
        {a, b, {b.x + o.d * u.x, b.y + o.d * u.y}, {a.x + o.d * u.x, a.y + o.d * u.y}}, o.outward));
    const Vec2& prev = ring[(i + n - 1) % n];
    const int turn = Orient(g[(i + n - 1) % n], g[i], g[(i + 1) % n]);
    if (o.outward ? turn > 0 : turn < 0) {
      const Vec2 n1 = LeftNormal(prev, a);
      const Vec2 u1{side * n1.x, side * n1.y};
      Ring wedge{a, {a.x + o.d * u1.x, a.y + o.d * u1.y}};
      JoinPoints(a, u1, u, o, &wedge);
      wedge.push_back({a.x + o.d * u.x, a.y + o.d * u.y});
      if (wedge.size() >= 3) pieces.push_back(Oriented(wedge, o.outward));
    }
  }
  return pieces;
}

double UnionSweepWork(const Ring& ring) {
  const IRing g = ToGrid(ring);
  std::vector<WEdge> edges;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const IPoint& a = g[i];
    const IPoint& b = g[(i + 1) % g.size()];
    if (a != b) edges.push_back(a < b ? WEdge{a, b, 1} : WEdge{b, a, -1});
  }
  ShrinkCounts counts;
  WindingsBeside(edges, nullptr, &counts);
  return counts.sweep_tests;
}

namespace {

// Pairs of segments whose x ranges overlap (closed), as SplitAtIntersections tries them: in the
// order of low x, each segment with the later ones whose low x is within its range, so
// Σ_s #{t > s : lo(t) ≤ hi(s)} = Σ_i #{j : lo(j) ≤ hi(i)} − n(n + 1)/2 (ties among equal lows
// give the same sum in any order).
double TriedPairs(const std::vector<Seg>& segs) {
  std::vector<int64_t> lo(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) lo[i] = std::min(segs[i].a.x, segs[i].b.x);
  std::sort(lo.begin(), lo.end());
  double pairs = 0;
  for (const Seg& s : segs)
    pairs += static_cast<double>(std::upper_bound(lo.begin(), lo.end(), std::max(s.a.x, s.b.x)) -
                                 lo.begin());
  const double n = static_cast<double>(segs.size());
  return pairs - n * (n + 1) / 2;
}

// Pairs of segments whose closed bounding boxes overlap: a sweep over x (boxes opening before
// those closing at the same x), each opening box counting the open ones whose y range meets its
// own (all open, less those wholly below or wholly above it: two Fenwick trees over y).
double BoxPairs(const std::vector<Seg>& segs) {
  const std::size_t n = segs.size();
  std::vector<int64_t> ys;
  ys.reserve(2 * n);
  for (const Seg& s : segs) {
    ys.push_back(s.a.y);
    ys.push_back(s.b.y);
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<std::pair<std::size_t, std::size_t>> ranks(n);  // of each box's y0 and y1
  for (std::size_t i = 0; i < n; ++i) {
    auto rank = [&](int64_t y) {
      return static_cast<std::size_t>(std::lower_bound(ys.begin(), ys.end(), y) - ys.begin());
    };
    ranks[i] = {rank(std::min(segs[i].a.y, segs[i].b.y)), rank(std::max(segs[i].a.y, segs[i].b.y))};
  }
  std::vector<int64_t> top(ys.size() + 1, 0), bottom(ys.size() + 1, 0);  // by y1 and by y0
  auto add = [](std::vector<int64_t>& f, std::size_t i, int64_t v) {
    for (++i; i < f.size(); i += i & (~i + 1)) f[i] += v;
  };
  auto below = [](const std::vector<int64_t>& f, std::size_t i) {  // entries with rank < i
    int64_t s = 0;
    for (; i > 0; i -= i & (~i + 1)) s += f[i];
    return s;
  };
  struct Event {
    int64_t x;
    int closing;  // 0 opens, 1 closes
    std::size_t seg;
  };
  std::vector<Event> events;
  events.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    events.push_back({std::min(segs[i].a.x, segs[i].b.x), 0, i});
    events.push_back({std::max(segs[i].a.x, segs[i].b.x), 1, i});
  }
  std::sort(events.begin(), events.end(), [](const Event& p, const Event& q) {
    return p.x < q.x ||
           (p.x == q.x && (p.closing < q.closing || (p.closing == q.closing && p.seg < q.seg)));
  });
  double pairs = 0;
  int64_t open = 0;
  for (const Event& e : events) {
    const auto [y0, y1] = ranks[e.seg];
    if (e.closing == 0) {
      // Open boxes wholly below (top < y0) or wholly above (bottom > y1) miss this one.
      const int64_t miss = below(top, y0) + (open - below(bottom, y1 + 1));
      pairs += static_cast<double>(open - miss);
      add(top, y1, 1);
      add(bottom, y0, 1);
      ++open;
    } else {
      add(top, y1, -1);
      add(bottom, y0, -1);
      --open;
    }
  }
  return pairs;
}

}  // namespace

double TriedEdgePairs(const Ring& ring) {
  const IRing g = ToGrid(ring);
  return std::min(SweepPairs(g, false), SweepPairs(g, true));  // IsSimpleEitherAxis
}

SplitForecast ForecastSplits(const Ring& ring, const ShrinkOptions& o) {
  // As Shrink: the pre-clean, the normalised ring, its raw offset path on the grid.
  Ring r = PreClean(ring, o.clean_len, o.clean_angle_deg, nullptr);
  r = Normalise(r, o.keep_straight);
  SplitForecast f;
  if (r.size() < 3) return f;
  const IRing p = ToGrid(RawOffsetPath(r, o));
  std::vector<Seg> segs;
  segs.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] != p[(i + 1) % p.size()]) segs.push_back({p[i], p[(i + 1) % p.size()]});
  f.segments = static_cast<double>(segs.size());
  f.tried_pairs = TriedPairs(segs);
  // Each segment's box meets its two neighbours' at their shared vertex.
  f.box_pairs = std::max(0.0, BoxPairs(segs) - f.segments);
  return f;
}

std::vector<Ring> PositiveUnion(const std::vector<Ring>& paths, ShrinkCounts* counts,
                                bool keep_straight) {
  std::vector<IRing> g;
  for (const Ring& p : paths) g.push_back(ToGrid(p));
  return UnionOnce(g, counts, 0, keep_straight);
}

std::vector<Ring> Shrink(const Ring& ring, const ShrinkOptions& o, ShrinkCounts* counts) {
  int cleaned = 0;
  Ring r = PreClean(ring, o.clean_len, o.clean_angle_deg, &cleaned);
  if (counts) counts->cleaned_points += cleaned;
  r = Normalise(r, o.keep_straight);
  if (r.size() < 3) return {};
  // Steps 3-4: the faces of winding ≥ 1 of the raw offset path (Fig 6d: its CCW cycles), or,
  // with options.swept, of the ring with the swept pieces (−1 each when shrinking): the exact
  // erosion/dilation, quadratic when d spans many edges (the test twin of the raw path).
  std::vector<Ring> paths;
  if (o.swept) {
    paths.push_back(r);
    for (Ring& piece : SweptPieces(r, o)) paths.push_back(std::move(piece));
  } else {
    paths.push_back(RawOffsetPath(r, o));
  }
  std::vector<Ring> rings = PositiveUnion(paths, counts, o.keep_straight);
  if (counts != nullptr && counts->stopped) return {};
  // Slivers the rounding onto the grid can leave (area below 1e-4·d²) are dropped and counted.
  const IRing g = ToGrid(r);
  std::vector<Ring> out;
  for (Ring& q : rings) {
    // A kept face lies on the offset side, about d away (a guard against faces of the raw path
    // that belong to no offset region).
    bool far = false;  // some vertex at the offset distance (offset edges are at d from all)
    for (const Vec2& v : q)
      if (RingDistance(r, v) >= o.d * (1 - 1e-3) - 2 / kGridPerMetre) {
        far = true;
        break;
      }
    if (Inside(g, ToGrid(q[0])) == o.outward || !far) {
      if (counts) ++counts->dropped_rings;
      continue;
    }
    if (Area(q) < 1e-4 * o.d * o.d) {
      if (counts) ++counts->dropped_rings;
      continue;
    }
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace niwa::terrain
