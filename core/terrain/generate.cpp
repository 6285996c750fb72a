// The four contour generation methods and the contour tree (§3-4.4; see generate.h).
#include "terrain/generate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <functional>
#include <string>
#include <unordered_map>

#include "base/budget.h"
#include "math/det_math.h"
#include "params/param_text.h"
#include "run/study_run.h"
#include "terrain/fourier.h"
#include "terrain/loops.h"
#include "terrain/offset.h"
#include "terrain/polygon.h"
#include "terrain/segment_grid.h"
#include "terrain/terrain_budget.h"

namespace niwa::terrain {
namespace {

using P = TerrainParam;

double Ms(std::chrono::steady_clock::time_point a) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count();
}

double MeanEdge(const Ring& r) { return Perimeter(r) / static_cast<double>(r.size()); }

double EdgeLen(const Vec2& a, const Vec2& b) {
  return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
}

// One split's draws: θ's uniform in [0, 1) and the side's (generate.h SplitDraws).
struct SplitDraw {
  double u_theta, u_side;
};
using DrawFor = std::function<SplitDraw(const Vec2& midpoint, double len, int depth)>;

// False once `out` holds max_points (the splitting stops there: midpoint displacement at θ ≥ 60°
// doubles the points at every level, generate.h).
bool SplitEdge(const Vec2& a, const Vec2& b, double d0, double d2, double tmin, double tmax,
               const DrawFor& draw, int depth, std::size_t max_points, Ring* out) {
  const double len = EdgeLen(a, b);
  if (len < 2.0 * d0 || depth > 40) {
    if (out->size() >= max_points) return false;
    out->push_back(a);
    return true;
  }
  const double l = 0.5 * len;
  const SplitDraw u = draw({0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}, len, depth);
  const double theta = tmin + (tmax - tmin) * u.u_theta;
  const double side = u.u_side < 0.5 ? -1.0 : 1.0;
  const double delta = MidpointDelta(l, theta, d2);
  const Vec2 n{-(b.y - a.y) / len, (b.x - a.x) / len};
  const Vec2 m{0.5 * (a.x + b.x) + side * delta * n.x, 0.5 * (a.y + b.y) + side * delta * n.y};
  return SplitEdge(a, m, d0, d2, tmin, tmax, draw, depth + 1, max_points, out) &&
         SplitEdge(m, b, d0, d2, tmin, tmax, draw, depth + 1, max_points, out);
}

std::optional<Ring> DisplaceWith(const Ring& ring, double d0, double d2, double tmin, double tmax,
                                 const DrawFor& draw, std::size_t max_points) {
  Ring out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!SplitEdge(ring[i], ring[(i + 1) % n], d0, d2, tmin, tmax, draw, 0, max_points, &out))
      return std::nullopt;
  return out;
}

// SplitMix64's finaliser (Steele, Lea, Flood 2014): the key of a split's PCG32 seed.
uint64_t Mix(uint64_t h, uint64_t v) {
  uint64_t z = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A union of the perturbation counted against the grow's sweep budget (`budget`: its work so far
// and the most allowed); past it, `budget->stopped` and no rings.
std::vector<Ring> CountedUnion(const Ring& ring, ShrinkCounts* budget, ShrinkCounts* sc) {
  if (budget->max_sweep_tests >= 0)
    sc->max_sweep_tests = std::max(0.0, budget->max_sweep_tests - budget->sweep_tests);
  std::vector<Ring> out = PositiveUnion({Snap(ring)}, sc, true);
  budget->sweep_tests += sc->sweep_tests;
  if (sc->stopped) budget->stopped = true;
  return out;
}

// A pair of rings' nesting check beyond its sweep: the edges' copy and sort and the point tests,
// about 19 ns an edge of the two (a 3,000-tooth comb's 9 M pairs of 12-edge rings took 4.2 s,
// native release): 0.6 of a counted test (30 ns) an edge.
constexpr double kSweepWorkPerEdgePair = 0.6;

// The sweep work `budget` leaves (polygon.h SweepWork), and that work charged back to it.
SweepWork SweepWorkLeft(const ShrinkCounts& budget) {
  SweepWork w;
  if (budget.max_sweep_tests >= 0)
    w.max_tests = std::max(0.0, budget.max_sweep_tests - budget.sweep_tests);
  return w;
}
void ChargeSweepWork(const SweepWork& w, ShrinkCounts* budget) {
  budget->sweep_tests += w.tests;
  if (w.stopped) budget->stopped = true;
}

// A perturbed ring made simple: as is, untwisted (§4.4), or by the positive-winding union. Its
// simplicity checks, untwisting and unions count against `budget` (issue 34: the perturbation's
// unions were not counted, so a spiral strip at d = 0.5 counted 0.16 s of work and took 5.4 s;
// the checks and the untwisting's crossings, quadratic for a ring folded on itself, neither).
// Empty with budget->stopped past it.
std::vector<Ring> MakeSimple(const Ring& ring, const TerrainParams& p, GrowCounts* counts,
                             ShrinkCounts* budget) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Ring> out;
  Ring r = Normalise(ring, true);
  SweepWork check = SweepWorkLeft(*budget);
  const bool simple = r.size() >= 3 && IsSimple(ToGrid(r), &check);
  ChargeSweepWork(check, budget);
  if (budget->stopped) return {};
  if (simple) {
    out.push_back(r);
  } else {
    const int method = p.GetInt(P::kLoopMethod);
    const int threshold = method == 1 ? p.GetInt(P::kLoopFaces) : p.GetInt(P::kLoopRun);
    int removed = 0;
    SweepWork untwist = SweepWorkLeft(*budget);
    Ring u = Normalise(UntwistRing(Snap(ring), method, threshold, &removed, &untwist), true);
    // The cut must keep the ring's body: loop removal deletes from a crossing to its twin in walk
    // order, and where the perturbation pinches a deep narrow valley shut that can be the large
    // side (the valleys seed lost 490 of 496 points so). An untwisted ring with less than half the
    // area of the positive-winding union of the same ring cut the wrong side; the union is kept.
    bool body_kept = !untwist.stopped && u.size() >= 3 && IsSimple(ToGrid(u), &untwist);
    ChargeSweepWork(untwist, budget);
    if (budget->stopped) return {};
    std::vector<Ring> pieces;
    ShrinkCounts union_counts;
    if (body_kept) {
      pieces = CountedUnion(ring, budget, &union_counts);
      if (budget->stopped) return {};
      double whole = 0;
      for (const Ring& piece : pieces) whole += std::fabs(Area(piece));
      body_kept = std::fabs(Area(u)) >= 0.5 * whole;
    }
    if (body_kept) {
      counts->loops_removed += removed;
      out.push_back(u);
    } else if (!pieces.empty()) {
      ++counts->union_fallbacks;
      counts->holes_filled += union_counts.holes_filled;
      counts->dropped_rings += union_counts.dropped_rings;
      out = std::move(pieces);
    } else {
      ++counts->union_fallbacks;
      ShrinkCounts sc;
      out = CountedUnion(ring, budget, &sc);
      if (budget->stopped) return {};
      counts->holes_filled += sc.holes_filled;
      counts->dropped_rings += sc.dropped_rings;
    }
  }
  counts->ms_loops += Ms(t0);
  return out;
}

// The method's perturbation of one freshly shrunk ring (§4.1-4.3 steps 1.2-1.3); the midpoint
// displacement makes at most max_points points, else the error (MidpointOverflow).
Result<std::vector<Ring>> Perturb(const Ring& shrunk, const TerrainParams& p, double d0,
                                  const SplitDraws& draws, Pcg32* rng, std::size_t max_points,
                                  const std::string& what, GrowCounts* counts,
                                  ShrinkCounts* budget) {
  const int method = p.GetInt(P::kMethod);
  if (method == static_cast<int>(Method::kSimple)) return std::vector<Ring>{shrunk};
  const double d = p.Get(P::kD);
  Ring r = shrunk;
  if (method == static_cast<int>(Method::kMidpoint) ||
      method == static_cast<int>(Method::kImproved)) {
    const auto t0 = std::chrono::steady_clock::now();
    std::optional<Ring> displaced = MidpointDisplace(r, d0, p.Get(P::kD2) * d, p.Get(P::kThetaMin),
                                                     p.Get(P::kThetaMax), draws, max_points);
    counts->ms_mpd += Ms(t0);
    if (!displaced) {
      return MidpointOverflow(d0, p.Get(P::kD2) * d, p.Get(P::kThetaMax),
                              static_cast<double>(max_points), what);
    }
    r = std::move(*displaced);
  }
  if (method == static_cast<int>(Method::kFourier) ||
      method == static_cast<int>(Method::kImproved)) {
    const auto t0 = std::chrono::steady_clock::now();
    r = FourierPerturb(r, p.GetInt(P::kNfft), p.GetInt(P::kF0), p.Get(P::kPhaseAmp), rng);
    if (method == static_cast<int>(Method::kImproved)) {
      r = RemoveCollinearToShare(r, d0, p.Get(P::kLongFrac), 0.1 * d);  // eps ≤ 0.1·d: no collapse
    }
    counts->ms_fd += Ms(t0);
  }
  return MakeSimple(r, p, counts, budget);
}

// The perturbed rings of one level's groups (one group per shrunk ring) on the grid, with their
// boxes, for the nesting checks: a group's reach is the box of its perturbed rings and of its
// shrunk ring, so a group put back to its shrunk ring stays inside it, and the groups sorted on
// their reach's x find a ring's neighbours by a binary search (every ring was checked against
// every other: quadratic in the siblings, 4 s for a 3,000-tooth comb).
struct SiblingRings {
  std::vector<std::vector<IRing>> rings;
  std::vector<std::vector<IBox>> boxes;
  std::vector<IBox> reach;
  std::vector<int> by_x;  // group indices in the order of reach.x0
  int64_t widest = 0;     // the widest reach (the search's margin)

  void Set(std::size_t g, const std::vector<Ring>& group) {
    rings[g].clear();
    boxes[g].clear();
    for (const Ring& r : group) {
      rings[g].push_back(ToGrid(r));
      boxes[g].push_back(BoxOf(rings[g].back()));
    }
  }
};

SiblingRings MakeSiblingRings(const std::vector<std::vector<Ring>>& groups,
                              const std::vector<Ring>& shrunk) {
  SiblingRings s;
  s.rings.resize(groups.size());
  s.boxes.resize(groups.size());
  s.reach.resize(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    s.Set(g, groups[g]);
    IBox r = BoxOf(ToGrid(shrunk[g]));
    for (const IBox& b : s.boxes[g]) {
      r.x0 = std::min(r.x0, b.x0);
      r.y0 = std::min(r.y0, b.y0);
      r.x1 = std::max(r.x1, b.x1);
      r.y1 = std::max(r.y1, b.y1);
    }
    s.reach[g] = r;
    s.widest = std::max(s.widest, r.x1 - r.x0);
    s.by_x.push_back(static_cast<int>(g));
  }
  std::sort(s.by_x.begin(), s.by_x.end(), [&](int a, int b) {
    const int64_t xa = s.reach[static_cast<std::size_t>(a)].x0;
    const int64_t xb = s.reach[static_cast<std::size_t>(b)].x0;
    return xa < xb || (xa == xb && a < b);
  });
  return s;
}

// Ring k of group `self` leaves its parent or meets a ring of another group (only rings whose
// boxes meet can). Its sweeps and searches count against `work`, a pair of rings also its sort
// and point tests; once work->stopped, the answer means nothing.
bool Conflicts(const SiblingRings& s, std::size_t self, std::size_t k, const IRing& parent,
               const EdgeIndex& parent_edges, SweepWork* work) {
  const IRing& ring = s.rings[self][k];
  const IBox& box = s.boxes[self][k];
  const auto pair_work = [&](const IRing& o) {
    return SweepOver(work, kSweepWorkPerEdgePair * static_cast<double>(ring.size() + o.size()));
  };
  // The parent: its edges near the ring's, and a point test (a pass over the parent).
  if (SweepOver(work, kSweepWorkPerTry * static_cast<double>(parent.size()))) return true;
  if (parent_edges.Meets(ring, work) || work->stopped || !Inside(parent, ring[0])) return true;
  auto it = std::lower_bound(
      s.by_x.begin(), s.by_x.end(), box.x0 - s.widest,
      [&](int g, int64_t x) { return s.reach[static_cast<std::size_t>(g)].x0 < x; });
  for (; it != s.by_x.end() && s.reach[static_cast<std::size_t>(*it)].x0 <= box.x1; ++it) {
    const std::size_t j = static_cast<std::size_t>(*it);
    if (SweepOver(work, kSweepWorkPerTry)) return true;
    if (j == self || !BoxesMeet(s.reach[j], box)) continue;
    for (std::size_t m = 0; m < s.rings[j].size(); ++m) {
      if (!BoxesMeet(s.boxes[j][m], box)) continue;
      const IRing& o = s.rings[j][m];
      if (pair_work(o)) return true;
      if (RingsIntersect(ring, o, work) || work->stopped || Inside(o, ring[0]) ||
          Inside(ring, o[0]))
        return true;
    }
  }
  return false;
}

// The levels' elevations under the profile ratio q (`dh_ratio`; contour.h Terrain::dh_ratio):
// h_k = h0 + Δh·(1 + q + … + q^(k−1)) above the seed, h0 − Δh·(1/q + … + 1/q^(−k)) below it, by
// products and sums only (no pow: the same bits natively and in WASM); with q = 1 exactly
// h0 + k·Δh as before the row existed.
class LevelElevations {
 public:
  LevelElevations(double h0, double dh, double q) : h0_(h0), dh_(dh), q_(q) {}
  double At(int level) {
    if (q_ == 1) return h0_ + level * dh_;
    std::vector<double>& e = level >= 0 ? up_ : down_;
    const std::size_t k = static_cast<std::size_t>(level >= 0 ? level : -level);
    while (e.size() <= k) {
      if (e.empty()) {
        e.push_back(h0_);
        step_up_ = dh_;
        step_down_ = dh_ / q_;
        continue;
      }
      if (level >= 0) {
        e.push_back(e.back() + step_up_);
        step_up_ *= q_;
      } else {
        e.push_back(e.back() - step_down_);
        step_down_ /= q_;
      }
    }
    return e[k];
  }
  // The interval from `level` to the level above it.
  double Above(int level) { return q_ == 1 ? dh_ : At(level + 1) - At(level); }

 private:
  double h0_, dh_, q_;
  double step_up_ = 0, step_down_ = 0;
  std::vector<double> up_, down_;
};

}  // namespace

double LevelElevation(const Terrain& t, int level) {
  return LevelElevations(t.h0, t.dh, t.dh_ratio).At(level);
}

double MidpointDelta(double l, double theta_deg, double d2) {
  double s, c;
  det::SinCos(theta_deg * det::kPi / 180.0, &s, &c);
  return std::min(d2, std::fabs(l * s / c));
}

std::optional<Ring> MidpointDisplace(const Ring& ring, double d0, double d2, double tmin,
                                     double tmax, Pcg32* rng, std::size_t max_points) {
  return DisplaceWith(
      ring, d0, d2, tmin, tmax,
      [rng](const Vec2&, double, int) {
        const double u_theta = rng->Uniform();
        return SplitDraw{u_theta, rng->Uniform()};
      },
      max_points);
}

std::optional<Ring> MidpointDisplace(const Ring& ring, double d0, double d2, double tmin,
                                     double tmax, const SplitDraws& draws, std::size_t max_points) {
  return DisplaceWith(
      ring, d0, d2, tmin, tmax,
      [&draws](const Vec2& m, double, int depth) {
        // The cell of side draws.cell holding the midpoint (clamped: coordinates are ≤ 1e6 m).
        const auto cell = [&](double v) {
          const double c = std::floor(v / draws.cell);
          return static_cast<uint64_t>(static_cast<int64_t>(std::clamp(c, -4e18, 4e18)));
        };
        const uint64_t key =
            Mix(Mix(Mix(draws.key, static_cast<uint64_t>(depth)), cell(m.x)), cell(m.y));
        Pcg32 rng(key, draws.key);
        const double u_theta = rng.Uniform();
        return SplitDraw{u_theta, rng.Uniform()};
      },
      max_points);
}

uint64_t SplitDrawsKey(uint64_t rng_seed, int level) {
  return Mix(Mix(0x6d696473706c6974ULL, rng_seed), static_cast<uint64_t>(level));
}

Status MidpointOverflow(double d0, double d2, double theta_max_deg, double max_points,
                        const std::string& what) {
  // Halves as long as their edge: θ ≥ 60° (tan θ ≥ √3) with d'' ≥ √3·d0 (generate.h).
  const bool endless = theta_max_deg >= 60 && d2 >= std::sqrt(3.0) * d0;
  return Status::Error(
      "theta_max", FormatNumber(theta_max_deg) + ": midpoint displacement would make more than " +
                       FormatCount(max_points) + " points on one contour (" + what + ")" +
                       (endless ? "; at θ ≥ 60° with d'' = " + FormatNumber(d2) + " m ≥ √3·d0 = " +
                                      FormatNumber(std::round(std::sqrt(3.0) * d0 * 100) / 100) +
                                      " m a split edge is no shorter than its parent"
                                : std::string()) +
                       "; must be below 60, or lower d2");
}

namespace {

// What one test "may point i go with `last` the last kept point" found, kept across the eps values
// of RemoveCollinearToShare's bisection (the squared distances do not depend on eps): m is the
// largest squared distance to the chord of the points checked; full when every point was checked,
// else only the newest (then m is a lower bound).
struct ChordTest {
  double m = 0;
  bool full = false;
};
using ChordMemo = std::unordered_map<uint64_t, ChordTest>;

Ring RemoveNearlyCollinearMemo(const Ring& ring, double eps, ChordMemo* memo) {
  if (ring.size() <= 3) return ring;
  const std::size_t n = ring.size();
  Ring out{ring[0]};
  std::size_t last = 0;  // index of the last kept point
  // Squared distances against eps² decide unless within a hair of it, where SegmentDistance
  // itself does: the result is exactly "every SegmentDistance(...) < eps", only faster.
  const double eps2_hi = eps * eps * (1 + 1e-9), eps2_lo = eps * eps * (1 - 1e-9);
  for (std::size_t i = 1; i < n; ++i) {
    // Point i may go when it and every point dropped since the last kept one lie within eps of
    // the chord from the last kept point to point i + 1.
    if (out.size() + (n - i - 1) < 3) {
      out.push_back(ring[i]);
      last = i;
      continue;
    }
    const Vec2& a = ring[last];
    const Vec2& next = ring[(i + 1) % n];
    ChordTest& test = (*memo)[(static_cast<uint64_t>(last) << 32) | i];
    if (!test.full && test.m <= eps2_hi) {
      // The newest point first (the likeliest to be far), then all of them.
      test.m = SegmentDist2(ring[i], a, next);
      if (test.m <= eps2_hi) {
        for (std::size_t k = last + 1; k < i; ++k)
          test.m = std::max(test.m, SegmentDist2(ring[k], a, next));
        test.full = true;
      }
    }
    bool near = test.m < eps2_lo;
    if (test.m <= eps2_hi && !near) {  // within a hair of eps: the exact test
      near = true;
      for (std::size_t k = last + 1; k <= i && near; ++k)
        if (SegmentDistance(ring[k], a, next) >= eps) near = false;
    }
    if (near) continue;
    out.push_back(ring[i]);
    last = i;
  }
  return out.size() >= 3 ? out : ring;
}

}  // namespace

Ring RemoveNearlyCollinear(const Ring& ring, double eps) {
  ChordMemo memo;
  return RemoveNearlyCollinearMemo(ring, eps, &memo);
}

Ring RemoveCollinearToShare(const Ring& ring, double d0, double long_frac, double max_eps) {
  auto share = [&](const Ring& r) {
    std::size_t longs = 0;
    for (std::size_t i = 0; i < r.size(); ++i)
      if (EdgeLen(r[i], r[(i + 1) % r.size()]) >= 2.0 * d0) ++longs;
    return static_cast<double>(longs) / static_cast<double>(r.size());
  };
  if (share(ring) >= long_frac) return ring;
  double lo = 0, hi = max_eps;
  ChordMemo memo;
  Ring best = RemoveNearlyCollinearMemo(ring, hi, &memo);
  if (share(best) < long_frac) return best;
  for (int it = 0; it < 24; ++it) {
    const double mid = 0.5 * (lo + hi);
    Ring r = RemoveNearlyCollinearMemo(ring, mid, &memo);
    if (share(r) >= long_frac) {
      hi = mid;
      best = std::move(r);
    } else {
      lo = mid;
    }
  }
  return best;
}

Vec2 PoleOfInaccessibility(const Ring& ring, double* radius) {
  const RingBox box = BoundsOf(ring);
  const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  Vec2 best{0.5 * (x0 + x1), 0.5 * (y0 + y1)};
  double best_r = InsideDouble(ring, best) ? RingDistance(ring, best) : -1;
  // A candidate inside the ring that lies farther from its boundary is the new best.
  const auto consider = [&](const Vec2& q) {
    if (!InsideDouble(ring, q)) return;
    const double r = RingDistance(ring, q);
    if (r > best_r) {
      best_r = r;
      best = q;
    }
  };
  const int k = 16;
  double w = x1 - x0, h = y1 - y0;
  Vec2 c = best;
  for (int round = 0; round < 12; ++round) {
    for (int j = 0; j <= k; ++j) {
      for (int i = 0; i <= k; ++i) {
        const Vec2 q{c.x - 0.5 * w + w * i / k, c.y - 0.5 * h + h * j / k};
        consider(q);
      }
    }
    c = best;
    w *= 0.25;
    h *= 0.25;
  }
  if (best_r < 0) {
    // A thin or concave ring the grid missed (issue 31: an L-shaped top contour got its summit
    // at the vertex centroid, outside it, and a flat top): the middle of the widest inside span
    // of the scanlines halfway between two heights of its vertices (such a line meets the inside
    // of any simple ring with area), then refined around it.
    std::vector<double> ys;
    for (const Vec2& v : ring) ys.push_back(v.y);
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    const std::size_t n = ring.size();
    const std::size_t step = std::max<std::size_t>(1, ys.size() / 256);
    std::vector<double> xs;
    for (std::size_t g = 0; g + 1 < ys.size(); g += step) {
      const double y = 0.5 * (ys[g] + ys[g + 1]);
      xs.clear();
      for (std::size_t i = 0; i < n; ++i) {
        const Vec2& a = ring[i];
        const Vec2& b = ring[(i + 1) % n];
        if ((a.y > y) != (b.y > y)) xs.push_back(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y));
      }
      std::sort(xs.begin(), xs.end());
      for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
        const Vec2 q{0.5 * (xs[i] + xs[i + 1]), y};
        consider(q);
      }
    }
    for (int round = 0; best_r > 0 && round < 8; ++round) {
      const double span = 4 * best_r / (round + 1);
      const Vec2 at = best;
      for (int j = 0; j <= k; ++j) {
        for (int i = 0; i <= k; ++i) {
          const Vec2 q{at.x - 0.5 * span + span * i / k, at.y - 0.5 * span + span * j / k};
          consider(q);
        }
      }
    }
  }
  if (best_r < 0) {  // degenerate (no area): the centroid of the vertices
    best = {0, 0};
    for (const Vec2& v : ring) best = {best.x + v.x, best.y + v.y};
    best = {best.x / static_cast<double>(ring.size()), best.y / static_cast<double>(ring.size())};
    best_r = 0;
  }
  *radius = best_r;
  return best;
}

Result<Ring> CheckSeed(const Ring& seed) {
  if (seed.size() < 3) {
    return Status::Error("contour",
                         std::to_string(seed.size()) + " points; must have 3 to 1000000 points");
  }
  if (seed.size() > kMaxSeedPoints) {
    return Status::Error("contour",
                         std::to_string(seed.size()) + " points; must have 3 to 1000000 points");
  }
  for (std::size_t i = 0; i < seed.size(); ++i) {
    const Vec2& v = seed[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || std::fabs(v.x) > kMaxCoordinate ||
        std::fabs(v.y) > kMaxCoordinate) {
      return Status::Error("contour", "point " + std::to_string(i) +
                                          " is not a finite coordinate; each must be a number "
                                          "in [-1e6, 1e6] m");
    }
  }
  Ring r = Normalise(seed);
  const IRing grid = ToGrid(r);
  // Bounded before it is tried: the pairs of edges the check would test, counted in O(n log n).
  if (const double pairs = r.size() < 3 ? 0 : SimplicityPairs(grid); pairs > kMaxSimplicityPairs) {
    return Status::Error("contour", std::to_string(r.size()) +
                                        " points whose edges overlap on both axes: checking that "
                                        "it is simple would test " +
                                        FormatCount(pairs) + " pairs of edges, more than the " +
                                        FormatCount(kMaxSimplicityPairs) +
                                        " allowed; simplify the contour");
  }
  if (r.size() < 3 || !IsSimpleEitherAxis(grid)) {
    return Status::Error("contour",
                         "self-intersects or has no area; must be a simple closed polygon");
  }
  return r;
}

Ring ResampleSeed(const Ring& seed, const Ring& checked, double d) {
  const std::size_t n_in = seed.size();
  if (n_in < 3 || !(d > 0)) return checked;
  std::vector<double> at(n_in + 1, 0.0);  // arc length at each vertex (at[n_in]: the perimeter)
  for (std::size_t i = 0; i < n_in; ++i) at[i + 1] = at[i] + EdgeLen(seed[i], seed[(i + 1) % n_in]);
  const double perimeter = at[n_in];
  if (!(perimeter > 0)) return checked;
  double spacing = kSeedSpacingShare * d;
  for (int attempt = 0; attempt < 5; ++attempt, spacing *= 0.5) {
    const double want = std::round(perimeter / spacing);
    // Never coarser than d/4: a seed that would need more than the cap is grown as given (a
    // 3,000-tooth comb at d = 0.6 m would have been resampled at 1.4 m, across its 1 m gaps).
    if (want > static_cast<double>(kMaxSeedSamples)) break;
    const std::size_t n = static_cast<std::size_t>(std::clamp(
        want, static_cast<double>(kMinSeedSamples), static_cast<double>(kMaxSeedSamples)));
    const double h = perimeter / static_cast<double>(n);
    IRing grid;
    grid.reserve(n);
    std::size_t edge = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double s = h * static_cast<double>(k);
      while (edge + 1 < n_in && at[edge + 1] <= s) ++edge;
      const Vec2& a = seed[edge];
      const Vec2& b = seed[(edge + 1) % n_in];
      const double len = at[edge + 1] - at[edge];
      const double t = len > 0 ? (s - at[edge]) / len : 0.0;
      const IRing p = ToGrid(Ring{{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}});
      if (grid.empty() || !(p[0] == grid.back())) grid.push_back(p[0]);
    }
    while (grid.size() > 1 && grid.back() == grid.front()) grid.pop_back();
    if (grid.size() < 3) break;
    // Counter-clockwise as CheckSeed makes it, with the points on straight runs kept (Normalise
    // would drop them, and d0 with them: the straight-edged seeds).
    if (TwiceArea(grid) < 0) std::reverse(grid.begin(), grid.end());
    Ring out = FromGrid(grid);
    if (CheckSeed(out).ok()) return out;
  }
  return checked;
}

Result<Terrain> Grow(const Ring& seed_in, const TerrainParams& p, uint64_t rng_seed,
                     const TerrainGrowLimits* limits, const GrowWatch& watch) {
  NIWA_RETURN_IF_ERROR(CheckTerrainParams(p));
  Result<Ring> seed = CheckSeed(seed_in);
  if (!seed.ok()) return seed.status();
  Terrain t;
  t.d = p.Get(P::kD);
  t.dh = p.Get(P::kDh);
  t.h0 = p.Get(P::kH0);
  t.dh_ratio = p.Get(P::kDhRatio);
  LevelElevations elevations(t.h0, t.dh, t.dh_ratio);
  const double d = t.d;
  // Issue 31: grown from the seed at a uniform arc length of d/4 (ResampleSeed), so the mountain
  // does not depend on how the line was sampled: d0 follows d, not the drawing. The seed as given
  // stays the lowest contour (level 0); its children lie within d/8 of d inside it.
  const Ring sampled = ResampleSeed(seed_in, *seed, d);
  const double d0 = MeanEdge(sampled);
  t.d0 = d0;
  t.seed_samples = sampled.size();
  ShrinkOptions so;
  so.d = d;
  so.join = static_cast<Join>(p.GetInt(P::kJoin));
  so.c = p.Get(P::kC);
  so.clean_len = p.Get(P::kCleanLen) * d;
  so.clean_angle_deg = p.Get(P::kCleanAngle);
  so.keep_straight = true;  // the resampled seed's straight runs keep their points (offset.h)
  const int max_levels = p.GetInt(P::kMaxLevels);

  TerrainWork work;  // counted for the budget's checks (terrain_budget.h)
  work.vertices_held = static_cast<double>(seed->size() + sampled.size());
  // Growth below the seed (§2 enlarging): a chain of enlarged contours, the lowest the root.
  std::vector<Ring> below;
  {
    ShrinkOptions out = so;
    out.outward = true;
    Ring cur = sampled;
    for (int k = 0; k < p.GetInt(P::kDown); ++k) {
      if (watch && !watch(-k - 1)) return run::CancelledStatus();
      if (limits != nullptr) {
        t.counts.truncated_by = CheckTerrainContour(cur, 0, p, work, *limits, -k - 1);
        if (!t.counts.truncated_by.empty()) break;
      }
      t.counts.largest_worked = std::max(t.counts.largest_worked, static_cast<double>(cur.size()));
      ShrinkCounts sc;
      if (limits != nullptr)
        sc.max_sweep_tests = SweepTestsLeft(*limits, work, t.counts.sweep_tests);
      std::vector<Ring> rs = Shrink(cur, out, &sc);
      t.counts.sweep_tests += sc.sweep_tests;
      if (sc.stopped) {
        t.counts.truncated_by =
            SweepStoppedLine(cur, sc.max_sweep_tests, *limits, -k - 1, p.GetInt(P::kMaxLevels));
        break;
      }
      work.vertices_worked += static_cast<double>(cur.size());
      for (const Ring& r : rs) work.vertices_worked += static_cast<double>(r.size());
      t.counts.holes_filled += sc.holes_filled;
      if (rs.empty()) break;
      std::size_t big = 0;
      for (std::size_t i = 1; i < rs.size(); ++i)
        if (Area(rs[i]) > Area(rs[big])) big = i;
      cur = rs[big];
      below.push_back(cur);
      work.vertices_held += static_cast<double>(cur.size());
    }
  }
  const int down = static_cast<int>(below.size());
  for (int k = down - 1; k >= 0; --k) {
    ContourNode node;
    node.ring = below[static_cast<std::size_t>(k)];
    node.level = -(k + 1);
    node.elevation = elevations.At(node.level);
    node.parent = t.contours.empty() ? -1 : static_cast<int>(t.contours.size()) - 1;
    if (node.parent >= 0)
      t.contours[static_cast<std::size_t>(node.parent)].children.push_back(
          static_cast<int>(t.contours.size()));
    t.contours.push_back(node);
  }
  {
    ContourNode root;
    root.ring = *seed;
    root.level = 0;
    root.elevation = t.h0;
    root.parent = t.contours.empty() ? -1 : static_cast<int>(t.contours.size()) - 1;
    if (root.parent >= 0)
      t.contours[static_cast<std::size_t>(root.parent)].children.push_back(
          static_cast<int>(t.contours.size()));
    t.contours.push_back(root);
  }

  std::deque<int> queue{static_cast<int>(t.contours.size()) - 1};
  while (!queue.empty() && t.counts.truncated_by.empty()) {
    const int at = queue.front();
    queue.pop_front();
    if (t.contours[static_cast<std::size_t>(at)].level >= max_levels ||
        t.contours.size() >= kMaxContours) {
      t.counts.truncated = true;
      continue;
    }
    const bool is_seed = t.contours[static_cast<std::size_t>(at)].level == 0;
    const Ring parent = is_seed ? sampled : t.contours[static_cast<std::size_t>(at)].ring;
    const int level = t.contours[static_cast<std::size_t>(at)].level + 1;
    if (watch && !watch(level)) return run::CancelledStatus();
    if (limits != nullptr) {
      t.counts.truncated_by = CheckTerrainContour(parent, d0, p, work, *limits, level);
      if (!t.counts.truncated_by.empty()) break;
    }
    t.counts.largest_worked = std::max(t.counts.largest_worked, static_cast<double>(parent.size()));
    const auto t0 = std::chrono::steady_clock::now();
    ShrinkCounts sc;
    if (limits != nullptr) sc.max_sweep_tests = SweepTestsLeft(*limits, work, t.counts.sweep_tests);
    std::vector<Ring> shrunk = Shrink(parent, so, &sc);
    t.counts.sweep_tests += sc.sweep_tests;
    if (sc.stopped) {
      // The seed's own first shrink: nothing could grow, so the seed's shape is refused.
      if (level == 1 && t.contours.size() == static_cast<std::size_t>(down) + 1) {
        return Status::Error("contour", "the seed's first shrink stopped: " +
                                            SweepStoppedWhy(parent, sc.max_sweep_tests, *limits) +
                                            "; simplify the contour" +
                                            RaiseHint(limits->seconds_limit));
      }
      t.counts.truncated_by =
          SweepStoppedLine(parent, sc.max_sweep_tests, *limits, level, max_levels);
      break;
    }
    t.counts.cleaned_points += sc.cleaned_points;
    t.counts.holes_filled += sc.holes_filled;
    t.counts.dropped_rings += sc.dropped_rings;
    t.counts.ms_shrink += Ms(t0);
    work.vertices_worked += static_cast<double>(parent.size());
    for (const Ring& r : shrunk) work.vertices_worked += static_cast<double>(r.size());
    if (shrunk.empty()) continue;
    if (limits != nullptr) {
      t.counts.truncated_by =
          CheckTerrainPerturbation(parent, shrunk.size(), p, work, *limits, level);
      if (!t.counts.truncated_by.empty()) break;
    }
    work.vertices_worked += PerturbationWork(shrunk.size(), p);
    // One RNG stream per contour, from the seed and the parent's index (order-independent), for
    // the Fourier phases; the midpoint splits draw by place (SplitDraws).
    Pcg32 rng(rng_seed, static_cast<uint64_t>(at) * 2654435761ULL + 1);
    const SplitDraws draws{SplitDrawsKey(rng_seed, level), 2.0 * d0};
    // The midpoint displacement's room: what the budget leaves after the contours kept and the
    // vertices worked (the children's transient copies and their shrink), or the hard cap.
    std::size_t max_points = kMaxMidpointPoints;
    std::string what = "the most one contour may have";
    if (limits != nullptr) {
      double room = static_cast<double>(kMaxMidpointPoints);
      if (limits->max_bytes >= 0 && limits->transient_bytes_per_vertex > 0) {
        const double bytes = (limits->max_bytes - limits->base_bytes -
                              limits->bytes_per_vertex * work.vertices_held) /
                             limits->transient_bytes_per_vertex;
        if (bytes < room) what = "what " + limits->memory_limit + " leaves";
        room = std::min(room, bytes);
      }
      if (limits->max_seconds >= 0 && limits->seconds_per_vertex > 0) {
        const double worked =
            limits->max_seconds / limits->seconds_per_vertex - work.vertices_worked;
        if (worked < room) what = "what " + limits->seconds_limit + " leaves";
        room = std::min(room, worked);
      }
      max_points = static_cast<std::size_t>(std::max(0.0, std::floor(room)));
    }
    std::vector<std::vector<Ring>> groups;
    ShrinkCounts perturbed;  // the perturbation's unions, counted as the shrink's are
    if (limits != nullptr)
      perturbed.max_sweep_tests = SweepTestsLeft(*limits, work, t.counts.sweep_tests);
    for (const Ring& r : shrunk) {
      Result<std::vector<Ring>> g =
          Perturb(r, p, d0, draws, &rng, max_points, what, &t.counts, &perturbed);
      if (!g.ok()) return g.status();
      if (perturbed.stopped) break;
      groups.push_back(std::move(g).value());
    }
    t.counts.sweep_tests += perturbed.sweep_tests;
    if (perturbed.stopped) {
      t.counts.truncated_by =
          SweepStoppedLine(parent, perturbed.max_sweep_tests, *limits, level, max_levels);
      break;
    }
    // Perturbed rings must lie inside the parent (the seed as given, not its resampling) and
    // apart from their siblings; offenders go back to the unperturbed shrink (which is both),
    // until none is left.
    const IRing gp = ToGrid(t.contours[static_cast<std::size_t>(at)].ring);
    bool changed = true;
    for (std::size_t i = 0; i < groups.size(); ++i)
      if (groups[i].empty()) {
        groups[i] = {shrunk[i]};
        ++t.counts.perturbations_reverted;
      }
    SiblingRings siblings = MakeSiblingRings(groups, shrunk);
    const EdgeIndex parent_edges(gp);
    SweepWork nesting;  // the checks below, counted as the unions are
    if (limits != nullptr) nesting.max_tests = SweepTestsLeft(*limits, work, t.counts.sweep_tests);
    while (changed && !nesting.stopped) {
      changed = false;
      for (std::size_t i = 0; i < groups.size() && !nesting.stopped; ++i) {
        if (groups[i].size() == 1 && groups[i][0] == shrunk[i]) continue;
        bool bad = false;
        for (std::size_t k = 0; k < siblings.rings[i].size(); ++k)
          if (Conflicts(siblings, i, k, gp, parent_edges, &nesting)) bad = true;
        if (bad && !nesting.stopped) {
          groups[i] = {shrunk[i]};
          siblings.Set(i, groups[i]);
          ++t.counts.perturbations_reverted;
          changed = true;
        }
      }
    }
    t.counts.sweep_tests += nesting.tests;
    if (nesting.stopped) {
      t.counts.truncated_by =
          SweepStoppedLine(parent, nesting.max_tests, *limits, level, max_levels);
      break;
    }
    for (const std::vector<Ring>& g : groups) {
      for (const Ring& r : g) {
        if (r.size() > kMaxContourVertices) {
          t.counts.truncated = true;
          continue;
        }
        if (std::fabs(Area(r)) < kSliverAreaShare * d * d) {
          ++t.counts.slivers_dropped;  // a sliver, not a peak: its parent may take the summit
          continue;
        }
        ContourNode node;
        node.ring = r;
        node.level = level;
        node.elevation = elevations.At(level);
        node.parent = at;
        work.vertices_held += static_cast<double>(r.size());
        work.vertices_worked += static_cast<double>(r.size());
        const int id = static_cast<int>(t.contours.size());
        t.contours[static_cast<std::size_t>(at)].children.push_back(id);
        t.contours.push_back(std::move(node));
        queue.push_back(id);
      }
    }
  }
  if (!t.counts.truncated_by.empty()) t.counts.truncated = true;
  t.counts.vertices_worked = work.vertices_worked;
  // A summit on every top contour: h_T + Δh·min(1, r/d) at the pole of inaccessibility.
  for (std::size_t i = 0; i < t.contours.size(); ++i) {
    if (!t.contours[i].children.empty()) continue;
    Summit s;
    s.contour = static_cast<int>(i);
    s.position = PoleOfInaccessibility(t.contours[i].ring, &s.radius);
    s.elevation = t.contours[i].elevation +
                  elevations.Above(t.contours[i].level) * std::min(1.0, s.radius / d);
    t.summits.push_back(s);
  }
  return t;
}

}  // namespace niwa::terrain
