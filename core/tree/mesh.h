// Triangle meshes of a grown tree: bark tubes, leaf quads and flowers, in metres, for glTF and
// WebGL.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tree/tree.h"
#include "tree/tree_look.h"

namespace niwa {

// A flower node carries a blossom cluster card: a decagon 8 cm across textured with a cluster of
// five-petal blossoms (tree_textures.h MakeBlossomClusterTexture; a Somei-yoshino umbel holds 3-5
// flowers of 3-3.5 cm), so the blossom reads from a distance; lifted off its node.
constexpr float kFlowerOuterRadius_cm = 4.0f;  // the card's reach from its centre
constexpr float kFlowerInnerRadius_cm = 4.0f;  // every outline point on the circle: a decagon
constexpr float kFlowerLift_cm = 0.3f;         // offset from the node along the facing direction

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
  MeshBuffers leaves;  // one double-sided quad (two triangles each side) per leaf: its blade, or
                       // with leaf_spray > 1 a spray card (tree_textures.h LeafCardOf)
  std::vector<uint32_t> leaf_branch_id;     // branch the leaf grows on
  std::vector<uint32_t> leaf_node_index;    // node of that branch the leaf sits at
  MeshBuffers flowers;                      // a blossom-cluster decagon per open flower
  std::vector<uint32_t> flower_branch_id;   // branch the flower grows on
  std::vector<uint32_t> flower_node_index;  // node of that branch the flower sits at
  TreeLook look;  // the leaf shape and season it was built for (tree_gltf paints its textures)
};

struct MeshOptions {
  int min_sides = 3;          // sides of the thinnest tube
  int max_sides = 12;         // sides of the thickest tube
  float cm_to_units = 0.01f;  // tree data are in cm; glTF wants metres
  // Leaf shape and season (tree/tree_look.h); empty: the tree's own leaf_shape, season and
  // autumn_colour rows. The season drops leaves (winter, a cherry's spring) and flowers.
  std::optional<TreeLook> look;
};

TreeMesh BuildTreeMesh(const Tree& tree, const MeshOptions& options = {});

}  // namespace niwa
