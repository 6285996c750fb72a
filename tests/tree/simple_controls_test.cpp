// Tests of the tree's "Getting started" group (core/tree/tree_simple.h): a small group of rows,
// each with a plain name and help, carried in the page's table JSON, and each one that regrows the
// tree actually changes its form across its range (what makes it worth a newcomer's try).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "params/param_json.h"
#include "tree/growth.h"
#include "tree/presets.h"
#include "tree/tree_params.h"
#include "tree/tree_report.h"
#include "tree/tree_simple.h"

namespace niwa {
namespace {

TEST(SimpleControls, ASmallGroupInTableOrderWithPlainNamesAndHelp) {
  const std::vector<SimpleControl>& group = TreeSimpleControls();
  ASSERT_GE(group.size(), 4u);
  ASSERT_LE(group.size(), 8u);
  std::set<std::string> names;
  int last = -1;
  for (const SimpleControl& control : group) {
    const ParamSpec& spec = Spec(control.row);
    EXPECT_GT(static_cast<int>(control.row), last) << spec.key << " out of table order";
    last = static_cast<int>(control.row);
    EXPECT_GT(std::string(control.help).size(), 20u) << spec.key;
    EXPECT_TRUE(names.insert(control.name).second) << "repeated name " << control.name;
    EXPECT_NE(std::string(control.name), std::string(spec.key));  // a plain name, not the key
  }
}

TEST(SimpleControls, TheTableJsonCarriesThemOnlyOnTheirRows) {
  const nlohmann::json table = nlohmann::json::parse(TreeParamTableJsonWithSimple());
  const nlohmann::json plain = nlohmann::json::parse(ParamTableJson(TreeParamTable()));
  ASSERT_EQ(table.size(), plain.size());
  std::size_t marked = 0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    nlohmann::json row = table[i];
    const SimpleControl* control = nullptr;
    for (const SimpleControl& c : TreeSimpleControls()) {
      if (static_cast<std::size_t>(c.row) == i) control = &c;
    }
    if (control != nullptr) {
      ++marked;
      EXPECT_EQ(row["simple"], control->name);
      EXPECT_EQ(row["simple_help"], control->help);
      row.erase("simple");
      row.erase("simple_help");
    }
    EXPECT_EQ(row, plain[i]) << "row " << i << " differs beyond the simple fields";
  }
  EXPECT_EQ(marked, TreeSimpleControls().size());
}

struct Form {
  double internodes, height, width;
};

Form GrowWith(const ParamSpec& spec, double value) {
  GrowRequest request;
  request.preset = "sakura-thesis";
  request.params = FindPreset("sakura-thesis")->params;
  request.years = 7;
  EXPECT_TRUE(request.params.Set(static_cast<std::size_t>(spec.id), value).ok()) << spec.key;
  const Tree tree = GrowTree(request);
  const nlohmann::json stats = nlohmann::json::parse(TreeStatsJson(tree, GrowthTimings{}));
  return {stats["internodes"].get<double>(), stats["height"].get<double>(),
          ComputeTreeForm(tree).crown_width};
}

// The relative change from a to b (0 when both are 0).
double Change(double a, double b) {
  const double scale = std::max(std::fabs(a), std::fabs(b));
  return scale > 0 ? std::fabs(a - b) / scale : 0.0;
}

TEST(SimpleControls, EachGrowthControlChangesTheTreeAcrossItsRange) {
  for (const SimpleControl& control : TreeSimpleControls()) {
    const ParamSpec* spec = &Spec(control.row);
    if (spec->stage != Stage::kGrow) continue;  // wind: no regrowth (the page's sway test)
    // From a quarter to three quarters of the way between the row's default and its range ends,
    // so no end case (0 buds, a 90° angle) decides the test.
    const double low = spec->default_value - 0.75 * (spec->default_value - spec->min_value);
    const double high = spec->default_value + 0.75 * (spec->max_value - spec->default_value);
    const double high_capped = spec->max_value > 10 * std::max(1.0, spec->default_value)
                                   ? spec->default_value * 3  // D_high up to 100 cm: 3x is plenty
                                   : high;
    const Form a = GrowWith(*spec, low), b = GrowWith(*spec, high_capped);
    const double change = std::max(
        {Change(a.internodes, b.internodes), Change(a.height, b.height), Change(a.width, b.width)});
    EXPECT_GT(change, 0.15) << spec->key << " (" << control.name << ") " << low << " -> "
                            << high_capped << ": internodes " << a.internodes << " -> "
                            << b.internodes << ", height " << a.height << " -> " << b.height
                            << " cm, width " << a.width << " -> " << b.width << " cm";
  }
}

}  // namespace
}  // namespace niwa
