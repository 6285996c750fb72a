// Sway export: a grown tree's wind sway (thesis ch. 3) as a skinned, animated .glb (exact
// two-joint linear blend skinning form of eq. 3.15; docs/sway-model.md "Skinning and glTF export"),
// over the tree's glTF document (tree/tree_gltf.h). Does not: write files or draw.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/status.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "tree/tree_gltf.h"

namespace niwa {

// Joints of a sway model: joint 0 is the skeleton root (shared by fixed node points); a moving
// node point j has a base joint (translate(s anchor_j) R_j) and a tip joint (translate(s anchor_j +
// M_j) R_j), a follower only a base joint, both with inverse bind translate(-s rest_anchor_j).
struct SwayJoints {
  std::vector<int> base;  // per node point: its base joint (0 for a fixed one)
  std::vector<int> tip;   // per node point: its tip joint, -1 unless moving
  std::size_t count = 1;  // joints in all, the root included
};
SwayJoints MapSwayJoints(const SwayModel& model);

// Joints of the skin by default, the root included (issue 32: engines cap a skin's joints; Unity
// and Godot draw 128-joint skins on every platform).
inline constexpr std::size_t kDefaultSwayJoints = 128;

// Key reduction's bound by default, metres (SwayGlbOptions::key_error).
inline constexpr double kDefaultSwayKeyError = 0.002;

struct SwayGlbOptions {
  double fps = 30;            // keys per second of simulated time (each at the nearest step)
  float cm_to_units = 0.01f;  // the mesh's units (metres)
  // The most joints of the skin, the root included, in [2, kMaxGltfJoints]. The exact skin (1 + 2
  // per moving node point + 1 per follower) is written when it fits; else the clustered one.
  std::size_t max_joints = kDefaultSwayJoints;
  // Key reduction (docs/sway-model.md "Clip keys"): a joint's key is left out when the glTF
  // LINEAR interpolation (lerp, slerp) of its neighbours kept puts every vertex it moves within
  // this many metres of where the key puts it (a bound: |dT| + 2 sin(phi / 2) reach, phi the
  // rotation's error, reach the farthest vertex from the joint); 0 keeps every key.
  double key_error = kDefaultSwayKeyError;
};

struct SwayGlbInfo {
  std::size_t joints = 0, keys = 0, node_points = 0;
  std::size_t exact_joints = 0;  // what the exact skin would need
  double seconds = 0;            // time of the last key
  bool clustered = false;
  // Clustered skins only (0 for the exact one): how far the skinned nodes lie from the simulator's
  // (eq. 3.15), metres, over every node of every node point at every key (the largest and the
  // mean), and the largest distance a node moved from rest, for scale.
  double max_error = 0, mean_error = 0, max_motion = 0;
  // Key reduction: keys written over every animated joint, of keys x animated joints before, and
  // the largest vertex error bound of a left-out key (<= key_error), metres.
  std::size_t joint_keys = 0, full_joint_keys = 0;
  double key_error = 0;
};

// The clustered skin (docs/sway-model.md "Joint budget"): each representative node point's whole
// group turns rigidly with its rod (one joint: translate(s anchor_r) R_r with inverse bind
// translate(-s rest_anchor_r), R_r = SwaySimulator::RodRotation), and every node point follows its
// nearest representative at or above it, or the static root when it has none.
struct SwayClusters {
  std::vector<int> rep;   // per node point: the representative it follows, -1: the root
  std::vector<int> reps;  // the representatives in the order chosen: joint k + 1 is reps[k]
};

// Chooses at most `groups` representatives greedily: at each pick, the node point whose tip lies
// farthest from where its group's rigid turn puts it (the largest over `samples` evenly spaced
// steps of the run), times the vertices (`vertices`, one count a node point) that would follow it.
// Deterministic (ties to the lower index).
SwayClusters ClusterSwayNodePoints(const Tree& tree, const SwayParams& params,
                                   const std::vector<double>& vertices, std::size_t groups,
                                   int samples = 32);

// Key k is the state after step round(k / (fps dt)) (keys falling on the same step are merged),
// for k / fps <= duration. The skin is exact when it fits options.max_joints, else clustered
// (SwayClusters). Every primitive also carries the wind attributes _WIND_LEVEL (branch
// hierarchy level), _WIND_ALONG (node / last node of the branch, 0..1) and _WIND_PHASE (per branch,
// [0, 1)) for an engine's own wind shader (docs/sway-model.md "Wind attributes"). Errors are one
// line (e.g. too many joints for JOINTS_0).
// One part of a mesh to skin: each vertex's node point and eq. 3.15 weight (sway/skin.h) and its
// rest position (xyz a vertex, mesh units).
struct SwaySkinPart {
  const VertexSkin* skin = nullptr;
  const std::vector<float>* positions = nullptr;
};

// The skin of any parts (WriteSwayGlb's bark, leaves, flowers; the budgeted mesh's cards and
// twigs too, render/tree_lod_sway): the joints with their (reduced) keys, JOINTS_0 and WEIGHTS_0
// per part, and the times of the unreduced keys (joints with times of their own use those).
struct SwaySkin {
  std::vector<GltfJoint> joints;
  std::vector<float> times;
  std::vector<std::vector<uint16_t>> joints0;
  std::vector<std::vector<float>> weights0;
};

// WriteSwayGlb's skin and clip over `parts` (exact when it fits options.max_joints, else
// clustered, the vertices counted over every part), keys reduced by options.key_error.
Status BuildSwaySkin(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                     const std::vector<SwaySkinPart>& parts, SwaySkin* out, SwayGlbInfo* info);

Status WriteSwayGlb(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                    std::vector<unsigned char>* bytes, SwayGlbInfo* info = nullptr);

}  // namespace niwa
