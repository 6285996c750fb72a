// Wavefront OBJ input: `v` positions and `f` faces (polygons fan-triangulated; v, v/vt, v//vn and
// v/vt/vn forms; negative indices count back from the latest vertex). Does not: read materials
// (mtllib/usemtl are ignored), texture coordinates or normals (their indices are checked, not
// kept), curves or free-form surfaces.
#pragma once

#include <string>

#include "base/status.h"
#include "geom/tri_mesh.h"
#include "io/mesh_reader.h"

namespace niwa::io {

// Reads OBJ text. name is the error field; every error names the 1-based line ("rock.obj: line 12:
// face index 9 is out of range; must be in [1, 8] or [-8, -1]"). `p` and `l` lines are skipped and
// counted; a file with no faces is an error. Degenerate triangles are skipped and counted.
Result<geom::TriMesh> ReadObjMesh(const std::string& text, const std::string& name,
                                  MeshReadStats* stats = nullptr);

// Reads an .obj file (at most kMaxMeshFileBytes).
Result<geom::TriMesh> ReadObjFile(const std::string& path, MeshReadStats* stats = nullptr);

}  // namespace niwa::io
