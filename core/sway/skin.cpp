// Skinning form of thesis eq. 3.15: joint/weight per mesh vertex and a pose per node point.
#include "sway/skin.h"

#include <glm/mat3x3.hpp>

namespace niwa {
namespace {

void BindBuffer(const std::vector<uint32_t>& branch, const std::vector<uint32_t>& node,
                std::size_t vertices, const SwayModel& model, VertexSkin* out) {
  out->joint.assign(vertices, 0);
  out->weight.assign(vertices, 0.0f);
  for (std::size_t v = 0; v < vertices && v < branch.size() && v < node.size(); ++v) {
    SkinBinding b = BindNode(model, branch[v], node[v]);
    out->joint[v] = b.joint;
    out->weight[v] = b.weight;
  }
}

}  // namespace

SkinBinding BindNode(const SwayModel& model, uint32_t branch, uint32_t node) {
  int i = branch < model.node_of_branch.size() ? model.node_of_branch[branch] : -1;
  if (i < 0 || model.nodes.empty()) return {};  // dead/undrawn: the root's rod, weight 0
  std::size_t k = node;
  // Node 0 sits on the parent's node parent_node (fig. 3.3): take that node's binding.
  while (k == 0 && model.nodes[static_cast<std::size_t>(i)].parent >= 0) {
    const SwayNode& s = model.nodes[static_cast<std::size_t>(i)];
    k = static_cast<std::size_t>(s.parent_node);
    i = s.parent;
  }
  const SwayNode& s = model.nodes[static_cast<std::size_t>(i)];
  if (k >= s.weight.size()) k = s.weight.empty() ? 0 : s.weight.size() - 1;
  SkinBinding out;
  out.joint = static_cast<uint32_t>(i);
  out.weight = s.weight.empty() ? 0.0f : static_cast<float>(s.weight[k]);  // eq. 3.15
  return out;
}

TreeSkin BuildTreeSkin(const TreeMesh& mesh, const SwayModel& model) {
  TreeSkin skin;
  BindBuffer(mesh.bark_branch_id, mesh.bark_node_index, mesh.bark.vertex_count(), model,
             &skin.bark);
  BindBuffer(mesh.leaf_branch_id, mesh.leaf_node_index, mesh.leaves.vertex_count(), model,
             &skin.leaves);
  BindBuffer(mesh.flower_branch_id, mesh.flower_node_index, mesh.flowers.vertex_count(), model,
             &skin.flowers);
  return skin;
}

void RestSwayPoses(std::size_t nodes, float* out) {
  for (std::size_t i = 0; i < nodes; ++i) {
    float* p = out + kSwayPoseFloats * i;
    for (int k = 0; k < kSwayPoseFloats; ++k) p[k] = 0.0f;
    p[0] = p[5] = p[10] = 1.0f;
  }
}

void WriteSwayPoses(const SwaySimulator& sim, float cm_to_units, float* out) {
  const SwayModel& model = sim.model();
  const double s = static_cast<double>(cm_to_units);
  RestSwayPoses(model.nodes.size(), out);
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const SwayNode& node = model.nodes[i];
    if (node.kind == SwayKind::kFixed) continue;  // never moves: the rest pose
    const glm::dmat3 r = sim.ParentRotation(static_cast<int>(i));
    const glm::dvec3& anchor = sim.anchors()[i];
    // P'_jn = anchor + R (rest_jn - rest_anchor) (3.3.3); P_jn = P'_jn + w M_j (eq. 3.15).
    const glm::dvec3 t = s * anchor - r * (s * node.rest_anchor);
    const glm::dvec3 rigid_tip = anchor + r * (node.rest_tip - node.rest_anchor);
    const glm::dvec3 m = s * (sim.tips()[i] - rigid_tip);
    float* p = out + kSwayPoseFloats * i;
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) p[4 * c + k] = static_cast<float>(r[c][k]);
      p[4 * c + 3] = static_cast<float>(m[c]);
      p[12 + c] = static_cast<float>(t[c]);
    }
    p[15] = 0.0f;
  }
}

glm::vec3 SkinPosition(const float* poses, uint32_t joint, float weight, const glm::vec3& p) {
  const float* q = poses + kSwayPoseFloats * static_cast<std::size_t>(joint);
  glm::vec3 out;
  for (int k = 0; k < 3; ++k) {
    out[k] = q[k] * p.x + q[4 + k] * p.y + q[8 + k] * p.z + q[12 + k] + weight * q[4 * k + 3];
  }
  return out;
}

glm::vec3 SkinNormal(const float* poses, uint32_t joint, const glm::vec3& n) {
  const float* q = poses + kSwayPoseFloats * static_cast<std::size_t>(joint);
  glm::vec3 out;
  for (int k = 0; k < 3; ++k) out[k] = q[k] * n.x + q[4 + k] * n.y + q[8 + k] * n.z;
  return out;
}

}  // namespace niwa
