// glTF 2.0 export of a tree mesh with tinygltf: binary .glb bytes in memory, static or skinned
// and animated (the sway export, core/io/gltf_sway.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tree/mesh.h"

namespace niwa {

// Fills bytes with a complete .glb (bark, leaves, flowers, each with its material). Returns "" or
// one error line.
std::string WriteGlb(const TreeMesh& mesh, std::vector<unsigned char>* bytes);

// A skeleton for WriteSkinnedGlb. Every joint is a node directly under the skeleton root node
// (joints[0], identity, never animated), so a joint's local TRS is its global transform.
struct GltfJoint {
  std::string name;
  std::array<float, 3> translation{0, 0, 0};          // rest pose
  std::array<float, 3> inverse_bind_offset{0, 0, 0};  // inverse bind matrix = translate(offset)
  std::vector<float> translation_keys;                // 3 per key; empty: not animated
  std::vector<float> rotation_keys;                   // 4 per key, unit quaternion x, y, z, w
};

constexpr std::size_t kMaxGltfJoints = 65536;  // JOINTS_0 as unsigned short: indices 0..65535

struct GltfSkinning {
  std::vector<GltfJoint> joints;                 // joints[0]: the skeleton root
  std::array<std::vector<uint16_t>, 3> joints0;  // bark, leaves, flowers: 4 per vertex
  std::array<std::vector<float>, 3> weights0;    // 4 per vertex, summing to 1
  std::vector<float> times;                      // s, strictly increasing, one per key
  std::string clip_name = "sway";
};

// The .glb of WriteGlb as a skinned mesh with one animation clip (LINEAR translation and rotation
// channels for every joint with keys). Returns "" or one error line.
std::string WriteSkinnedGlb(const TreeMesh& mesh, const GltfSkinning& skinning,
                            std::vector<unsigned char>* bytes);

}  // namespace niwa
