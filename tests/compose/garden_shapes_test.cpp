// The garden's shared shapes (compose/garden_shapes, GardenRun::ExportTrees): ShareShapes against a
// brute-force twin (the farthest-point picks and the nearest assignment recomputed from the
// definition), and a shaded garden's .glb keeping at most `shapes` meshes a variant with every tree
// drawn, each shared shape turned to lean the tree's own way.
#include "compose/garden_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

#include "compose/garden_run.h"
#include "math/det_math.h"

namespace niwa::compose {
namespace {

// A fixed pseudo-random set (an LCG: the test's own numbers, the same everywhere).
std::vector<TreeShape> Shapes(int count, uint64_t seed) {
  uint64_t x = seed;
  const auto next = [&x]() {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(x >> 11) / 9007199254740992.0;
  };
  std::vector<TreeShape> out;
  for (int i = 0; i < count; ++i) out.push_back({4 + 3 * next(), 1 + 2 * next(), 0.5 * next()});
  return out;
}

TEST(GardenShapes, ShareShapesIsItsBruteForceTwin) {
  for (int count : {1, 5, 17, 60}) {
    for (int n : {1, 2, 4, 8, 64}) {
      const std::vector<TreeShape> s = Shapes(count, 1000 + count);
      const std::vector<int> rep_of = ShareShapes(s, n);
      ASSERT_EQ(rep_of.size(), s.size());
      if (count <= n) {
        for (int i = 0; i < count; ++i) EXPECT_EQ(rep_of[i], i);
        continue;
      }
      // The twin: the picks from the definition, O(n * count²).
      double mh = 0, mr = 0, ml = 0;
      for (const TreeShape& t : s) mh += t.height, mr += t.reach, ml += t.lean;
      const TreeShape mean{mh / count, mr / count, ml / count};
      const auto d = [&](const TreeShape& a, const TreeShape& b) {
        const double dh = (a.height - b.height) / mean.height,
                     dr = (a.reach - b.reach) / mean.reach, dl = (a.lean - b.lean) / mean.reach;
        return std::sqrt(dh * dh + dr * dr + dl * dl);
      };
      std::vector<int> picks = {0};
      for (int i = 1; i < count; ++i)
        if (d(s[i], mean) < d(s[picks[0]], mean)) picks[0] = i;
      while (static_cast<int>(picks.size()) < n) {
        int far = -1;
        double far_d = -1;
        for (int i = 0; i < count; ++i) {
          double nearest = 1e300;
          for (int p : picks) nearest = std::min(nearest, d(s[i], s[p]));
          if (nearest > far_d) far = i, far_d = nearest;
        }
        picks.push_back(far);
      }
      std::map<int, int> used;
      for (int i = 0; i < count; ++i) {
        ++used[rep_of[i]];
        bool is_pick = false;
        for (int p : picks) is_pick = is_pick || p == i;
        if (is_pick) {
          EXPECT_EQ(rep_of[i], i) << count << " " << n << " " << i;
          continue;
        }
        int best = picks[0];
        for (int p : picks)
          if (d(s[i], s[p]) < d(s[i], s[best])) best = p;
        EXPECT_EQ(rep_of[i], best) << count << " " << n << " " << i;
      }
      EXPECT_EQ(static_cast<int>(used.size()), n) << count << " " << n;
    }
  }
  // Identical shapes need one representative, whatever n.
  const std::vector<int> same = ShareShapes(std::vector<TreeShape>(6, {5, 2, 0.1}), 3);
  for (int r : same) EXPECT_EQ(r, same[0]);
}

// A dense garden of one species and one variant, shade on: every tree has a neighbour, so every
// tree is its own growth.
GardenState DenseGarden(int shapes) {
  GardenState s = DefaultGardenState();
  s.default_layout = false;
  s.objects.clear();
  s.plants.clear();
  s.ivy_on.clear();
  s.mix = {{"sakura", 1}};
  s.ground = GroundKind::kFlat;
  EXPECT_TRUE(s.params.Set(GardenParam::kSize, 16).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kGroundRes, 16).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kYears, 3).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kDensity, 0.05).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kSpacing, 2).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kVariants, 1).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMaxTriangles, 300).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kShapes, shapes).ok());
  return s;
}

TEST(GardenShapes, AShadedGardensGlbKeepsAtMostShapesMeshesAVariant) {
  Result<GardenRun> exact = GardenRun::Start(DenseGarden(0), Budget{});
  ASSERT_TRUE(exact.ok()) << exact.status().Line();
  ASSERT_TRUE(exact->Advance({}).ok());
  const std::size_t trees = exact->planting().trees.size();
  ASSERT_GE(trees, 6u);
  ASSERT_EQ(exact->groups().size(), trees);  // each tree grown with its neighbours' shade
  const auto tree_meshes = [](const gltf::Document& doc, std::size_t* instances) {
    int meshes = 0;
    *instances = 0;
    for (const gltf::Node& n : doc.nodes) {
      if (n.instance_count() == 0) continue;
      ++meshes;
      *instances += n.instance_count();
    }
    return meshes;
  };
  // shapes 0: every group draws its own tree (the .glb as before shapes).
  const std::vector<std::vector<GardenExportTree>> own = exact->ExportTrees();
  for (std::size_t k = 0; k < own.size(); ++k) {
    ASSERT_EQ(own[k].size(), 1u);
    EXPECT_EQ(exact->group_of(own[k][0].tree), static_cast<int>(k));
    EXPECT_EQ(own[k][0].scale, 1.0);
  }
  std::size_t drawn = 0;

  Result<GardenRun> shared = GardenRun::Start(DenseGarden(2), Budget{});
  ASSERT_TRUE(shared.ok());
  ASSERT_TRUE(shared->Advance({}).ok());
  ASSERT_EQ(shared->planting().trees.size(), trees);
  Result<gltf::Document> doc = shared->Document();
  ASSERT_TRUE(doc.ok());
  EXPECT_EQ(tree_meshes(*doc, &drawn), 2);
  EXPECT_EQ(drawn, trees);  // every tree still drawn
  Result<Estimate> estimate = shared->ExportEstimate("glb");
  Result<Estimate> exact_estimate = exact->ExportEstimate("glb");
  ASSERT_TRUE(estimate.ok() && exact_estimate.ok());
  EXPECT_LT(estimate->memory_bytes * 2, exact_estimate->memory_bytes);

  // Each tree drawn with another's shape is turned so that the shape's lean points along the
  // tree's own (its leaf centroid from its trunk, in the garden's frame), scaled within 25 %.
  const std::vector<std::vector<GardenExportTree>> by_mesh = shared->ExportTrees();
  int turned = 0;
  for (std::size_t k = 0; k < by_mesh.size(); ++k) {
    const Tree& shape = shared->groups()[k].tree();
    glm::dvec3 sum(0.0);
    double n = 0;
    for (const Branch& b : shape.branches)
      for (const Leaf& leaf : b.leaves)
        if (b.alive) sum += glm::dvec3(b.nodes[leaf.node]), n += 1;
    const glm::dvec3 local = sum / n / 100.0;
    for (const GardenExportTree& e : by_mesh[k]) {
      EXPECT_GE(e.scale, 0.8 - 1e-12);
      EXPECT_LE(e.scale, 1.25 + 1e-12);
      if (shared->group_of(e.tree) == static_cast<int>(k)) {
        EXPECT_EQ(e.yaw_deg, shared->planting().trees[e.tree].rot);
        continue;
      }
      const PlacedTree& p = shared->planting().trees[e.tree];
      const glm::dvec3 c = shared->CrownCentroid(e.tree);
      const double own_dir = std::atan2(c.x - p.x, c.z - p.z);
      const double a = e.yaw_deg * det::kPi / 180.0;
      const double x = std::cos(a) * local.x + std::sin(a) * local.z;
      const double z = -std::sin(a) * local.x + std::cos(a) * local.z;
      const double drawn_dir = std::atan2(x, z);
      EXPECT_NEAR(std::remainder(drawn_dir - own_dir, 2 * det::kPi), 0.0, 1e-6) << e.tree;
      ++turned;
    }
  }
  EXPECT_EQ(turned, static_cast<int>(trees) - 2);
}

}  // namespace
}  // namespace niwa::compose
