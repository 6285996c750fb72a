// The contour generation methods (§3 simple, §4.1 midpoint displacement, §4.2 Fourier
// descriptors, §4.3 improved): from one seed contour, every higher contour of the mountain as a
// tree (splits into several peaks, each grown on), and a summit on each top contour. Does not:
// build surfaces (heightfield.h) or read files (contour_io.h).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "base/status.h"
#include "random/pcg32.h"
#include "terrain/contour.h"
#include "terrain/terrain_params.h"

namespace niwa::terrain {

// Largest seed accepted, in points.
constexpr std::size_t kMaxSeedPoints = 1000000;
// Caps while growing (the result then says truncated).
constexpr std::size_t kMaxContourVertices = 200000;
constexpr std::size_t kMaxContours = 100000;

// The seed checked and normalised (finite, |x|, |y| ≤ 1e6 m, 3..1e6 points, snapped, CCW, simple);
// the error names "contour" and what is allowed.
Result<Ring> CheckSeed(const Ring& seed);

// Points one midpoint displacement makes at most when no budget gives fewer (128 MB of points).
constexpr std::size_t kMaxMidpointPoints = std::size_t{8} << 20;
// §4.1 (Fig 12): every edge ≥ 2·d0 is split at its midpoint displaced by s·min(d'', |l·tan θ|)
// along its normal (s = ±1, θ ~ U(θmin, θmax) degrees), recursively, until all edges are < 2·d0.
// A split halves an edge only while θ < 60°: with θ ≥ 60° and d'' ≥ √3·d0 the halves of an edge
// near 2·d''/√3 are as long as it, and the splitting doubles the points at each of its 41 levels.
// So it stops once the ring would pass max_points: then nullopt (the caller refuses the run).
std::optional<Ring> MidpointDisplace(const Ring& ring, double d0, double d2, double theta_min_deg,
                                     double theta_max_deg, Pcg32* rng,
                                     std::size_t max_points = kMaxMidpointPoints);
// Issue 31: the same splitting with each split's θ and side drawn from a PCG32 seeded by `key`
// (SplitDrawsKey: the RNG seed and the level), the split's depth and the cell of side `cell`
// holding the edge's midpoint: tied to where the split is, not to its place in the ring's order.
// With one stream drawn edge by edge (the overload above, the paper's reading), a seed jittered
// by centimetres changed which edges reached 2·d0 and so every draw after the first difference
// (an L grew 1 peak, its jittered copy 3); placed draws change only where the line moved across
// a cell's side. Grow uses these with cell = 2·d0 (docs/terrain-model.md "Seed sampling").
struct SplitDraws {
  uint64_t key = 0;
  double cell = 1;
};
std::optional<Ring> MidpointDisplace(const Ring& ring, double d0, double d2, double theta_min_deg,
                                     double theta_max_deg, const SplitDraws& draws,
                                     std::size_t max_points = kMaxMidpointPoints);
uint64_t SplitDrawsKey(uint64_t rng_seed, int level);
// The line of a midpoint displacement that passed `max_points` (`what`: the limit it came from,
// e.g. "what --max-memory leaves"), under the field "theta_max".
Status MidpointOverflow(double d0, double d2, double theta_max_deg, double max_points,
                        const std::string& what);
// The elevation of `level` (0: the seed, negative: below it) under t's h0, Δh and profile ratio
// q (dh_ratio): the grown contours' own heights, continued past the top by the same law.
double LevelElevation(const Terrain& t, int level);
// δ of Fig 12 for an edge of length 2l: min(d'', |l·tan θ|).
double MidpointDelta(double l, double theta_deg, double d2);

// §4.3 step 1.3: nearly collinear points (closer than eps to their neighbours' chord) removed.
Ring RemoveNearlyCollinear(const Ring& ring, double eps);
// The same with eps found by bisection so that the share of edges ≥ 2·d0 reaches long_frac.
Ring RemoveCollinearToShare(const Ring& ring, double d0, double long_frac, double max_eps);

// The pole of inaccessibility of a ring (the centre of its largest inscribed circle, by a grid
// search refined 12 times) and that circle's radius.
Vec2 PoleOfInaccessibility(const Ring& ring, double* radius);

// Grown rings smaller than kSliverAreaShare·d² (a square a tenth of d across) are dropped as
// slivers, not kept as peaks with summits (issue 31: rings of 1e-4 m² left by the perturbation's
// unions counted as peaks on jacksboro and on hand-drawn seeds). Such a ring is far below the
// shrink's own reach (it would vanish at the next shrink by d) and its summit would rise
// Δh·r/d ≈ 0 above it.
inline constexpr double kSliverAreaShare = 0.01;

struct TerrainGrowLimits;  // terrain_budget.h

// Issue 31: the seed at a uniform arc length, so that a mountain need not depend on how the user
// happened to sample the line (a square given by its 4 corners has d0 = its side and gets no
// midpoint displacement; the same square densified gets plenty). The spacing is
// kSeedSpacingShare·d, with at least kMinSeedSamples points; the walk starts at vertex 0. Grow
// grows from it (docs/terrain-model.md "Seed sampling"); a seed that would need more than
// kMaxSeedSamples points is grown as given, never resampled coarser than d/4.
inline constexpr double kSeedSpacingShare = 0.25;
inline constexpr std::size_t kMinSeedSamples = 16;
inline constexpr std::size_t kMaxSeedSamples = 50000;
// `seed` as given (its doubles, so a densified copy walks the same line) resampled as above, on
// the grid, counter-clockwise, points on straight runs kept; `checked` is CheckSeed(seed). Where
// chords across a narrow neck or tip make it self-intersect, the spacing is halved (up to 4
// times, within kMaxSeedSamples); if none is simple, `checked`.
Ring ResampleSeed(const Ring& seed, const Ring& checked, double d);

// Called before each contour is shrunk (or enlarged below the seed) with the level it grows (1, 2,
// ...; −1, −2, ... below the seed); false cancels: Grow returns run::CancelledStatus().
using GrowWatch = std::function<bool(int level)>;

// Grows the whole mountain from the seed with the table's method and constants and the RNG seed
// (TerrainState::seed; kDefaultTerrainSeed when none is given); with `limits`, stops before a
// contour whose worst case would cross them (counts.truncated_by holds the line).
Result<Terrain> Grow(const Ring& seed, const TerrainParams& params, uint64_t rng_seed,
                     const TerrainGrowLimits* limits = nullptr, const GrowWatch& watch = {});

}  // namespace niwa::terrain
