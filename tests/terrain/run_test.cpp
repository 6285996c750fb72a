// TerrainRun (core/terrain/terrain_run.h), the terrain pipeline once: a built-in seed grown level
// by level with progress; refusals before work naming the state field or the budget; cancel
// leaving the results as they were; every output's bytes equal to what `niwa terrain grow` writes;
// the share hash under the "terrain." prefix; Update re-doing only the changed rows' stage.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/files.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_run.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {
namespace {

using ::niwa::testing::Slurp;

TerrainState State(const char* builtin, const char* preset, int seed, int res) {
  TerrainState s;
  EXPECT_TRUE(SetTerrainBuiltin(builtin, &s).ok());
  EXPECT_TRUE(SetTerrainPreset(preset, &s).ok());
  EXPECT_TRUE(SetTerrainSeed(seed, &s).ok());
  EXPECT_TRUE(s.params.Set(TerrainParam::kRes, res).ok());
  return s;
}

TerrainRun Grown(const TerrainState& state, const Budget& budget = {}) {
  Result<TerrainRun> run = TerrainRun::Start(state, budget);
  EXPECT_TRUE(run.ok()) << run.status().Line();
  EXPECT_TRUE(run->Advance({}).ok());
  return std::move(run).value();
}

nlohmann::json WithoutMs(nlohmann::json j) {
  for (auto it = j.begin(); it != j.end();) it = it.key().rfind("ms", 0) == 0 ? j.erase(it) : ++it;
  return j;
}

TEST(TerrainRun, GrowsABuiltinSeedLevelByLevel) {
  Result<TerrainRun> run = TerrainRun::Start(State("lobes7", "improved", 3, 48), Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  EXPECT_STREQ(run->study(), "terrain");
  EXPECT_STREQ(run->unit(), "levels");
  EXPECT_EQ(run->done(), 0);
  EXPECT_EQ(run->target(), 1000);  // the cap (max_levels) until grown
  std::vector<run::Progress> seen;
  ASSERT_TRUE(run->Advance([&](const run::Progress& p) {
                   seen.push_back(p);
                   return true;
                 })
                  .ok());
  const nlohmann::json stats = nlohmann::json::parse(run->StatsJson());
  EXPECT_GE(stats["levels"].get<int>(), 8);
  EXPECT_EQ(run->done(), stats["levels"].get<int>());
  EXPECT_EQ(run->target(), run->done());
  EXPECT_EQ(stats["self_intersections"], 0);
  EXPECT_EQ(stats["pits"], 0);
  // A progress call before every contour: "levels" counts up to one per level grown above the
  // seed (the top level's contours vanish), then the surface.
  ASSERT_GE(seen.size(), 3u);
  double last = 0;
  for (std::size_t k = 0; k + 2 < seen.size(); ++k) {
    EXPECT_EQ(seen[k].phase, "levels");
    EXPECT_GE(seen[k].done, last);
    EXPECT_LE(seen[k].done, seen[k].total);
    last = seen[k].done;
  }
  EXPECT_EQ(last, stats["levels"].get<int>());
  EXPECT_EQ(seen[seen.size() - 2].phase, "surface");
  EXPECT_EQ(seen.back().done, 1);
  EXPECT_EQ(run->counts().grows, 1);
  EXPECT_EQ(run->counts().heightfields, 1);
  // The parts are the .glb's nodes, in metres and y up.
  std::vector<run::Part> parts = run->Parts();
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].name, "terrain");
  EXPECT_EQ(parts[0].mesh.vertex_count(), run->heightfield().h.size());
  EXPECT_NE(parts[0].mesh.FindAttribute("COLOR_0"), nullptr);
  EXPECT_EQ(parts[1].name, "contours");
  EXPECT_EQ(parts[1].mode, gltf::Mode::kLines);
}

TEST(TerrainRun, RefusesBeforeWorkNamingTheFieldOrTheLimit) {
  Budget small;
  small.memory_bytes = uint64_t{128} << 20;
  small.memory_limit = "max_memory";  // the front end's word for its limit
  Result<TerrainRun> big = TerrainRun::Start(State("disk", "improved", 1, 4096), small);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.status().field(), "max_memory");
  EXPECT_EQ(big.status().message(),
            "the heightfield (4,098 × 4,098 cells) needs about 577 MB, more than the 128 MB "
            "allowed; lower res");
  TerrainRunPlan cli;
  cli.words = {{"res", "--res"}};
  EXPECT_EQ(TerrainRun::Start(State("disk", "improved", 1, 4096), small, cli).status().message(),
            "the heightfield (4,098 × 4,098 cells) needs about 577 MB, more than the 128 MB "
            "allowed; lower --res");
  TerrainState bad = State("disk", "improved", 1, 32);
  ASSERT_TRUE(bad.params.Set(TerrainParam::kF0, 900).ok());
  EXPECT_EQ(TerrainRun::Start(bad, Budget{}).status().field(), "f0");
  TerrainState none;
  none.builtin.clear();
  EXPECT_EQ(TerrainRun::Start(none, Budget{}).status().field(), "contour");
  // A drawn seed that crosses itself: refused by the grow, naming the contour.
  TerrainState crossing;
  ASSERT_TRUE(SetTerrainPoints({{0, 0}, {100, 100}, {100, 0}, {0, 100}}, &crossing).ok());
  Result<TerrainRun> run = TerrainRun::Start(crossing, Budget{});
  ASSERT_TRUE(run.ok());
  const Status s = run->Advance({});
  EXPECT_EQ(s.field(), "contour");
  EXPECT_FALSE(run->grown());
}

TEST(TerrainRun, CancelLeavesTheResultsAsTheyWere) {
  Result<TerrainRun> run = TerrainRun::Start(State("lobes7", "improved", 3, 32), Budget{});
  ASSERT_TRUE(run.ok());
  int calls = 0;
  const run::Observer stop_at_third = [&](const run::Progress&) { return ++calls < 3; };
  EXPECT_TRUE(run::IsCancelled(run->Advance(stop_at_third)));
  EXPECT_EQ(calls, 3);
  EXPECT_FALSE(run->grown());
  EXPECT_EQ(run->done(), 0);
  EXPECT_EQ(run->counts().grows, 0);
  EXPECT_EQ(run->StatsJson(), "{}");
  ASSERT_TRUE(run->Advance({}).ok());
  const std::string stats = run->StatsJson();
  // A new seed cancelled on the surface: the last mountain is kept, whole.
  ASSERT_TRUE(run->Update(State("dumbbell", "improved", 3, 32)).ok());
  const run::Observer stop_on_surface = [](const run::Progress& p) { return p.phase != "surface"; };
  EXPECT_TRUE(run::IsCancelled(run->Advance(stop_on_surface)));
  EXPECT_EQ(run->StatsJson(), stats);
  EXPECT_EQ(run->state().builtin, "lobes7");
  EXPECT_EQ(run->counts().heightfields, 1);
}

TEST(TerrainRun, EveryOutputIsTheBytesTheCliWrites) {
  const std::string dir = ::testing::TempDir() + "terrain_run_";
  const std::string glb = dir + "t.glb", png = dir + "t.png", side = dir + "t.json";
  const std::string geo = dir + "t.geojson", json = dir + "c.json", svg = dir + "c.svg";
  for (const std::string& p : {glb, png, side, geo, json, svg}) std::remove(p.c_str());
  const std::vector<std::string> grow = {"terrain",  "grow",   "--builtin", "dumbbell", "--method",
                                         "improved", "--seed", "2",         "--res",    "40"};
  std::vector<std::string> a = grow, b = grow, c = grow;
  a.insert(a.end(), {"--stats", "--out", glb, "--heightmap", png, "--contours", geo});
  b.insert(b.end(), {"--contours", json});
  c.insert(c.end(), {"--contours", svg});
  CliResult r = RunNiwa(a);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(RunNiwa(b).code, 0);
  ASSERT_EQ(RunNiwa(c).code, 0);

  const TerrainRun run = Grown(State("dumbbell", "improved", 2, 40));
  const nlohmann::json cli_stats = nlohmann::json::parse(r.out);
  EXPECT_EQ(WithoutMs(cli_stats).dump(), run.StatsJson());
  EXPECT_EQ(cli_stats["url"], run.Hash(""));
  for (const auto& [format, path] :
       std::vector<std::pair<std::string, std::string>>{{"glb", glb},
                                                        {"heightmap", png},
                                                        {"sidecar", side},
                                                        {"geojson", geo},
                                                        {"json", json},
                                                        {"svg", svg}}) {
    Result<std::string> bytes = run.Export(format);
    ASSERT_TRUE(bytes.ok()) << format << ": " << bytes.status().Line();
    EXPECT_GT(bytes->size(), 100u) << format;
    EXPECT_TRUE(*bytes == Slurp(path)) << format << " differs from " << path;
  }
  EXPECT_EQ(run.Export("tif").status().Line(),
            "format: unknown format; must be glb, heightmap, sidecar, json, geojson or svg");
  for (const std::string& p : {glb, png, side, geo, json, svg}) std::remove(p.c_str());
}

TEST(TerrainRun, HashUnderThePrefixReadsBackTheState) {
  TerrainState drawn;
  ASSERT_TRUE(SetTerrainPoints({{0, 0}, {210.5, 0}, {190, 160.25}, {-20, 140}}, &drawn).ok());
  ASSERT_TRUE(drawn.params.Set(TerrainParam::kRes, 24).ok());
  const TerrainRun run = Grown(drawn);
  const std::string hash = run.Hash("terrain.");
  EXPECT_EQ(hash.rfind("terrain.", 0), 0u) << hash;
  TerrainState back;
  std::vector<std::string> notices;
  ApplyTerrainHash("ivy.steps=3&" + hash, "terrain.", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.points, drawn.points);
  EXPECT_EQ(back.params, drawn.params);
  EXPECT_EQ(EncodeTerrainHash(back), run.Hash(""));
}

// Erosion rows (stage mesh, erosion.h): an edit re-erodes the kept uneroded heightfield, neither
// regrowing nor rebuilding it; the result is a fresh run's; a view row does not re-erode; erosion
// back to 0 gives the uneroded bytes; res rebuilds and re-erodes.
TEST(TerrainRun, AnErosionThatCannotFitIsRefusedBeforeItStarts) {
  // The erosion's passes are in the estimate (EstimateErosion): 1000 passes over a 512² grid are
  // about 130 s, refused within 60 s, naming the limit and the erosion; without them it grows.
  TerrainState state = State("lobes7", "improved", 2, 512);
  ASSERT_TRUE(state.params.Set(TerrainParam::kErosion, 3).ok());
  ASSERT_TRUE(state.params.Set(TerrainParam::kErosionIterations, 1000).ok());
  Result<TerrainRun> run = TerrainRun::Start(state, Budget{});
  Status status = run.ok() ? run->Advance({}) : run.status();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.field(), "max_seconds");
  EXPECT_NE(status.message().find("the erosion (1,000 passes"), std::string::npos) << status.Line();
  // A grown run asked to re-erode with them keeps its surface and refuses the same way.
  TerrainState plain = state;
  ASSERT_TRUE(plain.params.Set(TerrainParam::kErosion, 0).ok());
  TerrainRun grown = Grown(plain);
  const std::string glb = *grown.Export("glb");
  ASSERT_TRUE(grown.Update(state).ok());
  const Status again = grown.Advance({});
  EXPECT_EQ(again.field(), "max_seconds") << again.Line();
  EXPECT_EQ(grown.counts().erosions, 0);
  EXPECT_EQ(*grown.Export("glb"), glb);
}

TEST(TerrainRun, ErosionRowsReErodeTheKeptSurface) {
  TerrainState state = State("lobes7", "improved", 2, 64);
  TerrainRun run = Grown(state);
  const std::string plain_glb = *run.Export("glb");
  const std::string plain_map = *run.Export("heightmap");
  EXPECT_EQ(run.counts().erosions, 0);
  EXPECT_EQ(nlohmann::json::parse(run.StatsJson()).count("erosion"), 0u);

  TerrainState eroded = state;
  ASSERT_TRUE(eroded.params.Set(TerrainParam::kErosion, 3).ok());
  ASSERT_TRUE(run.Update(eroded).ok());
  EXPECT_EQ(run.done(), 0);  // pending
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().grows, 1);
  EXPECT_EQ(run.counts().heightfields, 1);
  EXPECT_EQ(run.counts().erosions, 1);
  EXPECT_NE(*run.Export("glb"), plain_glb);
  EXPECT_NE(*run.Export("heightmap"), plain_map);
  EXPECT_EQ(*run.Export("glb"), *Grown(eroded).Export("glb"));
  EXPECT_EQ(*run.Export("heightmap"), *Grown(eroded).Export("heightmap"));
  EXPECT_EQ(run.StatsJson(), Grown(eroded).StatsJson());
  const nlohmann::json stats = nlohmann::json::parse(run.StatsJson());
  ASSERT_EQ(stats.count("erosion"), 1u);
  EXPECT_GT(stats["erosion"]["volume_moved"].get<double>(), 0);
  EXPECT_EQ(stats["erosion"]["pits_after"].get<int>(), 0);
  EXPECT_NE(stats["url"].get<std::string>().find("erosion=3"), std::string::npos);

  TerrainState talus = eroded;  // another erosion row: re-eroded from the kept surface
  ASSERT_TRUE(talus.params.Set(TerrainParam::kErosionTalus, 25).ok());
  ASSERT_TRUE(run.Update(talus).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().heightfields, 1);
  EXPECT_EQ(run.counts().erosions, 2);
  EXPECT_EQ(*run.Export("glb"), *Grown(talus).Export("glb"));

  TerrainState grey = talus;  // a view row: nothing re-eroded
  ASSERT_TRUE(grey.params.Set(TerrainParam::kTint, 0).ok());
  ASSERT_TRUE(run.Update(grey).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().erosions, 2);
  EXPECT_EQ(*run.Export("glb"), *Grown(grey).Export("glb"));

  TerrainState finer = grey;  // res: rebuilt, then eroded again
  ASSERT_TRUE(finer.params.Set(TerrainParam::kRes, 80).ok());
  ASSERT_TRUE(run.Update(finer).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().grows, 1);
  EXPECT_EQ(run.counts().heightfields, 2);
  EXPECT_EQ(run.counts().erosions, 3);
  EXPECT_EQ(*run.Export("glb"), *Grown(finer).Export("glb"));

  TerrainState off = finer;  // erosion off: the uneroded surface, bit for bit
  ASSERT_TRUE(off.params.Set(TerrainParam::kErosion, 0).ok());
  ASSERT_TRUE(run.Update(off).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().heightfields, 2);
  EXPECT_EQ(run.counts().erosions, 3);
  EXPECT_EQ(*run.Export("glb"), *Grown(off).Export("glb"));
  EXPECT_EQ(run.StatsJson(), Grown(off).StatsJson());
}

TEST(TerrainRun, UpdateRedoesOnlyTheChangedRowsStage) {
  TerrainState state = State("lobes7", "improved", 3, 48);
  TerrainRun run = Grown(state);
  ASSERT_EQ(run.counts().grows, 1);
  ASSERT_EQ(run.counts().heightfields, 1);

  // tint (view): nothing re-done; the .glb is a fresh run's with the new tint.
  TerrainState grey = state;
  ASSERT_TRUE(grey.params.Set(TerrainParam::kTint, 0).ok());
  ASSERT_TRUE(run.Update(grey).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().grows, 1);
  EXPECT_EQ(run.counts().heightfields, 1);
  EXPECT_EQ(*run.Export("glb"), *Grown(grey).Export("glb"));
  EXPECT_EQ(run.StatsJson(), Grown(grey).StatsJson());

  // res (mesh): the heightfield re-sampled from the kept contours, as a fresh run's.
  TerrainState finer = grey;
  ASSERT_TRUE(finer.params.Set(TerrainParam::kRes, 80).ok());
  ASSERT_TRUE(run.Update(finer).ok());
  EXPECT_EQ(run.done(), 0);  // pending
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().grows, 1);
  EXPECT_EQ(run.counts().heightfields, 2);
  EXPECT_EQ(*run.Export("glb"), *Grown(finer).Export("glb"));
  EXPECT_EQ(run.StatsJson(), Grown(finer).StatsJson());

  // The preset's name alone: the link changes, nothing is re-done.
  TerrainState named = finer;
  named.preset = "fig16";
  ASSERT_TRUE(run.Update(named).ok());
  EXPECT_EQ(run.Hash(""), EncodeTerrainHash(named));
  EXPECT_EQ(run.counts().heightfields, 2);

  // A grow row (seed): everything.
  TerrainState other = named;
  ASSERT_TRUE(SetTerrainSeed(4, &other).ok());
  ASSERT_TRUE(run.Update(other).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().grows, 2);
  EXPECT_EQ(run.counts().heightfields, 3);
  EXPECT_EQ(*run.Export("glb"), *Grown(other).Export("glb"));

  // A bad state leaves the run as it was.
  TerrainState bad = other;
  ASSERT_TRUE(bad.params.Set(TerrainParam::kF0, 900).ok());
  EXPECT_EQ(run.Update(bad).field(), "f0");
  EXPECT_EQ(run.state().params, other.params);
}

TEST(TerrainRun, ResRegrowsWhenItsShareOfTheBudgetStopsTheKeptGrow) {
  // res is held back from the grow's budget: a res whose heightfield leaves the grow less room
  // than its checks needed regrows (and the result is a fresh run's); one that leaves enough keeps
  // the contours.
  Budget budget;
  budget.seconds = 0.3;  // 0.1 before the seed was resampled at d/4 (issue 31: more points)
  TerrainState state = State("lobes7", "improved", 1, 16);
  TerrainRun run = Grown(state, budget);
  ASSERT_TRUE(run.terrain().counts.truncated_by.empty());
  int tight = 0;
  for (int res = 32; res <= 800 && tight == 0; res += 8) {
    TerrainState s = state;
    ASSERT_TRUE(s.params.Set(TerrainParam::kRes, res).ok());
    if (!GrowFitsLimits(run.terrain(), s.params, TerrainLimits(s.params, budget))) tight = res;
  }
  ASSERT_GT(tight, 32) << "no res between 32 and 800 squeezes the grow";
  TerrainState roomy = state;
  ASSERT_TRUE(roomy.params.Set(TerrainParam::kRes, tight - 16).ok());
  ASSERT_TRUE(run.Update(roomy).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  EXPECT_EQ(run.counts().grows, 1);
  EXPECT_EQ(*run.Export("glb"), *Grown(roomy, budget).Export("glb"));
  TerrainState squeezed = state;
  ASSERT_TRUE(squeezed.params.Set(TerrainParam::kRes, tight).ok());
  ASSERT_TRUE(run.Update(squeezed).ok());
  const Status s = run.Advance({});
  EXPECT_EQ(run.counts().grows, 2);
  Result<TerrainRun> fresh = TerrainRun::Start(squeezed, budget);
  ASSERT_TRUE(fresh.ok());
  const Status f = fresh->Advance({});
  EXPECT_EQ(s.Line(), f.Line());
  if (s.ok()) {
    EXPECT_EQ(run.StatsJson(), fresh->StatsJson());
  }
}

}  // namespace
}  // namespace niwa::terrain
