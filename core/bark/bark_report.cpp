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
  // Crack spacing along scan lines (regions.h: the paper's Table 3 measure).
  auto spacing = [](const Spacing& sp) {
    return nlohmann::ordered_json{{"mean", sp.mean},         {"max", sp.max},
                                  {"gap_mean", sp.gap_mean}, {"gap_max", sp.gap_max},
                                  {"lines", sp.lines},       {"open", sp.open}};
  };
  j["spacing"] = {{"width", spacing(c.spacing_width)},
                  {"height", spacing(c.spacing_height)},
                  {"height_all_runs", spacing(c.spacing_height_all_runs)}};
  if (run.four_layer()) {
    // The 4-layer model: three spring layers over the inner one (four_layer.h).
    const FourLayer& f = run.layers();
    const double area = m.node_area;
    // The inner layer's strains (S's anchors also move out with the cork: its radius is printed).
    const LayerGrowth lg = LayerGrowthAt(f);
    j["strain"] = {{"theta", (lg.r_inner - f.m.r_o) / f.m.r_o},
                   {"z", static_cast<double>(g.s_z) - 1.0},
                   {"r_I", lg.r_inner},
                   {"r_S", lg.mid[kS]}};
    j["springs"] = {{"axial", 3 * c.springs[0]},
                    {"diagonal", 3 * c.springs[1]},
                    {"shear", 3 * L.nodes()},
                    {"per_layer", L.springs()}};
    static const char* kNames[3] = {"S", "M1", "M2"};
    nlohmann::ordered_json layers;
    for (int r = 0; r < 3; ++r) {
      const Surface& s = f.layer[r].s;
      const int b = s.broken_count[0] + s.broken_count[1];
      layers[kNames[r]] = {
          {"born", f.layer[r].born},
          {"broken", {{"axial", s.broken_count[0]}, {"diagonal", s.broken_count[1]}}},
          {"broken_fraction", static_cast<double>(b) / L.springs()}};
    }
    j["layers"] = layers;
    // S's cracks (springs lost to peeling are not cracks).
    const Surface& S = f.layer[kS].s;
    const int bs = S.broken_count[0] + S.broken_count[1];
    j["broken"] = {{"axial", S.broken_count[0]}, {"diagonal", S.broken_count[1]}};
    j["broken_fraction"] = {{"axial", static_cast<double>(S.broken_count[0]) / c.springs[0]},
                            {"diagonal", static_cast<double>(S.broken_count[1]) / c.springs[1]},
                            {"all", static_cast<double>(bs) / L.springs()}};
    j["vertical_crack_share"] = bs ? static_cast<double>(S.broken_count[1]) / bs : 0.0;
    const int n = L.nodes();
    j["exchanges"] = f.cycle;
    j["peeled_fraction"] = static_cast<double>(n - PresentNodes(f)) / n;
    double exposed[4] = {0, 0, 0, 0};
    const std::vector<uint8_t> visible = VisibleLayer(L, f);
    for (uint8_t v : visible) exposed[v] += 1.0;
    const double tris = static_cast<double>(visible.size());
    j["exposed"] = {{"S", exposed[0] / tris},
                    {"M1", exposed[1] / tris},
                    {"M2", exposed[2] / tris},
                    {"I", exposed[3] / tris}};
    j["shed"] = {{"regions", f.shed_regions}, {"area", f.shed_nodes * area}};
    j["peel"] = {{"events", f.peel_events},
                 {"area", f.peeled_nodes * area},
                 {"bonds_broken", f.bonds_broken},
                 {"first_step", f.first_peel_step},
                 {"first_crack_step", f.first_crack_step}};
  }
  j["spring_steps"] = run.spring_steps();
  j["hash"] = run.Hash("");
  return j.dump();
}

}  // namespace niwa::bark
