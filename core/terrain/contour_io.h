// Contour files: a seed from {"points": [[x, y], ...]} (metres, optional "elevation") or a GeoJSON
// Polygon/LineString (Feature or geometry), either orientation; the grown contour tree as JSON.
// Does not: check the seed's geometry (generate.h CheckSeed) or write files.
#pragma once

#include <string>

#include "base/status.h"
#include "terrain/contour.h"

namespace niwa::terrain {

struct SeedFile {
  Ring ring;
  bool has_elevation = false;
  double elevation = 0;
};

// Errors name "contour" and say what is allowed.
Result<SeedFile> ParseContourJson(const std::string& text);
// {"h0", "dh", "d", "contours": [{"id", "level", "elevation", "parent", "children", "points"}],
//  "summits": [{"contour", "x", "y", "elevation"}]}
std::string TerrainToJson(const Terrain& terrain);

}  // namespace niwa::terrain
