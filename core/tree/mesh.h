// Triangle meshes of a grown tree: bark tubes, leaf quads and flowers, in metres, for glTF and
// WebGL.
#pragma once

#include <cstdint>
#include <vector>

#include "tree/tree.h"

namespace niwa {

// A flower: five petals, 3.2 cm across (a Somei-yoshino flower is 3-3.5 cm), lifted off its node.
constexpr float kFlowerOuterRadius_cm = 1.6f;   // petal tips
constexpr float kFlowerInnerRadius_cm = 0.64f;  // notches between the petals
constexpr float kFlowerLift_cm = 0.3f;          // offset from the node along the facing direction

// One indexed triangle list (GL/glTF ready: 32-bit indices, interleaving left to the consumer).
struct MeshBuffers {
  std::vector<float> positions;   // xyz per vertex, metres, y up
  std::vector<float> normals;     // unit xyz per vertex
  std::vector<float> uvs;         // uv per vertex
  std::vector<uint32_t> indices;  // three per triangle
  std::size_t vertex_count() const { return positions.size() / 3; }
};

// Every per-vertex id vector holds one entry per vertex of its buffer: the branch a vertex hangs on
// and which of that branch's nodes (a ring's node; a cap's tip node; the node a leaf or flower is
// attached to). core/sway/skin.h turns them into skinning joints and weights (thesis eq. 3.15).
struct TreeMesh {
  MeshBuffers bark;  // generalized cylinders, one ring per node, end caps at tips
  std::vector<uint32_t> bark_branch_id;   // branch id of each bark vertex (picking, pruning)
  std::vector<uint32_t> bark_node_index;  // node of that branch (ring or tip of the cap)
  MeshBuffers leaves;                    // one double-sided quad (two triangles each side) per leaf
  std::vector<uint32_t> leaf_branch_id;  // branch the leaf grows on
  std::vector<uint32_t> leaf_node_index;    // node of that branch the leaf sits at
  MeshBuffers flowers;                      // a small five-petal star per open flower
  std::vector<uint32_t> flower_branch_id;   // branch the flower grows on
  std::vector<uint32_t> flower_node_index;  // node of that branch the flower sits at
};

struct MeshOptions {
  int min_sides = 3;          // sides of the thinnest tube
  int max_sides = 12;         // sides of the thickest tube
  float cm_to_units = 0.01f;  // tree data are in cm; glTF wants metres
};

TreeMesh BuildTreeMesh(const Tree& tree, const MeshOptions& options = {});

}  // namespace niwa
