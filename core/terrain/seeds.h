// Built-in seed contours, each with where it comes from: disk (the cone oracle), dumbbell (splits
// into two peaks), lobes7 (seven valleys), jacksboro (a real contour: the 800 m contour of a USGS
// DEM, compiled in from core/terrain/seed_jacksboro.inc), valleys (18 valleys of different depths).
// Does not: read files at run time.
#pragma once

#include <string>
#include <vector>

#include "base/status.h"
#include "terrain/contour.h"

namespace niwa::terrain {

struct SeedInfo {
  std::string name;
  std::string source;              // provenance, one line
  double d = 20, dh = 10, h0 = 0;  // defaults that suit its size
};

const std::vector<SeedInfo>& BuiltinSeeds();
// The ring of a built-in seed (metres, counter-clockwise); the error lists the names.
Result<Ring> BuiltinSeed(const std::string& name);

}  // namespace niwa::terrain
