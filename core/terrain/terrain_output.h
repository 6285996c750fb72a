// The terrain's output formats as bytes: the heightfield as a glTF mesh (metres, normals, optional
// hypsometric tint, the contours as LINES at their heights), as a 16-bit greyscale PNG with a JSON
// sidecar, and the contour tree as GeoJSON and SVG. Does not: write files (native_cli stages and
// renames them), grow or build the heightfield (generate.h, heightfield.h).
#pragma once

#include <string>
#include <vector>

#include "base/status.h"
#include "io/gltf_writer.h"
#include "terrain/contour.h"
#include "terrain/heightfield.h"

namespace niwa::terrain {

// glTF is y-up: a point (x east, y north) at elevation h is the vertex (x, h, −y).
// Nodes "terrain" (the surface: one vertex per cell centre, TRIANGLES, NORMAL, TEXCOORD_0 over its
// extent, COLOR_0 when tint)
// and "contours" (every contour ring as LINES at its elevation). asset extras: extras_json.
gltf::Document TerrainDocument(const Terrain& terrain, const Heightfield& hf, bool tint,
                               const std::string& extras_json = "");
// The hypsometric tint of a normalised height t in [0, 1] (green, ochre, brown, white), RGB 0..1.
void HypsometricColour(double t, float rgb[3]);

// The heightmap's grid (issue 31 item 7: engines take square 2^k + 1 heightmaps; the heightfield
// is res cells along its longer side and as many as its box needs along the other): N x N cells
// with N = 2^ceil(log2(res)) + 1 (res 256: 257; 512: 513; 1000: 1025), covering the heightfield's
// extent, its longer side N - 1 cells and the shorter one centred, cell centres as the
// heightfield's (pixel (i, j) samples the surface at its centre). Only the grid: BuildHeightfieldOn
// fills it.
Heightfield HeightmapGrid(const Heightfield& hf, int res);

struct Heightmap {
  std::vector<unsigned char>
      png;  // 16-bit grey, row 0 north, sample = round((h−min)/(max−min)·65535)
  std::string sidecar_json;  // {"width", "height", "min_elevation", "max_elevation", ...}
};
// The PNG also carries the sidecar as a tEXt chunk "niwa-heightmap".
Result<Heightmap> EncodeHeightmap(const Heightfield& hf);

// A FeatureCollection: one Polygon Feature per contour (properties id, level, elevation, parent;
// rings closed, counter-clockwise as RFC 7946 says) and one Point Feature per summit.
std::string TerrainToGeoJson(const Terrain& terrain);
// A plan view: the contours coloured by height over the seed's box (north up), summits as dots.
std::string TerrainToSvg(const Terrain& terrain);

}  // namespace niwa::terrain
