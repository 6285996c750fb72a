// The moss run (core/moss/moss_run.h): days advance with progress, cancel restores, the estimate
// is refused up front, the same state gives the same bytes, the invariants of spec §6 hold (counts
// within caps, buckets within [0, O_SAT], every moss on a face or resting on a moss), and indirect
// off stores first hits only.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "geom/closest_point.h"
#include "moss/moss_run.h"

namespace niwa::moss {
namespace {

// The stats without their ms_* timing fields.
std::string StatsWithoutMs(const MossRun& run) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(run.StatsJson());
  for (auto it = j.begin(); it != j.end();) {
    if (it.key().rfind("ms", 0) == 0) {
      it = j.erase(it);
    } else {
      ++it;
    }
  }
  return j.dump();
}

MossState SmallState(const std::string& scene, int days, int photons, uint64_t seed = 1) {
  MossState state;
  EXPECT_TRUE(SetMossScene(scene, &state).ok());
  state.days = days;
  state.seed = seed;
  EXPECT_TRUE(state.params.Set(MossParam::kPhotons, photons).ok());
  return state;
}

// Spec §6's invariants after 20 days on every scene: counts within the caps, every bucket within
// [0, O_SAT], every moss on the front of a face (within 1e-5 m of it) or s from another moss.
TEST(MossRun, InvariantsHoldOnEveryScene) {
  for (const std::string& scene : SceneNames()) {
    MossState state = SmallState(scene, 20, 2048);
    Result<MossRun> run = MossRun::Start(state, Budget{});
    ASSERT_TRUE(run.ok()) << scene << ": " << run.status().message();
    EXPECT_EQ(run->done(), 0);
    EXPECT_EQ(run->world().mosses.size(), 64u);  // n_init
    ASSERT_TRUE(run->Advance(nullptr).ok());
    EXPECT_EQ(run->done(), 20);
    const MossWorld& w = run->world();
    EXPECT_EQ(w.population.size(), 21u);
    EXPECT_LE(w.mosses.size(), 16384u);
    EXPECT_LE(w.seeds.size(), 16384u);
    for (const Bucket& b : w.buckets) {
      ASSERT_GE(b.O, 0.0);
      ASSERT_LE(b.O, b.O_SAT);
    }
    const SoilCells& cells = run->cells();
    for (const MossPlant& m : w.mosses) {
      if (m.on_moss) {
        double nearest = 1e9;
        for (const MossPlant& o : w.mosses)
          if (&o != &m) nearest = std::min(nearest, glm::length(o.pos - m.pos));
        // It rested s from a moss; that moss may since have died (then nothing is that close).
        EXPECT_GE(nearest, 0.9 * 0.01 - 1e-12) << scene;
      } else {
        const geom::ClosestHit near =
            geom::ClosestPoint(cells.mesh, cells.bvh, glm::vec3(m.pos), 1.0f);
        ASSERT_TRUE(near.found);
        EXPECT_LT(near.distance, 1e-5) << scene;
      }
      EXPECT_LE(m.birth_day, 20);
    }
  }
}

TEST(MossRun, TheSameStateGivesTheSameBytes) {
  const MossState state = SmallState("thesis", 8, 2048, 2);
  MossRun a = *MossRun::Start(state, Budget{});
  MossRun b = *MossRun::Start(state, Budget{});
  ASSERT_TRUE(a.Advance(nullptr).ok());
  ASSERT_TRUE(b.Advance(nullptr).ok());
  EXPECT_EQ(StatsWithoutMs(a), StatsWithoutMs(b));
  EXPECT_NE(a.StatsJson().find("\"ms_photons\":"), std::string::npos);
  EXPECT_EQ(a.MossesJson(), b.MossesJson());
  MossRun c = *MossRun::Start(SmallState("thesis", 8, 2048, 3), Budget{});
  ASSERT_TRUE(c.Advance(nullptr).ok());
  EXPECT_NE(a.MossesJson(), c.MossesJson());
}

TEST(MossRun, ProgressAndCancelRestoresTheRun) {
  MossRun run = *MossRun::Start(SmallState("plane", 6, 1024), Budget{});
  const std::string day0 = StatsWithoutMs(run);
  int calls = 0;
  const Status cancelled = run.Advance([&](const run::Progress& p) {
    EXPECT_EQ(p.phase, "grow");
    EXPECT_EQ(p.total, 6);
    return ++calls < 4;  // cancel before the fourth day
  });
  EXPECT_TRUE(run::IsCancelled(cancelled));
  EXPECT_EQ(run.done(), 0);
  EXPECT_EQ(StatsWithoutMs(run), day0);
  // Advancing again from the restored run gives the bytes of an uncancelled run.
  ASSERT_TRUE(run.Advance(nullptr).ok());
  MossRun fresh = *MossRun::Start(SmallState("plane", 6, 1024), Budget{});
  ASSERT_TRUE(fresh.Advance(nullptr).ok());
  EXPECT_EQ(StatsWithoutMs(run), StatsWithoutMs(fresh));
}

// Eq 3.5's m per cell is counted on day 1 and then kept by each day's births and deaths: after
// days of both it is a fresh count over the living mosses (the run's own r_CH query).
TEST(MossRun, TheKeptMossCountsAreAFreshCount) {
  MossState state = SmallState("thesis", 45, 2048);
  MossRun run = *MossRun::Start(state, Budget{});
  ASSERT_TRUE(run.Advance(nullptr).ok());
  const MossWorld& w = run.world();
  ASSERT_GT(w.births, 0);
  ASSERT_GT(w.deaths_declined + w.deaths_contest, 0);
  const geom::RadiusGrid grid(run.cells().centroid, state.params.Get(MossParam::kRCH));
  std::vector<int> want(run.cells().size(), 0);
  for (const MossPlant& m : w.mosses)
    grid.ForEachWithin(m.pos, [&](uint32_t i, double) { ++want[i]; });
  EXPECT_EQ(w.m_near, want);
  int near = 0;
  for (int n : want) near += n > 0;
  EXPECT_GT(near, 100);
  // Each moss's mats count (§3.8), kept while no moss near it is born or dies.
  const LifeRules rules = LifeRulesOf(state.params);
  std::vector<glm::dvec3> centres;
  for (const MossPlant& m : w.mosses) centres.push_back(m.pos);
  const geom::RadiusGrid mats(centres, rules.interior_radius * rules.s);
  int crowded = 0;
  for (const MossPlant& m : w.mosses) {
    ASSERT_EQ(m.mat_count, static_cast<int>(mats.CountWithin(m.pos)));
    crowded += m.mat_count > 1;
  }
  EXPECT_GT(crowded, 5);
}

TEST(MossRun, OverTheBudgetIsRefusedUpFront) {
  Budget budget;
  budget.seconds = 1;
  const MossState state = SmallState("thesis", 300, 8192);
  const Estimate e = MossRun::RunEstimate(state, 16488);
  EXPECT_GT(e.seconds, 1.0);
  const Status refused = MossRun::Start(state, budget).status();
  EXPECT_EQ(refused.field(), "max_seconds");
  EXPECT_NE(refused.message().find("days"), std::string::npos) << refused.message();
  budget.seconds = 60;
  budget.memory_bytes = 1 << 20;
  EXPECT_EQ(MossRun::Start(state, budget).status().field(), "max_memory");
}

TEST(MossRun, RowsNotBuiltAreRefusedByName) {
  MossState state = SmallState("plane", 1, 64);
  ASSERT_TRUE(state.params.Set(MossParam::kSunPath, 1).ok());
  EXPECT_EQ(MossRun::Start(state, Budget{}).status().field(), "sun_path");
}

TEST(MossRun, IndirectOffStoresFirstHitsOnly) {
  MossState state = SmallState("thesis", 3, 4096);
  ASSERT_TRUE(state.params.Set(MossParam::kIndirect, 0).ok());
  MossRun run = *MossRun::Start(state, Budget{});
  ASSERT_TRUE(run.Advance(nullptr).ok());
  const std::vector<int64_t>& depth = run.world().stored_by_depth_total;
  ASSERT_FALSE(depth.empty());
  EXPECT_GT(depth[0], 0);
  for (std::size_t d = 1; d < depth.size(); ++d) EXPECT_EQ(depth[d], 0);
}

// Spec §1.5.6 on the plane (a single upward face at y = 0, nothing below it): a seed within s/2
// above snaps to it, one within s/2 below is behind the face, one farther below falls off, one
// above falls onto the face; and a seed touching a lone moss does not rest on it (only mats carry
// seeds), it falls past it to the face.
TEST(MossRun, LandingOnThePlane) {
  MossRun run = *MossRun::Start(SmallState("plane", 0, 64), Budget{});
  MossSeed seed;
  SeedLoss loss = SeedLoss::kCount;
  ASSERT_TRUE(run.LandSeed({0.31, 0.004, 0.2}, &seed, &loss));
  EXPECT_EQ(seed.pos, glm::dvec3(glm::vec3(0.31f, 0.0f, 0.2f)));
  EXPECT_FALSE(seed.on_moss);
  EXPECT_FALSE(run.LandSeed({0.31, -0.004, 0.2}, &seed, &loss));
  EXPECT_EQ(loss, SeedLoss::kBackFace);
  EXPECT_FALSE(run.LandSeed({0.31, -0.2, 0.2}, &seed, &loss));
  EXPECT_EQ(loss, SeedLoss::kFellOff);
  EXPECT_FALSE(run.LandSeed({3.0, 0.5, 0.0}, &seed, &loss));  // beside the plane
  EXPECT_EQ(loss, SeedLoss::kFellOff);
  ASSERT_TRUE(run.LandSeed({-0.4, 0.3, 0.1}, &seed, &loss));
  EXPECT_NEAR(seed.pos.y, 0.0, 1e-7);
  EXPECT_EQ(seed.normal, glm::dvec3(0, 1, 0));
  // Straight above a day-0 moss (64 on 4 m²: none inside a mat), touching it.
  const MossPlant& moss = run.world().mosses[0];
  ASSERT_TRUE(run.LandSeed(moss.pos + glm::dvec3(0, 0.01, 0), &seed, &loss));
  EXPECT_FALSE(seed.on_moss);
  EXPECT_NEAR(seed.pos.y, 0.0, 1e-7);
}

TEST(MossRun, TheStateHashCarriesSceneDaysAndSeed) {
  MossState state = SmallState("walls", 12, 8192, 5);
  EXPECT_EQ(EncodeMossHash(state), "preset=nomura2010&scene=walls&days=12&seed=5");
  MossState back;
  std::vector<std::string> notices;
  ApplyMossHash("preset=nomura2010&scene=walls&days=12&seed=5", "", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.scene, "walls");
  EXPECT_EQ(back.days, 12);
  EXPECT_EQ(back.seed, 5u);
  ApplyMossHash("scene=garden&days=-1&seed=1.5", "", &back, &notices);
  EXPECT_EQ(notices.size(), 3u);
  EXPECT_EQ(SetMossDays(3651, &back).field(), "days");
  EXPECT_EQ(SetMossScene("x", &back).field(), "scene");
}

}  // namespace
}  // namespace niwa::moss

namespace niwa::moss {
namespace {

// Stats every K days (spec §6 `--every K`, issue 29 item 3): rows at the end of days K, 2K, ...
// and the last day, each the breakdown the stats give; the last row equals the stats' own fields;
// the rows are what the run was on those days (a run of 3 days has the 7-day run's first row);
// without RecordEvery the stats have no rows; asked after day 0 or out of range it is refused.
TEST(MossRun, StatsEveryKDaysAreTheBreakdownOfThoseDays) {
  MossRun run = *MossRun::Start(SmallState("thesis", 7, 1024), Budget{});
  ASSERT_TRUE(run.RecordEvery(3).ok());
  ASSERT_TRUE(run.Advance({}).ok());
  const nlohmann::json stats = nlohmann::json::parse(run.StatsJson());
  ASSERT_EQ(stats["every"], 3);
  const nlohmann::json& rows = stats["every_days"];
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["day"], 3);
  EXPECT_EQ(rows[1]["day"], 6);
  EXPECT_EQ(rows[2]["day"], 7);
  const nlohmann::json& last = rows[2];
  EXPECT_EQ(last["mosses"], stats["mosses"]);
  EXPECT_EQ(last["seeds"], stats["seeds"]);
  EXPECT_EQ(last["births"], stats["births"]);
  EXPECT_EQ(last["deaths"], stats["deaths"]);
  EXPECT_EQ(last["soil"], stats["soil_last_day"]);
  EXPECT_EQ(last["photons"]["stored_by_depth"], stats["photons_last_day"]["stored_by_depth"]);
  // Day 3's row is the 3-day run's breakdown.
  MossRun three = *MossRun::Start(SmallState("thesis", 3, 1024), Budget{});
  ASSERT_TRUE(three.Advance({}).ok());
  const nlohmann::json at3 = nlohmann::json::parse(three.StatsJson());
  EXPECT_EQ(rows[0]["mosses"], at3["mosses"]);
  EXPECT_EQ(rows[0]["seeds"], at3["seeds"]);
  EXPECT_EQ(rows[0]["soil"], at3["soil_last_day"]);
  EXPECT_EQ(at3.find("every"), at3.end());
  // Without rows the stats are those of before: the same text but for the rows.
  EXPECT_EQ(StatsWithoutMs(three).find("every_days"), std::string::npos);
  EXPECT_EQ(run.RecordEvery(2).field(), "stats_every");  // after day 0
  MossRun fresh = *MossRun::Start(SmallState("plane", 2, 64), Budget{});
  EXPECT_EQ(fresh.RecordEvery(-1).field(), "stats_every");
  EXPECT_EQ(fresh.RecordEvery(1.5).field(), "stats_every");
  EXPECT_TRUE(fresh.RecordEvery(0).ok());
}

}  // namespace
}  // namespace niwa::moss

namespace niwa::moss {
namespace {

// light_smoothing_days N (spec §1.3, choice 31): day 1's S is the day's own; day 2's cell S is
// S_1 + k·(S_2 − S_1) with k = 1 − e^(−1/N), where S_2 is the unsmoothed run's day 2 (the same
// mosses start day 2: day 1 used the same light); 0 keeps the run of before.
TEST(MossRun, LightSmoothingIsAnExponentialMeanOverDays) {
  const double N = 3;
  const double k = 1.0 - std::exp(-1.0 / N);
  MossState plain = SmallState("thesis", 1, 2048);
  MossState smooth = plain;
  ASSERT_TRUE(smooth.params.Set(MossParam::kLightSmoothingDays, N).ok());
  MossRun a1 = *MossRun::Start(plain, Budget{});
  MossRun b1 = *MossRun::Start(smooth, Budget{});
  ASSERT_TRUE(a1.Advance({}).ok());
  ASSERT_TRUE(b1.Advance({}).ok());
  EXPECT_EQ(a1.world().S, b1.world().S);
  plain.days = 2;
  smooth.days = 2;
  MossRun a2 = *MossRun::Start(plain, Budget{});
  MossRun b2 = *MossRun::Start(smooth, Budget{});
  ASSERT_TRUE(a2.Advance({}).ok());
  ASSERT_TRUE(b2.Advance({}).ok());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a2.world().S.size(); ++i) {
    const double S1 = a1.world().S[i], S2 = a2.world().S[i];
    ASSERT_NEAR(b2.world().S[i], S1 + k * (S2 - S1), 1e-9 * (1 + std::abs(S1) + std::abs(S2))) << i;
    differ += S1 != S2;
  }
  EXPECT_GT(differ, 100u);  // the days' light differs, so the mean is not either day's
  // A moss's own light is its mean too (it grew on day 1 and day 2).
  for (std::size_t j = 0; j < b2.world().mosses.size(); ++j) {
    const MossPlant& m = b2.world().mosses[j];
    if (m.birth_day == 0) {
      ASSERT_TRUE(m.lit);
    }
  }
}

}  // namespace
}  // namespace niwa::moss
