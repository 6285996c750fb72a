// Node-point wind-sway model of thesis chapter 3 (eqs. 3.1-3.16): data types, parameters,
// simulator.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "tree/tree.h"
#include "tree/tree_params.h"

namespace niwa {

// ---- Parameters ----
// Every sway and wind parameter is a row of the one parameter table (core/tree/tree_params.h,
// groups "sway" and "wind"); SwayParams is the model's typed copy of those rows of a ParamSet.
struct SwayParams {
  SwayParams() : SwayParams(TreeParams()) {}  // table defaults
  explicit SwayParams(const ParamSet& p);

  // model (thesis 3.3, table 3.1), cgs
  double k_wind;       // K_wind, g/(cm²·s) (eq. 3.5)
  double k_dir_trunk;  // K_dir at the thickest branch, dyn/cm² (eq. 3.8)
  double k_dir_tip;    // K_dir at the thinnest branch, dyn/cm² (eq. 3.8)
  double k_rev;        // K_rev (eq. 3.10)
  double k_vdel;       // K_vdel (eq. 3.13)
  double density;      // δ, g/cm³ (eq. 3.1)
  double m_leaf;       // g (eq. 3.3)
  double s_leaf;       // cm² (eq. 3.4)
  double alpha;        // α (eq. 3.15)
  double gravity;      // |g|, m/s² (eq. 3.6)
  bool gravity_preload;
  double dt;          // s (eqs. 3.13, 3.14, 3.16)
  double omit_limit;  // largest K_x dt² / m of a moving node point (eq. 3.16: 3)
  // wind (thesis 3.5 plus the wind field of docs/sway-model.md)
  double wind_speed;        // m/s
  double wind_dir;          // deg, 0: towards +x, 90: towards +z
  double gust_on;           // s, at the origin
  double gust_off;          // s, at the origin
  double gust_front_speed;  // m/s, 0: the gust starts and stops everywhere at once
  double wind_variation;    // amplitude v of the travelling wave, 0..1
  double wind_wavelength;   // λ, m
  double wind_period;       // T, s
  double duration;          // s
};

// Cross-parameter checks of a ParamSet's sway rows (gust_off > gust_on); errors name the row
// ("gust_off").
Status CheckSwayParams(const ParamSet& params);

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

// The minimal rotation taking unit `from` onto unit `to`, applied to v (the turn of eq. 3.11:
// Rodrigues about from × to, a half turn when they are opposite).
glm::dvec3 RotateMinimal(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& v);

// Builds the node points, masses, areas, stiffnesses and the omission classes of a grown tree.
SwayModel BuildSwayModel(const Tree& tree, const SwayParams& params);

// The wind field (docs/sway-model.md, "Wind"). Defaults: the thesis's uniform sudden gust (3.5),
// speed·(cos dir, 0, sin dir) while gust_on <= t < gust_off. Beyond the thesis, so that trees of a
// grove do not sway in unison: with gust_front_speed c > 0 the gust starts and stops at a point x m
// downwind of the origin x / c s later, and with wind_variation v > 0 the speed is multiplied by
// 1 + v sin(2π (x/λ - t/T)), a wave travelling with the wind.
class WindField {
 public:
  explicit WindField(const SwayParams& params);
  // Distance (m) along the wind direction from the world origin to a world position (cm).
  double Along(const glm::dvec3& position) const;
  // Wind vector (cm/s) at a point `along` m downwind of the origin, at time t (s).
  glm::dvec3 AtAlong(double along, double t) const;
  glm::dvec3 At(const glm::dvec3& position, double t) const { return AtAlong(Along(position), t); }
  // True when the wind is the same everywhere (no front, no variation).
  bool uniform() const { return uniform_; }

 private:
  double speed_, gust_on_, gust_off_, front_speed_, variation_, wavelength_, period_;
  glm::dvec3 dir_{1, 0, 0};  // unit, horizontal
  bool uniform_ = true;
};

// Wind vector (cm/s) at world position (cm) and time t (s).
glm::dvec3 WindAt(const SwayParams& params, const glm::dvec3& position, double t);

class SwaySimulator {
 public:
  // origin: where the tree's root stands in the world (cm); only the wind field sees it, every
  // position below stays in the tree's own frame.
  SwaySimulator(const Tree& tree, const SwayParams& params,
                const glm::dvec3& origin = glm::dvec3(0.0));
  // From a model already built: BuildSwayModel(tree, p) with p's model rows (density, leaf mass
  // and area, alpha, dt, the stiffnesses, omit_limit) those of `params`; the wind rows (speed,
  // direction, gusts) may differ, since the model does not read them. What a garden does with the
  // copies of one tree (compose/garden_wind): one model built, copied to each.
  SwaySimulator(SwayModel model, const SwayParams& params,
                const glm::dvec3& origin = glm::dvec3(0.0));
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
  // Every original node of every node point (eq. 3.15), node point after node point in model order,
  // nodes 0..n-1 each: the same values as NodePosition, with the parent's turn taken once per node
  // point (what a renderer needs per frame; bench/ sway workloads).
  void NodePositions(std::vector<glm::dvec3>* out) const;
  // The rotation of node point i's parent rod (eq. 3.11) as a matrix: R v = ParentRotate(i, v);
  // identity for a node point on the root. Used by core/sway/skin.h.
  glm::dmat3 ParentRotation(int i) const;
  // The rotation of node point i's own rod since rest: the minimal turn of its rest direction onto
  // today's, i.e. ParentRotation of any child of i (eq. 3.11). Used by the clustered sway skin
  // (core/sway/sway_gltf.h), where a node point's whole subtree turns with one rod.
  glm::dmat3 RodRotation(int i) const;
  // The rest tree with every alive branch's nodes moved to the current interpolated pose (3.3.3).
  Tree DeformedTree(const Tree& rest) const;

 private:
  glm::dvec3 ParentRotate(int i, const glm::dvec3& v) const;  // rotation of the parent's rod
  void UpdateAnchorAndPose(int i);

  SwayParams params_;
  SwayModel model_;
  WindField wind_;
  std::vector<double> along_;  // per node point: distance (m) of its rest tip along the wind
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
// Traced tips that jitter between `from` and `to` seconds (docs/sway-model.md, "Omission"): each
// spans more than 2 cm there and its step-to-step motion reverses (negative dot product of two
// successive steps) on more than 40 % of the steps. A swing the time step resolves reverses about
// twice a period; a tip ringing near the eq. 3.16 bound reverses on nearly every step.
int CountJitteringTips(const SwayRun& run, double from, double to);
// CSV "time,node,x,y,z" (cm) of the traced tips.
std::string SwayCsv(const SwayRun& run);
// SVG plot against time of each traced tip's signed displacement from rest along the wind (cm),
// its full distance from rest faint behind it, the gust shaded.
std::string SwayPlotSvg(const SwayRun& run, const SwayParams& params);

}  // namespace niwa
