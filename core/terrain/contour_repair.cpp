// RepairContour: §4.4 loop removal, else the union's largest ring; FitContourToLink (see
// contour_repair.h).
#include "terrain/contour_repair.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "base/budget.h"
#include "terrain/generate.h"
#include "terrain/loops.h"
#include "terrain/offset.h"
#include "terrain/polygon.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {

Result<ContourRepair> RepairContour(const Ring& ring) {
  Result<Ring> checked = CheckSeed(ring);
  ContourRepair out;
  if (checked.ok()) {
    out.ring = ring;
    return out;
  }
  // Only a ring of 3 to kMaxSeedPoints finite points can be repaired; otherwise CheckSeed's line.
  if (ring.size() < 3 || ring.size() > kMaxSeedPoints) return checked.status();
  for (const Vec2& v : ring)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || std::fabs(v.x) > kMaxCoordinate ||
        std::fabs(v.y) > kMaxCoordinate)
      return checked.status();
  const Ring snapped = Snap(ring);
  // A seed too tangled to check is not repaired either (CheckSeed's line); the loop removal's
  // sweep runs along x (SelfIntersections), bounded as the check is.
  if (SimplicityPairs(ToGrid(Normalise(ring))) > kMaxSimplicityPairs) return checked.status();
  if (const double pairs = SweepPairs(ToGrid(snapped), false); pairs > kMaxSimplicityPairs) {
    return Status::Error("contour",
                         "is not a simple loop, and with " + std::to_string(ring.size()) +
                             " points whose edges overlap along x repairing it "
                             "would test " +
                             FormatCount(pairs) + " pairs of edges, more than the " +
                             FormatCount(kMaxSimplicityPairs) + " allowed; simplify the contour");
  }
  int removed = 0;
  // §4.4 method 2 with the table's default run (loop_run 5), whatever the state's rows.
  Result<Ring> untwisted = CheckSeed(Normalise(UntwistRing(snapped, 2, 5, &removed)));
  if (!untwisted.ok()) {
    ShrinkCounts counts;
    counts.max_sweep_tests = kMaxSimplicityPairs;  // the union's own count (empty when passed)
    std::vector<Ring> pieces = PositiveUnion({Normalise(snapped)}, &counts);
    const Ring* best = nullptr;
    for (const Ring& piece : pieces)
      if (!best || std::fabs(Area(piece)) > std::fabs(Area(*best))) best = &piece;
    if (best) untwisted = CheckSeed(*best);
    out.method = "union";
  } else {
    out.method = "loops";
  }
  if (!untwisted.ok()) {
    return Status::Error(
        "contour", "crosses itself and could not be repaired; must be one simple closed loop");
  }
  out.ring = std::move(untwisted).value();
  out.repaired = true;
  out.loops_removed = removed;
  out.reason = checked.status().Line();
  return out;
}

namespace {

// Douglas-Peucker over the closed ring: kept[i] for the points whose chord error passes `tol`,
// splitting at point 0 and the point farthest from it.
Ring Simplify(const Ring& r, double tol) {
  const std::size_t n = r.size();
  if (n <= 4) return r;
  std::size_t far = 1;
  double best = -1;
  for (std::size_t i = 1; i < n; ++i) {
    const double dx = r[i].x - r[0].x, dy = r[i].y - r[0].y;
    if (dx * dx + dy * dy > best) {
      best = dx * dx + dy * dy;
      far = i;
    }
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[far] = 1;
  std::vector<std::pair<std::size_t, std::size_t>> spans = {{0, far}, {far, n}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    if (b <= a + 1) continue;
    const Vec2& pa = r[a];
    const Vec2& pb = r[b % n];
    double worst = -1;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double e = SegmentDistance(r[i], pa, pb);
      if (e > worst) {
        worst = e;
        at = i;
      }
    }
    if (worst > tol) {
      keep[at] = 1;
      spans.push_back({a, at});
      spans.push_back({at, b});
    }
  }
  Ring out;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) out.push_back(r[i]);
  return out.size() >= 3 ? out : r;
}

}  // namespace

LinkFit FitContourToLink(const Ring& ring, std::size_t max_chars) {
  LinkFit fit;
  fit.ring = ring;
  if (ring.size() < 3 || EncodeContourPoints(ring).size() <= max_chars) return fit;
  const double span = BoundsOf(ring).span();
  double q = 1.0 / 1024;
  while (q * 2 <= span / 4096) q *= 2;
  Ring snapped;
  for (const Vec2& v : ring) {
    const Vec2 s{std::round(v.x / q) * q, std::round(v.y / q) * q};
    if (snapped.empty() || !(snapped.back() == s)) snapped.push_back(s);
  }
  while (snapped.size() > 3 && snapped.back() == snapped.front()) snapped.pop_back();
  fit.changed = true;
  fit.quantum = q;
  fit.ring = snapped;
  for (double tol = q; EncodeContourPoints(fit.ring).size() > max_chars && fit.ring.size() > 3;
       tol *= 2) {
    fit.ring = Simplify(snapped, tol);
    fit.tolerance = tol;
  }
  return fit;
}

}  // namespace niwa::terrain
