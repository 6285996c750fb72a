// A skeleton second table (not a real study) proves the mechanism takes any table: typed access,
// checked setters, JSON, the table as JSON, and hash keys with a study prefix ("ivy.").
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/hash_codec.h"
#include "params/param_json.h"
#include "params/param_table.h"
#include "tree/tree_params.h"

namespace niwa {
namespace {

// What a study writes in core/<study>/<study>_params.{h,cpp}: an enum, its table and TableOf.
enum class SkeletonParam : int { kT1, kAlpha, kSteps, kCount };

const ParamTable& SkeletonTable() {
  static const ParamTable table(
      "skeleton",
      {{0, "t1", "t_1", "", 1.5, 0, 10, false, "rules", Stage::kGrow, "A rule threshold."},
       {1, "alpha", "α", "deg", 30, -90, 90, false, "rules", Stage::kMesh, "A mesh angle."},
       {2, "steps", "n", "", 8, 1, 64, true, "look", Stage::kView, "Steps drawn."}},
      {{"rules", "Growth rules"}, {"look", "Look"}});
  return table;
}
const ParamTable& TableOf(SkeletonParam) { return SkeletonTable(); }
using SkeletonParams = StudyParams<SkeletonParam>;

TEST(SecondTable, HasItsOwnNameRowsDefaultsAndChecks) {
  SkeletonParams p;
  EXPECT_EQ(p.table().name(), "skeleton");
  EXPECT_EQ(p.size(), 3u);
  EXPECT_EQ(p.Get(SkeletonParam::kT1), 1.5);
  EXPECT_EQ(p.GetInt(SkeletonParam::kSteps), 8);
  EXPECT_TRUE(p.Set(SkeletonParam::kAlpha, -45).ok());
  EXPECT_EQ(p.Get(SkeletonParam::kAlpha), -45.0);
  EXPECT_EQ(p.Set(SkeletonParam::kSteps, 2.5).Line(),
            "steps: 2.5 is out of range; must be a whole number in [1, 64]");
  EXPECT_EQ(p.SetFromText("t1", "11").Line(),
            "t1: 11 is out of range; must be a number in [0, 10]");
  EXPECT_EQ(p.SetFromAssignment("t1=2").Line(), "");
  EXPECT_EQ(p.Get(SkeletonParam::kT1), 2.0);
  // Keys of another table are unknown here, and the sets of two tables never compare equal.
  EXPECT_EQ(p.SetFromText("gamma", "0.3").Line(), "unknown parameter 'gamma'");
  EXPECT_NE(static_cast<const ParamSet&>(p), static_cast<const ParamSet&>(TreeParams()));
  EXPECT_EQ(std::string(SkeletonTable().GroupTitle("look")), "Look");
  EXPECT_EQ(std::string(SkeletonTable().GroupTitle("nope")), "");
}

TEST(SecondTable, JsonAndTheTableAsJsonWorkUnchanged) {
  SkeletonParams p;
  EXPECT_EQ(ApplyParamsJson(R"({"t1": 3, "steps": 16})", &p).Line(), "");
  EXPECT_EQ(ParamsToJson(p, -1), R"({"t1":3.0,"alpha":30.0,"steps":16.0})");
  EXPECT_EQ(ApplyParamsJson(R"({"alpha_t": 0.5})", &p).Line(), "unknown parameter 'alpha_t'");
  nlohmann::json table = nlohmann::json::parse(ParamTableJson(SkeletonTable()));
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[0]["group_title"], "Growth rules");
  EXPECT_EQ(table[0]["stage"], "grow");
  EXPECT_EQ(table[1]["stage"], "mesh");
  EXPECT_EQ(table[2]["stage"], "view");
  EXPECT_EQ(table[2]["group_title"], "Look");
}

TEST(SecondTable, HashKeysCarryTheStudyPrefixOnAComposedPage) {
  SkeletonParams p;
  TreeParams tree;
  std::vector<std::string> notices;
  for (const auto& [key, value] : SplitHash("#ivy.t1=4&gamma=0.3&ivy.steps=100&ivy.nope=1")) {
    if (ApplyHashParam(key, value, "ivy.", &p, &notices)) continue;
    if (ApplyHashParam(key, value, "", &tree, &notices)) continue;
    notices.push_back("unknown key '" + Printable(key) + "' dropped");
  }
  EXPECT_EQ(p.Get(SkeletonParam::kT1), 4.0);
  EXPECT_EQ(p.Get(SkeletonParam::kSteps), 64.0);
  EXPECT_EQ(tree.Get(TreeParam::kGamma), 0.3);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_EQ(notices[0], "ivy.steps: clamped to 64, must be a whole number in [1, 64]");
  EXPECT_EQ(notices[1], "unknown key 'ivy.nope' dropped");
  EXPECT_EQ(EncodeChangedParams(p, SkeletonParams(), "ivy."), "&ivy.t1=4&ivy.steps=64");
}

#if GTEST_HAS_DEATH_TEST
TEST(SecondTableDeathTest, RowsOutOfOrderOrWithoutTheirGroupAbort) {
  EXPECT_DEATH(
      ParamTable("bad", {{1, "a", "", "", 0, 0, 1, false, "g", Stage::kGrow, "h"}}, {{"g", "G"}}),
      "out of id order");
  EXPECT_DEATH(
      ParamTable("bad", {{0, "a", "", "", 0, 0, 1, false, "x", Stage::kGrow, "h"}}, {{"g", "G"}}),
      "group");
  EXPECT_DEATH(
      ParamTable("bad", {{0, "a", "", "", 2, 0, 1, false, "g", Stage::kGrow, "h"}}, {{"g", "G"}}),
      "default");
}
#endif

}  // namespace
}  // namespace niwa
