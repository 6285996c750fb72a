// The ivy study's budgets: the support's estimate, Grow's per-step check and the export estimates
// (constants measured in docs/budgets.md, "Ivy").
#include "ivy/ivy_budget.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace niwa::ivy {
namespace {

// Fixed sizes, not sizeof (the WASM build's pointers are half as wide and both builds must stop
// at the same step). A Bud is 200 bytes natively (positions, directions, anchor in double), an
// Internode 16, the crowding grid's entry and its cell share 64 (measured on the wall); the
// PreOrder and rule lists of a step 8 a bud; the vectors double, so up to twice each while growing.
constexpr double kBaseBytes = kIvyBaseBytes;  // the process, tables, code
constexpr double kBytesPerBud = 2.0 * (200 + 16 + 64) + 8;
// Support: a TriMesh triangle (3 positions and normals once shared, 3 indices) about 40 bytes
// after Subdivide (which makes new vertices per triangle: 3 × (12 + 12) + 12 = 84) and the BVH's
// node and reference per triangle (64, measured); the subdivision holds the source and the result.
constexpr double kBytesPerSubdividedTriangle = 84, kBytesPerBvhTriangle = 64;
// The growth's and the support's times are IvyCosts' (ivy_budget.h): 3 µs a final triangle built,
// 0.6 µs a bud-step and 1.5 µs a candidate by default, native release (the slowest of several runs,
// times a margin).

// --stats (MeasureIvy): a brute-force triangle test (closest point or segment crossing), a pair
// of the overlap sweep tested by distance, and per bud the L-string (about 100 bytes printed, 5 ×
// while re-read: its pairs and both sorted key lists) and the sweep's span (24 bytes, twice).
// One set of constants for both builds (they stop and refuse at the same point), so they cover
// the slower, WASM under node (docs/budgets.md, CPU seconds): a triangle test 12 ns natively, 21
// in WASM (758 buds on 16,384 triangles); a pair 27-38 ns natively and 54-61 in WASM (3.4 M to
// 195 M pairs of the free literal replay; cache misses grow with the count: 65 ns natively was
// measured at 671 M pairs, so about 110 in WASM there).
constexpr double kNsPerTriangleTest = 40;
constexpr double kNsPerOverlapPair = 160;
constexpr double kNsPerStatsBud = 3000;  // printing, re-reading, sorting the L-string
constexpr double kStatsBytesPerBud = 5 * 100 + 2 * 24;
// The leaves as drawn for --stats (IvyRun::StatsJson): the ivy meshed (BuildIvyMeshes reserves
// exactly its .glb's vertices and indices, kGlb.per_bud below, and copies each part's birth steps
// into its attribute, 56 floats a bud) and the leaf cover's two 256² rasters of doubles. Times:
// a bud's tube, sucker and leaf with its placement checks (segment queries on the BVH), and a
// triangle drawn into a raster (its cells: small leaf triangles; a support's big triangles cover
// more, not counted) and a raster cell compared, measured in tests/ivy/ivy_budget_test.cpp
// (StatsMeshesAndLeafCoverAreInTheEstimate; docs/budgets.md).
constexpr double kMeshBirthCopyBytesPerBud = 56 * 4;
constexpr double kCoverCells = 256.0 * 256.0;
constexpr double kNsPerMeshedBud = 60000;
constexpr double kNsPerCoverTriangle = 400;
constexpr double kNsPerCoverCell = 20;

double AliveBuds(const IvyModel& model) {
  double alive = 0;
  for (const Bud& b : model.buds)
    if (b.kind != BudKind::kEnding) ++alive;
  return alive;
}

// Export sizes: output bytes per bud and per internode, the peak memory per output byte and the
// time per output byte.
struct ExportCost {
  double per_bud, per_internode, per_support_triangle, fixed, memory_per_byte, ns_per_byte;
  const char* what;
};
// .json: each bud's fields (about 520 bytes) and internode (80); .lsys: a module a bud; .svg: two
// views of every internode, leaf and support edge; .glb: 56 vertices of 28 bytes and 54 triangles
// of 12 bytes a bud (stem, sucker and leaf tubes and fans), 8 bytes of texture coordinates on each
// of its 23 leaf vertices, the support's 3 vertices and 12 bytes of indices a triangle, and the
// leaf texture (a 256² image painted once, its PNG about 30 kB, copied into the document).
constexpr ExportCost kJson = {520, 80, 0, 8192, 11, 90, "writing the .json"};
constexpr ExportCost kLsys = {70, 0, 0, 1024, 5, 60, "writing the .lsys"};
constexpr ExportCost kSvg = {260, 0, 160, 8192, 3, 60, "writing the .svg"};
constexpr ExportCost kGlb = {56 * 28 + 23 * 8 + 54 * 12, 0, 84, 131072, 7, 40, "writing the .glb"};

}  // namespace

double IvyPageMeshBytesPerBud(double leaves_per_bud) {
  return 2 * (kGlb.per_bud + (leaves_per_bud - 1) * kIvyGlbBytesPerLeaf) + 20;
}

Estimate EstimateIvySupport(const IvySupportSize& s) {
  const double after = s.triangles * std::pow(4.0, s.levels);
  Estimate e;
  const double copies = s.obstacles ? 2 : 1;
  e.memory_bytes =
      copies * (after * kBytesPerSubdividedTriangle + (s.bvh ? after * kBytesPerBvhTriangle : 0)) +
      (s.levels > 0 ? s.triangles * kBytesPerSubdividedTriangle : 0);
  e.memory_bytes += kBaseBytes;
  e.seconds = copies * after * s.costs.triangle_build;
  e.what = s.levels > 0 ? "subdividing the support to " + FormatCount(after) + " triangles"
                        : "holding the support (" + FormatCount(after) + " triangles)";
  return e;
}

IvyGrowLimits IvyLimits(const IvyParams& params, const Budget& budget, const Estimate& support,
                        bool has_support, const IvyCosts& costs) {
  IvyGrowLimits l;
  l.max_bytes = static_cast<double>(budget.memory_bytes);
  l.max_seconds = budget.seconds;
  l.base_bytes = support.memory_bytes;  // the process and the support
  l.bytes_per_bud = kBytesPerBud;
  l.seconds_before = support.seconds;
  l.seconds_per_bud_step = costs.bud_step;
  l.seconds_per_candidate = costs.candidate;
  // The walk's n_c · (R_max + 1), the tangent fan's directions when it is on, and a hanging
  // tendril's one when "hang" is.
  l.candidates_per_search =
      has_support ? params.GetInt(IvyParam::kCandidates) * (params.GetInt(IvyParam::kRetries) + 1) +
                        (params.GetBool(IvyParam::kTangentRetry) ? kTangentFanCandidates : 0) +
                        (params.GetInt(IvyParam::kHang) > 0 ? 1 : 0)
                  : 0;
  l.memory_limit = budget.memory_limit;
  l.seconds_limit = budget.seconds_limit;
  return l;
}

std::string CheckIvyStep(const IvyModel& model, const GrowLog& log, const IvyGrowLimits& l,
                         int step, int steps) {
  const double buds = static_cast<double>(model.buds.size());
  const double alive = AliveBuds(model);
  const std::string where = "at step " + std::to_string(step) + " of " + std::to_string(steps);
  const double bytes = l.base_bytes + l.bytes_per_bud * (buds + alive);
  if (l.max_bytes >= 0 && bytes > l.max_bytes) {
    return TruncatedLine(l.memory_limit, where,
                         FormatCount(buds) + " buds and " + FormatCount(alive) +
                             " growing would need more than " + FormatBytes(l.max_bytes),
                         l.change + RaiseHint(l.memory_limit));
  }
  const double seconds = l.seconds_before + l.seconds_per_bud_step * (log.bud_steps + buds) +
                         l.seconds_per_candidate * (static_cast<double>(log.candidates) +
                                                    alive * l.candidates_per_search) +
                         l.seconds_per_bud * (buds + alive);
  if (l.max_seconds >= 0 && seconds > l.max_seconds) {
    return TruncatedLine(l.seconds_limit, where,
                         "the next step over " + FormatCount(buds) + " buds would take more than " +
                             FormatSeconds(l.max_seconds),
                         l.change + RaiseHint(l.seconds_limit));
  }
  return "";
}

Estimate EstimateIvyGrown(const IvyModel& model, const GrowLog& log, const IvyGrowLimits& l) {
  const double buds = static_cast<double>(model.buds.size());
  Estimate e;
  e.memory_bytes = l.base_bytes + l.bytes_per_bud * buds;
  e.seconds = l.seconds_before + l.seconds_per_bud_step * log.bud_steps +
              l.seconds_per_candidate * static_cast<double>(log.candidates) +
              l.seconds_per_bud * buds;
  e.what = "growing the ivy (" + FormatCount(buds) + " buds)";
  return e;
}

IvyStatsWork CountIvyStatsWork(const IvyModel& model, const IvyParams& params,
                               double support_triangles) {
  IvyStatsWork w;
  w.buds = static_cast<double>(model.buds.size());
  w.internodes = static_cast<double>(model.internodes.size());
  w.triangle_tests = (w.buds + w.internodes) * support_triangles;
  // The sweep of ivy_report (spans sorted by their low x; span i tests every later span whose low
  // x is within hi_i + 2 r_tip): the same count by binary search, without a distance.
  const double reach = 2 * params.Get(IvyParam::kRTip);
  std::vector<double> lo;
  std::vector<double> hi;
  lo.reserve(model.internodes.size());
  hi.reserve(model.internodes.size());
  for (const Internode& in : model.internodes) {
    const double x0 = model.buds[static_cast<std::size_t>(in.from_bud)].pos.x;
    const double x1 = model.buds[static_cast<std::size_t>(in.to_bud)].pos.x;
    lo.push_back(std::min(x0, x1));
    hi.push_back(std::max(x0, x1));
  }
  std::vector<std::size_t> order(lo.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return lo[a] < lo[b] || (lo[a] == lo[b] && a < b);
  });
  std::vector<double> sorted_lo(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) sorted_lo[i] = lo[order[i]];
  for (std::size_t i = 0; i < order.size(); ++i) {
    const double limit = hi[order[i]] + reach;
    const auto end = std::upper_bound(sorted_lo.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                      sorted_lo.end(), limit);
    w.overlap_pairs_examined +=
        static_cast<double>(end - (sorted_lo.begin() + static_cast<std::ptrdiff_t>(i) + 1));
  }
  return w;
}

Estimate EstimateIvyStats(const IvyStatsWork& w) {
  Estimate e;
  e.memory_bytes =
      kStatsBytesPerBud * w.buds + 8192 +
      (kGlb.per_bud + (w.leaves_per_bud - 1) * kIvyGlbBytesPerLeaf + kMeshBirthCopyBytesPerBud) *
          w.meshed_buds +
      (w.leaf_cover ? 2 * kCoverCells * 8 : 0);
  e.seconds = 1e-9 * (kNsPerTriangleTest * w.triangle_tests +
                      kNsPerOverlapPair * w.overlap_pairs_examined + kNsPerStatsBud * w.buds +
                      kNsPerMeshedBud * w.meshed_buds + kNsPerCoverTriangle * w.cover_triangles +
                      (w.leaf_cover ? kNsPerCoverCell * 2 * kCoverCells : 0));
  e.what = "measuring the statistics (" + FormatCount(w.buds) + " buds re-checked against " +
           FormatCount(w.buds > 0 ? w.triangle_tests / (w.buds + w.internodes) : 0) +
           " triangles, " + FormatCount(w.overlap_pairs_examined) + " internode pairs)";
  return e;
}

void ReserveIvyStats(double support_triangles, IvyGrowLimits* limits, bool meshes,
                     double leaves_per_bud) {
  // Each bud adds itself and (but a seed) its internode to the brute-force re-checks, and its
  // leaf's triangles to the leaf cover's raster; meshed for it (meshes) its tube, sucker and leaf.
  limits->seconds_per_bud += 1e-9 * (kNsPerTriangleTest * 2 * support_triangles + kNsPerStatsBud);
  limits->bytes_per_bud += kStatsBytesPerBud;
  if (support_triangles > 0)
    limits->seconds_per_bud +=
        1e-9 * kNsPerCoverTriangle * kIvyLeafTrianglesPerBud * leaves_per_bud;
  if (meshes) {
    limits->seconds_per_bud += 1e-9 * kNsPerMeshedBud * leaves_per_bud;
    limits->bytes_per_bud +=
        kGlb.per_bud + (leaves_per_bud - 1) * kIvyGlbBytesPerLeaf + kMeshBirthCopyBytesPerBud;
  }
}

Estimate EstimateIvyExport(const IvyModel& model, IvyExport kind, double support_triangles,
                           double leaves_per_bud) {
  const ExportCost& c = kind == IvyExport::kJson   ? kJson
                        : kind == IvyExport::kLsys ? kLsys
                        : kind == IvyExport::kSvg  ? kSvg
                                                   : kGlb;
  const double buds = static_cast<double>(model.buds.size());
  const double per_bud =
      c.per_bud + (kind == IvyExport::kGlb ? (leaves_per_bud - 1) * kIvyGlbBytesPerLeaf : 0);
  const double bytes = c.fixed + per_bud * buds +
                       c.per_internode * static_cast<double>(model.internodes.size()) +
                       c.per_support_triangle * support_triangles;
  Estimate e;
  e.memory_bytes = c.memory_per_byte * bytes;
  e.seconds = c.ns_per_byte * 1e-9 * bytes;
  e.what = std::string(c.what) + " (" + FormatCount(buds) + " buds)";
  return e;
}

namespace {

// "growing the ivy (5,239 buds) and writing the .glb (5,239 buds)" without its " (...)" parts.
std::string WithoutCounts(const std::string& what) {
  std::string out;
  int depth = 0;
  for (std::size_t i = 0; i < what.size(); ++i) {
    if (what[i] == ' ' && i + 1 < what.size() && what[i + 1] == '(' && depth == 0) continue;
    if (what[i] == '(') ++depth;
    if (depth == 0) out += what[i];
    if (what[i] == ')' && depth > 0) --depth;
  }
  return out;
}

}  // namespace

Status ProjectIvyBuds(BudProjection* p, double buds, double new_buds, double bud_steps,
                      const Estimate& exported, double seconds_so_far, const IvyGrowLimits& limits,
                      const Budget& budget, int step, int steps, const std::string& change) {
  const BudProjection before = *p;
  *p = BudProjection{buds, new_buds, exported, buds, step};
  if (before.buds <= 0 || buds <= before.buds || new_buds <= 0 || new_buds < before.new_buds)
    return Status::Ok();
  double m = static_cast<double>(steps - step);  // further steps
  if (limits.max_bytes >= 0 && limits.bytes_per_bud > 0) {
    const double cap = (limits.max_bytes - limits.base_bytes) / (2 * limits.bytes_per_bud);
    m = std::min(m, std::floor((cap - buds) / new_buds));
  }
  // The growth's estimated seconds a bud-step so far (its searches as counted), at least the
  // bud-step constant, with the room kept per bud.
  const double c = std::max(limits.seconds_per_bud_step,
                            (seconds_so_far - limits.seconds_before) / std::max(1.0, bud_steps)) +
                   limits.seconds_per_bud;
  if (limits.max_seconds >= 0 && c > 0) {
    // c · Σ_{i=1..m} (buds + i · new_buds) <= the time left.
    const double left = std::max(0.0, limits.max_seconds - seconds_so_far) / c;
    const double a = new_buds / 2, b = buds + new_buds / 2;
    m = std::min(m, std::floor((-b + std::sqrt(b * b + 4 * a * left)) / (2 * a)));
  }
  if (!(m > 0)) return Status::Ok();
  p->final_buds = buds + m * new_buds;
  p->final_step = step + static_cast<int>(m);
  const double more = p->final_buds - buds, span = buds - before.buds;
  Estimate e;
  e.memory_bytes =
      exported.memory_bytes +
      std::max(0.0, (exported.memory_bytes - before.exported.memory_bytes) / span) * more;
  e.seconds =
      exported.seconds + std::max(0.0, (exported.seconds - before.exported.seconds) / span) * more;
  e.what = "growing on to about " + FormatCount(p->final_buds) + " buds by step " +
           std::to_string(p->final_step) + " (at least the " + FormatCount(new_buds) +
           " new buds of step " + std::to_string(step) + " each step) and " +
           WithoutCounts(exported.what);
  const Status fits = CheckEstimate(e, budget, change);
  if (fits.ok()) return fits;
  return Status::Error("steps", "at step " + std::to_string(step) + " of " + std::to_string(steps) +
                                    ": " + fits.message());
}

}  // namespace niwa::ivy
