// Memory and time budgets of the terrain study (issue 16, docs/budgets.md): the limits Grow
// checks before shrinking each contour (stopping with GrowCounts::truncated_by and a line naming
// the limit), and the estimates of the heightfield (res² cells) and of each output, made before
// that work starts. Does not: measure memory or wall-clock time (counts times constants
// calibrated in docs/budgets.md; time is a count of vertices worked, so the native and WASM
// builds stop at the same contour), grow contours or build surfaces.
#pragma once

#include <string>

#include "base/budget.h"
#include "terrain/contour.h"
#include "terrain/terrain_params.h"

namespace niwa::terrain {

// What Grow may use (no limit when max_bytes and max_seconds are negative). Before shrinking a
// contour of n vertices it checks the worst case after it: its children hold at most
// m = growth · max(n, nfft (§4.2), perimeter / d0 (§4.1 splits every edge ≥ 2·d0)) vertices.
//   memory  = base_bytes + bytes_per_vertex · (vertices held + m) + transient_bytes_per_vertex · m
//   seconds = seconds_per_vertex · (vertices worked + n + m)
struct TerrainGrowLimits {
  double max_bytes = -1, max_seconds = -1;
  double base_bytes = 0, bytes_per_vertex = 0, transient_bytes_per_vertex = 0;
  double seconds_per_vertex = 0;
  double seconds_per_sweep_test = 0;  // a shrink's union sweep (ShrinkSweepTests)
  double growth = 2;                  // children's vertices per parent vertex, at most (a margin)
  std::string memory_limit = "max_memory", seconds_limit = "max_seconds";
};

// The work Grow has done so far (counted as it goes; GrowCounts holds the final figures).
struct TerrainWork {
  double vertices_held = 0;    // Σ vertices of every contour kept
  double vertices_worked = 0;  // Σ over shrunk contours of parent and children vertices
};

// The limits of growing `params` within `budget`, less the heightfield's room for params' res.
TerrainGrowLimits TerrainLimits(const TerrainParams& params, const Budget& budget);

// Grow's check before shrinking `parent` (level `level` of at most max_levels): "" when it fits,
// else the truncation line ("--max-memory: stopped at level 120 of 1000: 3,400,000 contour
// vertices would need more than 2 GB; raise d or lower max_levels ... (or raise --max-memory)").
std::string CheckTerrainContour(const Ring& parent, double d0, const TerrainParams& params,
                                const TerrainWork& work, const TerrainGrowLimits& limits,
                                int level);

// The perturbation of `rings` freshly shrunk rings beyond their vertices, in vertices' worth of
// time (TerrainWork::vertices_worked): each is resampled to nfft equal edges for its Fourier
// descriptor (§4.2, the fourier and improved methods), whatever its size, so a level of thousands
// of small rings costs thousands of FFTs (issue 34: a 3,000-tooth comb took 8 s in them,
// uncounted).
double PerturbationWork(std::size_t rings, const TerrainParams& params);
// Grow's check before perturbing them (after the shrink of `parent`): "" when it fits, else the
// truncation line.
std::string CheckTerrainPerturbation(const Ring& parent, std::size_t rings,
                                     const TerrainParams& params, const TerrainWork& work,
                                     const TerrainGrowLimits& limits, int level);

// The union sweep edge tests the next shrink may make (offset.h ShrinkCounts::max_sweep_tests),
// what the seconds left after the vertices worked and the tests made so far allow; −1: no limit.
double SweepTestsLeft(const TerrainGrowLimits& limits, const TerrainWork& work,
                      double sweep_tests_so_far);
// The line of a shrink whose sweep passed SweepTestsLeft (at level `level` of at most max_levels).
std::string SweepStoppedLine(const Ring& parent, double allowed, const TerrainGrowLimits& limits,
                             int level, int max_levels);
// Its reason alone ("shrinking a contour of N points needs more than ..."), for the seed's refusal.
std::string SweepStoppedWhy(const Ring& parent, double allowed, const TerrainGrowLimits& limits);

// True when every check Grow made for `terrain` passes under `limits` too, by an upper bound (the
// final vertices held and worked with each contour's worst case): growing it again within them
// gives the same contours (TerrainRun keeps them when only res, which shares the budget, changed).
bool GrowFitsLimits(const Terrain& terrain, const TerrainParams& params,
                    const TerrainGrowLimits& limits);

// The work of one shrink's union sweep over `ring` (offset.cpp UnionOnce): each sloped edge tests
// the edges of its horizontal strip (√E strips over the ring's height), each horizontal edge every
// edge. Shape decides it: a round contour's strips hold about 2√E edges, a comb's hold every tooth
// (E²/2). Counted from the ring alone, in O(E), before any shrink.
double ShrinkSweepTests(const Ring& ring);
// The seed's first shrink (and its first enlargement when down > 0), forecast before any is made
// from the seed and the shrink's rows (offset.h ForecastSplits), in ShrinkCounts::sweep_tests'
// units: the windings over the seed's edges; the split points of its raw offset path (two a pair
// of segments whose boxes overlap: every crossing is one); the pairs the split sweep tries, in
// its first pass and, when it splits, in the second over the pieces (about 2·k̄ times the first,
// k̄ the pieces a segment is cut into: two partitions of overlapping ranges overlap in at most
// k_i + k_j pieces); and the pairs the seed's simplicity check tries (polygon.h IsSimple). It
// sees shape: a comb's teeth within 2·d of each other cross in its offset path about
// (2·d / pitch)² times a tooth. O(n log n), whatever the shape. Accuracy: docs/budgets.md.
struct SeedShrinkForecast {
  double windings = 0, split_points = 0, tried_pairs = 0;
  double work() const;
};
SeedShrinkForecast ForecastSeedShrink(const Ring& seed, const TerrainParams& params);
// The forecast against the budget's seconds, before anything grows (a seed that CheckSeed refuses,
// too few or too many points or one not finite, passes here and is refused there): ok, or
// {"contour", "N points whose shape needs about T s to shrink once (...); must take at most L s
// (limit); simplify the contour (or raise ...)"}.
Status CheckSeedShape(const Ring& seed, const TerrainParams& params, const Budget& budget);

// The grown contours' estimate (what Grow's checks counted).
Estimate EstimateTerrainGrown(const Terrain& terrain, const TerrainGrowLimits& limits);

// The heightfield's grid for `res` (heightfield.h's BuildHeightfield): width × height cells.
struct GridSize {
  double width = 0, height = 0;
  double cells() const { return width * height; }
};
GridSize TerrainGridSize(const Terrain& terrain, int res);

// BuildHeightfield over `grid`: heights, bands, the two stamped distances a cell, the fallback
// segment grids over every contour vertex; time per cell and per contour vertex.
Estimate EstimateHeightfield(const Terrain& terrain, const GridSize& grid);
// The erosion pass (erosion.h) on `grid` with params' erosion rows: the run's uneroded copy and the
// pass's scratch (order, flats, water, sediment, held loads, basins, the change, the pits before,
// the drainage measure's accumulation: 160 bytes a cell at most) and erosion_iterations passes of
// 500 ns a cell (measured 200-340 ns natively), with the two drainage measures; an
// empty estimate when erosion is 0.
Estimate EstimateErosion(const GridSize& grid, const TerrainParams& params);

enum class TerrainOutput { kGlb, kHeightmap, kContoursJson, kGeoJson, kSvg };
// One output of the grown terrain on `grid` (the .glb's surface has a vertex a cell).
Estimate EstimateTerrainOutput(const Terrain& terrain, const GridSize& grid, TerrainOutput kind);

// What the truncation lines tell the user to change (the refusals before a heightfield say "lower
// res" in the front end's words: terrain_run.h).
inline constexpr char kTerrainGrowChange[] = "raise d, or lower max_levels or the seed's points";

}  // namespace niwa::terrain
