// The bark study's run (run::StudyRun, paper 003): the 2-layer model (springs.h) or the 4-layer
// model (four_layer.h: role exchange, peeling, shedding) of a BarkState grown cycle by cycle (one
// cycle = the growth period T; the last followed by the settling steps), with progress in steps
// and cancel, the estimates checked before any work, the crack measures, the maps (PNG bytes of
// base colour, normal, 16-bit height and ORM; the 4-layer maps show the visible layer), a base
// colour frame per cycle on request, the stats JSON, a per-tenth-cycle CSV and the share hash.
// The one pipeline `niwa bark grow` (native_cli/bark_commands.cpp), the page's BarkLab
// (web/bindings/bark_bindings.cpp) and bark on a tree (core/compose/bark_on_tree) adapt.
// Its .glb (Document(), Parts()) is a trunk segment of the grown patch's radius and height wearing
// the maps (bark_gltf.h). Does not: parse flags, read or write files, or time itself (the front
// end adds ms and ns_per_spring_step).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bark/bark_maps.h"
#include "bark/bark_state.h"
#include "bark/four_layer.h"
#include "bark/lattice.h"
#include "bark/regions.h"
#include "bark/springs.h"
#include "base/budget.h"
#include "run/study_run.h"

namespace niwa::bark {

// One row of the cycles CSV (every tenth of a cycle, and the end of settling).
struct BarkSample {
  double cycle = 0;  // growth periods elapsed (fractional)
  int step = 0;
  double strain_theta = 0, strain_z = 0;
  int broken[2] = {0, 0};
  // The 4-layer model's columns: springs broken per role (S, M1, M2, both families), S→M1 bonds
  // broken, peeled share of S, visible share per role (S, M1, M2, inner), shed plates and nodes,
  // role exchanges done.
  int broken_role[3] = {0, 0, 0};
  int bonds_broken = 0;
  double peeled = 0;
  double exposed[4] = {0, 0, 0, 0};
  int shed_regions = 0, shed_nodes = 0, exchanges = 0;
  // The plates of the surface layer (S) then (regions.h: count, mean width around and height
  // along, cm; an uncracked surface is one strip, C × H).
  int plates = 0;
  double plate_w = 0, plate_h = 0;
};

// Table 3 of paper 003, the experiment column (cm, width around × height along the trunk); max_h
// < 0 is the paper's "(>20)": a region longer than the patch.
struct PaperTable3Row {
  const char* species;
  const char* observed;
  double mean_w, mean_h, max_w, max_h;
};
// The paper's row of camphor, tallow or pine; nullptr for any other species.
const PaperTable3Row* PaperTable3(const std::string& species);

// CPU seconds of one spring-step in the estimate (one core; the 4-layer model's second lane does
// not lower it). Measured on the passes in slots (docs/bark-model.md choice 6, docs/BENCHMARKS.md,
// at load 0.7-0.9): 2.39 ns the 2-layer camphor 128 × 64 (the whole process, maps included),
// 2.61 ns the 4-layer pine 128 × 64 over 10 cycles (39.8 s for 15.23 G spring-steps); with a
// third over the larger of them for a busier machine. The bench's bark workloads print it beside
// what they measure (bench/bark_workloads.cpp): re-measure when the passes change.
constexpr double kBarkSecondsPerSpringStep = 3.5e-9;

// What the state will cost: memory of the lattice, its state and the maps, and time by spring-steps
// (kBarkSecondsPerSpringStep, four a node a spring layer: three springs and a shear spring) and
// map pixels (calibrated upper bounds; docs/bark-model.md).
Estimate EstimateBarkRun(const BarkState& state);

// Table 3 of paper 003 measured (spec §4.1, E1): the 2-layer model of each state (one per species,
// in the paper's order camphor, tallow, pine; their model is taken as 2layer) over seeds
// first..last, the regions' mean and max width and height, intercepts, vertical-crack share and
// closed fraction as mean and sample sd over the seeds, beside the paper's observed and experiment
// numbers, as one JSON object. Every run's estimate is summed and checked before any work (errors
// name the budget's limit); a species outside the paper's three is named "species".
Result<std::string> Table3Json(const std::vector<BarkState>& states, uint64_t first_seed,
                               uint64_t last_seed, const Budget& budget);

class BarkRun : public run::StudyRun {
 public:
  // Checks the state (CheckBarkState, the model) and the estimate against the budget (errors name
  // the row or the budget's limit), then builds the lattice at rest. The growth waits for Advance.
  static Result<BarkRun> Start(const BarkState& state, const Budget& budget);
  // Start's checks alone, with no lattice built: a front end refuses a state up front with them
  // before a smaller stand-in of it runs (the page's preview).
  static Status Check(const BarkState& state, const Budget& budget);

  // A new state: a changed grow row, species, model or seed regrows at the next Advance; only
  // map_size changed: the maps are redrawn on demand from the kept surface.
  Status Update(const BarkState& state);
  // Draws the maps (maps(), MapPng, Parts) `width` px wide (even, in [16, 4096]; the rows follow
  // MapHeightPx) instead of the state's map_size: the composition tier's narrow tiles (a thin
  // trunk's tile is tall and narrow; compose/bark_on_tree's GrowOldBark keeps its longer side at
  // map_size). 0: the state's map_size again. Errors name "map_width".
  Status SetMapWidth(int width);

  const char* study() const override { return "bark"; }
  const char* unit() const override { return "cycles"; }
  int done() const override { return cycles_done_; }
  int target() const override;
  // To the state's cycles (and the settling after the last), progress every 256 steps; a cancel
  // leaves the run as it was before this Advance.
  Status Advance(const run::Observer& observer) override;
  // The trunk segment (bark_gltf.h: TrunkSegmentMesh, TrunkDocument) of the grown run: radius
  // R_o·s_θ and height H_o·s_z of its growth (the 4-layer model: S's), the maps' PNG bytes as
  // MapPng gives them. Refused (naming "bark") before the run has grown; Parts() is then empty.
  std::vector<run::Part> Parts() const override;
  Result<gltf::Document> Document() const override;
  std::string StatsJson() const override;
  std::string Hash(const std::string& prefix) const override;
  // "png" (the four maps at the state's map_size), "csv" or "glb" (the maps and the trunk
  // segment); other formats are refused.
  Result<Estimate> ExportEstimate(const std::string& format) const override;

  // The maps' PNG bytes: "base_colour", "normal", "height" (16-bit), "orm"; error names "format".
  Result<std::string> MapPng(const std::string& map) const;
  std::string CyclesCsv() const;
  // The rows the cycles CSV prints (every tenth of a cycle, each cycle's end before and after its
  // exchange).
  const std::vector<BarkSample>& samples() const { return samples_; }

  // Keep a base-colour PNG of each cycle's end (the 4-layer model: before its role exchange),
  // drawn at map_size, from the next Advance; off by default.
  void RecordFrames(bool on) { record_frames_ = on; }
  // The 4-layer model's steps on 1 or 2 lanes (step_lanes.h: two threads where the build has
  // them; the same bits either way), from the next Advance; 2 by default.
  void SetLanes(int lanes) { lanes_ = lanes < 2 ? 1 : 2; }
  int lanes() const { return lanes_; }
  const std::vector<std::string>& FramePngs() const { return frames_; }
  bool four_layer() const { return four_.has_value(); }
  // The 4-layer model's state (four_layer() only).
  const FourLayer& layers() const { return *four_; }

  const BarkState& state() const { return state_; }
  const Lattice& lattice() const { return lattice_; }
  const Mechanics& mechanics() const { return mech_; }
  // The surface layer (the 4-layer model's S).
  const Surface& surface() const { return four_ ? four_->layer[kS].s : surface_; }
  Growth growth() const { return GrowthAt(step_); }
  const CrackMeasures& cracks() const;
  const BarkMaps& maps() const;
  int steps() const { return step_; }
  // Springs (intra-layer and shear) times steps integrated: the divisor of ns_per_spring_step.
  double spring_steps() const;

 private:
  Growth GrowthAt(int step) const;
  void Reset();
  Status AdvanceFourLayer(const run::Observer& observer);
  BarkSample FourLayerSample() const;
  BarkMaps DrawMaps(int width) const;
  std::string FramePng() const;

  BarkState state_;
  Budget budget_;
  Lattice lattice_;
  Mechanics mech_;
  Surface surface_;
  int step_ = 0, cycles_done_ = 0;
  bool settled_ = false;
  std::vector<BarkSample> samples_;
  mutable std::optional<CrackMeasures> cracks_;
  mutable std::optional<BarkMaps> maps_;
  int map_width_ = 0;  // SetMapWidth's width; 0: the state's map_size
  std::optional<FourLayer> four_;
  bool record_frames_ = false;
  std::vector<std::string> frames_;
  int lanes_ = 2;
};

}  // namespace niwa::bark
