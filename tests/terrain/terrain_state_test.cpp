// terrain_state: the hash and the state JSON read back to the same state (bit for bit, drawn
// contours included), hostile hashes give notices and a usable state, strict JSON errors name the
// field.
#include "terrain/terrain_state.h"

#include <gtest/gtest.h>

#include "terrain/generate.h"

namespace niwa::terrain {
namespace {

TEST(TerrainState, HashRoundTripsBuiltinPresetAndOverrides) {
  TerrainState s;
  ASSERT_TRUE(SetTerrainBuiltin("lobes7", &s).ok());
  ASSERT_TRUE(SetTerrainPreset("fig13c", &s).ok());
  ASSERT_TRUE(SetTerrainSeed(7, &s).ok());
  ASSERT_TRUE(s.params.Set(TerrainParam::kD, 17.5).ok());
  const std::string hash = EncodeTerrainHash(s);
  EXPECT_EQ(hash, "preset=fig13c&builtin=lobes7&d=17.5&seed=7");
  TerrainState back;
  std::vector<std::string> notices;
  ApplyTerrainHash("#" + hash, "", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.preset, "fig13c");
  EXPECT_EQ(back.builtin, "lobes7");
  EXPECT_EQ(back.seed, 7u);
  EXPECT_TRUE(back.params == s.params);
}

// Issue 28 item 6: the seed is a state field, as the tree's and the ivy's; not a table row, so a
// preset or a new seed contour keeps it, and the link, the .glb's url and a state file of before
// read the same.
TEST(TerrainState, SeedIsAStateFieldNotARow) {
  EXPECT_FALSE(TerrainTable().Find("seed").has_value());
  TerrainState s;
  EXPECT_EQ(s.seed, kDefaultTerrainSeed);
  ASSERT_TRUE(SetTerrainSeed(4294967295.0, &s).ok());
  EXPECT_EQ(s.seed, 4294967295u);
  EXPECT_EQ(SetTerrainSeed(4294967296.0, &s).Line(),
            "seed: 4294967296 is out of range; must be a whole number in [0, 4294967295]");
  EXPECT_EQ(SetTerrainSeed(1.5, &s).field(), "seed");
  EXPECT_EQ(s.seed, 4294967295u);  // unchanged on error
  ASSERT_TRUE(SetTerrainPreset("fig9a", &s).ok());
  ASSERT_TRUE(SetTerrainBuiltin("lobes7", &s).ok());
  EXPECT_EQ(s.seed, 4294967295u);  // a preset or a seed contour keeps it
  // The default seed is not in the link; another is, where its row stood (after clean_angle,
  // before max_levels), so links and the .glb's asset url are those of before.
  TerrainState t;
  ASSERT_TRUE(SetTerrainBuiltin("disk", &t).ok());
  ASSERT_TRUE(t.params.Set(TerrainParam::kCleanAngle, 12).ok());
  ASSERT_TRUE(t.params.Set(TerrainParam::kMaxLevels, 50).ok());
  ASSERT_TRUE(t.params.Set(TerrainParam::kRes, 64).ok());
  EXPECT_EQ(EncodeTerrainHash(t), "builtin=disk&clean_angle=12&max_levels=50&res=64");
  ASSERT_TRUE(SetTerrainSeed(3, &t).ok());
  EXPECT_EQ(EncodeTerrainHash(t, "terrain."),
            "terrain.builtin=disk&terrain.clean_angle=12&terrain.seed=3&terrain.max_levels=50&"
            "terrain.res=64");
  TerrainState back;
  std::vector<std::string> notices;
  ApplyTerrainHash("terrain.seed=3&terrain.preset=improved&ivy.seed=9", "terrain.", &back,
                   &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(back.seed, 3u);  // read before the preset, kept by it
  ApplyTerrainHash("seed=x", "", &back, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0], "seed: 'x' is not a number; dropped");
  EXPECT_EQ(back.seed, 3u);
  // State JSON: the field at the top, or (a file of before) in params; not at both places.
  TerrainState j;
  ASSERT_TRUE(ApplyTerrainStateJson(R"({"builtin": "disk", "seed": 9})", &j).ok());
  EXPECT_EQ(j.seed, 9u);
  ASSERT_TRUE(ApplyTerrainStateJson(R"({"params": {"seed": "12", "d": 25}})", &j).ok());
  EXPECT_EQ(j.seed, 12u);
  EXPECT_EQ(j.params.Get(TerrainParam::kD), 25);
  EXPECT_EQ(ApplyTerrainStateJson(R"({"seed": 1, "params": {"seed": 2}})", &j).Line(),
            "seed: given at the top and in params; must be given once");
  EXPECT_EQ(ApplyTerrainStateJson(R"({"seed": -1})", &j).field(), "seed");
  EXPECT_EQ(ApplyTerrainStateJson(R"({"seed": [1]})", &j).field(), "seed");
  EXPECT_EQ(j.seed, 12u);
  TerrainState again;
  ASSERT_TRUE(ApplyTerrainStateJson(TerrainStateJson(j), &again).ok());
  EXPECT_EQ(again.seed, 12u);
  EXPECT_TRUE(again.params == j.params);
}

TEST(TerrainState, DrawnContourRoundTripsBitForBit) {
  TerrainState s;
  Ring drawn = {{0.1, 0.2}, {100.0 / 3.0, -1e-5}, {50.123456789, 80.5}, {-20.25, 40}};
  ASSERT_TRUE(SetTerrainPoints(drawn, &s).ok());
  ASSERT_TRUE(SetTerrainPreset("improved", &s).ok());
  const std::string hash = EncodeTerrainHash(s, "terrain.");
  TerrainState back;
  std::vector<std::string> notices;
  ApplyTerrainHash(hash + "&tree.years=3", "terrain.", &back, &notices);
  EXPECT_TRUE(notices.empty()) << notices.front();
  EXPECT_TRUE(back.builtin.empty());
  ASSERT_EQ(back.points.size(), drawn.size());
  for (std::size_t k = 0; k < drawn.size(); ++k) EXPECT_EQ(back.points[k], drawn[k]) << k;
  EXPECT_TRUE(back.params == s.params);
}

TEST(TerrainState, HostileHashesGiveNoticesAndAUsableState) {
  const std::vector<std::string> hashes = {"builtin=nope",
                                           "contour=1,2;3",
                                           "contour=a,b;c,d;e,f",
                                           "preset=<script>",
                                           "d=-5",
                                           "seed=abc",
                                           "zzz=1",
                                           "contour=nan,1;2,3;4,5",
                                           "contour=1e300,0;1,1;0,1",
                                           std::string(20000, '&'),
                                           "d=1e999"};
  for (const std::string& h : hashes) {
    TerrainState s;
    std::vector<std::string> notices;
    ApplyTerrainHash(h, "", &s, &notices);
    if (h.find_first_not_of('&') != std::string::npos) {
      EXPECT_FALSE(notices.empty()) << h;
    }
    for (const std::string& n : notices) EXPECT_EQ(n.find('<'), std::string::npos) << n;
    EXPECT_TRUE(StateSeed(s).ok()) << h;  // still the default disk or a valid point list
  }
  TerrainState s;
  std::vector<std::string> notices;
  ApplyTerrainHash("d=-5", "", &s, &notices);
  EXPECT_EQ(s.params.Get(TerrainParam::kD), 0.01);  // clamped into the row's range
}

TEST(TerrainState, StateJsonIsStrictAndRoundTrips) {
  TerrainState s;
  ASSERT_TRUE(ApplyTerrainStateJson(
                  R"({"preset": "fig16", "contour": [[0,0],[100,0],[100,80],[0,80]],
                      "params": {"seed": 5, "dh": 12}})",
                  &s)
                  .ok());
  EXPECT_EQ(s.seed, 5u);  // params.seed: a file of when the seed was a table row
  EXPECT_EQ(s.params.Get(TerrainParam::kDh), 12);
  EXPECT_EQ(s.points.size(), 4u);
  TerrainState back;
  ASSERT_TRUE(ApplyTerrainStateJson(TerrainStateJson(s), &back).ok());
  EXPECT_TRUE(back.params == s.params);
  EXPECT_EQ(back.points, s.points);
  const TerrainState before = back;
  Status bad = ApplyTerrainStateJson(R"({"preset": "fig16", "params": {"c": 0.5}})", &back);
  EXPECT_EQ(bad.Line(), "c: 0.5 is out of range; must be a number in [1, 100]");
  EXPECT_TRUE(back.params == before.params);  // unchanged on error
  EXPECT_EQ(ApplyTerrainStateJson(R"({"contour": [[0,0],[1,1]]})", &back).field(), "contour");
  EXPECT_EQ(ApplyTerrainStateJson(R"({"builtin": "x"})", &back).field(), "builtin");
  // Issue 34: a key repeated after a nested value was accepted (the last one used).
  EXPECT_EQ(
      ApplyTerrainStateJson(
          R"({"builtin": "disk", "contour": [[0,0],[10,0],[0,10]], "builtin": "lobes7"})", &back)
          .Line(),
      "builtin: given twice in one object");
  EXPECT_EQ(ApplyTerrainStateJson("{\"preset\": \"fig16\", \"x\": " + std::string(30000, '[') +
                                      std::string(30000, ']') + "}",
                                  &back)
                .Line(),
            "params: nested deeper than 32 levels");
}

TEST(TerrainState, HashRegrowsTheSameMountain) {
  TerrainState s;
  ASSERT_TRUE(SetTerrainBuiltin("dumbbell", &s).ok());
  ASSERT_TRUE(SetTerrainPreset("improved", &s).ok());
  ASSERT_TRUE(SetTerrainSeed(11, &s).ok());
  TerrainState back;
  std::vector<std::string> notices;
  ApplyTerrainHash(EncodeTerrainHash(s), "", &back, &notices);
  Result<Terrain> a = Grow(*StateSeed(s), s.params, s.seed);
  Result<Terrain> b = Grow(*StateSeed(back), back.params, back.seed);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->contours.size(), b->contours.size());
  for (std::size_t c = 0; c < a->contours.size(); ++c)
    EXPECT_EQ(a->contours[c].ring, b->contours[c].ring);
}

}  // namespace
}  // namespace niwa::terrain
