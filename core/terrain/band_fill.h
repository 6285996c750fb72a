// Depression filling that keeps every contour's level set: sub-cell slots of a band given to the
// child around them, then a priority-flood (Barnes, Lehman & Mulla 2014, Alg. 2) whose raise of a
// cell is capped at the top of the cell's band; each with a brute-force twin for the tests. Does
// not: build the surface (heightfield.h) or lower any cell.
//
// Hand-written: no library for this builds for both targets in our toolchain (/work/shared/
// TOOLCHAIN.md lists none; RichDEM, the authors' own code, is not a Debian package, only Python
// bindings on PyPI), and none caps the raise per cell, which is what keeps the level sets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "terrain/contour.h"

namespace niwa::terrain {

struct Heightfield;

// Sub-cell slots (docs/terrain-model.md, "Sub-cell slots"). The painted band map samples each
// band at the cell centres; where a band C is narrower than a cell (a slot of C's band cutting
// into a child of C, or a gap between two children), the grid can see cells of C's band that are
// cut off from the rest of it: an 8-connected component of band-C cells none of whose 8
// neighbours lies outside C's strict descendants (no neighbour in C's parent's band, outside
// the lowest contour, in a sibling's subtree or off the grid). Such an island cannot drain within
// its band, and a fill capped at C's top leaves it below its neighbours (a pit). The grid cannot
// represent the slot, so the island is given to the child of C that holds most of its outer
// neighbours (counted per cell and neighbour; ties to the lower contour index): band[k] = that
// child. Repeated until no island is left (a slot through two levels moves down twice). Returns
// the number of relabelled cells (a cell moved twice counts twice). O(cells) per pass; a map
// without islands takes one pass.
std::size_t AssignSubCellSlots(int width, int height, const Terrain& terrain,
                               std::vector<int>* band);
// The same by fixpoint raster sweeps (anchoring spread one neighbour per sweep, components by
// least-index propagation): the test's twin, O(cells²) at worst. Equal to AssignSubCellSlots.
std::size_t AssignSubCellSlotsBySweeps(int width, int height, const Terrain& terrain,
                                       std::vector<int>* band);

// The cells off the outlets (band ≥ 0, not on the grid's edge) with no strictly lower neighbour,
// in raster order: the fill's first scan. None means nothing can be raised, and also that the band
// map has no sub-cell slot island (an island's lowest cell has no lower neighbour: its band's
// heights are at most its top, which is the child's elevation, the least height inside the
// child), so AssignSubCellSlots would change nothing: heightfield.cpp skips it then.
std::vector<std::uint32_t> CellsWithoutLowerNeighbour(int width, int height,
                                                      const std::vector<int>& band,
                                                      const std::vector<double>& h);
// Whether one of `cells` lies in a sub-cell slot island of the band map (a component
// AssignSubCellSlots would relabel in its first pass). Every such island holds a cell without a
// lower neighbour (as above), so with `cells` = CellsWithoutLowerNeighbour false means
// AssignSubCellSlots would change nothing. Searches each cell's band component only until it
// meets an anchored cell (a few rows of cells, not the whole map).
bool AnyOnASlotIsland(int width, int height, const Terrain& terrain, const std::vector<int>& band,
                      const std::vector<std::uint32_t>& cells);

// The filled surface W on a width × height grid (row-major, 8-neighbour) is the smallest one with
// W ≥ h and, for every cell c that is not an outlet,
//   W[c] = max(h[c], min(top[band[c]], min over the 8 neighbours n of W[n])),
// i.e. Planchon-Darboux's W[c] = max(h[c], min_n W[n]) (ε = 0) with the raise capped at the band's
// top. Outlets keep W = h: cells with band < 0 (outside the lowest contour) and cells on the grid's
// edge. A cell in band b then stays in [h[c], top[b]] ⊂ [floor of b, top of b]: no cell leaves its
// band, so each contour stays the level set between its band and its parent's
// (docs/terrain-model.md). After the fill a cell below all 8 neighbours is one already at its
// band's top whose 8 neighbours are all above it (raising it further would take it out of its
// band): on the heightfield's band map, after AssignSubCellSlots, none is left on any built-in
// (tests/terrain/heightfield_test.cpp). A cell already above its top (never one of ours; see
// BandTops) keeps its h. Returns the number of cells raised (W > h).
//
// First a raster scan: if every cell off the outlets has a strictly lower neighbour, nothing is
// raised and the fill ends (the usual case, O(cells)). Else the trapped cells, those without a
// strictly descending path to an outlet (the others keep W = h), found upwards from the cells
// without a lower neighbour in the order of height: a cell off the outlets is trapped iff all its
// strictly lower neighbours are (O(trapped cells · log), not a search of the whole grid). Then a
// priority-flood over the trapped cells with a binary heap over (W, cell index), seeded by the
// draining cells next to them: a popped cell offers W' = max(h[n], min(top, W)) to each trapped
// neighbour, which is pushed again whenever its W drops (the cap makes W' < W possible, so this is
// the label-correcting form of the flood; every pushed (W, index) pair is distinct, so the pops
// are one total order, the same on every platform).
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
