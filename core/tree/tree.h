// Tree data: branches (one year's shoot each), their node points, buds, leaves and flowers.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "tree/tree_params.h"

namespace niwa {

// Where a shoot came from (thesis 2.3.1 d, 2.4.6).
enum class ShootKind : uint8_t { kSeedling, kTerminal, kTerminallyLateral, kLateral };

enum class BudState : uint8_t {
  kBreaking,  // will break at the start of next year (step 1 of the yearly loop)
  kDormant,   // did not break; can break later through dormancy break (2.4.6)
  kUsed,      // has become a shoot or a flower
};

struct Bud {
  ShootKind kind;
  int node;             // index into Branch::nodes where the bud sits
  glm::vec3 direction;  // unit growth direction of the shoot it would make
  glm::vec3 azimuth;    // unit vector across the direction, phyllotaxis reference for the shoot
  BudState state;
  bool flower;          // flower bud (sakura: laterals of dwarf shoots)
  float extra_hormone;  // H_n added at bud break when broken through dormancy break
};

struct Leaf {
  int node;             // node of the branch the leaf sits at
  glm::vec3 direction;  // unit direction from the node along the leaf
};

struct Branch {
  int id;
  int parent;       // -1 for the seedling shoot
  int parent_node;  // node of the parent the shoot starts from
  int year;         // year the shoot grew (1 = first year)
  ShootKind kind;
  bool dwarf;                    // initial hormone below H_s (2.4.2)
  bool alive;                    // false once dead or pruned: not drawn, not counted
  std::vector<glm::vec3> nodes;  // nodes[0] = base on the parent, nodes[1..N] = node points
  glm::vec3 bud_direction;       // v_tp: direction the bud pointed, before bending (eq. 2.6)
  glm::vec3 azimuth;             // phyllotaxis reference across the first internode
  float internode_length;        // D, cm
  float hormone_initial;         // H^0 (eq. 2.1)
  float hormone;                 // H after this year's update (eqs. 2.2, 2.3)
  float hormone_previous;        // H' (last year's H), for the sudden-drop dormancy break
  float light;                   // L in [0, 1] (light model)
  glm::vec3 light_direction;     // v_L, unit
  float cross_section;           // cm² (pipe model, 2.4.4)
  std::vector<int> children;
  std::vector<Bud> buds;
  std::vector<Leaf> leaves;  // only on the current year's shoots (deciduous)
  std::vector<int> flowers;  // node index of each open flower this year
};

// Most years a tree grows (the state, prunes and the CLI check against it).
constexpr int kMaxYears = 100;

// The page camera's ranges (cam=yaw,pitch,distance,tx,ty,tz): the state's camera check, the CLI's
// --cam and render/hybrid's orbit view all use these; camera.js clamps pitch and distance alike.
constexpr float kMinPitch = -0.1f, kMaxPitch = 1.5f;         // radians
constexpr float kMinDistance = 0.2f, kMaxDistance = 400.0f;  // metres
constexpr float kMaxYaw = 1000.0f;                           // |yaw| in radians: finite, never inf
constexpr float kMaxTarget = 10000.0f;  // |tx|, |ty|, |tz| of the camera target, metres

// A whole grown tree plus the settings that produced it.
struct Tree {
  std::string preset;
  uint64_t seed = 1;
  int years = 0;
  TreeParams params;
  std::vector<Branch> branches;  // index == id; dead branches stay with alive == false
  bool truncated = false;        // max_internodes or a budget (GrowLimits) was reached
  std::string truncated_by;      // the line naming the limit that stopped it first ("" if none)
};

// Per-sub-model timings of one growth run (thesis table 2.3).
struct GrowthTimings {
  double ms_total = 0, ms_light = 0, ms_hormone = 0, ms_branching = 0;
};

struct TreeStats {
  int internodes = 0, branches = 0, leaves = 0, flowers = 0;
  double height = 0;  // cm, highest node above the ground
};

TreeStats ComputeStats(const Tree& tree);
float BranchRadius(const Branch& branch);  // cm, from the pipe-model cross-section

}  // namespace niwa
