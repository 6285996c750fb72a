// Built-in seed contours, each with where it comes from: disk (the cone oracle), dumbbell (splits
// into two peaks), lobes7 (seven valleys), jacksboro900 (the 900 m contour of the USGS Jacksboro
// Fault DEM shipped in Debian's python-matplotlib-data; extracted by
// scripts/terrain_extract_contour.py into core/terrain/seeds/jacksboro900.json and embedded here).
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
