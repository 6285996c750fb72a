// The terrain study's run (run::StudyRun, paper 002): one mountain from a TerrainState (a built-in
// seed, or a contour file's or a drawing's points) within a Budget, the one pipeline the CLI
// (native_cli/terrain_commands.cpp) and the page (web/bindings/terrain_bindings.cpp) adapt: the
// checks and estimates before work, the grow level by level (progress and cancel), the
// heightfield, and the outputs (the .glb document with its asset extras, the 16-bit heightmap and
// its sidecar, the contour tree as .json, .geojson and .svg, the page's surface buffers), the
// stats JSON, the share hash and the export estimates. Update(state) keeps what the changed rows'
// stage allows: a view row (tint) re-does nothing but what is derived from the state on demand, a
// mesh row (res) re-samples the heightfield from the kept contours, an erosion row (stage mesh too)
// re-erodes the kept uneroded heightfield (erosion.h), a grow row or the seed regrows.
// Does not: parse flags or panels, read or write files, print, repair a contour that crosses
// itself (contour_repair.h; a front end does so before Start), or time anything but its own steps.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "params/param_table.h"
#include "run/field_names.h"
#include "run/study_run.h"
#include "terrain/contour.h"
#include "terrain/erosion.h"
#include "terrain/heightfield.h"
#include "terrain/terrain_budget.h"
#include "terrain/terrain_output.h"
#include "terrain/terrain_state.h"
#include "terrain/terrain_surface.h"

namespace niwa::terrain {

// What a front end takes from the run, declared before it starts.
struct TerrainRunPlan {
  // The outputs it will write (the CLI: its --out, --heightmap and --contours; the page: kGlb, the
  // size of its surface buffers): their estimates are checked with the grown contours' and the
  // heightfield's before the heightfield is built, and held by ExportEstimate.
  std::vector<TerrainOutput> outputs;
  // Its words for the state fields a refusal line quotes ("res" -> "--res": "lower --res").
  run::FieldNames words;
  // A cap on the grown contours' vertices (0: none) and who holds it ("the page draws"): above it
  // the run refuses right after growing, naming down (when > 0) or max_levels, before the
  // heightfield's and outputs' estimate (whose advice, res, would not help).
  double max_contour_vertices = 0;
  std::string contour_vertex_holder;
};

// What the run has done since Start (a test counts what an Update re-did).
struct TerrainRunCounts {
  int grows = 0;         // contour trees grown
  int heightfields = 0;  // heightfields built
  int erosions = 0;      // erosion passes run (erosion.h; none while erosion is 0)
};

// `terrain compare` (issue 19 item 4), once for every front end: the state grown from its seed and
// measured against a real DEM (the bytes of a 16-bit heightmap PNG and its sidecar JSON, as
// `terrain grow --heightmap` writes them), as one JSON object {method, seed, h0, dh, d, url, real,
// grown, levels, mean_iou, slope_share_l1}. The peak search's cost is refused before anything
// grows, the grown contours with the heightfield on the DEM's grid before that is built. Errors
// name "dem" or a state field ("contour", "theta_max", ...) or the budget's limit.
struct DemComparison {
  std::string json;
  std::string truncated_by;  // the line of the limit that stopped the grow, "" when none
};
Result<DemComparison> CompareWithDem(const TerrainState& state,
                                     const std::vector<unsigned char>& dem_png,
                                     const std::string& dem_sidecar, const Budget& budget);

// "glb", "heightmap" (the .png), "sidecar" (its .json), "json", "geojson" or "svg" as the output
// it is; error {"format", "unknown format; must be ..."}.
Result<TerrainOutput> TerrainOutputOfFormat(const std::string& format);

class TerrainRun : public run::StudyRun {
 public:
  // The state's seed (StateSeed), the heightfield's (res + 2)² cells against the budget and the
  // cross-row checks (CheckTerrainParams), in that order, before anything grows; errors name the
  // state field or the budget's limit. The grow itself waits for Advance.
  static Result<TerrainRun> Start(const TerrainState& state, const Budget& budget,
                                  TerrainRunPlan plan = {});

  // A new state, checked as Start checks one (the run is unchanged on error). Against the state of
  // the current results: a changed seed or grow row regrows at the next Advance; a changed mesh
  // row (res) re-samples the heightfield from the kept contours (unless the budget's room for the
  // grow, which res shares, shrank or a budget stopped the kept grow: then it regrows); only view
  // rows or the preset's name changed: the new state is taken at once, nothing is re-done.
  Status Update(const TerrainState& state);

  const char* study() const override { return "terrain"; }
  const char* unit() const override { return "levels"; }
  // The levels the results hold (0 while a grow or heightfield is pending); target() is done()
  // when nothing is pending, else the state's cap (max_levels above the seed, down below it): a
  // mountain stops at its summits, usually well below the cap.
  int done() const override;
  int target() const override;
  // Re-does what Start or Update left pending: the grow (phase "levels": a unit per contour level,
  // the total estimated from the seed's inradius 2A/P over d; the observer may cancel before each
  // contour), the estimate of the grown contours, the heightfield and the plan's outputs (refused
  // before the heightfield is built), then the heightfield (phase "surface"). On error or cancel
  // the results stay those of before.
  Status Advance(const run::Observer& observer) override;

  // The .glb's nodes as parts: "terrain" (the surface, COLOR_0 when tint) and "contours" (LINES).
  std::vector<run::Part> Parts() const override;
  // The surface and contours with asset extras {generator: "niwa terrain grow", url: hash}.
  Result<gltf::Document> Document() const override;
  // The stats object (terrain_report.h) of the results; "{}" before any.
  std::string StatsJson() const override;
  std::string Hash(const std::string& prefix) const override;
  // What writing `format` needs, added to what the front end holds (the plan's outputs) and the
  // heightfield; error {"format", ...} when the format is unknown.
  Result<Estimate> ExportEstimate(const std::string& format) const override;
  // ExportEstimate(format) against the run's budget, the refusal telling to lower res.
  Status CheckExport(const std::string& format) const;

  // The bytes of one output (formats as TerrainOutputOfFormat); errors as the encoders' (the
  // heightmap's name "heightmap").
  Result<std::string> Export(const std::string& format) const;
  // The heightmap .png and its sidecar at once (what Export("heightmap") and ("sidecar") give):
  // the surface rebuilt on HeightmapGrid (square, 2^k + 1), not the heightfield's own grid.
  Result<Heightmap> EncodeHeightmapFiles() const;
  // That grid, filled (built on first use and kept until the next grow).
  const Heightfield& heightmap_field() const;
  // The page's buffers of the results (terrain_surface.h), reusing `out`'s storage.
  void FillSurfaceBuffers(SurfaceBuffers* out) const;

  bool grown() const { return grown_; }
  const TerrainState& state() const { return state_; }  // the state of the results
  const Terrain& terrain() const { return terrain_; }
  const Heightfield& heightfield() const { return hf_; }
  const TerrainRunCounts& counts() const { return counts_; }
  // The truncation line of the last grow ("" when none stopped it), kept when its Advance then
  // failed, so a front end can say both.
  const std::string& truncated_by() const { return truncated_by_; }
  // The estimate the last Advance checked before the heightfield (calibration, docs/budgets.md).
  const std::optional<Estimate>& checked_estimate() const { return checked_estimate_; }
  // Wall time of the last successful Advance's grow and heightfield (0 when not re-done).
  double ms_grow() const { return ms_grow_; }
  double ms_heightfield() const { return ms_heightfield_; }
  double ms_erosion() const { return ms_erosion_; }
  // The last erosion's report (erosion.h; an empty one while erosion is 0).
  const ErosionReport& erosion() const { return erosion_; }

 private:
  enum class Redo { kNothing, kErosion, kHeightfield, kGrow };
  TerrainRun() = default;
  Result<Ring> Check(const TerrainState& state) const;  // Start's checks
  std::string Change() const;                           // "lower res", in the plan's words

  Budget budget_;
  TerrainRunPlan plan_;
  TerrainState next_;  // the state Advance works towards
  Ring next_seed_;
  Redo redo_ = Redo::kGrow;
  bool grown_ = false;
  TerrainState state_;  // the state of terrain_ and hf_
  Terrain terrain_;
  Heightfield hf_;      // eroded when the state's erosion is on
  Heightfield hf_raw_;  // hf_ before erosion (kept only while erosion is on)
  ErosionReport erosion_;
  mutable std::optional<Heightfield> heightmap_;  // hf_'s surface on HeightmapGrid
  TerrainGrowLimits limits_;                      // the limits terrain_ was grown within
  TerrainRunCounts counts_;
  std::string truncated_by_;
  std::optional<Estimate> checked_estimate_;
  double ms_grow_ = 0, ms_heightfield_ = 0, ms_erosion_ = 0;
  // Erodes hf_ from hf_raw_ by the state's erosion rows (or keeps hf_ = hf_raw_ when off).
  void ErodeKept(const TerrainState& state);
};

}  // namespace niwa::terrain
