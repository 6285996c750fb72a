// Mesh input shared by the glTF and OBJ readers: read statistics, limits, and ReadMeshFile, which
// picks the reader by extension (.glb, .gltf, .obj). Does not: build a BVH, weld vertices across
// primitives, decode textures (a base colour texture's image is kept encoded, its header checked),
// or write meshes (io/gltf_writer does).
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "base/status.h"
#include "geom/tri_mesh.h"

namespace niwa::io {

// A glTF image a material's baseColorTexture uses, kept encoded (the moss study decodes it for
// its geology; io only reads its header). Only PNG and JPEG are kept: a WebP or KTX 2 image, or an
// external file of a .gltf read from bytes (no folder), is listed with empty bytes.
struct MeshImage {
  std::string name;   // the image's name, else its uri, else "image N"
  std::string bytes;  // the encoded PNG or JPEG; empty when this build cannot decode it
  int width = 0;      // from the header, each side in [1, kMaxTextureSide]
  int height = 0;
};

// glTF sampler wrap modes (glTF 2.0 §5.26).
inline constexpr int kWrapRepeat = 10497;
inline constexpr int kWrapClampToEdge = 33071;
inline constexpr int kWrapMirroredRepeat = 33648;

// A glTF material as the studies need it: its name (ivy: a name starting with "noivy" marks an
// obstacle; moss: "humus"/"sand"/"asphalt" set the geology), baseColorFactor, its
// baseColorTexture's image and sampler wrap modes, and extras.niwa_ivy (false: obstacle, not
// support).
struct MeshMaterial {
  std::string name;
  glm::vec4 base_color{1.0f};  // linear RGBA, glTF default (1, 1, 1, 1)
  bool ivy_support = true;     // extras.niwa_ivy, default true
  // Index in MeshReadStats::images of the baseColorTexture's image (any texCoord set); -1 when
  // the material has none or its image has no bytes (a format this build does not decode).
  int base_color_image = -1;
  // The glTF image index of the baseColorTexture (its source, or EXT_texture_webp's, etc.) whether
  // or not its bytes are kept: a page that decodes WebP itself (the ivy page draws a dropped mesh
  // with it) finds its bytes there; -1 when the material has none.
  int base_color_source = -1;
  int wrap_s = kWrapRepeat, wrap_t = kWrapRepeat;
  // The baseColorTexture's UV set (textureInfo.texCoord, or KHR_texture_transform's texCoord,
  // which overrides it) and its KHR_texture_transform (glTF spec: uv' = T(offset) * R(rotation) *
  // S(scale) * uv, rotation in radians counter-clockwise in UV space). The reader has already
  // applied both to kBaseColorUvAttribute; they are kept for the record.
  int base_color_tex_coord = 0;
  bool has_uv_transform = false;
  double uv_offset[2] = {0.0, 0.0};
  double uv_rotation = 0.0;
  double uv_scale[2] = {1.0, 1.0};
};

// Per-vertex attributes the glTF reader adds to the TriMesh (vertices are never shared across
// primitives, so a vertex's material is its triangles' material):
inline constexpr const char* kMaterialAttribute =
    "material";  // 1 float: index in materials, -1 none
inline constexpr const char* kColorAttribute =
    "color";  // 4 floats: COLOR_0 RGBA, (1,1,1,1) if absent
// 2 floats: where the vertex's material's baseColorTexture is sampled, TEXCOORD_<texCoord> with
// its KHR_texture_transform applied ((0, 0) on a vertex whose material has no baseColorTexture).
// Present when some triangle primitive's material has a baseColorTexture; such a primitive without
// that UV set is refused (the glTF validator's MESH_PRIMITIVE_TOO_FEW_TEXCOORDS).
inline constexpr const char* kBaseColorUvAttribute = "base_color_uv";

// What a reader saw beside the triangles it kept.
struct MeshReadStats {
  std::size_t meshes = 0;      // mesh instances read (a glTF mesh used by two nodes counts twice)
  std::size_t primitives = 0;  // triangle primitives (glTF) or faces (OBJ) read
  std::size_t skipped_points_lines = 0;  // glTF POINTS/LINES primitives, OBJ `p`/`l` lines
  std::size_t draco_primitives = 0;      // primitives decoded from KHR_draco_mesh_compression
  std::size_t degenerate = 0;  // triangles skipped: a repeated vertex or zero area in world space
  // glTF materials in file order (kMaterialAttribute indexes them); empty for OBJ.
  std::vector<MeshMaterial> materials;
  // glTF images in file order (MeshMaterial::base_color_image indexes them): only the base colour
  // textures' images carry bytes.
  std::vector<MeshImage> images;
  // Metres per unit the format names: 1 for glTF (glTF 2.0 §3.4: "the units for all linear
  // distances are meters"), 0 for OBJ (no unit).
  double metres_per_unit = 0;
};

// Limits every reader enforces, each named in its error line.
inline constexpr std::size_t kMaxMeshTriangles = 4'000'000;               // "4 M triangles"
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t{512} << 20;  // 512 MiB per file
// Vertices in one scene: every triangle of the limit with its own three ("12 M vertices"), counted
// over instances (a mesh used by two nodes counts twice) before any is read.
inline constexpr std::size_t kMaxMeshVertices = 3 * kMaxMeshTriangles;
// Node instances one glTF scene walk visits (a node reached by two paths counts twice): "1 M".
inline constexpr std::size_t kMaxNodeInstances = 1'000'000;

// A base colour texture's image: each side at most 16,384 pixels, at most 2^24 pixels in all (a
// 4,096 x 4,096 texture; 64 MiB decoded). Checked from the header when the file is read.
inline constexpr int kMaxTextureSide = 16384;
inline constexpr std::size_t kMaxTexturePixels = std::size_t{1} << 24;

// Reads a whole file of at most max_bytes; errors name the path (missing, a folder, too large).
Result<std::string> ReadFileCapped(const std::string& path,
                                   std::size_t max_bytes = kMaxMeshFileBytes);

// The file name part of a path ("a/b/rock.glb" -> "rock.glb"), used as the error field.
std::string BaseName(const std::string& path);

// True when the triangle has zero area (computed in double; a repeated vertex included): such
// triangles are skipped and counted in MeshReadStats::degenerate.
bool DegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Reads a mesh's bytes (a dropped file: Draco already decoded, no external buffers) by its name:
// OBJ text when the name ends in .obj or .OBJ, else glTF (.glb or .gltf); errors name `name`.
Result<geom::TriMesh> ReadMeshBytes(const std::string& bytes, const std::string& name,
                                    MeshReadStats* stats = nullptr);

// Reads a .glb, .gltf or .obj file into one world-space TriMesh (metres, as stored).
Result<geom::TriMesh> ReadMeshFile(const std::string& path, MeshReadStats* stats = nullptr);

}  // namespace niwa::io
