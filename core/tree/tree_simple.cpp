// The tree's "Getting started" group and the table JSON that carries it.
#include "tree/tree_simple.h"

#include <nlohmann/json.hpp>

#include "params/param_json.h"

namespace niwa {

const std::vector<SimpleControl>& TreeSimpleControls() {
  using TP = TreeParam;
  static const std::vector<SimpleControl> group = {
      {TP::kDHigh, "Shoot length",
       "How far the strong shoots grow each year: longer shoots make a taller, wider tree."},
      {TP::kPsiL, "Branch angle",
       "How far side shoots lean out from their parent: small is upright and narrow, large is "
       "spreading."},
      {TP::kPLOld, "Branchiness",
       "How many side buds open into shoots each year: more makes a denser crown."},
      {TP::kSunWeight, "Sun",
       "How much light comes from the sun instead of an overcast sky: the tree leans and grows "
       "towards it (the sun's place is in the Light section)."},
      {TP::kBGHigh, "Uprightness",
       "How strongly the strong shoots turn upwards: below 0 they droop, as in a weeping cherry."},
      {TP::kLeafSize, "Leaf size", "Length of each leaf; bigger leaves also shade each other more."},
      {TP::kWindSpeed, "Wind",
       "How hard the wind blows when you press Blow (the tree is not grown again)."},
  };
  return group;
}

std::string TreeParamTableJsonWithSimple() {
  nlohmann::ordered_json table = nlohmann::ordered_json::parse(ParamTableJson(TreeParamTable()));
  for (const SimpleControl& control : TreeSimpleControls()) {
    nlohmann::ordered_json& row = table[static_cast<std::size_t>(control.row)];
    row["simple"] = control.name;
    row["simple_help"] = control.help;
  }
  return table.dump();
}

}  // namespace niwa
