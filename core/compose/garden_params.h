// The garden's parameter table ("garden"; issue 33, docs/garden-model.md): the ground's size,
// relief and grid, the one clock (years), the planting rules (density, minimum spacing, altitude
// band, slope limit, their seed, variants per species), the interactions' switches, the
// export's triangle budget and shared shapes, and the bark (procedural or simulated, its maps'
// size), each with its unit, range and stage. Does not: hold the lists a garden places (plants,
// objects, the species mix: garden_state.h), grow anything (garden_run.h) or parse text (params/,
// io/hash_codec).
#pragma once

#include "params/param_table.h"

namespace niwa::compose {

// One entry per row of the garden table, in panel order within each group.
enum class GardenParam : int {
  // ground
  kSize,
  kRelief,
  kGroundRes,
  // clock
  kYears,
  // planting rules
  kDensity,
  kSpacing,
  kAltMin,
  kAltMax,
  kSlopeMax,
  kPlantSeed,
  kVariants,
  // interactions
  kShade,
  kShadeReach,
  kIvySteps,
  kMossDays,
  kMossShade,
  kMossCanopy,
  // export
  kMaxTriangles,
  kLod,
  kInstancing,
  kShapes,
  // bark
  kBark,
  kBarkMapSize,
  kCount
};

const ParamTable& GardenTable();
const ParamTable& TableOf(GardenParam);
using GardenParams = StudyParams<GardenParam>;

}  // namespace niwa::compose
