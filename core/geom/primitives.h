// Primitive meshes (box, plane, cylinder, icosphere) with normals and uvs, in metres, and
// Subdivide: each triangle into 4^K coplanar ones. Does not: weld, smooth (subdivision keeps the
// faces flat), or make scenes (each study's scenes file places these).
#pragma once

#include <glm/vec3.hpp>

#include "geom/tri_mesh.h"

namespace niwa::geom {

// Axis-aligned box of `size` centred on `centre`: 6 faces of 2 triangles, 4 vertices per face
// (flat normals, each face's uvs span [0, 1]); 24 vertices, 12 triangles, outward winding.
TriMesh MakeBox(const glm::vec3& size, const glm::vec3& centre = glm::vec3(0.0f));

// Plane in x-z at y = 0, normal +y, `width` along x and `depth` along z, centred on the origin,
// split into segments_x × segments_z quads (each 2 triangles); uvs span [0, 1]. Segments are
// clamped to at least 1.
TriMesh MakePlane(float width, float depth, int segments_x = 1, int segments_z = 1);

// Cylinder along +y from y = 0 to `height`, `segments` (clamped to >= 3) around; side with smooth
// radial normals and a seam column of duplicated vertices (u 0..1 around, v 0..1 up); with `caps`
// a flat disc at each end (fan around a centre vertex, normals ∓y).
TriMesh MakeCylinder(float radius, float height, int segments, bool caps = true);

// Icosphere of `radius` at the origin: an icosahedron (20 triangles) whose triangles are split in 4
// `level` times (clamped to [0, 8]) with the new vertices pushed onto the sphere; 20·4^level
// triangles, shared vertices, normals = position / radius, equirectangular uvs (no seam fix).
TriMesh MakeIcosphere(float radius, int level);

// Each triangle into 4^levels coplanar ones by midpoint split, `levels` times (clamped to
// [0, 10]). An edge shared by two triangles (same two vertex indices) gets one midpoint vertex
// (edge-midpoint map), so index-shared meshes stay watertight; normals, uvs and every custom
// attribute are interpolated (normals renormalized). Triangle order: the 4 children of triangle t
// are 4t..4t+3 (corner a, corner b, corner c, centre).
TriMesh Subdivide(const TriMesh& mesh, int levels);

}  // namespace niwa::geom
