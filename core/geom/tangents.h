// Per-vertex tangents for tangent-space normal maps (glTF TANGENT: xyz, w = +-1 the bitangent's
// sign) from a TriMesh's positions, normals and uvs. Does not: weld or split vertices (a UV seam
// keeps its duplicated vertices, each with its own tangent), compute normals, or reproduce
// MikkTSpace's exact bits (no angle weights: angles would need acos, whose last bits differ
// between libms, and Niwa's bytes must match natively and in WASM).
#pragma once

#include <vector>

#include "geom/tri_mesh.h"

namespace niwa::geom {

// The attribute ComputeTangents writes: glTF's TANGENT semantic, 4 floats per vertex.
inline constexpr char kTangentAttribute[] = "TANGENT";

// 4 floats per vertex (x, y, z, w), or empty when the mesh has no normals or no uvs (each must
// have one per vertex). Triangles are the indices, three each (none: the vertices in order). Per
// triangle with a non-degenerate uv map, the directions of dP/du (the
// tangent) and dP/dv (the bitangent) are solved from its edges, normalised and summed into its
// three vertices weighted by the triangle's area (in double, in triangle order). At each vertex
// the tangent sum is made orthogonal to the normal (Gram-Schmidt) and normalised; w is -1 when
// cross(normal, tangent) points along the bitangent sum, else +1, so that bitangent =
// cross(normal, tangent.xyz) * w (as glTF reads it) runs along -dP/dv: glTF's normal texture has
// +Y up the image ("OpenGL" convention) and its uv origin at the image's top-left, so v grows
// down the image. (three.js' GLTFLoader agrees: without TANGENT it derives B = +dP/dv and negates
// normalScale.y.) A uv map seen from the front with u right and v down the image gets w = +1. A vertex with no usable uv
// triangle (degenerate uvs, unused, or a tangent along its normal) gets a unit tangent
// perpendicular to its normal and w = +1; a zero normal gets (1, 0, 0, 1). Never NaN for finite
// input.
std::vector<float> ComputeTangentValues(const TriMesh& mesh);

// Sets (adds or overwrites) the mesh's kTangentAttribute to ComputeTangentValues; leaves the mesh
// unchanged and returns false when it has no normals or uvs.
bool ComputeTangents(TriMesh* mesh);

}  // namespace niwa::geom
