// The moss study's built-in scenes (spec §3, §6): `plane` (a flat 2 m humus square), `thesis` (the
// fig 3.1 stand-in: soil slab of three geologies, back wall, roof, two stone blocks), `walls`
// (figs 2.5/2.6: two facing walls on humus) and `rocks` (humus ground with noise-displaced
// icosphere rocks and a triangle-count knob), each a geom::TriMesh in metres, y up, with one
// geology and one region per triangle. Does not: load files (a loaded mesh's geology comes from
// soil_cells.h), split faces into soil cells (soil_cells.h), place the sun (the table's rows) or
// know a run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "geom/tri_mesh.h"
#include "image/image.h"
#include "moss/moss.h"

namespace niwa::moss {

// A loaded mesh's base colour texture as the soil cells sample it (nearest texel, glTF's wrap
// modes; UV (0, 0) is the image's first pixel).
struct SceneTexture {
  image::Rgba8Image texels;            // sRGB
  int wrap_s = 10497, wrap_t = 10497;  // glTF: 10497 repeat, 33071 clamp, 33648 mirrored repeat
};

struct MossScene {
  std::string name;
  geom::TriMesh mesh;            // metres, y up, counter-clockwise seen from outside
  std::vector<Geology> geology;  // one per triangle (a textured triangle's: its cells sample)
  // A loaded mesh's textures (empty for the built-in scenes): per triangle the texture its cells
  // sample at their centroid's UV (-1: none), the three corners' UVs, and the linear colour the
  // texel is multiplied by (the material's baseColorFactor times the corners' mean COLOR_0).
  std::vector<SceneTexture> textures;
  std::vector<int32_t> texture;      // one per triangle, or empty
  std::vector<glm::vec2> corner_uv;  // three per triangle, or empty
  std::vector<glm::dvec3> tint;      // one per triangle, or empty
  std::vector<uint8_t> region;       // one per triangle, an index into region_names
  std::vector<std::string> region_names;
  std::string description;  // one line for `niwa moss scenes`
};

// The built-in scene names in the order `niwa moss scenes` lists them: plane, thesis, walls, rocks.
const std::vector<std::string>& SceneNames();

// The `rocks` scene's knob: the rocks' triangles (the ground's 3,200 come on top), in
// [kRockTrianglesMin, kRockTrianglesMax]; each of the five rocks is an icosphere subdivided until
// the five together have at least this many.
constexpr int kRockTrianglesDefault = 5 * 20 * 16;  // 1,600 (two subdivisions)
constexpr int kRockTrianglesMin = 100;
constexpr int kRockTrianglesMax = 5 * 20 * 65536;  // 6,553,600 (eight subdivisions)

// The rocks' own triangles the knob gives: 5·20·4^L at the first level L with at least
// `rock_triangles` (the ground's come on top). For an estimate before the scene is built.
std::size_t RockTrianglesBuilt(int rock_triangles);

// The built-in scene `name`; the error names "scene" (and the allowed names) or "rock_triangles".
Result<MossScene> BuildScene(std::string_view name, int rock_triangles = kRockTrianglesDefault);

// The 5 cm grid of the built-in scenes (spec §1.2: 2 triangles per square).
constexpr double kSceneGrid = 0.05;

}  // namespace niwa::moss
