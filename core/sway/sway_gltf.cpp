// Sway export: skinned .glb of the node-point sway (thesis eq. 3.15 as two-joint skinning).
#include "sway/sway_gltf.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <queue>

#include "math/det_math.h"
#include "sway/skin.h"
#include "sway/wind_attributes.h"
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

// The steps of the clip's keys: key k at the step nearest k / fps, for k / fps <= duration (keys
// falling on one step merged).
std::vector<long> KeySteps(const SwayParams& params, double fps) {
  const double dt = params.dt;
  const long steps = static_cast<long>(std::floor(params.duration / dt + 0.5));
  std::vector<long> key_steps;
  for (long k = 0;; ++k) {
    double t = static_cast<double>(k) / fps;
    if (t > params.duration + 1e-9) break;
    long step = std::min(steps, static_cast<long>(std::floor(t / dt + 0.5)));
    if (key_steps.empty() || step > key_steps.back()) key_steps.push_back(step);
  }
  return key_steps;
}

// Where a rest point of node point `r`'s group is drawn when the group turns rigidly with r's rod
// (anchor, tip: r's now; the rod is rigid, so its direction is (tip - anchor) / l_r); the rest
// point itself for the root's group (r < 0).
glm::dvec3 GroupPlace(const SwayModel& model, int r, const glm::dvec3& anchor,
                      const glm::dvec3& tip, const glm::dvec3& rest_point) {
  if (r < 0) return rest_point;
  const SwayNode& rod = model.nodes[static_cast<std::size_t>(r)];
  const glm::dvec3 along = tip - anchor;
  const double length = glm::length(along);
  const glm::dvec3 dir = length > 1e-12 ? along / length : rod.rest_dir;
  return anchor + RotateMinimal(rod.rest_dir, dir, rest_point - rod.rest_anchor);
}

// A candidate of the greedy pick: larger gain first, then the lower node point.
struct Pick {
  double gain;
  int node;
  unsigned version;
  bool operator<(const Pick& o) const {
    return gain != o.gain ? gain < o.gain
                          : node > o.node;  // std::priority_queue: the largest on top
  }
};

}  // namespace

SwayClusters ClusterSwayNodePoints(const Tree& tree, const SwayParams& params,
                                   const std::vector<double>& vertices, std::size_t groups,
                                   int samples) {
  SwaySimulator sim(tree, params);
  const SwayModel& model = sim.model();
  const std::size_t n = model.nodes.size();
  SwayClusters c;
  c.rep.assign(n, -1);
  if (n == 0 || groups == 0) return c;
  // The run at evenly spaced steps (whole steps, the first and the last included).
  const long steps = static_cast<long>(std::floor(params.duration / params.dt + 0.5));
  const long count = std::max(1L, std::min(static_cast<long>(std::max(samples, 1)), steps + 1));
  std::vector<std::vector<glm::dvec3>> anchor, tip;
  for (long k = 0; k < count; ++k) {
    const long step = count == 1 ? steps : k * steps / (count - 1);
    if (k > 0 && step == static_cast<long>(sim.steps())) continue;
    while (sim.steps() < step) sim.Step();
    anchor.push_back(sim.anchors());
    tip.push_back(sim.tips());
  }
  // A node point's distance from where its group puts its tip, the largest over the samples.
  auto error = [&](std::size_t j) {
    double worst = 0;
    const int r = c.rep[j];
    const glm::dvec3& rest_tip = model.nodes[j].rest_tip;
    for (std::size_t k = 0; k < tip.size(); ++k) {
      const std::size_t u = static_cast<std::size_t>(std::max(r, 0));
      const glm::dvec3 place = GroupPlace(model, r, anchor[k][u], tip[k][u], rest_tip);
      worst = std::max(worst, glm::length(tip[k][j] - place));
    }
    return worst;
  };
  std::vector<std::vector<int>> children(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int p = model.nodes[i].parent;
    if (p >= 0) children[static_cast<std::size_t>(p)].push_back(static_cast<int>(i));
  }
  // share[j]: the vertices of j's subtree that follow j's group (they would follow j).
  std::vector<double> err(n), share(n);
  for (std::size_t i = n; i-- > 0;) {
    err[i] = model.nodes[i].kind == SwayKind::kFixed ? 0.0 : error(i);
    share[i] = i < vertices.size() ? vertices[i] : 0.0;
    for (int ch : children[i]) share[i] += share[static_cast<std::size_t>(ch)];
  }
  std::vector<unsigned> version(n, 0);
  std::priority_queue<Pick> picks;
  for (std::size_t i = 0; i < n; ++i) {
    if (err[i] * share[i] > 0) picks.push({err[i] * share[i], static_cast<int>(i), 0});
  }
  std::vector<char> is_rep(n, 0);
  while (c.reps.size() < groups && !picks.empty()) {
    const Pick top = picks.top();
    picks.pop();
    const std::size_t j = static_cast<std::size_t>(top.node);
    if (top.version != version[j] || is_rep[j]) continue;
    const int old = c.rep[j];
    const double moved = share[j];
    is_rep[j] = 1;
    c.reps.push_back(top.node);
    // j's subtree down to the next representatives now follows j.
    std::vector<int> stack = {top.node};
    while (!stack.empty()) {
      const std::size_t u = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      c.rep[u] = top.node;
      err[u] = u == j || model.nodes[u].kind == SwayKind::kFixed ? 0.0 : error(u);
      ++version[u];
      if (u != j && err[u] * share[u] > 0)
        picks.push({err[u] * share[u], static_cast<int>(u), version[u]});
      for (int ch : children[u]) {
        if (!is_rep[static_cast<std::size_t>(ch)]) stack.push_back(ch);
      }
    }
    // Its ancestors in the old group lose those vertices.
    for (int a = model.nodes[j].parent; a >= 0 && c.rep[static_cast<std::size_t>(a)] == old;
         a = model.nodes[static_cast<std::size_t>(a)].parent) {
      const std::size_t u = static_cast<std::size_t>(a);
      share[u] -= moved;
      ++version[u];
      if (!is_rep[u] && err[u] * share[u] > 0) picks.push({err[u] * share[u], a, version[u]});
    }
  }
  return c;
}

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

namespace {

// The exact two-joint skin of eq. 3.15 (MapSwayJoints) and the clip's keys.
void ExactSkin(SwaySimulator& sim, const SwayParams& params, const SwayGlbOptions& options,
               const SwayJoints& joints, const std::vector<SwaySkinPart>& parts,
               SwaySkin* out_skin) {
  SwaySkin& out = *out_skin;
  const SwayModel& model = sim.model();
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
  out.joints0.resize(parts.size());
  out.weights0.resize(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    VertexJoints(*parts[k].skin, joints, &out.joints0[k], &out.weights0[k]);
  }
  std::vector<glm::dquat> last(model.nodes.size(), glm::dquat(1, 0, 0, 0));
  for (long step : KeySteps(params, options.fps)) {
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
}

}  // namespace

namespace {

// The clustered skin of WriteSwayGlb (SwayClusters): one joint a representative, every vertex on
// its node point's group with weight 1, and the clip's keys; the errors against eq. 3.15 into info.
// `sim` is WriteSwayGlb's simulator, not yet stepped.
void ClusteredSkin(SwaySimulator& sim, const Tree& tree, const SwayParams& params,
                   const SwayGlbOptions& options, const std::vector<SwaySkinPart>& parts,
                   SwaySkin* out, SwayGlbInfo* info, std::vector<int>* joint_of_node) {
  const SwayModel& model = sim.model();
  const std::size_t n = model.nodes.size();
  std::vector<double> vertices(n, 0.0);
  for (const SwaySkinPart& part : parts) {
    for (uint32_t j : part.skin->joint) vertices[j] += 1.0;
  }
  const SwayClusters clusters =
      ClusterSwayNodePoints(tree, params, vertices, options.max_joints - 1);
  std::vector<int> joint_of(n, 0);
  out->joints.resize(1 + clusters.reps.size());
  out->joints[0].name = "root";
  const double s = static_cast<double>(options.cm_to_units);
  for (std::size_t k = 0; k < clusters.reps.size(); ++k) {
    const SwayNode& node = model.nodes[static_cast<std::size_t>(clusters.reps[k])];
    joint_of[static_cast<std::size_t>(clusters.reps[k])] = static_cast<int>(k + 1);
    GltfJoint& joint = out->joints[k + 1];
    joint.name = "b" + std::to_string(node.branch);
    joint.translation = ToArray(s * node.rest_anchor);
    joint.inverse_bind_offset = ToArray(-s * node.rest_anchor);
  }
  out->joints0.resize(parts.size());
  out->weights0.resize(parts.size());
  joint_of_node->assign(n, 0);
  for (std::size_t u = 0; u < n; ++u) {
    const int r = clusters.rep[u];
    (*joint_of_node)[u] = r < 0 ? 0 : joint_of[static_cast<std::size_t>(r)];
  }
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const VertexSkin& part = *parts[k].skin;
    out->joints0[k].assign(4 * part.joint.size(), 0);
    out->weights0[k].assign(4 * part.joint.size(), 0.0f);
    for (std::size_t v = 0; v < part.joint.size(); ++v) {
      out->joints0[k][4 * v] = static_cast<uint16_t>((*joint_of_node)[part.joint[v]]);
      out->weights0[k][4 * v] = 1.0f;
    }
  }
  std::vector<glm::dquat> last(clusters.reps.size(), glm::dquat(1, 0, 0, 0));
  std::vector<glm::dvec3> exact;
  double error_sum = 0;
  long error_count = 0;
  for (long step : KeySteps(params, options.fps)) {
    while (sim.steps() < step) sim.Step();
    out->times.push_back(static_cast<float>(sim.time()));
    for (std::size_t k = 0; k < clusters.reps.size(); ++k) {
      const int r = clusters.reps[k];
      glm::dquat q = glm::normalize(glm::quat_cast(sim.RodRotation(r)));
      if (glm::dot(q, last[k]) < 0) q = -q;  // shortest path between keys
      last[k] = q;
      GltfJoint& joint = out->joints[k + 1];
      const std::array<float, 3> t = ToArray(s * sim.anchors()[static_cast<std::size_t>(r)]);
      joint.translation_keys.insert(joint.translation_keys.end(), t.begin(), t.end());
      joint.rotation_keys.insert(joint.rotation_keys.end(),
                                 {static_cast<float>(q.x), static_cast<float>(q.y),
                                  static_cast<float>(q.z), static_cast<float>(q.w)});
    }
    // Every node of every node point: the skin's place against eq. 3.15's.
    sim.NodePositions(&exact);
    std::size_t at = 0;
    for (std::size_t u = 0; u < n; ++u) {
      const SwayNode& node = model.nodes[u];
      const int r = clusters.rep[u];
      const std::size_t g = static_cast<std::size_t>(std::max(r, 0));
      for (const glm::dvec3& rest : node.rest_nodes) {
        const glm::dvec3 place = GroupPlace(model, r, sim.anchors()[g], sim.tips()[g], rest);
        const double e = s * glm::length(exact[at] - place);
        info->max_error = std::max(info->max_error, e);
        info->max_motion = std::max(info->max_motion, s * glm::length(exact[at] - rest));
        error_sum += e;
        ++error_count;
        ++at;
      }
    }
  }
  info->mean_error = error_count > 0 ? error_sum / static_cast<double>(error_count) : 0.0;
}

}  // namespace

namespace {

// glTF's LINEAR rotation between two keys (spec 3.11: slerp; the keys already take the shorter
// arc), in det math so both builds agree.
glm::dquat SlerpKeys(const glm::dquat& a, const glm::dquat& b, double u) {
  const double c = glm::dot(a, b);
  double wa = 1.0 - u, wb = u;
  if (c < 0.9999999) {
    const double theta = det::Acos(std::max(-1.0, c));
    const double s = det::Sin(theta);
    wa = det::Sin((1.0 - u) * theta) / s;
    wb = det::Sin(u * theta) / s;
  }
  return glm::normalize(glm::dquat(wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y,
                                   wa * a.z + wb * b.z));
}

// Leaves out the keys of one unit (joints sharing one rotation: a node point's base and tip, or a
// group's joint) that the interpolation of the kept ones reproduces within `tolerance` metres at
// every vertex: the error bound at key k between kept keys a and b is the largest translation
// miss over the unit's joints plus 2 sin(phi / 2) reach (phi the angle between the slerped and
// the true rotation, reach the farthest vertex from the joint). Greedy: from a kept key, the
// farthest next key whose span fits. Joints whose keys all stay keep the shared times; `worst`
// takes the largest bound of a left-out key.
void ReduceUnitKeys(const std::vector<float>& times, const std::vector<int>& unit, double reach,
                    double tolerance, std::vector<GltfJoint>* joints, double* worst) {
  const std::size_t n = times.size();
  if (!(tolerance > 0) || n < 3 || unit.empty()) return;
  const GltfJoint& first = (*joints)[static_cast<std::size_t>(unit[0])];
  if (first.rotation_keys.size() != 4 * n) return;
  auto rotation = [&](std::size_t k) {
    const float* q = &first.rotation_keys[4 * k];
    return glm::normalize(glm::dquat(q[3], q[0], q[1], q[2]));
  };
  auto translation = [&](int j, std::size_t k) {
    const float* t = &(*joints)[static_cast<std::size_t>(j)].translation_keys[3 * k];
    return glm::dvec3(t[0], t[1], t[2]);
  };
  // The largest error bound of the keys strictly between a and b.
  auto span_error = [&](std::size_t a, std::size_t b) {
    double e_max = 0;
    const double ta = times[a], tb = times[b];
    const glm::dquat qa = rotation(a), qb = rotation(b);
    for (std::size_t k = a + 1; k < b; ++k) {
      const double u = (static_cast<double>(times[k]) - ta) / (tb - ta);
      double e = 0;
      for (int j : unit) {
        const glm::dvec3 t = translation(j, a) + u * (translation(j, b) - translation(j, a));
        e = std::max(e, glm::length(t - translation(j, k)));
      }
      const double c = std::min(1.0, std::fabs(glm::dot(SlerpKeys(qa, qb, u), rotation(k))));
      e += 2.0 * std::sqrt(std::max(0.0, 1.0 - c * c)) * reach;
      e_max = std::max(e_max, e);
      if (e_max > tolerance) break;
    }
    return e_max;
  };
  std::vector<std::size_t> kept = {0};
  double unit_worst = 0;
  for (std::size_t a = 0; a + 1 < n;) {
    std::size_t b = a + 1;
    double e_b = 0;
    while (b + 1 < n) {
      const double e = span_error(a, b + 1);
      if (e > tolerance) break;
      ++b;
      e_b = e;
    }
    unit_worst = std::max(unit_worst, e_b);
    kept.push_back(b);
    a = b;
  }
  if (kept.size() == n) return;
  *worst = std::max(*worst, unit_worst);
  std::vector<float> kept_times;
  for (std::size_t k : kept) kept_times.push_back(times[k]);
  for (int j : unit) {
    GltfJoint& joint = (*joints)[static_cast<std::size_t>(j)];
    std::vector<float> t, r;
    for (std::size_t k : kept) {
      t.insert(t.end(), joint.translation_keys.begin() + static_cast<long>(3 * k),
               joint.translation_keys.begin() + static_cast<long>(3 * k + 3));
      r.insert(r.end(), joint.rotation_keys.begin() + static_cast<long>(4 * k),
               joint.rotation_keys.begin() + static_cast<long>(4 * k + 4));
    }
    joint.translation_keys = std::move(t);
    joint.rotation_keys = std::move(r);
    joint.times = kept_times;
  }
}

}  // namespace

Status BuildSwaySkin(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                     const std::vector<SwaySkinPart>& parts, SwaySkin* out, SwayGlbInfo* info) {
  if (!(options.fps > 0) || !std::isfinite(options.fps)) {
    return Status::Error("fps", "must be a positive number");
  }
  if (options.max_joints < 2 || options.max_joints > kMaxGltfJoints) {
    return Status::Error("max_joints", std::to_string(options.max_joints) +
                                           " is out of range; must be a whole number in [2, " +
                                           std::to_string(kMaxGltfJoints) + "]");
  }
  if (!(options.key_error >= 0) || !std::isfinite(options.key_error)) {
    return Status::Error("key_error", "must be a number >= 0");
  }
  SwayGlbInfo local;
  if (info == nullptr) info = &local;
  *info = SwayGlbInfo{};
  *out = SwaySkin{};
  SwaySimulator sim(tree, params);
  const SwayModel& model = sim.model();
  const SwayJoints joints = MapSwayJoints(model);
  info->exact_joints = joints.count;
  info->node_points = model.nodes.size();
  // Key units: joints that share a rotation (a node point's base and tip) are reduced together.
  std::vector<std::vector<int>> units;
  std::vector<int> unit_of_node(model.nodes.size(), -1);
  if (joints.count > options.max_joints) {
    info->clustered = true;
    std::vector<int> joint_of_node;
    ClusteredSkin(sim, tree, params, options, parts, out, info, &joint_of_node);
    for (std::size_t j = 1; j < out->joints.size(); ++j) units.push_back({static_cast<int>(j)});
    for (std::size_t u = 0; u < model.nodes.size(); ++u) unit_of_node[u] = joint_of_node[u] - 1;
  } else {
    ExactSkin(sim, params, options, joints, parts, out);
    for (std::size_t u = 0; u < model.nodes.size(); ++u) {
      if (joints.base[u] <= 0) continue;
      unit_of_node[u] = static_cast<int>(units.size());
      units.push_back({joints.base[u]});
      if (joints.tip[u] >= 0) units.back().push_back(joints.tip[u]);
    }
  }
  info->joints = out->joints.size();
  info->keys = out->times.size();
  info->seconds = out->times.empty() ? 0.0 : static_cast<double>(out->times.back());
  // Each unit's reach: the farthest vertex bound to it from its joints' rest place.
  std::vector<double> reach(units.size(), 0.0);
  for (const SwaySkinPart& part : parts) {
    const std::vector<float>& p = *part.positions;
    for (std::size_t v = 0; v < part.skin->joint.size(); ++v) {
      const int u = unit_of_node[part.skin->joint[v]];
      if (u < 0) continue;
      const std::array<float, 3>& o =
          out->joints[static_cast<std::size_t>(units[static_cast<std::size_t>(u)][0])]
              .inverse_bind_offset;
      const glm::dvec3 d(static_cast<double>(p[3 * v]) + o[0],
                         static_cast<double>(p[3 * v + 1]) + o[1],
                         static_cast<double>(p[3 * v + 2]) + o[2]);
      reach[static_cast<std::size_t>(u)] =
          std::max(reach[static_cast<std::size_t>(u)], glm::length(d));
    }
  }
  for (std::size_t u = 0; u < units.size(); ++u) {
    info->full_joint_keys += units[u].size() * out->times.size();
    ReduceUnitKeys(out->times, units[u], reach[u], options.key_error, &out->joints,
                   &info->key_error);
    for (int j : units[u]) {
      const GltfJoint& joint = out->joints[static_cast<std::size_t>(j)];
      info->joint_keys += joint.times.empty() ? out->times.size() : joint.times.size();
    }
  }
  return Status::Ok();
}

Status WriteSwayGlb(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                    std::vector<unsigned char>* bytes, SwayGlbInfo* info) {
  if (bytes == nullptr) return Status::Error("glb", "no output buffer");
  bytes->clear();
  MeshOptions mesh_options;
  mesh_options.cm_to_units = options.cm_to_units;
  const TreeMesh mesh = BuildTreeMesh(tree, mesh_options);
  SwayModel model = BuildSwayModel(tree, params);
  const TreeSkin skin = BuildTreeSkin(mesh, model);
  const std::vector<SwaySkinPart> parts = {{&skin.bark, &mesh.bark.positions},
                                           {&skin.leaves, &mesh.leaves.positions},
                                           {&skin.flowers, &mesh.flowers.positions}};
  SwaySkin built;
  NIWA_RETURN_IF_ERROR(BuildSwaySkin(tree, params, options, parts, &built, info));
  GltfSkinning out;
  out.joints = std::move(built.joints);
  out.times = std::move(built.times);
  for (std::size_t k = 0; k < 3; ++k) {
    out.joints0[k] = std::move(built.joints0[k]);
    out.weights0[k] = std::move(built.weights0[k]);
  }
  const std::vector<int> levels = BranchLevels(tree);
  out.attributes[0] = WindAttributes(tree, levels, mesh.bark_branch_id, mesh.bark_node_index);
  out.attributes[1] = WindAttributes(tree, levels, mesh.leaf_branch_id, mesh.leaf_node_index);
  out.attributes[2] = WindAttributes(tree, levels, mesh.flower_branch_id, mesh.flower_node_index);
  return WriteSkinnedTreeGlb(mesh, out, bytes);
}

}  // namespace niwa
