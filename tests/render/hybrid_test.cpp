// Unit tests of hybrid rendering (thesis ch. 4): eq. 4.1 on known viewports, threshold and
// hysteresis, leaf branches, card planes, grouping, atlas, eq. 4.2 colours, counts, sakura goal.
#include "render/hybrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "math/rotation.h"
#include "support/grow.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"

namespace niwa {
namespace {

constexpr float kRightAngle = 1.5707963f;  // 90° field of view: tan(fov/2) = 1

// A hand-made branch: nodes in cm; cross-section π r² gives radius r (cm).
Branch MakeBranch(int id, std::vector<glm::vec3> nodes, float radius_cm) {
  Branch b{};
  b.id = id;
  b.parent = -1;
  b.parent_node = 0;
  b.year = 1;
  b.alive = true;
  b.nodes = std::move(nodes);
  b.bud_direction = glm::vec3(0, 1, 0);
  b.azimuth = glm::vec3(1, 0, 0);
  b.cross_section = kPi * radius_cm * radius_cm;
  return b;
}

Tree MakeTree(std::vector<Branch> branches) {
  Tree tree;
  tree.preset = "test";
  for (std::size_t i = 0; i < branches.size(); ++i) branches[i].id = static_cast<int>(i);
  tree.branches = std::move(branches);
  return tree;
}

// Camera on the +z axis looking at the origin, 90° vertical field of view.
RenderCamera CameraAt(float distance_m, int width = 512, int height = 512) {
  RenderCamera c;
  c.eye = glm::vec3(0, 0, distance_m);
  c.target = glm::vec3(0, 0, 0);
  c.fov_y = kRightAngle;
  c.width = width;
  c.height = height;
  return c;
}

Tree GrowForHybrid(const std::string& preset, int years) { return testing::GrowPreset(preset, years); }

TEST(Eq41, ScreenWidthByHand) {
  // d = 0.02 m, R = 10 m, 512 × 512: D = 0.02 · 512 / 20 = 0.512 px.
  EXPECT_FLOAT_EQ(ScreenWidthPx(0.02f, 10.0f, 512, 512), 0.512f);
  // min(H, W) is used: 800 × 300 → 0.02 · 300 / 20 = 0.3 px.
  EXPECT_FLOAT_EQ(ScreenWidthPx(0.02f, 10.0f, 800, 300), 0.3f);
}

TEST(Eq41, EquivalentRadiusIsTheViewHalfExtentAtTheDepth) {
  // fov 90°: at depth 10 m the view is 20 m high, so R = 10 m on a square viewport; on a
  // 256 × 512 viewport (narrow) the shorter side spans 10 m, R = 5 m.
  EXPECT_NEAR(CameraAt(10).EquivalentRadius(10), 10.0f, 1e-4f);
  EXPECT_NEAR(CameraAt(10, 256, 512).EquivalentRadius(10), 5.0f, 1e-4f);
  EXPECT_NEAR(CameraAt(10).PixelsPerUnit(10), 25.6f, 1e-4f);  // 512 px / 20 m
}

TEST(Eq41, SelectionOnAHandBuiltTree) {
  // Branch 0: 2 cm thick (r = 1 cm) centred on the origin, camera 10 m away (depth 10):
  //   D = 0.02 m · 512 / (2 · 10 m) = 0.512 px → line.
  // Branch 1: 20 cm thick (r = 10 cm), same place: D = 0.2 · 512 / 20 = 5.12 px → card (> 4).
  Tree tree = MakeTree({MakeBranch(0, {{-50, 0, 0}, {0, 0, 0}, {50, 0, 0}}, 1.0f),
                        MakeBranch(0, {{0, -50, 0}, {0, 0, 0}, {0, 50, 0}}, 10.0f)});
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  HybridSelection s = SelectHybrid(tree, scene, CameraAt(10), nullptr);
  EXPECT_NEAR(s.screen_width_px[0], 0.512f, 1e-4f);
  EXPECT_NEAR(s.screen_width_px[1], 5.12f, 1e-4f);
  EXPECT_EQ(s.draw[0], BranchDraw::kLine);
  EXPECT_EQ(s.draw[1], BranchDraw::kCard);
  // Twice as close (depth 5 m): widths double; 1.024 px is still a line.
  s = SelectHybrid(tree, scene, CameraAt(5), nullptr);
  EXPECT_NEAR(s.screen_width_px[0], 1.024f, 1e-4f);
  EXPECT_EQ(s.draw[0], BranchDraw::kLine);
  // A wider viewport of the same height shows the same pixel widths (the fov is vertical).
  s = SelectHybrid(tree, scene, CameraAt(10, 1024, 512), nullptr);
  EXPECT_NEAR(s.screen_width_px[1], 5.12f, 1e-4f);
  // A lower threshold turns branch 0 into a card.
  RenderOptions low;
  low.threshold_px = 0.5f;
  HybridScene low_scene = BuildHybridScene(tree, low);
  EXPECT_EQ(SelectHybrid(tree, low_scene, CameraAt(10), nullptr).draw[0], BranchDraw::kCard);
}

TEST(Eq41, DeadBranchesAreHidden) {
  Tree tree = MakeTree({MakeBranch(0, {{0, 0, 0}, {0, 10, 0}}, 1.0f)});
  tree.branches[0].alive = false;
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  EXPECT_EQ(SelectHybrid(tree, scene, CameraAt(10), nullptr).draw[0], BranchDraw::kHidden);
}

TEST(Hysteresis, ABranchZoomedThroughTheThresholdSwitchesOnce) {
  // r = 1 cm, d = 0.02 m; at depth z (fov 90°, 512 px) D = 0.02 · 512 / (2z) = 5.12 / z.
  Tree tree = MakeTree({MakeBranch(0, {{0, -10, 0}, {0, 10, 0}}, 1.0f)});
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});  // t = 4, h = 0.25: 3 and 5 px
  int switches_with = 0, switches_without = 0;
  HybridSelection previous;
  BranchDraw last_without = BranchDraw::kHidden;
  for (int pass = 0; pass < 2; ++pass) {  // zoom out then back in
    for (int k = 0; k <= 100; ++k) {
      int step = pass == 0 ? k : 100 - k;
      // D sweeps 6 → 2 px with ±0.6 px jitter (hand-shake while zooming).
      float d_px = 6.0f - 0.04f * static_cast<float>(step) + 0.6f * ((step % 2) ? 1.0f : -1.0f);
      RenderCamera camera = CameraAt(5.12f / d_px);
      HybridSelection now =
          SelectHybrid(tree, scene, camera, previous.draw.empty() ? nullptr : &previous);
      if (!previous.draw.empty() && now.draw[0] != previous.draw[0]) ++switches_with;
      BranchDraw plain = SelectHybrid(tree, scene, camera, nullptr).draw[0];
      if (last_without != BranchDraw::kHidden && plain != last_without) ++switches_without;
      last_without = plain;
      previous = now;
    }
  }
  EXPECT_EQ(switches_with, 2);     // once out (card → line), once back in (line → card)
  EXPECT_GT(switches_without, 6);  // without hysteresis the jitter makes it flicker
}

TEST(Hysteresis, ThresholdsAreTimesOneMinusAndOnePlusH) {
  Tree tree = MakeTree({MakeBranch(0, {{0, -10, 0}, {0, 10, 0}}, 1.0f)});
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  HybridSelection card, line;
  card.draw = {BranchDraw::kCard};
  line.draw = {BranchDraw::kLine};
  // D = 3.2 px (depth 1.6 m): a card stays a card (>= 3), a line stays a line (<= 5).
  EXPECT_EQ(SelectHybrid(tree, scene, CameraAt(1.6f), &card).draw[0], BranchDraw::kCard);
  EXPECT_EQ(SelectHybrid(tree, scene, CameraAt(1.6f), &line).draw[0], BranchDraw::kLine);
  // D = 2.56 px (depth 2 m): a card becomes a line; D = 5.12 px (depth 1 m): a line a card.
  EXPECT_EQ(SelectHybrid(tree, scene, CameraAt(2.0f), &card).draw[0], BranchDraw::kLine);
  EXPECT_EQ(SelectHybrid(tree, scene, CameraAt(1.0f), &line).draw[0], BranchDraw::kCard);
  // A previous selection with more branches than the tree is ignored (plain threshold: line).
  HybridSelection other;
  other.draw = {BranchDraw::kCard, BranchDraw::kCard};
  EXPECT_EQ(SelectHybrid(tree, scene, CameraAt(1.6f), &other).draw[0], BranchDraw::kLine);
}

TEST(Hysteresis, AYearOlderTreeKeepsTheChoicesOfItsOldBranches) {
  // Year 1: one branch; year 2: the same branch (id 0) and a new one (id 1), both 3.2 px wide.
  Tree young = MakeTree({MakeBranch(0, {{0, -10, 0}, {0, 10, 0}}, 1.0f)});
  Tree older = MakeTree({MakeBranch(0, {{0, -10, 0}, {0, 10, 0}}, 1.0f),
                         MakeBranch(0, {{5, -10, 0}, {5, 10, 0}}, 1.0f)});
  HybridScene scene = BuildHybridScene(older, RenderOptions{});
  HybridSelection last;
  last.draw = {BranchDraw::kCard};  // young tree's frame: branch 0 was a card
  ASSERT_EQ(young.branches.size(), last.draw.size());
  HybridSelection now = SelectHybrid(older, scene, CameraAt(1.6f), &last);
  EXPECT_EQ(now.draw[0], BranchDraw::kCard);  // 3.2 px >= 3: stays a card
  EXPECT_EQ(now.draw[1], BranchDraw::kLine);  // new: 3.2 px <= 4, plain threshold
}

TEST(Leaves, LeafBranchesAreAlwaysCardsInBranchMode) {
  Branch thin = MakeBranch(0, {{0, 0, 0}, {0, 5, 0}, {0, 10, 0}}, 0.05f);
  thin.leaves.push_back({1, glm::vec3(1, 0, 0)});
  Tree tree = MakeTree({thin, MakeBranch(0, {{0, 0, 0}, {0, 5, 0}, {0, 10, 0}}, 0.05f)});
  RenderOptions options;
  options.leaf_mode = LeafMode::kBranchCards;
  HybridScene scene = BuildHybridScene(tree, options);
  HybridSelection s = SelectHybrid(tree, scene, CameraAt(100), nullptr);  // D ≈ 0.003 px
  EXPECT_EQ(s.draw[0], BranchDraw::kCard);
  EXPECT_EQ(s.draw[1], BranchDraw::kLine);
  // The card covers the leaf: 6 cm long from node 1 (0, 5 cm) along +x, 1.5 cm half width.
  for (const CardPlane& p : scene.frames[0].planes) {
    glm::vec3 leaf_tip = glm::vec3(0.06f, 0.05f, 0.0f) - scene.frames[0].origin;
    EXPECT_LE(p.u0, glm::dot(leaf_tip, p.right) + 1e-6f);
    EXPECT_GE(p.u1, glm::dot(leaf_tip, p.right) - 1e-6f);
  }
  RenderStats stats = CountHybrid(scene, s);
  EXPECT_EQ(stats.leaf_polygons, 2);  // table 4.1 counts leaf-bearing cards as leaf polygons
  EXPECT_EQ(stats.branch_polygons, 0);
  EXPECT_EQ(stats.lines, 1);
}

TEST(Leaves, ClusterModeCoversEveryLeafBranchWithACluster) {
  Tree tree = GrowForHybrid("sakura-thesis", 6);
  RenderOptions options;  // kClusterCards
  HybridScene scene = BuildHybridScene(tree, options);
  int leaf_branches = 0;
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    const Branch& b = tree.branches[i];
    if (!b.alive || (b.leaves.empty() && b.flowers.empty())) continue;
    ++leaf_branches;
    int c = scene.cluster_of_branch[i];
    ASSERT_GE(c, 0);
    const LeafCluster& cluster = scene.clusters[static_cast<std::size_t>(c)];
    // Every leaf base lies in the rectangle of every plane of its cluster.
    for (const Leaf& leaf : b.leaves) {
      glm::vec3 p = b.nodes[static_cast<std::size_t>(leaf.node)] * 0.01f - cluster.origin;
      for (const CardPlane& plane : cluster.planes) {
        EXPECT_LE(plane.u0, glm::dot(p, plane.right) + 1e-5f);
        EXPECT_GE(plane.u1, glm::dot(p, plane.right) - 1e-5f);
        EXPECT_LE(plane.v0, glm::dot(p, plane.up) + 1e-5f);
        EXPECT_GE(plane.v1, glm::dot(p, plane.up) - 1e-5f);
      }
    }
  }
  ASSERT_GT(leaf_branches, 10);
  EXPECT_GT(scene.clusters.size(), 1u);
  EXPECT_LT(scene.clusters.size(), static_cast<std::size_t>(leaf_branches));  // merged
  EXPECT_LE(scene.clusters.size(), 6u * 6u * 6u);
}

TEST(Planes, PlaneZeroHoldsTheBendAndPlanesRotateAboutB) {
  // Bent in the xy plane: plane 0 must be that plane (normal ±z), b = unit base→tip.
  Tree tree = MakeTree({MakeBranch(0, {{0, 0, 0}, {0, 10, 0}, {5, 20, 0}}, 0.5f)});
  RenderOptions options;
  options.card_planes = 3;
  HybridScene scene = BuildHybridScene(tree, options);
  const CardFrame& f = scene.frames[0];
  ASSERT_EQ(f.planes.size(), 3u);
  glm::vec3 b = glm::normalize(glm::vec3(5, 20, 0));
  EXPECT_NEAR(glm::dot(f.b, b), 1.0f, 1e-6f);
  EXPECT_NEAR(std::fabs(f.planes[0].normal.z), 1.0f, 1e-5f);
  for (std::size_t k = 0; k < 3; ++k) {
    const CardPlane& p = f.planes[k];
    EXPECT_NEAR(glm::dot(p.up, b), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(p.normal, b), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(p.right, p.normal), 0.0f, 1e-5f);
    // 60° apart about b.
    EXPECT_NEAR(std::fabs(glm::dot(p.normal, f.planes[(k + 1) % 3].normal)), 0.5f, 1e-4f);
    // The rectangle covers every node with the radius.
    for (const glm::vec3& node : tree.branches[0].nodes) {
      glm::vec3 q = node * 0.01f - f.origin;
      EXPECT_LE(p.u0, glm::dot(q, p.right) - 0.005f + 1e-6f);
      EXPECT_GE(p.u1, glm::dot(q, p.right) + 0.005f - 1e-6f);
      EXPECT_LE(p.v0, glm::dot(q, p.up) - 0.005f + 1e-6f);
      EXPECT_GE(p.v1, glm::dot(q, p.up) + 0.005f - 1e-6f);
    }
  }
}

TEST(Planes, ChooseCardPlaneTakesTheNormalClosestToTheView) {
  std::vector<CardPlane> planes(2);
  planes[0].normal = glm::vec3(0, 0, 1);
  planes[1].normal = glm::vec3(1, 0, 0);
  EXPECT_EQ(ChooseCardPlane(planes, glm::vec3(0, 0, -1)), 0);
  EXPECT_EQ(ChooseCardPlane(planes, glm::vec3(0.9f, 0, 0.3f)), 1);
  EXPECT_EQ(ChooseCardPlane(planes, glm::vec3(-0.9f, 0, 0.3f)), 1);  // double-sided
  EXPECT_EQ(ChooseCardPlane(planes, glm::vec3(0.3f, -1, 0.5f)), 0);
}

TEST(Grouping, IdenticalBranchesShareATextureDifferentOnesDoNot) {
  std::vector<glm::vec3> shape = {{0, 0, 0}, {0, 10, 0}, {2, 19, 0}, {5, 27, 0}};
  std::vector<glm::vec3> moved, turned, longer, more_nodes;
  for (const glm::vec3& p : shape) {
    moved.push_back(p + glm::vec3(100, 40, -30));
    turned.push_back(glm::vec3(p.z, p.y, -p.x) + glm::vec3(-50, 0, 0));  // 90° about y
    longer.push_back(p * 2.0f);
  }
  more_nodes = {{0, 0, 0}, {0, 5, 0}, {0, 10, 0}, {2, 19, 0}, {5, 27, 0}};
  std::vector<glm::vec3> straight = {{0, 0, 0}, {0, 9, 0}, {0, 18, 0}, {0, 27.6f, 0}};
  Tree tree =
      MakeTree({MakeBranch(0, shape, 0.5f), MakeBranch(0, moved, 0.5f), MakeBranch(0, turned, 0.5f),
                MakeBranch(0, longer, 0.5f), MakeBranch(0, shape, 1.5f),
                MakeBranch(0, more_nodes, 0.5f), MakeBranch(0, straight, 0.5f)});
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  const std::vector<int>& g = scene.group_of_branch;
  EXPECT_EQ(g[0], g[1]);  // identical, moved
  EXPECT_EQ(g[0], g[2]);  // identical, turned
  EXPECT_NE(g[0], g[3]);  // twice as long
  EXPECT_NE(g[0], g[4]);  // three times as thick
  EXPECT_NE(g[0], g[5]);  // one more node
  EXPECT_NE(g[0], g[6]);  // straight (bend 0° against about 21°)
  EXPECT_EQ(scene.group_representative[static_cast<std::size_t>(g[0])], 0);
  EXPECT_EQ(scene.group_size[static_cast<std::size_t>(g[0])], 3);
  // The moved copy's card is the representative's card moved; the turned one's is turned.
  for (int k = 0; k < 2; ++k) {
    glm::vec3 rep[4], copy[4], turn[4];
    CardCorners(scene, 0, k, rep);
    CardCorners(scene, 1, k, copy);
    CardCorners(scene, 2, k, turn);
    for (int c = 0; c < 4; ++c) {
      glm::vec3 d = copy[c] - rep[c] - glm::vec3(1.0f, 0.4f, -0.3f);
      EXPECT_LT(glm::length(d), 1e-5f);
      glm::vec3 t = glm::vec3(rep[c].z, rep[c].y, -rep[c].x) + glm::vec3(-0.5f, 0, 0);
      EXPECT_LT(glm::length(turn[c] - t), 1e-5f);
    }
  }
  // The matrix maps the representative's frame onto the member's: origin and b.
  float m[16];
  GroupToBranchMatrix(scene, 1, m);
  EXPECT_NEAR(m[12], 1.0f, 1e-6f);
  EXPECT_NEAR(m[13], 0.4f, 1e-6f);
  EXPECT_NEAR(m[14], -0.3f, 1e-6f);
  EXPECT_NEAR(glm::dot(glm::vec3(m[4], m[5], m[6]), scene.frames[1].b), 1.0f, 1e-5f);
}

TEST(Eq42, LineColoursByHand) {
  const glm::vec3 cb(0.5f, 0.4f, 0.2f), white(1.0f);
  // θ = 90°: C = C_b (0.8 · 1 + 0.2) = C_b.
  glm::vec3 c = LineColor(cb, white, {0, 1, 0}, {1, 0, 0}, 0.8f, 0.2f);
  EXPECT_NEAR(c.r, 0.5f, 1e-6f);
  EXPECT_NEAR(c.g, 0.4f, 1e-6f);
  EXPECT_NEAR(c.b, 0.2f, 1e-6f);
  // b parallel to L: sin θ = 0, only ambient: 0.2 C_b = (0.1, 0.08, 0.04).
  c = LineColor(cb, white, {0, 1, 0}, {0, 3, 0}, 0.8f, 0.2f);
  EXPECT_NEAR(c.r, 0.1f, 1e-6f);
  EXPECT_NEAR(c.g, 0.08f, 1e-6f);
  EXPECT_NEAR(c.b, 0.04f, 1e-6f);
  // θ = 45° with |L| = √2: |b||L| sin θ = 1 · √2 · √2/2 = 1 → C_b again.
  c = LineColor(cb, white, {0, 1, 0}, {1, 1, 0}, 0.8f, 0.2f);
  EXPECT_NEAR(c.g, 0.4f, 1e-6f);
  // |b| = 2, θ = 90°: 0.8 · 2 + 0.2 = 1.8 → (0.9, 0.72, 0.36); coloured light C_L = (1, 0.5, 0):
  // factors (1.8, 1.0, 0.2) → (0.9, 0.4, 0.04).
  c = LineColor(cb, {1.0f, 0.5f, 0.0f}, {0, 2, 0}, {0, 0, 1}, 0.8f, 0.2f);
  EXPECT_NEAR(c.r, 0.9f, 1e-6f);
  EXPECT_NEAR(c.g, 0.4f, 1e-6f);
  EXPECT_NEAR(c.b, 0.04f, 1e-6f);
  // Clamped to 1.
  c = LineColor(white, white, {0, 2, 0}, {0, 0, 1}, 0.8f, 0.2f);
  EXPECT_FLOAT_EQ(c.r, 1.0f);
}

TEST(Camera, OrbitViewMatchesThePage) {
  OrbitView v;
  v.yaw = 0;
  v.pitch = 0;
  v.distance = 4;
  v.target = glm::vec3(1, 2, 3);
  RenderCamera c = CameraFromOrbit(v, 512, 512);
  EXPECT_NEAR(glm::length(c.eye - glm::vec3(1, 2, 7)), 0.0f, 1e-6f);
  EXPECT_NEAR(c.Depth(v.target), 4.0f, 1e-6f);
  EXPECT_NEAR(c.Distance(glm::vec3(1, 5, 7)), 3.0f, 1e-6f);
  // camera.js frame(): 2 × 2 × 2 box, r = √3, distance = √3 / sin(22.5°) · 1.12.
  Bounds3 box;
  box.Add({0, 0, 0});
  box.Add({2, 2, 2});
  OrbitView framed = FrameOrbitView(box);
  EXPECT_NEAR(framed.distance, 1.7320508f / 0.38268343f * 1.12f, 1e-4f);
  EXPECT_NEAR(framed.target.y, 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(framed.yaw, 0.6f);
  EXPECT_FLOAT_EQ(framed.pitch, 0.25f);
  OrbitView parsed;
  const Status ok = ParseOrbitView("0.6,0.25,5.5,0.3,1.5,-0.01", &parsed);
  ASSERT_TRUE(ok.ok()) << ok.Line();
  EXPECT_FLOAT_EQ(parsed.distance, 5.5f);
  EXPECT_EQ(FormatOrbitView(parsed), "0.6,0.25,5.5,0.3,1.5,-0.01");
  EXPECT_FALSE(ParseOrbitView("0.6,0.25,5.5", &parsed).ok());
  const Status pitch = ParseOrbitView("0.6,2,5.5,0,0,0", &parsed);
  EXPECT_EQ(pitch.field(), "cam");  // the state field, never a flag
  EXPECT_NE(pitch.message().find("pitch"), std::string::npos);
  const Status distance = ParseOrbitView("0.6,0.2,500,0,0,0", &parsed);
  EXPECT_EQ(distance.field(), "cam");
  EXPECT_NE(distance.message().find("distance"), std::string::npos);
  EXPECT_FLOAT_EQ(parsed.distance, 5.5f);  // unchanged by the refused texts
}

TEST(Options, CheckNamesTheFieldAndRange) {
  EXPECT_TRUE(CheckRenderOptions(RenderOptions{}).ok());
  RenderOptions o;
  o.threshold_px = 0;
  EXPECT_EQ(CheckRenderOptions(o).field(), "threshold");
  o = RenderOptions{};
  o.card_planes = 1;
  EXPECT_EQ(CheckRenderOptions(o).Line(),
            "card_planes: 1 is out of range; must be a whole number in [2, 8]");
  o = RenderOptions{};
  o.atlas_size = 1000;
  EXPECT_NE(CheckRenderOptions(o).Line().find("power of two"), std::string::npos);
}

// Counts agree with the draw list, and the sakura goal of the issue holds at the page's view.
TEST(Counts, SakuraFifteenYearsDefaultViewMeetsOneTwentieth) {
  Tree tree = GrowForHybrid("sakura-thesis", 15);
  TreeMesh mesh = BuildTreeMesh(tree);
  RenderCamera camera = CameraFromOrbit(FrameOrbitView(MeshBounds(mesh)), 512, 512);
  for (LeafMode mode : {LeafMode::kClusterCards, LeafMode::kBranchCards}) {
    RenderOptions options;
    options.leaf_mode = mode;
    HybridScene scene = BuildHybridScene(tree, options);
    HybridSelection selection = SelectHybrid(tree, scene, camera, nullptr);
    RenderStats stats = CountHybrid(scene, selection);
    CountFull(mesh, &stats);
    HybridDrawList list = BuildDrawList(tree, scene, selection, camera);
    EXPECT_EQ(stats.total_polygons, stats.branch_polygons + stats.leaf_polygons);
    EXPECT_EQ(stats.primitives, stats.total_polygons + stats.lines);
    EXPECT_EQ(static_cast<std::size_t>(stats.total_polygons), list.card_indices.size() / 3);
    EXPECT_EQ(static_cast<std::size_t>(stats.lines), list.line_positions.size() / 6);
    EXPECT_EQ(list.line_colors.size(), list.line_positions.size() / 2);
    EXPECT_EQ(list.card_uvs.size(), list.card_positions.size() / 3 * 2);
    EXPECT_EQ(stats.full_polygons,
              static_cast<int>((mesh.bark.indices.size() + mesh.leaves.indices.size() +
                                mesh.flowers.indices.size()) /
                               3));
    EXPECT_GT(stats.lines, 0);
    EXPECT_GT(stats.card_branches, 0);
    EXPECT_GT(stats.textures, 0);
    EXPECT_LE(stats.textures, stats.atlas_tiles);
    // Goal: hybrid draws at most 1/20 of the full mode's primitives.
    EXPECT_LE(20 * stats.primitives, stats.full_polygons)
        << "primitives " << stats.primitives << " full " << stats.full_polygons;
    // The first card's base corner samples its tile's lower-left texel corner.
    ASSERT_FALSE(list.card_branch.empty());
    if (list.card_branch[0] >= 0) {
      std::size_t id = static_cast<std::size_t>(list.card_branch[0]);
      glm::vec3 centre =
          scene.frames[id].origin + scene.frames[id].b * (0.5f * scene.frames[id].length);
      int plane = ChooseCardPlane(scene.frames[id].planes, centre - camera.eye);
      const AtlasTile& tile = scene.group_tiles[static_cast<std::size_t>(scene.group_of_branch[id])]
                                               [static_cast<std::size_t>(plane)];
      EXPECT_FLOAT_EQ(list.card_uvs[0],
                      static_cast<float>(tile.x) / static_cast<float>(scene.atlas_size));
      EXPECT_FLOAT_EQ(list.card_uvs[5],
                      static_cast<float>(tile.y + tile.h) / static_cast<float>(scene.atlas_size));
    }
    // One atlas job per tile, clusters render leaves only.
    std::vector<AtlasJob> jobs = AtlasJobs(scene);
    EXPECT_EQ(static_cast<int>(jobs.size()), stats.atlas_tiles);
    for (const AtlasJob& job : jobs) {
      EXPECT_FALSE(job.branches.empty());
      EXPECT_GT(job.plane.u1, job.plane.u0);
      EXPECT_GT(job.plane.v1, job.plane.v0);
    }
    // Atlas: every tile inside, none overlapping.
    EXPECT_TRUE(scene.atlas_fits);
    std::vector<AtlasTile> tiles;
    for (const auto& g : scene.group_tiles) tiles.insert(tiles.end(), g.begin(), g.end());
    for (const auto& c : scene.cluster_tiles) tiles.insert(tiles.end(), c.begin(), c.end());
    EXPECT_EQ(static_cast<int>(tiles.size()), stats.atlas_tiles);
    for (std::size_t a = 0; a < tiles.size(); ++a) {
      const AtlasTile& t = tiles[a];
      ASSERT_TRUE(t.x >= 0 && t.y >= 0 && t.x + t.w <= scene.atlas_size &&
                  t.y + t.h <= scene.atlas_size);
      for (std::size_t b = a + 1; b < tiles.size(); ++b) {
        const AtlasTile& u = tiles[b];
        bool apart = t.x + t.w <= u.x || u.x + u.w <= t.x || t.y + t.h <= u.y || u.y + u.h <= t.y;
        ASSERT_TRUE(apart) << a << " overlaps " << b;
      }
    }
  }
}

TEST(Counts, ZoomingInTurnsLinesIntoCards) {
  Tree tree = GrowForHybrid("sakura-thesis", 8);
  TreeMesh mesh = BuildTreeMesh(tree);
  OrbitView view = FrameOrbitView(MeshBounds(mesh));
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  int last_cards = -1;
  for (float zoom : {2.0f, 1.0f, 0.5f, 0.25f}) {
    OrbitView v = view;
    v.distance *= zoom;
    HybridSelection s = SelectHybrid(tree, scene, CameraFromOrbit(v, 512, 512), nullptr);
    RenderStats stats = CountHybrid(scene, s);
    EXPECT_GE(stats.card_branches, last_cards);
    last_cards = stats.card_branches;
  }
  EXPECT_GT(last_cards, 0);
}

// A zoom in and back out with hysteresis: no living branch is ever undrawn, each switches at most
// twice (card → line → card or the reverse), and cards turn into lines and back.
TEST(Counts, ZoomSequenceNeverDropsABranchAndDoesNotFlicker) {
  Tree tree = GrowForHybrid("sakura-thesis", 8);
  TreeMesh mesh = BuildTreeMesh(tree);
  OrbitView view = FrameOrbitView(MeshBounds(mesh));
  HybridScene scene = BuildHybridScene(tree, RenderOptions{});
  std::vector<int> switches(tree.branches.size(), 0);
  HybridSelection previous;
  int min_cards = 1 << 30, max_cards = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k <= 40; ++k) {
      int step = pass == 0 ? k : 40 - k;
      OrbitView v = view;
      // 1× → 1/8× distance, with a ±6 % wobble (larger than one step of 5 %).
      v.distance *= det::Expf(-0.052f * static_cast<float>(step)) * (step % 2 ? 1.06f : 0.94f);
      HybridSelection now = SelectHybrid(tree, scene, CameraFromOrbit(v, 512, 512),
                                         previous.draw.empty() ? nullptr : &previous);
      int cards = 0;
      for (std::size_t i = 0; i < tree.branches.size(); ++i) {
        bool alive = tree.branches[i].alive && tree.branches[i].nodes.size() >= 2;
        ASSERT_EQ(now.draw[i] != BranchDraw::kHidden, alive) << "branch " << i;
        if (!previous.draw.empty() && now.draw[i] != previous.draw[i]) ++switches[i];
        cards += now.draw[i] == BranchDraw::kCard ? 1 : 0;
      }
      min_cards = std::min(min_cards, cards);
      max_cards = std::max(max_cards, cards);
      previous = now;
    }
  }
  EXPECT_LE(*std::max_element(switches.begin(), switches.end()), 2);
  EXPECT_GT(std::count(switches.begin(), switches.end(), 2), 0);  // some went there and back
  EXPECT_GT(max_cards, 2 * min_cards);
}

}  // namespace
}  // namespace niwa
