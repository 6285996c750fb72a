// Band distance-ratio heightfield and terrain statistics (see heightfield.h).
#include "terrain/heightfield.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "math/det_math.h"
#include "terrain/polygon.h"

namespace niwa::terrain {
namespace {

// Marks the cells whose centres lie inside the ring with `id` (even-odd spans per row).
void Paint(const Ring& ring, int id, Heightfield* hf) {
  const std::size_t n = ring.size();
  std::vector<double> xs;
  for (int j = 0; j < hf->height; ++j) {
    const double y = hf->y1 - (j + 0.5) * hf->cell;
    xs.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2& a = ring[k];
      const Vec2& b = ring[(k + 1) % n];
      if ((a.y > y) != (b.y > y)) xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - hf->x0) / hf->cell - 0.5)));
      const int i1 = std::min(hf->width - 1,
                              static_cast<int>(std::floor((xs[k + 1] - hf->x0) / hf->cell - 0.5)));
      for (int i = i0; i <= i1; ++i) hf->band[static_cast<std::size_t>(j) * hf->width + i] = id;
    }
  }
}

}  // namespace

Heightfield BuildHeightfield(const Terrain& t, int res) {
  Heightfield hf;
  if (t.contours.empty()) return hf;
  const Ring& root = t.contours[0].ring;
  double x0 = root[0].x, x1 = x0, y0 = root[0].y, y1 = y0;
  for (const Vec2& v : root) {
    x0 = std::min(x0, v.x);
    x1 = std::max(x1, v.x);
    y0 = std::min(y0, v.y);
    y1 = std::max(y1, v.y);
  }
  const double span = std::max(x1 - x0, y1 - y0);
  hf.cell = span / res;
  hf.width = static_cast<int>(std::ceil((x1 - x0) / hf.cell)) + 2;
  hf.height = static_cast<int>(std::ceil((y1 - y0) / hf.cell)) + 2;
  hf.x0 = x0 - hf.cell;
  hf.y1 = y1 + hf.cell;
  const std::size_t cells = static_cast<std::size_t>(hf.width) * hf.height;
  hf.h.assign(cells, t.contours[0].elevation);
  hf.band.assign(cells, -1);
  for (std::size_t c = 0; c < t.contours.size(); ++c)
    Paint(t.contours[c].ring, static_cast<int>(c), &hf);
  std::vector<int> summit_of(t.contours.size(), -1);
  for (std::size_t s = 0; s < t.summits.size(); ++s)
    summit_of[static_cast<std::size_t>(t.summits[s].contour)] = static_cast<int>(s);
  for (int j = 0; j < hf.height; ++j) {
    for (int i = 0; i < hf.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * hf.width + i;
      const int b = hf.band[k];
      if (b < 0) continue;
      const ContourNode& node = t.contours[static_cast<std::size_t>(b)];
      const Vec2 p = hf.Centre(i, j);
      const double a = RingDistance(node.ring, p);
      double up = 1e300, dh = t.dh;
      if (node.children.empty()) {
        const Summit& s =
            t.summits[static_cast<std::size_t>(summit_of[static_cast<std::size_t>(b)])];
        up = std::sqrt((p.x - s.position.x) * (p.x - s.position.x) +
                       (p.y - s.position.y) * (p.y - s.position.y));
        dh = s.elevation - node.elevation;
      } else {
        for (int c : node.children)
          up = std::min(up, RingDistance(t.contours[static_cast<std::size_t>(c)].ring, p));
      }
      hf.h[k] = a + up > 0 ? node.elevation + dh * a / (a + up) : node.elevation;
    }
  }
  return hf;
}

TerrainStats ComputeStats(const Terrain& t, const Heightfield* hf) {
  TerrainStats s;
  s.contours = static_cast<int>(t.contours.size());
  std::set<int> levels;
  double hmax = t.contours.empty() ? 0 : t.contours[0].elevation;
  for (const ContourNode& c : t.contours) {
    levels.insert(c.level);
    s.vertices += c.ring.size();
    if (c.children.empty()) ++s.peaks;
    if (c.children.size() >= 2) ++s.splits;
    const IRing g = ToGrid(c.ring);
    if (!IsSimple(g) || TwiceArea(g) <= 0) ++s.self_intersections;
    if (c.parent >= 0) {
      const ContourNode& par = t.contours[static_cast<std::size_t>(c.parent)];
      const IRing gp = ToGrid(par.ring);
      if (RingsIntersect(g, gp) || !Inside(gp, g[0])) ++s.nesting_violations;
    }
    // Siblings: disjoint and not nested in each other.
    for (int sib : c.children) {
      for (int other : c.children) {
        if (other <= sib) continue;
        const IRing a = ToGrid(t.contours[static_cast<std::size_t>(sib)].ring);
        const IRing b = ToGrid(t.contours[static_cast<std::size_t>(other)].ring);
        if (RingsIntersect(a, b) || Inside(a, b[0]) || Inside(b, a[0])) ++s.nesting_violations;
      }
    }
  }
  for (const Summit& sm : t.summits) hmax = std::max(hmax, sm.elevation);
  s.levels = static_cast<int>(levels.size());
  const double hmin = t.contours.empty() ? 0 : t.contours[0].elevation;
  s.relief = hmax - hmin;
  if (hf && !hf->h.empty()) {
    double sum = 0, slope_sum = 0;
    std::size_t count = 0, slope_count = 0;
    for (int j = 0; j < hf->height; ++j) {
      for (int i = 0; i < hf->width; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * hf->width + i;
        if (hf->band[k] < 0) continue;
        sum += hf->h[k];
        ++count;
        if (i == 0 || j == 0 || i + 1 == hf->width || j + 1 == hf->height) continue;
        bool interior = true, pit = true;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            if (di == 0 && dj == 0) continue;
            const std::size_t q = static_cast<std::size_t>(j + dj) * hf->width + (i + di);
            if (hf->band[q] < 0) interior = false;
            if (hf->h[q] <= hf->h[k]) pit = false;
          }
        if (!interior) continue;
        if (pit) ++s.pits;
        const double gx = (hf->At(i + 1, j) - hf->At(i - 1, j)) / (2 * hf->cell);
        const double gy = (hf->At(i, j - 1) - hf->At(i, j + 1)) / (2 * hf->cell);
        slope_sum += det::Atan2(std::sqrt(gx * gx + gy * gy), 1.0) * 180.0 / 3.14159265358979323846;
        ++slope_count;
      }
    }
    if (count > 0 && hmax > hmin)
      s.hypsometric_integral = (sum / static_cast<double>(count) - hmin) / (hmax - hmin);
    if (slope_count > 0) s.mean_slope_deg = slope_sum / static_cast<double>(slope_count);
  }
  return s;
}

}  // namespace niwa::terrain
