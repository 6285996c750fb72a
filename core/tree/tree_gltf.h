// glTF 2.0 export of a tree mesh (bark, leaves, flowers with their procedural textures) over the
// generic io/gltf_writer: binary .glb bytes in memory, static or skinned and animated (the sway
// export, core/sway/sway_gltf.h, fills GltfSkinning). Does not: simulate sway, or write files.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "io/gltf_writer.h"
#include "tree/mesh.h"

namespace niwa {

// A skeleton for WriteSkinnedTreeGlb. Every joint is a node directly under the skeleton root node
// (joints[0], identity, never animated), so a joint's local TRS is its global transform.
struct GltfJoint {
  std::string name;
  std::array<float, 3> translation{0, 0, 0};          // rest pose
  std::array<float, 3> inverse_bind_offset{0, 0, 0};  // inverse bind matrix = translate(offset)
  std::vector<float> translation_keys;                // 3 per key; empty: not animated
  std::vector<float> rotation_keys;                   // 4 per key, unit quaternion x, y, z, w
  // The keys' times (s, strictly increasing) when the joint has keys of its own (a reduced clip);
  // empty: GltfSkinning::times. Joints with equal times share one input accessor.
  std::vector<float> times;
};

constexpr std::size_t kMaxGltfJoints = 65536;  // JOINTS_0 as unsigned short: indices 0..65535

struct GltfSkinning {
  std::vector<GltfJoint> joints;                 // joints[0]: the skeleton root
  std::array<std::vector<uint16_t>, 3> joints0;  // bark, leaves, flowers: 4 per vertex
  std::array<std::vector<float>, 3> weights0;    // 4 per vertex, summing to 1
  // Extra per-vertex attributes of bark, leaves, flowers (empty, or the same names on every
  // non-empty part), written as application-specific attributes "_NAME" (the sway's wind data).
  std::array<std::vector<geom::VertexAttribute>, 3> attributes;
  std::vector<float> times;  // s, strictly increasing, one per key
  std::string clip_name = "sway";
};

// The tree's glTF document: node "tree" with mesh "tree" of one primitive per non-empty part
// (bark, leaves, flowers, in that order), each with its material ("bark", "leaves", "flowers")
// and 512 px texture (tree_textures.h: bark also has its normal map and, as extras, the mesh's look
// {leaf_shape, season, autumn_colour}; the leaf texture is the mesh's leaf shape in its season);
// with `skinning`, the skeleton nodes, skin "tree" and one clip (LINEAR translation and rotation
// channels for every joint with keys). For callers that change a material (another bark texture)
// before gltf::WriteGlb.
Result<gltf::Document> TreeGltfDocument(const TreeMesh& mesh,
                                        const GltfSkinning* skinning = nullptr);

// Fills bytes with the .glb of TreeGltfDocument (cleared on error).
Status WriteTreeGlb(const TreeMesh& mesh, std::vector<unsigned char>* bytes);

// The skeleton nodes of `skinning` (its joints; joints[0] the root, the others its children), the
// skin "tree" on node 0 (the mesh's node) and the clip, appended to `doc` (its per-part joints0,
// weights0 and attributes are not read: the caller fills its primitives). For documents of other
// meshes over a tree (render/tree_lod_sway).
void AddTreeSkinAndAnimation(const GltfSkinning& skinning, gltf::Document* doc);

// The same, skinned and animated.
Status WriteSkinnedTreeGlb(const TreeMesh& mesh, const GltfSkinning& skinning,
                           std::vector<unsigned char>* bytes);

}  // namespace niwa
