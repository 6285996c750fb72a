// The ivy state's tree scene (the page's "tree" choice): scene=tree with tree= and tree_years= in
// the hash and the state JSON, checked spelling and range, and `niwa ivy grow --url` on it growing
// exactly what --tree-preset grows. In-process, natively and under node on WASM.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "ivy/ivy_state.h"
#include "support/cli_runner.h"

namespace niwa::ivy {
namespace {

nlohmann::json WithoutMs(nlohmann::json j) {
  for (const char* key : {"ms", "ms_bvh", "ms_rules", "ms_search", "ms_mesh"}) j.erase(key);
  return j;
}

TEST(IvyTreeScene, HashCarriesTreeAndYearsOnlyOnTheTreeScene) {
  IvyState state;
  std::vector<std::string> notices;
  ApplyIvyHash("preset=metric&scene=tree&tree=maple&tree_years=7", "", &state, &notices);
  EXPECT_TRUE(notices.empty()) << notices[0];
  EXPECT_EQ(state.scene, "tree");
  EXPECT_EQ(state.tree, "maple");
  EXPECT_EQ(state.tree_years, 7);
  const std::string hash = EncodeIvyHash(state);
  EXPECT_NE(hash.find("&scene=tree&tree=maple&tree_years=7"), std::string::npos) << hash;
  IvyState again;
  ApplyIvyHash(hash, "", &again, &notices);
  EXPECT_EQ(EncodeIvyHash(again), hash);
  // Prefixed on a composed page.
  IvyState prefixed;
  ApplyIvyHash(EncodeIvyHash(state, "ivy."), "ivy.", &prefixed, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(prefixed.tree, "maple");
  EXPECT_EQ(prefixed.tree_years, 7);
  // A built-in scene's hash names no tree.
  IvyState wall;
  ASSERT_TRUE(SetIvyScene("wall", &wall).ok());
  EXPECT_EQ(EncodeIvyHash(wall).find("tree"), std::string::npos) << EncodeIvyHash(wall);
}

TEST(IvyTreeScene, JsonReadsTreeFieldsStrictly) {
  IvyState state;
  ASSERT_TRUE(ApplyIvyStateJson(R"({"scene":"tree","tree":"pine","tree_years":12})", &state).ok());
  EXPECT_EQ(state.tree, "pine");
  EXPECT_EQ(state.tree_years, 12);
  for (const char* bad : {R"({"tree_years":0})", R"({"tree_years":101})", R"({"tree_years":2.5})",
                          R"({"tree":""})", R"({"tree":"Oak<script>"})", R"({"tree":3})"}) {
    IvyState s;
    Status st = ApplyIvyStateJson(bad, &s);
    ASSERT_FALSE(st.ok()) << bad;
    EXPECT_EQ(st.field().rfind("tree", 0), 0u) << st.Line();
    EXPECT_EQ(st.Line().find('\n'), std::string::npos);
    EXPECT_EQ(s.tree, "sakura");  // unchanged
  }
}

TEST(IvyTreeScene, HostileHashValuesAreDroppedWithANotice) {
  IvyState state;
  std::vector<std::string> notices;
  ApplyIvyHash("scene=tree&tree=../x&tree_years=1000", "", &state, &notices);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_EQ(notices[0].rfind("tree: ", 0), 0u) << notices[0];
  EXPECT_NE(notices[1].find("[1, 100]"), std::string::npos) << notices[1];
  EXPECT_EQ(state.tree, "sakura");
  EXPECT_EQ(state.tree_years, 10);
}

TEST(IvyTreeScene, UrlGrowsWhatTreePresetGrows) {
  CliResult flags =
      RunNiwa({"ivy", "grow", "--tree-preset", "sakura", "--tree-years", "6", "--stats"});
  ASSERT_EQ(flags.code, 0) << flags.err;
  CliResult url =
      RunNiwa({"ivy", "grow", "--url",
               "preset=metric&seed=1&steps=50&scene=tree&tree=sakura&tree_years=6", "--stats"});
  ASSERT_EQ(url.code, 0) << url.err;
  const nlohmann::json a = WithoutMs(nlohmann::json::parse(flags.out));
  const nlohmann::json b = WithoutMs(nlohmann::json::parse(url.out));
  EXPECT_EQ(a, b);
  EXPECT_GT(a["tri_count"].get<int>(), 1000);
  EXPECT_GT(a["internodes"].get<int>(), 10);
}

TEST(IvyTreeScene, UnknownTreeInTheUrlIsOneLineNamingUrl) {
  CliResult r = RunNiwa({"ivy", "grow", "--url", "scene=tree&tree=oak", "--stats"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.find("niwa: error: --url:"), 0u) << r.err;
  EXPECT_NE(r.err.find("oak"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
}  // namespace niwa::ivy
