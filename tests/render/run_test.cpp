// core/render/tree_run: the tree study's run once through its pipeline: grown year by year with
// progress, cancelled at a whole year, refused by field, its .glb/.json/.svg the CLI's bytes, its
// parts, hash, estimates, table 4.1, update by stage, and the CLI's mappings and render-stats as
// adapters over it (prunes checked by the run).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "render/tree_run.h"
#include "support/cli_runner.h"
#include "support/files.h"
#include "support/grow.h"
#include "tree/tree_gltf.h"
#include "tree/tree_json.h"
#include "tree/tree_report.h"

namespace niwa {
namespace {

constexpr int kYears = 5;

TreeRun StartSakura(int years = kYears) {
  Result<TreeRun> run = TreeRun::Start(testing::PresetState("sakura", years), Budget{});
  EXPECT_TRUE(run.ok()) << run.status().Line();
  return std::move(run).value();
}

using ::niwa::testing::Slurp;

TEST(TreeRun, GrowsYearByYearWithProgress) {
  TreeRun run = StartSakura();
  EXPECT_STREQ(run.study(), "tree");
  EXPECT_STREQ(run.unit(), "years");
  EXPECT_EQ(run.done(), 0);
  EXPECT_EQ(run.target(), kYears);
  std::vector<double> seen;
  const Status status = run.Advance([&](const run::Progress& p) {
    EXPECT_EQ(p.phase, "grow");
    EXPECT_EQ(p.total, kYears);
    EXPECT_EQ(p.done, run.done());  // reported between whole years
    seen.push_back(p.done);
    return true;
  });
  ASSERT_TRUE(status.ok()) << status.Line();
  EXPECT_EQ(seen, (std::vector<double>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(run.done(), kYears);
  EXPECT_TRUE(run.finished());
  EXPECT_EQ(run.tree().years, kYears);
  EXPECT_FALSE(run.GrowYear());  // nothing left
}

TEST(TreeRun, CancelLeavesTheLastWholeYearAndResumes) {
  TreeRun run = StartSakura();
  const Status cancelled =
      run.Advance([](const run::Progress& p) { return p.done < 3; });  // cancel before year 4
  EXPECT_TRUE(run::IsCancelled(cancelled)) << cancelled.Line();
  EXPECT_EQ(run.done(), 3);
  EXPECT_EQ(run.tree().years, 3);
  EXPECT_FALSE(run.finished());
  // The tree at its last whole year is the 3-year tree; going on gives the 5-year tree.
  EXPECT_EQ(TreeToJson(run.tree()), TreeToJson(testing::GrowPreset("sakura", 3)));
  ASSERT_TRUE(run.Advance(nullptr).ok());
  EXPECT_EQ(run.done(), kYears);
  EXPECT_EQ(TreeToJson(run.tree()), TreeToJson(testing::GrowPreset("sakura", kYears)));
}

TEST(TreeRun, RefusesByFieldBeforeWork) {
  TreeState state = testing::PresetState("sakura", kYears);
  state.years = kMaxYears + 1;
  Result<TreeRun> years = TreeRun::Start(state, Budget{});
  ASSERT_FALSE(years.ok());
  EXPECT_EQ(years.status().field(), "years");
  state = testing::PresetState("sakura", kYears);
  ASSERT_TRUE(state.params.Set(ParamId::kGustOn, 9).ok());
  ASSERT_TRUE(state.params.Set(ParamId::kGustOff, 8).ok());
  Result<TreeRun> gust = TreeRun::Start(state, Budget{});
  ASSERT_FALSE(gust.ok());
  EXPECT_EQ(gust.status().field(), "gust_off");

  // An export the budget cannot hold is refused before it is made, naming the budget's limit.
  Budget small;
  small.memory_bytes = 1 << 20;
  small.memory_limit = "max_memory";
  Result<TreeRun> started = TreeRun::Start(testing::PresetState("sakura", kYears), small);
  ASSERT_TRUE(started.ok());
  ASSERT_TRUE(started->Advance(nullptr).ok());
  TreeExportRequest glb;
  const Status refused = started->CheckExport(glb);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.field(), "max_memory");
  EXPECT_NE(refused.message().find("writing the .glb"), std::string::npos) << refused.Line();
  EXPECT_FALSE(started->has_mesh());  // nothing was built for it
  // The mesh stage is refused the same way, leaving an empty mesh.
  const Status mesh = started->BuildMesh();
  EXPECT_EQ(mesh.field(), "max_memory");
  EXPECT_TRUE(started->mesh().bark.indices.empty());
}

TEST(TreeRun, ExportsAreTheCliBytes) {
  TreeRun run = StartSakura(4);
  ASSERT_TRUE(run.Advance(nullptr).ok());
  for (const char* ext : {"glb", "json", "svg"}) {
    const std::string path = ::testing::TempDir() + "tree_run_test." + ext;
    std::remove(path.c_str());
    CliResult cli = RunNiwa({"tree", "grow", "--preset", "sakura", "--years", "4", "--out", path});
    ASSERT_EQ(cli.code, 0) << cli.err;
    TreeExportRequest request;
    request.kind = TreeExportKind(ext).value();
    ASSERT_TRUE(run.CheckExport(request).ok());
    Result<std::string> bytes = run.Export(request);
    ASSERT_TRUE(bytes.ok()) << bytes.status().Line();
    EXPECT_EQ(*bytes, Slurp(path)) << ext;
    std::remove(path.c_str());
  }
  // And the tree study's own pipeline without the run (grow, mesh, .glb).
  std::vector<unsigned char> direct;
  ASSERT_TRUE(WriteTreeGlb(BuildTreeMesh(testing::GrowPreset("sakura", 4)), &direct).ok());
  TreeExportRequest glb;
  EXPECT_EQ(run.Export(glb).value(), std::string(direct.begin(), direct.end()));
  // The page's path (the mesh stage built first) writes the same bytes.
  ASSERT_TRUE(run.BuildMesh().ok());
  EXPECT_EQ(run.Export(glb).value(), std::string(direct.begin(), direct.end()));
}

TEST(TreeRun, PartsDocumentStatsHashAndEstimates) {
  TreeRun run = StartSakura();
  ASSERT_TRUE(run.Advance(nullptr).ok());
  const std::vector<run::Part> parts = run.Parts();
  ASSERT_GE(parts.size(), 2u);
  EXPECT_EQ(parts[0].name, "bark");
  EXPECT_EQ(parts[1].name, "leaves");
  for (const run::Part& part : parts) {
    EXPECT_EQ(part.material.name, part.name);
    EXPECT_GT(part.mesh.triangle_count(), 0u) << part.name;
    ASSERT_GE(part.material.base_color_texture, 0) << part.name;
    EXPECT_LT(part.material.base_color_texture, static_cast<int>(part.textures.size()));
    for (const glm::vec3& p : part.mesh.positions) {  // metres, y up, a young cherry
      ASSERT_GT(p.y, -0.5f) << part.name;
      ASSERT_LT(p.y, 20.0f) << part.name;
    }
  }
  EXPECT_EQ(parts[0].textures.size(), 2u);  // bark colour and normal map
  Result<gltf::Document> doc = run.Document();
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(doc->meshes.at(0).primitives.size(), parts.size());

  const nlohmann::json stats = nlohmann::json::parse(run.StatsJson());
  EXPECT_EQ(stats["preset"], "sakura");
  EXPECT_EQ(stats["years"], kYears);

  const std::string hash = run.Hash("tree.");
  EXPECT_EQ(hash.rfind("tree.preset=sakura&tree.seed=", 0), 0u) << hash;
  std::vector<std::string> notices;
  const TreeState back = DecodeTreeHash(hash, &notices, "tree.");
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.preset, "sakura");
  EXPECT_EQ(back.years, kYears);
  EXPECT_EQ(back.seed, run.state().seed);

  for (const char* format : {"glb", "json", "svg", "lod.glb", "sway.glb"}) {
    Result<Estimate> estimate = run.ExportEstimate(format);
    ASSERT_TRUE(estimate.ok()) << format;
    EXPECT_GT(estimate->memory_bytes, run.grown().memory_bytes) << format;
  }
  Result<Estimate> obj = run.ExportEstimate("obj");
  ASSERT_FALSE(obj.ok());
  EXPECT_EQ(obj.status().field(), "format");
}

TEST(TreeRun, Table41IsRenderStatsCounts) {
  TreeRun run = StartSakura(4);
  ASSERT_TRUE(run.Advance(nullptr).ok());
  run.BuildBareMesh();
  const RenderCamera camera = CameraFromOrbit(run.FrameView(kDefaultFovY), 512, 512);
  const HybridScene scene =
      BuildHybridScene(run.tree(), RenderOptionsFromParams(run.state().params));
  const HybridSelection selection = SelectHybrid(run.tree(), scene, camera, nullptr);
  const nlohmann::json view =
      nlohmann::json::parse(ViewCountsJson(run.CountView(scene, selection)));
  CliResult cli = RunNiwa({"tree", "render-stats", "--preset", "sakura", "--years", "4"});
  ASSERT_EQ(cli.code, 0) << cli.err;
  const nlohmann::json stats = nlohmann::json::parse(cli.out);
  for (const char* key :
       {"lines", "line_branches", "card_branches", "branch_polygons", "leaf_polygons",
        "total_polygons", "primitives", "textures", "leaf_clusters", "full_polygons"}) {
    EXPECT_EQ(view[key], stats[key]) << key;
  }
  EXPECT_GT(view["full_polygons"].get<int>(), 0);
  // Every alive branch is a line or a card (the page's renderUnassigned hook is 0).
  EXPECT_EQ(view["alive_branches"].get<int>(),
            view["line_branches"].get<int>() + view["card_branches"].get<int>());
}

run::StageMask From(Stage stage) {  // that stage and the ones after it
  run::StageMask mask = 0;
  for (int s = static_cast<int>(stage); s <= static_cast<int>(Stage::kView); ++s) mask |= 1u << s;
  return mask;
}

TEST(TreeRun, UpdateRedoesTheEarliestChangedStage) {
  TreeRun run = StartSakura();
  ASSERT_TRUE(run.Advance(nullptr).ok());
  ASSERT_TRUE(run.BuildMesh().ok());
  const std::string grown = TreeToJson(run.tree());
  const std::size_t leaves = run.mesh().leaves.indices.size();
  ASSERT_GT(leaves, 0u);

  EXPECT_EQ(run.Update(run.state()).value(), 0u);  // nothing changed, nothing re-done

  TreeState view = run.state();  // a view row (line_threshold): only the state
  ASSERT_EQ(TreeParamTable()[static_cast<std::size_t>(ParamId::kLineThreshold)].stage,
            Stage::kView);
  ASSERT_TRUE(view.params.Set(ParamId::kLineThreshold, 9).ok());
  EXPECT_EQ(run.Update(view).value(), From(Stage::kView));
  EXPECT_EQ(run.state().params.Get(ParamId::kLineThreshold), 9);
  EXPECT_EQ(run.mesh().leaves.indices.size(), leaves);

  TreeState sway = run.state();  // a sway row: the skin's weights follow sway_alpha
  const std::vector<float> weights = run.skin().bark.weight;
  ASSERT_TRUE(sway.params.Set(ParamId::kSwayAlpha, 3).ok());
  EXPECT_EQ(run.Update(sway).value(), From(Stage::kSway));
  EXPECT_NE(run.skin().bark.weight, weights);
  EXPECT_EQ(run.mesh().leaves.indices.size(), leaves);  // the mesh is kept

  TreeState mesh = run.state();  // a mesh row: winter drops the leaves, the tree is not regrown
  ASSERT_TRUE(mesh.params.Set(TreeParam::kSeason, 3).ok());
  EXPECT_EQ(run.Update(mesh).value(), From(Stage::kMesh));
  EXPECT_TRUE(run.mesh().leaves.indices.empty());
  EXPECT_EQ(run.skin().leaves.joint.size(), 0u);
  EXPECT_EQ(run.skin().bark.joint.size(), run.mesh().bark.vertex_count());
  EXPECT_EQ(TreeToJson(run.tree()), grown);
  EXPECT_EQ(run.done(), kYears);
  EXPECT_EQ(run.state().limits.years_name, "years");  // the growth's limits stay

  TreeState grow = run.state();  // another seed: regrown from year 0
  grow.seed += 1;
  EXPECT_EQ(run.Update(grow).value(), From(Stage::kGrow));
  EXPECT_EQ(run.done(), 0);
  EXPECT_FALSE(run.has_mesh());
  ASSERT_TRUE(run.Advance(nullptr).ok());
  EXPECT_NE(TreeToJson(run.tree()), grown);

  TreeState bad = run.state();  // refused as Start refuses; the run unchanged
  bad.years = kMaxYears + 1;
  Result<run::StageMask> refused = run.Update(bad);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().field(), "years");
  EXPECT_EQ(run.state().years, kYears);
}

// Issue 28 item 2: a prune that cuts nothing is the run's error ("prune"), named by the CLI's
// flag; `tree mappings` and `tree render-stats` print what the run gives.
TEST(TreeRun, CheckPrunesNamesTheIdlePrune) {
  TreeState state = testing::PresetState("sakura", kYears);
  ASSERT_TRUE(AddStatePrune("3:b99999", &state).ok());
  Result<TreeRun> run = TreeRun::Start(state, Budget{});
  ASSERT_TRUE(run.ok());
  ASSERT_TRUE(run->Advance(nullptr).ok());
  const Status idle = run->CheckPrunes();
  EXPECT_EQ(idle.field(), "prune");
  EXPECT_EQ(idle.message().rfind("3:b99999: ", 0), 0u) << idle.Line();
  Result<std::string> csv = TreeRun::MappingsCsv(state, Budget{});
  ASSERT_FALSE(csv.ok());
  EXPECT_EQ(csv.status().Line(), idle.Line());
  CliResult cli =
      RunNiwa({"tree", "mappings", "--preset", "sakura", "--years", "5", "--prune", "3:b99999"});
  EXPECT_EQ(cli.code, 2);
  EXPECT_EQ(cli.err, "niwa: error: --" + idle.Line() + "\n");
}

TEST(TreeRun, MappingsAndRenderStatsAreTheCliOutputs) {
  const TreeState state = testing::PresetState("sakura", kYears);
  Result<std::string> csv = TreeRun::MappingsCsv(state, Budget{});
  ASSERT_TRUE(csv.ok());
  EXPECT_EQ(*csv, TreeMappingsCsv(state.params));
  CliResult mappings = RunNiwa({"tree", "mappings", "--preset", "sakura", "--years", "5"});
  ASSERT_EQ(mappings.code, 0) << mappings.err;
  EXPECT_EQ(mappings.out, *csv);

  const auto without_ms = [](const std::string& text) {
    nlohmann::json j = nlohmann::json::parse(text);
    for (const char* key : {"ms_grow_mesh", "ms_scene", "ms_select"}) j.erase(key);
    return j;
  };
  RenderStatsRequest request;
  request.width = 640;
  request.height = 480;
  TreeState edited = state;  // the flags --threshold 6 --leaf-mode branch, as rows
  ASSERT_TRUE(edited.params.Set(ParamId::kLineThreshold, 6).ok());
  ASSERT_TRUE(edited.params.Set(ParamId::kLeafClusterCards, 0).ok());
  Result<std::string> stats = TreeRun::RenderStats(edited, Budget{}, request);
  ASSERT_TRUE(stats.ok()) << stats.status().Line();
  const nlohmann::json core = without_ms(*stats);
  EXPECT_EQ(core["threshold"], 6);
  EXPECT_EQ(core["leaf_mode"], "branch");
  CliResult cli = RunNiwa({"tree", "render-stats", "--preset", "sakura", "--years", "5", "--width",
                           "640", "--height", "480", "--threshold", "6", "--leaf-mode", "branch"});
  ASSERT_EQ(cli.code, 0) << cli.err;
  EXPECT_EQ(without_ms(cli.out), core);
  // An explicit view is used as given.
  request.view = OrbitView{};
  request.view->distance = 20;
  Result<std::string> near = TreeRun::RenderStats(state, Budget{}, request);
  ASSERT_TRUE(near.ok());
  EXPECT_EQ(nlohmann::json::parse(*near)["cam"], FormatOrbitView(*request.view));
}

}  // namespace
}  // namespace niwa
