// Mesh input shared by the glTF and OBJ readers: read statistics, limits, and ReadMeshFile, which
// picks the reader by extension (.glb, .gltf, .obj). Does not: build a BVH, weld vertices across
// primitives, read materials or textures, or write meshes (io/gltf_export does).
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>

#include "base/status.h"
#include "geom/tri_mesh.h"

namespace niwa::io {

// What a reader saw beside the triangles it kept.
struct MeshReadStats {
  std::size_t meshes = 0;      // mesh instances read (a glTF mesh used by two nodes counts twice)
  std::size_t primitives = 0;  // triangle primitives (glTF) or faces (OBJ) read
  std::size_t skipped_points_lines = 0;  // glTF POINTS/LINES primitives, OBJ `p`/`l` lines
  std::size_t draco_primitives = 0;      // primitives decoded from KHR_draco_mesh_compression
  std::size_t degenerate = 0;  // triangles skipped: a repeated vertex or zero area in world space
};

// Limits every reader enforces, each named in its error line.
inline constexpr std::size_t kMaxMeshTriangles = 4'000'000;               // "4 M triangles"
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t{512} << 20;  // 512 MiB per file

// Reads a whole file of at most max_bytes; errors name the path (missing, a folder, too large).
Result<std::string> ReadFileCapped(const std::string& path,
                                   std::size_t max_bytes = kMaxMeshFileBytes);

// The file name part of a path ("a/b/rock.glb" -> "rock.glb"), used as the error field.
std::string BaseName(const std::string& path);

// True when the triangle has zero area (computed in double; a repeated vertex included): such
// triangles are skipped and counted in MeshReadStats::degenerate.
bool DegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Reads a .glb, .gltf or .obj file into one world-space TriMesh (metres, as stored).
Result<geom::TriMesh> ReadMeshFile(const std::string& path, MeshReadStats* stats = nullptr);

}  // namespace niwa::io
