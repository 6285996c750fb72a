// Sway export: skinned .glb of the node-point sway (thesis eq. 3.15 as two-joint skinning).
#include "sway/sway_gltf.h"

#include <algorithm>
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

// Hierarchy level of every branch: 0 for a shoot without a parent, its parent's + 1 otherwise.
std::vector<int> BranchLevels(const Tree& tree) {
  std::vector<int> level(tree.branches.size(), -1);
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    // Walk up to a branch whose level is known (or the root), then fill the path down.
    std::vector<std::size_t> path;
    std::size_t b = i;
    while (level[b] < 0) {
      path.push_back(b);
      const int parent = tree.branches[b].parent;
      if (parent < 0 || static_cast<std::size_t>(parent) >= tree.branches.size()) break;
      b = static_cast<std::size_t>(parent);
    }
    int at = level[b] >= 0 ? level[b] + 1 : 0;
    for (std::size_t k = path.size(); k-- > 0;) level[path[k]] = at++;
  }
  return level;
}

// A branch's wind phase in [0, 1): its id through a multiplicative hash (Knuth's 2654435761),
// the top 24 bits, so neighbours sway out of step (same bits natively and in WASM).
float WindPhase(uint32_t branch) {
  const uint32_t h = branch * 2654435761u;
  return static_cast<float>(h >> 8) / 16777216.0f;
}

// The wind data of one part's vertices (docs/sway-model.md "Wind attributes"): wind_level, the
// branch's hierarchy level; wind_along, the vertex's node along its branch over the branch's
// last node (0 at the base, 1 at the tip); wind_phase, the branch's phase.
std::vector<geom::VertexAttribute> WindAttributes(const Tree& tree, const std::vector<int>& levels,
                                                  const std::vector<uint32_t>& branch_id,
                                                  const std::vector<uint32_t>& node_index) {
  std::vector<geom::VertexAttribute> out(3);
  out[0].name = "wind_level";
  out[1].name = "wind_along";
  out[2].name = "wind_phase";
  for (std::size_t v = 0; v < branch_id.size(); ++v) {
    const uint32_t b = branch_id[v];
    float level = 0, along = 0;
    if (b < tree.branches.size()) {
      level = static_cast<float>(levels[b]);
      const std::size_t nodes = tree.branches[b].nodes.size();
      if (nodes >= 2) {
        const std::size_t last = nodes - 1;
        along = std::min(1.0f, static_cast<float>(node_index[v]) / static_cast<float>(last));
      }
    }
    out[0].values.push_back(level);
    out[1].values.push_back(along);
    out[2].values.push_back(WindPhase(b));
  }
  return out;
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
  const std::vector<int> levels = BranchLevels(tree);
  out.attributes[0] = WindAttributes(tree, levels, mesh.bark_branch_id, mesh.bark_node_index);
  out.attributes[1] = WindAttributes(tree, levels, mesh.leaf_branch_id, mesh.leaf_node_index);
  out.attributes[2] = WindAttributes(tree, levels, mesh.flower_branch_id, mesh.flower_node_index);

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
