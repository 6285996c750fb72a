// Band-capped depression filling: priority-flood and its Planchon-Darboux twin (see band_fill.h).
#include "terrain/band_fill.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "terrain/heightfield.h"

namespace niwa::terrain {
namespace {

constexpr int kDi[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kDj[8] = {-1, -1, -1, 0, 0, 1, 1, 1};

// Neighbour q (0..7) of cell k at (i, j) in *n, false when it lies off the grid.
bool Neighbour(int width, int height, int i, int j, int q, std::size_t* n) {
  const int ni = i + kDi[q], nj = j + kDj[q];
  if (ni < 0 || nj < 0 || ni >= width || nj >= height) return false;
  *n = static_cast<std::size_t>(nj) * width + ni;
  return true;
}

// Cells whose filled height w is above their own h.
std::size_t CountRaised(const std::vector<double>& h, const std::vector<double>& w) {
  std::size_t raised = 0;
  for (std::size_t k = 0; k < h.size(); ++k)
    if (w[k] > h[k]) ++raised;
  return raised;
}

bool IsOutlet(int width, int height, const std::vector<int>& band, int i, int j) {
  return band[static_cast<std::size_t>(j) * width + i] < 0 || i == 0 || j == 0 || i + 1 == width ||
         j + 1 == height;
}

// What a neighbour at W offers cell k: max(h, min(top, W)) (band_fill.h).
double Offer(const std::vector<double>& h, const std::vector<int>& band,
             const std::vector<double>& top, std::size_t k, double w) {
  return std::max(h[k], std::min(top[static_cast<std::size_t>(band[k])], w));
}

}  // namespace

std::size_t FillWithinBands(int width, int height, const std::vector<int>& band,
                            const std::vector<double>& top, std::vector<double>* h) {
  const std::size_t cells = static_cast<std::size_t>(width) * height;
  if (cells == 0) return 0;
  const std::vector<double>& h0 = *h;
  // 0. If every cell off the outlets has a strictly lower neighbour, every one has a strictly
  // descending path to an outlet and nothing is raised: one raster scan (off the outlets all
  // cells are inside the grid's edge, so the neighbours are fixed offsets).
  bool any_minimum = false;
  for (int j = 1; j + 1 < height && !any_minimum; ++j) {
    for (int i = 1; i + 1 < width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * width + i;
      if (band[k] < 0) continue;
      bool lower = false;
      for (int q = 0; q < 8 && !lower; ++q)
        lower = h0[k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q]] < h0[k];
      if (!lower) {
        any_minimum = true;
        break;
      }
    }
  }
  if (!any_minimum) return 0;
  // 1. The cells with a strictly descending 8-path to an outlet keep W = h (the path's maximum is
  // their own height): a breadth-first search up from the outlets, no heap. On a surface without
  // depressions that is every cell, and the fill ends here.
  std::vector<char> drains(cells, 0);
  std::vector<std::uint32_t> fifo;
  fifo.reserve(cells);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      if (IsOutlet(width, height, band, i, j)) {
        const std::size_t k = static_cast<std::size_t>(j) * width + i;
        drains[k] = 1;
        fifo.push_back(static_cast<std::uint32_t>(k));
      }
  for (std::size_t r = 0; r < fifo.size(); ++r) {
    const std::size_t k = fifo[r];
    const int i = static_cast<int>(k % static_cast<std::size_t>(width));
    const int j = static_cast<int>(k / static_cast<std::size_t>(width));
    for (int q = 0; q < 8; ++q) {
      std::size_t n;
      if (!Neighbour(width, height, i, j, q, &n)) continue;
      if (!drains[n] && h0[n] > h0[k]) {
        drains[n] = 1;
        fifo.push_back(static_cast<std::uint32_t>(n));
      }
    }
  }
  if (fifo.size() == cells) return 0;
  fifo = std::vector<std::uint32_t>();
  // 2. The rest (in or above a depression): the flood, seeded by the draining cells next to them.
  // Every walk from an outlet into the rest enters it through such a cell, whose W = h is final,
  // so the result is the whole grid's flood (the Planchon-Darboux twin checks it).
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> w(h0);
  using Entry = std::pair<double, std::uint32_t>;  // (W, cell index): the heap's total order
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (std::size_t k = 0; k < cells; ++k)
    if (!drains[k]) w[k] = inf;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * width + i;
      if (!drains[k]) continue;
      for (int q = 0; q < 8; ++q) {
        std::size_t n;
        if (!Neighbour(width, height, i, j, q, &n)) continue;
        if (!drains[n]) {
          open.push({w[k], static_cast<std::uint32_t>(k)});
          break;
        }
      }
    }
  }
  while (!open.empty()) {
    const Entry e = open.top();
    open.pop();
    const std::size_t k = e.second;
    if (e.first != w[k]) continue;  // superseded by a lower W
    const int i = static_cast<int>(k % static_cast<std::size_t>(width));
    const int j = static_cast<int>(k / static_cast<std::size_t>(width));
    for (int q = 0; q < 8; ++q) {
      std::size_t n;
      if (!Neighbour(width, height, i, j, q, &n)) continue;
      if (drains[n]) continue;  // outlets and draining cells keep W = h
      const double offer = Offer(h0, band, top, n, e.first);
      if (offer < w[n]) {
        w[n] = offer;
        open.push({offer, static_cast<std::uint32_t>(n)});
      }
    }
  }
  // Every cell is 8-connected to the grid's edge, so none is left at ∞.
  const std::size_t raised = CountRaised(h0, w);
  *h = std::move(w);
  return raised;
}

std::size_t FillWithinBandsPlanchonDarboux(int width, int height, const std::vector<int>& band,
                                           const std::vector<double>& top, std::vector<double>* h) {
  const std::vector<double>& h0 = *h;
  std::vector<double> w(h0);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * width + i;
      if (!IsOutlet(width, height, band, i, j))
        w[k] = std::max(h0[k], top[static_cast<std::size_t>(band[k])]);
    }
  for (bool changed = true; changed;) {
    changed = false;
    for (int j = 0; j < height; ++j) {
      for (int i = 0; i < width; ++i) {
        if (IsOutlet(width, height, band, i, j)) continue;
        const std::size_t k = static_cast<std::size_t>(j) * width + i;
        for (int q = 0; q < 8; ++q) {
          const std::size_t n = static_cast<std::size_t>(j + kDj[q]) * width + (i + kDi[q]);
          const double offer = Offer(h0, band, top, k, w[n]);
          if (offer < w[k]) {
            w[k] = offer;
            changed = true;
          }
        }
      }
    }
  }
  const std::size_t raised = CountRaised(h0, w);
  *h = std::move(w);
  return raised;
}

std::vector<double> BandTops(const Terrain& t) {
  std::vector<double> top(t.contours.size());
  for (std::size_t c = 0; c < t.contours.size(); ++c) top[c] = t.contours[c].elevation + t.dh;
  for (const Summit& s : t.summits) {
    const ContourNode& node = t.contours[static_cast<std::size_t>(s.contour)];
    top[static_cast<std::size_t>(s.contour)] = node.elevation + (s.elevation - node.elevation);
  }
  return top;
}

void FillHeightfieldWithinBands(const Terrain& t, Heightfield* hf) {
  hf->cells_filled = FillWithinBands(hf->width, hf->height, hf->band, BandTops(t), &hf->h);
}

}  // namespace niwa::terrain
