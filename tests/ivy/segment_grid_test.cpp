// ivy::SegmentGrid (the improved preset's branch avoidance) against its brute-force twin, the loop
// over every segment: same answer for random segments and queries at several radii, each segment
// offered at most once per query, and far-away coordinates; and the improved preset still keeps
// its promise (no overlapping internodes) while growing with it.
#include "ivy/segment_grid.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "ivy/growth.h"
#include "ivy/ivy_report.h"
#include "ivy/scenes.h"
#include "random/pcg32.h"

namespace niwa::ivy {
namespace {

struct Seg {
  glm::dvec3 a, b;
};

TEST(SegmentGrid, AnswersWhatTheLoopOverEverySegmentAnswers) {
  Pcg32 rng(2024);
  const double L = 50;
  std::vector<Seg> segs;
  SegmentGrid grid(L);
  const auto random_point = [&rng]() {
    double x = rng.Uniform(-400.0, 400.0);
    double y = rng.Uniform(0.0, 800.0);
    double z = rng.Uniform(-100.0, 100.0);
    return glm::dvec3(x, y, z);
  };
  const auto random_dir = [&rng]() {
    double x = rng.Uniform(-1.0, 1.0);
    double y = rng.Uniform(-1.0, 1.0);
    double z = rng.Uniform(-1.0, 1.0);
    glm::dvec3 d(x, y, z);
    const double l = std::sqrt(glm::dot(d, d));
    return l > 1e-6 ? d / l : glm::dvec3(0, 1, 0);
  };
  for (int i = 0; i < 800; ++i) {
    glm::dvec3 a = random_point();
    segs.push_back({a, a + L * random_dir()});
    grid.Insert(i, segs.back().a, segs.back().b);
  }
  int hits = 0, misses = 0;
  for (double r : {0.5, 3.0, 10.0, 40.0}) {
    for (int q = 0; q < 2000; ++q) {
      glm::dvec3 a = random_point(), b = a + L * random_dir();
      bool brute = false;
      for (const Seg& s : segs) brute = brute || SegmentSegmentDistance(a, b, s.a, s.b) < r;
      std::set<int> offered;
      bool twice = false;
      bool fast = grid.Any(a, b, r, [&](int id) {
        twice = twice || !offered.insert(id).second;
        return SegmentSegmentDistance(a, b, segs[static_cast<std::size_t>(id)].a,
                                      segs[static_cast<std::size_t>(id)].b) < r;
      });
      ASSERT_EQ(fast, brute) << "r " << r << " query " << q;
      ASSERT_FALSE(twice);
      (brute ? hits : misses) += 1;
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(hits, 500);
  EXPECT_GT(misses, 500);
}

TEST(SegmentGrid, OffersOnlyNearbySegmentsAndSurvivesFarCoordinates) {
  SegmentGrid grid(1.0);
  grid.Insert(0, {0, 0, 0}, {1, 0, 0});
  grid.Insert(1, {100, 0, 0}, {101, 0, 0});
  grid.Insert(2, {1e30, 1e30, -1e30}, {1e30, 1e30 + 1, -1e30});
  int offered = 0;
  EXPECT_FALSE(grid.Any({0, 5, 0}, {1, 5, 0}, 0.5, [&](int) { return ++offered, false; }));
  EXPECT_EQ(offered, 0);  // nothing within two cells
  EXPECT_TRUE(grid.Any({100.5, 0.2, 0}, {100.5, 1, 0}, 0.5, [](int id) { return id == 1; }));
  EXPECT_TRUE(
      grid.Any({1e30, 1e30, -1e30}, {1e30, 1e30, -1e30}, 1, [](int id) { return id == 2; }));
}

TEST(SegmentGrid, ImprovedPresetGrowsWithoutOverlapsOnCubes4) {
  IvyScene scene = *MakeIvyScene("cubes4");
  geom::Bvh bvh = geom::Bvh::Build(scene.mesh);
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    GrowLog log;
    Result<IvyModel> m = Grow({&scene.mesh, &bvh, Accel::kBvh}, {scene.seeds[0].pos},
                              *IvyPreset("improved"), 50, seed, &log);
    ASSERT_TRUE(m.ok()) << m.status().Line();
    IvyStats s = MeasureIvy(*m, log, &scene.mesh, *IvyPreset("improved"));
    EXPECT_EQ(s.overlap_pairs, 0) << "seed " << seed;
    EXPECT_GT(s.internodes, 20) << "seed " << seed;
    EXPECT_GT(log.rejected[kCrowding], 0) << "seed " << seed;  // the check does reject candidates
  }
}

}  // namespace
}  // namespace niwa::ivy
