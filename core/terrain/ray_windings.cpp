// Winding sums along +x rays through a cell grid and a Fenwick tree; see ray_windings.h.
#include "terrain/ray_windings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace niwa::terrain {
namespace {

bool Crosses(const RayEdge& e, const IPoint& p) {
  return e.lo.y <= p.y && p.y < e.hi.y && Orient(e.lo, e.hi, p) > 0;
}

struct Piece {
  int64_t y0, y1;  // the half-open y range of the edge in its row
  uint32_t edge;
  int32_t c0;  // the first column it covers
};
struct PieceCols {
  int64_t c0, c1;  // the columns a piece covers
};

struct Grid {
  int64_t x0 = 0, y0 = 0, cw = 1, ch = 1, cols = 1, rows = 1;
  int64_t Col(int64_t x) const { return std::clamp<int64_t>((x - x0) / cw, 0, cols - 1); }
  int64_t Row(int64_t y) const { return std::clamp<int64_t>((y - y0) / ch, 0, rows - 1); }
  std::size_t Cell(int64_t row, int64_t col) const {
    return static_cast<std::size_t>(row * cols + col);
  }
};

Grid MakeGrid(const std::vector<RayEdge>& edges, const std::vector<IPoint>& points) {
  int64_t x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
  auto take = [&](const IPoint& p) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  };
  for (const IPoint& p : points) take(p);
  for (const RayEdge& e : edges) {
    take(e.lo);
    take(e.hi);
  }
  const double n = static_cast<double>(edges.size() + points.size());
  const double w = static_cast<double>(x1 - x0) + 1, h = static_cast<double>(y1 - y0) + 1;
  const double side = std::max(1.0, std::sqrt(w * h / n));
  const double cap = 2 * n + 1;
  Grid g;
  g.x0 = x0;
  g.y0 = y0;
  const double cols = std::clamp(std::ceil(w / side), 1.0, cap);
  const double rows = std::clamp(std::ceil(h / side), 1.0, cap);
  g.cw = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(w / cols)));
  g.ch = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(h / rows)));
  g.cols = (x1 - x0) / g.cw + 1;
  g.rows = (y1 - y0) / g.ch + 1;
  return g;
}

// Calls f(piece) for each row piece of e (rows crossed by [lo.y, hi.y)), its columns widened to
// hold the segment's x over the piece's y range.
template <typename F>
void ForEachPiece(const Grid& g, const RayEdge& e, std::size_t index, F&& f) {
  const int64_t r0 = g.Row(e.lo.y), r1 = g.Row(e.hi.y - 1);
  const double dx = static_cast<double>(e.hi.x - e.lo.x), dy = static_cast<double>(e.hi.y - e.lo.y);
  const int64_t ex0 = std::min(e.lo.x, e.hi.x), ex1 = std::max(e.lo.x, e.hi.x);
  for (int64_t r = r0; r <= r1; ++r) {
    const int64_t ya = std::max(e.lo.y, g.y0 + r * g.ch);
    const int64_t yb = std::min(e.hi.y, g.y0 + (r + 1) * g.ch);  // exclusive
    if (ya >= yb) continue;
    const double xa = static_cast<double>(e.lo.x) + static_cast<double>(ya - e.lo.y) * dx / dy;
    const double xb = static_cast<double>(e.lo.x) + static_cast<double>(yb - e.lo.y) * dx / dy;
    const int64_t lo = std::max(ex0, static_cast<int64_t>(std::floor(std::min(xa, xb))) - 1);
    const int64_t hi = std::min(ex1, static_cast<int64_t>(std::ceil(std::max(xa, xb))) + 1);
    const int64_t c0 = g.Col(lo);
    f(Piece{ya, yb, static_cast<uint32_t>(index), static_cast<int32_t>(c0)},
      PieceCols{c0, g.Col(hi)}, r);
  }
}

}  // namespace

double RayWindings(const std::vector<RayEdge>& edges, const std::vector<IPoint>& points,
                   double max_work, std::vector<int>* out, RayWindingsFill fill) {
  if (points.empty()) return 0;
  if (edges.empty()) {
    if (out != nullptr) out->assign(points.size(), 0);
    return static_cast<double>(points.size());
  }
  const Grid g = MakeGrid(edges, points);
  auto over = [&](double work) { return max_work >= 0 && work > max_work; };
  // Count pass: pieces and cell entries, then each point's exact tests (its cell's entries).
  std::vector<uint32_t> entries(static_cast<std::size_t>(g.rows * g.cols) + 1, 0);
  // Pieces a row, for the row scan below (not when only counting: the estimates' path).
  std::vector<std::size_t> row_at(out != nullptr ? static_cast<std::size_t>(g.rows) + 1 : 0, 0);
  double work = static_cast<double>(points.size());
  std::size_t pieces = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    ForEachPiece(g, edges[i], i, [&](const Piece&, const PieceCols& pc, int64_t row) {
      ++pieces;
      if (out != nullptr) ++row_at[static_cast<std::size_t>(row) + 1];
      work += 1 + static_cast<double>(pc.c1 - pc.c0 + 1);
      if (over(work)) return;
      for (int64_t c = pc.c0; c <= pc.c1; ++c) ++entries[g.Cell(row, c)];
    });
    if (over(work)) return work;
  }
  for (const IPoint& p : points) work += entries[g.Cell(g.Row(p.y), g.Col(p.x))];
  if (out == nullptr || over(work)) return work;
  // The row scan: each point tests the pieces of its row exactly (an edge crossing a point's ray
  // has a piece in the point's row), chosen when that is at most kRowScanFactor times the work.
  constexpr double kRowScanFactor = 4;
  double row_tests = 0;
  for (const IPoint& p : points)
    row_tests += static_cast<double>(row_at[static_cast<std::size_t>(g.Row(p.y)) + 1]);
  if (fill == RayWindingsFill::kRows ||
      (fill == RayWindingsFill::kAuto && row_tests <= kRowScanFactor * work)) {
    std::vector<uint32_t>().swap(entries);  // the cells are not needed by the row scan
    for (std::size_t r = 0; r + 1 < row_at.size(); ++r) row_at[r + 1] += row_at[r];
    std::vector<uint32_t> by_row(pieces);
    for (std::size_t i = 0; i < edges.size(); ++i)
      ForEachPiece(g, edges[i], i, [&](const Piece&, const PieceCols&, int64_t row) {
        by_row[row_at[static_cast<std::size_t>(row)]++] = static_cast<uint32_t>(i);
      });  // row_at[r] is now row r's end, row_at[r - 1] its start
    out->assign(points.size(), 0);
    for (std::size_t q = 0; q < points.size(); ++q) {
      const IPoint& p = points[q];
      const std::size_t r = static_cast<std::size_t>(g.Row(p.y));
      int64_t w = 0;
      for (std::size_t m = r == 0 ? 0 : row_at[r - 1]; m < row_at[r]; ++m) {
        const RayEdge& e = edges[by_row[m]];
        if (Crosses(e, p)) w += e.weight;
      }
      (*out)[q] = static_cast<int>(w);
    }
    return work;
  }
  std::vector<std::size_t>().swap(row_at);
  // The cells' lists (compressed rows: `entries` becomes each cell's end, then, filled backwards,
  // its start) and the pieces by first column.
  for (std::size_t k = 1; k < entries.size(); ++k) entries[k] += entries[k - 1];
  std::vector<uint32_t> list(entries.back());
  std::vector<Piece> all;
  all.reserve(pieces);
  std::vector<int64_t> keys;
  keys.reserve(2 * pieces);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    ForEachPiece(g, edges[i], i, [&](const Piece& p, const PieceCols& pc, int64_t row) {
      for (int64_t c = pc.c0; c <= pc.c1; ++c)
        list[--entries[g.Cell(row, c)]] = static_cast<uint32_t>(i);
      all.push_back(p);
      keys.push_back(p.y0);
      keys.push_back(p.y1);
    });
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<std::size_t> piece_at(static_cast<std::size_t>(g.cols) + 1, 0);
  for (const Piece& p : all) ++piece_at[static_cast<std::size_t>(p.c0) + 1];
  for (std::size_t c = 0; c < static_cast<std::size_t>(g.cols); ++c) piece_at[c + 1] += piece_at[c];
  std::vector<uint32_t> by_col(all.size());
  {
    std::vector<std::size_t> next(piece_at.begin(), piece_at.end() - 1);
    for (std::size_t k = 0; k < all.size(); ++k)
      by_col[next[static_cast<std::size_t>(all[k].c0)]++] = static_cast<uint32_t>(k);
  }
  std::vector<std::size_t> point_at(static_cast<std::size_t>(g.cols) + 1, 0);
  for (const IPoint& p : points) ++point_at[static_cast<std::size_t>(g.Col(p.x)) + 1];
  for (std::size_t c = 0; c < static_cast<std::size_t>(g.cols); ++c) point_at[c + 1] += point_at[c];
  std::vector<std::size_t> points_by_col(points.size());
  {
    std::vector<std::size_t> next(point_at.begin(), point_at.end() - 1);
    for (std::size_t k = 0; k < points.size(); ++k)
      points_by_col[next[static_cast<std::size_t>(g.Col(points[k].x))]++] = k;
  }
  // Fenwick tree over the keys: +weight at a piece's y0, −weight at its y1; the prefix sum to a
  // point's y is the weight of the pieces (inserted so far) whose [y0, y1) holds it.
  std::vector<int64_t> tree(keys.size() + 1, 0);
  auto add = [&](int64_t key, int64_t v) {
    std::size_t k =
        static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin()) +
        1;
    for (; k < tree.size(); k += k & (~k + 1)) tree[k] += v;
  };
  auto prefix = [&](int64_t y) {
    std::size_t k =
        static_cast<std::size_t>(std::upper_bound(keys.begin(), keys.end(), y) - keys.begin());
    int64_t s = 0;
    for (; k > 0; k -= k & (~k + 1)) s += tree[k];
    return s;
  };
  out->assign(points.size(), 0);
  for (int64_t c = g.cols - 1; c >= 0; --c) {
    const std::size_t cc = static_cast<std::size_t>(c);
    for (std::size_t k = point_at[cc]; k < point_at[cc + 1]; ++k) {
      const std::size_t q = points_by_col[k];
      const IPoint& p = points[q];
      int64_t w = prefix(p.y);  // pieces wholly right of this column
      const std::size_t cell = g.Cell(g.Row(p.y), c);
      for (std::size_t m = entries[cell]; m < entries[cell + 1]; ++m) {
        const RayEdge& e = edges[list[m]];
        if (Crosses(e, p)) w += e.weight;
      }
      (*out)[q] = static_cast<int>(w);
    }
    for (std::size_t k = piece_at[cc]; k < piece_at[cc + 1]; ++k) {
      const Piece& p = all[by_col[k]];
      const int weight = edges[p.edge].weight;
      add(p.y0, weight);
      add(p.y1, -weight);
    }
  }
  return work;
}

std::vector<int> RayWindingsBruteForce(const std::vector<RayEdge>& edges,
                                       const std::vector<IPoint>& points) {
  std::vector<int> out(points.size(), 0);
  for (std::size_t k = 0; k < points.size(); ++k)
    for (const RayEdge& e : edges)
      if (Crosses(e, points[k])) out[k] += e.weight;
  return out;
}

}  // namespace niwa::terrain
