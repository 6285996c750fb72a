// Tests of the tree table's "Getting started" group (ParamSpec::simple): a small group of rows,
// each with a plain name and help, carried in the table JSON, and each one that regrows the tree
// actually changes its form between the ends of its range (what makes it worth a newcomer's try).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "params/param_json.h"
#include "tree/growth.h"
#include "tree/presets.h"
#include "tree/tree_params.h"
#include "tree/tree_report.h"

namespace niwa {
namespace {

std::vector<const ParamSpec*> SimpleRows() {
  std::vector<const ParamSpec*> rows;
  for (const ParamSpec& spec : TreeParamTable()) {
    if (spec.simple != nullptr) rows.push_back(&spec);
  }
  return rows;
}

TEST(SimpleControls, ASmallGroupWithPlainNamesAndHelp) {
  const std::vector<const ParamSpec*> rows = SimpleRows();
  ASSERT_GE(rows.size(), 4u);
  ASSERT_LE(rows.size(), 8u);
  std::set<std::string> names;
  for (const ParamSpec* spec : rows) {
    ASSERT_NE(spec->simple_help, nullptr) << spec->key;
    EXPECT_GT(std::string(spec->simple_help).size(), 20u) << spec->key;
    EXPECT_TRUE(names.insert(spec->simple).second) << "repeated simple name " << spec->simple;
    // A plain name, not the thesis's key.
    EXPECT_NE(std::string(spec->simple), std::string(spec->key));
  }
}

TEST(SimpleControls, TheTableJsonCarriesThemOnlyOnTheirRows) {
  const nlohmann::json table = nlohmann::json::parse(ParamTableJson(TreeParamTable()));
  std::size_t marked = 0;
  for (const nlohmann::json& row : table) {
    const std::size_t index = *TreeParamTable().Find(row["key"].get<std::string>());
    const ParamSpec& spec = TreeParamTable()[index];
    if (spec.simple == nullptr) {
      EXPECT_FALSE(row.contains("simple")) << spec.key;
      EXPECT_FALSE(row.contains("simple_help")) << spec.key;
      continue;
    }
    ++marked;
    EXPECT_EQ(row["simple"], spec.simple);
    EXPECT_EQ(row["simple_help"], spec.simple_help);
  }
  EXPECT_EQ(marked, SimpleRows().size());
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
  for (const ParamSpec* spec : SimpleRows()) {
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
    EXPECT_GT(change, 0.15) << spec->key << " (" << spec->simple << ") " << low << " -> "
                            << high_capped << ": internodes " << a.internodes << " -> "
                            << b.internodes << ", height " << a.height << " -> " << b.height
                            << " cm, width " << a.width << " -> " << b.width << " cm";
  }
}

}  // namespace
}  // namespace niwa
