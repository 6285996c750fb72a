// Depression filling that keeps every contour's level set: a priority-flood (Barnes, Lehman & Mulla
// 2014, Alg. 2) whose raise of a cell is capped at the top of the cell's band, and its brute-force
// Planchon-Darboux (2001) twin for the tests. Does not: build the surface (heightfield.h) or lower
// any cell.
//
// Hand-written: no library for this builds for both targets in our toolchain (/work/shared/
// TOOLCHAIN.md lists none; RichDEM, the authors' own code, is not a Debian package, only Python
// bindings on PyPI), and none caps the raise per cell, which is what keeps the level sets.
#pragma once

#include <cstddef>
#include <vector>

#include "terrain/contour.h"

namespace niwa::terrain {

struct Heightfield;

// The filled surface W on a width × height grid (row-major, 8-neighbour) is the smallest one with
// W ≥ h and, for every cell c that is not an outlet,
//   W[c] = max(h[c], min(top[band[c]], min over the 8 neighbours n of W[n])),
// i.e. Planchon-Darboux's W[c] = max(h[c], min_n W[n]) (ε = 0) with the raise capped at the band's
// top. Outlets keep W = h: cells with band < 0 (outside the lowest contour) and cells on the grid's
// edge. A cell in band b then stays in [h[c], top[b]] ⊂ [floor of b, top of b]: no cell leaves its
// band, so each contour stays the level set between its band and its parent's
// (docs/terrain-model.md). After the fill a cell below all 8 neighbours is one already at its
// band's top whose 8 neighbours are all above it (raising it further would take it out of its
// band). A cell already above its top (never one of ours; see BandTops) keeps its h. Returns the
// number of cells raised (W > h).
//
// First a raster scan: if every cell off the outlets has a strictly lower neighbour, nothing is
// raised and the fill ends (the usual case, O(cells)). Else a breadth-first search up from the
// outlets marks the cells with a strictly descending path to one (they keep W = h; when that is
// every cell, e.g. minima on flats that drain, nothing else runs). Then a priority-flood
// over the rest with a binary heap over (W, cell index), seeded by the marked cells next to them: a
// popped cell offers W' = max(h[n], min(top, W)) to each unmarked neighbour, which is pushed again
// whenever its W drops (the cap makes W' < W possible, so this is the label-correcting form of the
// flood; every pushed (W, index) pair is distinct, so the pops are one total order, the same on
// every platform).
std::size_t FillWithinBands(int width, int height, const std::vector<int>& band,
                            const std::vector<double>& top, std::vector<double>* h);
// The same by Planchon & Darboux's iteration (W = max(h, top) off the outlets, then raster sweeps
// lowering W[c] to max(h[c], min(top, min_n W[n])) until nothing changes): the test's twin,
// O(cells²) at worst. Equal bit for bit (both only compare and copy the input values).
std::size_t FillWithinBandsPlanchonDarboux(int width, int height, const std::vector<int>& band,
                                           const std::vector<double>& top, std::vector<double>* h);

// The top of each contour's band: h_C + Δh, or the summit's elevation in a top band (the same
// floating-point expression heightfield.cpp's band height reaches at a = ∞, so no cell is above
// it).
std::vector<double> BandTops(const Terrain& terrain);

// FillWithinBands on the heightfield's cells with its contours' band tops; sets hf->cells_filled.
void FillHeightfieldWithinBands(const Terrain& terrain, Heightfield* hf);

}  // namespace niwa::terrain
