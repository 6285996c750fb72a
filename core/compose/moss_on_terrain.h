// Moss on a grown Niwa terrain: the terrain study's mountain (core/terrain TerrainRun from a
// preset, the built-in disk seed and an RNG seed) as the moss study's land, in metres with y up
// (the terrain's .glb frame: x, height, −y), geology by slope and height (choice 30 of
// docs/moss-model.md) and regions by height. Does not: grow the moss (moss/moss_run does, through
// MossRun::StartOnScene), read a contour file or a drawing (the built-in disk only), or name a
// flag (errors name "terrain", "terrain_seed" or the budget's limit; the front ends rename them).
#pragma once

#include <string>

#include "base/budget.h"
#include "base/status.h"
#include "moss/scenes.h"

namespace niwa::compose {

// The terrain's heightfield resolution for a moss land (the terrain's res row): cells along the
// longer side. 64 keeps the land at about 8,500 triangles; the soil cells then split them
// (doubling soil_edge over the cells' cap, with a notice).
constexpr int kMossTerrainRes = 64;
// Geology by slope and height (choice 30): steeper than this is bare rock (asphalt), ...
constexpr double kMossRockSlopeDeg = 30;
// ... above this share of the relief (from the lowest point) thin upland soil (sandy), else humus.
constexpr double kMossUplandShare = 2.0 / 3.0;

// Grows terrain preset `preset` (a method or a figure preset: `niwa presets terrain`) from the
// built-in disk seed with RNG seed `seed` at res kMossTerrainRes within `budget`, and returns the
// land: scene "terrain:<preset>", every triangle of the surface with its geology (slope over
// kMossRockSlopeDeg: asphalt; else above kMossUplandShare of the relief: sandy; else humus) and
// its region by the centroid's height in thirds of the relief ("foot", "middle", "top");
// `truncated_by` gets the grow's stop line ("" if none). Errors name "terrain" (an unknown
// preset), "terrain_seed", or the budget's limit.
Result<moss::MossScene> MossTerrainLand(const std::string& preset, double seed,
                                        const Budget& budget, std::string* truncated_by);

}  // namespace niwa::compose
