// The yearly growth loop (thesis 2.4): branching model, light model, hormone model, bending,
// dormancy break.
#include "tree/growth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "math/det_math_lanes.h"
#include "math/rotation.h"
#include "math/simd4.h"
#include "params/param_text.h"
#include "random/pcg32.h"
#include "tree/light.h"

namespace niwa {
namespace {

using Clock = std::chrono::steady_clock;
double MsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

float Clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

CosSin MakeTurn(float angle) { return {det::Cosf(angle), det::Sinf(angle)}; }

// RotateToward (math/rotation.h) with the angle given by its cosine and sine: same arithmetic.
glm::vec3 RotateToward(const glm::vec3& v, const glm::vec3& target, const CosSin& turn) {
  glm::vec3 axis = glm::cross(v, target);
  float length = glm::length(axis);
  if (length < 1e-6f) return v;
  return glm::normalize(RotateAbout(v, Divide(axis, length), turn.c, turn.s));
}

#if NIWA_SIMD
// Four vec3 at a time (one per lane) for the batched geometry below (math/simd4.h: each helper
// does, lane by lane, exactly the IEEE operations of its glm counterpart in glm's order, so
// batched and scalar results are the same bits).
using simd::Float4;
using simd::Int4;
using Vec4 = simd::Vec3x4;
#if defined(__SSE2__)
// For the bending of four shoots at a time (native only: in WASM under V8 the scalar lanes were
// faster).
// RotateToward(v, target, turn) of this file: v unchanged where v and target are parallel.
Vec4 RotateToward4(const Vec4& v, const Vec4& target, Float4 c, Float4 s) {
  Vec4 axis = simd::Cross(v, target);
  Float4 length = simd::Sqrt(simd::Dot(axis, axis));
  Int4 parallel = (Int4)(length < 1e-6f);
  Vec4 u{axis.x / length, axis.y / length, axis.z / length};
  Vec4 r = simd::Normalize(RotateAbout(v, u, c, s));
  return simd::Select(parallel, v, r);
}
#endif  // __SSE2__
#endif

// For each bud b of buds[0..count): b.direction = RotateToward(d, side, turns[i]) and
// b.azimuth = Orthonormalize(side, b.direction), where on entry b.direction holds d (the node's
// direction) and b.azimuth the side. Four buds at a time with SIMD where there is SIMD (SSE2,
// WASM simd128), lane by lane the same IEEE operations in the same order as the scalar functions
// (glm's cross, dot as (x + y) + z, normalize as v · (1 / sqrt(dot))), so the results are the
// same bits; the square roots and divisions, which bound this step, take a quarter of the
// instructions.
void TurnBuds(Bud* buds, const CosSin* turns, std::size_t count) {
  std::size_t i = 0;
#if NIWA_SIMD
  for (; i + 4 <= count; i += 4) {
    const Bud &b0 = buds[i], &b1 = buds[i + 1], &b2 = buds[i + 2], &b3 = buds[i + 3];
    const Vec4 d = simd::Gather(b0.direction, b1.direction, b2.direction, b3.direction);
    const Vec4 side = simd::Gather(b0.azimuth, b1.azimuth, b2.azimuth, b3.azimuth);
    const Float4 c{turns[i].c, turns[i + 1].c, turns[i + 2].c, turns[i + 3].c};
    const Float4 s{turns[i].s, turns[i + 1].s, turns[i + 2].s, turns[i + 3].s};
    // RotateToward(d, side, turn): Rodrigues about the unit axis d × side, then normalize.
    Vec4 axis = simd::Cross(d, side);
    Float4 length = simd::Sqrt(simd::Dot(axis, axis));
    Int4 parallel = (Int4)(length < 1e-6f);  // RotateToward returns d unchanged
    Vec4 u{axis.x / length, axis.y / length, axis.z / length};
    Vec4 r = simd::Normalize(RotateAbout(d, u, c, s));
    Vec4 direction = simd::Select(parallel, d, r);
    // Orthonormalize(side, direction).
    Float4 projection = simd::Dot(side, direction);
    Vec4 q{side.x - direction.x * projection, side.y - direction.y * projection,
           side.z - direction.z * projection};
    Float4 q_length = simd::Sqrt(simd::Dot(q, q));
    Vec4 azimuth{q.x / q_length, q.y / q_length, q.z / q_length};
    for (int k = 0; k < 4; ++k) {
      Bud& b = buds[i + static_cast<std::size_t>(k)];
      b.direction = simd::Lane(direction, k);
      b.azimuth = q_length[k] < 1e-6f ? AnyPerpendicular(b.direction) : simd::Lane(azimuth, k);
    }
  }
#endif
  for (; i < count; ++i) {
    Bud& b = buds[i];
    glm::vec3 side = b.azimuth;
    b.direction = RotateToward(b.direction, side, turns[i]);
    b.azimuth = Orthonormalize(side, b.direction);
  }
}

// Leaf directions of a shoot: leaf j = (i - 1)·per_node + k sits at node i, turned turns[k]
// around it: normalize(RotateAbout(azimuth[i], direction[i], turn) + direction[i]·lift). Four
// leaves at a time with SIMD where there is SIMD, the same bits as the scalar expression.
void LeafDirections(Leaf* leaves, std::size_t count, const glm::vec3* azimuth,
                    const glm::vec3* direction, const CosSin* turns, std::size_t per_node,
                    float lift) {
  auto scalar = [&](std::size_t j) {
    const std::size_t i = j / per_node + 1;
    const CosSin& turn = turns[j % per_node];
    glm::vec3 side = RotateAbout(azimuth[i], direction[i], turn.c, turn.s);
    leaves[j].direction = glm::normalize(side + direction[i] * lift);
  };
  std::size_t j = 0;
#if NIWA_SIMD
  for (; j + 4 <= count; j += 4) {
    std::size_t node[4];
    float c[4], s[4];
    for (std::size_t k = 0; k < 4; ++k) {
      node[k] = (j + k) / per_node + 1;
      c[k] = turns[(j + k) % per_node].c;
      s[k] = turns[(j + k) % per_node].s;
    }
    const glm::vec3 &a0 = azimuth[node[0]], &a1 = azimuth[node[1]], &a2 = azimuth[node[2]],
                    &a3 = azimuth[node[3]];
    const glm::vec3 &d0 = direction[node[0]], &d1 = direction[node[1]], &d2 = direction[node[2]],
                    &d3 = direction[node[3]];
    const Vec4 a = simd::Gather(a0, a1, a2, a3);
    const Vec4 d = simd::Gather(d0, d1, d2, d3);
    Vec4 side = RotateAbout(a, d, Float4{c[0], c[1], c[2], c[3]}, Float4{s[0], s[1], s[2], s[3]});
    Vec4 out = simd::Normalize(Vec4{side.x + d.x * lift, side.y + d.y * lift, side.z + d.z * lift});
    for (std::size_t k = 0; k < 4; ++k) {
      leaves[j + k].direction = glm::vec3(out.x[k], out.y[k], out.z[k]);
    }
  }
#endif
  for (; j < count; ++j) scalar(j);
}

// Turns 2π·k/count for k = 0..count-1 (bud and leaf positions around a node).
std::vector<CosSin> MakeTurnsAround(int count) {
  std::vector<CosSin> turns;
  for (int k = 0; k < count; ++k) {
    turns.push_back(MakeTurn(2.0f * kPi * static_cast<float>(k) / static_cast<float>(count)));
  }
  return turns;
}

// Direction of each internode and the phyllotaxis azimuth of each node (index 1..N); buffers
// reused from shoot to shoot.
struct NodeFrames {
  std::vector<glm::vec3> direction, azimuth;
};

void ComputeNodeFrames(const Branch& shoot, const std::vector<float>& turn_cos,
                       const std::vector<float>& turn_sin, NodeFrames& frames) {
  std::size_t n = shoot.nodes.size();
  // Entries 1..N are all written below, so the buffers are only resized (filling every entry of
  // them was 2.7 % of a sakura-thesis 15-year grow); entry 0 (no internode) is never read.
  frames.direction.resize(n);
  frames.azimuth.resize(n);
  frames.direction[0] = kUp;
  frames.azimuth[0] = glm::vec3(1, 0, 0);
  glm::vec3 transported = shoot.azimuth;
  for (std::size_t i = 1; i < n; ++i) {
    glm::vec3 d = glm::normalize(shoot.nodes[i] - shoot.nodes[i - 1]);
    transported = Orthonormalize(transported, d);  // parallel transport along the shoot
    frames.direction[i] = d;
    frames.azimuth[i] = RotateAbout(transported, d, turn_cos[i], turn_sin[i]);
  }
}

// Share t in [0, 1] of a hormone-dependent range: H / H_sat, or 1 with the hormone model off.
float HormoneShare(const ParamSet& params, float hormone) {
  return params.GetBool(ParamId::kUseHormone)
             ? Clamp01(hormone / static_cast<float>(params.Get(ParamId::kHSat)))
             : 1.0f;
}

float RangeAt(const ParamSet& params, ParamId low, ParamId high, float share) {
  float a = static_cast<float>(params.Get(low)), b = static_cast<float>(params.Get(high));
  return a + (b - a) * share;
}
}  // namespace

float HormoneRamp(const ParamSet& params, float hormone, ParamId low, ParamId high) {
  return RangeAt(params, low, high, HormoneShare(params, hormone));
}

float ShootLengthRamp(const ParamSet& params, float hormone_initial, bool dwarf, ParamId low,
                      ParamId high) {
  float t = HormoneShare(params, hormone_initial);
  float step = static_cast<float>(params.Get(ParamId::kLengthStep));
  return RangeAt(params, low, high, dwarf ? (1.0f - step) * t : t + step * (1.0f - t));
}

float BreakProbability(float hormone, float h_short, float h_sat, float p_dwarf, float p_long) {
  // Fig. 2.8 as described in 2.5.2: at most p_dwarf below the dwarf threshold H_s, at least p_dwarf
  // above it, rising linearly to p_long at H_sat.
  if (hormone < h_short) return h_short > 0.0f ? p_dwarf * Clamp01(hormone / h_short) : p_dwarf;
  if (h_sat <= h_short) return p_long;
  return p_dwarf + (p_long - p_dwarf) * Clamp01((hormone - h_short) / (h_sat - h_short));
}

float LateralBreakMax(const ParamSet& p, int year) {
  float age = Clamp01(static_cast<float>(year - 1) / static_cast<float>(p.Get(ParamId::kPLYears)));
  return static_cast<float>(p.Get(ParamId::kPLYoung) +
                            (p.Get(ParamId::kPLOld) - p.Get(ParamId::kPLYoung)) * age);
}

Sky GrowthSky(const ParamSet& p) {
  return MakeSky(static_cast<float>(p.Get(ParamId::kSunElevation)),
                 static_cast<float>(p.Get(ParamId::kSunAzimuth)),
                 static_cast<float>(p.Get(ParamId::kSunWeight)),
                 static_cast<float>(p.Get(ParamId::kSkyZenithRatio)));
}

BreakChances BudBreakChances(const ParamSet& p, float hormone, int year) {
  float p_lateral_max = LateralBreakMax(p, year);
  float p_tl_long = static_cast<float>(p.Get(ParamId::kPTlL));
  if (!p.GetBool(ParamId::kUseHormone)) return {1.0f, p_tl_long, p_lateral_max};
  float h_short = static_cast<float>(p.Get(ParamId::kHShort));
  float h_sat = static_cast<float>(p.Get(ParamId::kHSat));
  BreakChances chance;
  // Fig. 2.8: break probabilities from the shoot's hormone.
  chance.terminal = BreakProbability(hormone, h_short, h_sat, 1.0f, 1.0f);
  chance.terminally_lateral = BreakProbability(
      hormone, h_short, h_sat, static_cast<float>(p.Get(ParamId::kPTlS)), p_tl_long);
  // Lateral buds: P_l (fig. 2.9) scaled by the shoot's hormone, reaching it at H_sat. A dwarf
  // shoot's low hormone keeps the chance low; its lateral buds are flowers instead when
  // dwarf_flowers = 1 (sakura), which SetNextYearBuds decides.
  chance.lateral = p_lateral_max * Clamp01(hormone / h_sat);
  return chance;
}

Grower::Grower(const GrowRequest& request) : request_(request), rng_(request.seed) {
  // cos and sin of the phyllotaxis turn 2πϕ·i at node i (N <= 100), computed once per tree.
  float phi = static_cast<float>(request.params.Get(ParamId::kPhi));
  for (int i = 0; i <= 101; ++i) {
    float angle = 2.0f * kPi * phi * static_cast<float>(i);
    turn_cos_.push_back(det::Cosf(angle));
    turn_sin_.push_back(det::Sinf(angle));
  }
  const ParamSet& p = request.params;
  cap_branch_ = MakeTurn(Radians(static_cast<float>(p.Get(ParamId::kThetaBmaxB))));
  cap_node_ = MakeTurn(Radians(static_cast<float>(p.Get(ParamId::kThetaBmaxN))));
  sympodial_turn_ = MakeTurn(-Radians(static_cast<float>(p.Get(ParamId::kThetaN))));
  psi_t_ = MakeTurn(Radians(static_cast<float>(p.Get(ParamId::kPsiT))));
  psi_tl_ = MakeTurn(Radians(static_cast<float>(p.Get(ParamId::kPsiTl))));
  psi_l_ = MakeTurn(Radians(static_cast<float>(p.Get(ParamId::kPsiL))));
  around_leaves_ = MakeTurnsAround(std::max(1, p.GetInt(ParamId::kBL)));
  around_tl_ = MakeTurnsAround(p.GetInt(ParamId::kBTl));
  around_laterals_ = MakeTurnsAround(p.GetInt(ParamId::kBL));
  tree_.preset = request.preset;
  tree_.seed = request.seed;
  tree_.params = request.params;
}

void Grower::Kill(int branch_id) {
  // Iterative so that deep trees cannot overflow the stack (a buffer kept between calls).
  std::vector<int>& stack = kill_stack_;
  stack.assign(1, branch_id);
  while (!stack.empty()) {
    Branch& b = tree_.branches[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (!b.alive) continue;
    b.alive = false;
    internodes_ -= static_cast<long>(b.nodes.size()) - 1;
    for (int child : b.children) stack.push_back(child);
  }
}

void Grower::BreakBuds() {
  const ParamSet& p = tree_.params;
  // Leaves fall, flowers fade (deciduous): leaves grow only on the last year's shoots, flowers on
  // the branches listed when they opened.
  // A year a limit cuts short keeps them (issue 17 item 5: prune the growth, not the foliage), so
  // they are held aside until the year's shoots are made.
  std::vector<std::pair<int, std::vector<Leaf>>> held_leaves;
  std::vector<std::pair<int, std::vector<int>>> held_flowers;
  for (const std::vector<int>* ids : {&new_shoots_, &kept_foliage_}) {
    for (int id : *ids) {
      std::vector<Leaf>& leaves = tree_.branches[static_cast<std::size_t>(id)].leaves;
      if (!leaves.empty()) held_leaves.emplace_back(id, std::move(leaves));
      leaves.clear();
    }
  }
  for (int id : flowering_) {
    std::vector<int>& flowers = tree_.branches[static_cast<std::size_t>(id)].flowers;
    if (!flowers.empty()) held_flowers.emplace_back(id, std::move(flowers));
    flowers.clear();
  }
  flowering_.clear();
  // Terminal flower buds (terminal_flowers, Rhododendron): last year's shoots open a truss at
  // their tips this spring. No random draw, so trees without the row grow the same.
  std::vector<int> tip_flowering;
  if (p.GetBool(ParamId::kTerminalFlowers)) tip_flowering = new_shoots_;
  new_shoots_.clear();
  kept_foliage_.clear();
  const long refused_before = refused_shoots_;
  struct KeepFoliage {  // runs when BreakBuds returns
    Grower* grower;
    long refused_before;
    std::vector<std::pair<int, std::vector<Leaf>>>* leaves;
    std::vector<std::pair<int, std::vector<int>>>* flowers;
    ~KeepFoliage() {
      // Kept when a limit refused a shoot this year, or when a tree a limit already cut makes no
      // shoot at all (its refused buds left no buds to break: the foliage stays as it was).
      const bool cut = grower->refused_shoots_ != refused_before ||
                       (grower->tree_.truncated && grower->new_shoots_.empty());
      if (!cut) return;
      for (auto& [id, held] : *leaves) {
        Branch& b = grower->tree_.branches[static_cast<std::size_t>(id)];
        if (!b.alive || !b.leaves.empty()) continue;
        b.leaves = std::move(held);
        grower->kept_foliage_.push_back(id);
      }
      for (auto& [id, held] : *flowers) {
        Branch& b = grower->tree_.branches[static_cast<std::size_t>(id)];
        if (!b.alive || !b.flowers.empty()) continue;
        b.flowers = std::move(held);
        grower->flowering_.push_back(id);
      }
    }
  } keep_foliage{this, refused_before, &held_leaves, &held_flowers};
  auto make_shoot = [&](int parent, int parent_node, ShootKind kind, glm::vec3 direction,
                        glm::vec3 azimuth, float hormone_initial) {
    Branch shoot{};
    shoot.id = static_cast<int>(tree_.branches.size());
    shoot.parent = parent;
    shoot.parent_node = parent_node;
    shoot.year = tree_.years;
    shoot.kind = kind;
    shoot.alive = true;
    shoot.bud_direction = direction;
    shoot.azimuth = Orthonormalize(azimuth, direction);
    shoot.hormone_initial = hormone_initial;
    shoot.dwarf = p.GetBool(ParamId::kUseHormone) &&
                  hormone_initial < static_cast<float>(p.Get(ParamId::kHShort));
    // Step 1 of 2.4.3: node count N and internode length D from the hormone (fig. 2.5).
    int nodes =
        std::max(1, static_cast<int>(std::lround(ShootLengthRamp(
                        p, hormone_initial, shoot.dwarf, ParamId::kNLow, ParamId::kNHigh))));
    float length =
        ShootLengthRamp(p, hormone_initial, shoot.dwarf, ParamId::kDLow, ParamId::kDHigh);
    if (shoot.dwarf) length *= static_cast<float>(p.Get(ParamId::kDwarfInternodeRatio));
    shoot.internode_length = length;
    if (internodes_ + nodes > p.GetInt(ParamId::kMaxInternodes)) {
      Truncate(
          "max_internodes",
          "the tree reached " + std::to_string(p.GetInt(ParamId::kMaxInternodes)) + " internodes",
          "raise max_internodes (at most " + FormatNumber(Spec(ParamId::kMaxInternodes).max_value) +
              ") or lower " + request_.limits.years_name);
      return;
    }
    const GrowLimits& limits = request_.limits;
    if (limits.max_internodes >= 0 && internodes_ + nodes > limits.max_internodes) {
      stopped_ = true;
      Truncate(limits.internode_limit,
               "the tree reached " + std::to_string(limits.max_internodes) + " internodes",
               "lower " + limits.years_name + ", N_high or B_l");
      return;
    }
    const double made = made_internodes_ + nodes, branches = made_branches_ + 1;
    if (limits.max_bytes >= 0 &&
        limits.base_bytes + limits.bytes_per_branch * branches + limits.bytes_per_internode * made +
                limits.bytes_per_alive_internode * double(internodes_ + nodes) >
            limits.max_bytes) {
      stopped_ = true;  // no shoot fits any more: the years after would only add time
      Truncate(limits.memory_limit,
               "more internodes would need more than " + FormatBytes(limits.max_bytes),
               "lower " + limits.years_name + ", N_high or B_l" + RaiseHint(limits.memory_limit));
      return;
    }
    if (limits.max_seconds >= 0 &&
        limits.seconds_per_internode_year * (internode_years_ + double(internodes_ + nodes)) +
                limits.seconds_per_branch * branches + limits.seconds_per_internode * made >
            limits.max_seconds) {
      stopped_ = true;
      Truncate(limits.seconds_limit,
               "more internodes would take more than " + FormatSeconds(limits.max_seconds),
               "lower " + limits.years_name + RaiseHint(limits.seconds_limit));
      return;
    }
    made_internodes_ = made;
    made_branches_ = branches;
    internodes_ += nodes;
    glm::vec3 base = parent < 0 ? glm::vec3(0.0f)
                                : tree_.branches[static_cast<std::size_t>(parent)]
                                      .nodes[static_cast<std::size_t>(parent_node)];
    shoot.nodes.assign(static_cast<std::size_t>(nodes) + 1, base);
    shoot.light = 1.0f;
    shoot.light_direction = kUp;
    if (parent >= 0) tree_.branches[static_cast<std::size_t>(parent)].children.push_back(shoot.id);
    new_shoots_.push_back(shoot.id);
    tree_.branches.push_back(std::move(shoot));
  };

  if (tree_.branches.empty()) {
    make_shoot(-1, 0, ShootKind::kSeedling, kUp, glm::vec3(1, 0, 0),
               static_cast<float>(p.Get(ParamId::kHInit)));
    MakeBasalShoots(make_shoot);
    return;
  }
  // Only the branches with a breaking bud (listed by SetNextYearBuds, in id order) are visited.
  for (int breaking_id : breaking_) {
    const std::size_t id = static_cast<std::size_t>(breaking_id);
    if (!tree_.branches[id].alive) continue;
    // Room for this year's shoots and flowers at once, instead of growing the lists one by one.
    std::size_t shoots = 0, flowers = 0;
    for (const Bud& bud : tree_.branches[id].buds) {
      if (bud.state == BudState::kBreaking) ++(bud.flower ? flowers : shoots);
    }
    if (shoots == 0 && flowers == 0) continue;
    tree_.branches[id].children.reserve(tree_.branches[id].children.size() + shoots);
    if (flowers > 0) {
      tree_.branches[id].flowers.reserve(flowers);
      flowering_.push_back(static_cast<int>(id));
    }
    for (std::size_t k = 0; k < tree_.branches[id].buds.size(); ++k) {
      Bud bud = tree_.branches[id].buds[k];
      if (bud.state != BudState::kBreaking) continue;
      tree_.branches[id].buds[k].state = BudState::kUsed;
      if (bud.flower) {
        tree_.branches[id].flowers.push_back(bud.node);
        continue;
      }
      // Eq. 2.1: the new shoot inherits a share of its parent's hormone of last year.
      ParamId alpha = bud.kind == ShootKind::kLateral             ? ParamId::kAlphaL
                      : bud.kind == ShootKind::kTerminallyLateral ? ParamId::kAlphaTl
                                                                  : ParamId::kAlphaT;
      float inherited = static_cast<float>(p.Get(alpha)) * tree_.branches[id].hormone;
      make_shoot(static_cast<int>(id), bud.node, bud.kind, bud.direction, bud.azimuth,
                 inherited + bud.extra_hormone);
    }
  }
  for (int id : tip_flowering) {
    Branch& b = tree_.branches[static_cast<std::size_t>(id)];
    if (!b.alive || b.nodes.size() < 2) continue;
    if (b.flowers.empty()) flowering_.push_back(id);
    b.flowers.push_back(static_cast<int>(b.nodes.size()) - 1);
  }
  MakeBasalShoots(make_shoot);
}

template <typename MakeShoot>
void Grower::MakeBasalShoots(MakeShoot& make_shoot) {
  const ParamSet& p = tree_.params;
  // Basal shoots (not in the thesis, docs/tree-species.md): in years 1..k_c, B_c shoots break
  // from the root collar (node 0 of the seedling) with the seedling's hormone H⁰ = H_init, leaning
  // ψ_tl from the vertical, each a golden angle (2π(1 − 1/ϕ_g) ≈ 137.5°) round from the one
  // before. No random draws, so a tree without them draws the same numbers as before.
  const int basal = p.GetInt(ParamId::kBasalShoots);
  if (basal > 0 && tree_.years <= p.GetInt(ParamId::kBasalYears) && !tree_.branches.empty() &&
      tree_.branches[0].alive) {
    const float golden_angle = 2.3999632f;
    for (int k = 0; k < basal && !stopped_; ++k) {
      const float angle = golden_angle * static_cast<float>(basal_made_++);
      const glm::vec3 side(det::Cosf(angle), 0.0f, det::Sinf(angle));
      make_shoot(0, 0, ShootKind::kTerminallyLateral, RotateToward(kUp, side, psi_tl_), side,
                 static_cast<float>(p.Get(ParamId::kHInit)));
    }
  }
}

bool Grower::OnLeader(const Branch& shoot) const {
  const Branch* b = &shoot;
  while (b->kind == ShootKind::kTerminal && b->parent >= 0) {
    b = &tree_.branches[static_cast<std::size_t>(b->parent)];
  }
  return b->kind == ShootKind::kSeedling;
}

void Grower::LayOutShoots(bool bend) {
  const ParamSet& p = tree_.params;
  const bool sympodial = p.GetBool(ParamId::kSympodial);
  const float theta_n = Radians(static_cast<float>(p.Get(ParamId::kThetaN)));
  const bool zigzag = sympodial && theta_n != 0.0f;
  const float cap_branch = Radians(static_cast<float>(p.Get(ParamId::kThetaBmaxB)));
  const float cap_node = Radians(static_cast<float>(p.Get(ParamId::kThetaBmaxN)));

  // Node i of a shoot that bends or zigzags: eqs. 2.6-2.9 and the sympodial turn.
  auto step = [&](ShootLayout& l, std::size_t i) {
    if (l.b > 0.0f) {
      float difference = AngleBetween(l.direction, l.target);  // eqs. 2.6, 2.8
      float cap = i == 1 ? cap_branch : cap_node;              // eqs. 2.7, 2.9
      float angle = l.b * difference;
      if (!(cap < angle)) {  // std::min(angle, cap)
        double c, s;
        det::SinCos(angle, &s, &c);  // as det::Cosf, det::Sinf, in one call
        l.direction = RotateToward(l.direction, l.target,
                                   CosSin{static_cast<float>(c), static_cast<float>(s)});
      } else {
        l.direction = RotateToward(l.direction, l.target, i == 1 ? cap_branch_ : cap_node_);
      }
    }
    if (zigzag) {
      // Sympodial zigzag: each node turns θ_N away from the side its bud sits on (steps 5, 8).
      glm::vec3 side = RotateAbout(Orthonormalize(l.azimuth, l.direction), l.direction,
                                   turn_cos_[i], turn_sin_[i]);
      l.direction = RotateToward(l.direction, side, sympodial_turn_);
    }
    if (zigzag) l.azimuth = Orthonormalize(l.azimuth, l.direction);  // only the zigzag reads it
    Branch& shoot = *l.shoot;
    shoot.nodes[i] = shoot.nodes[i - 1] + l.direction * shoot.internode_length;
  };

  // Every node depends on the one before it through a long chain of square roots and divisions,
  // so shoots are laid out kLanes at a time, node i of each in turn: the processor overlaps the
  // independent chains. Each shoot gets exactly the arithmetic it would get alone.
  constexpr std::size_t kLanes = 4;
  ShootLayout lanes[kLanes];
  std::size_t used = 0, longest = 0;
  auto flush = [&]() {
#if defined(__SSE2__)  // in WASM (V8) the scalar lanes below were faster: 22.8 vs 26.6 ms
    if (!zigzag) {
      // Without the zigzag every lane is a bending shoot (b > 0): node i of all four lanes at
      // once with SIMD, eqs. 2.6-2.9 as in `step` (det_math two lanes at a time, the rotation
      // four), the same bits. Idle lanes turn a dummy and are not written.
      for (std::size_t i = 1; i < longest; ++i) {
        Vec4 direction{}, target{};
        Float4 b{}, difference_of_lane{};
        for (std::size_t k = 0; k < used; ++k) {
          const ShootLayout& l = lanes[k];
          direction.x[k] = l.direction.x;
          direction.y[k] = l.direction.y;
          direction.z[k] = l.direction.z;
          target.x[k] = l.target.x;
          target.y[k] = l.target.y;
          target.z[k] = l.target.z;
          b[k] = l.b;
        }
        // AngleBetween (eqs. 2.6, 2.8): the dot product clamped to [-1, 1], then det::Acosf.
        Float4 cosine = simd::Dot(direction, target);
        cosine = simd::Select((Int4)(cosine > 1.0f), simd::Splat4(1.0f), cosine);
        cosine = simd::Select((Int4)(cosine < -1.0f), simd::Splat4(-1.0f), cosine);
        difference_of_lane = det::Acosf(cosine);
        const Float4 angle = b * difference_of_lane;
        Float4 s_of_angle, c_of_angle;
        det::SinCosf(angle, &s_of_angle, &c_of_angle);
        // Eqs. 2.7, 2.9: angles above the cap turn by the cap.
        const float cap = i == 1 ? cap_branch : cap_node;
        const CosSin& cap_turn = i == 1 ? cap_branch_ : cap_node_;
        const Int4 capped = (Int4)(cap < angle);
        const Float4 c = simd::Select(capped, simd::Splat4(cap_turn.c), c_of_angle);
        const Float4 s = simd::Select(capped, simd::Splat4(cap_turn.s), s_of_angle);
        const Vec4 turned = RotateToward4(direction, target, c, s);
        for (std::size_t k = 0; k < used; ++k) {
          ShootLayout& l = lanes[k];
          Branch& shoot = *l.shoot;
          if (i >= shoot.nodes.size()) continue;
          if (l.b > 0.0f) l.direction = glm::vec3(turned.x[k], turned.y[k], turned.z[k]);
          shoot.nodes[i] = shoot.nodes[i - 1] + l.direction * shoot.internode_length;
        }
      }
      used = 0;
      longest = 0;
      return;
    }
#endif
    for (std::size_t i = 1; i < longest; ++i) {
      for (std::size_t k = 0; k < used; ++k) {
        if (i < lanes[k].shoot->nodes.size()) step(lanes[k], i);
      }
    }
    used = 0;
    longest = 0;
  };

  const float standard_height = static_cast<float>(p.Get(ParamId::kStandardHeight));
  const float b_h = static_cast<float>(p.Get(ParamId::kBH));
  for (int id : new_shoots_) {
    Branch& shoot = tree_.branches[static_cast<std::size_t>(id)];
    if (!shoot.alive) continue;
    // Trained standard (not in the thesis, docs/tree-species.md): a leader shoot whose base is
    // below H_std is tied to the stake: it grows straight up, node i at base + i·D·up.
    if (standard_height > 0.0f && shoot.nodes.front().y < standard_height && OnLeader(shoot)) {
      for (std::size_t i = 1; i < shoot.nodes.size(); ++i) {
        shoot.nodes[i] = shoot.nodes[i - 1] + kUp * shoot.internode_length;
      }
      continue;
    }
    // Steps 2-3 of 2.4.3: bending rates from the hormone, eqs. 2.4 and 2.5.
    float b = 0.0f;
    glm::vec3 target = kUp;
    if (bend) {
      // Fig. 2.16 (d), the thesis's own: the rate follows the hormone; (c): it follows the light
      // L.
      float b_light = p.GetBool(ParamId::kBLByLight)
                          ? static_cast<float>(p.Get(ParamId::kBLLow) +
                                               (p.Get(ParamId::kBLHigh) - p.Get(ParamId::kBLLow)) *
                                                   static_cast<double>(shoot.light))
                          : HormoneRamp(p, shoot.hormone, ParamId::kBLLow, ParamId::kBLHigh);
      float b_gravity = HormoneRamp(p, shoot.hormone, ParamId::kBGLow, ParamId::kBGHigh);
      glm::vec3 pull = b_light * shoot.light_direction + b_gravity * kUp;  // b_L v_L - b_g v_g
      // Plagiotropism (not in the thesis, docs/tree-species.md): + b_h v_h, v_h the horizontal
      // unit of the bud direction, for every shoot but the leader.
      if (b_h > 0.0f && !OnLeader(shoot)) {
        glm::vec3 flat(shoot.bud_direction.x, 0.0f, shoot.bud_direction.z);
        float flat_length = glm::length(flat);
        if (flat_length > 1e-6f) pull += (b_h / flat_length) * flat;
      }
      b = glm::length(pull);            // eq. 2.4
      if (b > 0.0f) target = pull / b;  // eq. 2.5
    }
    if (b == 0.0f && !zigzag) {  // straight: no rotations needed
      const glm::vec3 direction = shoot.bud_direction;
      for (std::size_t i = 1; i < shoot.nodes.size(); ++i) {
        shoot.nodes[i] = shoot.nodes[i - 1] + direction * shoot.internode_length;
      }
      continue;
    }
    lanes[used++] = {&shoot, shoot.bud_direction, shoot.azimuth, target, b};
    longest = std::max(longest, shoot.nodes.size());
    if (used == kLanes) flush();
  }
  flush();
}

void Grower::MakeLeafSpheres() {
  // Thesis 2.3.2: each shoot of the year a shading sphere around its straight layout.
  leaf_spheres_.clear();
  leaf_spheres_.reserve(new_shoots_.size());
  float leaf = static_cast<float>(tree_.params.Get(ParamId::kLeafSize));
  for (int id : new_shoots_) {
    const Branch& s = tree_.branches[static_cast<std::size_t>(id)];
    glm::vec3 base = s.nodes.front(), tip = s.nodes.back();
    leaf_spheres_.push_back({0.5f * (base + tip), 0.5f * glm::length(tip - base) + 0.5f * leaf});
  }
}

void Grower::ComputeLight(const std::vector<LeafSphere>& foreign_shade) {
  const ParamSet& p = tree_.params;
  if (!p.GetBool(ParamId::kUseLight)) return;  // L = 1, v_L = up, no death
  const std::vector<LeafSphere>& spheres = leaf_spheres_;
  Sky sky = GrowthSky(p);
  const float opacity = static_cast<float>(p.Get(ParamId::kSphereOpacity));
  std::vector<LightSample> samples =
      foreign_shade.empty()
          ? ComputeLightGrid(spheres, sky, opacity, light_buffers_)
          : ComputeLightGrid(spheres, foreign_shade, sky, opacity, light_buffers_);
  float k = static_cast<float>(p.Get(ParamId::kKDeath));
  float light_scale = static_cast<float>(p.Get(ParamId::kLightScale));
  for (std::size_t i = 0; i < new_shoots_.size(); ++i) {
    Branch& s = tree_.branches[static_cast<std::size_t>(new_shoots_[i])];
    s.light = light_scale * samples[i].light;
    s.light_direction = samples[i].direction;
    // 2.4.1: death below a threshold drawn from k × U(0.5, 1).
    float threshold = k * static_cast<float>(rng_.Uniform(0.5, 1.0));
    if (s.parent >= 0 && s.light < threshold) Kill(s.id);
  }
}

void Grower::ComputeHormone() {
  const ParamSet& p = tree_.params;
  float beta_c = static_cast<float>(p.Get(ParamId::kBetaC));
  float beta_p = static_cast<float>(p.Get(ParamId::kBetaP));
  float gamma = static_cast<float>(p.Get(ParamId::kGamma));
  float h_dwarf = static_cast<float>(p.Get(ParamId::kHS));
  float h_long = static_cast<float>(p.Get(ParamId::kHL));
  // Children always have larger ids, so a descending sweep sees every child before its parent:
  // hormone flows from the tips towards the trunk (thesis 2.4.2, rule 4).
  for (std::size_t n = tree_.branches.size(); n-- > 0;) {
    Branch& b = tree_.branches[n];
    if (!b.alive) continue;
    b.hormone_previous = b.hormone;
    if (b.year == tree_.years) {
      b.hormone_previous = b.hormone_initial;
      b.hormone = beta_c * b.hormone_initial + (b.dwarf ? h_dwarf : h_long) * b.light;  // eq. 2.2
    } else {
      float from_children = 0.0f;
      for (int c : b.children) {
        const Branch& child = tree_.branches[static_cast<std::size_t>(c)];
        if (child.alive) from_children += child.hormone;
      }
      b.hormone = beta_p * b.hormone_previous + gamma * from_children;  // eq. 2.3
    }
  }
}

void Grower::ThickenBranches() {
  // Pipe model (2.4.4): each branch's cross-section grows in proportion to all leaves above it.
  float per_leaf = static_cast<float>(tree_.params.Get(ParamId::kPipeAreaPerLeaf));
  std::vector<int> leaves_above(tree_.branches.size(), 0);
  for (std::size_t n = tree_.branches.size(); n-- > 0;) {
    Branch& b = tree_.branches[n];
    if (!b.alive) continue;
    leaves_above[n] += static_cast<int>(b.leaves.size());
    b.cross_section += per_leaf * static_cast<float>(leaves_above[n]);
    // A shoot on node 0 of its parent (a basal shoot on the root collar) is a stem of its own
    // beside it: its leaves do not thicken the parent. No thesis shoot starts at node 0.
    if (b.parent >= 0 && b.parent_node > 0) {
      leaves_above[static_cast<std::size_t>(b.parent)] += leaves_above[n];
    }
  }
}

void Grower::SetNextYearBuds() {
  const ParamSet& p = tree_.params;
  int terminal_buds = p.GetInt(ParamId::kBT), tl_buds = p.GetInt(ParamId::kBTl);
  int lateral_buds = p.GetInt(ParamId::kBL);
  bool dwarf_flowers = p.GetBool(ParamId::kDwarfLateralFlowers);
  float leaf_lift = 0.6f;

  NodeFrames f;
  breaking_.clear();
  for (int id : new_shoots_) {
    Branch& s = tree_.branches[static_cast<std::size_t>(id)];
    if (!s.alive) continue;
    ComputeNodeFrames(s, turn_cos_, turn_sin_, f);
    int tip = static_cast<int>(s.nodes.size()) - 1;
    // Leaves: one per lateral bud position at every node (at least one per node).
    int per_node = std::max(1, lateral_buds);
    s.leaves.reserve(static_cast<std::size_t>(tip * per_node));
    s.buds.reserve(
        static_cast<std::size_t>((terminal_buds > 0 ? 1 : 0) + tl_buds + (tip - 1) * lateral_buds));
    const std::size_t first_leaf = s.leaves.size();
    for (int i = 1; i <= tip; ++i) {
      for (int k = 0; k < per_node; ++k) s.leaves.push_back({i, glm::vec3(0.0f)});
    }
    LeafDirections(s.leaves.data() + first_leaf, s.leaves.size() - first_leaf, f.azimuth.data(),
                   f.direction.data(), around_leaves_.data(), static_cast<std::size_t>(per_node),
                   leaf_lift);
    bool any_breaking = false;
    // The terminal bud is turned at once (its azimuth is set from its direction below); the
    // others are stored with the node's direction and their side and turned in one batch
    // (TurnBuds) at the end: the random draws do not depend on the geometry.
    bud_turns_.clear();
    auto add_bud = [&](ShootKind kind, int node, glm::vec3 side, const CosSin& angle,
                       float probability, bool flower) {
      glm::vec3 d = f.direction[static_cast<std::size_t>(node)];
      Bud bud{};
      bud.kind = kind;
      bud.node = node;
      if (kind == ShootKind::kTerminal) {
        bud.direction = RotateToward(d, side, angle);
        bud.azimuth = Orthonormalize(side, bud.direction);
      } else {
        bud.direction = d;
        bud.azimuth = side;
        bud_turns_.push_back(angle);
      }
      bud.flower = flower;
      bool breaks = flower || rng_.Bernoulli(probability);
      bud.state = breaks ? BudState::kBreaking : BudState::kDormant;
      any_breaking |= breaks;
      s.buds.push_back(bud);
    };
    BreakChances chance = BudBreakChances(p, s.hormone, tree_.years);
    float p_terminal = chance.terminal, p_tl = chance.terminally_lateral,
          p_lateral = chance.lateral;
    glm::vec3 tip_azimuth = f.azimuth[static_cast<std::size_t>(tip)];
    glm::vec3 tip_direction = f.direction[static_cast<std::size_t>(tip)];
    if (terminal_buds > 0) {
      add_bud(ShootKind::kTerminal, tip, tip_azimuth, psi_t_, p_terminal, false);
      // The terminal shoot continues the phyllotaxis spiral: its node 1 is one step (φ) past this
      // shoot's tip node, as node i + 1 is one step past node i. (It used to start one step later:
      // with φ = 1/2 and one node per shoot, the binary pattern then split to the same side every
      // year and its main axis curved over by 45° in eight years.)
      s.buds.back().azimuth = Orthonormalize(tip_azimuth, s.buds.back().direction);
    }
    for (int k = 0; k < tl_buds; ++k) {
      const CosSin& turn = around_tl_[static_cast<std::size_t>(k)];
      glm::vec3 side = RotateAbout(tip_azimuth, tip_direction, turn.c, turn.s);
      add_bud(ShootKind::kTerminallyLateral, tip, side, psi_tl_, p_tl, false);
    }
    for (int i = 1; i < tip; ++i) {
      for (int k = 0; k < lateral_buds; ++k) {
        const CosSin& turn = around_laterals_[static_cast<std::size_t>(k)];
        glm::vec3 side = RotateAbout(f.azimuth[static_cast<std::size_t>(i)],
                                     f.direction[static_cast<std::size_t>(i)], turn.c, turn.s);
        add_bud(ShootKind::kLateral, i, side, psi_l_, p_lateral, s.dwarf && dwarf_flowers);
      }
    }
    TurnBuds(s.buds.data() + (s.buds.size() - bud_turns_.size()), bud_turns_.data(),
             bud_turns_.size());
    if (any_breaking) breaking_.push_back(id);
  }
  const std::size_t new_breaking = breaking_.size();

  // Dormancy break (2.4.6) on the older branches: by threshold, and by a sudden drop.
  struct Trigger {
    ParamId threshold, chance, most, extra;
  };
  const Trigger by_threshold{ParamId::kHBL, ParamId::kDeltaL, ParamId::kBBL, ParamId::kHNL};
  const Trigger by_drop{ParamId::kHBD, ParamId::kDeltaD, ParamId::kBBD, ParamId::kHND};
  const float h_b_l = static_cast<float>(p.Get(ParamId::kHBL));
  const float h_b_d = static_cast<float>(p.Get(ParamId::kHBD));
  for (Branch& b : tree_.branches) {
    if (!b.alive || b.year == tree_.years) continue;
    // "H becomes <= H_b^l" (2.4.6): an event when H crosses the threshold, not every year below it.
    bool low = h_b_l > 0.0f && b.hormone < h_b_l && b.hormone_previous >= h_b_l;
    bool dropped = h_b_d > 0.0f && b.hormone < b.hormone_previous / h_b_d;
    for (const Trigger* trigger : {low ? &by_threshold : nullptr, dropped ? &by_drop : nullptr}) {
      if (!trigger) continue;
      float chance = static_cast<float>(p.Get(trigger->chance));
      int most = p.GetInt(trigger->most), broken = 0;
      for (Bud& bud : b.buds) {  // Step 1: each dormant bud breaks with chance δ; Step 2: cap B_b
        if (broken >= most) break;
        if (bud.state != BudState::kDormant || bud.flower) continue;
        if (!rng_.Bernoulli(chance)) continue;
        bud.state = BudState::kBreaking;
        bud.extra_hormone = static_cast<float>(p.Get(trigger->extra));  // Step 3: H_n
        ++broken;
      }
      if (broken > 0 && (breaking_.size() == new_breaking || breaking_.back() != b.id)) {
        breaking_.push_back(b.id);
      }
    }
  }
  // Both parts are in id order: merged, BreakBuds visits the branches in id order as before.
  std::inplace_merge(breaking_.begin(),
                     breaking_.begin() + static_cast<std::ptrdiff_t>(new_breaking),
                     breaking_.end());
}

void Grower::ApplyPrunes() {
  for (const Prune& prune : request_.prunes) {
    if (prune.year != tree_.years) continue;
    if (prune.branch >= 0 && prune.branch < static_cast<int>(tree_.branches.size())) {
      Kill(prune.branch);
    }
    if (prune.since_year >= 0) {
      for (Branch& b : tree_.branches) {
        if (b.alive && b.year >= prune.since_year) Kill(b.id);
      }
    }
  }
}

void Grower::RaiseCrown() {
  // Gardener's trim (docs/tree-species.md): cut every shoot whose tip hangs below trim_height.
  float trim = static_cast<float>(tree_.params.Get(ParamId::kTrimHeight));
  if (trim > 0.0f) {
    for (const Branch& b : tree_.branches) {
      if (b.alive && b.parent >= 0 && b.nodes.back().y < trim) Kill(b.id);
    }
  }
  // Nursery crown raising (docs/tree-species.md): cut every side shoot whose base sits below
  // min(clear_stem, 0.4 height); the seedling and its chain of terminal shoots (the trunk) stay.
  float clear_stem = static_cast<float>(tree_.params.Get(ParamId::kClearStem));
  if (clear_stem <= 0.0f) return;
  float height = 0.0f;
  for (const Branch& b : tree_.branches) {
    if (!b.alive) continue;
    for (const glm::vec3& n : b.nodes) height = std::max(height, n.y);
  }
  float line = std::min(clear_stem, 0.4f * height);
  for (const Branch& b : tree_.branches) {
    if (!b.alive || b.kind == ShootKind::kSeedling || b.kind == ShootKind::kTerminal) continue;
    if (b.nodes.front().y < line) Kill(b.id);
  }
}

void Grower::Truncate(const std::string& limit, const std::string& why, const std::string& change) {
  ++refused_shoots_;
  tree_.truncated = true;
  if (!tree_.truncated_by.empty()) return;
  tree_.truncated_by = TruncatedLine(
      limit, "in year " + std::to_string(tree_.years) + " of " + std::to_string(request_.years),
      why, change);
}

Estimate Grower::estimate() const {
  const GrowLimits& limits = request_.limits;
  Estimate e;
  e.memory_bytes = limits.base_bytes + limits.bytes_per_branch * made_branches_ +
                   limits.bytes_per_internode * made_internodes_;
  e.seconds = limits.seconds_per_internode_year * internode_years_ +
              limits.seconds_per_branch * made_branches_ +
              limits.seconds_per_internode * made_internodes_;
  e.what = "growing the tree";
  return e;
}

void Grower::GrowYear() {
  StartYear();
  FinishYear();
}

void Grower::StartYear() {
  if (stopped_ || year_started_) return;
  const GrowLimits& limits = request_.limits;
  // A year costs at least its alive internodes' light, hormone and thickening.
  if (limits.max_seconds >= 0 &&
      estimate().seconds + limits.seconds_per_internode_year * double(internodes_) >
          limits.max_seconds) {
    stopped_ = true;
    ++tree_.years;  // the year that would not fit, for the line
    Truncate(limits.seconds_limit,
             "another year would take more than " + FormatSeconds(limits.max_seconds),
             "lower " + limits.years_name + RaiseHint(limits.seconds_limit));
    --tree_.years;
    return;
  }
  Clock::time_point start = Clock::now();
  ++tree_.years;
  BreakBuds();
  LayOutShoots(false);
  MakeLeafSpheres();
  ms_started_ = MsSince(start);
  year_started_ = true;
}

void Grower::FinishYear(const std::vector<LeafSphere>& foreign_shade) {
  // Not stopped_: a limit met during this year's bud break stops the years after, not this one.
  if (!year_started_) return;
  year_started_ = false;
  Clock::time_point light_start = Clock::now();
  ComputeLight(foreign_shade);
  timings_.ms_light += MsSince(light_start);

  Clock::time_point hormone_start = Clock::now();
  ComputeHormone();
  timings_.ms_hormone += MsSince(hormone_start);

  Clock::time_point shape_start = Clock::now();
  LayOutShoots(true);
  SetNextYearBuds();
  ThickenBranches();
  ApplyPrunes();
  RaiseCrown();
  internode_years_ += static_cast<double>(internodes_);
  const double shape = MsSince(shape_start);
  timings_.ms_branching += ms_started_ + shape;
  timings_.ms_total += ms_started_ + MsSince(light_start);
}

Tree GrowTree(const GrowRequest& request, GrowthTimings* timings) {
  Grower grower(request);
  while (grower.year() < request.years && !grower.stopped()) grower.GrowYear();
  if (timings) *timings = grower.timings();
  return grower.TakeTree();
}

TreeStats ComputeStats(const Tree& tree) {
  TreeStats stats;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    ++stats.branches;
    stats.internodes += static_cast<int>(b.nodes.size()) - 1;
    stats.leaves += static_cast<int>(b.leaves.size());
    stats.flowers += static_cast<int>(b.flowers.size());
    for (const glm::vec3& n : b.nodes) stats.height = std::max(stats.height, double(n.y));
  }
  return stats;
}

float BranchRadius(const Branch& branch) {
  return std::max(0.05f, std::sqrt(branch.cross_section / kPi));
}

}  // namespace niwa
