// The terrain study's budgets: Grow's per-contour check, the heightfield's and the outputs'
// estimates (constants measured in docs/budgets.md, "Terrain").
#include "terrain/terrain_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "terrain/generate.h"
#include "terrain/offset.h"
#include "terrain/polygon.h"

namespace niwa::terrain {
namespace {

// Fixed sizes (not sizeof: both builds must stop at the same contour). A kept vertex is a Vec2
// (16 bytes) in its ring, with the ring's spare room; a contour in the making holds its parent's
// copy, the shrink's rings, the perturbed ones and their 1/1024 m grid copies (IRing) at once.
constexpr double kBaseBytes = 64.0 * 1024 * 1024;  // the process, tables, code
constexpr double kBytesPerVertex = 32, kTransientBytesPerVertex = 200;
// Native release, the slowest of several runs with a margin: shrink (offset, union, loops) and
// perturbation per vertex worked.
constexpr double kNsPerVertex = 10000;
// The heightfield: h (8 bytes), band (4), the stamped a and b (8 + 8) and the painting rows (36
// measured) a cell; a contour vertex is a segment in two segment grids (its contour's and its
// parent's children's), each with its ends (32 bytes), its share of up to 16 buckets' counts and
// starts (segment_grid.cpp) and its bucket entries: 160 bytes a vertex measured on jacksboro /
// improved at d = 20 m (34,888 vertices, 7.85 MB at res 256, 2026-12-06), 240 with a margin. (48
// before: true while seeds kept few, long edges; the seed resampled at d/4, issue 31, keeps many
// short ones, and the grids' buckets follow the segments.) Time a cell (painting, stamping about
// three contours' windows, the band height) and a vertex (its segment grid). The band fill's W,
// marks and heap, where it raises cells, stay under the same figure (tested on valleys).
constexpr double kBytesPerCell = 36, kBytesPerGridVertex = 240;
constexpr double kNsPerCell = 600, kNsPerGridVertex = 400;
// The erosion pass (EstimateErosion): its buffers a cell, a pass's time a cell (about 200 ns
// natively: 0.26 s for 20 passes at res 256; 6.8 s at res 1024, 340 ns, under load), and a
// drainage measure's.
constexpr double kBytesPerErosionCell = 160, kNsPerErosionCellPass = 500, kNsPerDrainageCell = 200;
// One edge test of the union sweep (WindingBeside), with the sweep's other per-test work: 7 to 15
// ns on the combs of docs/budgets.md (native release, a loaded 2-core host), twice the slowest
// (26 ns was seen under four parallel builds).
constexpr double kNsPerSweepTest = 30;
// A sample of a contour's Fourier perturbation (resampling, the forward and inverse FFT, the
// collinear pass): 1.2-1.4 µs at nfft 1,024 (a 3,000-tooth comb's 6,000 rings of 12 points took
// 7.3-8.1 s in it, native release, a loaded 2-core host), with a margin: 0.2 of a vertex's 10 µs.
constexpr double kVerticesPerFftSample = 0.2;

double Vertices(const Terrain& t) {
  double n = 0;
  for (const ContourNode& c : t.contours) n += static_cast<double>(c.ring.size());
  return n;
}

// Output sizes: bytes a cell and a contour vertex, fixed, the peak memory per output byte (the
// mesh or document, the buffers and the file's bytes at once) and the time per output byte.
struct OutputCost {
  double per_cell, per_vertex, fixed, memory_per_byte, ns_per_byte;
  const char* what;
};
// .glb: a vertex a cell (position, normal, texture coordinates, colour: 44 bytes) and two
// triangles (24 bytes of indices), the contour lines' 12-byte vertices and 8 bytes of indices; the
// heightmap: 2 bytes a cell (deflated, with the image and its rows held); the contour files a
// vertex as text.
constexpr OutputCost kGlb = {68, 20, 65536, 6, 20, "writing the .glb"};  // 6: WASM peaks at 5.3x
constexpr OutputCost kHeightmap = {2, 0, 8192, 8, 60, "writing the heightmap"};
constexpr OutputCost kJson = {0, 40, 8192, 7, 60, "writing the contours' .json"};
constexpr OutputCost kGeoJson = {0, 40, 8192, 7, 60, "writing the contours' .geojson"};
constexpr OutputCost kSvg = {0, 24, 8192, 3, 60, "writing the contours' .svg"};

}  // namespace

TerrainGrowLimits TerrainLimits(const TerrainParams& params, const Budget& budget) {
  TerrainGrowLimits l;
  // The heightfield of res cells a side (at most (res + 2)² cells) is held back, so a growth
  // stopped early still gets its surface.
  const double side = params.GetInt(TerrainParam::kRes) + 2.0;
  l.max_bytes =
      std::max(0.0, static_cast<double>(budget.memory_bytes) - kBytesPerCell * side * side);
  l.max_seconds = std::max(0.0, budget.seconds - kNsPerCell * 1e-9 * side * side);
  l.base_bytes = kBaseBytes;
  l.bytes_per_vertex = kBytesPerVertex;
  l.transient_bytes_per_vertex = kTransientBytesPerVertex;
  l.seconds_per_vertex = kNsPerVertex * 1e-9;
  l.seconds_per_sweep_test = kNsPerSweepTest * 1e-9;
  l.memory_limit = budget.memory_limit;
  l.seconds_limit = budget.seconds_limit;
  return l;
}

namespace {

// The worst case of a contour's children (terrain_budget.h TerrainGrowLimits): m vertices.
double WorstChildren(const Ring& parent, double d0, const TerrainParams& params,
                     const TerrainGrowLimits& l) {
  double m = static_cast<double>(parent.size());
  if (params.GetInt(TerrainParam::kMethod) != 0) {  // §4.1-§4.3 perturb: splits, resampling
    if (d0 > 0) m = std::max(m, Perimeter(parent) / d0);
    m = std::max(m, static_cast<double>(params.GetInt(TerrainParam::kNfft)));
  }
  return m * l.growth;
}

// The children (at most m vertices) are held with the rest once made: counted here, so that the
// grown contours' estimate (EstimateTerrainGrown, which holds them all) stays within a limit that
// stopped the growth.
double CheckBytes(const TerrainGrowLimits& l, double held, double m) {
  return l.base_bytes + l.bytes_per_vertex * (held + m) + l.transient_bytes_per_vertex * m;
}

double CheckSeconds(const TerrainGrowLimits& l, double worked, double n, double m) {
  return l.seconds_per_vertex * (worked + n + m);
}

}  // namespace

std::string CheckTerrainContour(const Ring& parent, double d0, const TerrainParams& params,
                                const TerrainWork& work, const TerrainGrowLimits& l, int level) {
  const double n = static_cast<double>(parent.size());
  const double m = WorstChildren(parent, d0, params, l);
  const std::string where = "at level " + std::to_string(level) + " of " +
                            std::to_string(params.GetInt(TerrainParam::kMaxLevels));
  const double bytes = CheckBytes(l, work.vertices_held, m);
  if (l.max_bytes >= 0 && bytes > l.max_bytes) {
    return TruncatedLine(l.memory_limit, where,
                         FormatCount(work.vertices_held + m) +
                             " contour vertices would need more than " + FormatBytes(l.max_bytes),
                         kTerrainGrowChange + RaiseHint(l.memory_limit));
  }
  const double seconds = CheckSeconds(l, work.vertices_worked, n, m);
  if (l.max_seconds >= 0 && seconds > l.max_seconds) {
    return TruncatedLine(l.seconds_limit, where,
                         "shrinking " + FormatCount(work.vertices_worked + n + m) +
                             " contour vertices would take more than " +
                             FormatSeconds(l.max_seconds),
                         kTerrainGrowChange + RaiseHint(l.seconds_limit));
  }
  return "";
}

double PerturbationWork(std::size_t rings, const TerrainParams& params) {
  const int method = params.GetInt(TerrainParam::kMethod);
  if (method != static_cast<int>(Method::kFourier) && method != static_cast<int>(Method::kImproved))
    return 0;
  return kVerticesPerFftSample * static_cast<double>(params.GetInt(TerrainParam::kNfft)) *
         static_cast<double>(rings);
}

std::string CheckTerrainPerturbation(const Ring& parent, std::size_t rings,
                                     const TerrainParams& params, const TerrainWork& work,
                                     const TerrainGrowLimits& l, int level) {
  const double fft = PerturbationWork(rings, params);
  if (l.max_seconds < 0 || fft <= 0 ||
      l.seconds_per_vertex * (work.vertices_worked + fft) <= l.max_seconds)
    return "";
  return TruncatedLine(
      l.seconds_limit,
      "at level " + std::to_string(level) + " of " +
          std::to_string(params.GetInt(TerrainParam::kMaxLevels)),
      "perturbing the " + FormatCount(static_cast<double>(rings)) + " contours inside one of " +
          FormatCount(static_cast<double>(parent.size())) + " points (each resampled to nfft = " +
          std::to_string(params.GetInt(TerrainParam::kNfft)) + ") would take more than " +
          FormatSeconds(l.max_seconds),
      "lower nfft, raise d, or lower max_levels or the seed's points" + RaiseHint(l.seconds_limit));
}

double SweepTestsLeft(const TerrainGrowLimits& l, const TerrainWork& work, double so_far) {
  if (l.max_seconds < 0 || !(l.seconds_per_sweep_test > 0)) return -1;
  const double seconds = l.max_seconds - l.seconds_per_vertex * work.vertices_worked;
  return std::max(0.0, seconds / l.seconds_per_sweep_test - so_far);
}

std::string SweepStoppedLine(const Ring& parent, double allowed, const TerrainGrowLimits& l,
                             int level, int max_levels) {
  return TruncatedLine(
      l.seconds_limit, "at level " + std::to_string(level) + " of " + std::to_string(max_levels),
      SweepStoppedWhy(parent, allowed, l), kTerrainGrowChange + RaiseHint(l.seconds_limit));
}

std::string SweepStoppedWhy(const Ring& parent, double allowed, const TerrainGrowLimits& l) {
  return "shrinking a contour of " + FormatCount(static_cast<double>(parent.size())) +
         " points needs more than the " + FormatCount(allowed) + " edge tests of its union sweep " +
         "that " + l.seconds_limit +
         " leaves (edges side by side across its height, as a comb's teeth)";
}

bool GrowFitsLimits(const Terrain& t, const TerrainParams& params, const TerrainGrowLimits& l) {
  if (t.contours.empty()) return true;
  // Grow's d0 (the resampled seed's mean edge; the down chain's checks use 0, which asks less).
  const double d0 = t.d0;
  const double held = Vertices(t) + static_cast<double>(t.seed_samples),
               worked = t.counts.vertices_worked;
  for (const ContourNode& c : t.contours) {
    // The seed was shrunk as resampled (its points and about its perimeter).
    const double n = c.level == 0 ? std::max(static_cast<double>(c.ring.size()),
                                             static_cast<double>(t.seed_samples))
                                  : static_cast<double>(c.ring.size());
    const double m = std::max(WorstChildren(c.ring, d0, params, l), n * l.growth);
    if (l.max_bytes >= 0 && CheckBytes(l, held, m) > l.max_bytes) return false;
    if (l.max_seconds >= 0 && CheckSeconds(l, worked, n, m) > l.max_seconds) return false;
  }
  return true;
}

double ShrinkSweepTests(const Ring& ring) { return ring.size() < 2 ? 0 : UnionSweepWork(ring); }

double SeedShrinkForecast::work() const {
  return windings + kSweepWorkPerSplit * split_points + kSweepWorkPerTry * tried_pairs;
}

SeedShrinkForecast ForecastSeedShrink(const Ring& seed, const TerrainParams& p) {
  SeedShrinkForecast f;
  if (seed.size() < 3) return f;
  // As Grow: the seed normalised (CheckSeed), then shrunk with the table's options (enlarged
  // first when down > 0).
  const Ring normal = Normalise(seed);
  if (normal.size() < 3) return f;
  // Grow shrinks the seed resampled at d/4 (generate.h ResampleSeed): its points are forecast.
  const Ring ring = ResampleSeed(seed, normal, p.Get(TerrainParam::kD));
  f.windings = ShrinkSweepTests(ring);
  f.tried_pairs = TriedEdgePairs(ring);  // IsSimple
  ShrinkOptions so;
  so.d = p.Get(TerrainParam::kD);
  so.join = static_cast<Join>(p.GetInt(TerrainParam::kJoin));
  so.c = p.Get(TerrainParam::kC);
  so.clean_len = p.Get(TerrainParam::kCleanLen) * so.d;
  so.clean_angle_deg = p.Get(TerrainParam::kCleanAngle);
  so.keep_straight = true;  // as Grow
  for (const bool outward : {false, true}) {
    if (outward && p.GetInt(TerrainParam::kDown) == 0) break;
    so.outward = outward;
    const SplitForecast s = ForecastSplits(ring, so);
    const double splits = 2 * s.box_pairs;
    f.split_points += splits;
    f.tried_pairs += s.tried_pairs;
    if (splits > 0 && s.segments > 0)
      f.tried_pairs += 2 * (1 + splits / s.segments) * s.tried_pairs;
  }
  return f;
}

Status CheckSeedShape(const Ring& seed, const TerrainParams& params, const Budget& budget) {
  // CheckSeed's own refusals come first (in Grow), and the forecast needs finite grid points.
  if (seed.size() < 3 || seed.size() > kMaxSeedPoints) return Status::Ok();
  for (const Vec2& v : seed)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || std::fabs(v.x) > kMaxCoordinate ||
        std::fabs(v.y) > kMaxCoordinate)
      return Status::Ok();
  const SeedShrinkForecast f = ForecastSeedShrink(seed, params);
  const double seconds = kNsPerSweepTest * 1e-9 * f.work();
  if (seconds <= budget.seconds) return Status::Ok();
  return Status::Error("contour",
                       FormatCount(static_cast<double>(seed.size())) +
                           " points whose shape needs about " + FormatSeconds(seconds) +
                           " to shrink once (" + FormatCount(f.split_points) +
                           " split points of its offset path, " + FormatCount(f.tried_pairs) +
                           " edge pairs tried: many edges side by side within 2·d, as a comb's "
                           "teeth); must take at most " +
                           FormatSeconds(budget.seconds) + " (" + budget.seconds_limit +
                           "); simplify the contour or lower d" + RaiseHint(budget.seconds_limit));
}

Estimate EstimateTerrainGrown(const Terrain& t, const TerrainGrowLimits& l) {
  Estimate e;
  const double vertices = Vertices(t) + static_cast<double>(t.seed_samples);
  // The largest contour in the making held its copies at once: the largest one shrunk (a contour
  // a budget stopped before is not; the resampled seed is, when it was shrunk).
  const double largest = t.counts.largest_worked;
  e.memory_bytes = l.base_bytes + l.bytes_per_vertex * vertices +
                   l.transient_bytes_per_vertex * l.growth * largest;
  e.seconds = l.seconds_per_vertex * t.counts.vertices_worked;
  e.what = "growing " + FormatCount(static_cast<double>(t.contours.size())) + " contours (" +
           FormatCount(vertices) + " vertices)";
  return e;
}

GridSize TerrainGridSize(const Terrain& t, int res) {
  if (t.contours.empty() || t.contours[0].ring.empty() || res <= 0) return {};
  // As heightfield.cpp's GridFor: res cells along the root's longer side, one of margin a side.
  const Ring& root = t.contours[0].ring;
  const RingBox box = BoundsOf(root);
  const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  const double span = box.span();
  const double cell = span / res;
  if (!(cell > 0)) return {};
  return {std::ceil((x1 - x0) / cell) + 2, std::ceil((y1 - y0) / cell) + 2};
}

Estimate EstimateHeightfield(const Terrain& t, const GridSize& g) {
  const double vertices = Vertices(t);
  Estimate e;
  e.memory_bytes = kBytesPerCell * g.cells() + kBytesPerGridVertex * vertices;
  e.seconds = (kNsPerCell * g.cells() + kNsPerGridVertex * vertices) * 1e-9;
  e.what = "the heightfield (" + FormatCount(g.width) + " × " + FormatCount(g.height) + " cells)";
  return e;
}

Estimate EstimateErosion(const GridSize& g, const TerrainParams& params) {
  Estimate e;
  if (params.GetInt(TerrainParam::kErosion) == 0) return e;
  const double passes = params.GetInt(TerrainParam::kErosionIterations);
  e.memory_bytes = kBytesPerErosionCell * g.cells();
  e.seconds = (kNsPerErosionCellPass * passes + 2 * kNsPerDrainageCell) * 1e-9 * g.cells();
  e.what =
      "the erosion (" + FormatCount(passes) + " passes over " + FormatCount(g.cells()) + " cells)";
  return e;
}

Estimate EstimateTerrainOutput(const Terrain& t, const GridSize& g, TerrainOutput kind) {
  const OutputCost& c = kind == TerrainOutput::kGlb         ? kGlb
                        : kind == TerrainOutput::kHeightmap ? kHeightmap
                        : kind == TerrainOutput::kGeoJson   ? kGeoJson
                        : kind == TerrainOutput::kSvg       ? kSvg
                                                            : kJson;
  const double bytes = c.fixed + c.per_cell * g.cells() + c.per_vertex * Vertices(t);
  Estimate e;
  e.memory_bytes = c.memory_per_byte * bytes;
  e.seconds = c.ns_per_byte * 1e-9 * bytes;
  e.what = c.what;
  return e;
}

}  // namespace niwa::terrain
