// The garden's planting (issue 33 items 1 and 3): the hand-placed trees checked against the
// objects, then the planting rules: darts thrown over the square, each kept or refused by the
// density mask, the altitude band, the slope limit, the objects' footprints and the Poisson
// minimum spacing (in that order; the first rule that refuses is counted), a species drawn from
// the mix by weight and one of `variants` tree seeds. Every tree's foot is at the ground's height
// under it. Does not: grow trees (garden_run.h), read a mask file (the state carries its bytes),
// or name a flag (errors name state fields).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "compose/garden_scene.h"
#include "compose/garden_state.h"

namespace niwa::compose {

// ---- data ----

struct PlacedTree {
  std::string species;
  uint64_t seed = 1;
  int age = 0;                 // years when the garden starts
  double x = 0, y = 0, z = 0;  // the trunk's foot on the ground
  double rot = 0;              // degrees about y
  int hand = -1;               // index into state.plants, −1 for a rule-planted tree
};

struct PlantingReport {
  long target = 0;      // density · size²
  long candidates = 0;  // darts thrown
  long by_hand = 0, by_rule = 0;
  // Darts refused, by the first rule that refused them.
  long refused_mask = 0, refused_altitude = 0, refused_slope = 0, refused_object = 0,
       refused_spacing = 0;
};

struct Planting {
  std::vector<PlacedTree> trees;  // the hand-placed ones first, in state order, then the rules'
  PlantingReport report;
};

// ---- constants ----

// Darts thrown per tree the density asks for before the rules give up (Poisson dart throwing).
constexpr long kDartsPerTree = 30;
// Most trees the rules may place (the budget refuses a garden's growth earlier).
constexpr long kMaxRuleTrees = 100000;
// A trunk keeps this far from an object's footprint.
constexpr double kTrunkClearance = 0.3;

// ---- functions ----

// The trees of `state` on `scene`. Errors: "plants[i].pos" (a hand-placed tree inside an object's
// footprint), "mask" (not a PNG), "density" (more than kMaxRuleTrees trees asked for).
Result<Planting> PlantGarden(const GardenState& state, const GardenScene& scene);

// Positions as JSON: {"trees": [{species, seed, age, pos: [x, y, z], rot, hand}], "report": {...}}.
std::string PlantingJson(const Planting& planting);

}  // namespace niwa::compose
