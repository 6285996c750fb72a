// Node-point wind-sway model of thesis chapter 3: parameters, node points, forces, motion,
// omission.
#include "sway/sway.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "math/det_math.h"
#include "tree/tree_params.h"

namespace niwa {
namespace {

using glm::dvec3;

// Internal units are cgs (cm, g, s, dyn), as the tree (cm) and thesis table 3.1 (g, cm², g/cm³).
constexpr double kCmPerM = 100.0;

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

SwayParams::SwayParams(const ParamSet& p)
    : k_wind(p.Get(ParamId::kKWind)),
      k_dir_trunk(p.Get(ParamId::kKDirTrunk)),
      k_dir_tip(p.Get(ParamId::kKDirTip)),
      k_rev(p.Get(ParamId::kKRev)),
      k_vdel(p.Get(ParamId::kKVdel)),
      density(p.Get(ParamId::kWoodDensity)),
      m_leaf(p.Get(ParamId::kMLeaf)),
      s_leaf(p.Get(ParamId::kSLeaf)),
      alpha(p.Get(ParamId::kSwayAlpha)),
      gravity(p.Get(ParamId::kGravity)),
      gravity_preload(p.GetBool(ParamId::kGravityPreload)),
      dt(p.Get(ParamId::kSwayDt)),
      omit_limit(p.Get(ParamId::kOmitLimit)),
      wind_speed(p.Get(ParamId::kWindSpeed)),
      wind_dir(p.Get(ParamId::kWindDir)),
      gust_on(p.Get(ParamId::kGustOn)),
      gust_off(p.Get(ParamId::kGustOff)),
      gust_front_speed(p.Get(ParamId::kGustFrontSpeed)),
      wind_variation(p.Get(ParamId::kWindVariation)),
      wind_wavelength(p.Get(ParamId::kWindWavelength)),
      wind_period(p.Get(ParamId::kWindPeriod)),
      duration(p.Get(ParamId::kSwayDuration)) {}

Status CheckSwayParams(const ParamSet& params) {
  double on = params.Get(ParamId::kGustOn), off = params.Get(ParamId::kGustOff);
  if (off <= on) {
    return Status::Error(
        "gust_off", FormatNumber(off) + " must be greater than gust_on (" + FormatNumber(on) + ")");
  }
  return Status::Ok();
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
  const double delta = params.density;
  const double m_leaf = params.m_leaf, s_leaf = params.s_leaf;
  const double alpha = params.alpha;
  const double dt = params.dt;
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

  const double k_trunk = params.k_dir_trunk, k_tip = params.k_dir_tip;
  const double k_rev = params.k_rev;
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
    omitted[u] = !(n.mass > 0) || !(n.restoring <= params.omit_limit * n.mass / (dt * dt));
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

WindField::WindField(const SwayParams& params)
    : speed_(params.wind_speed * kCmPerM),
      gust_on_(params.gust_on),
      gust_off_(params.gust_off),
      front_speed_(params.gust_front_speed),
      variation_(params.wind_variation),
      wavelength_(params.wind_wavelength),
      period_(params.wind_period) {
  double s = 0, c = 1;
  det::SinCos(params.wind_dir * (det::kPi / 180.0), &s, &c);
  dir_ = dvec3(c, 0.0, s);
  uniform_ = front_speed_ == 0.0 && variation_ == 0.0;
}

double WindField::Along(const dvec3& position) const { return glm::dot(position, dir_) / kCmPerM; }

dvec3 WindField::AtAlong(double along, double t) const {
  // The gust front reaches a point `along` m downwind of the origin along / c s after the origin.
  double delay = front_speed_ > 0.0 ? along / front_speed_ : 0.0;
  if (t < gust_on_ + delay || t >= gust_off_ + delay) return dvec3(0.0);
  double speed = speed_;
  if (variation_ > 0.0) {
    // A wave of speed travelling with the wind: 1 + v sin(2π (x/λ - t/T)), in [1 - v, 1 + v].
    double phase = 2.0 * det::kPi * (along / wavelength_ - t / period_);
    speed *= 1.0 + variation_ * det::Sin(phase);
  }
  return dvec3(speed * dir_.x, 0.0, speed * dir_.z);
}

dvec3 WindAt(const SwayParams& params, const dvec3& position, double t) {
  return WindField(params).At(position, t);
}

// ---- simulator ----

SwaySimulator::SwaySimulator(const Tree& tree, const SwayParams& params, const dvec3& origin)
    : SwaySimulator(BuildSwayModel(tree, params), params, origin) {}

SwaySimulator::SwaySimulator(SwayModel model, const SwayParams& params, const dvec3& origin)
    : params_(params), model_(std::move(model)), wind_(params) {
  const std::size_t n = model_.nodes.size();
  // The wind each node point feels is taken at its rest tip in the world (the tree moves by cm,
  // the field varies over metres).
  along_.resize(n);
  for (std::size_t i = 0; i < n; ++i) along_[i] = wind_.Along(origin + model_.nodes[i].rest_tip);
  tip_.resize(n);
  anchor_.resize(n);
  dir_.resize(n);
  velocity_.assign(n, dvec3(0.0));
  force_.assign(n, dvec3(0.0));
  preload_.assign(n, dvec3(0.0));
  const double g = params_.gravity * kCmPerM;
  const bool preload = params_.gravity_preload;
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

glm::dmat3 SwaySimulator::ParentRotation(int i) const {
  // RotateMin is linear in v: its columns are the images of the unit axes.
  return glm::dmat3(ParentRotate(i, dvec3(1, 0, 0)), ParentRotate(i, dvec3(0, 1, 0)),
                    ParentRotate(i, dvec3(0, 0, 1)));
}

dvec3 RotateMinimal(const dvec3& from, const dvec3& to, const dvec3& v) {
  return RotateMin(from, to, v);
}

glm::dmat3 SwaySimulator::RodRotation(int i) const {
  const std::size_t u = static_cast<std::size_t>(i);
  const dvec3& from = model_.nodes[u].rest_dir;
  return glm::dmat3(RotateMin(from, dir_[u], dvec3(1, 0, 0)),
                    RotateMin(from, dir_[u], dvec3(0, 1, 0)),
                    RotateMin(from, dir_[u], dvec3(0, 0, 1)));
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

void SwaySimulator::NodePositions(std::vector<dvec3>* out) const {
  out->clear();
  out->reserve(static_cast<std::size_t>(model_.internodes) + model_.nodes.size());
  for (std::size_t u = 0; u < model_.nodes.size(); ++u) {
    const SwayNode& s = model_.nodes[u];
    const dvec3& anchor = anchor_[u];
    // The parent rod's turn of eq. 3.11 (identity on the root), as in ParentRotate; RotateMin's
    // axis and cosine taken once (the same arithmetic, so the same values).
    const dvec3 from =
        s.parent >= 0 ? model_.nodes[static_cast<std::size_t>(s.parent)].rest_dir : dvec3(0, 1, 0);
    const dvec3 to = s.parent >= 0 ? dir_[static_cast<std::size_t>(s.parent)] : from;
    const dvec3 w = glm::cross(from, to);
    const double c = glm::dot(from, to);
    const bool general = from != to && c > -0.999999;
    auto turn = [&](const dvec3& v) {
      if (general) return v * c + glm::cross(w, v) + w * (glm::dot(w, v) / (1.0 + c));
      return RotateMin(from, to, v);  // identity or half turn
    };
    // thesis eq. 3.15: P_jn(t) = P'_jn + (l_jn / l_j)^α (P_j(t) - P'_j)
    const dvec3 moved = tip_[u] - (anchor + turn(s.rest_tip - s.rest_anchor));
    out->push_back(anchor);
    for (std::size_t k = 1; k < s.rest_nodes.size(); ++k) {
      out->push_back(anchor + turn(s.rest_nodes[k] - s.rest_anchor) + s.weight[k] * moved);
    }
  }
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
  const double dt = params_.dt;
  const double k_wind = params_.k_wind;
  const double k_rev = params_.k_rev;
  const double k_vdel = params_.k_vdel;
  const dvec3 gravity(0.0, -params_.gravity * kCmPerM, 0.0);
  const bool uniform = wind_.uniform();
  const dvec3 uniform_wind = uniform ? wind_.AtAlong(0.0, time_) : dvec3(0.0);
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
    const dvec3 wind = uniform ? uniform_wind : wind_.AtAlong(along_[u], time_);
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
  const double dt = params.dt;
  const long steps = static_cast<long>(std::floor(params.duration / dt + 0.5));
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

int CountJitteringTips(const SwayRun& run, double from, double to) {
  int jittering = 0;
  for (const std::vector<dvec3>& track : run.tip_positions) {
    dvec3 lo(HUGE_VAL), hi(-HUGE_VAL), last_step(0.0);
    int steps = 0, reversals = 0;
    const dvec3* previous = nullptr;
    for (std::size_t k = 0; k < track.size() && k < run.times.size(); ++k) {
      if (run.times[k] < from || run.times[k] > to) continue;
      const dvec3& p = track[k];
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      if (previous) {
        dvec3 step = p - *previous;
        if (steps > 0 && glm::dot(step, last_step) < 0.0) ++reversals;
        last_step = step;
        ++steps;
      }
      previous = &p;
    }
    if (steps >= 2 && glm::length(hi - lo) > 2.0 && reversals > 0.4 * (steps - 1)) ++jittering;
  }
  return jittering;
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
  const double width = 800, height = 400, left = 70, right = 20, top = 30, bottom = 50;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  double t_max = run.times.empty() ? 1.0 : std::max(run.times.back(), 1e-9);
  // Signed displacement along the wind (positive downwind), so that the swing back past rest after
  // the wind stops shows; the distance from rest is drawn faintly behind it.
  double s = 0, c = 1;
  det::SinCos(params.wind_dir * (det::kPi / 180.0), &s, &c);
  const dvec3 along(c, 0.0, s);
  double lo = 0, hi = 0;
  for (const std::vector<dvec3>& series : run.tip_positions) {
    for (const dvec3& p : series) {
      double d = glm::length(p - series.front());
      if (!std::isfinite(d)) continue;
      hi = std::max(hi, d);
      lo = std::min(lo, glm::dot(p - series.front(), along));
    }
  }
  if (!(hi > 0)) hi = 1;
  if (lo < 0) lo = std::min(lo, -0.05 * hi);  // room for the zero line's label
  auto px = [&](double t) { return left + plot_w * t / t_max; };
  auto py = [&](double d) { return top + plot_h * (hi - d) / (hi - lo); };
  std::string svg;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"12\">\n",
                width, height, width, height);
  svg += buf;
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double on = std::min(params.gust_on, t_max), off = std::min(params.gust_off, t_max);
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
  // Zero line (rest) and the value labels of the vertical axis.
  std::snprintf(buf, sizeof buf,
                "<path d=\"M%.2f %.2f H%.2f\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n"
                "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\">0</text>\n"
                "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\">%.3g</text>\n",
                left, py(0), left + plot_w, left - 4, py(0) + 4, left - 4, top + 4, hi);
  svg += buf;
  if (lo < 0) {
    std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\">%.3g</text>\n",
                  left - 4, top + plot_h + 4, lo);
    svg += buf;
  }
  std::snprintf(buf, sizeof buf,
                "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">time (s), 0 to %.3g; shaded: "
                "wind %.3g m/s</text>\n",
                left + plot_w / 2, height - 15, t_max, params.wind_speed);
  svg += buf;
  std::snprintf(buf, sizeof buf,
                "<text x=\"15\" y=\"%.2f\" transform=\"rotate(-90 15 %.2f)\" "
                "text-anchor=\"middle\">tip displacement along the wind (cm); faint: distance "
                "from rest</text>\n",
                top + plot_h / 2, top + plot_h / 2);
  svg += buf;
  static const char* kColors[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e",
                                  "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  for (std::size_t t = 0; t < run.tip_positions.size(); ++t) {
    const std::vector<dvec3>& series = run.tip_positions[t];
    std::string signed_points, distance_points;
    for (std::size_t k = 0; k < series.size(); ++k) {
      dvec3 moved = series[k] - series.front();
      double d = glm::length(moved);
      if (!std::isfinite(d)) continue;
      std::snprintf(buf, sizeof buf, "%s%.2f,%.2f", signed_points.empty() ? "" : " ",
                    px(run.times[k]), py(glm::dot(moved, along)));
      signed_points += buf;
      std::snprintf(buf, sizeof buf, "%s%.2f,%.2f", distance_points.empty() ? "" : " ",
                    px(run.times[k]), py(d));
      distance_points += buf;
    }
    const char* color = kColors[t % (sizeof kColors / sizeof kColors[0])];
    svg += "<polyline fill=\"none\" stroke=\"" + std::string(color) +
           "\" stroke-width=\"1\" stroke-opacity=\"0.3\" points=\"" + distance_points + "\"/>\n";
    svg += "<polyline fill=\"none\" stroke=\"" + std::string(color) +
           "\" stroke-width=\"1.5\" points=\"" + signed_points + "\"/>\n";
    std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\" fill=\"%s\">branch %d</text>\n",
                  left + 10 + 90.0 * static_cast<double>(t), top - 10, color, run.tip_branches[t]);
    svg += buf;
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace niwa
