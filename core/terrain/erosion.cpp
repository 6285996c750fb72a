// Thermal and hydraulic erosion of a heightfield, its D8 drainage measures (see erosion.h).
#include "terrain/erosion.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>

#include "math/det_math.h"

namespace niwa::terrain {
namespace {

constexpr int kErDi[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kErDj[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
constexpr double kErSqrt2 = 1.4142135623730951;
constexpr double kErLen[8] = {kErSqrt2, 1, kErSqrt2, 1, 1, kErSqrt2, 1, kErSqrt2};

// Cell indices by height, highest first, ties by the lower index: a total order, so the same
// order on every platform and std::sort's result is unique.
void SortCellsHighestFirst(const std::vector<double>& h, std::vector<std::uint32_t>* order) {
  order->resize(h.size());
  std::iota(order->begin(), order->end(), 0u);
  std::sort(order->begin(), order->end(), [&h](std::uint32_t a, std::uint32_t b) {
    return h[a] > h[b] || (h[a] == h[b] && a < b);
  });
}

bool IsStrictMinimum(const Heightfield& hf, int i, int j) {
  if (i <= 0 || j <= 0 || i + 1 >= hf.width || j + 1 >= hf.height) return false;
  const double hk = hf.At(i, j);
  for (int n = 0; n < 8; ++n)
    if (hf.At(i + kErDi[n], j + kErDj[n]) <= hk) return false;
  return true;
}

// Thermal erosion, one pass (Musgrave et al. 1989 §4, Olsen 2004 §3.1): a cell whose drop to a
// neighbour exceeds T·distance (T = tan talus) moves half its largest excess to those neighbours,
// shared by excess. Every move is computed from the heights before the pass (Jacobi), so the
// order of the cells does not matter; each move leaves one cell and enters another (volume kept).
void ThermalPass(double talus_drop_per_cell, Heightfield* hf, std::vector<double>* delta) {
  const int w = hf->width, ht = hf->height;
  std::vector<double>& h = hf->h;
  delta->assign(h.size(), 0.0);
  double excess[8];
  for (int j = 0; j < ht; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      double sum = 0, most = 0;
      for (int n = 0; n < 8; ++n) {
        excess[n] = 0;
        const int ii = i + kErDi[n], jj = j + kErDj[n];
        if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
        const double e =
            h[k] - h[static_cast<std::size_t>(jj) * w + ii] - talus_drop_per_cell * kErLen[n];
        if (e > 0) {
          excess[n] = e;
          sum += e;
          most = std::max(most, e);
        }
      }
      if (!(most > 0)) continue;
      const double move = 0.5 * most;
      for (int n = 0; n < 8; ++n) {
        if (!(excess[n] > 0)) continue;
        const double amount = move * (excess[n] / sum);
        (*delta)[static_cast<std::size_t>(j + kErDj[n]) * w + (i + kErDi[n])] += amount;
        (*delta)[k] -= amount;
      }
    }
  }
  for (std::size_t k = 0; k < h.size(); ++k) h[k] += (*delta)[k];
}

struct HydraulicScratch {
  std::vector<std::uint32_t> order;  // cells in the order taken
  std::vector<std::uint32_t> queue;  // the flat distance's breadth-first queue
  std::vector<std::uint32_t> flat;   // steps over equal heights to a way down (kUnreached: none)
  std::vector<std::uint8_t> higher;  // neighbours that drain to the cell, not yet taken
  std::vector<std::uint8_t> taken;
  std::vector<double> start, water, sediment;
  std::vector<double> pending;  // load held in a closed basin, carried to the next pass
  double exported = 0;          // Σ height (m) of the load that left at the grid's edge
  // FillBasins' lake: its cells, the heap of its shore and a visit stamp per cell.
  std::vector<std::uint32_t> lake, seen;
  std::vector<std::pair<double, std::uint32_t>> shore;
  std::uint32_t stamp = 0;
};

constexpr std::uint32_t kUnreached = 0xffffffffu;

// Each cell's steps over cells of its own height to one with a strictly lower neighbour or on the
// grid's edge (0 there; kUnreached in a closed basin): the way across a flat (Garbrecht & Martz
// 1997's gradient towards lower terrain), breadth-first, seeded in index order.
void FlatDistance(const Heightfield& hf, HydraulicScratch* s) {
  const int w = hf.width, ht = hf.height;
  const std::vector<double>& h = hf.h;
  s->flat.assign(h.size(), kUnreached);
  s->queue.clear();
  for (int j = 0; j < ht; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      bool way = i == 0 || j == 0 || i + 1 == w || j + 1 == ht;
      for (int n = 0; n < 8 && !way; ++n)
        if (h[static_cast<std::size_t>(j + kErDj[n]) * w + (i + kErDi[n])] < h[k]) way = true;
      if (!way) continue;
      s->flat[k] = 0;
      s->queue.push_back(static_cast<std::uint32_t>(k));
    }
  }
  for (std::size_t head = 0; head < s->queue.size(); ++head) {
    const std::uint32_t k = s->queue[head];
    const int i = static_cast<int>(k % static_cast<std::uint32_t>(w));
    const int j = static_cast<int>(k / static_cast<std::uint32_t>(w));
    for (int n = 0; n < 8; ++n) {
      const int ii = i + kErDi[n], jj = j + kErDj[n];
      if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
      const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
      if (s->flat[q] != kUnreached || h[q] != h[k]) continue;
      s->flat[q] = s->flat[k] + 1;
      s->queue.push_back(static_cast<std::uint32_t>(q));
    }
  }
}

// The load each closed basin held from the last pass (pending, in index order) fills it as a
// lake: cells are flooded lowest first from where the load waits (a heap on height, then index:
// the same order everywhere), the level rising over the lake's cells until the load is used (all
// of them set to that level: volume kept), or until the shore meets a cell lower than the level
// (the lake spills there: the rest is added to `spill` at that cell, to flow on from there), or
// the lake reaches the grid's edge (the rest leaves the grid, counted). Priority-flood order as in
// Barnes, Lehman & Mulla 2014 (band_fill.h), run only from the cells that hold a load; a load
// waiting on a cell the lake takes in joins it (so a basin is flooded once a pass).
void FillBasins(Heightfield* hf, HydraulicScratch* s, std::vector<double>* spill) {
  const int w = hf->width, ht = hf->height;
  std::vector<double>& h = hf->h;
  if (s->seen.size() != h.size()) s->seen.assign(h.size(), 0);
  const auto greater = [](const std::pair<double, std::uint32_t>& a,
                          const std::pair<double, std::uint32_t>& b) { return a > b; };
  for (std::size_t b = 0; b < h.size(); ++b) {
    double load = s->pending[b];
    if (!(load > 0)) continue;
    s->pending[b] = 0;
    if (++s->stamp == 0) {  // the stamps wrapped: start them again
      std::fill(s->seen.begin(), s->seen.end(), 0);
      s->stamp = 1;
    }
    s->lake.clear();
    s->shore.clear();
    s->shore.push_back({h[b], static_cast<std::uint32_t>(b)});
    s->seen[b] = s->stamp;
    double level = h[b];
    while (load > 0 && !s->shore.empty()) {
      std::pop_heap(s->shore.begin(), s->shore.end(), greater);
      const auto [hc, c] = s->shore.back();
      s->shore.pop_back();
      if (!s->lake.empty() && hc < level) {  // lower than the lake: it spills here
        (*spill)[c] += load;
        load = 0;
        break;
      }
      if (!s->lake.empty()) {
        const double room = static_cast<double>(s->lake.size()) * (hc - level);
        if (load <= room) {
          level += load / static_cast<double>(s->lake.size());
          load = 0;
          break;
        }
        load -= room;
      }
      level = hc;
      s->lake.push_back(c);
      load += s->pending[c];  // a load waiting in the same basin joins this one (one flood a basin)
      s->pending[c] = 0;
      const int i = static_cast<int>(c % static_cast<std::uint32_t>(w));
      const int j = static_cast<int>(c / static_cast<std::uint32_t>(w));
      if (i == 0 || j == 0 || i + 1 == w || j + 1 == ht) {  // the lake reaches the edge
        s->exported += load;
        load = 0;
        break;
      }
      for (int n = 0; n < 8; ++n) {
        const std::size_t q = static_cast<std::size_t>(j + kErDj[n]) * w + (i + kErDi[n]);
        if (s->seen[q] == s->stamp) continue;
        s->seen[q] = s->stamp;
        s->shore.push_back({h[q], static_cast<std::uint32_t>(q)});
        std::push_heap(s->shore.begin(), s->shore.end(), greater);
      }
    }
    if (load > 0) level += load / static_cast<double>(s->lake.size());  // never: the edge ends it
    for (const std::uint32_t c : s->lake) h[c] = level;
  }
}

// The load that spilled from a basin after the last pass, laid down from cell c along the
// steepest way down: each cell takes what keeps it within the talus slope over its lowest
// neighbour, the rest goes on to that neighbour (ties: the lower index); at the grid's edge it
// leaves (counted); after 4·(width + height) steps (a flat crossed) the rest stays where it is.
void SettleDownhill(std::size_t c, double load, double talus_drop, Heightfield* hf,
                    HydraulicScratch* s) {
  const int w = hf->width, ht = hf->height;
  std::vector<double>& h = hf->h;
  for (int step = 0; step < 4 * (w + ht) && load > 0; ++step) {
    const int i = static_cast<int>(c % static_cast<std::size_t>(w));
    const int j = static_cast<int>(c / static_cast<std::size_t>(w));
    std::size_t low = c;
    double lowest = INFINITY;
    for (int n = 0; n < 8; ++n) {
      const int ii = i + kErDi[n], jj = j + kErDj[n];
      if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
      const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
      if (h[q] < lowest || (h[q] == lowest && q < low)) {
        lowest = h[q];
        low = q;
      }
    }
    const double settle = std::min(load, std::max(0.0, lowest + talus_drop - h[c]));
    h[c] += settle;
    load -= settle;
    if (!(load > 0)) return;
    if (i == 0 || j == 0 || i + 1 == w || j + 1 == ht) {
      s->exported += load;
      return;
    }
    c = low;
  }
  h[c] += load;
}

// Hydraulic erosion, one pass. A cell drains to a neighbour that is lower at the pass's start, or
// as high and nearer a way down across a flat (FlatDistance). One cell of rain falls on every
// cell; every cell is taken once, after all the neighbours that drain to it (Kahn's topological
// order, seeded and run first in, first out in index order: deterministic, and O(cells) where a
// sort by height was 3x slower). Its water is its rain plus what its upper neighbours sent. On a
// slope, its capacity is C = Kc · water · S (S its steepest drop per metre to a lower cell not
// yet taken; Musgrave et al. 1989 §5's capacity ∝ water × slope); below C it gives
// Ks·(C − sediment) of its height to the water (at most half its drop to the lowest such cell, so
// it stays above it), above C it takes Kd·(sediment − C) (at most half way up to the lowest of
// its neighbours already taken, so none of them is left below all its neighbours, and no deposit
// makes a flat); then water (less evaporation) and sediment go on to its strictly lower neighbours
// not yet taken, in shares ∝ (drop / distance)⁴ (Holmgren 1994: exponents 4-6 follow valleys, 1
// spreads water over slopes). On a flat (no lower neighbour) still water drops the share Kd of its
// load (no higher than the talus slope over its lowest neighbour) and passes the rest in equal
// parts to the neighbours it drains to (a fan spreads across the flat towards its way down). A cell
// with none: on the grid's edge the load leaves the grid (counted: ErosionReport::volume_exported);
// in a closed basin it waits for the next pass, which first fills the basin with it as a lake
// (FillBasins; after the last pass too). Sediment moves only from a cell to one lower or, across a
// flat, as high: a valley is cut where water gathers and filled only where its slope no longer
// carries the load.
void HydraulicPass(const ErosionParams& p, double talus_drop, Heightfield* hf,
                   HydraulicScratch* s) {
  const int w = hf->width, ht = hf->height;
  std::vector<double>& h = hf->h;
  const std::size_t cells = h.size();
  // Basins that held a load fill first; what spills over is this pass's load where it spills.
  s->sediment.assign(cells, 0.0);
  FillBasins(hf, s, &s->sediment);
  FlatDistance(*hf, s);
  s->start = h;
  const std::vector<double>& h0 = s->start;
  const std::vector<std::uint32_t>& f = s->flat;
  // q drains from k (k is above q in the pass's order).
  const auto drains = [&](std::size_t k, std::size_t q) {
    return h0[q] < h0[k] || (h0[q] == h0[k] && f[q] < f[k]);
  };
  s->higher.assign(cells, 0);
  s->taken.assign(cells, 0);
  s->order.clear();
  s->order.reserve(cells);
  for (int j = 0; j < ht; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * w + i;
      std::uint8_t n_higher = 0;
      for (int n = 0; n < 8; ++n) {
        const int ii = i + kErDi[n], jj = j + kErDj[n];
        if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
        if (drains(static_cast<std::size_t>(jj) * w + ii, k)) ++n_higher;
      }
      s->higher[k] = n_higher;
      if (n_higher == 0) s->order.push_back(static_cast<std::uint32_t>(k));
    }
  }
  s->water.assign(cells, 0.0);
  s->pending.assign(cells, 0.0);
  const double cell = hf->cell;
  double share[8];
  for (std::size_t r = 0; r < s->order.size(); ++r) {
    const std::uint32_t k = s->order[r];
    s->taken[k] = 1;
    const int i = static_cast<int>(k % static_cast<std::uint32_t>(w));
    const int j = static_cast<int>(k / static_cast<std::uint32_t>(w));
    // The neighbours it drains to lose one upper neighbour still to be taken.
    for (int n = 0; n < 8; ++n) {
      const int ii = i + kErDi[n], jj = j + kErDj[n];
      if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
      const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
      if (drains(k, q) && --s->higher[q] == 0) s->order.push_back(static_cast<std::uint32_t>(q));
    }
    const double water = s->water[k] + 1.0;
    const double carried = s->sediment[k];
    // The steepest drop to a cell not yet taken, and the lowest taken neighbour.
    double steepest = 0, lowest_drop = 0, cap = INFINITY;
    for (int n = 0; n < 8; ++n) {
      const int ii = i + kErDi[n], jj = j + kErDj[n];
      if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
      const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
      if (s->taken[q]) {
        cap = std::min(cap, h[q]);
        continue;
      }
      const double drop = h[k] - h[q];
      if (!(drop > 0)) continue;
      steepest = std::max(steepest, drop / kErLen[n]);
      lowest_drop = std::max(lowest_drop, drop);
    }
    if (!(steepest > 0)) {
      // A flat: the share Kd settles, the rest goes on across the flat in equal parts.
      int across[8], count = 0;
      for (int n = 0; n < 8; ++n) {
        const int ii = i + kErDi[n], jj = j + kErDj[n];
        if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
        const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
        if (!s->taken[q] && drains(k, q)) across[count++] = n;
      }
      if (count == 0) {
        if (i == 0 || j == 0 || i + 1 == w || j + 1 == ht) {
          s->exported += carried;  // the edge of a flat: the load leaves the grid
        } else {
          s->pending[k] += carried;  // a closed basin: it fills as a lake (FillBasins)
        }
        continue;
      }
      // No deposit stands above the talus slope over the lowest neighbour (a flat is its own
      // height: one talus step a pass), so a valley's whole load at its mouth makes no spike.
      double lowest = h[k];
      for (int n = 0; n < 8; ++n) {
        const int ii = i + kErDi[n], jj = j + kErDj[n];
        if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
        lowest = std::min(lowest, h[static_cast<std::size_t>(jj) * w + ii]);
      }
      const double settle =
          std::min(p.deposition * carried, std::max(0.0, lowest + talus_drop - h[k]));
      h[k] += settle;
      const double rest = carried - settle;
      const double out_water = water * (1.0 - p.evaporation);
      double given = 0;
      for (int c = 0; c < count; ++c) {
        const std::size_t q =
            static_cast<std::size_t>(j + kErDj[across[c]]) * w + (i + kErDi[across[c]]);
        const double part = c + 1 == count ? rest - given : rest / count;
        s->sediment[q] += part;
        s->water[q] += out_water / count;
        given += part;
      }
      continue;
    }
    const double capacity = p.capacity * water * (steepest / cell);
    double load = carried;
    if (carried < capacity) {
      const double cut = std::min(p.solubility * (capacity - carried), 0.5 * lowest_drop);
      h[k] -= cut;
      load += cut;
    } else {
      const double room = cap > h[k] ? 0.5 * (cap - h[k]) : 0.0;
      const double drop = std::min(p.deposition * (carried - capacity), room);
      h[k] += drop;
      load -= drop;
    }
    // Shares among the neighbours still strictly below the cell's new height (the lowest one is:
    // the cut leaves half the drop).
    double sum = 0;
    int last = -1;
    for (int n = 0; n < 8; ++n) {
      share[n] = 0;
      const int ii = i + kErDi[n], jj = j + kErDj[n];
      if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
      const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
      if (s->taken[q]) continue;
      const double g = (h[k] - h[q]) / kErLen[n];
      if (!(g > 0)) continue;
      const double g2 = g * g;
      share[n] = g2 * g2;
      sum += share[n];
      last = n;
    }
    const double out_water = water * (1.0 - p.evaporation);
    double given = 0;
    for (int n = 0; n < 8; ++n) {
      if (!(share[n] > 0)) continue;
      const std::size_t q = static_cast<std::size_t>(j + kErDj[n]) * w + (i + kErDi[n]);
      const double part_share = share[n] / sum;
      s->water[q] += out_water * part_share;
      // The last share takes what rounding left, so the load is passed on whole.
      const double part = n == last ? load - given : load * part_share;
      s->sediment[q] += part;
      given += part;
    }
  }
}

// Levels each strict minimum that was not one before with its lowest neighbour (ties: the lower
// index): both take their mean. Neither is then below all its neighbours, and no other cell
// becomes a minimum (the raised cell stays at or below its lowest neighbour's old height, the
// lowered one has the raised one beside it at its height), so every pass removes minima and adds
// none. Volume is kept (two cells, one sum).
int LevelNewPits(const std::vector<char>& was_pit, Heightfield* hf) {
  int levelled = 0;
  for (int pass = 0; pass < 64; ++pass) {
    int now = 0;
    for (int j = 1; j + 1 < hf->height; ++j) {
      for (int i = 1; i + 1 < hf->width; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * hf->width + i;
        if (was_pit[k] || !IsStrictMinimum(*hf, i, j)) continue;
        std::size_t low = k;
        double lowest = INFINITY;
        for (int n = 0; n < 8; ++n) {
          const std::size_t q = static_cast<std::size_t>(j + kErDj[n]) * hf->width + (i + kErDi[n]);
          if (hf->h[q] < lowest || (hf->h[q] == lowest && q < low)) {
            lowest = hf->h[q];
            low = q;
          }
        }
        const double mean = 0.5 * (hf->h[k] + hf->h[low]);
        hf->h[k] = mean;
        hf->h[low] = mean;
        ++now;
      }
    }
    levelled += now;
    if (now == 0) break;
  }
  return levelled;
}

double Sum(const std::vector<double>& h) {
  double s = 0;
  for (double v : h) s += v;
  return s;
}

}  // namespace

ErosionParams ErosionParamsOf(const TerrainParams& params) {
  ErosionParams p;
  p.mode = params.GetInt(TerrainParam::kErosion);
  p.iterations = params.GetInt(TerrainParam::kErosionIterations);
  p.talus_deg = params.Get(TerrainParam::kErosionTalus);
  p.capacity = params.Get(TerrainParam::kErosionCapacity);
  p.solubility = params.Get(TerrainParam::kErosionSolubility);
  p.deposition = params.Get(TerrainParam::kErosionDeposition);
  p.evaporation = params.Get(TerrainParam::kErosionEvaporation);
  return p;
}

Status CheckErosionParams(const ErosionParams& p) {
  TerrainParams check;  // the table's own ranges and one-line errors
  NIWA_RETURN_IF_ERROR(check.Set(TerrainParam::kErosion, p.mode));
  NIWA_RETURN_IF_ERROR(check.Set(TerrainParam::kErosionIterations, p.iterations));
  NIWA_RETURN_IF_ERROR(check.Set(TerrainParam::kErosionTalus, p.talus_deg));
  NIWA_RETURN_IF_ERROR(check.Set(TerrainParam::kErosionCapacity, p.capacity));
  NIWA_RETURN_IF_ERROR(check.Set(TerrainParam::kErosionSolubility, p.solubility));
  NIWA_RETURN_IF_ERROR(check.Set(TerrainParam::kErosionDeposition, p.deposition));
  return check.Set(TerrainParam::kErosionEvaporation, p.evaporation);
}

std::vector<double> D8Accumulation(const Heightfield& hf) {
  const int w = hf.width, ht = hf.height;
  std::vector<std::uint32_t> order;
  SortCellsHighestFirst(hf.h, &order);
  std::vector<double> acc(hf.h.size(), 1.0);
  for (const std::uint32_t k : order) {
    const int i = static_cast<int>(k % static_cast<std::uint32_t>(w));
    const int j = static_cast<int>(k / static_cast<std::uint32_t>(w));
    double best = 0;
    std::size_t to = k;
    for (int n = 0; n < 8; ++n) {
      const int ii = i + kErDi[n], jj = j + kErDj[n];
      if (ii < 0 || jj < 0 || ii >= w || jj >= ht) continue;
      const std::size_t q = static_cast<std::size_t>(jj) * w + ii;
      const double g = (hf.h[k] - hf.h[q]) / kErLen[n];
      if (g > best) {
        best = g;
        to = q;
      }
    }
    if (to != k) acc[to] += acc[k];
  }
  return acc;
}

DrainageMeasure MeasureDrainage(const Heightfield& hf) {
  DrainageMeasure m;
  const std::vector<double> acc = D8Accumulation(hf);
  double cells = 0, sum = 0;
  for (std::size_t k = 0; k < acc.size(); ++k)
    if (hf.band[k] >= 0) cells += 1;
  if (cells == 0) return m;
  m.threshold = std::max(8.0, std::floor(cells / 100));
  double channel = 0;
  for (std::size_t k = 0; k < acc.size(); ++k) {
    if (hf.band[k] < 0) continue;
    sum += acc[k];
    m.max_accumulation = std::max(m.max_accumulation, acc[k]);
    if (acc[k] >= m.threshold) channel += 1;
  }
  m.channel_share = channel / cells;
  m.mean_accumulation = sum / cells;
  return m;
}

int CountStrictPits(const Heightfield& hf) {
  int pits = 0;
  for (int j = 1; j + 1 < hf.height; ++j)
    for (int i = 1; i + 1 < hf.width; ++i)
      if (IsStrictMinimum(hf, i, j)) ++pits;
  return pits;
}

ErosionReport Erode(const ErosionParams& p, Heightfield* hf) {
  ErosionReport report;
  report.sum_before = Sum(hf->h);
  report.pits_before = CountStrictPits(*hf);
  const auto mode = static_cast<ErosionMode>(p.mode);
  if (mode == ErosionMode::kOff || hf->h.empty()) {
    report.sum_after = report.sum_before;
    report.pits_after = report.pits_before;
    return report;
  }
  report.drainage_before = MeasureDrainage(*hf);
  std::vector<char> was_pit(hf->h.size(), 0);
  for (int j = 1; j + 1 < hf->height; ++j)
    for (int i = 1; i + 1 < hf->width; ++i)
      was_pit[static_cast<std::size_t>(j) * hf->width + i] = IsStrictMinimum(*hf, i, j) ? 1 : 0;
  const std::vector<double> before = hf->h;
  double s = 0, c = 1;
  det::SinCos(p.talus_deg * (det::kPi / 180.0), &s, &c);
  const double talus_drop = s / c * hf->cell;  // m per cell of distance
  const bool thermal = mode == ErosionMode::kThermal || mode == ErosionMode::kBoth;
  const bool hydraulic = mode == ErosionMode::kHydraulic || mode == ErosionMode::kBoth;
  std::vector<double> delta;
  HydraulicScratch scratch;
  scratch.pending.assign(hf->h.size(), 0.0);
  for (int it = 0; it < p.iterations; ++it) {
    if (thermal) ThermalPass(talus_drop, hf, &delta);
    if (hydraulic) HydraulicPass(p, talus_drop, hf, &scratch);
    // After every pass, so the next one meets no new basin (where a load would stop whole).
    report.pits_levelled += LevelNewPits(was_pit, hf);
  }
  // Load still waiting in basins fills them; what spills over settles where it spills.
  if (hydraulic) {
    scratch.sediment.assign(hf->h.size(), 0.0);
    FillBasins(hf, &scratch, &scratch.sediment);
    for (std::size_t k = 0; k < hf->h.size(); ++k)
      if (scratch.sediment[k] > 0) SettleDownhill(k, scratch.sediment[k], talus_drop, hf, &scratch);
  }
  report.pits_levelled += LevelNewPits(was_pit, hf);
  report.exported = scratch.exported;
  report.volume_exported = scratch.exported * hf->cell * hf->cell;
  report.sum_after = Sum(hf->h);
  report.pits_after = CountStrictPits(*hf);
  double cut = 0, laid = 0;
  for (std::size_t k = 0; k < before.size(); ++k) {
    const double d = hf->h[k] - before[k];
    if (d < 0) cut -= d;
    if (d > 0) laid += d;
    report.max_cut = std::max(report.max_cut, -d);
    report.max_deposit = std::max(report.max_deposit, d);
  }
  report.volume_moved = cut * hf->cell * hf->cell;
  report.volume_laid = laid * hf->cell * hf->cell;
  report.drainage_after = MeasureDrainage(*hf);
  return report;
}

void AddErosionChange(const Heightfield& raw, const Heightfield& eroded, Heightfield* target) {
  if (raw.h.empty() || raw.h.size() != eroded.h.size()) return;
  const int w = raw.width, ht = raw.height;
  const auto change = [&](int i, int j) {
    const std::size_t k = static_cast<std::size_t>(j) * w + i;
    return eroded.h[k] - raw.h[k];
  };
  for (int j = 0; j < target->height; ++j) {
    for (int i = 0; i < target->width; ++i) {
      const Vec2 c = target->Centre(i, j);
      // raw's cell coordinates of the point (cell centres at whole numbers), clamped.
      const double u = std::clamp((c.x - raw.x0) / raw.cell - 0.5, 0.0, w - 1.0);
      const double v = std::clamp((raw.y1 - c.y) / raw.cell - 0.5, 0.0, ht - 1.0);
      const int i0 = std::min(static_cast<int>(u), std::max(0, w - 2));
      const int j0 = std::min(static_cast<int>(v), std::max(0, ht - 2));
      const int i1 = std::min(i0 + 1, w - 1), j1 = std::min(j0 + 1, ht - 1);
      const double fu = u - i0, fv = v - j0;
      const double top = change(i0, j0) * (1 - fu) + change(i1, j0) * fu;
      const double bottom = change(i0, j1) * (1 - fu) + change(i1, j1) * fu;
      target->h[static_cast<std::size_t>(j) * target->width + i] += top * (1 - fv) + bottom * fv;
    }
  }
}

}  // namespace niwa::terrain
