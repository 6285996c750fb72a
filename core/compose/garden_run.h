// The garden's run (issue 33, docs/garden-model.md): the stage (ground and objects), the planting,
// and every tree grown year by year on one clock, as a run::StudyRun the CLI (`niwa garden grow`)
// and, next, the page call. Trees that are the same (species, seed, age) and stand apart from
// every other tree (shade off, or no trunk within shade_reach) are grown once and placed as
// copies; a tree with a neighbour within reach is grown on its own, shaded by its neighbours'
// leaves each year when shade is 1 (compose/tree_neighbours GrowTogetherYear). Outputs: the .glb
// (ground, objects, each distinct tree once within max_triangles (render/tree_lod), its copies as
// EXT_mesh_gpu_instancing or plain nodes sharing the mesh, optional _LOD1/_LOD2), the 16-bit
// heightmap of the ground, the plan as SVG, the stats. Ivy (paper 004) grows from the state's seeds
// at the feet of objects and hand-placed trees, climbing the objects, the trunks near them and the
// ground. Moss (paper 001) grows over the ground and the objects, moss_days days after each
// garden year, its photons crossing that year's leaves (compose/garden_moss). With bark 1, each
// distinct tree's bark is the bark study run on its own trunk's radius history
// (compose/garden_bark). With record_years (the page), each garden year's picture is kept as the
// clock runs (GardenYearRecord: each distinct tree as it stood after that year, the moss's light
// and count), within a quarter of the budget's memory, so a front end replays the years without
// regrowing; the ivy grows on the same clock (ivy_steps steps a year on the trunks of that year),
// so its birth steps date the ivy of each year. Does not: record the bark year by year (grown
// after the clock), read files, or name a flag.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "compose/garden_bark.h"
#include "compose/garden_plant.h"
#include "compose/garden_scene.h"
#include "compose/garden_state.h"
#include "ivy/ivy_run.h"
#include "moss/moss_run.h"
#include "render/tree_run.h"
#include "run/study_run.h"

namespace niwa::compose {

// What the garden's ivy counts its work at (ivy::IvyCosts; docs/garden-model.md "The ivy's
// estimate"): measured in CPU time natively on the garden's supports (its ground, objects and
// trunks), where the ivy study's own figures (a bud-step 0.6 µs, a candidate 1.5 µs, a triangle's
// BVH 3 µs) are upper bounds for its scenes, 2-5 times the garden's.
ivy::IvyCosts GardenIvyCosts();
// The garden's own time a support triangle, for meshing it (the ground, the objects, the trunks'
// bark) before the ivy study builds its BVH (GardenIvyCosts().triangle_build).
inline constexpr double kGardenIvyMeshSecondsPerTriangle = 0.3e-6;
// The garden's time a support triangle each year for joining the trunks' BVH to the kept part's
// (geom::Bvh::Join: the copy of both trees and the wide tree made again), and for copying the kept
// part's mesh into the year's support.
inline constexpr double kGardenIvyJoinSecondsPerTriangle = 0.05e-6;

// ---- data ----

// One distinct grown tree and the planted trees that are copies of it.
struct GardenTreeGroup {
  std::string species;
  uint64_t seed = 1;
  int age = 0;                   // years before the garden's clock starts
  std::vector<int> trees;        // indices into Planting::trees (one when grown on its own)
  bool shaded = false;           // grown with its neighbours' shade
  std::unique_ptr<TreeRun> run;  // the tree study's run (render/tree_run)
  const Tree& tree() const { return run->tree(); }
  std::string name;  // "keyaki_s1_a0", "keyaki_t3" (a tree grown on its own)
};

// One planted tree in the .glb: the group whose mesh draws it, turned about y by yaw_deg and
// scaled by `scale` (1, and its own rotation, unless it is drawn with a shared shape: `shapes`,
// compose/garden_shapes.h).
struct GardenExportTree {
  int tree = 0;  // index into Planting::trees
  double yaw_deg = 0;
  double scale = 1;
};

// One garden year's picture, kept as the clock runs (GardenRun::Start's record_years): what a
// front end needs to draw that year again without regrowing.
struct GardenYearRecord {
  int year = 0;  // garden years done (0: the planted garden, after the nursery, before the clock)
  // Each distinct tree (one per group) as it stood after that year: a copy of the tree study's
  // Tree, shared with the year before when the tree did not change (at its years, or stopped).
  std::vector<std::shared_ptr<const Tree>> trees;
  // The moss's light S on the ground after that year's days (GardenMossGroundLight), and its
  // living mosses; empty and 0 without moss.
  std::vector<float> moss_light;
  long mosses = 0;
  // The ivy after that year (grown year by year on the trunks of each year): its steps and
  // internodes (0 without ivy). The ivy of year y is the final ivy's buds born by step ivy_steps
  // (buds are never moved or removed), so a front end shows it by the buds' birth steps.
  int ivy_steps = 0;
  long ivy_internodes = 0;
  double bytes = 0;  // its estimate (the trees' copies new this year, the light)
};

// The share of the budget's memory the year records may take when recording (the trees' growth
// then shares the rest, so the garden with its records stays within the budget).
constexpr double kGardenRecordShare = 0.25;

// ---- the run ----

class GardenRun : public run::StudyRun {
 public:
  // Builds the stage and plants it (the state checked first, then every tree's growth estimated
  // against `budget`: each group gets an equal share of it). Errors name state fields
  // ("plants[1].pos", "ground.terrain", "density") or the budget's limit ("lower years, density or
  // size"). With `record_years`, each year's picture is recorded as the clock runs (years(),
  // `record_share` (default kGardenRecordShare, in (0, 1)) of the memory kept for it); the .glb,
  // the stats and the trees' growth are the same as without it unless the trees reach their
  // memory share.
  static Result<GardenRun> Start(const GardenState& state, const Budget& budget,
                                 bool record_years = false,
                                 double record_share = kGardenRecordShare);

  const char* study() const override { return "garden"; }
  const char* unit() const override { return "years"; }
  int done() const override { return year_; }
  int target() const override { return state_.params.GetInt(GardenParam::kYears); }

  // Grows every tree to the garden's years on one clock (a tree planted at age a is first grown
  // a years alone: the nursery), year by year; the observer sees {"grow", year, years}. A cancel
  // stops at the last whole year.
  Status Advance(const run::Observer& observer) override;

  // ground, objects, and one part per distinct tree (its full mesh's bark and leaves, at the
  // origin): what a page draws with the placements.
  std::vector<run::Part> Parts() const override;
  Result<gltf::Document> Document() const override;
  std::string StatsJson() const override;
  std::string Hash(const std::string& prefix) const override;
  // "glb", "heightmap" (16-bit PNG), "svg", "json" (the planting).
  Result<Estimate> ExportEstimate(const std::string& format) const override;
  Result<std::string> Export(const std::string& format) const;

  const GardenState& state() const { return state_; }
  // The wind of Blow and `niwa garden grow --wind-time` (state().wind; ApplyGardenWindJson's rows
  // and errors): not the growth's, so the garden grown stays as it is; Hash and the state's JSON
  // carry it.
  Status SetWind(const std::string& json) { return ApplyGardenWindJson(json, &state_); }
  const GardenScene& scene() const { return scene_; }
  const Planting& planting() const { return planting_; }
  const std::vector<GardenTreeGroup>& groups() const { return groups_; }
  // The group of planted tree t.
  int group_of(int t) const { return tree_group_[t]; }
  // Horizontal reach of a group's crown (m): the farthest alive node from the trunk's axis.
  double CrownRadius(int group) const;
  // The .glb's trees by the group whose mesh draws them (one list per group; empty for a group
  // drawn with another's shape): every group its own trees, unless `shapes` N > 0 shares the
  // shapes of the trees grown with their neighbours' shade, at most N meshes per (species, seed,
  // age) (compose/garden_shapes.h).
  std::vector<std::vector<GardenExportTree>> ExportTrees() const;
  // The groups whose meshes `shapes` shares: the shaded groups of each (species, seed, age), in
  // group order, variants in key order; none with shapes 0.
  std::vector<std::vector<int>> SharedVariants() const;
  // The leaf-area centroid of planted tree t, in the garden's frame (m).
  glm::dvec3 CrownCentroid(int t) const;
  const std::string& truncated_by() const { return truncated_by_; }
  // The recorded years (0, 1, ... in order; empty without record_years), and why the recording
  // stopped before the clock's end ("" when every year was recorded).
  const std::vector<GardenYearRecord>& years() const { return records_; }
  const std::string& record_stopped_by() const { return record_stopped_by_; }
  double record_bytes() const { return record_bytes_; }
  // Group `group`'s tree after garden year `year`: the record's, the run's own at the last year
  // grown, or nullptr when that year was not recorded.
  const Tree* TreeAtYear(int group, int year) const;
  // The garden's ivy once grown (nullptr without ivy seeds, ivy_steps 0 or before Advance).
  const ivy::IvyRun* ivy() const { return ivy_ && ivy_->grown() ? ivy_.get() : nullptr; }
  // The same while it grows (between garden years; nullptr before year 1 or without ivy): its
  // model_so_far(), log_so_far() and limits, e.g. the counts beside cpu_ms_ivy() year by year.
  const ivy::IvyRun* ivy_so_far() const { return ivy_.get(); }
  // The ivy's internodes after each garden year 1, 2, ... (with or without record_years).
  const std::vector<long>& ivy_internodes_by_year() const { return ivy_by_year_; }
  double ms_ivy() const { return ms_ivy_; }
  // Within ms_ivy: building each year's support (its meshes, the trunks' bark, the BVH).
  double ms_ivy_support() const { return ms_ivy_support_; }
  // The process's CPU time over the ivy's years (std::clock): what --stats' ms_ivy_cpu and
  // scripts/bench set beside the ivy's time estimate.
  double cpu_ms_ivy() const { return cpu_ms_ivy_; }
  double cpu_ms_ivy_support() const { return cpu_ms_ivy_support_; }
  // The garden's moss (nullptr with moss_days 0 or years 0), grown to years × moss_days days.
  const moss::MossRun* moss() const { return moss_.get(); }
  double ms_moss() const { return ms_moss_; }
  // The process's CPU time over the moss's start (its land and cells) and its days, the canopy
  // handed over each year included (std::clock): what scripts/bench sets beside the estimate.
  double cpu_ms_moss() const { return cpu_ms_moss_; }
  // The moss's whole run as the budget counted it at Start (GardenMossCosts; 0 without moss).
  const Estimate& moss_estimate() const { return moss_estimate_; }
  // Memory a front end holds per ivy bud beside the run (the page's mesh of the ivy: its
  // ivy::IvyPageMeshBytesPerBud; 0 on the CLI), counted in the ivy's growth limits. Set before
  // Advance.
  void set_ivy_extra_bytes_per_bud(double bytes) { ivy_extra_bytes_per_bud_ = bytes; }
  // The budget the ivy was grown within: the garden's less what the trees' growth used.
  const Budget& ivy_budget() const { return ivy_budget_; }
  double ms_ground() const { return ms_ground_; }
  double ms_plant() const { return ms_plant_; }
  double ms_trees() const { return ms_trees_; }
  // The trees' own growth within ms_trees: the nursery and each year's growth of every distinct
  // tree (with its neighbours' shade) and its trunk's record, without the moss's days, the year
  // records or the ivy (the seam a front end would split across workers: docs/garden-model.md
  // "Where the garden's time goes").
  double ms_growth() const { return ms_growth_; }
  // The year records' time (record_years: copying each year's trees and the moss's light).
  double ms_records() const { return ms_records_; }
  // Each distinct tree's bark (one per group; empty when bark is 0) and the bark runs' wall time.
  const GardenBarks& barks() const { return barks_; }
  double ms_bark() const { return barks_.ms; }

 private:
  GardenState state_;
  Budget budget_;
  GardenScene scene_;
  Planting planting_;
  std::vector<GardenTreeGroup> groups_;
  std::vector<int> tree_group_;
  int year_ = 0;
  bool nursery_done_ = false;
  std::string truncated_by_;
  double tree_base_bytes_ = 0;  // the process's base in each tree's estimate (counted once)
  Budget ivy_budget_;
  double ivy_extra_bytes_per_bud_ = 0;
  double ms_ground_ = 0, ms_plant_ = 0, ms_trees_ = 0, ms_ivy_ = 0, ms_moss_ = 0;
  double ms_ivy_support_ = 0, cpu_ms_ivy_ = 0, cpu_ms_ivy_support_ = 0, cpu_ms_moss_ = 0;
  double ms_growth_ = 0, ms_records_ = 0;
  std::unique_ptr<ivy::IvyRun> ivy_;
  std::unique_ptr<moss::MossRun> moss_;
  // The year records (record_years): each year's picture, their estimated bytes, and the memory
  // they may take (kGardenRecordShare of the budget's).
  bool record_years_ = false;
  std::vector<GardenYearRecord> records_;
  double record_bytes_ = 0, record_limit_ = 0, record_share_ = kGardenRecordShare;
  std::string record_stopped_by_;
  // Keeps year_'s picture when it fits what is left of the records' share, else stops recording.
  void RecordYear();  // RecordYearPicture, timed (ms_records)
  void RecordYearPicture();
  // The moss's days of one garden year, after the trees' year: that year's leaves as its canopy.
  void GrowMossYear();
  // What the garden's budget holds after the trees' growth (their estimates; the process's base
  // counted once), the moss's whole run (its estimate, taken up front) and, with `ivy_support`,
  // the ivy's support: the ivy's and the barks' share.
  Budget BudgetLeft(bool ivy_support) const;
  Estimate moss_estimate_{0, 0, ""};
  // Grows the state's ivy by one garden year's steps (ivy_steps) on the garden as it stands after
  // that year's growth (see docs/garden-model.md "One clock"), within what the trees' growth so
  // far, the moss and the records left of the budget.
  Status GrowIvyYear();
  std::vector<long> ivy_by_year_;
  bool ivy_done_ = false;  // the ivy is grown to its steps, extinct, stopped, or has none
  // The part of the ivy's support that is the same every year (the ground and the objects): its
  // mesh, made in the ivy's first year, and its BVH, built once and joined to each year's trunks'
  // (geom::Bvh::Join) instead of building the whole support's every year.
  geom::TriMesh ivy_kept_mesh_;
  geom::Bvh ivy_kept_bvh_;
  bool ivy_kept_meshed_ = false, ivy_kept_built_ = false;
  // The simulated bark (compose/garden_bark): the trunks recorded each year, the bark run on each
  // history after the clock, within what the trees' growth and the ivy's support left.
  GardenBarks barks_;
  Status GrowBarks(const run::Observer& observer);
};

}  // namespace niwa::compose
