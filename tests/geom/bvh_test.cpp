// Bvh: structure (every triangle in exactly one leaf, boxes nest and contain their triangles),
// determinism, options, and that the oracle comparison catches a wrongly skipped subtree.
#include "geom/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "geom_oracle.h"
#include "support/test_meshes.h"

namespace niwa::geom {

// Reaches into a Bvh to break it on purpose.
struct BvhTestAccess {
  static std::vector<BvhNode>& nodes(Bvh& bvh) { return bvh.nodes_; }
  static void Rewiden(Bvh& bvh) { bvh.BuildWide(); }  // the queries' wide tree from nodes_ again
};

namespace {

bool BoxContains(const Bounds3& outer, const Bounds3& inner) {
  return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
         outer.max.x >= inner.max.x && outer.max.y >= inner.max.y && outer.max.z >= inner.max.z;
}

// Walks the tree: checks nesting, leaf sizes and triangle containment; returns the depth.
int CheckSubtree(const TriMesh& mesh, const Bvh& bvh, uint32_t node, std::vector<int>* seen,
                 int max_leaf) {
  const BvhNode& n = bvh.nodes()[node];
  if (n.is_leaf()) {
    EXPECT_LE(static_cast<int>(n.count), max_leaf);
    for (uint32_t i = n.first; i < n.first + n.count; ++i) {
      uint32_t t = bvh.order()[i];
      ++(*seen)[t];
      for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(
            n.bounds.Contains(mesh.positions[mesh.indices[3 * t + static_cast<uint32_t>(k)]]))
            << "triangle " << t << " outside its leaf " << node;
    }
    return 1;
  }
  EXPECT_LT(n.first + 1, static_cast<uint32_t>(bvh.node_count()));
  EXPECT_TRUE(BoxContains(n.bounds, bvh.nodes()[n.first].bounds));
  EXPECT_TRUE(BoxContains(n.bounds, bvh.nodes()[n.first + 1].bounds));
  return 1 + std::max(CheckSubtree(mesh, bvh, n.first, seen, max_leaf),
                      CheckSubtree(mesh, bvh, n.first + 1, seen, max_leaf));
}

// Walks the wide tree below wide node w (whose box is `box`): slots fill from 0, child boxes nest
// in `box`, leaves hold their triangles; returns the depth in wide levels.
int CheckWideSubtree(const TriMesh& mesh, const Bvh& bvh, uint32_t w, const Bounds3& box,
                     std::vector<int>* seen, int max_leaf) {
  EXPECT_LT(w, bvh.wide_nodes().size());
  const BvhWideNode& n = bvh.wide_nodes()[w];
  int depth = 1, used = 0;
  bool ended = false;
  for (int k = 0; k < 4; ++k) {
    if (n.count[k] == BvhWideNode::kEmpty) {
      ended = true;
      continue;
    }
    EXPECT_FALSE(ended) << "slot " << k << " used after an empty one in wide node " << w;
    ++used;
    // Decoded (quantised) boxes are conservative, not nested: a child's triangles must lie in
    // its own box and in every ancestor's, so the walk passes down the intersection.
    Bounds3 b = n.ChildBounds(k);
    b.min = glm::max(b.min, box.min);
    b.max = glm::min(b.max, box.max);
    if (n.count[k] == 0) {
      EXPECT_GT(n.child[k], w);  // depth first: children after their parent
      depth = std::max(depth, 1 + CheckWideSubtree(mesh, bvh, n.child[k], b, seen, max_leaf));
      continue;
    }
    EXPECT_LE(static_cast<int>(n.count[k]), max_leaf);
    for (uint32_t i = n.child[k]; i < n.child[k] + n.count[k]; ++i) {
      uint32_t t = bvh.order()[i];
      ++(*seen)[t];
      for (int c = 0; c < 3; ++c)
        EXPECT_TRUE(b.Contains(mesh.positions[mesh.indices[3 * t + static_cast<uint32_t>(c)]]))
            << "triangle " << t << " outside its wide leaf";
    }
  }
  EXPECT_GE(used, w == 0 ? 1 : 2);
  return depth;
}

void CheckTree(const TriMesh& mesh, const Bvh& bvh, const BvhOptions& options = {}) {
  std::vector<int> seen(mesh.triangle_count(), 0);
  int depth = CheckSubtree(mesh, bvh, 0, &seen, options.max_leaf_triangles);
  EXPECT_EQ(depth, bvh.depth());
  for (std::size_t t = 0; t < seen.size(); ++t) ASSERT_EQ(seen[t], 1) << "triangle " << t;
  std::vector<int> wide_seen(mesh.triangle_count(), 0);
  const int wide_depth =
      CheckWideSubtree(mesh, bvh, 0, bvh.nodes()[0].bounds, &wide_seen, options.max_leaf_triangles);
  EXPECT_EQ(wide_depth, bvh.wide_depth());
  EXPECT_LE(wide_depth, depth);  // each wide level descends at least one binary level
  for (std::size_t t = 0; t < wide_seen.size(); ++t)
    ASSERT_EQ(wide_seen[t], 1) << "triangle " << t << " in the wide tree";
  EXPECT_EQ(bvh.triangle_count(), mesh.triangle_count());
  EXPECT_EQ(bvh.node_count() % 2, 1);  // root + pairs
  // Leaves of at most L triangles: at least N / L leaves, so at least 2 N / L - 1 nodes.
  const int leaves = static_cast<int>(mesh.triangle_count()) / options.max_leaf_triangles;
  EXPECT_GE(bvh.node_count(), 2 * leaves - 1);
}

void CheckStructure(const TriMesh& mesh, const BvhOptions& options = {}) {
  CheckTree(mesh, Bvh::Build(mesh, options), options);
}

// `a`'s triangles, then `b`'s (as the garden's ivy support: its ground, then its trunks).
TriMesh Joined(const TriMesh& a, const TriMesh& b) {
  TriMesh m = a;
  const auto base = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (uint32_t i : b.indices) m.indices.push_back(base + i);
  return m;
}

TEST(Bvh, StructureOnEveryTestMesh) {
  CheckStructure(MakeIcosphere(1.0f, 3));
  CheckStructure(Subdivide(MakeBox({2, 1, 3}), 3));
  CheckStructure(test::RandomSoup(3000, 7));
  CheckStructure(test::ThinDegenerateMesh(3));
  CheckStructure(MakePlane(4, 4, 30, 30), BvhOptions{8, 1, false});
  CheckStructure(test::RandomSoup(3000, 8), BvhOptions{16, 4, true});
  CheckStructure(MakePlane(4, 4, 30, 30), BvhOptions{2, 16, false});
}

TEST(Bvh, EmptyAndSingleTriangle) {
  TriMesh empty;
  Bvh e = Bvh::Build(empty);
  EXPECT_TRUE(e.empty());
  EXPECT_EQ(e.node_count(), 0);
  EXPECT_EQ(e.depth(), 0);
  EXPECT_FALSE(ClosestPoint(empty, e, glm::vec3(0), 1e9f).found);
  EXPECT_FALSE(SegmentHits(empty, e, glm::vec3(-1), glm::vec3(1)));
  TriMesh one;
  one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.indices = {0, 1, 2};
  Bvh b = Bvh::Build(one);
  EXPECT_EQ(b.node_count(), 1);
  EXPECT_EQ(b.depth(), 1);
}

TEST(Bvh, AllCentroidsEqualStillGivesSmallLeaves) {
  // 200 copies of one triangle: no SAH split exists, so the build halves the range.
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (int i = 0; i < 200; ++i) m.indices.insert(m.indices.end(), {0u, 1u, 2u});
  CheckStructure(m);
  Bvh bvh = Bvh::Build(m);
  ClosestHit h = ClosestPoint(m, bvh, glm::vec3(0.2f, 0.2f, 1.0f), 5.0f);
  ASSERT_TRUE(h.found);
  EXPECT_EQ(h.triangle, 0u);  // all tie: the lowest index wins
  RayHit r = FirstHit(m, bvh, glm::vec3(0.2f, 0.2f, 1.0f), glm::vec3(0, 0, -1), 5.0f);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.triangle, 0u);
}

TEST(Bvh, SameMeshSameTreeBitForBit) {
  TriMesh m = test::RandomSoup(5000, 11);
  Bvh a = Bvh::Build(m), b = Bvh::Build(m);
  ASSERT_EQ(a.node_count(), b.node_count());
  EXPECT_EQ(a.depth(), b.depth());
  EXPECT_EQ(a.order(), b.order());
  EXPECT_EQ(0, std::memcmp(a.nodes().data(), b.nodes().data(), a.nodes().size() * sizeof(BvhNode)));
}

TEST(Bvh, OptionsAreClamped) {
  TriMesh m = test::RandomSoup(500, 2);
  Bvh wild = Bvh::Build(m, BvhOptions{-5, 1000, false});
  Bvh clamped = Bvh::Build(m, BvhOptions{2, 16, false});
  EXPECT_EQ(wild.order(), clamped.order());
  EXPECT_EQ(wild.node_count(), clamped.node_count());
}

// The oracle comparison must be able to fail: move one subtree's box to a point far away (so the
// traversal skips that subtree) and the BVH answers must now differ from the linear ones.
TEST(Bvh, OracleCatchesASkippedSubtree) {
  TriMesh m = MakeIcosphere(1.0f, 3);
  Bvh bvh = Bvh::Build(m);
  test::OracleCounts ok = test::CompareWithLinear(m, bvh, 2000, 5);
  EXPECT_EQ(ok.closest_mismatch + ok.ray_mismatch + ok.segment_mismatch, 0) << ok.first_mismatch;
  // Node 2 is the root's right child: half the sphere. Its box moved far away, the traversal
  // never enters it.
  std::vector<BvhNode>& nodes = BvhTestAccess::nodes(bvh);
  ASSERT_GE(nodes.size(), 3u);
  nodes[2].bounds = Bounds3{glm::vec3(50.0f), glm::vec3(50.0f)};
  BvhTestAccess::Rewiden(bvh);
  test::OracleCounts bad = test::CompareWithLinear(m, bvh, 2000, 5);
  EXPECT_GT(bad.closest_mismatch, 0);
  EXPECT_GT(bad.ray_mismatch, 0);
  EXPECT_GT(bad.segment_mismatch, 0);
}

TEST(Bvh, AllAxesTreesAgreeWithLinearToo) {
  for (const test::OracleCase& c : test::OracleMeshes()) {
    Bvh bvh = Bvh::Build(c.mesh, BvhOptions{16, 4, true});
    test::OracleCounts counts = test::CompareWithLinear(c.mesh, bvh, 500, 300);
    EXPECT_EQ(counts.closest_mismatch + counts.ray_mismatch + counts.segment_mismatch, 0)
        << c.name << ": " << counts.first_mismatch;
  }
}

// Bvh::Join: a tree over a ground of shared edges (closest-point ties between its triangles) and a
// soup and a sphere standing on it is a valid tree of the joined mesh, and every query answers as
// the linear twins (so as Build over the joined mesh: the same triangle, the same bits).
TEST(Bvh, JoinedTreesAnswerAsTheJoinedMesh) {
  const TriMesh ground = MakePlane(4, 4, 24, 24);
  const TriMesh sphere = MakeIcosphere(0.5f, 2);
  const TriMesh soup = test::RandomSoup(500, 3);
  const Bvh ground_bvh = Bvh::Build(ground);
  for (const TriMesh* part : {&sphere, &soup}) {
    const TriMesh mesh = Joined(ground, *part);
    const Bvh joined = Bvh::Join(ground_bvh, Bvh::Build(*part));
    CheckTree(mesh, joined);
    EXPECT_EQ(joined.depth(), 1 + std::max(ground_bvh.depth(), Bvh::Build(*part).depth()));
    const test::OracleCounts counts = test::CompareWithLinear(mesh, joined, 400, 200);
    EXPECT_EQ(counts.closest_mismatch + counts.ray_mismatch + counts.segment_mismatch, 0)
        << counts.first_mismatch;
  }
  // An empty part joins to the other tree as it is.
  const Bvh none = Bvh::Build(TriMesh{});
  EXPECT_EQ(Bvh::Join(ground_bvh, none).nodes().size(), ground_bvh.nodes().size());
  EXPECT_EQ(Bvh::Join(none, ground_bvh).order(), ground_bvh.order());
}

TEST(Bvh, DepthAndNodeCountStaySmallOnALargeWall) {
  TriMesh wall = Subdivide(MakePlane(2.0f, 1.0f, 2, 1), 6);  // 16384 triangles
  Bvh bvh = Bvh::Build(wall);
  std::printf("wall 16384 tris: %d nodes, depth %d; wide: %zu nodes, depth %d\n", bvh.node_count(),
              bvh.depth(), bvh.wide_nodes().size(), bvh.wide_depth());
  EXPECT_LE(2 * bvh.wide_depth(), bvh.depth() + 2);  // the wide tree: about half the depth
  EXPECT_LE(bvh.depth(), 40);
  EXPECT_LE(bvh.node_count(), static_cast<int>(wall.triangle_count()));
}

}  // namespace
}  // namespace niwa::geom
