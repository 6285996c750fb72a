// The bark study's glTF output (issue 30 items 2 and 6: "a .glb of a trunk segment"): a lit trunk
// segment wearing the maps, a cylinder of the grown patch's radius and height (metres, y up, its
// axis on the y axis, base at y = 0), the tile wrapped a whole number of times around (the patch
// is the real circumference, so once: u = n_u·angle/2π, the seam's two columns of vertices at u =
// 0 and u = n_u) and once along (v = 0 at the top, 1 at the base: the maps' rows run down the
// trunk), with its exact tangent frame (TANGENT around, w = +1: bitangent = cross(normal,
// tangent) up the trunk, the normal map's +y: OpenGL, "+Y up the image" as glTF's normalTexture
// says), one material with the base colour, normal and occlusion/roughness/metallic maps as
// embedded PNG textures (sampler REPEAT). Does not: run the model or draw the maps (bark_run.h
// hands the PNG bytes), cap the ends (an open tube), write bytes (io/gltf_writer) or read files.
#pragma once

#include <string>

#include "base/budget.h"
#include "geom/tri_mesh.h"
#include "io/gltf_writer.h"

namespace niwa::bark {

constexpr int kTrunkSides = 96;  // the segment's columns of quads around

// Whole wraps of a tile tile_width_m wide around a circle of radius_m: max(1, round(2πr / C)).
int TileWraps(double radius_m, double tile_width_m);

// The open cylinder: kTrunkSides + 1 vertices a ring (the seam doubled), two rings (base, top);
// positions, outward normals, uvs (u = TileWraps·k/kTrunkSides around, v = 0 at the top, 1 at
// the base) and the "TANGENT" attribute (around, w = +1). Triangles counter-clockwise seen from
// outside. Angles by det:: maths (native == WASM).
geom::TriMesh TrunkSegmentMesh(double radius_m, double height_m, double tile_width_m);

// The maps' PNG bytes (as `niwa bark grow --out/--normal/--orm` write them).
struct TrunkMaps {
  std::string base_colour, normal, orm;
};

// The document: node "trunk" (mesh "trunk": one primitive of TrunkSegmentMesh), material "bark"
// (baseColorTexture, normalTexture, occlusionTexture = metallicRoughnessTexture = the ORM map,
// factors 1), textures "bark", "bark_normal", "bark_orm" (REPEAT); the scene's extras_json as the
// asset's extras.
gltf::Document TrunkDocument(geom::TriMesh mesh, const TrunkMaps& maps,
                             const std::string& extras_json);

// What the .glb adds to the maps' PNGs: its mesh and the document (bytes; upper bounds).
Estimate TrunkGlbEstimate();

}  // namespace niwa::bark
