// Tests of the skinning form of thesis eq. 3.15: poses + joints/weights reproduce the node points.
#include "sway/skin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "support/hand_tree.h"
#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

constexpr float kScale = 0.01f;  // default cm_to_units

// Branches of the hand-made trees carry a flower at their tip when they have leaves.
int AddFloweringBranch(Tree* tree, int parent, int parent_node, glm::vec3 base, glm::vec3 tip,
                       int segments, float radius, int leaves = 0) {
  return ::niwa::testing::AddBranch(tree, parent, parent_node, base, tip, segments, radius, leaves,
                                    true);
}

// Moving arms, a follower twig, a fixed stub, a branch starting at its parent's node 0 and a dead
// branch with a child.
Tree HandTree() {
  Tree t;
  int trunk = AddFloweringBranch(&t, -1, 0, {0, 0, 0}, {0, 60, 0}, 6, 1.2f);
  int arm = AddFloweringBranch(&t, trunk, 6, {}, {-30, 85, 10}, 5, 0.4f, 5);
  AddFloweringBranch(&t, arm, 3, {}, {-40, 95, 5}, 4, 0.2f, 4);
  AddFloweringBranch(&t, arm, 5, {}, {-31, 87, 10}, 1, 0.1f);  // short: a follower
  int top = AddFloweringBranch(&t, trunk, 6, {}, {5, 100, 0}, 8, 0.6f, 8);
  AddFloweringBranch(&t, top, 0, {}, {20, 70, 5}, 4, 0.3f, 3);  // starts at top's node 0
  int stump =
      AddFloweringBranch(&t, -1, 0, {50, 0, 0}, {50, 10, 0}, 2, 5.0f);  // second root: fixed
  AddFloweringBranch(&t, stump, 1, {}, {55, 5, 0}, 1, 2.0f);            // thick stub on it: fixed
  int dead = AddFloweringBranch(&t, trunk, 3, {}, {30, 40, 0}, 3, 0.3f, 2);
  AddFloweringBranch(&t, dead, 3, {}, {40, 45, 0}, 2, 0.2f, 2);
  t.branches[static_cast<std::size_t>(dead)].alive = false;
  return t;
}

Tree Sakura(int years) {
  GrowRequest request;
  const Preset* preset = FindPreset("sakura-thesis");
  request.preset = preset->name;
  request.params = preset->params;
  request.seed = preset->seed;
  request.years = years;
  return GrowTree(request);
}

SwayParams Gust(double speed) {
  TreeParams ps;
  EXPECT_EQ(ps.Set(ParamId::kWindSpeed, speed).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOn, 0.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOff, 5.0).Line(), "");
  return SwayParams(ps);
}

glm::vec3 ToF(const glm::dvec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

glm::vec3 Vertex(const std::vector<float>& data, std::size_t v) {
  return {data[3 * v], data[3 * v + 1], data[3 * v + 2]};
}

// Largest distance of a rest node from the origin, mesh units: the scale of "relative".
double Extent(const SwayModel& model) {
  double e = 0;
  for (const SwayNode& s : model.nodes) {
    for (const glm::dvec3& p : s.rest_nodes) e = std::max(e, glm::length(p) * kScale);
  }
  return e;
}

// Every node of every node point, skinned from its rest position, against eq. 3.15.
void ExpectSkinMatchesNodePositions(const Tree& tree, const SwayParams& params, int steps) {
  SwaySimulator sim(tree, params);
  for (int k = 0; k < steps; ++k) sim.Step();
  const SwayModel& model = sim.model();
  ASSERT_GT(model.moving, 0);
  std::vector<float> poses(kSwayPoseFloats * model.nodes.size());
  WriteSwayPoses(sim, kScale, poses.data());
  const double extent = Extent(model);
  double moved = 0, worst = 0;
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const SwayNode& s = model.nodes[i];
    for (std::size_t n = 0; n < s.rest_nodes.size(); ++n) {
      SkinBinding b = BindNode(model, static_cast<uint32_t>(s.branch), static_cast<uint32_t>(n));
      glm::vec3 rest = ToF(s.rest_nodes[n] * static_cast<double>(kScale));
      glm::vec3 skinned = SkinPosition(poses.data(), b.joint, b.weight, rest);
      glm::dvec3 expected =
          sim.NodePosition(static_cast<int>(i), static_cast<int>(n)) * static_cast<double>(kScale);
      double error = glm::length(glm::dvec3(skinned) - expected);
      worst = std::max(worst, error / extent);
      EXPECT_LE(error, 1e-5 * extent) << "node point " << i << " node " << n;
      moved =
          std::max(moved, glm::length(expected - s.rest_nodes[n] * static_cast<double>(kScale)));
    }
  }
  EXPECT_GT(moved, 1e-3 * extent);  // the wind really moved the tree
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", worst);
  ::testing::Test::RecordProperty("worst_relative_error", text);
}

TEST(SwaySkin, HandTreeNodesMatchEq315After30Steps) {
  Tree t = HandTree();
  SwayParams p = Gust(10.0);
  SwayModel model = BuildSwayModel(t, p);
  EXPECT_GT(model.followers, 0);
  EXPECT_GT(model.fixed, 0);
  ExpectSkinMatchesNodePositions(t, p, 30);
}

TEST(SwaySkin, SakuraNodesMatchEq315After30Steps) {
  for (int years : {3, 5}) {
    SCOPED_TRACE(years);
    ExpectSkinMatchesNodePositions(Sakura(years), Gust(8.0), 30);
  }
}

TEST(SwaySkin, RestPosesGiveTheRestMeshExactly) {
  Tree t = Sakura(4);
  SwayModel model = BuildSwayModel(t, SwayParams());
  TreeMesh mesh = BuildTreeMesh(t);
  TreeSkin skin = BuildTreeSkin(mesh, model);
  std::vector<float> poses(kSwayPoseFloats * model.nodes.size(), -7.0f);
  RestSwayPoses(model.nodes.size(), poses.data());
  struct Part {
    const MeshBuffers* buffers;
    const VertexSkin* skin;
  };
  for (Part part : {Part{&mesh.bark, &skin.bark}, Part{&mesh.leaves, &skin.leaves},
                    Part{&mesh.flowers, &skin.flowers}}) {
    ASSERT_EQ(part.skin->joint.size(), part.buffers->vertex_count());
    ASSERT_EQ(part.skin->weight.size(), part.buffers->vertex_count());
    for (std::size_t v = 0; v < part.buffers->vertex_count(); ++v) {
      ASSERT_LT(part.skin->joint[v], model.nodes.size());
      glm::vec3 p = Vertex(part.buffers->positions, v), n = Vertex(part.buffers->normals, v);
      ASSERT_EQ(SkinPosition(poses.data(), part.skin->joint[v], part.skin->weight[v], p), p);
      ASSERT_EQ(SkinNormal(poses.data(), part.skin->joint[v], n), n);
    }
  }
  EXPECT_GT(mesh.flowers.vertex_count() + mesh.leaves.vertex_count(), 0u);
}

// A child's base ring and the parent's ring at the same node get the same binding, so they move
// together; every skinned bark vertex keeps its distance to its skinned node centre (rigid R).
TEST(SwaySkin, BaseRingFollowsTheParentNode) {
  Tree t = HandTree();
  SwaySimulator sim(t, Gust(10.0));
  for (int k = 0; k < 30; ++k) sim.Step();
  const SwayModel& model = sim.model();
  TreeMesh mesh = BuildTreeMesh(t);
  TreeSkin skin = BuildTreeSkin(mesh, model);
  std::vector<float> poses(kSwayPoseFloats * model.nodes.size());
  WriteSwayPoses(sim, kScale, poses.data());
  int base_rings = 0;
  for (std::size_t v = 0; v < mesh.bark.vertex_count(); ++v) {
    uint32_t branch = mesh.bark_branch_id[v], node = mesh.bark_node_index[v];
    const Branch& b = t.branches[branch];
    ASSERT_LT(node, b.nodes.size());
    int i = model.node_of_branch[branch];
    if (i < 0) {  // the alive child of the dead branch: rigid with the root
      EXPECT_EQ(skin.bark.joint[v], 0u);
      EXPECT_EQ(skin.bark.weight[v], 0.0f);
      continue;
    }
    glm::vec3 p = Vertex(mesh.bark.positions, v);
    glm::vec3 moved = SkinPosition(poses.data(), skin.bark.joint[v], skin.bark.weight[v], p);
    glm::dvec3 centre = sim.NodePosition(i, static_cast<int>(node)) * static_cast<double>(kScale);
    double rest_radius = glm::length(p - b.nodes[node] * kScale);
    EXPECT_NEAR(glm::length(glm::dvec3(moved) - centre), rest_radius, 1e-6);
    if (node == 0 && b.parent >= 0) {
      ++base_rings;
      const SwayNode& s = model.nodes[static_cast<std::size_t>(i)];
      SkinBinding parent =
          BindNode(model, static_cast<uint32_t>(b.parent), static_cast<uint32_t>(b.parent_node));
      EXPECT_EQ(skin.bark.joint[v], parent.joint);
      EXPECT_EQ(skin.bark.weight[v], parent.weight);
      // The same binding on the same rest point: the skinned centres are the same floats.
      const Branch& pb = t.branches[static_cast<std::size_t>(b.parent)];
      glm::vec3 parent_rest = pb.nodes[static_cast<std::size_t>(b.parent_node)] * kScale;
      EXPECT_EQ(
          SkinPosition(poses.data(), skin.bark.joint[v], skin.bark.weight[v], b.nodes[0] * kScale),
          SkinPosition(poses.data(), parent.joint, parent.weight, parent_rest));
      glm::dvec3 parent_node = sim.NodePosition(s.parent, s.parent_node) * 0.01;
      EXPECT_NEAR(glm::length(centre - parent_node), 0.0, 1e-7);  // metres
    }
  }
  EXPECT_GT(base_rings, 0);
  // Leaves and flowers on the dead branch (and its alive child) bind to the root, weight 0.
  for (std::size_t v = 0; v < mesh.leaves.vertex_count(); ++v) {
    EXPECT_EQ(skin.leaves.joint[v] == 0 && skin.leaves.weight[v] == 0.0f,
              model.node_of_branch[mesh.leaf_branch_id[v]] < 0);
  }
}

TEST(SwaySkin, PosesAtTimeZeroAreTheRestPose) {
  Tree t = Sakura(4);
  SwaySimulator sim(t, Gust(8.0));
  std::vector<float> poses(kSwayPoseFloats * sim.model().nodes.size());
  std::vector<float> rest(poses.size());
  WriteSwayPoses(sim, kScale, poses.data());
  RestSwayPoses(sim.model().nodes.size(), rest.data());
  for (std::size_t k = 0; k < poses.size(); ++k) EXPECT_NEAR(poses[k], rest[k], 1e-6) << k;
}

}  // namespace
}  // namespace niwa
