// Checks of a glTF file's JSON before tinygltf parses it or anything is allocated from it: the
// shared JSON guard (depth, repeated keys), declared sizes (buffers, buffer views, accessor count
// times stride, overflow-checked in 64 bits on every build so native and WASM refuse alike), and an
// estimate of the scene's instanced nodes, triangles and vertices against the reader's limits.
// Also reads a Draco buffer's header (PreflightDracoHeader) for its declared counts.
// Does not: read buffers, decode Draco, or check what tinygltf itself refuses (malformed JSON,
// missing required properties): a file it cannot interpret is left to tinygltf's own error.
#pragma once

#include <string>
#include <string_view>

#include "base/status.h"

namespace niwa::io {

// Ok when json (a .gltf file or a .glb's JSON chunk) is safe to hand to tinygltf and its scene is
// within kMaxNodeInstances, kMaxMeshTriangles and kMaxMeshVertices; else one line naming `name`.
Status PreflightGltfJson(std::string_view json, const std::string& name);

// A KHR_draco_mesh_compression buffer's header (bitstream 2.2, what every encoder since Draco 1.3
// writes): Ok unless it declares more than kMaxMeshTriangles faces or kMaxMeshVertices points
// (vertices), refused naming `label` before the decoder sizes anything from them; also Ok for
// what it cannot read (another version, metadata, a short buffer), which is left to the decoder.
// Draco 1.5.5 itself refuses counts its bytes cannot hold cheaply (2^28 faces in a 642-byte buffer:
// a 6 MB peak); this cap stops a file that really holds a mesh above the reader's limits before it
// is decoded, natively. The page decodes Draco with draco3d (web/mesh/mesh_import.js) before the
// core sees the file; its dracoHeaderCounts reads the header the same way and refuses with the same
// line (tests/cli/mesh_import.test.mjs checks its caps against mesh_reader.h's).
Status PreflightDracoHeader(std::string_view bytes, const std::string& label);

}  // namespace niwa::io
