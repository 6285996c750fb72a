// Unit tests of the sway export (sway/sway_gltf): a skinned tree mesh and one animation clip whose
// poses, evaluated from the .glb alone, are the simulator's (thesis eq. 3.15).
#include "sway/sway_gltf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "support/glb_parse.h"
#include "support/glb_skin.h"
#include "support/grow.h"
#include "sway/skin.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_params.h"

namespace niwa {
namespace {

using ::niwa::testing::Glb;
using ::niwa::testing::GlbSkinEval;
using ::niwa::testing::ParseGlb;
using ::niwa::testing::PrimitiveAtKey;
using ::niwa::testing::ReadAccessor;
using nlohmann::json;

Tree GrowForSway(const std::string& preset, int years) {
  return testing::GrowPreset(preset, years, 1);
}

SwayParams ShortGust() {
  TreeParams ps;
  EXPECT_EQ(ps.Set(ParamId::kWindSpeed, 8.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOn, 0.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOff, 5.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kSwayDuration, 1.0).Line(), "");
  return SwayParams(ps);
}

TEST(GltfSwayTest, SkinnedGlbHasJointsClipAndReproducesTheSkinnedPoses) {
  const Tree tree = GrowForSway("sakura-thesis", 5);
  const SwayParams params = ShortGust();
  std::vector<unsigned char> bytes;
  SwayGlbInfo info;
  SwayGlbOptions every_key;
  every_key.key_error = 0;  // every key (the reduction: KeyReductionStaysWithinItsBound)
  ASSERT_EQ(WriteSwayGlb(tree, params, every_key, &bytes, &info).Line(), "");
  const Glb glb = ParseGlb(bytes);
  const json& gltf = glb.gltf;

  SwaySimulator sim(tree, params);
  const SwayModel& model = sim.model();
  ASSERT_GT(model.moving, 0);
  const SwayJoints map = MapSwayJoints(model);
  const std::size_t joints =
      1 + 2 * static_cast<std::size_t>(model.moving) + static_cast<std::size_t>(model.followers);
  EXPECT_EQ(map.count, joints);
  EXPECT_EQ(info.joints, joints);
  ASSERT_EQ(gltf["skins"].size(), 1u);
  const json& skin = gltf["skins"][0];
  ASSERT_EQ(skin["joints"].size(), joints);
  EXPECT_EQ(gltf["accessors"][skin["inverseBindMatrices"].get<std::size_t>()]["count"], joints);
  EXPECT_EQ(gltf["nodes"][0]["skin"], 0);
  EXPECT_EQ(gltf["scenes"][0]["nodes"].size(), 2u);  // the mesh and the skeleton root, at top

  // One clip; every joint but the root (fixed node points) has one translation and one rotation
  // channel; the keys are the steps (fps 30 = 1 / dt), 0 to 1 s.
  ASSERT_EQ(gltf["animations"].size(), 1u);
  const json& clip = gltf["animations"][0];
  std::vector<int> translation_channels(joints, 0), rotation_channels(joints, 0);
  GlbSkinEval eval{&glb, {}, {}, {}, {}};
  eval.translation.resize(joints);
  eval.rotation.resize(joints);
  std::vector<float> times;
  for (const json& channel : clip["channels"]) {
    const int node = channel["target"]["node"].get<int>();
    auto it = std::find(skin["joints"].begin(), skin["joints"].end(), node);
    ASSERT_NE(it, skin["joints"].end());
    const std::size_t j = static_cast<std::size_t>(it - skin["joints"].begin());
    const json& sampler = clip["samplers"][channel["sampler"].get<std::size_t>()];
    EXPECT_EQ(sampler.value("interpolation", "LINEAR"), "LINEAR");
    times = ReadAccessor<float>(glb, sampler["input"].get<int>());
    if (channel["target"]["path"] == "translation") {
      ++translation_channels[j];
      eval.translation[j] = ReadAccessor<float>(glb, sampler["output"].get<int>());
    } else {
      ASSERT_EQ(channel["target"]["path"], "rotation");
      ++rotation_channels[j];
      eval.rotation[j] = ReadAccessor<float>(glb, sampler["output"].get<int>());
    }
  }
  for (std::size_t j = 0; j < joints; ++j) {
    EXPECT_EQ(translation_channels[j], j == 0 ? 0 : 1) << j;
    EXPECT_EQ(rotation_channels[j], j == 0 ? 0 : 1) << j;
  }
  ASSERT_EQ(times.size(), 31u);
  EXPECT_EQ(info.keys, 31u);
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_NEAR(times[k], static_cast<double>(k) * params.dt, 1e-6);
  }
  for (std::size_t j = 0; j < joints; ++j) {
    const json& node = gltf["nodes"][skin["joints"][j].get<std::size_t>()];
    std::array<float, 3> t{0, 0, 0};
    if (node.contains("translation")) {
      for (int c = 0; c < 3; ++c) t[c] = node["translation"][c].get<float>();
    }
    eval.rest.push_back(t);
  }
  const std::vector<float> ibm = ReadAccessor<float>(glb, skin["inverseBindMatrices"].get<int>());
  ASSERT_EQ(ibm.size(), 16 * joints);
  for (std::size_t j = 0; j < joints; ++j) {
    eval.inverse_offset.push_back({ibm[16 * j + 12], ibm[16 * j + 13], ibm[16 * j + 14]});
  }

  // Keys 0 and 15 against the skin formula with WriteSwayPoses (core/sway/skin.h) on every
  // vertex of every primitive, and the moved tree really moves at key 15.
  const TreeMesh mesh = BuildTreeMesh(tree);
  const TreeSkin tree_skin = BuildTreeSkin(mesh, model);
  const json& primitives = gltf["meshes"][0]["primitives"];
  const MeshBuffers* buffers[3] = {&mesh.bark, &mesh.leaves, &mesh.flowers};
  const VertexSkin* vertex_skin[3] = {&tree_skin.bark, &tree_skin.leaves, &tree_skin.flowers};
  std::vector<float> poses(kSwayPoseFloats * model.nodes.size());
  double moved = 0;
  for (std::size_t key : {std::size_t{0}, std::size_t{15}}) {
    while (sim.steps() < static_cast<long>(key)) sim.Step();
    WriteSwayPoses(sim, 0.01f, poses.data());
    std::size_t primitive = 0;
    for (std::size_t part = 0; part < 3; ++part) {
      if (buffers[part]->indices.empty()) continue;
      const json& attributes = primitives[primitive++]["attributes"];
      const int joints_accessor = attributes["JOINTS_0"].get<int>();
      EXPECT_EQ(gltf["accessors"][static_cast<std::size_t>(joints_accessor)]["componentType"],
                5123);  // unsigned short
      const std::vector<uint16_t> j0 = ReadAccessor<uint16_t>(glb, joints_accessor);
      const std::vector<float> w0 = ReadAccessor<float>(glb, attributes["WEIGHTS_0"].get<int>());
      const std::vector<float> positions =
          ReadAccessor<float>(glb, attributes["POSITION"].get<int>());
      ASSERT_EQ(j0.size(), 4 * buffers[part]->vertex_count());
      for (std::size_t v = 0; v < buffers[part]->vertex_count(); ++v) {
        glm::vec3 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
        EXPECT_NEAR(w0[4 * v] + w0[4 * v + 1] + w0[4 * v + 2] + w0[4 * v + 3], 1.0, 1e-6);
        glm::dvec3 got = eval.At(key, j0, w0, v, glm::dvec3(p));
        glm::vec3 want = SkinPosition(poses.data(), vertex_skin[part]->joint[v],
                                      vertex_skin[part]->weight[v], p);
        ASSERT_LE(glm::length(got - glm::dvec3(want)), 1e-4) << "part " << part << " v " << v;
        if (key == 0) {
          ASSERT_LE(glm::length(got - glm::dvec3(p)), 1e-5);
        }
        moved = std::max(moved, glm::length(got - glm::dvec3(p)));
      }
    }
  }
  EXPECT_GT(moved, 0.01);  // metres
}

// The wind attributes (docs/sway-model.md "Wind attributes"): on bark, leaves and flowers, one
// value a vertex; a branch's vertices share its level and phase, a child is one level below its
// parent, _WIND_ALONG is the vertex's node over the branch's last node.
TEST(GltfSwayTest, WindAttributesFollowTheBranches) {
  const Tree tree = GrowForSway("sakura-thesis", 5);
  std::vector<unsigned char> bytes;
  ASSERT_EQ(WriteSwayGlb(tree, ShortGust(), SwayGlbOptions{}, &bytes).Line(), "");
  const Glb glb = ParseGlb(bytes);
  MeshOptions mesh_options;
  mesh_options.cm_to_units = SwayGlbOptions{}.cm_to_units;
  const TreeMesh mesh = BuildTreeMesh(tree, mesh_options);
  const std::vector<uint32_t>* ids[3] = {&mesh.bark_branch_id, &mesh.leaf_branch_id,
                                         &mesh.flower_branch_id};
  const std::vector<uint32_t>* nodes[3] = {&mesh.bark_node_index, &mesh.leaf_node_index,
                                           &mesh.flower_node_index};
  std::vector<float> level(tree.branches.size(), -1.0f), phase(tree.branches.size(), -1.0f);
  std::size_t part = 0, checked = 0;
  for (const json& p : glb.gltf["meshes"][0]["primitives"]) {
    while (part < 3 && ids[part]->empty()) ++part;  // the writer skips empty parts
    ASSERT_LT(part, 3u);
    const std::size_t n = ids[part]->size();
    ASSERT_EQ(glb.gltf["accessors"][p["attributes"]["POSITION"].get<std::size_t>()]["count"], n);
    std::vector<float> values[3];
    const char* names[3] = {"_WIND_LEVEL", "_WIND_ALONG", "_WIND_PHASE"};
    for (int a = 0; a < 3; ++a) {
      ASSERT_TRUE(p["attributes"].contains(names[a])) << names[a];
      values[a] = ReadAccessor<float>(glb, p["attributes"][names[a]].get<int>());
      ASSERT_GE(values[a].size(), n);
    }
    for (std::size_t v = 0; v < n; ++v) {
      const uint32_t b = (*ids[part])[v];
      ASSERT_LT(b, tree.branches.size());
      if (level[b] < 0) level[b] = values[0][v], phase[b] = values[2][v];
      EXPECT_EQ(values[0][v], level[b]);  // one level and phase a branch, across its parts
      EXPECT_EQ(values[2][v], phase[b]);
      EXPECT_GE(values[2][v], 0.0f);
      EXPECT_LT(values[2][v], 1.0f);
      const float last = static_cast<float>(tree.branches[b].nodes.size() - 1);
      EXPECT_FLOAT_EQ(values[1][v], std::min(1.0f, static_cast<float>((*nodes[part])[v]) / last));
      ++checked;
    }
    ++part;
  }
  EXPECT_GT(checked, 1000u);
  int children = 0, phases_apart = 0;
  for (const Branch& b : tree.branches) {
    const std::size_t i = static_cast<std::size_t>(b.id);
    if (b.parent < 0 || level[i] < 0 || level[static_cast<std::size_t>(b.parent)] < 0) continue;
    EXPECT_EQ(level[i], level[static_cast<std::size_t>(b.parent)] + 1.0f) << b.id;
    ++children;
    phases_apart += phase[i] != phase[static_cast<std::size_t>(b.parent)] ? 1 : 0;
  }
  EXPECT_GT(children, 10);
  EXPECT_EQ(phases_apart, children);  // a child never swings in step with its parent
}

// A tree whose exact skin passes the joint budget is written clustered within it (a tree past
// JOINTS_0's 65,536 exact joints, once refused, takes the same path), and a budget outside
// [2, 65536] is a one-line error.
TEST(GltfSwayTest, AWideTreeIsClusteredAndABadBudgetIsAOneLineError) {
  // 3,000 long thin twigs with leaves on one trunk: every twig moves, 2 joints each.
  Tree tree;
  auto add = [&](int parent, glm::vec3 a, glm::vec3 b, float radius, int leaves) {
    Branch br{};
    br.id = static_cast<int>(tree.branches.size());
    br.parent = parent;
    br.parent_node = parent < 0 ? 0 : 1;
    br.alive = true;
    br.nodes = {a, b};
    br.cross_section = 3.14159265f * radius * radius;
    for (int k = 0; k < leaves; ++k) br.leaves.push_back(Leaf{1, glm::vec3(1, 0, 0)});
    if (parent >= 0) tree.branches[static_cast<std::size_t>(parent)].children.push_back(br.id);
    tree.branches.push_back(br);
  };
  add(-1, {0, 0, 0}, {0, 100, 0}, 3.0f, 0);
  for (int k = 0; k < 3000; ++k) {
    float a = static_cast<float>(k) * 0.01f;
    add(0, {0, 100, 0}, {60 * std::cos(a), 100, 60 * std::sin(a)}, 0.2f, 5);
  }
  const SwayParams params = ShortGust();
  ASSERT_GT(MapSwayJoints(BuildSwayModel(tree, params)).count, 6000u);
  std::vector<unsigned char> bytes;
  SwayGlbInfo info;
  ASSERT_EQ(WriteSwayGlb(tree, params, SwayGlbOptions{}, &bytes, &info).Line(), "");
  EXPECT_TRUE(info.clustered);
  EXPECT_EQ(info.joints, kDefaultSwayJoints);
  EXPECT_GT(info.exact_joints, 6000u);
  const Glb glb = ParseGlb(bytes);
  EXPECT_EQ(glb.gltf["skins"][0]["joints"].size(), kDefaultSwayJoints);

  for (std::size_t bad : {std::size_t{0}, std::size_t{1}, kMaxGltfJoints + 1}) {
    SwayGlbOptions options;
    options.max_joints = bad;
    const std::string error = WriteSwayGlb(tree, params, options, &bytes).Line();
    EXPECT_NE(error.find("max_joints"), std::string::npos) << error;
    EXPECT_NE(error.find("[2, 65536]"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
    EXPECT_TRUE(bytes.empty());
  }
}

// The groups (SwayClusters): at most the asked number, each representative once, and every node
// point follows the nearest representative at or above it (or the root when none is).
TEST(GltfSwayTest, ClustersFollowTheNearestRepresentativeAbove) {
  const Tree tree = GrowForSway("sakura-thesis", 5);
  const SwayParams params = ShortGust();
  const SwayModel model = BuildSwayModel(tree, params);
  const std::vector<double> vertices(model.nodes.size(), 10.0);
  for (std::size_t groups : {std::size_t{1}, std::size_t{7}, std::size_t{30}}) {
    const SwayClusters c = ClusterSwayNodePoints(tree, params, vertices, groups);
    ASSERT_EQ(c.rep.size(), model.nodes.size());
    EXPECT_EQ(c.reps.size(), groups);  // this tree has more moving node points than that
    std::vector<char> is_rep(model.nodes.size(), 0);
    for (int r : c.reps) {
      EXPECT_FALSE(is_rep[static_cast<std::size_t>(r)]) << r;
      is_rep[static_cast<std::size_t>(r)] = 1;
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      int expected = -1;
      for (int a = static_cast<int>(i); a >= 0;
           a = model.nodes[static_cast<std::size_t>(a)].parent) {
        if (is_rep[static_cast<std::size_t>(a)]) {
          expected = a;
          break;
        }
      }
      EXPECT_EQ(c.rep[i], expected) << i;
    }
    // Deterministic.
    EXPECT_EQ(ClusterSwayNodePoints(tree, params, vertices, groups).reps, c.reps);
  }
}

// The clustered skin, read back from the .glb alone: each vertex on one joint, the joints' keys
// turning its group with one rod; more joints, closer to eq. 3.15; and the exact skin (today's
// bytes) whenever it fits the budget.
TEST(GltfSwayTest, ClusteredSkinApproachesTheSwayAsJointsGrow) {
  const Tree tree = GrowForSway("sakura-thesis", 5);
  const SwayParams params = ShortGust();
  std::vector<unsigned char> exact, wide;
  SwayGlbInfo exact_info;
  SwayGlbOptions options;
  options.key_error = 0;  // keys compared by index
  options.max_joints = kMaxGltfJoints;
  ASSERT_EQ(WriteSwayGlb(tree, params, options, &wide, &exact_info).Line(), "");
  options.max_joints = exact_info.exact_joints;
  ASSERT_EQ(WriteSwayGlb(tree, params, options, &exact).Line(), "");
  EXPECT_EQ(exact, wide);  // the exact skin at its own count
  EXPECT_FALSE(exact_info.clustered);
  EXPECT_EQ(exact_info.joints, exact_info.exact_joints);

  // Key 30 (t = 1 s, the gust blowing) of the exact skin, evaluated from its .glb.
  const std::vector<glm::dvec3> exact_rest = PrimitiveAtKey(ParseGlb(exact), 0, 0);
  const std::vector<glm::dvec3> exact_moved = PrimitiveAtKey(ParseGlb(exact), 0, 30);
  double last_mean = 1e9, motion = 0, last_vertex_mean = 1e9;
  for (std::size_t joints : {std::size_t{4}, std::size_t{16}, std::size_t{64}}) {
    ASSERT_LT(joints, exact_info.exact_joints);
    options.max_joints = joints;
    std::vector<unsigned char> bytes;
    SwayGlbInfo info;
    ASSERT_EQ(WriteSwayGlb(tree, params, options, &bytes, &info).Line(), "");
    EXPECT_TRUE(info.clustered);
    EXPECT_EQ(info.joints, joints);
    EXPECT_GT(info.max_motion, 0.05);  // metres: the gust moves the tree
    EXPECT_LT(info.mean_error, last_mean) << joints;
    last_mean = info.mean_error;
    motion = info.max_motion;
    const Glb glb = ParseGlb(bytes);
    const json& skin = glb.gltf["skins"][0];
    ASSERT_EQ(skin["joints"].size(), joints);
    for (const json& p : glb.gltf["meshes"][0]["primitives"]) {
      const std::vector<float> w =
          ReadAccessor<float>(glb, p["attributes"]["WEIGHTS_0"].get<int>());
      for (std::size_t v = 0; v + 3 < w.size(); v += 4) {
        ASSERT_EQ(w[v], 1.0f);
        ASSERT_EQ(w[v + 1] + w[v + 2] + w[v + 3], 0.0f);
      }
    }
    EXPECT_EQ(glb.gltf["animations"][0]["channels"].size(), 2 * (joints - 1));
    // The bark's vertices from this .glb against the exact .glb's: the rest pose is exact, the
    // blowing one closer with more joints.
    const std::vector<glm::dvec3> rest = PrimitiveAtKey(ParseGlb(bytes), 0, 0);
    const std::vector<glm::dvec3> moved = PrimitiveAtKey(ParseGlb(bytes), 0, 30);
    ASSERT_EQ(moved.size(), exact_moved.size());
    double sum = 0;
    for (std::size_t v = 0; v < moved.size(); ++v) {
      ASSERT_LE(glm::length(rest[v] - exact_rest[v]), 1e-5) << v;
      sum += glm::length(moved[v] - exact_moved[v]);
    }
    const double vertex_mean = sum / static_cast<double>(moved.size());
    EXPECT_LT(vertex_mean, last_vertex_mean) << joints;
    last_vertex_mean = vertex_mean;
  }
  EXPECT_LT(last_vertex_mean, 0.1 * motion);
  // 64 of the tree's joints: on average within a tenth of the largest motion.
  EXPECT_LT(last_mean, 0.1 * motion);
}

// Every vertex of every primitive of a skinned .glb at time t, from the .glb alone: each joint's
// channels interpolated as glTF LINEAR (lerp, slerp) over their own input times.
std::vector<std::vector<glm::dvec3>> VerticesAtTime(const std::vector<unsigned char>& bytes,
                                                    double t) {
  const Glb glb = ParseGlb(bytes);
  const json& gltf = glb.gltf;
  const json& skin = gltf["skins"][0];
  const std::size_t joints = skin["joints"].size();
  std::vector<glm::dvec3> translation(joints);
  std::vector<glm::dquat> rotation(joints, glm::dquat(1, 0, 0, 0));
  std::vector<glm::dvec3> offset(joints);
  const std::vector<float> ibm = ReadAccessor<float>(glb, skin["inverseBindMatrices"].get<int>());
  for (std::size_t j = 0; j < joints; ++j) {
    const json& node = gltf["nodes"][skin["joints"][j].get<std::size_t>()];
    if (node.contains("translation")) {
      translation[j] =
          glm::dvec3(node["translation"][0].get<double>(), node["translation"][1].get<double>(),
                     node["translation"][2].get<double>());
    }
    offset[j] = glm::dvec3(ibm[16 * j + 12], ibm[16 * j + 13], ibm[16 * j + 14]);
  }
  const json& clip = gltf["animations"][0];
  for (const json& channel : clip["channels"]) {
    const int node = channel["target"]["node"].get<int>();
    const std::size_t j = static_cast<std::size_t>(
        std::find(skin["joints"].begin(), skin["joints"].end(), node) - skin["joints"].begin());
    const json& sampler = clip["samplers"][channel["sampler"].get<std::size_t>()];
    const std::vector<float> times = ReadAccessor<float>(glb, sampler["input"].get<int>());
    const std::vector<float> values = ReadAccessor<float>(glb, sampler["output"].get<int>());
    std::size_t b = 1;
    while (b + 1 < times.size() && times[b] < t) ++b;
    const std::size_t a = b - 1;
    const double u = std::clamp((t - times[a]) / (times[b] - times[a]), 0.0, 1.0);
    if (channel["target"]["path"] == "translation") {
      const glm::dvec3 pa(values[3 * a], values[3 * a + 1], values[3 * a + 2]);
      const glm::dvec3 pb(values[3 * b], values[3 * b + 1], values[3 * b + 2]);
      translation[j] = pa + u * (pb - pa);
    } else {
      const glm::dquat qa(values[4 * a + 3], values[4 * a], values[4 * a + 1], values[4 * a + 2]);
      const glm::dquat qb(values[4 * b + 3], values[4 * b], values[4 * b + 1], values[4 * b + 2]);
      rotation[j] = glm::slerp(qa, qb, u);
    }
  }
  std::vector<std::vector<glm::dvec3>> out;
  for (const json& p : gltf["meshes"][0]["primitives"]) {
    const std::vector<uint16_t> j0 =
        ReadAccessor<uint16_t>(glb, p["attributes"]["JOINTS_0"].get<int>());
    const std::vector<float> w0 = ReadAccessor<float>(glb, p["attributes"]["WEIGHTS_0"].get<int>());
    const std::vector<float> pos = ReadAccessor<float>(glb, p["attributes"]["POSITION"].get<int>());
    out.emplace_back();
    for (std::size_t v = 0; 3 * v + 2 < pos.size(); ++v) {
      const glm::dvec3 rest(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
      glm::dvec3 at(0.0);
      for (std::size_t c = 0; c < 4; ++c) {
        const double w = w0[4 * v + c];
        if (w == 0) continue;
        const std::size_t j = j0[4 * v + c];
        at += w * (rotation[j] * (rest + offset[j]) + translation[j]);
      }
      out.back().push_back(at);
    }
  }
  return out;
}

// The clip's key reduction (docs/sway-model.md "Clip keys"): fewer keys, and at every key time of
// the full clip every vertex of the reduced one within the bound of the full one's place, for the
// exact and the clustered skin; key_error 0 keeps every key (one shared input).
TEST(GltfSwayTest, KeyReductionStaysWithinItsBound) {
  const Tree tree = GrowForSway("sakura-thesis", 5);
  TreeParams ps;
  ASSERT_EQ(ps.Set(ParamId::kWindSpeed, 8.0).Line(), "");
  ASSERT_EQ(ps.Set(ParamId::kGustOn, 0.5).Line(), "");
  ASSERT_EQ(ps.Set(ParamId::kGustOff, 1.5).Line(), "");
  ASSERT_EQ(ps.Set(ParamId::kSwayDuration, 3.0).Line(), "");
  const SwayParams params(ps);
  for (std::size_t max_joints : {kMaxGltfJoints, std::size_t{24}}) {
    SwayGlbOptions options;
    options.max_joints = max_joints;
    options.key_error = 0;
    std::vector<unsigned char> full;
    SwayGlbInfo full_info;
    ASSERT_EQ(WriteSwayGlb(tree, params, options, &full, &full_info).Line(), "");
    EXPECT_EQ(full_info.joint_keys, full_info.full_joint_keys);
    const Glb full_glb = ParseGlb(full);
    const json& samplers = full_glb.gltf["animations"][0]["samplers"];
    EXPECT_EQ(samplers.size(), 2 * (full_info.joints - 1));
    std::set<int> full_inputs;
    for (const json& s : samplers) full_inputs.insert(s["input"].get<int>());
    EXPECT_EQ(full_inputs.size(), 1u);
    const std::size_t keys = full_info.keys;
    ASSERT_EQ(keys, 91u);
    std::vector<std::vector<std::vector<glm::dvec3>>> want;
    for (std::size_t k = 0; k < keys; ++k) {
      want.push_back(VerticesAtTime(full, static_cast<double>(k) * params.dt));
    }
    std::size_t last_keys = full_info.joint_keys + 1;
    for (double bound : {0.001, 0.01}) {
      options.key_error = bound;
      std::vector<unsigned char> reduced;
      SwayGlbInfo info;
      ASSERT_EQ(WriteSwayGlb(tree, params, options, &reduced, &info).Line(), "");
      EXPECT_EQ(info.full_joint_keys, full_info.full_joint_keys);
      EXPECT_LT(info.joint_keys, last_keys) << bound;  // fewer keys for a looser bound
      last_keys = info.joint_keys;
      EXPECT_LE(info.key_error, bound);
      EXPECT_GT(info.key_error, 0.0);
      EXPECT_LT(reduced.size(), full.size());
      double worst = 0;
      for (std::size_t k = 0; k < keys; ++k) {
        const auto got = VerticesAtTime(reduced, static_cast<double>(k) * params.dt);
        ASSERT_EQ(got.size(), want[k].size());
        for (std::size_t p = 0; p < got.size(); ++p) {
          ASSERT_EQ(got[p].size(), want[k][p].size());
          for (std::size_t v = 0; v < got[p].size(); ++v) {
            worst = std::max(worst, glm::length(got[p][v] - want[k][p][v]));
          }
        }
      }
      // float keys: a few micrometres beside the bound.
      EXPECT_LE(worst, bound + 1e-5) << max_joints << " joints, bound " << bound;
      EXPECT_GT(worst, 0.0);
    }
  }
}

}  // namespace
}  // namespace niwa
