// Sway budgets (core/sway/sway_budget.h); constants calibrated in docs/budgets.md.
#include "sway/sway_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace niwa {
namespace {

constexpr double kNsPerInternodeStep = 90;  // measured 25-55 ns natively (sakura 15, 30 years)
constexpr double kNodePointBytes = 600;     // SwayNode and the simulator's eight vectors
constexpr double kInternodeBytes = 48;      // rest nodes, arc ratios, weights
constexpr double kJointKeyBytes = 28;       // a translation and a rotation a joint and key
constexpr double kGlbMemoryPerByte = 8;     // measured 7.5 (sakura 15, 60 s at 240 fps)
constexpr double kGlbNsPerByte = 30;

std::string Steps(double steps) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.0f", steps);
  return buffer;
}

}  // namespace

double SwaySteps(const SwayParams& params) {
  return params.dt > 0 ? std::floor(params.duration / params.dt + 0.5) : 0;
}

Estimate EstimateSwayRun(const SwayModel& model, const SwayParams& params, int tips) {
  const double steps = SwaySteps(params);
  const double internodes = static_cast<double>(model.internodes);
  Estimate e;
  e.memory_bytes = kNodePointBytes * static_cast<double>(model.nodes.size()) +
                   kInternodeBytes * internodes + (8.0 + 24.0 * tips) * (steps + 1);
  e.seconds = kNsPerInternodeStep * 1e-9 * steps * internodes;
  e.what = "swaying " + Steps(steps) + " steps over " + Steps(internodes) + " internodes";
  return e;
}

Estimate EstimateSwayGlb(const SwayModel& model, const TreeCounts& counts, const SwayParams& params,
                         double fps, std::size_t max_joints) {
  const double keys_per_second = params.dt > 0 ? std::min(fps, 1.0 / params.dt) : fps;
  const double keys = std::floor(params.duration * keys_per_second) + 1;
  const double exact = 1.0 + 2.0 * model.moving + model.followers;
  const bool clustered = exact > static_cast<double>(max_joints);
  const double joints = clustered ? static_cast<double>(max_joints) : exact;
  const double mesh_bytes = EstimateTreeExport(counts, TreeExport::kGlb).memory_bytes;
  const double clip_bytes = keys * joints * kJointKeyBytes;
  Estimate e;
  e.memory_bytes = mesh_bytes + kGlbMemoryPerByte * clip_bytes;
  e.seconds = (clustered ? 2.0 : 1.0) * EstimateSwayRun(model, params, 0).seconds +
              kGlbNsPerByte * 1e-9 * clip_bytes +
              EstimateTreeExport(counts, TreeExport::kGlb).seconds;
  e.what = "writing the .glb (" + Steps(keys) + " keys of " + Steps(joints) + " joints)";
  return e;
}

Estimate EstimatePageSway(const SwayModel& model, int instances) {
  const double nodes = static_cast<double>(model.nodes.size());
  const double internodes = static_cast<double>(model.internodes);
  Estimate e;
  e.memory_bytes =
      instances * (kNodePointBytes * nodes + kInternodeBytes * internodes + 16.0 * 4.0 * nodes);
  e.what = "swaying " + Steps(instances) + " tree" + (instances == 1 ? "" : "s") + " of " +
           Steps(internodes) + " internodes";
  return e;
}

PageSwayTime EstimatePageSwayTime(const SwayModel& model, const SwayParams& params, int instances) {
  PageSwayTime t;
  t.step_seconds =
      kNsPerInternodeStep * 1e-9 * static_cast<double>(model.internodes) * std::max(instances, 1);
  const double fit = t.step_seconds > 0 ? std::floor(kPageSwayTickSeconds / t.step_seconds) : 8;
  t.steps_per_tick = static_cast<int>(std::clamp(fit, 1.0, double{kPageSwayMaxStepsPerTick}));
  t.speed = t.step_seconds > 0 ? std::min(1.0, params.dt / t.step_seconds) : 1.0;
  return t;
}

Status CheckPageSwayTime(const PageSwayTime& time, const SwayModel& model, const SwayParams& params,
                         int instances, const std::string& limit, const std::string& change) {
  const std::string what = "swaying " + FormatCount(instances) + " tree" +
                           (instances == 1 ? "" : "s") + " of " +
                           FormatCount(static_cast<double>(model.internodes)) + " internodes";
  if (time.step_seconds > kPageSwayTickSeconds) {
    char step[32], tick[32];
    std::snprintf(step, sizeof step, "%.2f s", time.step_seconds);
    std::snprintf(tick, sizeof tick, "%.2f s", kPageSwayTickSeconds);
    return Status::Error(limit, what + " takes about " + step + " a step, more than the " + tick +
                                    " a worker tick may take (a click must answer within 1 s); " +
                                    change);
  }
  if (time.speed < kPageSwaySlowest) {
    char slow[32];
    std::snprintf(slow, sizeof slow, "%.0f", 1.0 / time.speed);
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.1f ms", time.step_seconds * 1e3);
    char dt[32];
    std::snprintf(dt, sizeof dt, "%g s", params.dt);
    return Status::Error(limit, what + " takes about " + ms + " a step of dt " + dt + ": 1/" +
                                    slow + " of real time, slower than the 1/" +
                                    std::to_string(static_cast<int>(1 / kPageSwaySlowest)) +
                                    " allowed; " + change);
  }
  return Status::Ok();
}

}  // namespace niwa
