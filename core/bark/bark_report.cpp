// The bark run's stats JSON.
#include "bark/bark_report.h"

#include <nlohmann/json.hpp>

#include "bark/bark_run.h"

namespace niwa::bark {

std::string BarkStatsJson(const BarkRun& run) {
  const Lattice& L = run.lattice();
  const Mechanics& m = run.mechanics();
  const CrackMeasures& c = run.cracks();
  const Growth g = run.growth();
  nlohmann::ordered_json j;
  j["species"] = run.state().species;
  j["model"] = run.state().model;
  j["seed"] = run.state().seed;
  j["nodes"] = L.nodes();
  j["springs"] = {{"axial", c.springs[0]}, {"diagonal", c.springs[1]}, {"shear", L.nodes()}};
  j["cycles"] = run.done();
  j["steps"] = run.steps();
  j["steps_per_cycle"] = m.steps_per_cycle;
  j["dt"] = m.dt;
  j["R_o"] = L.radius();
  j["H_o"] = L.height();
  j["strain"] = {{"theta", static_cast<double>(g.s_theta) - 1.0},
                 {"z", static_cast<double>(g.s_z) - 1.0}};
  j["broken"] = {{"axial", c.broken[0]}, {"diagonal", c.broken[1]}};
  j["broken_fraction"] = {
      {"axial", c.broken_fraction[0]},
      {"diagonal", c.broken_fraction[1]},
      {"all", static_cast<double>(c.broken[0] + c.broken[1]) / (c.springs[0] + c.springs[1])}};
  j["vertical_crack_share"] = c.vertical_crack_share;
  j["regions"] = {{"count", c.count},
                  {"strips", c.strips},
                  {"mean_w", c.mean_width},
                  {"mean_h", c.mean_height},
                  {"max_w", c.max_width},
                  {"max_h", c.max_height},
                  {"closed_fraction", c.closed_fraction},
                  {"plate_fraction", c.plate_fraction}};
  j["intercept"] = {{"width", c.intercept_width}, {"height", c.intercept_height}};
  j["spring_steps"] = run.spring_steps();
  j["hash"] = run.Hash("");
  return j.dump();
}

}  // namespace niwa::bark
