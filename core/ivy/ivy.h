// The ivy study's data (Shindo & Sakamoto, "A Model Generation Method for Climbing Plants Using
// Growth Simulation"): buds A/D/Z in a binary tree (Fig. 2), internodes of fixed length L between
// sucker points, axes, and what a run counted. Does not: grow (growth.h), print the L-string
// (lstring.h), report (ivy_report.h) or mesh (ivy_mesh.h).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "geom/query_stats.h"

namespace niwa::ivy {

// The support's geometry queries: a BVH, or brute force (the oracle; the state's "accel").
enum class Accel { kBvh, kLinear };

// Table 1: apical A (a branch tip), dormant D (mid-branch, may still branch), ending Z (never
// branches again).
enum class BudKind : uint8_t { kApical, kDormant, kEnding };
char BudSymbol(BudKind kind);  // 'A', 'D', 'Z'

// One bud = one sucker (attachment) point (§2.2). child[0]: the next bud on the same axis (made by
// p0), child[1]: the first bud of the lateral (made by p1; only on a Z).
struct Bud {
  int id = 0;
  BudKind kind = BudKind::kApical;
  glm::dvec3 pos{0.0};
  glm::dvec3 dir{0.0, 1.0, 0.0};  // unit direction of the internode ending here (seed: initial)
  double N = 0;                   // nutrient (§3.1)
  int plant = 0;                  // index of the seed point
  int axis = 0;
  int order = 0;  // branch order of the axis, 0 = main axis
  int index_on_axis = 0;
  int parent = -1;
  std::array<int, 2> child{-1, -1};
  int born_step = 0;
  int died_step = -1;                 // step at which it became Z (-1: not ended)
  bool released = false;              // E4: woken by a dead apex, breaks at the next step
  glm::dvec3 anchor{0.0};             // closest support point (= sucker end)
  int anchor_tri = -1;                // its triangle, -1 without a support
  double clearance = 0;               // |pos - anchor|, <= d
  glm::dvec3 outward{0.0, 0.0, 1.0};  // unit(pos - anchor): the sucker's opposite = leaf side
  // Hanging tendril (the row "hang", beyond §3.2): the internodes off the support up to and
  // including this bud's (0: on the support; no sucker, clearance may exceed d).
  int hang = 0;
};

struct Internode {
  int from_bud = 0, to_bud = 0;
  int step = 0;
  int axis = 0;
};

struct Axis {
  int id = 0;
  int order = 0;
  int parent_axis = -1;
  int base_bud = 0;  // the bud the axis grows from (a Z on the parent axis; the seed for order 0)
  int born_step = 0;
  int death_step = -1;                      // step at which its apex ended (p3), -1 = alive
  std::array<double, 3> rotation{0, 0, 0};  // R(θx, θy, θz) of the p1 that made it, degrees
};

// A grown ivy: every plant (one per seed point) in one store; the L-string is printed from it.
struct IvyModel {
  std::vector<Bud> buds;  // by id
  std::vector<Internode> internodes;
  std::vector<Axis> axes;
  std::vector<int> roots;  // seed bud of each plant
};

// Rejection reasons of the position search (E8), in the order they are tested.
// kBody (appended, issue 31 item 6): a point of the internode's body farther than body·d from
// every face (the row "body"; 0: off, nodes only).
enum Reject : int { kGravitropism, kBend, kFar, kNear, kCollision, kCrowding, kBody, kRejectCount };
const char* RejectName(int reason);

// The candidates of the tangent fan (growth.cpp's TangentRetry, parameter tangent_retry): 16
// directions around the tangent plane times 3 tilts toward the face, and 5 turns over an edge;
// ivy_budget counts them.
constexpr int kTangentFanCandidates = 53;

// What one step did (the nutrient ledger E5 and the rule counts).
struct StepLog {
  int p0 = 0, p1 = 0, p2 = 0, p3_a = 0, p3_d = 0, released_breaks = 0;
  double accumulated = 0, spent = 0, lost = 0;
  double nutrient_total = 0;  // ΣN over all buds after the step
};

struct GrowLog {
  double nutrient_start = 0;   // ΣN before step 1
  std::vector<StepLog> steps;  // steps[s - 1] is step s
  int steps_run = 0;
  int extinct_step = -1;      // first step after which no A and no D is left
  int first_break_step = -1;  // first p1
  int64_t attempts = 0, candidates = 0, retries = 0, failures = 0;
  // The tangent fan (tangent_retry): searches that reached it after every E10 retry failed, and
  // those it saved (found a valid position); its candidates are in `candidates` and `rejected`.
  int64_t tangent_retries = 0, tangent_saves = 0;
  // Hanging tendrils (the row "hang"): internodes grown off the support, tendrils started.
  int64_t hang_internodes = 0, tendrils = 0;
  std::array<int64_t, kRejectCount> rejected{};
  geom::QueryStats closest, segment;
  double ms_rules = 0, ms_search = 0;
  // Budgets (ivy_budget.h): Σ over the steps run of the buds each walked (work units), and the
  // line of the limit that stopped the growth early ("" when none did).
  double bud_steps = 0;
  std::string truncated_by;
};

}  // namespace niwa::ivy
