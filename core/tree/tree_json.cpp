// JSON writing of whole trees with nlohmann-json.
#include "tree/tree_json.h"

#include <nlohmann/json.hpp>

#include "params/param_json.h"

namespace niwa {

using nlohmann::ordered_json;

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

}  // namespace niwa
