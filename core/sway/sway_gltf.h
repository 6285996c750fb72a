// Sway export: a grown tree's wind sway (thesis ch. 3) as a skinned, animated .glb (exact
// two-joint linear blend skinning form of eq. 3.15; docs/sway-model.md "Skinning and glTF export"),
// over the tree's glTF document (tree/tree_gltf.h). Does not: write files or draw.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/status.h"
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

struct SwayGlbOptions {
  double fps = 30;            // keys per second of simulated time (each at the nearest step)
  float cm_to_units = 0.01f;  // the mesh's units (metres)
};

struct SwayGlbInfo {
  std::size_t joints = 0, keys = 0, node_points = 0;
  double seconds = 0;  // time of the last key
};

// Key k is the state after step round(k / (fps dt)) (keys falling on the same step are merged),
// for k / fps <= duration. Every primitive also carries the wind attributes _WIND_LEVEL (branch
// hierarchy level), _WIND_ALONG (node / last node of the branch, 0..1) and _WIND_PHASE (per branch,
// [0, 1)) for an engine's own wind shader (docs/sway-model.md "Wind attributes"). Errors are one
// line (e.g. too many joints for JOINTS_0).
Status WriteSwayGlb(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                    std::vector<unsigned char>* bytes, SwayGlbInfo* info = nullptr);

}  // namespace niwa
