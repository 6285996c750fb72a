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

}  // namespace
}  // namespace niwa
