// The tree study's stats JSON and mappings CSV.
#include "tree/tree_report.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

namespace niwa {
namespace {

// Shortest text that reads back as the same float (the model computes in float).
std::string FormatFloat(float value) {
  char buffer[32];
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, static_cast<double>(value));
    if (std::strtof(buffer, nullptr) == value) break;
  }
  return buffer;
}

}  // namespace

TreeForm ComputeTreeForm(const Tree& tree) {
  TreeForm form;
  float lo[2] = {0, 0}, hi[2] = {0, 0};
  bool any_node = false, any_leaf = false;
  int tips = 0, drooping = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const glm::vec3& n : b.nodes) {
      float xz[2] = {n.x, n.z};
      for (int k = 0; k < 2; ++k) {
        lo[k] = any_node ? std::min(lo[k], xz[k]) : xz[k];
        hi[k] = any_node ? std::max(hi[k], xz[k]) : xz[k];
      }
      any_node = true;
    }
    for (const Leaf& leaf : b.leaves) {
      double y = b.nodes[static_cast<std::size_t>(leaf.node)].y;
      form.crown_base_height = any_leaf ? std::min(form.crown_base_height, y) : y;
      any_leaf = true;
    }
    if (b.year == tree.years && b.nodes.size() >= 2) {
      ++tips;
      const glm::vec3& tip = b.nodes.back();
      const glm::vec3& before = b.nodes[b.nodes.size() - 2];
      if (tip.y < before.y) ++drooping;
    }
  }
  form.crown_width = std::max(double(hi[0]) - lo[0], double(hi[1]) - lo[1]);
  form.drooping_tips_share = tips > 0 ? double(drooping) / tips : 0.0;
  return form;
}

std::vector<std::string> IdlePruneNotices(const std::vector<Prune>& prunes, const Tree& grown) {
  std::vector<std::string> notices;
  for (const Prune& prune : prunes) {
    Status idle = IdlePruneReason(prune, grown);
    if (!idle.ok()) notices.push_back("prune " + idle.Line());
  }
  return notices;
}

std::string TreeStatsJson(const Tree& tree, const GrowthTimings& t, const TreeStatsExtras& extras) {
  TreeStats s = ComputeStats(tree);
  nlohmann::ordered_json j;
  j["preset"] = tree.preset;
  j["seed"] = tree.seed;
  j["years"] = tree.years;
  j["internodes"] = s.internodes;
  j["branches"] = s.branches;
  j["leaves"] = s.leaves;
  j["flowers"] = s.flowers;
  j["height"] = s.height;
  j["truncated"] = tree.truncated;
  if (!tree.truncated_by.empty()) j["truncated_by"] = tree.truncated_by;
  TreeForm form = ComputeTreeForm(tree);
  j["crown_width"] = form.crown_width;
  j["crown_base_height"] = form.crown_base_height;
  j["drooping_tips_share"] = form.drooping_tips_share;
  j["ms"] = t.ms_total;
  j["ms_light"] = t.ms_light;
  j["ms_hormone"] = t.ms_hormone;
  j["ms_branching"] = t.ms_branching;
  if (extras.idle_prunes) j["idle_prunes"] = IdlePruneNotices(*extras.idle_prunes, tree);
  if (extras.mesh) {
    // Axis-aligned bounds of every mesh vertex (metres), for framing the camera.
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool any = false;
    const TreeMesh& mesh = *extras.mesh;
    for (const MeshBuffers* m : {&mesh.bark, &mesh.leaves, &mesh.flowers}) {
      for (std::size_t i = 0; i + 2 < m->positions.size(); i += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
          float v = m->positions[i + k];
          lo[k] = any ? std::min(lo[k], v) : v;
          hi[k] = any ? std::max(hi[k], v) : v;
        }
        any = true;
      }
    }
    j["bounds"] = {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}};
  }
  return j.dump();
}

std::string TreeMappingsCsv(const TreeParams& p) {
  std::ostringstream out;
  double h_sat = p.Get(ParamId::kHSat);
  out << "hormone,N_long,N_dwarf,D_long_cm,D_dwarf_cm,b_L,b_g,P_terminal,P_tl,"
         "P_lateral_at_age_P_l_years\n";
  for (int i = 0; i <= 60; ++i) {
    float h = static_cast<float>(1.5 * h_sat * i / 60.0);
    // A long and a dwarf shoot of initial hormone h, as BreakBuds sizes them (fig. 2.5, fig. 2.13).
    float d_dwarf = ShootLengthRamp(p, h, true, ParamId::kDLow, ParamId::kDHigh) *
                    static_cast<float>(p.Get(ParamId::kDwarfInternodeRatio));
    BreakChances chance = BudBreakChances(p, h, 1 + static_cast<int>(p.Get(ParamId::kPLYears)));
    out << FormatFloat(h) << ","
        << FormatFloat(ShootLengthRamp(p, h, false, ParamId::kNLow, ParamId::kNHigh)) << ","
        << FormatFloat(ShootLengthRamp(p, h, true, ParamId::kNLow, ParamId::kNHigh)) << ","
        << FormatFloat(ShootLengthRamp(p, h, false, ParamId::kDLow, ParamId::kDHigh)) << ","
        << FormatFloat(d_dwarf) << ","
        << FormatFloat(HormoneRamp(p, h, ParamId::kBLLow, ParamId::kBLHigh)) << ","
        << FormatFloat(HormoneRamp(p, h, ParamId::kBGLow, ParamId::kBGHigh)) << ","
        << FormatFloat(chance.terminal) << "," << FormatFloat(chance.terminally_lateral) << ","
        << FormatFloat(chance.lateral) << "\n";
  }
  out << "\nyear,P_l_max\n";
  int last = static_cast<int>(p.Get(ParamId::kPLYears)) + 5;
  for (int year = 1; year <= last; ++year) {
    out << year << "," << FormatFloat(LateralBreakMax(p, year)) << "\n";
  }
  return out.str();
}

}  // namespace niwa
