// Band-capped depression filling: priority-flood and its Planchon-Darboux twin (see band_fill.h).
#include "terrain/band_fill.h"

#include <algorithm>
#include <cstddef>
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
// Grows the breadth-first queue `fifo` (its seeds already marked) to every cell reachable by
// 8-neighbour steps k -> n with n unmarked and accept(k, n), marking each as it is queued.
template <typename Accept>
void FloodFrom(int width, int height, std::vector<std::uint32_t>* fifo, std::vector<char>* mark,
               Accept accept) {
  for (std::size_t r = 0; r < fifo->size(); ++r) {
    const std::size_t k = (*fifo)[r];
    const int i = static_cast<int>(k % static_cast<std::size_t>(width));
    const int j = static_cast<int>(k / static_cast<std::size_t>(width));
    for (int q = 0; q < 8; ++q) {
      std::size_t n;
      if (!Neighbour(width, height, i, j, q, &n)) continue;
      if (!(*mark)[n] && accept(k, n)) {
        (*mark)[n] = 1;
        fifo->push_back(static_cast<std::uint32_t>(n));
      }
    }
  }
}

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

// The contour tree as pre-order intervals: d is a strict descendant of c iff
// pre[c] < pre[d] < end[c].
struct TreeOrder {
  std::vector<int> pre, end;
  explicit TreeOrder(const Terrain& t) : pre(t.contours.size()), end(t.contours.size()) {
    int next = 0;
    std::vector<std::pair<int, std::size_t>> stack;  // (contour, next child to visit)
    for (std::size_t r = 0; r < t.contours.size(); ++r) {
      if (t.contours[r].parent >= 0) continue;
      stack.push_back({static_cast<int>(r), 0});
      pre[r] = next++;
      while (!stack.empty()) {
        auto& [c, child] = stack.back();
        const std::vector<int>& kids = t.contours[static_cast<std::size_t>(c)].children;
        if (child < kids.size()) {
          const int k = kids[child++];
          pre[static_cast<std::size_t>(k)] = next++;
          stack.push_back({k, 0});
        } else {
          end[static_cast<std::size_t>(c)] = next;
          stack.pop_back();
        }
      }
    }
  }
  bool StrictlyInside(int d, int c) const {
    if (d < 0) return false;
    const int p = pre[static_cast<std::size_t>(d)];
    return pre[static_cast<std::size_t>(c)] < p && p < end[static_cast<std::size_t>(c)];
  }
};

// Whether band-b cell (i, j) touches the rest of the world: it lies on the grid's edge or one of
// its 8 neighbours is neither in band b nor in a strict descendant of b.
bool Anchored(int width, int height, const std::vector<int>& band, const TreeOrder& tree, int i,
              int j) {
  if (i == 0 || j == 0 || i + 1 == width || j + 1 == height) return true;
  const std::size_t k = static_cast<std::size_t>(j) * width + i;
  const int b = band[k];
  for (int q = 0; q < 8; ++q) {
    const int bn = band[k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q]];
    if (bn != b && !tree.StrictlyInside(bn, b)) return true;
  }
  return false;
}

// The child of b whose subtree holds d (a strict descendant of b).
int ChildOnPath(const Terrain& t, int b, int d) {
  while (t.contours[static_cast<std::size_t>(d)].parent != b)
    d = t.contours[static_cast<std::size_t>(d)].parent;
  return d;
}

// The child an island of band b goes to: the one holding most (cell, outer neighbour) pairs, ties
// to the lower index (band_fill.h). `cells` are the island's cells.
int IslandChild(int width, const Terrain& t, const std::vector<int>& band, int b,
                const std::vector<std::uint32_t>& cells) {
  std::vector<std::pair<int, int>> votes;  // (child, count)
  for (const std::uint32_t k : cells)
    for (int q = 0; q < 8; ++q) {
      const int bn = band[k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q]];
      if (bn == b) continue;
      const int child = ChildOnPath(t, b, bn);
      auto it = std::find_if(votes.begin(), votes.end(),
                             [child](const std::pair<int, int>& v) { return v.first == child; });
      if (it == votes.end())
        votes.push_back({child, 1});
      else
        ++it->second;
    }
  int best = -1, best_count = 0;
  for (const auto& [child, count] : votes)
    if (count > best_count || (count == best_count && child < best)) {
      best = child;
      best_count = count;
    }
  return best;
}

}  // namespace

std::size_t AssignSubCellSlots(int width, int height, const Terrain& t, std::vector<int>* band_io) {
  std::vector<int>& band = *band_io;
  const std::size_t cells = static_cast<std::size_t>(width) * height;
  if (cells == 0 || t.contours.empty()) return 0;
  const TreeOrder tree(t);
  std::size_t relabelled = 0;
  std::vector<char> anchored(cells);
  std::vector<std::uint32_t> fifo, island;
  fifo.reserve(cells);
  for (;;) {
    // Anchored cells, then everything 8-connected to them within their band.
    std::fill(anchored.begin(), anchored.end(), 0);
    fifo.clear();
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * width + i;
        if (band[k] < 0 || !Anchored(width, height, band, tree, i, j)) continue;
        anchored[k] = 1;
        fifo.push_back(static_cast<std::uint32_t>(k));
      }
    FloodFrom(width, height, &fifo, &anchored,
              [&](std::size_t k, std::size_t n) { return band[n] == band[k]; });
    // Each island (a component of unanchored band cells; never on the grid's edge) to its child.
    bool any = false;
    for (std::size_t s = 0; s < cells; ++s) {
      if (band[s] < 0 || anchored[s]) continue;
      any = true;
      const int b = band[s];
      island.assign(1, static_cast<std::uint32_t>(s));
      anchored[s] = 1;  // reused as "visited"
      for (std::size_t r = 0; r < island.size(); ++r) {
        const std::size_t k = island[r];
        for (int q = 0; q < 8; ++q) {
          const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
          if (!anchored[n] && band[n] == b) {
            anchored[n] = 1;
            island.push_back(static_cast<std::uint32_t>(n));
          }
        }
      }
      const int child = IslandChild(width, t, band, b, island);
      for (const std::uint32_t k : island) band[k] = child;
      relabelled += island.size();
    }
    if (!any) return relabelled;
  }
}

std::size_t AssignSubCellSlotsBySweeps(int width, int height, const Terrain& t,
                                       std::vector<int>* band_io) {
  std::vector<int>& band = *band_io;
  const std::size_t cells = static_cast<std::size_t>(width) * height;
  if (cells == 0 || t.contours.empty()) return 0;
  const TreeOrder tree(t);
  std::size_t relabelled = 0;
  for (;;) {
    // Anchoring spreads one neighbour per sweep until nothing changes.
    std::vector<char> anchored(cells, 0);
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * width + i;
        anchored[k] = band[k] >= 0 && Anchored(width, height, band, tree, i, j);
      }
    for (bool changed = true; changed;) {
      changed = false;
      for (int j = 1; j + 1 < height; ++j)
        for (int i = 1; i + 1 < width; ++i) {
          const std::size_t k = static_cast<std::size_t>(j) * width + i;
          if (band[k] < 0 || anchored[k]) continue;
          for (int q = 0; q < 8; ++q) {
            const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
            if (anchored[n] && band[n] == band[k]) {
              anchored[k] = 1;
              changed = true;
              break;
            }
          }
        }
    }
    // Components of the unanchored cells: every cell takes the least index in its component.
    std::vector<std::uint32_t> label(cells);
    bool any = false;
    for (std::size_t k = 0; k < cells; ++k) {
      label[k] = static_cast<std::uint32_t>(k);
      if (band[k] >= 0 && !anchored[k]) any = true;
    }
    if (!any) return relabelled;
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = 0; k < cells; ++k) {
        if (band[k] < 0 || anchored[k]) continue;
        for (int q = 0; q < 8; ++q) {
          const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
          if (!anchored[n] && band[n] == band[k] && label[n] < label[k]) {
            label[k] = label[n];
            changed = true;
          }
        }
      }
    }
    // Each component's child from the map as it was at the start of the pass.
    const std::vector<int> before = band;
    for (std::size_t root = 0; root < cells; ++root) {
      if (before[root] < 0 || anchored[root] || label[root] != root) continue;
      std::vector<std::uint32_t> island;
      for (std::size_t k = root; k < cells; ++k)
        if (before[k] >= 0 && !anchored[k] && label[k] == root)
          island.push_back(static_cast<std::uint32_t>(k));
      const int child = IslandChild(width, t, before, before[root], island);
      for (const std::uint32_t k : island) band[k] = child;
      relabelled += island.size();
    }
  }
}

std::vector<std::uint32_t> CellsWithoutLowerNeighbour(int width, int height,
                                                      const std::vector<int>& band,
                                                      const std::vector<double>& h) {
  // Off the outlets all cells are inside the grid's edge, so the neighbours are fixed offsets.
  std::vector<std::uint32_t> out;
  for (int j = 1; j + 1 < height; ++j) {
    for (int i = 1; i + 1 < width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * width + i;
      if (band[k] < 0) continue;
      bool lower = false;
      for (int q = 0; q < 8 && !lower; ++q)
        lower = h[k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q]] < h[k];
      if (!lower) out.push_back(static_cast<std::uint32_t>(k));
    }
  }
  return out;
}

bool AnyOnASlotIsland(int width, int height, const Terrain& t, const std::vector<int>& band,
                      const std::vector<std::uint32_t>& cells_in) {
  if (cells_in.empty() || t.contours.empty()) return false;
  const TreeOrder tree(t);
  // seen: 0 not yet, 1 in the current search, 2 joined to an anchored cell within its band.
  std::vector<char> seen(static_cast<std::size_t>(width) * height, 0);
  std::vector<std::uint32_t> queue;
  for (const std::uint32_t start : cells_in) {
    if (band[start] < 0 || seen[start] == 2) continue;
    const int b = band[start];
    queue.assign(1, start);
    seen[start] = 1;
    bool anchored = false;
    for (std::size_t r = 0; r < queue.size() && !anchored; ++r) {
      const std::size_t k = queue[r];
      const int i = static_cast<int>(k % static_cast<std::size_t>(width));
      const int j = static_cast<int>(k / static_cast<std::size_t>(width));
      if (Anchored(width, height, band, tree, i, j)) {
        anchored = true;
        break;
      }
      // Not anchored, so not on the grid's edge: its 8 neighbours exist.
      for (int q = 0; q < 8; ++q) {
        const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
        if (band[n] != b || seen[n] == 1) continue;
        if (seen[n] == 2) {
          anchored = true;
          break;
        }
        seen[n] = 1;
        queue.push_back(static_cast<std::uint32_t>(n));
      }
    }
    if (!anchored) return true;
    for (const std::uint32_t k : queue) seen[k] = 2;
  }
  return false;
}

std::size_t FillWithinBands(int width, int height, const std::vector<int>& band,
                            const std::vector<double>& top, std::vector<double>* h) {
  const std::size_t cells = static_cast<std::size_t>(width) * height;
  if (cells == 0) return 0;
  const std::vector<double>& h0 = *h;
  // 0. If every cell off the outlets has a strictly lower neighbour, every one has a strictly
  // descending path to an outlet and nothing is raised: one raster scan.
  const std::vector<std::uint32_t> minima = CellsWithoutLowerNeighbour(width, height, band, h0);
  if (minima.empty()) return 0;
  // 1. The trapped cells, those without a strictly descending 8-path to an outlet (the others
  // keep W = h: the path's maximum is their own height): a cell off the outlets is trapped iff
  // every strictly lower neighbour is (a cell without one is). Found upwards from the minima in
  // the order of height (a binary heap over (h, cell index)): when a cell is popped every lower
  // neighbour has been, so each candidate is decided once. Depressions are small, and so is the
  // work (the whole grid is no longer searched from the outlets).
  std::vector<char> trapped(cells, 0), queued(cells, 0);
  std::vector<std::uint32_t> trapped_cells;
  using Entry = std::pair<double, std::uint32_t>;  // (height, cell index): a total order
  {
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> rising;
    for (const std::uint32_t k : minima) {
      queued[k] = 1;
      rising.push({h0[k], k});
    }
    while (!rising.empty()) {
      const std::size_t k = rising.top().second;
      rising.pop();
      const int i = static_cast<int>(k % static_cast<std::size_t>(width));
      const int j = static_cast<int>(k / static_cast<std::size_t>(width));
      if (IsOutlet(width, height, band, i, j)) continue;
      bool trap = true;
      for (int q = 0; q < 8 && trap; ++q) {
        const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
        if (h0[n] < h0[k] && !trapped[n]) trap = false;
      }
      if (!trap) continue;
      trapped[k] = 1;
      trapped_cells.push_back(static_cast<std::uint32_t>(k));
      for (int q = 0; q < 8; ++q) {
        const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
        if (queued[n] || !(h0[n] > h0[k])) continue;
        queued[n] = 1;
        rising.push({h0[n], static_cast<std::uint32_t>(n)});
      }
    }
  }
  if (trapped_cells.empty()) return 0;
  queued = std::vector<char>();
  // 2. The trapped cells (in or above a depression): the flood, seeded by the draining cells next
  // to them. Every walk from an outlet into them enters through such a cell, whose W = h is
  // final, so the result is the whole grid's flood (the Planchon-Darboux twin checks it). The
  // pops are one total order, so the order of the seeds' pushes does not matter.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> w(h0);
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (const std::uint32_t k : trapped_cells) w[k] = inf;
  {
    std::vector<char> seeded(cells, 0);
    for (const std::uint32_t k : trapped_cells) {
      // A trapped cell is off the outlets, so not on the grid's edge: its 8 neighbours exist.
      for (int q = 0; q < 8; ++q) {
        const std::size_t n = k + static_cast<std::ptrdiff_t>(kDj[q]) * width + kDi[q];
        if (trapped[n] || seeded[n]) continue;
        seeded[n] = 1;
        open.push({w[n], static_cast<std::uint32_t>(n)});
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
      if (!trapped[n]) continue;  // outlets and draining cells keep W = h
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
  for (std::size_t c = 0; c < t.contours.size(); ++c)
    top[c] = t.contours[c].elevation + BandInterval(t, t.contours[c]);
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
