// The ivy study's run (run::StudyRun): the one pipeline the CLI (`niwa ivy grow`), the ivy page's
// bindings (IvyLab) and the composer drive. A support is prepared once (IvySupport: a built-in
// scene, a read mesh with its noivy obstacles, or a scene prepared elsewhere such as a tree's bark
// from core/compose; subdivided within its cap, its BVHs, its default seeds, its estimate checked
// against the budget); an IvyRun grows a state on it in steps with progress and cancel, measures
// it, exports it (.json, .lsys, .svg, .glb, each estimate checked before the bytes are made) and
// gives its hash, parts and glTF document. Errors name state fields ("steps", "seed_points",
// "scene", "mesh", "subdivide") or the budget's limit. Does not: parse flags or JSON text, read or
// write files (io/ reads a mesh's bytes; the front ends write), know a page, or include another
// study (a tree support arrives as a prepared IvyScene).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "geom/bvh.h"
#include "geom/tri_mesh.h"
#include "io/gltf_writer.h"
#include "io/mesh_reader.h"
#include "ivy/growth.h"
#include "ivy/ivy.h"
#include "ivy/ivy_budget.h"
#include "ivy/ivy_mesh.h"
#include "ivy/ivy_report.h"
#include "ivy/ivy_state.h"
#include "ivy/ivy_svg.h"
#include "ivy/scenes.h"
#include "run/study_run.h"

namespace niwa::ivy {

constexpr int kMaxIvySubdivide = 8;  // the "subdivide" field's range: [0, 8]

// Where the ivy climbs: one of a built-in scene, a read mesh, or a scene prepared elsewhere.
struct IvySupportInput {
  enum class Kind { kScene, kMesh, kPrepared };
  Kind kind = Kind::kScene;
  std::string scene = "cubes4";             // kScene: MakeIvyScene's name
  geom::TriMesh mesh;                       // kMesh: the mesh as read (io::ReadMeshBytes)
  std::string name;                         // kMesh: its name (the scene's name)
  std::vector<io::MeshMaterial> materials;  // kMesh: the reader's (noivy obstacles)
  double metres_per_unit = 0;         // kMesh: the unit its file names (io MeshReadStats), 0 none
  IvyScene prepared;                  // kPrepared: e.g. compose/ivy_on_tree's bark
  Estimate prepared_estimate;         // kPrepared: building it (its seconds count)
  std::string prepared_truncated_by;  // kPrepared: its stop line, "" if none
  // kPrepared: the scene's BVH made by the caller (e.g. geom::Bvh::Join of a part built once and
  // a part built again), its time in prepared_estimate; used as it is when the support is not
  // subdivided and its queries are kBvh (else Prepare builds its own), and its build is then not
  // counted again. Must be a tree of that very mesh.
  std::optional<geom::Bvh> prepared_bvh;

  static IvySupportInput Scene(std::string name);
  static IvySupportInput Mesh(geom::TriMesh mesh, std::string name,
                              std::vector<io::MeshMaterial> materials, double metres_per_unit = 0);
  static IvySupportInput Prepared(IvyScene scene, Estimate estimate, std::string truncated_by);
};

struct IvySupportOptions {
  int subdivide = 0;          // split every triangle into 4^K, K in [0, kMaxIvySubdivide]
  Accel accel = Accel::kBvh;  // kLinear builds no BVH
  // A mesh support: add the default seed "front" (the surface point nearest to a point in front
  // of the mesh (+z) at a tenth of its height), so a dropped mesh grows at once. Needs kBvh.
  bool front_seed = false;
  // Check the support's estimate against the budget before subdividing (refused with `change`);
  // false: it only enters the growth's limits (the page).
  bool check_budget = true;
  std::string change = kIvyChange;
  // A mesh support's estimate counts its attach mesh and BVH: always (the CLI), or only when it
  // has obstacles (the page). Kept apart so both keep their figures.
  bool mesh_attach_always_counted = true;
  // What the estimates count the work at (the study's by default; the garden passes its measured
  // figures): the support's triangles here, and the growth's bud-steps and candidates in the
  // limits of every run grown on this support (IvyRun::SetLimits reads IvySupport::costs).
  IvyCosts costs;

  // The options a state asks for (its accel); the rest as above.
  static IvySupportOptions For(const IvyState& state);
};

// A prepared support: the scene (subdivided), its BVHs, the attach mesh of a mesh support.
// Immutable once made; several runs may share it.
class IvySupport {
 public:
  // Errors: "scene" (unknown name), "mesh" (ValidateMesh), "subdivide" (over the triangle cap),
  // the budget's limit (the support's estimate, when options.check_budget).
  static Result<std::shared_ptr<const IvySupport>> Prepare(IvySupportInput input,
                                                           const IvySupportOptions& options,
                                                           const Budget& budget);

  const IvyScene& scene() const { return scene_; }
  bool free() const { return scene_.free; }
  bool is_mesh() const { return is_mesh_; }
  Accel accel() const { return accel_; }
  std::size_t obstacles() const { return obstacles_; }
  double triangles() const {  // 0 on the free replay
    return scene_.free ? 0 : static_cast<double>(scene_.mesh.triangle_count());
  }
  const geom::Bvh& bvh() const { return bvh_; }
  const geom::TriMesh* mesh() const { return scene_.free ? nullptr : &scene_.mesh; }
  const geom::TriMesh* attach() const { return obstacles_ > 0 ? &attach_ : nullptr; }
  Support ForGrow() const;                                // what Grow climbs
  const Estimate& estimate() const { return estimate_; }  // the support's, with a tree's seconds
  const IvyCosts& costs() const { return costs_; }        // IvySupportOptions::costs: the runs' too
  const std::string& truncated_by() const { return truncated_by_; }
  double ms_bvh() const { return ms_bvh_; }  // building the BVHs (timing, not compared)
  // Its largest extent (0 on the free replay) and its own paper pixels per unit (IvyPxPerUnit with
  // the row "scale" at 0: the scene's, else from the extent).
  double extent() const { return extent_; }
  double px_per_unit() const;
  // The paper pixels per unit of its look's lengths (tubes, leaves: IvyLookPxPerUnit with the row
  // "scale" at 0): a glTF's metres (1000) whatever its size, else px_per_unit().
  double look_px_per_unit() const;
  // A state's parameters in the support's units (IvyScaledParams at IvyPxPerUnit, the look's at
  // IvyLookPxPerUnit); error "scale".
  Result<IvyParams> Scaled(const IvyParams& declared) const;

 private:
  IvyScene scene_;
  bool is_mesh_ = false;
  geom::TriMesh attach_;
  std::size_t obstacles_ = 0;
  geom::Bvh bvh_, attach_bvh_;
  Accel accel_ = Accel::kBvh;
  Estimate estimate_;
  IvyCosts costs_;
  std::string truncated_by_;
  double ms_bvh_ = 0;
  double extent_ = 0;
};

struct IvyRunOptions {
  // Keep room in the growth's limits for MeasureIvy (the CLI's --stats; the page always measures).
  bool reserve_stats = false;
  double extra_bytes_per_bud = 0;  // held per bud beside the model (the page's meshes)
  std::string change;              // the truncation line's advice ("" = kIvyChange)
  bool build_meshes = false;       // BuildIvyMeshes once grown (the page shows them)
  // What an export refusal and a statistics refusal tell the user to change.
  std::string export_change = kIvyChange;
  std::string stats_change = kIvyStatsChange;
  // The exports' estimate counts the grown ivy with the room kept for its statistics (the page);
  // else without it (the CLI, which adds the measurement's exact estimate when `stats`).
  bool export_with_stats_room = false;
  bool stats = false;  // the CLI's --stats: an export's check includes the measurement
  // The export asked for before growing ("glb", "json", ...; "" none) and its support flag: while
  // the ivy grows, the export's estimate (and the measurement's, with `stats`) for the buds made
  // so far is checked whenever they have grown by a quarter, so a run whose output cannot fit is
  // refused as soon as the buds made prove it (buds are never removed), not after growing all of
  // them (issue 34: --steps 10000 on cubes4 was refused after 78 MB of growth).
  std::string planned_export;
  bool planned_with_support = false;
};

struct IvyExportOptions {
  bool with_support = false;  // .glb: the support mesh as a node (an .svg always draws it)
  IvySvgOptions svg;
};

class IvyRun : public run::StudyRun {
 public:
  // Starts growing `state` on `support` within `budget`: seeds are the state's seed_point_items
  // resolved against the support's scene ("X,Y,Z" or a named seed; the run's state then holds the
  // points), else its seed_points, else the scene's first named seed (error "seed_points" when
  // there is none); error "accel" when the support was prepared with other queries than the
  // state's. The limits are set from the support's estimate. Nothing grows until Advance.
  static Result<IvyRun> Start(const IvyState& state, std::shared_ptr<const IvySupport> support,
                              const Budget& budget, const IvyRunOptions& options = {});

  const char* study() const override { return "ivy"; }
  const char* unit() const override { return "steps"; }
  int done() const override { return grown_ ? log_.steps_run : 0; }
  int target() const override { return state_.steps; }
  // Grows to the state's steps (progress "grow", step of steps; the observer's false cancels,
  // leaving the run as it was). Errors: Grow's ("steps", "seed_points", "mesh"), cancelled.
  Status Advance(const run::Observer& observer) override;
  // Grows on to step `to` (at most the state's steps) on `support`, which replaces the run's
  // support from this step on (the garden: the trunks the ivy climbs grew since the last call;
  // IvyGrowth::SetSupport with `kept_triangles`, the support's unchanged part), within `budget`
  // (the limits are set again; the earlier supports' seconds stay counted). Once at the state's
  // steps (or extinct, or stopped by a limit) the run is grown as after Advance. Advance's checks
  // of planned outputs are not made. Errors: Grow's, cancelled.
  Status AdvanceOn(std::shared_ptr<const IvySupport> support, uint32_t kept_triangles,
                   const Budget& budget, int to, const run::Observer& observer);
  // The model and log so far (a run between AdvanceOn calls; the grown ones after).
  const IvyModel& model_so_far() const { return growth_ ? growth_->model() : model_; }
  const GrowLog& log_so_far() const { return growth_ ? growth_->log() : log_; }
  // A new state on the same support: when only mesh-stage rows changed, re-meshes the grown ivy;
  // else forgets it (Advance grows again).
  Status Update(const IvyState& state);
  std::vector<run::Part> Parts() const override;
  Result<gltf::Document> Document() const override;
  // The statistics (IvyStatsJson with timings()): the overlap sweep left out, with its line in
  // overlap_skipped_by, when the measurement does not fit the budget. "{}" before a grow.
  std::string StatsJson() const override;
  std::string Hash(const std::string& prefix) const override;
  Result<Estimate> ExportEstimate(const std::string& format) const override;

  // Ivy's own.
  bool grown() const { return grown_; }
  const IvyState& state() const { return state_; }
  // The parameters the ivy grows with: the state's in the support's units (IvyScaledParams).
  const IvyParams& params() const { return params_; }
  const IvySupport& support() const { return *support_; }
  const IvyModel& model() const { return model_; }
  const GrowLog& log() const { return log_; }
  const IvyGrowLimits& limits() const { return limits_; }  // without the statistics' room
  const IvyMeshes& meshes() const { return meshes_; }      // options.build_meshes
  const std::vector<glm::dvec3>& seeds() const { return seeds_; }
  IvyTimings& timings() { return timings_; }  // the front end sets ms (its own clock)
  const IvyTimings& timings() const { return timings_; }
  int grows() const { return grows_; }        // Grow calls so far (the stage cache's test)
  int remeshes() const { return remeshes_; }  // BuildIvyMeshes calls so far

  // After Advance: an error when steps > 0 grew no internode (a run that makes nothing is not a
  // result; issue 31 item 4), naming why: "scale" when the scaled L or d is half the support's
  // size or more at a given scale (px on a mesh in metres), "L" when the user's own L or d are,
  // else "seed_points" (every seed's first search found no place within d of the support).
  Status CheckGrewSomething() const;
  // The measurement's estimate (counted from the model) and its check with the grown ivy.
  Estimate StatsEstimate() const;
  Status CheckStats() const;
  // Export of "json", "lsys", "svg" or "glb": its estimate, the check ("" = fits), the bytes
  // (checked first: an error names the budget's limit) or unchecked (the page's text downloads).
  Result<Estimate> ExportEstimate(const std::string& format, bool with_support) const;
  // The same for a model and log (a growing one: Advance's early check).
  Result<Estimate> ExportEstimateOf(const IvyModel& model, const GrowLog& log,
                                    const std::string& format, bool with_support) const;
  Status CheckExport(const std::string& format, bool with_support) const;
  Result<std::string> Export(const std::string& format, const IvyExportOptions& options) const;
  Result<std::string> ExportUnchecked(const std::string& format,
                                      const IvyExportOptions& options) const;

 private:
  IvyRun() = default;
  void SetLimits();
  // The support the leaves are kept outside of (BuildIvyMeshes), nullptr on the free replay.
  const Support* LeafSupport() const;
  // The measurement's work for `model`: CountIvyStatsWork and StatsJson's leaves as drawn (meshed
  // unless options_.build_meshes, and their cover) on a support.
  IvyStatsWork StatsWork(const IvyModel& model) const;

  IvyState state_;
  IvyParams params_;      // state_.params in the support's units
  Support leaf_support_;  // support_->ForGrow()
  std::shared_ptr<const IvySupport> support_;
  Budget budget_;
  IvyRunOptions options_;
  std::vector<glm::dvec3> seeds_;
  IvyGrowLimits limits_, grow_limits_;
  bool grown_ = false;
  IvyModel model_;
  GrowLog log_;
  IvyMeshes meshes_;
  LeafPlacement placement_;  // BuildIvyMeshes' counts for meshes_
  IvyTimings timings_;
  int grows_ = 0, remeshes_ = 0;
  // AdvanceOn: the growth between calls, and the seconds of the supports it grew on before.
  std::shared_ptr<IvyGrowth> growth_;
  double earlier_supports_seconds_ = 0;
  // Ends a growth: its model and log kept, the meshes built when asked for, grown_ set.
  void FinishGrowth(IvyModel model, GrowLog log, const run::Observer& observer);
};

}  // namespace niwa::ivy
