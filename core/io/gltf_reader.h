// glTF 2.0 input (.glb and .gltf, with KHR_draco_mesh_compression where this build can decode it):
// every triangle mesh of the default scene (or scene 0) in world space, through tinygltf, with its
// materials' names, base colours and base colour textures' images (kept encoded, header checked).
// Does not: decode images, read other textures, skins, morph targets or animations; decode Draco in
// the WASM build (the page decodes it first, see web/mesh); fetch URIs other than data: and files
// beside a .gltf.
#pragma once

#include <string>

#include "base/status.h"
#include "geom/tri_mesh.h"
#include "io/mesh_reader.h"

namespace niwa::io {

// True when this build links Draco (native: Debian libdraco) and so decodes
// KHR_draco_mesh_compression primitives.
bool GltfReaderDecodesDraco();

// Reads glTF from bytes (.glb or .gltf JSON, told apart by the 'glTF' magic). name is the error
// field (the file name). base_dir is where external buffers of a .gltf live ("" = none allowed).
// Node world transforms are applied (matrix or TRS, parent * child), normals by the inverse
// transpose, winding flipped under a mirroring transform; TRIANGLE_STRIP and TRIANGLE_FAN become
// triangles; POINTS and LINES primitives are skipped and counted; degenerate triangles skipped and
// counted. Errors: empty, truncated, not glTF, NaN/inf positions, only points/lines, over
// kMaxMeshTriangles, an unsupported required extension, Draco not decodable in this build; a
// material's baseColorTexture naming a missing texture or image, or whose PNG/JPEG image is
// unreadable, empty or over kMaxTextureSide / kMaxTexturePixels (a WebP or KTX 2 image is kept
// without bytes, not refused).
Result<geom::TriMesh> ReadGltfMesh(const std::string& bytes, const std::string& name,
                                   const std::string& base_dir, MeshReadStats* stats = nullptr);

// Reads a .glb or .gltf file (at most kMaxMeshFileBytes, external buffers beside it).
Result<geom::TriMesh> ReadGltfFile(const std::string& path, MeshReadStats* stats = nullptr);

}  // namespace niwa::io
