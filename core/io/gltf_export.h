// glTF 2.0 export of a tree mesh with tinygltf: binary .glb bytes in memory.
#pragma once

#include <string>
#include <vector>

#include "tree/mesh.h"

namespace niwa {

// Fills bytes with a complete .glb (bark, leaves, flowers, each with its material). Returns "" or
// one error line.
std::string WriteGlb(const TreeMesh& mesh, std::vector<unsigned char>* bytes);

}  // namespace niwa
