// Geometry that paints the hybrid renderer's card atlas in one draw call (thesis 4.2.1: each card
// texture is the branch rendered orthographically onto its plane), and the sway skin of the cards
// and lines of a draw list.
#pragma once

#include <cstdint>
#include <vector>

#include "render/hybrid.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "tree/mesh.h"
#include "tree/tree.h"

namespace niwa {

// One part (bark, leaves or flowers) of every tile's source, already projected: positions are atlas
// clip coordinates (x, y in [-1, 1] over the whole atlas, z in [-1, 1] the depth along the plane's
// normal within the tile, nearer to the viewer = smaller), normals stay in world space so the atlas
// can be lit by the same sun as the full-polygon view.
struct AtlasMesh {
  MeshBuffers bark, leaves, flowers;
  int tiles = 0;  // tiles with at least one triangle
};

// For every (group, plane) tile: the group representative's bark (and, with LeafMode::kBranchCards,
// its leaves and flowers) seen along the plane's normal and mapped onto the tile's rectangle
// [u0, u1] x [v0, v1] -> texels [x, x + w] x [y, y + h] (the uv that BuildDrawList gives the card).
// For every (cluster, plane) tile: the leaves and flowers of the cluster's branches likewise.
// bark_uvs (u, v per bark vertex of `mesh`, as mesh.bark.uvs), when given, are the bark's texture
// coordinates instead of mesh.bark.uvs: a simulated bark's tile wrapped around every tube
// (compose/bark_on_tree WrapBarkUvs), so the cards wear the bark the full view wears.
AtlasMesh BuildAtlasMesh(const TreeMesh& mesh, const HybridScene& scene,
                         const std::vector<float>* bark_uvs = nullptr);

// Sway skin of a draw list (core/sway/skin.h): per card vertex and per line endpoint the node point
// and eq. 3.15 weight it follows. A branch card's base corners follow the branch's base (its
// parent's node), its top corners the branch's tip (its own node point, weight 1); a line's
// endpoints follow the nodes they sit on; a leaf-cluster card follows the tip of its first branch.
struct DrawListSkin {
  VertexSkin cards;  // 4 per card
  VertexSkin lines;  // 2 per segment
};
DrawListSkin BuildDrawListSkin(const Tree& tree, const HybridScene& scene,
                               const HybridDrawList& list, const SwayModel& model);

}  // namespace niwa
