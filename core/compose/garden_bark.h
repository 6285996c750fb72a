// Simulated bark per trunk in the garden (issue 33 items 1, 3, 5; docs/garden-model.md "Bark"):
// each distinct tree's trunk radius recorded year by year on the garden's clock (nursery years
// too), the bark study run on that history (compose/bark_on_tree's plan and run) with the bark
// species its tree species maps to, and the maps put on that tree's tube bark in the garden's
// .glb (base colour, normal, occlusion/roughness), on every level of detail. Copies that share one
// growth share one bark, and trees whose bark states come out the same share one run. Does not:
// grow trees (GardenRun does, calling RecordGardenTrunk after each year), draw the bark on the
// page, dress the twig cones or branch cards (they keep their colour and atlas), or run the young
// shoots' second bark (one frame on every tube, as the tree page's one bark part does).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "compose/bark_on_tree.h"
#include "compose/garden_state.h"
#include "io/gltf_writer.h"
#include "render/tree_lod.h"
#include "run/study_run.h"
#include "tree/tree.h"

namespace niwa::compose {

// The bark preset (bark::BarkPresetNames) a tree preset's simulated bark uses: pine -> pine;
// sakura, weeping (cherries), keyaki, tsutsuji -> tallow; maple, ginkgo and the rest -> camphor
// (the choices and why: docs/garden-model.md).
std::string GardenBarkSpecies(const std::string& tree_preset);

// The heights the garden reads a trunk at (m): breast height, or for a trunk that did not reach
// it the year before the last (a young tree, an azalea), near its foot.
constexpr double kGardenBarkHeights[2] = {kDefaultBarkHeight, 0.3};

// One distinct tree's (one GardenRun group's) bark.
struct GardenBark {
  std::string species;                     // the bark preset
  TrunkHistory trunk[2];                   // the trunk's radius year by year at each height
  double height_m = 0;                     // the height the bark ran at (0: not run)
  BarkOnTreePlan plan;                     // its plan (the window's radii, N_R, dR)
  std::shared_ptr<const BarkFrame> frame;  // the simulated bark; null: procedural
  std::string procedural_why;  // why a tree asked for simulated bark kept the procedural one
};

// Every distinct tree's bark, and what they took.
struct GardenBarks {
  bool on = false;                // the state's bark row is 1
  int map_size = 256;             // the state's bark_map_size
  std::vector<GardenBark> trees;  // one per group, in the groups' order
  bool grown = false;             // GrowGardenBarks ran
  int runs = 0;                   // bark runs made (trees with the same bark state share one)
  double ms = 0;                  // wall time of the bark runs
  int simulated() const;
};

// The barks of `species` (one per group, their tree presets) as the state asks (nothing recorded
// or run when bark is 0). Errors: "bark_map_size" (not a power of two).
Result<GardenBarks> StartGardenBarks(const GardenState& state,
                                     const std::vector<std::string>& species);

// The least the garden's barks can cost (each run at its smallest lattice, N_R 8, one cycle, and
// its maps), checked up front against the budget (GardenRun::Start): a garden whose barks cannot
// fit even so is refused naming "bark". Zero when bark is 0.
Estimate GardenBarkLeastEstimate(const GardenBarks& barks);

// Records tree's year into the bark of group g (a no-op when bark is 0 or the year is recorded).
void RecordGardenTrunk(const Tree& tree, std::size_t g, GardenBarks* barks);

// Runs the bark of each group on its own trunk history within `left` (what the trees and the ivy
// left of the garden's budget), seeded with its tree's seed. A tree whose trunk grew too little
// (under two years at any height) keeps the procedural bark (procedural_why says so); a bark whose
// plan no longer fits what is left is not run and `truncated_by` gets one line naming "bark"
// (when empty). Errors: a cancel or a bark run's error (naming "bark").
// The observer sees {"bark", distinct tree, distinct trees} before each.
Status GrowGardenBarks(const std::vector<const Tree*>& trees, const std::vector<uint64_t>& seeds,
                       const Budget& left, const run::Observer& observer, GardenBarks* barks,
                       std::string* truncated_by);

// The tube bark of every level wears the simulated bark's old frame: ring UVs u · wraps around
// the branch, v in metres over the tile's height (WrapBarkUvs on each level's parts).
void WrapGardenBarkUvs(const Tree& tree, const BarkFrame& frame, std::vector<LodMesh>* levels);

// The tree document's "bark" material (shared by its levels) takes the simulated maps: base
// colour, normal, and the ORM map as occlusion and metallic-roughness, sampler REPEAT.
void DressGardenBark(const BarkFrame& frame, gltf::Document* tree_doc);

// The bark's part of the .glb's estimate: three maps a simulated tree.
Estimate GardenBarkExportEstimate(const GardenBarks& barks);

// {"simulated", "procedural", "runs", "map_size", "species": {bark preset: trees}, "trees": [one
// per distinct tree: its species, height, window's years and radii, N_R, dR, tile, hash, or why it
// kept the procedural bark]} for the stats ("" when bark is 0).
std::string GardenBarksJson(const GardenBarks& barks);

}  // namespace niwa::compose
