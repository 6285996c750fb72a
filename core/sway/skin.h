// Skinning form of the sway interpolation (thesis eq. 3.15): per-vertex joints and weights of a
// tree mesh and per-node-point poses, so that a GPU or a glTF skin reproduces the node positions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "sway/sway.h"
#include "tree/mesh.h"

namespace niwa {

// Per vertex: the node point it follows and its eq. 3.15 weight (l_jn / l_j)^α.
struct VertexSkin {
  std::vector<uint32_t> joint;  // SwayModel::nodes index
  std::vector<float> weight;    // (l_jn / l_j)^α of the vertex's node, 0 at a branch base
};

struct TreeSkin {
  VertexSkin bark, leaves, flowers;
};

// The node point and weight that a vertex hanging on node `node` of branch `branch` follows.
// Node 0 of a branch (its base ring, at the parent's node parent_node) takes the binding of that
// parent node (recursively when parent_node is 0 too), so joints stay continuous. A branch without
// a node point (dead or undrawn, or off the model) binds to node point 0 (the root shoot) with
// weight 0, i.e. it moves rigidly with the root's rod, which never moves.
struct SkinBinding {
  uint32_t joint = 0;
  float weight = 0.0f;
};
SkinBinding BindNode(const SwayModel& model, uint32_t branch, uint32_t node);

// Joints and weights of every vertex of mesh (bark, leaves, flowers) from its branch/node ids.
TreeSkin BuildTreeSkin(const TreeMesh& mesh, const SwayModel& model);

constexpr int kSwayPoseFloats = 16;

// Per node point, 16 floats in mesh units: R col0.xyz, M.x, R col1.xyz, M.y, R col2.xyz, M.z,
// T.xyz, 0. A vertex at rest position p (mesh units), normal n, joint j, weight w is drawn at
// p' = R_j p + T_j + w M_j, n' = R_j n, where R_j is the rotation of j's parent rod (eq. 3.11),
// T_j = s anchor_j - R_j (s rest_anchor_j), M_j = s (tip_j - rigid_tip_j) (eq. 3.15), s =
// cm_to_units. Fixed node points get the rest pose. out holds 16 * sim.model().nodes.size().
void WriteSwayPoses(const SwaySimulator& sim, float cm_to_units, float* out);
// The rest pose of `nodes` node points: identity R, zero T and M.
void RestSwayPoses(std::size_t nodes, float* out);

// The skin formula above for one point (p') and one direction (n'), in float as a shader does.
glm::vec3 SkinPosition(const float* poses, uint32_t joint, float weight, const glm::vec3& p);
glm::vec3 SkinNormal(const float* poses, uint32_t joint, const glm::vec3& n);

}  // namespace niwa
