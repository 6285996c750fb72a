// The artist preset (issue 31 item 5; docs/ivy-model.md "The artist preset"): on the Stanford bunny
// (tests/data/meshes/bunny.obj) and on the overhang facade it grows down the far side (internodes
// pointing down, where paper's never do), branches spread (overlapping internode pairs at most 5 %
// of the internodes, where paper bundles above that on the bunny), no turn past 90°, tendrils hang
// under the overhang, leaves are thinned, enlarged and turned by light, and the leaf cover seen
// from the front (--stats' leaf_cover) is measured against a hand-made coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "io/mesh_reader.h"
#include "ivy/ivy_report.h"
#include "ivy/ivy_run.h"
#include "support/ivy_bunny.h"

namespace niwa::ivy {
namespace {

std::shared_ptr<const IvySupport> Scene(const char* name) {
  Result<std::shared_ptr<const IvySupport>> support =
      IvySupport::Prepare(IvySupportInput::Scene(name), IvySupportOptions{}, Budget{});
  EXPECT_TRUE(support.ok()) << support.status().Line();
  return *support;
}

struct Grown {
  nlohmann::json stats;
  IvyModel model;
  IvyMeshes meshes;
  glm::dvec3 up{0, 1, 0};
};

Grown GrowOn(const std::shared_ptr<const IvySupport>& support, const char* preset, int steps,
             const std::vector<std::pair<std::string, double>>& set = {}) {
  Grown g;
  IvyState state;
  EXPECT_TRUE(SetIvyPreset(preset, &state).ok());
  for (const auto& [key, value] : set)
    EXPECT_TRUE(state.params.Set(*state.params.table().Find(key), value).ok()) << key;
  state.steps = steps;
  IvyRunOptions options;
  options.build_meshes = true;
  Result<IvyRun> run = IvyRun::Start(state, support, Budget{}, options);
  EXPECT_TRUE(run.ok()) << run.status().Line();
  if (!run.ok()) return g;
  EXPECT_TRUE(run->Advance({}).ok());
  g.stats = nlohmann::json::parse(run->StatsJson());
  g.model = run->model();
  g.meshes = run->meshes();
  return g;
}

int DownwardInternodes(const IvyModel& m, double below) {
  int n = 0;
  for (const Internode& in : m.internodes) {
    const glm::dvec3 v = m.buds[static_cast<std::size_t>(in.to_bud)].pos -
                         m.buds[static_cast<std::size_t>(in.from_bud)].pos;
    n += v.y < below * glm::length(v);
  }
  return n;
}

// The mean of n·up over the leaves' blade triangles (those whose three vertex normals agree; a
// petiole's tube has two normals per triangle).
double BladeUp(const geom::TriMesh& leaves) {
  double sum = 0;
  int count = 0;
  for (std::size_t t = 0; t < leaves.triangle_count(); ++t) {
    const glm::vec3 a = leaves.normals[leaves.indices[3 * t]];
    if (a != leaves.normals[leaves.indices[3 * t + 1]] ||
        a != leaves.normals[leaves.indices[3 * t + 2]])
      continue;
    sum += static_cast<double>(a.y);
    ++count;
  }
  return count > 0 ? sum / count : 0;
}

void Print(const char* where, const char* preset, const Grown& g) {
  const nlohmann::json& s = g.stats;
  std::printf(
      "%s, %s: %d internodes, overlap %d, bend_max %.1f, up_min %.2f, down (< -0.5) %d, "
      "tendrils %d (%d internodes), leaves %d (thinned %d), cover %.3f\n",
      where, preset, s["internodes"].get<int>(), s["overlap_pairs"].get<int>(),
      s["bend_max"].get<double>(), s["up_min"].get<double>(), DownwardInternodes(g.model, -0.5),
      s["hanging"]["tendrils"].get<int>(), s["hanging"]["internodes"].get<int>(),
      s["leaves"].get<int>(), s["leaves_thinned"].get<int>(), s["leaf_cover"].get<double>());
}

TEST(IvyArtist, SpreadsDownTheFarSideWithoutReversalsOnTheBunnyAndAFacade) {
  const std::shared_ptr<const IvySupport> bunny = testing::BunnySupport(),
                                          facade = Scene("overhang");
  for (const auto& [where, support] : {std::pair{"bunny", bunny}, std::pair{"facade", facade}}) {
    const Grown paper = GrowOn(support, "paper", 150);
    const Grown artist = GrowOn(support, "artist", 150);
    Print(where, "paper", paper);
    Print(where, "artist", artist);
    const int n = artist.stats["internodes"].get<int>();
    ASSERT_GT(n, 300) << where;
    // Crowding avoidance: overlapping pairs at most 5 % of the internodes.
    EXPECT_LE(artist.stats["overlap_pairs"].get<int>(), 0.05 * n) << where;
    // No reversal: every same-axis turn at most 90°.
    EXPECT_LE(artist.stats["bend_max"].get<double>(), 90.0 + 1e-9) << where;
    // Down the far side: internodes pointing down (more than 60° below the horizontal), which
    // the paper's g_min = 0 never grows.
    EXPECT_GT(DownwardInternodes(artist.model, -0.5), 0.02 * n) << where;
    EXPECT_EQ(DownwardInternodes(paper.model, -1e-9), 0) << where;
    EXPECT_GE(paper.stats["up_min"].get<double>(), 0.0) << where;
    // The attached nodes keep §3.2's condition (a) and no internode crosses a face.
    EXPECT_EQ(artist.stats["frac_nodes_within_d"].get<double>(), 1.0) << where;
    EXPECT_EQ(artist.stats["internode_hits"].get<int>(), 0) << where;
    // The leaves cover more of the support seen from the front than paper's.
    EXPECT_GT(artist.stats["leaf_cover"].get<double>(), paper.stats["leaf_cover"].get<double>())
        << where;
  }
  // The bunny is where paper bundles (issue 31: 1,367 overlapping pairs at 150 steps).
  const Grown paper = GrowOn(bunny, "paper", 150);
  EXPECT_GT(paper.stats["overlap_pairs"].get<int>(), 0.05 * paper.stats["internodes"].get<int>());
}

TEST(IvyArtist, TendrilsHangUnderTheOverhangAndOnlyWithHang) {
  const std::shared_ptr<const IvySupport> facade = Scene("overhang");
  const Grown artist = GrowOn(facade, "artist", 150);
  const Grown off = GrowOn(facade, "artist", 150, {{"hang", 0}});
  EXPECT_GT(artist.stats["hanging"]["tendrils"].get<int>(), 0);
  EXPECT_EQ(off.stats["hanging"]["tendrils"].get<int>(), 0);
  EXPECT_EQ(off.stats["hanging"]["internodes"].get<int>(), 0);
  // Every hanging bud: at most `hang` internodes off the support, each a turn of at most 30°
  // from its parent internode toward the ground (so the tendril ends pointing down).
  int hanging = 0, down = 0;
  for (const Bud& b : artist.model.buds) {
    if (b.hang == 0) continue;
    ++hanging;
    EXPECT_LE(b.hang, 8);
    const Bud& parent = artist.model.buds[static_cast<std::size_t>(b.parent)];
    if (parent.hang > 0) {
      EXPECT_GE(glm::dot(b.dir, parent.dir), std::cos(30.0 * 3.14159265358979 / 180) - 1e-9);
    }
    down += b.dir.y < -0.5;
  }
  EXPECT_EQ(hanging, artist.stats["hanging"]["buds"].get<int>());
  EXPECT_GT(down, hanging / 3);
}

TEST(IvyArtist, LeavesAreThinnedEnlargedAndTurnedByLight) {
  EXPECT_DOUBLE_EQ(LeafLight({0, 1, 0}, {0, 1, 0}, false), 1.0);
  EXPECT_DOUBLE_EQ(LeafLight({0, 0, 1}, {0, 1, 0}, false), 0.8);
  EXPECT_DOUBLE_EQ(LeafLight({0, -1, 0}, {0, 1, 0}, true), 0.6 * 0.35);
  const std::shared_ptr<const IvySupport> wall = Scene("wall");
  const Grown lit = GrowOn(wall, "artist", 100);
  const Grown flat = GrowOn(wall, "artist", 100, {{"leaf_light", 0}});
  // The same ivy (leaf_light is a mesh row), fewer leaves.
  EXPECT_EQ(lit.stats["internodes"], flat.stats["internodes"]);
  EXPECT_EQ(flat.stats["leaves_thinned"].get<int>(), 0);
  EXPECT_GT(lit.stats["leaves_thinned"].get<int>(), 0);
  EXPECT_EQ(lit.stats["leaves"].get<int>() + lit.stats["leaves_thinned"].get<int>(),
            flat.stats["leaves"].get<int>());
  // On the wall the blades turn toward the sky (45° from the wall's normal: n·up near 0.7), flat
  // against it without light (n·up near 0).
  const double up_lit = BladeUp(lit.meshes.leaves), up_flat = BladeUp(flat.meshes.leaves);
  std::printf("wall blades: mean n.up %.3f with leaf_light 1, %.3f without\n", up_lit, up_flat);
  EXPECT_GT(up_lit, 0.5);
  EXPECT_LT(std::fabs(up_flat), 0.2);
}

TEST(IvyArtist, LeafCoverCountsTheSupportHiddenFromTheFront) {
  // A unit square support at z = 0 and a "leaf" square over its left half at z = 0.1: cover 1/2;
  // the same leaf behind it (z = -0.1) hides nothing; a leaf outside the square's bounds neither.
  geom::TriMesh support;
  support.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  support.indices = {0, 1, 2, 0, 2, 3};
  auto leaf = [](float x0, float x1, float z) {
    geom::TriMesh m;
    m.positions = {{x0, 0, z}, {x1, 0, z}, {x1, 1, z}, {x0, 1, z}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
  };
  EXPECT_NEAR(LeafCoverFront(support, leaf(0, 0.5f, 0.1f), 64), 0.5, 1e-12);
  EXPECT_EQ(LeafCoverFront(support, leaf(0, 0.5f, -0.1f), 64), 0.0);
  EXPECT_EQ(LeafCoverFront(support, leaf(2, 3, 0.1f), 64), 0.0);
  EXPECT_NEAR(LeafCoverFront(support, leaf(-1, 2, 0.1f), 64), 1.0, 1e-12);
}

}  // namespace
}  // namespace niwa::ivy
