// Node-point wind-sway model of thesis chapter 3 (eqs. 3.1-3.16): data types, parameters,
// simulator.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tree/tree.h"

namespace niwa {

// ---- Parameters (same shape as core/params/param_table.h; see docs/sway-model.md) ----

enum class SwayParamId : int {
  kKWind,           // K_wind (eq. 3.5)
  kKDirTrunk,       // K_dir at the thickest branch (eq. 3.8)
  kKDirTip,         // K_dir at the thinnest branch (eq. 3.8)
  kKRev,            // K_rev (eq. 3.10)
  kKVdel,           // K_vdel (eq. 3.13)
  kDensity,         // δ (eq. 3.1)
  kMLeaf,           // m_leaf (eq. 3.3)
  kSLeaf,           // s_leaf (eq. 3.4)
  kAlpha,           // α (eq. 3.15)
  kGravity,         // |g| (eq. 3.6)
  kGravityPreload,  // 1: the grown shape is the equilibrium under gravity
  kWindSpeed,       // |v_wind| (eq. 3.5)
  kWindDir,         // azimuth of the wind in the horizontal plane
  kGustOn,          // wind starts (s)
  kGustOff,         // wind stops (s)
  kDt,              // dt (eqs. 3.13, 3.14, 3.16)
  kDuration,        // simulated time (s)
  kCount
};

constexpr std::size_t kSwayParamCount = static_cast<std::size_t>(SwayParamId::kCount);

struct SwayParamSpec {
  SwayParamId id;
  const char* key;     // stable name used by --set-sway key=value
  const char* symbol;  // the paper's symbol
  const char* unit;    // "" when dimensionless
  double default_value;
  double min_value;
  double max_value;
  bool integer;
  const char* group;  // "sway" (model) or "wind" (input)
  const char* help;
};

const std::array<SwayParamSpec, kSwayParamCount>& SwayParamTable();
const SwayParamSpec& SwaySpec(SwayParamId id);
std::optional<SwayParamId> FindSwayParam(std::string_view key);
std::string SwayRangeText(const SwayParamSpec& spec);

class SwayParams {
 public:
  SwayParams();  // table defaults
  double Get(SwayParamId id) const { return values_[static_cast<std::size_t>(id)]; }
  // Checked setters: "" or one line "key: value is out of range; must be a number in [a, b]".
  std::string Set(SwayParamId id, double value);
  std::string SetFromText(std::string_view key, std::string_view text);
  // Cross-parameter checks (gust_off > gust_on); "" or one line.
  std::string Validate() const;

 private:
  std::array<double, kSwayParamCount> values_;
};

// ---- The node-point model ----

// How a node point moves (thesis 3.4.2).
enum class SwayKind : uint8_t {
  kMoving,    // integrated (eqs. 3.12-3.14)
  kFollower,  // passes eq. 3.16, parent moves: keeps its rest pose relative to the parent (3.4.3)
  kFixed,     // passes eq. 3.16, parent is the root or fixed: never moves
};

// One node point: the tip of one branch (one year's shoot) of the grown tree (thesis 3.3.1).
struct SwayNode {
  int branch = -1;      // Tree::branches index
  int parent = -1;      // SwayModel::nodes index of the parent branch's node point, -1: the root
  int parent_node = 0;  // node of the parent branch the branch starts at (its anchor)
  SwayKind kind = SwayKind::kMoving;
  double radius = 0;       // d, cm (BranchRadius)
  double length = 0;       // l_i, arc length of the branch, cm (eqs. 3.1-3.4)
  int leaves = 0;          // n_i
  double mass = 0;         // m_i, g (eqs. 3.1, 3.3)
  double area = 0;         // s_i, cm² (eqs. 3.2, 3.4)
  double k_dir = 0;        // K_dir at this branch, dyn/cm²
  double stiffness = 0;    // K_dir π d² / l_j, dyn/cm (eq. 3.8)
  double restoring = 0;    // K_x of 3.4.1: stiffness + reactions of moving children, dyn/cm (3.16)
  double rest_length = 0;  // l_j: distance anchor → tip at rest, kept after every step
  glm::dvec3 rest_anchor{0.0};         // nodes[0] at rest
  glm::dvec3 rest_tip{0.0};            // P_j(0)
  glm::dvec3 rest_dir{0, 1, 0};        // unit (P_j(0) - anchor(0)) / l_j
  std::vector<glm::dvec3> rest_nodes;  // every original node at rest (drawing, 3.3.3)
  std::vector<double> arc_ratio;       // l_jn / l_j per node, by arc length (eq. 3.15)
  std::vector<double> weight;          // (l_jn / l_j)^α per node (eq. 3.15)
};

struct SwayModel {
  std::vector<SwayNode> nodes;      // parents before children
  std::vector<int> node_of_branch;  // branch id -> node index, -1 for dead branches
  int moving = 0, followers = 0, fixed = 0;
  long internodes = 0;  // alive internodes drawn
};

// Builds the node points, masses, areas, stiffnesses and the omission classes of a grown tree.
SwayModel BuildSwayModel(const Tree& tree, const SwayParams& params);

// Wind vector (cm/s) at time t: speed·(cos dir, 0, sin dir) while gust_on <= t < gust_off.
glm::dvec3 WindAt(const SwayParams& params, double t);

class SwaySimulator {
 public:
  SwaySimulator(const Tree& tree, const SwayParams& params);
  void Step();  // one time step dt
  double time() const { return time_; }
  long steps() const { return steps_; }
  const SwayModel& model() const { return model_; }
  const std::vector<glm::dvec3>& tips() const { return tip_; }
  const std::vector<glm::dvec3>& anchors() const { return anchor_; }
  // Own velocity of each node point relative to its parent's frame (eq. 3.13), cm/s.
  const std::vector<glm::dvec3>& velocities() const { return velocity_; }
  // Position of original node n of node point i, interpolated with eq. 3.15.
  glm::dvec3 NodePosition(int i, int n) const;
  // The rest tree with every alive branch's nodes moved to the current interpolated pose (3.3.3).
  Tree DeformedTree(const Tree& rest) const;

 private:
  glm::dvec3 ParentRotate(int i, const glm::dvec3& v) const;  // rotation of the parent's rod
  void UpdateAnchorAndPose(int i);

  SwayParams params_;
  SwayModel model_;
  std::vector<glm::dvec3> tip_, velocity_, anchor_, dir_, force_, preload_;
  std::vector<glm::dvec3> prev_dir_;  // dir_ before this step's pose update
  double time_ = 0;
  long steps_ = 0;
};

// A whole run for the CLI and tests: stats and the trajectories of a few tips.
struct SwayRun {
  int node_points = 0, moving = 0, followers = 0, fixed = 0;
  long internodes = 0, steps = 0;
  double ms = 0, ns_per_internode = 0;
  double max_tip_displacement = 0;  // cm, over every node point and every step
  bool finite = true;               // no NaN or infinity appeared
  std::vector<int> tip_branches;    // branch ids of the traced tips
  std::vector<double> times;        // s, one per recorded sample (t = 0 and after every step)
  std::vector<std::vector<glm::dvec3>> tip_positions;  // [tip][sample], cm
};

// Runs params' duration; traces up to `tips` moving tips farthest from the root.
SwayRun RunSway(const Tree& tree, const SwayParams& params, int tips);
// CSV "time,node,x,y,z" (cm) of the traced tips.
std::string SwayCsv(const SwayRun& run);
// SVG plot of each traced tip's displacement from rest (cm) against time, gust shaded.
std::string SwayPlotSvg(const SwayRun& run, const SwayParams& params);

}  // namespace niwa
