// The tree study's run (run::StudyRun) over its three chapters: growth year by year (ch. 2), the
// mesh and its sway skin and the sway run (ch. 3), hybrid views and their table 4.1 counts (ch. 4),
// and every export (.glb, .json, .svg, the LOD and sway .glb) checked against the budget first.
// It lives in core/render because it spans the chapters: tree knows neither sway nor render,
// render may include both. Does not: parse flags, read or write files, know a page or a flag
// (errors name state fields or the budget's limits; the front ends rename them), or simulate the
// page's running sway (the bindings step SwaySimulators over sway_model()).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "render/hybrid.h"
#include "render/tree_lod.h"
#include "render/tree_lod_sway.h"
#include "run/study_run.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "sway/sway_gltf.h"
#include "tree/crown_occlusion.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/tree_budget.h"
#include "tree/tree_state.h"
#include "tree/tree_svg.h"

namespace niwa {

// One export of the run's tree and what shapes it.
struct TreeExportRequest {
  enum class Kind { kGlb, kJson, kSvg, kLodGlb, kSwayGlb };
  Kind kind = Kind::kGlb;
  SvgOptions svg;                               // kSvg
  long max_triangles = -1;                      // kLodGlb: within N triangles; -1: the full mesh
  bool lod = false;                             // kLodGlb: levels LOD0..LOD2
  LodLayout layout = LodLayout::kSiblings;      // kLodGlb with lod
  std::string lod_field = "max_triangles";      // the field a level that cannot fit names
  double fps = 30;                              // kSwayGlb: keys per second
  std::size_t max_joints = kDefaultSwayJoints;  // kSwayGlb: the skin's joints (sway_gltf.h)
  // kSwayGlb: the mesh within N triangles (render/tree_lod_sway; -1: the full mesh) and the
  // clip's key reduction bound, metres (0: every key).
  long sway_triangles = kDefaultSwayTriangles;
  double key_error = kDefaultSwayKeyError;
};

// The run's export kinds by name: "glb", "json", "svg", "lod.glb", "sway.glb" (else an error
// naming "format").
Result<TreeExportRequest::Kind> TreeExportKind(const std::string& format);

// Table 4.1 of one view (thesis ch. 4): the hybrid and full counts.
struct TreeViewCounts {
  RenderStats stats;
  bool atlas_fits = true;
  int alive_branches = 0;
};

// Table 4.1 of one view as JSON, written once for both front ends. kView: the page's drawList
// stats {lines, line_branches, card_branches, branch_polygons, leaf_polygons, total_polygons,
// primitives, textures, leaf_clusters, full_polygons, alive_branches}. kRenderStats: `niwa tree
// render-stats` {mode, preset, seed, years, width, height, cam, threshold, leaf_mode, the counts
// (zero in the hybrid-only ones with full), full_*, primitive_ratio, ms_grow_mesh, ms_scene,
// ms_select}.
struct RenderStatsHeader {
  bool full = false;  // mode "full": every polygon
  std::string preset;
  uint64_t seed = 0;
  int years = 0, width = 0, height = 0;
  std::string cam;  // FormatOrbitView
  float threshold = 0;
  std::string leaf_mode;
  double ms_grow_mesh = 0, ms_scene = 0, ms_select = 0;
};
std::string ViewCountsJson(const TreeViewCounts& counts);
std::string RenderStatsJson(const TreeViewCounts& counts, const RenderStatsHeader& header);

// One view for `niwa tree render-stats` (TreeRun::RenderStats). The hybrid options are the
// state's render rows (line_threshold, card_planes, leaf_cluster_cards) and line_segments.
struct RenderStatsRequest {
  bool full = false;  // mode "full": every polygon
  int width = 512, height = 512;
  float fov_deg = 45;
  std::optional<OrbitView> view;  // none: the page's framing of the tree (FrameView)
  int line_segments = 1;          // most segments per line branch (not a row of the table)
};

class TreeRun : public run::StudyRun {
 public:
  // state.limits are the growth limits (tree_budget's TreeGrowLimits over the front end's budget,
  // the page's internode cap on top); `budget` is what the mesh, the sway and every export are
  // checked against. Refuses a state it cannot grow (field "years", or "gust_off" before
  // gust_on). Nothing is grown yet.
  static Result<TreeRun> Start(const TreeState& state, const Budget& budget);

  const char* study() const override { return "tree"; }
  const char* unit() const override { return "years"; }
  int done() const override { return grower_->year(); }
  int target() const override { return state_.years; }
  // True once a growth limit stopped the growth (tree().truncated_by says which).
  bool stopped() const { return grower_->stopped(); }
  // True when no year is left to grow (all of them, or a limit stopped it).
  bool finished() const { return stopped() || done() >= target(); }

  // Grows one more year (false when finished).
  bool GrowYear();
  // GrowYear in two halves (Grower::StartYear, FinishYear), for trees grown together
  // (core/compose/tree_neighbours): StartYear (false when finished or a limit stopped the growth
  // before the year began) makes this year's
  // leaf_spheres(); FinishYear lights them shaded also by `foreign_shade` (other trees' leaf
  // spheres in this tree's frame, cm) and ends the year. With no foreign shade the pair is
  // GrowYear.
  bool StartYear();
  void FinishYear(const std::vector<LeafSphere>& foreign_shade);
  // The leaf spheres of the year last started (Grower::leaf_spheres), in this tree's frame, cm.
  const std::vector<LeafSphere>& leaf_spheres() const { return grower_->leaf_spheres(); }
  // Grows to the state's years, year by year; the observer sees {"grow", years done, years} before
  // each year and after the last. A cancel leaves the run at its last whole year (a later Advance
  // goes on from there) and returns run::CancelledStatus().
  Status Advance(const run::Observer& observer) override;

  const TreeState& state() const { return state_; }
  const Tree& tree() const { return grower_->tree(); }
  const GrowthTimings& timings() const { return grower_->timings(); }
  const Budget& budget() const { return budget_; }
  // What the growth so far is estimated to have used.
  Estimate grown() const { return grower_->estimate(); }

  // ---- mesh stage: the mesh in the state's look (leaf_shape, season) and its sway skin ----
  // Builds the mesh and its skin once the grown tree and the mesh fit the budget; else the mesh
  // is left empty (the stage ran: the exports draw that empty mesh) and the error names the
  // budget's memory or time limit.
  Status BuildMesh();
  // The mesh alone, unchecked (render-stats, whose budget covers the growth only).
  void BuildBareMesh();
  bool has_mesh() const { return has_mesh_; }
  const TreeMesh& mesh() const { return mesh_; }
  // The node points of the tree in the state's sway rows and the skin of the mesh to them (eq.
  // 3.15). Built by BuildMesh and by an Update that re-does the mesh or sway stage.
  const SwayModel& sway_model() const { return sway_model_; }
  const TreeSkin& skin() const { return skin_; }
  // The crown's ambient occlusion of every vertex of mesh() (tree/crown_occlusion.h), computed at
  // the first call after the mesh was (re)built and kept with it (the page shades with it; no
  // export carries it).
  const CrownOcclusion& occlusion();

  // A new state: re-does only the earliest stage whose rows changed (the table's stage column:
  // grow, mesh, sway, view) and the ones after it, and returns those stages as a mask (0: nothing
  // changed). grow (a grow row, preset, seed, years or prunes): the tree is regrown from year 0
  // with next.limits (Advance again), the mesh stage dropped. mesh (leaf_shape, and any row of the
  // look: season, autumn_colour, flower_colour, flower_form are view rows of the table but the mesh
  // carries the look): the mesh, when built, and its skin are rebuilt. sway: the skin (eq. 3.15
  // weights follow sway_alpha). view: only the state. The growth's limits stay unless it regrows.
  // Refused as Start refuses, the run then unchanged.
  Result<run::StageMask> Update(const TreeState& next);

  // A prune that cut nothing (a mistyped id or year), found once grown: the first such prune's
  // IdlePruneReason under the field "prune" ("prune: 3:b99: ..."); ok when every prune cut.
  Status CheckPrunes() const;

  // `niwa tree mappings`: the hormone- and age-dependent ranges of the state's rows (N, D, b_L,
  // b_g, break chances) as CSV (tree_report TreeMappingsCsv); with prunes, the tree is grown
  // first and a prune that cuts nothing refused (CheckPrunes). Errors as Start's, "prune".
  static Result<std::string> MappingsCsv(const TreeState& state, const Budget& budget);

  // `niwa tree render-stats`: the state grown (the budget covers the growth), its prunes checked,
  // its mesh built, and table 4.1 of the request's view (the page's framing when none) as
  // RenderStatsJson, its times measured here. Errors as Start's, "prune", CheckRenderOptions's.
  static Result<std::string> RenderStats(const TreeState& state, const Budget& budget,
                                         const RenderStatsRequest& request);

  // ---- outputs ----
  // bark, leaves, flowers (the non-empty ones) with their materials and textures, as the .glb's
  // (the mesh stage's mesh, built when it has not been).
  std::vector<run::Part> Parts() const override;
  Result<gltf::Document> Document() const override;
  // The tree's stats (tree_report); with the mesh built, also idle_prunes (once finished) and the
  // mesh's bounds, as the page shows them.
  std::string StatsJson() const override;
  std::string PageStatsJson() const;
  // The share hash, its keys prefixed ("tree." on a composed page).
  std::string Hash(const std::string& prefix) const override;
  // Estimate of `format` (TreeExportKind's names) with default options; see Estimate(request).
  Result<Estimate> ExportEstimate(const std::string& format) const override;
  // What the run holds (the grown tree, and its mesh when built) and the export's own work.
  Estimate ExportWork(const TreeExportRequest& request) const;
  Estimate Held() const;
  // Held() + ExportWork(request) against the budget; the refusal names the budget's limit and
  // tells to lower state.limits.years_name, N_high or B_l.
  Status CheckExport(const TreeExportRequest& request) const;
  // The export's bytes (not checked against the budget: call CheckExport first). .glb errors
  // name "glb" (io/gltf_writer), LOD ones request.lod_field. `sway` (kSwayGlb): the skin's joints
  // and, when clustered, its error against eq. 3.15; `sway_choice` the budgeted mesh's choice.
  Result<std::string> Export(const TreeExportRequest& request, SwayGlbInfo* sway = nullptr,
                             LodChoice* sway_choice = nullptr) const;

  // ---- sway (thesis ch. 3) ----
  SwayParams sway_params() const { return SwayParams(state_.params); }
  // The run (stats, `tips` traced tips) of the state's sway rows over their duration.
  SwayRun Sway(int tips) const;
  // Its estimate (a sway model of the tree as it is now), added to the grown tree's.
  Estimate SwayEstimate(int tips) const;

  // ---- hybrid rendering (thesis ch. 4) ----
  // The frame of the page for this tree (camera.js frame of the mesh's bounds; the mesh built
  // when it has not been).
  OrbitView FrameView(float fov_y) const;
  // Table 4.1 of one view: the counts of the scene's selection against the full mesh.
  TreeViewCounts CountView(const HybridScene& scene, const HybridSelection& selection) const;

 private:
  TreeRun(const TreeState& state, const Budget& budget);
  void BuildSkin();
  MeshOptions LookOptions() const;
  // The mesh stage's mesh, or one built into `scratch` when there is none.
  const TreeMesh& MeshOrBuilt(TreeMesh* scratch) const;
  // The sway model built with the mesh, or one built into `scratch`.
  const SwayModel& ModelOrBuilt(SwayModel* scratch) const;

  TreeState state_;
  Budget budget_;
  std::unique_ptr<Grower> grower_;
  bool has_mesh_ = false;
  TreeMesh mesh_;
  std::optional<CrownOcclusion> occlusion_;  // of mesh_, once asked for
  SwayModel sway_model_;
  TreeSkin skin_;
};

}  // namespace niwa
