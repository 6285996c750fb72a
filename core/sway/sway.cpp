// Node-point wind-sway model of thesis chapter 3: parameters, node points, forces, motion,
// omission.
#include "sway/sway.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "math/det_math.h"
#include "params/param_table.h"

namespace niwa {
namespace {

using S = SwayParamId;
using glm::dvec3;

// Internal units are cgs (cm, g, s, dyn), as the tree (cm) and thesis table 3.1 (g, cm², g/cm³).
const std::array<SwayParamSpec, kSwayParamCount> kSwayTable = {{
    {S::kKWind, "K_wind", "K_wind", "g/(cm²·s)", 0.1, 0, 100, false, "sway",
     "Wind force per unit area and unit relative speed (eq. 3.5; table 3.1: 0.1)."},
    {S::kKDirTrunk, "K_dir_trunk", "K_dir", "dyn/cm²", 150000, 0, 1e9, false, "sway",
     "Direction-restoring coefficient at the thickest branch (eq. 3.8; table 3.1: 50000~150000)."},
    {S::kKDirTip, "K_dir_tip", "K_dir", "dyn/cm²", 50000, 0, 1e9, false, "sway",
     "Direction-restoring coefficient at the thinnest branch; linear in radius between (eq. 3.8)."},
    {S::kKRev, "K_rev", "K_rev", "", 0.8, 0, 1, false, "sway",
     "Share of the restoring force's reaction passed to the parent node (eq. 3.10; table 3.1: "
     "0.8)."},
    {S::kKVdel, "K_vdel", "K_vdel", "", 1, 0, 1, false, "sway",
     "Velocity kept per step, damping by the tree itself (eq. 3.13; table 3.1: 1)."},
    {S::kDensity, "delta", "δ", "g/cm³", 0.12, 0.01, 2, false, "sway",
     "Branch density (eqs. 3.1, 3.3; table 3.1: 0.12)."},
    {S::kMLeaf, "m_leaf", "m_leaf", "g", 3, 0, 100, false, "sway",
     "Mass of one leaf (eq. 3.3; table 3.1: 3 g, exaggerated in the thesis). 0: no leaf mass."},
    {S::kSLeaf, "s_leaf", "s_leaf", "cm²", 30, 0, 1000, false, "sway",
     "Surface area of one leaf (eq. 3.4; table 3.1: 30 cm²). 0: no leaf area."},
    {S::kAlpha, "alpha", "α", "", 2, 1, 8, false, "sway",
     "Exponent of the interpolation of intermediate nodes (eq. 3.15); 1 bends at the node."},
    {S::kGravity, "g", "g", "m/s²", 9.8, 0, 100, false, "sway",
     "Gravitational acceleration, along -y (eq. 3.6)."},
    {S::kGravityPreload, "gravity_preload", "", "", 1, 0, 1, true, "sway",
     "1: the grown shape is the rest pose under gravity (no sag at t = 0); 0: as the thesis."},
    {S::kWindSpeed, "wind", "v_wind", "m/s", 5, 0, 100, false, "wind",
     "Wind speed while the gust blows (eq. 3.5; thesis examples: 5, 10, 20)."},
    {S::kWindDir, "wind_dir", "", "deg", 0, -360, 360, false, "wind",
     "Wind azimuth in the horizontal plane: 0 blows towards +x, 90 towards +z."},
    {S::kGustOn, "gust_on", "", "s", 1, 0, 3600, false, "wind",
     "Time the wind starts suddenly from still air (thesis 3.5)."},
    {S::kGustOff, "gust_off", "", "s", 6, 0, 3600, false, "wind",
     "Time the wind stops suddenly; must be after gust_on."},
    {S::kDt, "dt", "dt", "s", 1.0 / 30.0, 0.0001, 0.1, false, "wind",
     "Time step (eqs. 3.13, 3.14, 3.16; table 3.1: 1/30 s)."},
    {S::kDuration, "duration", "", "s", 12, 0, 600, false, "wind", "Simulated time."},
}};

constexpr double kCmPerM = 100.0;
constexpr double kOmitLimit = 3.0;  // thesis eq. 3.16: K_x <= 3 m / dt²

// Minimal rotation taking unit `from` to unit `to`, applied to v (Rodrigues with the unnormalized
// axis from × to; no trigonometry needed). Equals the thesis's θ(0)⁻¹·dθ(t)⁻¹·θ(0) (eq. 3.11).
dvec3 RotateMin(const dvec3& from, const dvec3& to, const dvec3& v) {
  if (from == to) return v;
  dvec3 w = glm::cross(from, to);
  double c = glm::dot(from, to);
  if (c > -0.999999) return v * c + glm::cross(w, v) + w * (glm::dot(w, v) / (1.0 + c));
  // Half turn about an axis perpendicular to `from`.
  dvec3 other = std::fabs(from.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  dvec3 k = glm::normalize(glm::cross(from, other));
  return k * (2.0 * glm::dot(k, v)) - v;
}

dvec3 ToD(const glm::vec3& v) {
  return dvec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

double PowAlpha(double x, double alpha) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  if (alpha == 2.0) return x * x;
  return det::Exp(alpha * det::Log(x));
}

}  // namespace

// ---- parameters ----

const std::array<SwayParamSpec, kSwayParamCount>& SwayParamTable() {
  static const bool ordered = [] {
    for (std::size_t i = 0; i < kSwayParamCount; ++i) {
      if (static_cast<std::size_t>(kSwayTable[i].id) != i) return false;
    }
    return true;
  }();
  if (!ordered) std::abort();  // programming error: rows out of SwayParamId order
  return kSwayTable;
}

const SwayParamSpec& SwaySpec(SwayParamId id) {
  return SwayParamTable()[static_cast<std::size_t>(id)];
}

std::optional<SwayParamId> FindSwayParam(std::string_view key) {
  for (const SwayParamSpec& spec : SwayParamTable()) {
    if (key == spec.key) return spec.id;
  }
  return std::nullopt;
}

std::string SwayRangeText(const SwayParamSpec& spec) {
  return RangeText(spec.min_value, spec.max_value, spec.integer);
}

SwayParams::SwayParams() {
  for (const SwayParamSpec& spec : SwayParamTable()) {
    values_[static_cast<std::size_t>(spec.id)] = spec.default_value;
  }
}

std::string SwayParams::Set(SwayParamId id, double value) {
  const SwayParamSpec& spec = SwaySpec(id);
  std::string error = CheckValue(spec.key, value, spec.min_value, spec.max_value, spec.integer);
  if (error.empty()) values_[static_cast<std::size_t>(id)] = value;
  return error;
}

std::string SwayParams::SetFromText(std::string_view key, std::string_view text) {
  std::optional<SwayParamId> id = FindSwayParam(key);
  if (!id) return "unknown sway parameter '" + std::string(key.substr(0, 64)) + "'";
  std::optional<double> value = ParseNumber(text);
  if (!value) {
    return std::string(key) + ": '" + std::string(text.substr(0, 32)) + "' is not " +
           SwayRangeText(SwaySpec(*id));
  }
  return Set(*id, *value);
}

std::string SwayParams::Validate() const {
  if (Get(S::kGustOff) <= Get(S::kGustOn)) {
    return "gust_off: " + FormatNumber(Get(S::kGustOff)) + " must be greater than gust_on (" +
           FormatNumber(Get(S::kGustOn)) + ")";
  }
  return "";
}

// ---- model ----

SwayModel BuildSwayModel(const Tree& tree, const SwayParams& params) {
  SwayModel model;
  const std::size_t count = tree.branches.size();
  model.node_of_branch.assign(count, -1);

  // Parents before children: breadth-first from the seedling shoot(s).
  std::vector<int> order;
  for (const Branch& b : tree.branches) {
    if (b.alive && b.parent < 0) order.push_back(b.id);
  }
  for (std::size_t head = 0; head < order.size(); ++head) {
    const Branch& b = tree.branches[static_cast<std::size_t>(order[head])];
    for (int child : b.children) {
      if (child < 0 || static_cast<std::size_t>(child) >= count) continue;
      const Branch& c = tree.branches[static_cast<std::size_t>(child)];
      if (c.alive && c.parent == b.id) order.push_back(child);
    }
  }

  const double pi = det::kPi;
  const double delta = params.Get(S::kDensity);
  const double m_leaf = params.Get(S::kMLeaf), s_leaf = params.Get(S::kSLeaf);
  const double alpha = params.Get(S::kAlpha);
  const double dt = params.Get(S::kDt);
  double max_radius = 0;
  for (int id : order) {
    const Branch& b = tree.branches[static_cast<std::size_t>(id)];
    if (b.nodes.empty()) continue;
    SwayNode n;
    n.branch = id;
    n.parent = b.parent >= 0 ? model.node_of_branch[static_cast<std::size_t>(b.parent)] : -1;
    n.radius = static_cast<double>(BranchRadius(b));
    n.leaves = static_cast<int>(b.leaves.size());
    for (const glm::vec3& p : b.nodes) n.rest_nodes.push_back(ToD(p));
    if (n.parent >= 0) {
      // The anchor is the parent's node the shoot starts at (fig. 3.3).
      const SwayNode& parent = model.nodes[static_cast<std::size_t>(n.parent)];
      int last = static_cast<int>(parent.rest_nodes.size()) - 1;
      n.parent_node = std::min(std::max(b.parent_node, 0), last);
      n.rest_nodes[0] = parent.rest_nodes[static_cast<std::size_t>(n.parent_node)];
    }
    n.rest_anchor = n.rest_nodes.front();
    n.rest_tip = n.rest_nodes.back();
    std::vector<double> arc(n.rest_nodes.size(), 0.0);
    for (std::size_t k = 1; k < arc.size(); ++k) {
      arc[k] = arc[k - 1] + glm::length(n.rest_nodes[k] - n.rest_nodes[k - 1]);
    }
    n.length = arc.back();
    n.arc_ratio.resize(arc.size());
    n.weight.resize(arc.size());
    for (std::size_t k = 0; k < arc.size(); ++k) {
      n.arc_ratio[k] =
          n.length > 0
              ? arc[k] / n.length
              : (arc.size() > 1 ? static_cast<double>(k) / static_cast<double>(arc.size() - 1)
                                : 1.0);
      n.weight[k] = PowAlpha(n.arc_ratio[k], alpha);  // (l_jn / l_j)^α, eq. 3.15
    }
    dvec3 chord = n.rest_tip - n.rest_anchor;
    n.rest_length = glm::length(chord);
    n.rest_dir = n.rest_length > 1e-9 ? chord / n.rest_length : dvec3(0, 1, 0);
    // thesis eqs. 3.1-3.4: m = π d² l δ + n m_leaf, s = 2π d l + n s_leaf
    n.mass = pi * n.radius * n.radius * n.length * delta + n.leaves * m_leaf;
    n.area = 2.0 * pi * n.radius * n.length + n.leaves * s_leaf;
    max_radius = std::max(max_radius, n.radius);
    model.node_of_branch[static_cast<std::size_t>(id)] = static_cast<int>(model.nodes.size());
    model.nodes.push_back(std::move(n));
  }

  const double k_trunk = params.Get(S::kKDirTrunk), k_tip = params.Get(S::kKDirTip);
  const double k_rev = params.Get(S::kKRev);
  for (SwayNode& n : model.nodes) {
    double w = max_radius > 0 ? n.radius / max_radius : 1.0;
    n.k_dir = k_tip + (k_trunk - k_tip) * w;
    // thesis eq. 3.8: K_dir π d² / l_j (d of the branch the rod belongs to; docs/sway-model.md)
    n.stiffness =
        n.rest_length > 1e-9 ? n.k_dir * pi * n.radius * n.radius / n.rest_length : HUGE_VAL;
    n.restoring = n.stiffness;
  }
  // thesis eq. 3.16, children first: K_x of 3.4.1 is every restoring force proportional to the
  // node's own displacement, i.e. its own K_dir π d² / l plus, through the reactions of eqs.
  // 3.9-3.10, K_rev (L_j / l_i)² times the stiffness of each moving child (docs/sway-model.md).
  std::vector<bool> omitted(model.nodes.size(), false);
  for (std::size_t u = model.nodes.size(); u-- > 0;) {
    SwayNode& n = model.nodes[u];
    omitted[u] = !(n.mass > 0) || !(n.restoring <= kOmitLimit * n.mass / (dt * dt));
    if (!omitted[u] && n.parent >= 0) {
      SwayNode& parent = model.nodes[static_cast<std::size_t>(n.parent)];
      if (parent.rest_length > 1e-9) {
        double lever = glm::length(n.rest_tip - parent.rest_anchor) / parent.rest_length;
        parent.restoring += k_rev * lever * lever * n.stiffness;
      }
    }
  }
  // thesis 3.4.2: an omitted node is fixed when its parent is the root or fixed, else it follows.
  for (std::size_t u = 0; u < model.nodes.size(); ++u) {
    SwayNode& n = model.nodes[u];
    if (!omitted[u]) {
      n.kind = SwayKind::kMoving;
      ++model.moving;
    } else if (n.parent < 0 ||
               model.nodes[static_cast<std::size_t>(n.parent)].kind == SwayKind::kFixed) {
      n.kind = SwayKind::kFixed;
      ++model.fixed;
    } else {
      n.kind = SwayKind::kFollower;
      ++model.followers;
    }
    model.internodes += static_cast<long>(n.rest_nodes.size()) - 1;
  }
  return model;
}

dvec3 WindAt(const SwayParams& params, double t) {
  if (t < params.Get(S::kGustOn) || t >= params.Get(S::kGustOff)) return dvec3(0.0);
  double s = 0, c = 1;
  det::SinCos(params.Get(S::kWindDir) * (det::kPi / 180.0), &s, &c);
  double speed = params.Get(S::kWindSpeed) * kCmPerM;
  return dvec3(speed * c, 0.0, speed * s);
}

// ---- simulator ----

SwaySimulator::SwaySimulator(const Tree& tree, const SwayParams& params)
    : params_(params), model_(BuildSwayModel(tree, params)) {
  const std::size_t n = model_.nodes.size();
  tip_.resize(n);
  anchor_.resize(n);
  dir_.resize(n);
  velocity_.assign(n, dvec3(0.0));
  force_.assign(n, dvec3(0.0));
  preload_.assign(n, dvec3(0.0));
  const double g = params_.Get(S::kGravity) * kCmPerM;
  const bool preload = params_.Get(S::kGravityPreload) != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const SwayNode& s = model_.nodes[i];
    tip_[i] = s.rest_tip;
    anchor_[i] = s.rest_anchor;
    dir_[i] = s.rest_dir;
    // Holds the grown shape against its own weight: -m g, fixed in the world (docs/sway-model.md).
    if (preload) preload_[i] = dvec3(0.0, s.mass * g, 0.0);
  }
}

dvec3 SwaySimulator::ParentRotate(int i, const dvec3& v) const {
  int p = model_.nodes[static_cast<std::size_t>(i)].parent;
  if (p < 0) return v;
  return RotateMin(model_.nodes[static_cast<std::size_t>(p)].rest_dir,
                   dir_[static_cast<std::size_t>(p)], v);
}

dvec3 SwaySimulator::NodePosition(int i, int n) const {
  const SwayNode& s = model_.nodes[static_cast<std::size_t>(i)];
  const std::size_t k = static_cast<std::size_t>(n);
  const dvec3& anchor = anchor_[static_cast<std::size_t>(i)];
  if (k == 0) return anchor;
  // thesis 3.3.3 step 2: P'_j, P'_jn = the rest pose turned with the parent's rod.
  dvec3 rigid_tip = anchor + ParentRotate(i, s.rest_tip - s.rest_anchor);
  dvec3 rigid = anchor + ParentRotate(i, s.rest_nodes[k] - s.rest_anchor);
  // thesis eq. 3.15: P_jn(t) = P'_jn + (l_jn / l_j)^α M_j, M_j = P_j(t) - P'_j
  return rigid + s.weight[k] * (tip_[static_cast<std::size_t>(i)] - rigid_tip);
}

void SwaySimulator::UpdateAnchorAndPose(int i) {
  const std::size_t u = static_cast<std::size_t>(i);
  const SwayNode& s = model_.nodes[u];
  if (s.kind == SwayKind::kFixed) {
    anchor_[u] = s.rest_anchor;
    tip_[u] = s.rest_tip;
    dir_[u] = s.rest_dir;
    return;
  }
  const dvec3 old_anchor = anchor_[u];
  anchor_[u] = s.parent < 0 ? s.rest_anchor : NodePosition(s.parent, s.parent_node);
  if (s.kind == SwayKind::kFollower || !(s.rest_length > 1e-9)) {
    // thesis 3.4.3: a follower keeps the reference direction b(t) at its rest distance.
    dir_[u] = ParentRotate(i, s.rest_dir);
    tip_[u] = anchor_[u] + s.rest_length * dir_[u];
    velocity_[u] = dvec3(0.0);
    return;
  }
  // Carry the node with its parent's rigid motion over this step (anchor shift and the turn of
  // the parent's rod, the rotation of eq. 3.11), so that it moves by its own velocity only
  // relative to its parent (docs/sway-model.md: without this a chain amplifies its parent's
  // motion by up to K_x dt² / m = 3 per generation).
  dvec3 relative = tip_[u] - old_anchor;
  dvec3 velocity = velocity_[u];
  if (s.parent >= 0) {
    const std::size_t q = static_cast<std::size_t>(s.parent);
    const dvec3& rest = model_.nodes[q].rest_dir;
    relative = RotateMin(rest, dir_[q], RotateMin(prev_dir_[q], rest, relative));
    velocity = RotateMin(rest, dir_[q], RotateMin(prev_dir_[q], rest, velocity));
  }
  dvec3 carried = anchor_[u] + relative;
  // Fig. 3.10: back to the rest distance l_j(0) from the parent, along the current direction.
  dvec3 d = carried - anchor_[u];
  double len = glm::length(d);
  dir_[u] = len > 1e-12 * s.rest_length ? d / len : ParentRotate(i, s.rest_dir);
  tip_[u] = anchor_[u] + s.rest_length * dir_[u];
  // The rod is rigid: the velocity along it is dropped with the length (docs/sway-model.md).
  velocity_[u] = velocity - glm::dot(velocity, dir_[u]) * dir_[u];
}

void SwaySimulator::Step() {
  const double dt = params_.Get(S::kDt);
  const double k_wind = params_.Get(S::kKWind);
  const double k_rev = params_.Get(S::kKRev);
  const double k_vdel = params_.Get(S::kKVdel);
  const dvec3 gravity(0.0, -params_.Get(S::kGravity) * kCmPerM, 0.0);
  const dvec3 wind = WindAt(params_, time_);
  const std::size_t n = model_.nodes.size();

  std::fill(force_.begin(), force_.end(), dvec3(0.0));
  for (std::size_t u = 0; u < n; ++u) {
    const SwayNode& s = model_.nodes[u];
    if (s.kind != SwayKind::kMoving) continue;
    const int i = static_cast<int>(u);
    dvec3 b = ParentRotate(i, s.rest_dir);      // reference direction b(t), eq. 3.11
    dvec3 p = anchor_[u] + s.rest_length * b;   // thesis eq. 3.7
    dvec3 f_dir = s.stiffness * (p - tip_[u]);  // thesis eq. 3.8
    // thesis eq. 3.5 is K_wind s (v_wind - v_i), v_i the node's own velocity of eq. 3.13; its
    // -K_wind s v_i part is taken at t + dt below.
    dvec3 f = k_wind * s.area * wind  // thesis eq. 3.5 (wind part)
              + s.mass * gravity      // thesis eq. 3.6
              + f_dir + preload_[u];
    force_[u] += f;
    // Reaction on the parent (thesis eqs. 3.9, 3.10): -F_dir at p turns the parent's rod about its
    // anchor P_k; the force at the parent's node point with the same moment (perpendicular to
    // the rod) is (M × r_ki) / l_i, scaled by K_rev.
    if (s.parent >= 0 && k_rev > 0) {
      const std::size_t q = static_cast<std::size_t>(s.parent);
      const SwayNode& parent = model_.nodes[q];
      if (parent.kind == SwayKind::kMoving && parent.rest_length > 0) {
        dvec3 moment = glm::cross(p - anchor_[q], -f_dir);                        // thesis eq. 3.9
        force_[q] += (k_rev / parent.rest_length) * glm::cross(moment, dir_[q]);  // eq. 3.10
      }
    }
  }
  for (std::size_t u = 0; u < n; ++u) {
    const SwayNode& s = model_.nodes[u];
    if (s.kind != SwayKind::kMoving) continue;
    dvec3 f = force_[u] - glm::dot(force_[u], dir_[u]) * dir_[u];  // only ⊥ r_ki (fig. 3.9)
    dvec3 a = f / s.mass;                                          // thesis eq. 3.12
    // thesis eq. 3.13 with the drag of eq. 3.5 on v(t + dt): v' = K_vdel v + (a - c v') dt,
    // c = K_wind s / m. With explicit drag, symplectic Euler needs K_x dt²/m < 4 - 2 c dt, which
    // thin twigs near the eq. 3.16 bound can break; this form is stable for every c.
    double drag = k_wind * s.area / s.mass * dt;
    velocity_[u] = (k_vdel * velocity_[u] + a * dt) / (1.0 + drag);
    tip_[u] += velocity_[u] * dt;  // thesis eq. 3.14
  }
  prev_dir_ = dir_;
  for (std::size_t u = 0; u < n; ++u) UpdateAnchorAndPose(static_cast<int>(u));
  ++steps_;
  time_ = static_cast<double>(steps_) * dt;
}

Tree SwaySimulator::DeformedTree(const Tree& rest) const {
  Tree out = rest;
  for (std::size_t u = 0; u < model_.nodes.size(); ++u) {
    const SwayNode& s = model_.nodes[u];
    Branch& b = out.branches[static_cast<std::size_t>(s.branch)];
    for (std::size_t k = 0; k < b.nodes.size() && k < s.rest_nodes.size(); ++k) {
      dvec3 p = NodePosition(static_cast<int>(u), static_cast<int>(k));
      b.nodes[k] =
          glm::vec3(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
    }
  }
  return out;
}

// ---- runs and outputs ----

SwayRun RunSway(const Tree& tree, const SwayParams& params, int tips) {
  using Clock = std::chrono::steady_clock;
  SwaySimulator sim(tree, params);
  const SwayModel& model = sim.model();
  SwayRun run;
  run.node_points = static_cast<int>(model.nodes.size());
  run.moving = model.moving;
  run.followers = model.followers;
  run.fixed = model.fixed;
  run.internodes = model.internodes;

  // Tips to trace: node points without children, moving ones if any; the first farthest from the
  // root, each next one farthest from those already chosen (spread over the crown).
  std::vector<bool> has_child(model.nodes.size(), false);
  for (const SwayNode& s : model.nodes) {
    if (s.parent >= 0) has_child[static_cast<std::size_t>(s.parent)] = true;
  }
  std::vector<int> pool;
  for (int pass = 0; pass < 2 && pool.empty(); ++pass) {
    for (std::size_t u = 0; u < model.nodes.size(); ++u) {
      if (!has_child[u] && (pass == 1 || model.nodes[u].kind == SwayKind::kMoving)) {
        pool.push_back(static_cast<int>(u));
      }
    }
  }
  std::vector<int> candidates;
  std::vector<double> gap(pool.size(), HUGE_VAL);
  dvec3 root = model.nodes.empty() ? dvec3(0.0) : model.nodes.front().rest_anchor;
  for (std::size_t k = 0; k < pool.size(); ++k) {
    gap[k] = glm::length(model.nodes[static_cast<std::size_t>(pool[k])].rest_tip - root);
  }
  while (static_cast<int>(candidates.size()) < tips && candidates.size() < pool.size()) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < pool.size(); ++k) {
      if (gap[k] > gap[best]) best = k;
    }
    if (!(gap[best] > 0) && !candidates.empty()) break;
    candidates.push_back(pool[best]);
    const dvec3 chosen = model.nodes[static_cast<std::size_t>(pool[best])].rest_tip;
    for (std::size_t k = 0; k < pool.size(); ++k) {
      gap[k] = std::min(
          gap[k], glm::length(model.nodes[static_cast<std::size_t>(pool[k])].rest_tip - chosen));
    }
  }
  for (int u : candidates)
    run.tip_branches.push_back(model.nodes[static_cast<std::size_t>(u)].branch);
  run.tip_positions.assign(candidates.size(), {});

  auto record = [&]() {
    run.times.push_back(sim.time());
    for (std::size_t t = 0; t < candidates.size(); ++t) {
      run.tip_positions[t].push_back(sim.tips()[static_cast<std::size_t>(candidates[t])]);
    }
  };
  record();
  const double dt = params.Get(S::kDt);
  const long steps = static_cast<long>(std::floor(params.Get(S::kDuration) / dt + 0.5));
  double ms = 0;
  for (long k = 0; k < steps; ++k) {
    Clock::time_point start = Clock::now();
    sim.Step();
    ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    for (std::size_t u = 0; u < model.nodes.size(); ++u) {
      const dvec3& p = sim.tips()[u];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) run.finite = false;
      run.max_tip_displacement =
          std::max(run.max_tip_displacement, glm::length(p - model.nodes[u].rest_tip));
    }
    record();
  }
  run.steps = steps;
  run.ms = ms;
  if (steps > 0 && run.internodes > 0) {
    run.ns_per_internode =
        ms * 1e6 / (static_cast<double>(steps) * static_cast<double>(run.internodes));
  }
  return run;
}

std::string SwayCsv(const SwayRun& run) {
  std::string out = "time,node,x,y,z\n";
  char line[160];
  for (std::size_t k = 0; k < run.times.size(); ++k) {
    for (std::size_t t = 0; t < run.tip_branches.size(); ++t) {
      const dvec3& p = run.tip_positions[t][k];
      std::snprintf(line, sizeof line, "%.6f,%d,%.6f,%.6f,%.6f\n", run.times[k],
                    run.tip_branches[t], p.x, p.y, p.z);
      out += line;
    }
  }
  return out;
}

std::string SwayPlotSvg(const SwayRun& run, const SwayParams& params) {
  const double width = 800, height = 400, left = 60, right = 20, top = 30, bottom = 50;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  double t_max = run.times.empty() ? 1.0 : std::max(run.times.back(), 1e-9);
  double d_max = 0;
  for (std::size_t t = 0; t < run.tip_positions.size(); ++t) {
    for (const dvec3& p : run.tip_positions[t]) {
      d_max = std::max(d_max, glm::length(p - run.tip_positions[t].front()));
    }
  }
  if (!(d_max > 0) || !std::isfinite(d_max)) d_max = 1;
  auto px = [&](double t) { return left + plot_w * t / t_max; };
  auto py = [&](double d) { return top + plot_h * (1.0 - d / d_max); };
  std::string svg;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"12\">\n",
                width, height, width, height);
  svg += buf;
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double on = std::min(params.Get(S::kGustOn), t_max),
         off = std::min(params.Get(S::kGustOff), t_max);
  if (off > on) {
    std::snprintf(buf, sizeof buf,
                  "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"#e8f0fb\"/>\n",
                  px(on), top, px(off) - px(on), plot_h);
    svg += buf;
  }
  std::snprintf(buf, sizeof buf,
                "<path d=\"M%.2f %.2f V%.2f H%.2f\" fill=\"none\" stroke=\"black\"/>\n", left, top,
                top + plot_h, left + plot_w);
  svg += buf;
  std::snprintf(buf, sizeof buf,
                "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">time (s), 0 to %.3g; shaded: "
                "wind %.3g m/s</text>\n",
                left + plot_w / 2, height - 15, t_max, params.Get(S::kWindSpeed));
  svg += buf;
  std::snprintf(buf, sizeof buf,
                "<text x=\"15\" y=\"%.2f\" transform=\"rotate(-90 15 %.2f)\" "
                "text-anchor=\"middle\">tip displacement (cm), 0 to %.3g</text>\n",
                top + plot_h / 2, top + plot_h / 2, d_max);
  svg += buf;
  static const char* kColors[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e",
                                  "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  for (std::size_t t = 0; t < run.tip_positions.size(); ++t) {
    const std::vector<dvec3>& series = run.tip_positions[t];
    std::string points;
    for (std::size_t k = 0; k < series.size(); ++k) {
      double d = glm::length(series[k] - series.front());
      if (!std::isfinite(d)) continue;
      std::snprintf(buf, sizeof buf, "%s%.2f,%.2f", points.empty() ? "" : " ", px(run.times[k]),
                    py(d));
      points += buf;
    }
    const char* color = kColors[t % (sizeof kColors / sizeof kColors[0])];
    svg += "<polyline fill=\"none\" stroke=\"" + std::string(color) +
           "\" stroke-width=\"1.5\" points=\"" + points + "\"/>\n";
    std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\" fill=\"%s\">branch %d</text>\n",
                  left + 10 + 90.0 * static_cast<double>(t), top - 10, color, run.tip_branches[t]);
    svg += buf;
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace niwa
