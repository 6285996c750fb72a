// The wind over a grown garden (issue 33 item 6, docs/garden-model.md "The page": Blow): one sway
// simulator (core/sway, thesis ch. 3) per planted tree at its place and turn, in one wind field
// over the whole garden, a gust front entering at the garden's upwind edge; every copy's node-point
// poses in one array, and each distinct tree's per-vertex sway skin of its page mesh
// (compose/garden_view). Does not: grow, mesh or draw trees, run on a clock (the caller steps it),
// or sway a recorded year's trees (the last grown only). The wind's rows: garden_wind_rows.h.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "compose/garden_run.h"
#include "compose/garden_wind_rows.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "sway/sway_budget.h"

namespace niwa::compose {

class GardenWind {
 public:
  // One simulator per planted tree of `run`'s last grown garden (group by group, each group's
  // copies in GardenTreeGroup::trees order), each from rest at t = 0, in the tree's own sway rows
  // with `wind`'s "wind" rows and time step dt (GardenWindRows), so every tree is on one clock. A
  // tree turned by rot° sways in the wind turned by −rot in its own frame, and meets the front
  // where its world position does. Refused up front (naming `budget`'s limit) when the simulators
  // and poses do not fit its memory, or one step of every tree does not fit the page's tick
  // (core/sway/sway_budget's page sway rules, over every tree's internodes).
  static Result<GardenWind> Start(const GardenRun& run, const ParamSet& wind, const Budget& budget);

  // Every tree `steps` time steps further.
  void Step(int steps);
  double time() const { return time_; }
  double dt() const { return dt_; }
  double duration() const { return duration_; }
  // Steps the caller may take in one page tick, and the share of real time it keeps (the page sway
  // rules of core/sway/sway_budget, over every tree's internodes).
  int steps_per_tick() const { return timing_.steps_per_tick; }
  double speed() const { return timing_.speed; }
  double step_seconds() const { return timing_.step_seconds; }

  int groups() const { return static_cast<int>(groups_.size()); }
  // Node points of group g's tree (one pose block per node point and copy).
  int nodes(int group) const { return groups_[group].nodes; }
  // Pose blocks of every copy of every group (the poses' length / kSwayPoseFloats).
  std::size_t blocks() const { return blocks_; }
  // The first pose block of copy `copy` of group `group`: its node point j is block first + j.
  std::size_t first_block(int group, int copy) const;

  // Every copy's poses (core/sway/skin.h WriteSwayPoses, metres, the tree's own frame), copy after
  // copy as first_block orders them: blocks() × kSwayPoseFloats floats into `out`.
  void WritePoses(float* out) const;
  // {time, steps, dt, wind_speed (m/s at the garden's centre now), trees: [{x, z, sway}]}: per
  // planted tree in planting order (run.planting().trees; `run` the one Start was given), its foot
  // and the sum over its node points of |M_j| (eq. 3.15 tip offsets, m) now: what `niwa garden grow
  // --wind-time` prints under "wind" (the same bytes natively and in WASM).
  std::string StatsJson(const GardenRun& run) const;
  // The wind's speed (m/s) at garden point (x, z) m now.
  double SpeedAt(double x, double z) const;

  // The sway skin of group g's page mesh (GardenGroupMesh: bark, leaves, flowers): per vertex its
  // node point in the group's model (0 .. nodes(g) − 1) and eq. 3.15 weight.
  TreeSkin Skin(const GardenRun& run, int group) const;

 private:
  struct Group {
    int nodes = 0;
    std::size_t first = 0;  // first pose block of its first copy
    SwayParams params;      // the tree's sway rows with the garden's wind (wind_dir unturned)
    std::vector<std::unique_ptr<SwaySimulator>> copies;
  };
  std::vector<Group> groups_;
  std::size_t blocks_ = 0;
  double time_ = 0, dt_ = 0, duration_ = 0;
  long steps_ = 0;
  SwayParams wind_;  // the wind rows (of the table's defaults elsewhere): SpeedAt's field
  PageSwayTime timing_;
};

}  // namespace niwa::compose
