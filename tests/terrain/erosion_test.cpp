// The erosion pass (erosion.h) on grown mountains: volume kept, no new pits, drainage that
// concentrates, valleys cut rather than filled (material ends lower than it started), the same
// bytes twice, the change carried to another grid, and the table's one-line errors.
#include "terrain/erosion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "terrain/generate.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {
namespace {

Heightfield GrowSurface(const TerrainState& s, int res) {
  Result<Terrain> t = Grow(*StateSeed(s), s.params, s.seed);
  EXPECT_TRUE(t.ok());
  return t.ok() ? BuildHeightfield(*t, res) : Heightfield();
}

TerrainState Builtin(const std::string& seed, const std::string& method) {
  TerrainState s;
  EXPECT_TRUE(SetTerrainBuiltin(seed, &s).ok());
  EXPECT_TRUE(SetTerrainPreset(method, &s).ok());
  return s;
}

// A contour as a hand drawing is (the page's five-lobed loop, uneven, 90 points).
TerrainState Drawn() {
  TerrainState s;
  Ring ring;
  for (int k = 0; k < 90; ++k) {
    const double a = 2 * 3.14159265358979 * k / 90;
    const double r = 250 * (1 + 0.3 * std::sin(5 * a) + 0.1 * std::cos(3 * a + 1));
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  EXPECT_TRUE(SetTerrainPoints(ring, &s).ok());
  EXPECT_TRUE(SetTerrainPreset("improved", &s).ok());
  return s;
}

// The table's defaults in a mode; thermal alone at 15° (jacksboro's slopes, 14° on average, are
// below the default 35°: nothing would slip).
ErosionParams Mode(ErosionMode mode) {
  ErosionParams p = ErosionParamsOf(TerrainParams());
  p.mode = static_cast<int>(mode);
  if (mode == ErosionMode::kThermal) p.talus_deg = 15;
  return p;
}

struct Case {
  const char* name;
  TerrainState state;
};

std::vector<Case> Cases() {
  return {{"jacksboro", Builtin("jacksboro", "improved")},
          {"drawn", Drawn()},
          {"valleys", Builtin("valleys", "improved")}};
}

// The cells of the mountain above its lowest band whose D8 accumulation before is in the top
// 5 %: the valley floors.
std::vector<std::size_t> ValleyFloors(const Heightfield& hf) {
  const std::vector<double> acc = D8Accumulation(hf);
  std::vector<std::size_t> cells;
  for (std::size_t k = 0; k < acc.size(); ++k)
    if (hf.band[k] > 0) cells.push_back(k);
  std::sort(cells.begin(), cells.end(), [&](std::size_t a, std::size_t b) {
    return acc[a] > acc[b] || (acc[a] == acc[b] && a < b);
  });
  cells.resize(std::max<std::size_t>(1, cells.size() / 20));
  return cells;
}

TEST(Erosion, DefaultsAreTheTables) {
  const ErosionParams table = ErosionParamsOf(TerrainParams());
  const ErosionParams plain;
  EXPECT_EQ(table.mode, 0);
  EXPECT_EQ(table.iterations, plain.iterations);
  EXPECT_EQ(table.talus_deg, plain.talus_deg);
  EXPECT_EQ(table.capacity, plain.capacity);
  EXPECT_EQ(table.solubility, plain.solubility);
  EXPECT_EQ(table.deposition, plain.deposition);
  EXPECT_EQ(table.evaporation, plain.evaporation);
}

TEST(Erosion, OffChangesNothing) {
  Heightfield hf = GrowSurface(Builtin("lobes7", "improved"), 96);
  const std::vector<double> before = hf.h;
  const ErosionReport r = Erode(ErosionParams{}, &hf);
  EXPECT_EQ(hf.h, before);
  EXPECT_EQ(r.volume_moved, 0);
}

TEST(Erosion, KeepsVolumeAndMakesNoNewPits) {
  for (const Case& c : Cases()) {
    const Heightfield raw = GrowSurface(c.state, 160);
    for (ErosionMode mode : {ErosionMode::kThermal, ErosionMode::kHydraulic, ErosionMode::kBoth}) {
      SCOPED_TRACE(std::string(c.name) + " mode " + std::to_string(static_cast<int>(mode)));
      Heightfield hf = raw;
      const ErosionReport r = Erode(Mode(mode), &hf);
      // Σh kept within rounding (n cells · ulp of the largest sum), what left at the edge
      // counted.
      const double tolerance =
          1e-12 * static_cast<double>(hf.h.size()) *
          std::max(1.0, std::fabs(r.sum_before) / static_cast<double>(hf.h.size()));
      EXPECT_NEAR(r.sum_after + r.exported, r.sum_before, tolerance);
      EXPECT_GE(r.exported, 0);
      double sum = 0;
      for (double v : hf.h) sum += v;
      EXPECT_EQ(sum, r.sum_after);
      // Every cell with 8 neighbours that was not a strict minimum is not one now.
      for (int j = 1; j + 1 < hf.height; ++j) {
        for (int i = 1; i + 1 < hf.width; ++i) {
          bool was = true, is = true;
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              if (di == 0 && dj == 0) continue;
              if (raw.At(i + di, j + dj) <= raw.At(i, j)) was = false;
              if (hf.At(i + di, j + dj) <= hf.At(i, j)) is = false;
            }
          ASSERT_FALSE(is && !was) << "new pit at " << i << "," << j;
        }
      }
      EXPECT_LE(r.pits_after, r.pits_before);
      EXPECT_GT(r.volume_moved, 0);
      std::printf(
          "%s mode %d: exported %.0f m3 moved %.0f m3, cut %.2f m, deposit %.2f m, pits %d -> %d "
          "(levelled %d), channel share %.4f -> %.4f, max acc %.0f -> %.0f, mean acc "
          "%.1f -> %.1f\n",
          c.name, static_cast<int>(mode), r.volume_exported, r.volume_moved, r.max_cut,
          r.max_deposit, r.pits_before, r.pits_after, r.pits_levelled,
          r.drainage_before.channel_share, r.drainage_after.channel_share,
          r.drainage_before.max_accumulation, r.drainage_after.max_accumulation,
          r.drainage_before.mean_accumulation, r.drainage_after.mean_accumulation);
    }
  }
}

// Drainage forms: on jacksboro and the drawn seed the share of channel cells (D8 accumulation
// at least a hundredth of the mountain) grows under hydraulic erosion (and both).
TEST(Erosion, DrainageConcentrates) {
  for (const Case& c : Cases()) {
    const Heightfield raw = GrowSurface(c.state, 160);
    for (ErosionMode mode : {ErosionMode::kHydraulic, ErosionMode::kBoth}) {
      SCOPED_TRACE(std::string(c.name) + " mode " + std::to_string(static_cast<int>(mode)));
      Heightfield hf = raw;
      const ErosionReport r = Erode(Mode(mode), &hf);
      EXPECT_GT(r.drainage_after.channel_share, r.drainage_before.channel_share);
      EXPECT_GT(r.drainage_after.mean_accumulation, r.drainage_before.mean_accumulation);
    }
  }
}

// Not backwards (a prototype filled valleys on `valleys`): the valley floors' mean height goes
// down, and the material removed sat higher (its mean height before, weighted by the cut) than
// where it was laid down (mean height after, weighted by the deposit); the surface's potential
// energy Σh² falls.
TEST(Erosion, CutsValleysAndMovesMaterialDown) {
  for (const Case& c : Cases()) {
    const Heightfield raw = GrowSurface(c.state, 160);
    const std::vector<std::size_t> floors = ValleyFloors(raw);
    for (ErosionMode mode : {ErosionMode::kThermal, ErosionMode::kHydraulic, ErosionMode::kBoth}) {
      SCOPED_TRACE(std::string(c.name) + " mode " + std::to_string(static_cast<int>(mode)));
      Heightfield hf = raw;
      Erode(Mode(mode), &hf);
      double cut = 0, cut_h = 0, laid = 0, laid_h = 0, e0 = 0, e1 = 0;
      for (std::size_t k = 0; k < hf.h.size(); ++k) {
        const double d = hf.h[k] - raw.h[k];
        if (d < 0) {
          cut -= d;
          cut_h -= d * raw.h[k];
        } else if (d > 0) {
          laid += d;
          laid_h += d * hf.h[k];
        }
        e0 += raw.h[k] * raw.h[k];
        e1 += hf.h[k] * hf.h[k];
      }
      ASSERT_GT(cut, 0);
      EXPECT_LT(laid_h / laid, cut_h / cut);
      EXPECT_LT(e1, e0);
      if (mode == ErosionMode::kThermal) continue;  // talus fills a valley's foot: not a cut
      double floor_before = 0, floor_after = 0;
      for (std::size_t k : floors) {
        floor_before += raw.h[k];
        floor_after += hf.h[k];
      }
      EXPECT_LT(floor_after, floor_before);
      std::printf(
          "%s mode %d: valley floors mean %.3f -> %.3f m; cut from %.2f m, laid at "
          "%.2f m\n",
          c.name, static_cast<int>(mode), floor_before / static_cast<double>(floors.size()),
          floor_after / static_cast<double>(floors.size()), cut_h / cut, laid_h / laid);
    }
  }
}

TEST(Erosion, SameBytesTwice) {
  const Heightfield raw = GrowSurface(Builtin("lobes7", "improved"), 96);
  Heightfield a = raw, b = raw;
  Erode(Mode(ErosionMode::kBoth), &a);
  Erode(Mode(ErosionMode::kBoth), &b);
  ASSERT_EQ(a.h.size(), b.h.size());
  EXPECT_EQ(std::memcmp(a.h.data(), b.h.data(), a.h.size() * sizeof(double)), 0);
}

TEST(Erosion, ChangeCarriesToAnotherGrid) {
  const Heightfield raw = GrowSurface(Builtin("lobes7", "improved"), 96);
  Heightfield eroded = raw;
  Erode(Mode(ErosionMode::kBoth), &eroded);
  // On raw's own grid the interpolated change is the change itself.
  Heightfield same = raw;
  AddErosionChange(raw, eroded, &same);
  for (std::size_t k = 0; k < same.h.size(); ++k) EXPECT_NEAR(same.h[k], eroded.h[k], 1e-9);
}

TEST(Erosion, BadValuesNameTheRowAndItsRange) {
  ErosionParams p = Mode(ErosionMode::kBoth);
  EXPECT_TRUE(CheckErosionParams(p).ok());
  p.talus_deg = 95;
  Status s = CheckErosionParams(p);
  EXPECT_EQ(s.field(), "erosion_talus");
  EXPECT_NE(s.message().find("[1, 89]"), std::string::npos) << s.message();
  p = Mode(ErosionMode::kBoth);
  p.iterations = 0;
  EXPECT_EQ(CheckErosionParams(p).field(), "erosion_iterations");
  p = Mode(ErosionMode::kBoth);
  p.mode = 4;
  EXPECT_EQ(CheckErosionParams(p).field(), "erosion");
  TerrainParams params;
  EXPECT_EQ(params.SetFromText("erosion_evaporation", "1").field(), "erosion_evaporation");
}

}  // namespace
}  // namespace niwa::terrain
