// Triangle meshes of a grown tree: bark tubes, leaf quads and flowers, in metres, for glTF and
// WebGL.
#pragma once

#include <cstdint>
#include <vector>

#include "tree/tree.h"

namespace niwa {

// One indexed triangle list (GL/glTF ready: 32-bit indices, interleaving left to the consumer).
struct MeshBuffers {
  std::vector<float> positions;   // xyz per vertex, metres, y up
  std::vector<float> normals;     // unit xyz per vertex
  std::vector<float> uvs;         // uv per vertex
  std::vector<uint32_t> indices;  // three per triangle
  std::size_t vertex_count() const { return positions.size() / 3; }
};

struct TreeMesh {
  MeshBuffers bark;  // generalized cylinders, one ring per node, end caps at tips
  std::vector<uint32_t> bark_branch_id;  // branch id of each bark vertex (picking, pruning)
  MeshBuffers leaves;                    // one double-sided quad (two triangles each side) per leaf
  MeshBuffers flowers;                   // a small five-petal star per open flower
};

struct MeshOptions {
  int min_sides = 3;          // sides of the thinnest tube
  int max_sides = 12;         // sides of the thickest tube
  float cm_to_units = 0.01f;  // tree data are in cm; glTF wants metres
};

TreeMesh BuildTreeMesh(const Tree& tree, const MeshOptions& options = {});

}  // namespace niwa
