// Tests of the JSON input rules every reader shares (params/param_json): a key given twice, keys
// beside a "params" object and deep nesting are refused naming the key or the limit.
#include <gtest/gtest.h>

#include <string>

#include "params/param_json.h"
#include "tree/presets.h"
#include "tree/tree_params.h"
#include "tree/tree_state.h"

namespace niwa {
namespace {

TEST(StrictJson, DuplicateKeysAreRefusedNamingTheKey) {
  TreeParams params;
  EXPECT_EQ(ApplyParamsJson(R"({"gamma": 0.1, "gamma": 0.9})", &params).Line(),
            "gamma: given twice in one object");
  EXPECT_EQ(ApplyParamsJson(R"({"params": {"alpha_t": 0.1, "alpha_t": 0.2}})", &params).Line(),
            "alpha_t: given twice in one object");
  EXPECT_EQ(params.Get(TreeParam::kGamma), TreeParams().Get(TreeParam::kGamma));  // unchanged
  // The same key in two different objects is fine.
  EXPECT_TRUE(CheckJsonKeys(R"({"a": {"x": 1}, "b": {"x": 2}})", "f").ok());
}

TEST(StrictJson, KeysBesideAParamsObjectAreRefused) {
  TreeParams params;
  EXPECT_EQ(ApplyParamsJson(R"({"params": {"gamma": 0.5}, "alpha_t": 0.1})", &params).Line(),
            "alpha_t: beside a \"params\" object; put every parameter inside \"params\"");
  // A preset file's own fields may stand beside "params".
  EXPECT_TRUE(ApplyParamsJson(R"({"name": "x", "years": 3, "params": {"gamma": 0.5}})", &params,
                              PresetFileFields())
                  .ok());
  EXPECT_EQ(params.Get(TreeParam::kGamma), 0.5);
}

TEST(StrictJson, DeepNestingIsRefused) {
  std::string deep = std::string(1000, '[') + std::string(1000, ']');
  EXPECT_EQ(CheckJsonKeys(deep, "params").Line(), "params: nested deeper than 32 levels");
  TreeParams params;
  EXPECT_EQ(ApplyParamsJson("{\"a\": " + deep + "}", &params).Line(),
            "params: nested deeper than 32 levels");
  TreeState state;
  EXPECT_EQ(ApplyStateJson(R"({"seed": 1, "seed": 2})", &state).Line(),
            "seed: given twice in one object");
}

// Issue 34: a key repeated after a nested object was accepted (the old parse callback lost track of
// which object was open once a nested one closed).
TEST(StrictJson, KeyRepeatedAfterANestedObjectIsRefused) {
  TreeParams params;
  EXPECT_EQ(
      ApplyParamsJson(R"({"params": {"gamma": 0.1}, "params": {"gamma": 0.9}})", &params).Line(),
      "params: given twice in one object");
  EXPECT_EQ(CheckJsonKeys(R"({"a": {"x": 1}, "b": [1, {"y": 2}], "a": 2})", "f").Line(),
            "a: given twice in one object");
  EXPECT_EQ(CheckJsonKeys(R"({"a": {"b": {"c": 1}, "d": 2, "d": 3}})", "f").Line(),
            "d: given twice in one object");
  EXPECT_EQ(CheckJsonKeys(R"([{"k": 1}, {"k": 2}, {"k": 3, "k": 4}])", "f").Line(),
            "k: given twice in one object");
  TreeState state;
  EXPECT_EQ(ApplyStateJson(R"({"seed": 1, "params": {"gamma": 0.5}, "seed": 2})", &state).Line(),
            "seed: given twice in one object");
  EXPECT_EQ(params.Get(TreeParam::kGamma), TreeParams().Get(TreeParam::kGamma));  // unchanged
}

// The depth limit is a byte scan before any parser sees the text: brackets inside strings do not
// count, exactly kMaxJsonDepth levels pass, one more is refused, and 100 000 levels do not recurse.
TEST(StrictJson, DepthIsCountedOnTheBytesOutsideStrings) {
  const std::string at_limit = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  EXPECT_TRUE(CheckJsonKeys(at_limit, "f").ok());
  EXPECT_EQ(CheckJsonKeys("[" + at_limit + "]", "f").Line(), "f: nested deeper than 32 levels");
  EXPECT_TRUE(CheckJsonKeys(R"({"a": "[[[[{{{{\"[[[[", "b": "]]]"})", "f").ok());
  const std::string huge = "{\"x\": " + std::string(100000, '{') + "}";
  EXPECT_EQ(CheckJsonKeys(huge, "contour").Line(), "contour: nested deeper than 32 levels");
  EXPECT_TRUE(CheckJsonKeys("not json {", "f").ok());  // malformed: the caller's parse says so
}

}  // namespace
}  // namespace niwa
