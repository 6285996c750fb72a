// core/render/tree_lod_sway: the sway .glb on a budgeted mesh: the full mesh's bytes when it fits,
// else every primitive of the level skinned, within its triangles and joints, and the cards and
// twig cones following their branches' node points (thesis eq. 3.15, the simulator's own nodes).
#include "render/tree_lod_sway.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/glb_parse.h"
#include "support/glb_skin.h"
#include "support/grow.h"
#include "tree/mesh.h"
#include "tree/tree_params.h"

namespace niwa {
namespace {

using ::niwa::testing::Glb;
using ::niwa::testing::ParseGlb;
using ::niwa::testing::PrimitiveAtKey;
using ::niwa::testing::ReadAccessor;
using nlohmann::json;

SwayParams Gust() {
  TreeParams ps;
  EXPECT_EQ(ps.Set(ParamId::kWindSpeed, 10.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOn, 0.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOff, 5.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kSwayDuration, 1.0).Line(), "");
  return SwayParams(ps);
}

TEST(TreeLodSway, FullMeshThatFitsIsTheSwayGlb) {
  const Tree tree = testing::GrowPreset("sakura-thesis", 4);
  const SwayParams params = Gust();
  std::vector<unsigned char> plain, budgeted;
  ASSERT_EQ(WriteSwayGlb(tree, params, SwayGlbOptions{}, &plain).Line(), "");
  LodChoice choice;
  ASSERT_EQ(WriteLodSwayGlb(tree, params, SwayGlbOptions{}, 100000000, &budgeted, nullptr, &choice)
                .Line(),
            "");
  EXPECT_TRUE(choice.full);
  EXPECT_EQ(budgeted, plain);
  ASSERT_EQ(WriteLodSwayGlb(tree, params, SwayGlbOptions{}, -1, &budgeted).Line(), "");
  EXPECT_EQ(budgeted, plain);
  const std::string error = WriteLodSwayGlb(tree, params, SwayGlbOptions{}, 3, &budgeted, nullptr,
                                            nullptr, "--max-triangles")
                                .Line();
  EXPECT_EQ(error.rfind("--max-triangles: ", 0), 0u) << error;
  EXPECT_TRUE(budgeted.empty());
}

// A budgeted level with the exact skin and every key: each twig cone's apex moves as the simulator
// moves its branch's tip node (eq. 3.15), and every primitive (tubes, cards, twigs) is skinned.
TEST(TreeLodSway, TwigConesFollowTheirBranchesTips) {
  const Tree tree = testing::GrowPreset("sakura-thesis", 5);
  const SwayParams params = Gust();
  const long full = FullTriangles(BuildTreeMesh(tree));
  long budget = full / 2;
  while (BuildLodMesh(tree, budget)->choice.twigs == 0 && budget > 500) budget = budget * 3 / 4;
  SwayGlbOptions options;
  options.max_joints = kMaxGltfJoints;  // the exact skin
  options.key_error = 0;
  std::vector<unsigned char> bytes;
  SwayGlbInfo info;
  LodChoice choice;
  ASSERT_EQ(WriteLodSwayGlb(tree, params, options, budget, &bytes, &info, &choice).Line(), "");
  ASSERT_FALSE(choice.full);
  ASSERT_GT(choice.twigs, 0);
  ASSERT_GT(choice.cards, 0);
  EXPECT_FALSE(info.clustered);
  EXPECT_LE(choice.triangles, budget);
  const Glb glb = ParseGlb(bytes);
  const json& primitives = glb.gltf["meshes"][0]["primitives"];
  std::vector<std::string> materials;
  for (const json& p : primitives) {
    materials.push_back(glb.gltf["materials"][p["material"].get<std::size_t>()]["name"]);
    EXPECT_TRUE(p["attributes"].contains("JOINTS_0")) << materials.back();
    EXPECT_TRUE(p["attributes"].contains("WEIGHTS_0")) << materials.back();
    EXPECT_TRUE(p["attributes"].contains("_WIND_ALONG")) << materials.back();
  }
  const std::size_t twigs = static_cast<std::size_t>(
      std::find(materials.begin(), materials.end(), "twigs") - materials.begin());
  ASSERT_LT(twigs, materials.size());
  // The simulator's nodes at key 30 (t = 1 s, the gust blowing), and their rest places.
  SwaySimulator sim(tree, params);
  std::vector<glm::dvec3> rest_nodes, moved_nodes;
  for (const SwayNode& n : sim.model().nodes) {
    for (const glm::dvec3& r : n.rest_nodes) rest_nodes.push_back(0.01 * r);
  }
  while (sim.steps() < 30) sim.Step();
  sim.NodePositions(&moved_nodes);
  for (glm::dvec3& m : moved_nodes) m *= 0.01;
  const std::vector<float> rest =
      ReadAccessor<float>(glb, primitives[twigs]["attributes"]["POSITION"].get<int>());
  const std::vector<glm::dvec3> at0 = PrimitiveAtKey(glb, twigs, 0);
  const std::vector<glm::dvec3> at30 = PrimitiveAtKey(glb, twigs, 30);
  std::size_t matched = 0;
  double moved = 0;
  for (std::size_t v = 3; v < at30.size(); v += 4) {  // the apex of each cone: its tip node
    const glm::dvec3 apex(rest[3 * v], rest[3 * v + 1], rest[3 * v + 2]);
    ASSERT_LE(glm::length(at0[v] - apex), 1e-5) << v;
    std::size_t best = 0;
    for (std::size_t k = 1; k < rest_nodes.size(); ++k) {
      if (glm::length(rest_nodes[k] - apex) < glm::length(rest_nodes[best] - apex)) best = k;
    }
    if (glm::length(rest_nodes[best] - apex) > 1e-6) continue;  // a shared place: skip
    ++matched;
    EXPECT_LE(glm::length(at30[v] - moved_nodes[best]), 1e-4) << "twig apex " << v;
    moved = std::max(moved, glm::length(at30[v] - apex));
  }
  EXPECT_GE(matched, static_cast<std::size_t>(choice.twigs) / 2);
  EXPECT_GT(moved, 0.01);  // metres: the twigs sway
}

// The default budget and joints on a 15-year sakura (the case): within both, fewer
// keys than the full clip, every primitive skinned, far smaller than the full mesh's sway .glb.
TEST(TreeLodSway, FifteenYearSakuraWithinTheDefaultBudgets) {
  const Tree tree = testing::GrowPreset("sakura", 15);
  TreeParams ps;
  const SwayParams params(ps);
  std::vector<unsigned char> bytes;
  SwayGlbInfo info;
  LodChoice choice;
  ASSERT_EQ(
      WriteLodSwayGlb(tree, params, SwayGlbOptions{}, kDefaultSwayTriangles, &bytes, &info, &choice)
          .Line(),
      "");
  EXPECT_FALSE(choice.full);
  EXPECT_LE(choice.triangles, kDefaultSwayTriangles);
  EXPECT_EQ(info.joints, kDefaultSwayJoints);
  EXPECT_LT(info.joint_keys, info.full_joint_keys);
  EXPECT_LE(bytes.size(), 8u * 1000 * 1000);
  const Glb glb = ParseGlb(bytes);
  EXPECT_EQ(glb.gltf["skins"][0]["joints"].size(), kDefaultSwayJoints);
  for (const json& p : glb.gltf["meshes"][0]["primitives"]) {
    EXPECT_TRUE(p["attributes"].contains("JOINTS_0"));
    EXPECT_EQ(p.value("mode", 4), 4);
  }
}

}  // namespace
}  // namespace niwa
