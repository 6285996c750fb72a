// Mesh metrics: surface area, bounds, degenerate triangles and the validity check every mesh from
// outside passes before a BVH is built on it. Does not: repair meshes beyond dropping degenerate
// triangles, weld vertices, or smooth normals (FaceNormals gives faceted ones).
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "base/status.h"
#include "geom/bounds.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

// Area of triangle t (|(b - a) x (c - a)| / 2, in double), 0 for a degenerate one.
double TriangleArea(const TriMesh& mesh, std::size_t t);
// Sum of the triangle areas, m² (summed in double, in triangle order).
double SurfaceArea(const TriMesh& mesh);
// Bounds of the vertices the triangles use (unused vertices are ignored); empty with no triangles.
Bounds3 MeshBounds(const TriMesh& mesh);

// Degenerate: a repeated index, or zero area (the cross product of its edges is exactly zero).
bool IsDegenerateTriangle(const TriMesh& mesh, std::size_t t);
std::size_t CountDegenerateTriangles(const TriMesh& mesh);
// Drops degenerate triangles (keeping the order of the rest); returns how many were dropped.
// Vertices are kept.
std::size_t RemoveDegenerateTriangles(TriMesh* mesh);

// Per-vertex normals of a mesh without them: each vertex gets its triangles' face normal (the
// readers never share vertices across primitives; a shared vertex gets the area-weighted sum),
// unit length, (0, 1, 0) where that sum is zero.
std::vector<glm::vec3> FaceNormals(const TriMesh& mesh);

// Ok, or the first problem, named under `field` (e.g. "mesh.glb"): an index count that is not a
// multiple of 3, no triangles, a NaN/infinite position, an index out of range, or normals/uvs/
// attributes whose size does not match the vertex count.
Status ValidateMesh(const TriMesh& mesh, const std::string& field = "mesh");

}  // namespace niwa::geom
