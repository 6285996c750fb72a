// The sway .glb on a triangle-budgeted mesh (issue 32 item 2): the skin and clip of
// sway/sway_gltf over render/tree_lod's level (tubes, branch cards, twig cones, leaf-cluster
// cards), so a grown tree's animated export stays a game asset's size. Does not: simulate anything
// of its own, choose the level (BuildLodMesh does), or write files.
#pragma once

#include <vector>

#include "base/status.h"
#include "render/tree_lod.h"
#include "sway/sway_gltf.h"

namespace niwa {

// Triangles of the sway .glb's mesh by default: a tree whose full mesh is larger is skinned on
// its BuildLodMesh level within this many (a 15-year sakura: 386,300 -> 17,478), the budget
// .glb of docs/lod-export.md with the skin and clip on top.
inline constexpr long kDefaultSwayTriangles = 20000;
// The card atlas side of the sway .glb's level (texels): half the budget .glb's 2048. With the
// species' leaf sprays (tree mesh row leaf_spray) the leaf-cluster cards fill a 2048² atlas with
// leaves, 8.4 MB of PNG for a 15-year sakura, which puts its sway .glb at 12 MB against issue 32's
// 8 MB; at 1024² the atlas is about a quarter of that (docs/lod-export.md "The sway .glb").
inline constexpr int kSwayAtlasSize = 1024;

// WriteSwayGlb when max_triangles < 0 or the full mesh fits (the same bytes); else one node
// "tree" of BuildLodMesh(tree, max_triangles)'s level at kSwayAtlasSize (LodGltfDocument: its
// materials, atlas and wind attributes), every primitive skinned by BuildSwaySkin: tubes, leaves
// and flowers through their branch and node as the full mesh, branch cards and twig cones through
// the node nearest each vertex along their branch, leaf-cluster cards through their leafiest
// branch's tip (LodMesh's card and twig ids). `choice` (optional) gets the level's choice. Errors
// name `field` for a budget the tree cannot fit, else as WriteSwayGlb's.
Status WriteLodSwayGlb(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                       long max_triangles, std::vector<unsigned char>* bytes,
                       SwayGlbInfo* info = nullptr, LodChoice* choice = nullptr,
                       const std::string& field = "max_triangles");

}  // namespace niwa
