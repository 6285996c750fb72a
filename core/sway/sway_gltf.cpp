// Sway export: skinned .glb of the node-point sway (thesis eq. 3.15 as two-joint skinning).
#include "sway/sway_gltf.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "sway/skin.h"
#include "tree/mesh.h"

namespace niwa {
namespace {

std::array<float, 3> ToArray(const glm::dvec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

// Per vertex of one buffer: JOINTS_0 and WEIGHTS_0 from the eq. 3.15 binding. A moving node
// point's vertex blends base (1 - w) and tip (w): R p + T + w M exactly (docs/sway-model.md).
void VertexJoints(const VertexSkin& skin, const SwayJoints& joints, std::vector<uint16_t>* j0,
                  std::vector<float>* w0) {
  j0->assign(4 * skin.joint.size(), 0);
  w0->assign(4 * skin.joint.size(), 0.0f);
  for (std::size_t v = 0; v < skin.joint.size(); ++v) {
    const std::size_t i = skin.joint[v];
    const float w = skin.weight[v];
    const int tip = joints.tip[i];
    // Only joints of non-zero weight are listed (unused slots: joint 0, weight 0).
    const int used[2] = {tip >= 0 && w == 1.0f ? -1 : joints.base[i], tip >= 0 && w > 0 ? tip : -1};
    const float weight[2] = {tip >= 0 ? 1.0f - w : 1.0f, w};
    std::size_t slot = 4 * v;
    for (int k = 0; k < 2; ++k) {
      if (used[k] < 0) continue;
      (*j0)[slot] = static_cast<uint16_t>(used[k]);
      (*w0)[slot++] = weight[k];
    }
  }
}

}  // namespace

SwayJoints MapSwayJoints(const SwayModel& model) {
  SwayJoints joints;
  joints.base.assign(model.nodes.size(), 0);
  joints.tip.assign(model.nodes.size(), -1);
  joints.count = 1;
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const SwayKind kind = model.nodes[i].kind;
    if (kind == SwayKind::kFixed) continue;
    joints.base[i] = static_cast<int>(joints.count++);
    if (kind == SwayKind::kMoving) joints.tip[i] = static_cast<int>(joints.count++);
  }
  return joints;
}

Status WriteSwayGlb(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                    std::vector<unsigned char>* bytes, SwayGlbInfo* info) {
  if (bytes == nullptr) return Status::Error("glb", "no output buffer");
  bytes->clear();
  if (!(options.fps > 0) || !std::isfinite(options.fps)) {
    return Status::Error("fps", "must be a positive number");
  }
  SwaySimulator sim(tree, params);
  const SwayModel& model = sim.model();
  const SwayJoints joints = MapSwayJoints(model);
  if (info != nullptr) {
    info->joints = joints.count;
    info->node_points = model.nodes.size();
  }
  if (joints.count > kMaxGltfJoints) {
    return Status::Error("", "the sway needs " + std::to_string(joints.count) +
                                 " joints (1 root + 2 per moving and 1 per follower node point) "
                                 "but JOINTS_0 (unsigned short) indexes at most 65536; grow "
                                 "fewer years");
  }
  MeshOptions mesh_options;
  mesh_options.cm_to_units = options.cm_to_units;
  const TreeMesh mesh = BuildTreeMesh(tree, mesh_options);
  const TreeSkin skin = BuildTreeSkin(mesh, model);

  GltfSkinning out;
  out.joints.resize(joints.count);
  out.joints[0].name = "root";
  const double s = static_cast<double>(options.cm_to_units);
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const SwayNode& node = model.nodes[i];
    const std::string name = "b" + std::to_string(node.branch);
    for (int j : {joints.base[i], joints.tip[i]}) {
      if (j <= 0) continue;
      GltfJoint& joint = out.joints[static_cast<std::size_t>(j)];
      joint.name = name + (j == joints.base[i] ? "_base" : "_tip");
      joint.translation = ToArray(s * node.rest_anchor);
      joint.inverse_bind_offset = ToArray(-s * node.rest_anchor);
    }
  }
  const VertexSkin* parts[3] = {&skin.bark, &skin.leaves, &skin.flowers};
  for (std::size_t k = 0; k < 3; ++k) {
    VertexJoints(*parts[k], joints, &out.joints0[k], &out.weights0[k]);
  }

  // Keys: k / fps <= duration, each at its nearest step (merged when two fall on one step).
  const double dt = params.dt;
  const long steps = static_cast<long>(std::floor(params.duration / dt + 0.5));
  std::vector<long> key_steps;
  for (long k = 0;; ++k) {
    double t = static_cast<double>(k) / options.fps;
    if (t > params.duration + 1e-9) break;
    long step = std::min(steps, static_cast<long>(std::floor(t / dt + 0.5)));
    if (key_steps.empty() || step > key_steps.back()) key_steps.push_back(step);
  }
  std::vector<glm::dquat> last(model.nodes.size(), glm::dquat(1, 0, 0, 0));
  for (long step : key_steps) {
    while (sim.steps() < step) sim.Step();
    out.times.push_back(static_cast<float>(sim.time()));
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      if (joints.base[i] <= 0) continue;
      const SwayNode& node = model.nodes[i];
      const glm::dmat3 r = sim.ParentRotation(static_cast<int>(i));  // eq. 3.11
      glm::dquat q = glm::normalize(glm::quat_cast(r));
      if (glm::dot(q, last[i]) < 0) q = -q;  // shortest path between keys
      last[i] = q;
      const glm::dvec3 anchor = s * sim.anchors()[i];
      // M_j = P_j(t) - P'_j (eq. 3.15), P'_j the rest tip turned with the parent's rod.
      const glm::dvec3 rigid_tip = sim.anchors()[i] + r * (node.rest_tip - node.rest_anchor);
      const glm::dvec3 m = s * (sim.tips()[i] - rigid_tip);
      for (int j : {joints.base[i], joints.tip[i]}) {
        if (j <= 0) continue;
        GltfJoint& joint = out.joints[static_cast<std::size_t>(j)];
        std::array<float, 3> t = ToArray(j == joints.base[i] ? anchor : anchor + m);
        joint.translation_keys.insert(joint.translation_keys.end(), t.begin(), t.end());
        joint.rotation_keys.insert(joint.rotation_keys.end(),
                                   {static_cast<float>(q.x), static_cast<float>(q.y),
                                    static_cast<float>(q.z), static_cast<float>(q.w)});
      }
    }
  }
  if (info != nullptr) {
    info->keys = out.times.size();
    info->seconds = out.times.empty() ? 0.0 : static_cast<double>(out.times.back());
  }
  return WriteSkinnedTreeGlb(mesh, out, bytes);
}

}  // namespace niwa
