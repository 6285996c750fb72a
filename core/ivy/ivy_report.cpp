// Ivy measurements (spec §3's table) and JSON output.
#include "ivy/ivy_report.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <nlohmann/json.hpp>

#include "geom/linear_queries.h"
#include "ivy/lstring.h"
#include "math/det_math.h"
#include "params/param_json.h"

namespace niwa::ivy {
namespace {

nlohmann::json Vec(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

const Bud& BudOf(const IvyModel& m, int id) { return m.buds[static_cast<std::size_t>(id)]; }

glm::dvec3 Direction(const IvyModel& m, const Internode& in) {
  glm::dvec3 v = BudOf(m, in.to_bud).pos - BudOf(m, in.from_bud).pos;
  double len = std::sqrt(glm::dot(v, v));
  return len > 0 ? v / len : v;
}

}  // namespace

int LateralsAt(const IvyModel& model, int step) {
  int n = 0;
  for (const Axis& a : model.axes) n += a.order > 0 && a.born_step <= step;
  return n;
}

int InternodesAt(const IvyModel& model, int step) {
  int n = 0;
  for (const Internode& in : model.internodes) n += in.step <= step;
  return n;
}

IvyStats MeasureIvy(const IvyModel& m, const GrowLog& log, const geom::TriMesh* mesh,
                    const IvyParams& params, const geom::TriMesh* attach_mesh, bool overlap_sweep) {
  IvyStats s;
  const double d = params.Get(IvyParam::kD), eps = params.Get(IvyParam::kEps);
  const double L = params.Get(IvyParam::kL), r_tip = params.Get(IvyParam::kRTip);
  const glm::dvec3 up = [&] {
    glm::dvec3 u(params.Get(IvyParam::kUpX), params.Get(IvyParam::kUpY),
                 params.Get(IvyParam::kUpZ));
    return u / std::sqrt(glm::dot(u, u));
  }();
  s.steps_run = log.steps_run;
  s.extinct_step = log.extinct_step;
  s.internodes = static_cast<int>(m.internodes.size());
  for (const Bud& b : m.buds) {
    s.buds_A += b.kind == BudKind::kApical;
    s.buds_D += b.kind == BudKind::kDormant;
    s.buds_Z += b.kind == BudKind::kEnding;
  }
  s.axes = static_cast<int>(m.axes.size());
  for (const Axis& a : m.axes) {
    s.laterals += a.order > 0;
    s.max_order = std::max(s.max_order, a.order);
  }
  for (const Internode& in : m.internodes)
    s.main_axis_internodes += m.axes[static_cast<std::size_t>(in.axis)].order == 0;
  s.first_break_step = log.first_break_step;
  for (const StepLog& st : log.steps) {
    s.released_breaks += st.released_breaks;
    s.p3_A += st.p3_a;
    s.p3_D += st.p3_d;
  }
  // C4 (§4 "分岐枝の伸び率は親枝より小さい": the laterals' elongation rate is below the parent's):
  // for each lateral, the internodes its apex made by p0 and those its parent axis's apex made in
  // the steps both apices were alive, (born, min(parent death, lateral death, S)]; the internode
  // p1 made at the break (step born) is the break itself, not elongation. Pooled over the
  // laterals: rho = Σ lateral / Σ parent. Laterals born after their parent apex died (the
  // obstacle's dormancy break) are reiterations, not compared; no window with parent growth:
  // rho undefined (rho_laterals 0). docs/ivy-model.md argues the choice.
  const int S = log.steps_run;
  std::vector<std::vector<int>> steps_of_axis(m.axes.size());
  for (const Internode& in : m.internodes)
    steps_of_axis[static_cast<std::size_t>(in.axis)].push_back(in.step);
  long lateral_sum = 0, parent_sum = 0;
  for (const Axis& a : m.axes) {
    if (a.order == 0) continue;
    const Axis& parent = m.axes[static_cast<std::size_t>(a.parent_axis)];
    if (parent.death_step >= 0 && a.born_step > parent.death_step) {
      ++s.reiterations;
      continue;
    }
    int end = parent.death_step >= 0 ? parent.death_step : S;
    if (a.death_step >= 0) end = std::min(end, a.death_step);
    int lat = 0, par = 0;
    for (int st : steps_of_axis[static_cast<std::size_t>(a.id)])
      lat += st > a.born_step && st <= end;
    for (int st : steps_of_axis[static_cast<std::size_t>(parent.id)])
      par += st > a.born_step && st <= end;
    lateral_sum += lat;
    parent_sum += par;
    s.rho_laterals += par > 0;
    if (lat > par) ++s.lateral_longer_than_parent;
  }
  s.rho = parent_sum > 0 ? static_cast<double>(lateral_sum) / static_cast<double>(parent_sum)
                         : std::numeric_limits<double>::quiet_NaN();
  // C1, re-measured with the brute-force twins.
  s.tri_count = mesh ? mesh->triangle_count() : 0;
  int within = 0;
  s.clearance_min = std::numeric_limits<double>::infinity();
  s.clearance_max = 0;
  s.tendrils = log.tendrils;
  s.hang_internodes = log.hang_internodes;
  for (const Bud& b : m.buds) {
    if (b.hang > 0) {
      ++s.hanging_buds;
      continue;
    }
    double c = b.clearance;
    if (mesh) {
      geom::ClosestHit h =
          geom::ClosestPointLinear(attach_mesh ? *attach_mesh : *mesh, glm::vec3(b.pos),
                                   std::numeric_limits<float>::infinity());
      c = static_cast<double>(h.distance);
    }
    s.clearance_min = std::min(s.clearance_min, c);
    s.clearance_max = std::max(s.clearance_max, c);
    // The seed is snapped to d/2; every other node passed eps <= dist <= d in the search.
    within += c <= d && (c >= eps || b.parent < 0);
  }
  const std::size_t attached = m.buds.size() - static_cast<std::size_t>(s.hanging_buds);
  s.frac_nodes_within_d =
      attached == 0 ? 0 : static_cast<double>(within) / static_cast<double>(attached);
  s.up_min = m.internodes.empty() ? 0 : std::numeric_limits<double>::infinity();
  double up_sum = 0;
  for (const Internode& in : m.internodes) {
    const glm::dvec3 a = BudOf(m, in.from_bud).pos, b = BudOf(m, in.to_bud).pos;
    if (mesh && geom::SegmentHitsLinear(*mesh, glm::vec3(a), glm::vec3(b))) ++s.internode_hits;
    const double len = std::sqrt(glm::dot(b - a, b - a));
    s.internode_len_err_max = std::max(s.internode_len_err_max, std::fabs(len - L));
    const double u = glm::dot(Direction(m, in), up);
    s.up_min = std::min(s.up_min, u);
    up_sum += u;
  }
  for (const Internode& in : m.internodes) {
    const Bud& a = BudOf(m, in.from_bud);
    const Bud& b = BudOf(m, in.to_bud);
    if (glm::dot(a.outward, b.outward) >= 0.5) continue;  // cos 60°
    if (glm::dot(b.anchor - a.anchor, a.outward) < 0) {
      ++s.convex_crossings;
    } else {
      ++s.concave_crossings;
    }
  }
  s.up_mean = m.internodes.empty() ? 0 : up_sum / static_cast<double>(m.internodes.size());
  for (int root : m.roots) {
    const double y0 = glm::dot(BudOf(m, root).pos, up);
    for (const Bud& b : m.buds)
      if (b.plant == BudOf(m, root).plant) s.rise = std::max(s.rise, glm::dot(b.pos, up) - y0);
  }
  // P1: the turn between consecutive internodes of one axis (at a bud with a same-axis child).
  for (const Internode& in : m.internodes) {
    const Bud& from = BudOf(m, in.from_bud);
    if (from.parent < 0 || from.axis != in.axis) continue;
    const glm::dvec3 prev = from.dir, next = Direction(m, in);
    const double angle = det::Acos(std::clamp(glm::dot(prev, next), -1.0, 1.0)) * 180.0 / det::kPi;
    s.bend_max = std::max(s.bend_max, angle);
  }
  // P2: non-adjacent internode pairs closer than two tip radii (sweep over x, so O(n log n + k)).
  if (overlap_sweep) {
    const double reach = 2 * r_tip;
    struct Span {
      double lo, hi;
      std::size_t index;
    };
    std::vector<Span> spans;
    for (std::size_t i = 0; i < m.internodes.size(); ++i) {
      const double x0 = BudOf(m, m.internodes[i].from_bud).pos.x;
      const double x1 = BudOf(m, m.internodes[i].to_bud).pos.x;
      spans.push_back({std::min(x0, x1), std::max(x0, x1), i});
    }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) {
      return a.lo < b.lo || (a.lo == b.lo && a.index < b.index);
    });
    for (std::size_t i = 0; i < spans.size(); ++i) {
      const Internode& a = m.internodes[spans[i].index];
      for (std::size_t j = i + 1; j < spans.size() && spans[j].lo <= spans[i].hi + reach; ++j) {
        ++s.overlap_pairs_examined;
        const Internode& b = m.internodes[spans[j].index];
        if (a.from_bud == b.from_bud || a.from_bud == b.to_bud || a.to_bud == b.from_bud ||
            a.to_bud == b.to_bud)
          continue;
        if (SegmentSegmentDistance(BudOf(m, a.from_bud).pos, BudOf(m, a.to_bud).pos,
                                   BudOf(m, b.from_bud).pos, BudOf(m, b.to_bud).pos) < reach)
          ++s.overlap_pairs;
      }
    }
  }
  s.leaves = static_cast<int>(m.buds.size()) - static_cast<int>(m.roots.size());
  s.suckers = static_cast<int>(m.buds.size()) - s.hanging_buds;
  // E5 ledger: ΣN(s) = ΣN(s-1) + accumulated - spent - lost, worst error over the steps.
  double prev = log.nutrient_start;
  for (const StepLog& st : log.steps) {
    s.ledger_err = std::max(
        s.ledger_err, std::fabs(st.nutrient_total - (prev + st.accumulated - st.spent - st.lost)));
    prev = st.nutrient_total;
  }
  s.nutrient_total = prev;
  s.lstring_ok = LStringMatchesModel(m);
  if (m.buds.empty() || std::isinf(s.clearance_min)) s.clearance_min = 0;
  return s;
}

namespace {

// The nearest z (largest: the viewer is at +z) of a mesh at every cell centre of the grid.
void DepthRaster(const geom::TriMesh& mesh, double x0, double y0, double cell, int cells,
                 std::vector<double>* depth) {
  const std::size_t n = mesh.triangle_count();
  for (std::size_t t = 0; t < n; ++t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
    const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (area == 0) continue;  // edge-on: hides nothing
    const double lo_x = std::min({a.x, b.x, c.x}), hi_x = std::max({a.x, b.x, c.x});
    const double lo_y = std::min({a.y, b.y, c.y}), hi_y = std::max({a.y, b.y, c.y});
    // Cells whose centre x0 + (i + 1/2) cell lies in [lo, hi].
    const int i0 = std::max(0, static_cast<int>(std::ceil((lo_x - x0) / cell - 0.5)));
    const int i1 = std::min(cells - 1, static_cast<int>(std::floor((hi_x - x0) / cell - 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((lo_y - y0) / cell - 0.5)));
    const int j1 = std::min(cells - 1, static_cast<int>(std::floor((hi_y - y0) / cell - 0.5)));
    for (int j = j0; j <= j1; ++j) {
      const double py = y0 + (j + 0.5) * cell;
      for (int i = i0; i <= i1; ++i) {
        const double px = x0 + (i + 0.5) * cell;
        const double w0 = ((b.x - px) * (c.y - py) - (c.x - px) * (b.y - py)) / area;
        const double w1 = ((c.x - px) * (a.y - py) - (a.x - px) * (c.y - py)) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double z = w0 * a.z + w1 * b.z + w2 * c.z;
        double& d = (*depth)[static_cast<std::size_t>(j) * static_cast<std::size_t>(cells) +
                             static_cast<std::size_t>(i)];
        d = std::max(d, z);
      }
    }
  }
}

}  // namespace

double LeafCoverFront(const geom::TriMesh& support, const geom::TriMesh& leaves, int cells) {
  if (support.positions.empty() || cells < 1) return 0;
  glm::dvec3 lo(support.positions[0]), hi = lo;
  for (const glm::vec3& p : support.positions) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  const double cell = std::max(hi.x - lo.x, hi.y - lo.y) / cells;
  if (!(cell > 0)) return 0;
  const double none = -std::numeric_limits<double>::infinity();
  const std::size_t count = static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells);
  std::vector<double> s_depth(count, none), l_depth(count, none);
  DepthRaster(support, lo.x, lo.y, cell, cells, &s_depth);
  DepthRaster(leaves, lo.x, lo.y, cell, cells, &l_depth);
  // "Level with it": within a millionth of the support's size (a leaf lying on a face).
  const double tol = 1e-6 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  std::size_t seen = 0, covered = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (s_depth[k] == none) continue;
    ++seen;
    covered += l_depth[k] >= s_depth[k] - tol;
  }
  return seen == 0 ? 0 : static_cast<double>(covered) / static_cast<double>(seen);
}

std::string IvyStatsJson(const IvyStats& s, const GrowLog& log, const IvyModel& model,
                         const IvyTimings& t) {
  nlohmann::json j;
  j["steps_run"] = s.steps_run;
  j["extinct_step"] = s.extinct_step;
  j["truncated"] = !log.truncated_by.empty();  // stopped at a budget (ivy_budget.h)
  if (!log.truncated_by.empty()) j["truncated_by"] = log.truncated_by;
  if (!s.tree_truncated_by.empty()) j["tree_truncated_by"] = s.tree_truncated_by;
  j["tri_count"] = s.tri_count;
  j["internodes"] = s.internodes;
  j["buds"] = {{"A", s.buds_A}, {"D", s.buds_D}, {"Z", s.buds_Z}};
  j["axes"] = s.axes;
  j["laterals"] = s.laterals;
  nlohmann::json at = nlohmann::json::object();
  for (int step : {10, 20, 30, 40, 50}) at[std::to_string(step)] = LateralsAt(model, step);
  j["laterals_at"] = at;
  j["main_axis_internodes"] = s.main_axis_internodes;
  j["max_order"] = s.max_order;
  j["first_break_step"] = s.first_break_step;
  j["released_breaks"] = s.released_breaks;
  j["reiterations"] = s.reiterations;
  j["p3"] = {{"A", s.p3_A}, {"D", s.p3_D}};
  j["rho"] = std::isnan(s.rho) ? nlohmann::json(nullptr) : nlohmann::json(s.rho);
  j["rho_laterals"] = s.rho_laterals;
  j["lateral_longer_than_parent"] = s.lateral_longer_than_parent;
  j["frac_nodes_within_d"] = s.frac_nodes_within_d;
  j["clearance"] = {{"min", s.clearance_min}, {"max", s.clearance_max}};
  j["internode_hits"] = s.internode_hits;
  j["convex_crossings"] = s.convex_crossings;
  j["concave_crossings"] = s.concave_crossings;
  j["internode_len_err_max"] = s.internode_len_err_max;
  j["up_min"] = s.up_min;
  j["up_mean"] = s.up_mean;
  j["rise"] = s.rise;
  j["bend_max"] = s.bend_max;
  j["overlap_pairs"] =
      s.overlap_skipped_by.empty() ? nlohmann::json(s.overlap_pairs) : nlohmann::json(nullptr);
  if (!s.overlap_skipped_by.empty()) j["overlap_skipped_by"] = s.overlap_skipped_by;
  j["leaves"] = s.leaves;
  j["leaves_thinned"] = s.leaves_thinned;
  j["leaf_cover"] = s.leaf_cover < 0 ? nlohmann::json(nullptr) : nlohmann::json(s.leaf_cover);
  j["suckers"] = s.suckers;
  j["hanging"] = {
      {"tendrils", s.tendrils}, {"internodes", s.hang_internodes}, {"buds", s.hanging_buds}};
  j["nutrient_total"] = s.nutrient_total;
  j["ledger_err"] = s.ledger_err;
  j["lstring_ok"] = s.lstring_ok;
  nlohmann::json rejected;
  for (int r = 0; r < kRejectCount; ++r)
    rejected[RejectName(r)] = log.rejected[static_cast<std::size_t>(r)];
  j["search"] = {{"attempts", log.attempts},
                 {"candidates", log.candidates},
                 {"retries", log.retries},
                 {"failures", log.failures},
                 {"tangent_retries", log.tangent_retries},
                 {"tangent_saves", log.tangent_saves},
                 {"rejected", rejected}};
  j["queries"] = {{"closest", log.closest.queries}, {"segment", log.segment.queries}};
  const uint64_t q = log.closest.queries + log.segment.queries;
  j["bvh_visits_per_query"] =
      q == 0 ? 0.0
             : static_cast<double>(log.closest.nodes_visited + log.segment.nodes_visited) /
                   static_cast<double>(q);
  j["ms"] = t.ms;
  j["ms_bvh"] = t.ms_bvh;
  j["ms_rules"] = t.ms_rules;
  j["ms_search"] = t.ms_search;
  j["ms_mesh"] = t.ms_mesh;
  return j.dump();
}

std::string IvyModelJson(const IvyModel& m, const IvyParams& params, uint64_t seed, int steps) {
  nlohmann::json j;
  nlohmann::json buds = nlohmann::json::array();
  for (const Bud& b : m.buds) {
    buds.push_back({{"id", b.id},
                    {"kind", std::string(1, BudSymbol(b.kind))},
                    {"pos", Vec(b.pos)},
                    {"dir", Vec(b.dir)},
                    {"N", b.N},
                    {"parent", b.parent},
                    {"children", {b.child[0], b.child[1]}},
                    {"plant", b.plant},
                    {"axis", b.axis},
                    {"order", b.order},
                    {"born_step", b.born_step},
                    {"died_step", b.died_step},
                    {"released", b.released},
                    {"anchor", Vec(b.anchor)},
                    {"anchor_tri", b.anchor_tri},
                    {"clearance", b.clearance}});
    if (b.hang > 0) buds.back()["hang"] = b.hang;  // a tendril's bud (the row "hang")
  }
  nlohmann::json internodes = nlohmann::json::array();
  for (const Internode& in : m.internodes)
    internodes.push_back(
        {{"from", in.from_bud}, {"to", in.to_bud}, {"step", in.step}, {"axis", in.axis}});
  nlohmann::json axes = nlohmann::json::array();
  for (const Axis& a : m.axes)
    axes.push_back({{"id", a.id},
                    {"order", a.order},
                    {"parent_axis", a.parent_axis},
                    {"base_bud", a.base_bud},
                    {"born_step", a.born_step},
                    {"death_step", a.death_step},
                    {"rotation", {a.rotation[0], a.rotation[1], a.rotation[2]}}});
  j["buds"] = buds;
  j["internodes"] = internodes;
  j["axes"] = axes;
  j["roots"] = m.roots;
  j["params"] = nlohmann::json::parse(ParamsToJson(params, -1));
  j["seed"] = seed;
  j["steps"] = steps;
  return j.dump(1);
}

}  // namespace niwa::ivy
