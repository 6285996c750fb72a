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

const std::vector<GardenWindValue>& GardenWindDefaults() {
  static const std::vector<GardenWindValue> kDefaults = {
      {"wind_speed", 8},       {"wind_dir", 0},         {"gust_off", 600},       {"duration", 600},
      {"gust_front_speed", 4}, {"wind_variation", 0.4}, {"wind_wavelength", 25}, {"wind_period", 5},
  };
  return kDefaults;
}

Result<ParamSet> GardenWindRows(double size, const std::string& json) {
  ParamSet wind = TreeParams();
  for (const GardenWindValue& v : GardenWindDefaults()) {
    const std::optional<std::size_t> row = wind.table().Find(v.key);
    if (row) NIWA_RETURN_IF_ERROR(wind.Set(*row, v.value));
  }
  bool gust_on_given = false;
  if (!json.empty()) {
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    if (j.is_discarded() || !j.is_object())
      return Status::Error("wind", "must be a JSON object of the wind rows");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::optional<std::size_t> row = wind.table().Find(it.key());
      if (!row || !IsWindRow(wind.table().row(*row)))
        return Status::Error("wind", "'" + it.key().substr(0, 40) +
                                         "' is not a wind row (niwa params tree, group wind)");
      gust_on_given = gust_on_given || it.key() == "gust_on";
    }
    NIWA_RETURN_IF_ERROR(ApplyParamsJson(json, &wind));
  }
  if (!gust_on_given) {
    // The upwind edge of the square: its corner farthest against the wind, |cos| + |sin| half
    // sides upwind of the origin.
    const double front = wind.Get(TreeParam::kGustFrontSpeed);
    double s = 0, c = 1;
    det::SinCos(wind.Get(TreeParam::kWindDir) * (det::kPi / 180.0), &s, &c);
    const double upwind = 0.5 * size * (std::abs(c) + std::abs(s));
    NIWA_RETURN_IF_ERROR(wind.Set(TreeParam::kGustOn, front > 0 ? upwind / front : 0.0));
  }
  NIWA_RETURN_IF_ERROR(CheckSwayParams(wind));
  return wind;
}

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
  for (std::size_t g = 0; g < run.groups().size(); ++g) {
    const GardenTreeGroup& group = run.groups()[g];
    ParamSet rows = group.run->state().params;
    TakeWindRows(wind, &rows);
    params[g] = SwayParams(rows);
    const SwayModel model = BuildSwayModel(group.tree(), params[g]);
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
    for (int t : group.trees) {
      const PlacedTree& p = placed[t];
      // The tree's own frame is the garden's turned by rot about y (garden.vert's turn): the wind
      // direction in it is wind_dir + rot, and its origin turned back by rot keeps every node's
      // distance along the wind equal to its world position's.
      SwayParams turned = params[g];
      turned.wind_dir = params[g].wind_dir + p.rot;
      double s = 0, c = 1;
      det::SinCos(p.rot * (det::kPi / 180.0), &s, &c);
      const glm::dvec3 origin(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
      out.copies.push_back(
          std::make_unique<SwaySimulator>(group.tree(), turned, origin * kWindCmPerM));
    }
    out.nodes = out.copies.empty() ? 0 : static_cast<int>(out.copies[0]->model().nodes.size());
    w.blocks_ += static_cast<std::size_t>(out.nodes) * out.copies.size();
    w.groups_.push_back(std::move(out));
  }
  return w;
}

void GardenWind::Step(int steps) {
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

double GardenWind::SpeedAt(double x, double z) const {
  return glm::length(WindAt(wind_, glm::dvec3(x, 0, z) * kWindCmPerM, time_)) / kWindCmPerM;
}

TreeSkin GardenWind::Skin(const GardenRun& run, int group) const {
  // Every copy of a group has the one model (the wind does not enter it): its first copy's.
  return BuildTreeSkin(GardenGroupMesh(run, group), groups_[group].copies[0]->model());
}

}  // namespace niwa::compose
