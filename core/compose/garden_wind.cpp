// The wind over a grown garden: one sway simulator per planted tree (see garden_wind.h).
#include "compose/garden_wind.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "compose/garden_view.h"
#include "math/det_math.h"
#include "params/param_json.h"
#include "params/param_text.h"
#include "tree/tree_params.h"

namespace niwa::compose {

namespace {

constexpr double kWindCmPerM = 100.0;

bool IsWindRow(const ParamSpec& row) { return std::string(row.group) == "wind"; }

// The wind rows of `wind` copied into `params` (a tree's own rows), and its time step.
void TakeWindRows(const ParamSet& wind, ParamSet* params) {
  for (std::size_t r = 0; r < wind.size(); ++r)
    if (IsWindRow(wind.table().row(r))) (void)params->Set(r, wind.Get(r));
  (void)params->Set(TreeParam::kSwayDt, wind.Get(TreeParam::kSwayDt));
}

}  // namespace

Result<GardenWind> GardenWind::Start(const GardenRun& run, const ParamSet& wind,
                                     const Budget& budget) {
  GardenWind w;
  w.wind_ = SwayParams(wind);
  w.dt_ = w.wind_.dt;
  w.duration_ = w.wind_.duration;
  const std::vector<PlacedTree>& placed = run.planting().trees;
  // The page's budget first, from each distinct tree's model (node points and internodes).
  Estimate memory;
  double internodes = 0;
  long trees = 0;
  std::vector<SwayParams> params(run.groups().size());
  // Each distinct tree's model, built once: its copies' simulators take copies of it (the wind
  // rows each copy turns do not enter the model).
  std::vector<SwayModel> models(run.groups().size());
  for (std::size_t g = 0; g < run.groups().size(); ++g) {
    const GardenTreeGroup& group = run.groups()[g];
    ParamSet rows = group.run->state().params;
    TakeWindRows(wind, &rows);
    params[g] = SwayParams(rows);
    models[g] = BuildSwayModel(group.tree(), params[g]);
    const SwayModel& model = models[g];
    const int copies = static_cast<int>(group.trees.size());
    memory = memory + EstimatePageSway(model, copies);
    internodes += static_cast<double>(model.internodes) * copies;
    trees += copies;
  }
  memory.what = "swaying " + FormatCount(static_cast<double>(trees)) + " trees of " +
                FormatCount(internodes) + " internodes";
  NIWA_RETURN_IF_ERROR(CheckEstimate(memory, budget, "lower years, density or size"));
  // Time: one step of every tree within the page's tick, at least 1/4 of real time (the page
  // sway's rules, its estimate per internode summed over the trees).
  SwayModel all;
  all.internodes = static_cast<long>(internodes);
  w.timing_ = EstimatePageSwayTime(all, w.wind_, 1);
  NIWA_RETURN_IF_ERROR(CheckPageSwayTime(w.timing_, all, w.wind_, static_cast<int>(trees),
                                         budget.seconds_limit, "lower years, density or size"));
  for (std::size_t g = 0; g < run.groups().size(); ++g) {
    const GardenTreeGroup& group = run.groups()[g];
    Group out;
    out.params = params[g];
    out.first = w.blocks_;
    for (std::size_t k = 0; k < group.trees.size(); ++k) {
      const PlacedTree& p = placed[group.trees[k]];
      // The tree's own frame is the garden's turned by rot about y (garden.vert's turn): the wind
      // direction in it is wind_dir + rot, and its origin turned back by rot keeps every node's
      // distance along the wind equal to its world position's.
      SwayParams turned = params[g];
      turned.wind_dir = params[g].wind_dir + p.rot;
      double s = 0, c = 1;
      det::SinCos(p.rot * (det::kPi / 180.0), &s, &c);
      const glm::dvec3 origin(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
      // The last copy takes the model itself, the others a copy.
      SwayModel model = k + 1 < group.trees.size() ? models[g] : std::move(models[g]);
      out.copies.push_back(
          std::make_unique<SwaySimulator>(std::move(model), turned, origin * kWindCmPerM));
    }
    out.nodes = out.copies.empty() ? 0 : static_cast<int>(out.copies[0]->model().nodes.size());
    w.blocks_ += static_cast<std::size_t>(out.nodes) * out.copies.size();
    w.groups_.push_back(std::move(out));
  }
  return w;
}

void GardenWind::Step(int steps) {
  steps_ += steps;
  for (Group& g : groups_)
    for (std::unique_ptr<SwaySimulator>& sim : g.copies)
      for (int i = 0; i < steps; ++i) sim->Step();
  // Every simulator's clock is the same (one dt, from 0); a garden without trees counts steps.
  time_ = !groups_.empty() && !groups_[0].copies.empty() ? groups_[0].copies[0]->time()
                                                         : time_ + steps * dt_;
}

std::size_t GardenWind::first_block(int group, int copy) const {
  const Group& g = groups_[group];
  return g.first + static_cast<std::size_t>(copy) * static_cast<std::size_t>(g.nodes);
}

void GardenWind::WritePoses(float* out) const {
  const float cm_to_units = MeshOptions{}.cm_to_units;
  for (const Group& g : groups_)
    for (std::size_t k = 0; k < g.copies.size(); ++k)
      WriteSwayPoses(*g.copies[k], cm_to_units,
                     out + (g.first + k * static_cast<std::size_t>(g.nodes)) * kSwayPoseFloats);
}

std::string GardenWind::StatsJson(const GardenRun& run) const {
  const std::vector<PlacedTree>& placed = run.planting().trees;
  std::vector<double> sway(placed.size(), 0.0);
  std::vector<float> poses;
  for (std::size_t g = 0; g < groups_.size() && g < run.groups().size(); ++g) {
    const Group& group = groups_[g];
    poses.resize(static_cast<std::size_t>(group.nodes) * kSwayPoseFloats);
    for (std::size_t k = 0; k < group.copies.size(); ++k) {
      WriteSwayPoses(*group.copies[k], MeshOptions{}.cm_to_units, poses.data());
      double sum = 0;
      for (int j = 0; j < group.nodes; ++j) {
        const float* p = poses.data() + static_cast<std::size_t>(j) * kSwayPoseFloats;
        sum += std::sqrt(static_cast<double>(p[3]) * p[3] + static_cast<double>(p[7]) * p[7] +
                         static_cast<double>(p[11]) * p[11]);
      }
      const int t = run.groups()[g].trees[k];
      if (t >= 0 && static_cast<std::size_t>(t) < sway.size()) sway[t] = sum;
    }
  }
  nlohmann::ordered_json j;
  j["time"] = time_;
  j["steps"] = steps_;
  j["dt"] = dt_;
  j["wind_speed"] = SpeedAt(0, 0);
  j["trees"] = nlohmann::ordered_json::array();
  for (std::size_t t = 0; t < placed.size(); ++t)
    j["trees"].push_back({{"x", placed[t].x}, {"z", placed[t].z}, {"sway", sway[t]}});
  return j.dump();
}

double GardenWind::SpeedAt(double x, double z) const {
  return glm::length(WindAt(wind_, glm::dvec3(x, 0, z) * kWindCmPerM, time_)) / kWindCmPerM;
}

TreeSkin GardenWind::Skin(const GardenRun& run, int group) const {
  // Every copy of a group has the one model (the wind does not enter it): its first copy's.
  return BuildTreeSkin(GardenGroupMesh(run, group), groups_[group].copies[0]->model());
}

}  // namespace niwa::compose
