// Per-level measures of a grown mountain's contours (see level_measures.h).
#include "terrain/level_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "math/det_math.h"
#include "terrain/polygon.h"

namespace niwa::terrain {
namespace {

double Dist(const Vec2& a, const Vec2& b) {
  return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
}

// Spec §3: D = 1 − slope of log L(s) against log s, s = 2·d0·2^i while s < P/8 (det::Log: the
// same bits in WASM).
double DividerDimension(const Ring& ring, double d0) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double p = Perimeter(ring);
  if (!(d0 > 0)) return nan;
  std::vector<double> xs, ys;
  for (double s = 2 * d0; s < p / 8 && xs.size() < 40; s *= 2) {
    const double l = DividerLength(ring, s);
    if (!(l > 0)) break;
    xs.push_back(det::Log(s));
    ys.push_back(det::Log(l));
  }
  if (xs.size() < 2) return nan;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    mx += xs[i];
    my += ys[i];
  }
  mx /= static_cast<double>(xs.size());
  my /= static_cast<double>(xs.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) * (xs[i] - mx);
  }
  return 1 - sxy / sxx;
}

}  // namespace

double DividerLength(const Ring& ring, double s) {
  const std::size_t n = ring.size();
  if (n < 2 || !(s > 0)) return 0;
  Vec2 c = ring[0];
  std::size_t i = 0;  // the segment ring[i] → ring[i + 1] (the last one closes the ring)
  double t = 0;       // the walk's place on it
  std::size_t steps = 0;
  while (i < n) {
    // The next point at distance s from c: where the segment leaves the circle around c (the
    // larger root of |a + t·(b − a) − c|² = s²), after the walk's place.
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    const double dx = b.x - a.x, dy = b.y - a.y, fx = a.x - c.x, fy = a.y - c.y;
    const double qa = dx * dx + dy * dy, qb = 2 * (fx * dx + fy * dy),
                 qc = fx * fx + fy * fy - s * s;
    const double disc = qb * qb - 4 * qa * qc;
    if (qa > 0 && disc >= 0) {
      const double root = (-qb + std::sqrt(disc)) / (2 * qa);
      if (root > t && root <= 1) {
        c = {a.x + root * dx, a.y + root * dy};
        t = root;
        ++steps;
        continue;
      }
    }
    ++i;
    t = 0;
  }
  return static_cast<double>(steps) * s + Dist(c, ring[0]);
}

std::vector<LevelMeasures> ComputeLevelMeasures(const Terrain& t) {
  std::map<int, LevelMeasures> by_level;
  std::map<int, const Ring*> longest;
  std::map<int, std::size_t> long_edges;
  std::map<int, double> weighted_q;
  for (const ContourNode& c : t.contours) {
    LevelMeasures& m = by_level[c.level];
    m.level = c.level;
    m.elevation = c.elevation;
    ++m.rings;
    m.vertices += c.ring.size();
    const double a = std::fabs(Area(c.ring)), p = Perimeter(c.ring);
    m.area += a;
    m.perimeter += p;
    if (p > 0) weighted_q[c.level] += a * (4 * det::kPi * a / (p * p));
    for (std::size_t i = 0; i < c.ring.size(); ++i)
      if (Dist(c.ring[i], c.ring[(i + 1) % c.ring.size()]) >= 2 * t.d0) ++long_edges[c.level];
    const Ring*& l = longest[c.level];
    if (!l || p > Perimeter(*l)) l = &c.ring;
  }
  std::vector<LevelMeasures> out;
  double below = std::numeric_limits<double>::quiet_NaN();
  for (auto& [level, m] : by_level) {
    m.area_ratio = below > 0 ? m.area / below : std::numeric_limits<double>::quiet_NaN();
    below = m.area;
    m.compactness = m.area > 0 ? weighted_q[level] / m.area : 0;
    m.long_edge_share =
        m.vertices > 0 ? static_cast<double>(long_edges[level]) / static_cast<double>(m.vertices)
                       : 0;
    m.fractal_dimension = DividerDimension(*longest[level], t.d0);
    out.push_back(m);
  }
  return out;
}

}  // namespace niwa::terrain
