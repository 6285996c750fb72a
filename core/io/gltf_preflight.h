// Checks of a glTF file's JSON before tinygltf parses it or anything is allocated from it: the
// shared JSON guard (depth, repeated keys), declared sizes (buffers, buffer views, accessor count
// times stride, overflow-checked in 64 bits on every build so native and WASM refuse alike), and an
// estimate of the scene's instanced nodes, triangles and vertices against the reader's limits.
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

}  // namespace niwa::io
