// JSON reading and writing of parameters and trees with nlohmann-json.
#include "io/json_io.h"

#include <nlohmann/json.hpp>

namespace niwa {

using nlohmann::json;
using nlohmann::ordered_json;

std::string ApplyParamsJson(const std::string& text, ParamSet* params) {
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) return "params: malformed JSON";
  if (!document.is_object()) return "params: the JSON must be an object of key: number";
  const json& values = document.contains("params") ? document["params"] : document;
  if (!values.is_object()) return "params: 'params' must be an object of key: number";
  ParamSet result = *params;
  for (auto it = values.begin(); it != values.end(); ++it) {
    std::optional<ParamId> id = FindParam(it.key());
    if (!id) {
      if (&values == &document &&
          (it.key() == "name" || it.key() == "title" || it.key() == "source" ||
           it.key() == "years" || it.key() == "seed")) {
        continue;
      }
      return "unknown parameter '" + it.key().substr(0, 64) + "'";
    }
    if (!it.value().is_number()) {
      return it.key() + ": must be " + RangeText(Spec(*id));
    }
    std::string error = result.Set(*id, it.value().get<double>());
    if (!error.empty()) return error;
  }
  *params = result;
  return "";
}

std::string ParamsToJson(const ParamSet& params, int indent) {
  ordered_json out = ordered_json::object();
  for (const ParamSpec& spec : ParamTable()) out[spec.key] = params.Get(spec.id);
  return out.dump(indent);
}

namespace {

ordered_json Vec(const glm::vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

const char* KindName(ShootKind kind) {
  switch (kind) {
    case ShootKind::kSeedling:
      return "seedling";
    case ShootKind::kTerminal:
      return "terminal";
    case ShootKind::kTerminallyLateral:
      return "terminally_lateral";
    case ShootKind::kLateral:
      return "lateral";
  }
  return "unknown";
}

const char* StateName(BudState state) {
  switch (state) {
    case BudState::kBreaking:
      return "breaking";
    case BudState::kDormant:
      return "dormant";
    case BudState::kUsed:
      return "used";
  }
  return "unknown";
}

}  // namespace

std::string TreeToJson(const Tree& tree) {
  ordered_json out;
  out["format"] = "niwa-tree-1";
  out["preset"] = tree.preset;
  out["seed"] = tree.seed;
  out["years"] = tree.years;
  out["truncated"] = tree.truncated;
  out["params"] = ordered_json::parse(ParamsToJson(tree.params, -1));
  ordered_json branches = ordered_json::array();
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    ordered_json j;
    j["id"] = b.id;
    j["parent"] = b.parent;
    j["parent_node"] = b.parent_node;
    j["year"] = b.year;
    j["kind"] = KindName(b.kind);
    j["dwarf"] = b.dwarf;
    j["hormone"] = b.hormone;
    j["light"] = b.light;
    j["radius"] = BranchRadius(b);
    ordered_json nodes = ordered_json::array();
    for (const glm::vec3& n : b.nodes) nodes.push_back(Vec(n));
    j["nodes"] = std::move(nodes);
    ordered_json buds = ordered_json::array();
    for (const Bud& bud : b.buds) {
      buds.push_back({{"node", bud.node},
                      {"kind", KindName(bud.kind)},
                      {"state", StateName(bud.state)},
                      {"flower", bud.flower}});
    }
    j["buds"] = std::move(buds);
    ordered_json leaves = ordered_json::array();
    for (const Leaf& leaf : b.leaves) {
      leaves.push_back({{"node", leaf.node}, {"direction", Vec(leaf.direction)}});
    }
    j["leaves"] = std::move(leaves);
    j["flowers"] = b.flowers;
    branches.push_back(std::move(j));
  }
  out["branches"] = std::move(branches);
  return out.dump(1);
}

namespace {

// What an edit of a row invalidates (the web page reruns only that): sway and wind rows restart
// the sway, render rows redraw, every other row regrows the tree.
const char* ParamStage(const std::string& group) {
  if (group == "sway" || group == "wind") return "sway";
  if (group == "render") return "view";
  return "grow";
}

// The panel's section title of a group.
std::string ParamGroupTitle(const std::string& group) {
  if (group == "dormancy_break") return "Dormancy break";
  if (group == "shape") return "Shape and limits";
  std::string title = group;
  for (char& c : title) c = c == '_' ? ' ' : c;
  if (!title.empty() && title[0] >= 'a' && title[0] <= 'z')
    title[0] = static_cast<char>(title[0] - 'a' + 'A');
  return title;
}

}  // namespace

std::string ParamTableJson() {
  ordered_json out = ordered_json::array();
  for (const ParamSpec& s : ParamTable()) {
    out.push_back({{"key", s.key},
                   {"symbol", s.symbol},
                   {"unit", s.unit},
                   {"default", s.default_value},
                   {"min", s.min_value},
                   {"max", s.max_value},
                   {"integer", s.integer},
                   {"group", s.group},
                   {"group_title", ParamGroupTitle(s.group)},
                   {"stage", ParamStage(s.group)},
                   {"help", s.help}});
  }
  return out.dump();
}

}  // namespace niwa
