// Memory and time budgets of the ivy study (issue 16, docs/budgets.md): the support's estimate (a
// --subdivide refused before it runs), the limits Grow checks before every step (stopping with
// GrowLog::truncated_by and a line naming the limit), and the estimates of the exports (.json,
// .lsys, .svg, .glb) and of the --stats measurement (ivy_report's brute-force re-checks, overlap
// sweep and L-string re-read) from the grown model's counts. Does not: measure memory or wall-clock
// time (every figure is a count times a constant calibrated in docs/budgets.md; time is a work-unit
// count, so the native and WASM builds stop at the same step), grow or mesh ivy.
#pragma once

#include <string>

#include "base/budget.h"
#include "ivy/ivy.h"
#include "ivy/ivy_params.h"

namespace niwa::ivy {

// What Grow may use (no limit when max_bytes and max_seconds are negative). Before step s it
// checks that the worst case after the step stays within both: every alive bud (A or D) makes at
// most one new bud and internode, and every search evaluates at most n_c · (R_max + 1) candidates
// (+ kTangentFanCandidates with tangent_retry).
//   memory  = base_bytes + bytes_per_bud · (buds + alive)
//   seconds = seconds_before + seconds_per_bud_step · Σ_steps buds + seconds_per_candidate ·
//             (candidates so far + alive · n_c · (R_max + 1)) + seconds_per_bud · (buds + alive)
// What the refusal and truncation lines tell the user to change (the CLI's flags; the page names
// its own fields: IvyGrowLimits::change).
// In state fields; the CLI says the same with its flags (native_cli/ivy_commands.cpp).
inline constexpr char kIvyChange[] = "lower steps or subdivide, or raise t1 and t2";
inline constexpr char kIvyStatsChange[] =
    "lower steps or subdivide, or raise t1 and t2, or leave out the statistics";

// The process, its tables and code: every ivy estimate's memory starts at it.
inline constexpr double kIvyBaseBytes = 64.0 * 1024 * 1024;

// What the ivy's time estimates count a unit of work at, in seconds. The defaults are the study's
// own (docs/budgets.md "Ivy": the slowest of several runs on its scenes, times a margin); a
// composed run passes its measured figures (compose/garden_run.h GardenIvyCosts), as the moss's
// MossCosts.
struct IvyCosts {
  double triangle_build = 3e-6;  // a final support triangle: subdividing it and its BVH
  double bud_step = 0.6e-6;      // a bud a step: PreOrder, rule choice, ΣN and Alive
  double candidate = 1.5e-6;     // a candidate position: closest point, segment hit, crowding
};

struct IvyGrowLimits {
  double max_bytes = -1, max_seconds = -1;
  double base_bytes = 0, bytes_per_bud = 0;
  double seconds_before = 0;  // the support's (subdivision, BVH) estimate
  double seconds_per_bud_step = 0, seconds_per_candidate = 0;
  // Work done once per bud after the growth (the --stats measurement: ReserveIvyStats), 0 without.
  double seconds_per_bud = 0;
  double candidates_per_search = 0;  // n_c · (R_max + 1) (+ the fan's); 0 without a support
  std::string memory_limit = "max_memory", seconds_limit = "max_seconds";
  std::string change = kIvyChange;  // what a truncation line says to change
};

// The support the ivy climbs: `triangles` after subdividing `levels` times (4^K each), its BVH.
struct IvySupportSize {
  double triangles = 0;    // before subdividing
  int levels = 0;          // --subdivide K
  bool bvh = true;         // --accel bvh (the linear twin builds none)
  bool obstacles = false;  // a second (attach) mesh and BVH
  // What a final triangle takes to build (IvyCosts::triangle_build; the study's by default).
  IvyCosts costs;
};
// Memory and time of the process with its support (the mesh, its subdivision and BVH, held while
// the ivy grows); `what` names it ("subdividing the support to 4,194,304 triangles").
Estimate EstimateIvySupport(const IvySupportSize& support);

// The limits of growing `params` within `budget` on top of `support` (already held);
// `has_support` false: the free replay, whose searches evaluate no candidates. The bud-steps and
// candidates are counted at `costs` (the study's by default).
IvyGrowLimits IvyLimits(const IvyParams& params, const Budget& budget, const Estimate& support,
                        bool has_support, const IvyCosts& costs = IvyCosts{});

// Grow's check before step `step` of `steps`: "" when the worst case after the step fits, else the
// truncation line ("--max-memory: stopped at step 37 of 10000: more buds would need more than 2 GB;
// lower --steps ... (or raise --max-memory)").
std::string CheckIvyStep(const IvyModel& model, const GrowLog& log, const IvyGrowLimits& limits,
                         int step, int steps);

// The grown model's estimate (what Grow's check used for the buds it made, without the next step).
Estimate EstimateIvyGrown(const IvyModel& model, const GrowLog& log, const IvyGrowLimits& limits);

// The --stats measurement (MeasureIvy) of a grown model on a support of `support_triangles`
// (0: the free replay): every bud's clearance and every internode's crossing re-tested by brute
// force against every triangle, the x-sweep for overlapping internode pairs, the L-string printed
// and re-read. Counted exactly from the model before any of it runs.
struct IvyStatsWork {
  double buds = 0, internodes = 0;
  double triangle_tests = 0;          // (buds + internodes) · triangles: an upper bound
  double overlap_pairs_examined = 0;  // pairs the x-sweep tests by distance (exact)
  // The leaves as drawn (IvyRun::StatsJson, on a support): the buds meshed for them
  // (BuildIvyMeshes: a tube, a sucker and a checked leaf a bud; 0 where the run holds its meshes
  // already, the page), and the leaf cover's two 256² depth rasters over the support's triangles
  // and the leaves' (kIvyLeafTrianglesPerBud a bud at most).
  double meshed_buds = 0;
  double leaves_per_bud = 1;  // IvyLeavesPerBud of the run's params
  bool leaf_cover = false;
  double cover_triangles = 0;
};
inline constexpr double kIvyLeafTrianglesPerBud = 46;  // a petiole tube (36) and a blade fan (10)
// A leaf's part of the .glb (its 23 vertices of 28 bytes with 8 bytes of texture coordinates, 46
// triangles of 12 bytes): each further leaf a bud (the row leaf_spacing, IvyLeavesPerBud) adds it.
inline constexpr double kIvyGlbBytesPerLeaf = 23 * 28 + 23 * 8 + 46 * 12;
IvyStatsWork CountIvyStatsWork(const IvyModel& model, const IvyParams& params,
                               double support_triangles);
// Its memory (the sweep's spans, the L-string and its re-read) and time (work-unit constants).
Estimate EstimateIvyStats(const IvyStatsWork& work);
// Keeps room for the measurement in Grow's per-step check: the part that grows with every bud
// (its triangle tests, L-string and spans), so a growth with --stats stops where they still fit;
// the sweep's pairs, which are not linear in the buds, are checked once grown (EstimateIvyStats).
// meshes: the measurement meshes the ivy for its leaves (the CLI; the page's run holds them).
// leaves_per_bud: IvyLeavesPerBud of the run's params.
void ReserveIvyStats(double support_triangles, IvyGrowLimits* limits, bool meshes = false,
                     double leaves_per_bud = 1);

enum class IvyExport { kJson, kLsys, kSvg, kGlb };
// Memory and time of one export of a grown model (upper bounds); `support_triangles` is the
// support written into the .glb (--with-support) or drawn in the .svg, else 0.
Estimate EstimateIvyExport(const IvyModel& model, IvyExport kind, double support_triangles,
                           double leaves_per_bud = 1);

// A planned export's projection to the last step (IvyRun::Advance, issue 34), made as the buds
// grow by 5 %: the buds the growth will have by the last step if every further step adds at least
// the new buds of the latest one (made only while those do not shrink between projections), cut
// at the step where the growth's own limits would stop it (the memory of buds and their alive
// copies, at most 2 · bytes_per_bud a bud; the time at the growth's estimated seconds a bud-step
// so far, `bud_steps` being Σ buds over the steps made), and the export's estimate there (extended
// along its slope between the last two projections). Refused naming `steps` when that does not fit
// `budget`. Measured against real runs in docs/budgets.md.
struct BudProjection {
  double buds = 0, new_buds = 0;  // at the latest projection
  Estimate exported;              // the export's estimate then
  double final_buds = 0;          // the latest projection's buds at its last step
  int final_step = 0;
};
Status ProjectIvyBuds(BudProjection* projection, double buds, double new_buds, double bud_steps,
                      const Estimate& exported, double seconds_so_far, const IvyGrowLimits& limits,
                      const Budget& budget, int step, int steps, const std::string& change);

// The page's meshes per bud (BuildIvyMeshes, their flat copies and the buds' buffer, held with the
// model): the page adds it to IvyGrowLimits::bytes_per_bud, so the growth stops where they fit.
double IvyPageMeshBytesPerBud(double leaves_per_bud = 1);

}  // namespace niwa::ivy
