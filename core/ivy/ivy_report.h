// What a grown ivy measures (the paper's claims C1-C4 and problems P1-P2 as numbers, spec §3) and
// its JSON: the --stats object and the model (buds, internodes, axes, params). Does not: grow,
// time anything itself (the caller passes the ms fields) or write files.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geom/tri_mesh.h"
#include "ivy/growth.h"
#include "ivy/ivy.h"
#include "ivy/ivy_params.h"

namespace niwa::ivy {

struct IvyStats {
  int steps_run = 0, extinct_step = -1;
  int internodes = 0, buds_A = 0, buds_D = 0, buds_Z = 0;
  int axes = 0, laterals = 0, max_order = 0, main_axis_internodes = 0;
  int first_break_step = -1, released_breaks = 0, reiterations = 0, p3_A = 0, p3_D = 0;
  // C4: Σ lateral / Σ parent internodes made by p0 in the steps both apices were alive (after the
  // lateral's break); NaN (JSON null) when no lateral had such a window with parent growth.
  double rho = 0;
  int rho_laterals = 0;  // laterals whose window held parent growth (the comparisons pooled)
  int lateral_longer_than_parent = 0;  // laterals that made more than their parent in the window
  double frac_nodes_within_d = 0;      // ε <= clearance <= d, re-measured by brute force (C1)
  double clearance_min = 0, clearance_max = 0;
  int internode_hits = 0;  // internodes crossing a face, re-tested by brute force (C1)
  // Internodes whose end normals differ by > 60°: convex iff (anchor_to - anchor_from)·n_from < 0.
  int convex_crossings = 0, concave_crossings = 0;
  double internode_len_err_max = 0;
  double up_min = 0, up_mean = 0, rise = 0;  // C2
  double bend_max = 0;                       // degrees (P1)
  int overlap_pairs = 0;                     // non-adjacent internodes closer than 2 r_tip (P2)
  double overlap_pairs_examined = 0;  // pairs the sweep tested (ivy_budget's CountIvyStatsWork)
  int leaves = 0, suckers = 0;
  // Hanging tendrils (the row "hang"): tendrils started, internodes off the support. Their buds
  // are left out of frac_nodes_within_d (they hold on to nothing) and counted here.
  int64_t tendrils = 0, hang_internodes = 0;
  int hanging_buds = 0;
  // Set by the caller (IvyRun, with the leaves meshed): the share of the support's area seen from
  // the front (+z) that leaves hide (LeafCoverFront); < 0 when not measured (JSON null).
  double leaf_cover = -1;
  int leaves_thinned = 0;  // leaves left out by light (leaf_light)
  double nutrient_total = 0, ledger_err = 0;
  bool lstring_ok = false;
  std::size_t tri_count = 0;
  // Set by the caller: the support's own stop line (a Niwa tree grown within the budget that
  // stopped early), printed as tree_truncated_by when not empty.
  std::string tree_truncated_by;
  // Set by the caller (the page): the budget line of an overlap sweep left out (MeasureIvy with
  // overlap_sweep false; overlap_pairs printed as null and this as overlap_skipped_by).
  std::string overlap_skipped_by;
};

// Measures a model grown on `mesh` (nullptr for the free scene); distances are re-measured to
// `attach_mesh` when given (the support without its obstacle-only triangles).
// overlap_sweep false leaves out P2's sweep over internode pairs (the page, when its exact
// estimate does not fit the page's budget: ivy_budget's EstimateIvyStats).
IvyStats MeasureIvy(const IvyModel& model, const GrowLog& log, const geom::TriMesh* mesh,
                    const IvyParams& params, const geom::TriMesh* attach_mesh = nullptr,
                    bool overlap_sweep = true);

// Leaf cover seen from the front (issue 31 item 5): both meshes drawn orthographically along -z
// into a grid of `cells` × `cells` square cells over the support's x-y bounds (the larger side
// split in `cells`); a cell whose centre sees the support counts, and is covered when a leaf
// triangle is nearer the viewer there than the support (or level with it). The share covered, 0
// when the support shows in no cell. z-buffer of cell centres, no RNG: the same number natively
// and in WASM.
double LeafCoverFront(const geom::TriMesh& support, const geom::TriMesh& leaves, int cells = 256);

// Laterals (axes of order >= 1) alive at the end of step `step` (born at or before it).
int LateralsAt(const IvyModel& model, int step);
// Internodes made at or before `step`.
int InternodesAt(const IvyModel& model, int step);

// Timings the caller measured, printed as ms and ms_<stage>.
struct IvyTimings {
  double ms = 0, ms_bvh = 0, ms_rules = 0, ms_search = 0, ms_mesh = 0;
};

// The --stats object (one line). bvh_visits_per_query is 0 with --accel linear.
std::string IvyStatsJson(const IvyStats& stats, const GrowLog& log, const IvyModel& model,
                         const IvyTimings& timings);
// The model: {buds: [{id, kind, pos, dir, N, parent, children, axis, order, born_step, died_step,
// anchor, clearance}], internodes: [{from, to, step, axis}], axes: [...], params: {...}, seed,
// steps}.
std::string IvyModelJson(const IvyModel& model, const IvyParams& params, uint64_t seed, int steps);

}  // namespace niwa::ivy
