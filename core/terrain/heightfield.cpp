// Band distance-ratio heightfield (segment grids, and the brute-force twin) and terrain statistics
// (see heightfield.h).
#include "terrain/heightfield.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "math/det_math.h"
#include "terrain/band_fill.h"
#include "terrain/polygon.h"
#include "terrain/segment_grid.h"

namespace niwa::terrain {
namespace {

// Marks the cells whose centres lie inside the ring with `id` (even-odd spans per row; each edge
// adds its crossing to the rows it spans only).
void Paint(const Ring& ring, int id, Heightfield* hf, std::vector<std::vector<double>>* rows) {
  const std::size_t n = ring.size();
  rows->resize(static_cast<std::size_t>(hf->height));
  int jlo = hf->height, jhi = -1;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = ring[k];
    const Vec2& b = ring[(k + 1) % n];
    // Rows j whose centre y = y1 − (j + ½)·cell has (a.y > y) != (b.y > y).
    const double ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
    const int j0 = std::max(0, static_cast<int>(std::floor((hf->y1 - yhi) / hf->cell - 0.5)));
    const int j1 =
        std::min(hf->height - 1, static_cast<int>(std::ceil((hf->y1 - ylo) / hf->cell - 0.5)));
    for (int j = j0; j <= j1; ++j) {
      const double y = hf->y1 - (j + 0.5) * hf->cell;
      if ((a.y > y) == (b.y > y)) continue;
      (*rows)[static_cast<std::size_t>(j)].push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
      jlo = std::min(jlo, j);
      jhi = std::max(jhi, j);
    }
  }
  for (int j = jlo; j <= jhi; ++j) {
    std::vector<double>& xs = (*rows)[static_cast<std::size_t>(j)];
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - hf->x0) / hf->cell - 0.5)));
      const int i1 = std::min(hf->width - 1,
                              static_cast<int>(std::floor((xs[k + 1] - hf->x0) / hf->cell - 0.5)));
      for (int i = i0; i <= i1; ++i) hf->band[static_cast<std::size_t>(j) * hf->width + i] = id;
    }
    xs.clear();
  }
}

// The grid of `res` cells along the root's longer side (heightfield.h).
Heightfield GridFor(const Terrain& t, int res) {
  Heightfield hf;
  const Ring& root = t.contours[0].ring;
  const RingBox box = BoundsOf(root);
  const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  const double span = box.span();
  hf.cell = span / res;
  hf.width = static_cast<int>(std::ceil((x1 - x0) / hf.cell)) + 2;
  hf.height = static_cast<int>(std::ceil((y1 - y0) / hf.cell)) + 2;
  hf.x0 = x0 - hf.cell;
  hf.y1 = y1 + hf.cell;
  return hf;
}

// The grid's bands painted (with the sub-cell slots given to their children when the surface will
// be filled: band_fill.h) and every cell at the lowest elevation.
Heightfield PaintedGrid(const Terrain& t, const Heightfield& grid, bool assign_slots) {
  Heightfield hf;
  hf.width = grid.width;
  hf.height = grid.height;
  hf.x0 = grid.x0;
  hf.y1 = grid.y1;
  hf.cell = grid.cell;
  const std::size_t cells = static_cast<std::size_t>(hf.width) * hf.height;
  hf.h.assign(cells, t.contours[0].elevation);
  hf.band.assign(cells, -1);
  std::vector<std::vector<double>> rows;
  for (std::size_t c = 0; c < t.contours.size(); ++c)
    Paint(t.contours[c].ring, static_cast<int>(c), &hf, &rows);
  if (assign_slots) hf.slot_cells = AssignSubCellSlots(hf.width, hf.height, t, &hf.band);
  return hf;
}

// h = h_C + Δh·a/(a + b) (heightfield.h).
double BandHeight(const ContourNode& node, double a, double up, double dh) {
  return a + up > 0 ? node.elevation + dh * a / (a + up) : node.elevation;
}

// summit_of[c]: the index of the summit on top contour c, −1 for the others.
std::vector<int> SummitOf(const Terrain& t) {
  std::vector<int> summit_of(t.contours.size(), -1);
  for (std::size_t s = 0; s < t.summits.size(); ++s)
    summit_of[static_cast<std::size_t>(t.summits[s].contour)] = static_cast<int>(s);
  return summit_of;
}

// The height of the point p in band b by brute force over the band's rings (the same values as
// the stamps and the segment grids: heightfield.h).
double BruteBandHeight(const Terrain& t, const std::vector<int>& summit_of, int b, Vec2 p) {
  const ContourNode& node = t.contours[static_cast<std::size_t>(b)];
  const double a = RingDistance(node.ring, p);
  double up = 1e300, dh = BandInterval(t, node);
  if (node.children.empty()) {
    const Summit& s = t.summits[static_cast<std::size_t>(summit_of[static_cast<std::size_t>(b)])];
    up = std::sqrt((p.x - s.position.x) * (p.x - s.position.x) +
                   (p.y - s.position.y) * (p.y - s.position.y));
    dh = s.elevation - node.elevation;
  } else {
    for (int c : node.children)
      up = std::min(up, RingDistance(t.contours[static_cast<std::size_t>(c)].ring, p));
  }
  return BandHeight(node, a, up, dh);
}

// The sub-cell slots of the painted map given to their children (band_fill.h) and the moved cells'
// heights taken in their new band. Called only when a cell without a lower neighbour lies on a
// slot island (else there is none: band_fill.h AnyOnASlotIsland, and the map is left as painted).
void AssignSlotsOnSurface(const Terrain& t, Heightfield* hf) {
  const std::vector<int> painted = hf->band;
  hf->slot_cells = AssignSubCellSlots(hf->width, hf->height, t, &hf->band);
  if (hf->slot_cells == 0) return;
  const std::vector<int> summit_of = SummitOf(t);
  for (int j = 0; j < hf->height; ++j)
    for (int i = 0; i < hf->width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * hf->width + i;
      if (hf->band[k] != painted[k])
        hf->h[k] = BruteBandHeight(t, summit_of, hf->band[k], hf->Centre(i, j));
    }
}

// A half-plane ax·x + ay·y + c ≥ 0.
struct HalfPlane {
  double ax, ay, c;
};

// Calls visit(k, centre) for the cells of rows ylo..yhi (y, metres) whose centres lie within r of
// `disk` (when r > 0) and in every half-plane: a convex region, its x-range found row by row.
// The ends are widened by a hair for the rounding (a cell too many only costs a distance).
template <typename Visit>
void ForCellsIn(const Heightfield& hf, double ylo, double yhi, const HalfPlane* planes, int np,
                Vec2 disk, double r, const Visit& visit) {
  const double hair = 1e-9 * (std::fabs(ylo) + std::fabs(yhi) + r + hf.cell) + 1e-9;
  const double jlo = std::ceil((hf.y1 - yhi - hair) / hf.cell - 0.5);
  const double jhi = std::floor((hf.y1 - ylo + hair) / hf.cell - 0.5);
  const int j0 = static_cast<int>(std::max(0.0, jlo));
  const int j1 = static_cast<int>(std::min(static_cast<double>(hf.height - 1), jhi));
  const double xmax = static_cast<double>(hf.width - 1);
  for (int j = j0; j <= j1; ++j) {
    const double y = hf.y1 - (j + 0.5) * hf.cell;
    double lo = -1e300, hi = 1e300;
    if (r > 0) {
      const double dy = y - disk.y;
      if (dy * dy > r * r) continue;
      const double w = std::sqrt(r * r - dy * dy);
      lo = disk.x - w;
      hi = disk.x + w;
    }
    bool empty = false;
    for (int q = 0; q < np; ++q) {
      const double rest = planes[q].ay * y + planes[q].c;
      if (planes[q].ax > 0) {
        lo = std::max(lo, -rest / planes[q].ax);
      } else if (planes[q].ax < 0) {
        hi = std::min(hi, -rest / planes[q].ax);
      } else if (rest < 0) {
        empty = true;
      }
    }
    if (empty || lo > hi) continue;
    const double pad = 1e-9 * (std::fabs(lo) + std::fabs(hi) + r + hf.cell) + 1e-9;
    const double ilo = std::max(0.0, std::ceil((lo - pad - hf.x0) / hf.cell - 0.5));
    const double ihi = std::min(xmax, std::floor((hi + pad - hf.x0) / hf.cell - 0.5));
    if (ilo > ihi) continue;
    const std::size_t row = static_cast<std::size_t>(j) * hf.width;
    for (int i = static_cast<int>(ilo); i <= static_cast<int>(ihi); ++i)
      visit(row + static_cast<std::size_t>(i), hf.Centre(i, j));
  }
}

// The least squared distances of the cells of band `id` (into A) and of band `parent` (into B)
// to the ring's segments, for every cell whose nearest segment lies within ρ (BandSurfaceOn says
// which cells each segment stamps and why that is exact).
void StampRing(const Ring& ring, int id, int parent, double rho, Heightfield* hf,
               std::vector<double>* A, std::vector<double>* B) {
  const std::size_t n = ring.size();
  if (n < 2) return;
  // The margin m past a segment's ends: a twentieth of a cell, and never under the rounding of
  // the coordinates' scale.
  const RingBox box = BoundsOf(ring);
  const double scale =
      std::max({std::fabs(box.x0), std::fabs(box.x1), std::fabs(box.y0), std::fabs(box.y1), rho});
  const double m = std::max(0.05 * hf->cell, 1e-6 * scale);
  std::vector<double> len(n);
  std::vector<Vec2> u(n);
  for (std::size_t s = 0; s < n; ++s) {
    const Vec2& a = ring[s];
    const Vec2& e = ring[(s + 1) % n];
    len[s] = std::sqrt((e.x - a.x) * (e.x - a.x) + (e.y - a.y) * (e.y - a.y));
    u[s] = len[s] > 0 ? Vec2{(e.x - a.x) / len[s], (e.y - a.y) / len[s]} : Vec2{0, 0};
  }
  const std::vector<int>& band = hf->band;
  const auto stamp = [&](std::size_t k, const Vec2& p, std::size_t s) {
    const int b = band[k];
    if (b != id && (b != parent || parent < 0)) return;
    const double d2 = SegmentDist2(p, ring[s], ring[(s + 1) % n]);
    double& slot = b == id ? (*A)[k] : (*B)[k];
    if (d2 < slot) slot = d2;
  };
  for (std::size_t s = 0; s < n; ++s) {
    const Vec2& a = ring[s];
    const Vec2& e = ring[(s + 1) % n];
    const std::size_t prev = (s + n - 1) % n, next = (s + 1) % n;
    const auto one = [&](std::size_t k, const Vec2& p) { stamp(k, p, s); };
    if (len[prev] < m || len[next] < m || len[s] < m) {
      // The whole capsule: the cells within ρ of the segment.
      // Its box widened by ρ, the cells then tested by distance.
      const HalfPlane sides[2] = {{1, 0, rho - std::min(a.x, e.x)},
                                  {-1, 0, rho + std::max(a.x, e.x)}};
      ForCellsIn(*hf, std::min(a.y, e.y) - rho, std::max(a.y, e.y) + rho, sides, 2, Vec2{0, 0}, 0,
                 [&](std::size_t k, const Vec2& p) {
                   if (SegmentDist2(p, a, e) <= rho * rho) one(k, p);
                 });
    } else {
      // The slab: −m ≤ (x − a)·u ≤ L + m, |(x − a)·nrm| ≤ ρ.
      const Vec2 v = u[s], nrm{-v.y, v.x};
      const double ua = v.x * a.x + v.y * a.y, na = nrm.x * a.x + nrm.y * a.y;
      const HalfPlane slab[4] = {{v.x, v.y, m - ua},
                                 {-v.x, -v.y, len[s] + m + ua},
                                 {-nrm.x, -nrm.y, rho + na},
                                 {nrm.x, nrm.y, rho - na}};
      const double ext = std::fabs(nrm.y) * rho + std::fabs(v.y) * m;
      ForCellsIn(*hf, std::min(a.y, e.y) - ext, std::max(a.y, e.y) + ext, slab, 4, Vec2{0, 0}, 0,
                 one);
    }
    // The wedge at e, past this segment's end and before the next's start: both stamp it.
    const Vec2 w = u[next];
    const HalfPlane wedge[2] = {{u[s].x, u[s].y, m - (u[s].x * e.x + u[s].y * e.y)},
                                {-w.x, -w.y, m + (w.x * e.x + w.y * e.y)}};
    ForCellsIn(*hf, e.y - rho, e.y + rho, wedge, 2, e, rho, [&](std::size_t k, const Vec2& p) {
      stamp(k, p, s);
      stamp(k, p, next);
    });
  }
}

// The band heights on `grid` (heightfield.h), before any fill.
Heightfield BandSurfaceOn(const Terrain& t, const Heightfield& grid) {
  Heightfield hf = PaintedGrid(t, grid, false);
  const std::size_t nc = t.contours.size();
  const std::size_t cells = hf.h.size();
  // Stamping: every segment of contour C writes its squared distance into cells near it that lie
  // in C's band (their a) or in C's parent's band (their b). A cell whose least stamped value is
  // within ρ has its exact nearest segment among the stamped ones; the others (wide bands) ask a
  // SegmentGrid (its buckets ρ wide: those cells lie ρ or more from the ring they ask about).
  // ρ = 1.5·d: neighbouring contours are about d apart, up to c·d in valleys (measured on the
  // lobes7 and the page's drawn mountain: d left 6-8 % of the cells to the grids, 1.5·d costs
  // 6-8 % fewer instructions in all, 2·d and 3·d more).
  //
  // Which cells a segment s = (p, q) stamps (StampRing): a point x whose nearest segment is s
  // either projects onto s (its slab, |(x − p)·n| ≤ ρ, (x − p)·u in [−m, L + m]) or lies past
  // an end, say q, where it is then also past the start of the next segment s' (the wedge
  // (x − q)·u ≥ −m, (x − q)·u' ≤ m within ρ of q): were it more than m along s', s' would be
  // nearer by at least min(m, L')². So s stamps its slab and both segments stamp each vertex's
  // wedge, about one distance a cell and ring side instead of the 2ρ/L of a capsule each (the
  // seed resampled at d/4 made L ≈ d/4, and the capsules cost 2× the whole surface before). A
  // segment next to one shorter than m stamps its whole capsule (the argument needs L' ≥ m).
  // The margin m (a twentieth of a cell) dwarfs the rounding of the distances (m² ≫ 1e−9 m²), so
  // the least stamped value is the brute force's bit for bit (the twin test checks it).
  const double rho = t.d > 0 ? 1.5 * t.d : 4 * hf.cell;
  const double rho_in = rho - (rho * 1e-6 + 1e-6);  // a margin for the index rounding
  std::vector<double> A(cells, 1e300), B(cells, 1e300);
  for (std::size_t c = 0; c < nc && rho_in > 0; ++c)
    StampRing(t.contours[c].ring, static_cast<int>(c), t.contours[c].parent, rho, &hf, &A, &B);
  // The fallback grids, made when first needed: a grid over a contour's own ring (a) and one over
  // its children's rings (b).
  std::vector<SegmentGrid> own(nc), kids(nc);
  std::vector<char> own_built(nc, 0), kids_built(nc, 0);
  std::vector<int> summit_of(nc, -1);
  for (std::size_t s = 0; s < t.summits.size(); ++s)
    summit_of[static_cast<std::size_t>(t.summits[s].contour)] = static_cast<int>(s);
  std::vector<int> hint_a(nc, -1), hint_b(nc, -1);
  const double limit = rho_in > 0 ? rho_in * rho_in : -1;
  for (int j = 0; j < hf.height; ++j) {
    for (int i = 0; i < hf.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * hf.width + i;
      const int b = hf.band[k];
      if (b < 0) continue;
      const std::size_t ub = static_cast<std::size_t>(b);
      const ContourNode& node = t.contours[ub];
      const Vec2 p = hf.Centre(i, j);
      double a;
      if (A[k] <= limit) {
        a = std::sqrt(A[k]);
      } else {
        if (!own_built[ub]) {
          own[ub].AddRing(node.ring);
          own[ub].Build(rho);
          own_built[ub] = 1;
        }
        a = own[ub].Distance(p, &hint_a[ub]);
      }
      double up, dh = BandInterval(t, node);
      if (node.children.empty()) {
        const Summit& s = t.summits[static_cast<std::size_t>(summit_of[ub])];
        up = std::sqrt((p.x - s.position.x) * (p.x - s.position.x) +
                       (p.y - s.position.y) * (p.y - s.position.y));
        dh = s.elevation - node.elevation;
      } else if (B[k] <= limit) {
        up = std::sqrt(B[k]);
      } else {
        if (!kids_built[ub]) {
          for (int c : node.children)
            kids[ub].AddRing(t.contours[static_cast<std::size_t>(c)].ring);
          kids[ub].Build(rho);
          kids_built[ub] = 1;
        }
        up = kids[ub].Distance(p, &hint_b[ub]);
      }
      hf.h[k] = BandHeight(node, a, up, dh);
    }
  }
  return hf;
}

}  // namespace

Heightfield BuildHeightfield(const Terrain& t, int res, bool fill_depressions) {
  if (t.contours.empty()) return Heightfield();
  return BuildHeightfieldOn(t, GridFor(t, res), fill_depressions);
}

Heightfield BuildHeightfieldOn(const Terrain& t, const Heightfield& grid, bool fill_depressions) {
  if (t.contours.empty()) return Heightfield();
  Heightfield hf = BandSurfaceOn(t, grid);  // its stamped distances freed before the fill
  // The cells without a lower neighbour decide both steps: with none there is no slot island and
  // nothing to raise, and only when one lies on a slot island are the slots assigned (each
  // island holds one: band_fill.h).
  if (fill_depressions) {
    const std::vector<std::uint32_t> minima =
        CellsWithoutLowerNeighbour(hf.width, hf.height, hf.band, hf.h);
    if (!minima.empty()) {
      if (AnyOnASlotIsland(hf.width, hf.height, t, hf.band, minima)) AssignSlotsOnSurface(t, &hf);
      FillHeightfieldWithinBands(t, &hf);
    }
  }
  return hf;
}

Heightfield BuildHeightfieldBruteForce(const Terrain& t, int res, bool fill_depressions) {
  if (t.contours.empty()) return Heightfield();
  // The slots always assigned here (no gate): the twin of BuildHeightfieldOn's gated step.
  Heightfield hf = PaintedGrid(t, GridFor(t, res), fill_depressions);
  const std::vector<int> summit_of = SummitOf(t);
  for (int j = 0; j < hf.height; ++j) {
    for (int i = 0; i < hf.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * hf.width + i;
      if (hf.band[k] >= 0) hf.h[k] = BruteBandHeight(t, summit_of, hf.band[k], hf.Centre(i, j));
    }
  }
  if (fill_depressions) FillHeightfieldWithinBands(t, &hf);
  return hf;
}

TerrainStats ComputeStats(const Terrain& t, const Heightfield* hf) {
  TerrainStats s;
  s.contours = static_cast<int>(t.contours.size());
  std::set<int> levels;
  double hmax = t.contours.empty() ? 0 : t.contours[0].elevation;
  // Every ring on the grid once (a parent and its children are each tested several times).
  std::vector<IRing> grid(t.contours.size());
  for (std::size_t c = 0; c < t.contours.size(); ++c) grid[c] = ToGrid(t.contours[c].ring);
  for (std::size_t ci = 0; ci < t.contours.size(); ++ci) {
    const ContourNode& c = t.contours[ci];
    levels.insert(c.level);
    s.vertices += c.ring.size();
    if (c.children.empty()) ++s.peaks;
    if (c.children.size() >= 2) ++s.splits;
    const IRing& g = grid[ci];
    if (!IsSimple(g) || TwiceArea(g) <= 0) ++s.self_intersections;
    // Children: inside this contour, apart from it.
    if (!c.children.empty()) {
      const EdgeIndex edges(g);
      for (int child : c.children) {
        const IRing& gc = grid[static_cast<std::size_t>(child)];
        if (edges.Meets(gc) || !Inside(g, gc[0])) ++s.nesting_violations;
      }
    }
    // Siblings: disjoint and not nested in each other (only those whose boxes meet can fail).
    std::vector<IBox> boxes;
    boxes.reserve(c.children.size());
    for (int sib : c.children) boxes.push_back(BoxOf(grid[static_cast<std::size_t>(sib)]));
    for (const auto& [i, j] : MeetingBoxPairs(boxes)) {
      const IRing& a = grid[static_cast<std::size_t>(c.children[static_cast<std::size_t>(i)])];
      const IRing& b = grid[static_cast<std::size_t>(c.children[static_cast<std::size_t>(j)])];
      if (RingsIntersect(a, b) || Inside(a, b[0]) || Inside(b, a[0])) ++s.nesting_violations;
    }
  }
  for (const Summit& sm : t.summits) hmax = std::max(hmax, sm.elevation);
  s.levels = static_cast<int>(levels.size());
  const double hmin = t.contours.empty() ? 0 : t.contours[0].elevation;
  s.relief = hmax - hmin;
  if (hf && !hf->h.empty()) {
    double sum = 0, slope_sum = 0;
    std::size_t count = 0, slope_count = 0;
    // Gradient lengths of the interior cells in order; their angles are taken two at a time
    // (det::AtanOfNonNegativeInPlace: Atan2(g, 1)'s bits) and summed in the same order.
    std::vector<double> gradient;
    gradient.reserve(hf->h.size());
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
        gradient.push_back(std::sqrt(gx * gx + gy * gy));
        ++slope_count;
      }
    }
    det::AtanOfNonNegativeInPlace(gradient.data(), gradient.size());
    for (const double a : gradient) slope_sum += a * 180.0 / 3.14159265358979323846;
    if (count > 0 && hmax > hmin)
      s.hypsometric_integral = (sum / static_cast<double>(count) - hmin) / (hmax - hmin);
    if (slope_count > 0) s.mean_slope_deg = slope_sum / static_cast<double>(slope_count);
  }
  return s;
}

}  // namespace niwa::terrain
