// The moss run's size limit (issue 29 items 6-7): a land of more than 200,000 triangles is grown
// with one soil cell a triangle when the run's estimate fits the budget and refused, naming the
// budget's limit, when it does not; the rocks scene's rock_triangles is refused up front, before
// its scene is built, by the same estimate; rock_triangles as a state field (hash, state file,
// range).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "moss/scenes.h"

namespace niwa::moss {
namespace {

// A 1 m humus square of n x n squares (2 n² triangles, edges far under soil_edge).
MossScene FineSquare(int n) {
  MossScene scene;
  scene.name = "fine";
  scene.region_names = {"all"};
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      scene.mesh.positions.emplace_back(static_cast<float>(i) / static_cast<float>(n), 0.0f,
                                        static_cast<float>(j) / static_cast<float>(n));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const uint32_t a = static_cast<uint32_t>(i * (n + 1) + j), b = a + 1,
                     c = a + static_cast<uint32_t>(n + 1), d = c + 1;
      scene.mesh.indices.insert(scene.mesh.indices.end(), {a, b, c, c, b, d});  // up-facing
      for (int k = 0; k < 2; ++k) {
        scene.geology.push_back(Geology::kHumus);
        scene.region.push_back(0);
      }
    }
  }
  return scene;
}

TEST(MossSizeLimit, OverTwoHundredThousandTrianglesFollowsTheEstimate) {
  const MossScene scene = FineSquare(320);  // 204,800 triangles
  ASSERT_EQ(scene.mesh.triangle_count(), 204800u);
  MossState state;
  state.days = 2;
  ASSERT_TRUE(state.params.Set(MossParam::kPhotons, 256).ok());
  const Estimate e = MossRun::RunEstimate(state, 204800);
  // Just enough: grown, one cell a triangle (no soil_edge doubling).
  Budget fits;
  fits.memory_bytes = static_cast<uint64_t>(e.memory_bytes * 1.01);
  fits.seconds = e.seconds * 1.01;
  Result<MossRun> run = MossRun::StartOnScene(state, scene, fits, "fine.glb");
  ASSERT_TRUE(run.ok()) << run.status().Line();
  EXPECT_EQ(run->cells().size(), 204800u);
  EXPECT_DOUBLE_EQ(run->cells().soil_edge, state.params.Get(MossParam::kSoilEdge));
  ASSERT_TRUE(run->Advance(nullptr).ok());
  EXPECT_EQ(run->world().day, 2);
  // A little less memory, or a little less time: refused, one line naming the limit.
  Budget short_memory = fits;
  short_memory.memory_bytes = static_cast<uint64_t>(e.memory_bytes * 0.99);
  const Status memory = MossRun::StartOnScene(state, scene, short_memory, "fine.glb").status();
  EXPECT_EQ(memory.field(), "max_memory");
  EXPECT_NE(memory.message().find("204,800 soil cells"), std::string::npos) << memory.message();
  Budget short_time = fits;
  short_time.seconds = e.seconds * 0.99;
  EXPECT_EQ(MossRun::StartOnScene(state, scene, short_time, "fine.glb").status().field(),
            "max_seconds");
}

TEST(MossSizeLimit, RocksAreRefusedBeforeTheirSceneIsBuilt) {
  EXPECT_EQ(RockTrianglesBuilt(kRockTrianglesDefault), 1600u);
  EXPECT_EQ(RockTrianglesBuilt(1000), 1600u);
  EXPECT_EQ(RockTrianglesBuilt(1000000), 1638400u);
  EXPECT_EQ(RockTrianglesBuilt(kRockTrianglesMax), static_cast<std::size_t>(kRockTrianglesMax));
  MossState state;
  state.scene = "rocks";
  ASSERT_TRUE(SetMossRockTriangles(kRockTrianglesMax, &state).ok());
  // 6.5 M cells need about 10 GB (and 300 days of them hours): refused by the default budget
  // without building 6.5 M triangles, the line naming the limit and the cells.
  const Status s = MossRun::Start(state, Budget{}).status();
  EXPECT_EQ(s.field(), "max_memory");
  EXPECT_NE(s.message().find("6,553,600 soil cells"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("rock_triangles"), std::string::npos) << s.message();
  // 1 M (1,638,400 built, ~2.3 GB at its peak) is over the default 2 GB; within 3 GB, 300 days of
  // it do not fit the 60 s.
  ASSERT_TRUE(SetMossRockTriangles(1000000, &state).ok());
  EXPECT_EQ(MossRun::Start(state, Budget{}).status().field(), "max_memory");
  Budget more;
  more.memory_bytes = uint64_t{3} << 30;
  const Status t = MossRun::Start(state, more).status();
  EXPECT_EQ(t.field(), "max_seconds");
  EXPECT_NE(t.message().find("1,638,400 soil cells"), std::string::npos) << t.message();
  // The same budget grows the scene of the knob's smallest level (the estimate fits).
  ASSERT_TRUE(SetMossRockTriangles(kRockTrianglesMin, &state).ok());
  state.days = 1;
  Result<MossRun> small = MossRun::Start(state, Budget{});
  ASSERT_TRUE(small.ok()) << small.status().Line();
  EXPECT_GT(small->cells().size(), RockTrianglesBuilt(kRockTrianglesMin));
}

TEST(MossSizeLimit, RockTrianglesIsAStateField) {
  MossState state;
  ASSERT_TRUE(SetMossScene("rocks", &state).ok());
  EXPECT_EQ(EncodeMossHash(state), "preset=nomura2010&scene=rocks");  // the default: no key
  ASSERT_TRUE(SetMossRockTriangles(102400, &state).ok());
  EXPECT_EQ(EncodeMossHash(state), "preset=nomura2010&scene=rocks&rock_triangles=102400");
  MossState back;
  std::vector<std::string> notices;
  ApplyMossHash(EncodeMossHash(state), "", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.rock_triangles, 102400);
  MossState from_json;
  ASSERT_TRUE(ApplyMossStateJson(MossStateJson(back), &from_json).ok());
  EXPECT_EQ(from_json.rock_triangles, 102400);
  // Another scene does not carry it.
  ASSERT_TRUE(SetMossScene("thesis", &state).ok());
  EXPECT_EQ(EncodeMossHash(state), "preset=nomura2010");
  EXPECT_EQ(MossStateJson(state).find("rock_triangles"), std::string::npos);
  // Out of range, not whole, not a number: refused naming the field, or dropped with a notice.
  EXPECT_EQ(SetMossRockTriangles(99, &state).field(), "rock_triangles");
  EXPECT_EQ(SetMossRockTriangles(kRockTrianglesMax + 1.0, &state).field(), "rock_triangles");
  EXPECT_EQ(SetMossRockTriangles(1600.5, &state).field(), "rock_triangles");
  EXPECT_EQ(ApplyMossStateJson(R"({"rock_triangles": "many"})", &state).field(), "rock_triangles");
  ApplyMossHash("scene=rocks&rock_triangles=50", "", &state, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(state.rock_triangles, 102400);
}

}  // namespace
}  // namespace niwa::moss
