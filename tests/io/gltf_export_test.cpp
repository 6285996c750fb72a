// Unit tests of the .glb writer: container, JSON chunk, accessors, materials, binary payload.
#include "io/gltf_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "io/gltf_sway.h"
#include "render/textures.h"
#include "sway/skin.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"

namespace niwa {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kRepeat = 10497;
constexpr int kClampToEdge = 33071;

Tree Grow(const std::string& preset, int years) {
  GrowRequest r;
  r.preset = preset;
  r.params = FindPreset(preset)->params;
  r.years = years;
  r.seed = 1;
  return GrowTree(r);
}

uint32_t ReadU32(const std::vector<unsigned char>& bytes, std::size_t offset) {
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4);  // glb is little-endian, as are both targets
  return value;
}

// A parsed .glb: its JSON and its BIN chunk payload.
struct Glb {
  json gltf;
  std::vector<unsigned char> bin;
};

// Parses the container, checking the header and chunk layout (glTF 2.0 spec, 4.4).
Glb ParseGlb(const std::vector<unsigned char>& bytes) {
  Glb glb;
  EXPECT_GE(bytes.size(), 20u);
  if (bytes.size() < 20) return glb;
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "glTF");
  EXPECT_EQ(ReadU32(bytes, 4), 2u);
  EXPECT_EQ(ReadU32(bytes, 8), bytes.size());
  EXPECT_EQ(bytes.size() % 4, 0u);
  uint32_t json_length = ReadU32(bytes, 12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(ReadU32(bytes, 16), 0x4E4F534Au);  // "JSON"
  EXPECT_LE(20u + json_length, bytes.size());
  if (20u + json_length > bytes.size()) return glb;
  glb.gltf = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
  std::size_t next = 20u + json_length;
  if (next < bytes.size()) {
    EXPECT_GE(bytes.size(), next + 8);
    uint32_t bin_length = ReadU32(bytes, next);
    EXPECT_EQ(ReadU32(bytes, next + 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(next + 8 + bin_length, bytes.size());
    glb.bin.assign(bytes.begin() + static_cast<std::ptrdiff_t>(next + 8), bytes.end());
  }
  return glb;
}

template <typename T>
std::vector<T> ReadAccessor(const Glb& glb, int index) {
  const json& accessor = glb.gltf["accessors"][static_cast<std::size_t>(index)];
  const json& view = glb.gltf["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  std::size_t offset = view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", 0u);
  std::size_t length = view["byteLength"].get<std::size_t>();
  std::vector<T> values(length / sizeof(T));
  EXPECT_LE(offset + length, glb.bin.size());
  if (offset + length <= glb.bin.size())
    std::memcpy(values.data(), glb.bin.data() + offset, length);
  return values;
}

// The material's base colour comes from an embedded PNG (bufferView + mimeType) through a texture
// and sampler; double-sided cut-outs (leaves, flowers) are alpha-masked and clamped, bark repeats.
void ExpectTexturedMaterial(const Glb& glb, const json& mat, bool cut_out) {
  const json& gltf = glb.gltf;
  const json& pbr = mat["pbrMetallicRoughness"];
  ASSERT_TRUE(pbr.contains("baseColorTexture"));
  EXPECT_EQ(pbr["baseColorTexture"].value("texCoord", 0), 0);
  std::size_t texture_index = pbr["baseColorTexture"]["index"].get<std::size_t>();
  ASSERT_LT(texture_index, gltf["textures"].size());
  const json& texture = gltf["textures"][texture_index];
  std::size_t image_index = texture["source"].get<std::size_t>();
  ASSERT_LT(image_index, gltf["images"].size());
  const json& image = gltf["images"][image_index];
  EXPECT_EQ(image["mimeType"], "image/png");
  EXPECT_FALSE(image.contains("uri"));
  std::size_t view_index = image["bufferView"].get<std::size_t>();
  ASSERT_LT(view_index, gltf["bufferViews"].size());
  const json& view = gltf["bufferViews"][view_index];
  std::size_t offset = view.value("byteOffset", std::size_t{0});
  std::size_t length = view["byteLength"].get<std::size_t>();
  ASSERT_GT(length, 8u);
  ASSERT_LE(offset + length, glb.bin.size());
  static const unsigned char kPngMagic[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  EXPECT_TRUE(std::equal(kPngMagic, kPngMagic + 8, glb.bin.begin() + static_cast<long>(offset)));
  EXPECT_EQ(std::string(glb.bin.begin() + static_cast<long>(offset + length - 8),
                        glb.bin.begin() + static_cast<long>(offset + length - 4)),
            "IEND");  // the whole file, up to its last chunk
  ASSERT_TRUE(texture.contains("sampler"));
  const json& sampler = gltf["samplers"][texture["sampler"].get<std::size_t>()];
  const int wrap = cut_out ? kClampToEdge : kRepeat;
  EXPECT_EQ(sampler.value("wrapS", kRepeat), wrap);
  EXPECT_EQ(sampler.value("wrapT", kRepeat), wrap);
  if (cut_out) {
    EXPECT_EQ(mat.value("alphaMode", std::string("OPAQUE")), "MASK");
    EXPECT_EQ(mat.value("alphaCutoff", 0.5), 0.5);
  } else {
    EXPECT_EQ(mat.value("alphaMode", std::string("OPAQUE")), "OPAQUE");
  }
}

void ExpectPrimitiveMatches(const Glb& glb, const json& primitive, const MeshBuffers& buffers,
                            const std::string& material, bool double_sided) {
  SCOPED_TRACE(material);
  const json& attributes = primitive["attributes"];
  ASSERT_TRUE(attributes.contains("POSITION"));
  ASSERT_TRUE(attributes.contains("NORMAL"));
  ASSERT_TRUE(attributes.contains("TEXCOORD_0"));
  ASSERT_TRUE(primitive.contains("indices"));
  EXPECT_EQ(primitive.value("mode", 4), 4);  // triangles

  const json& accessors = glb.gltf["accessors"];
  const json& position = accessors[attributes["POSITION"].get<std::size_t>()];
  EXPECT_EQ(position["count"].get<std::size_t>(), buffers.vertex_count());
  EXPECT_EQ(position["componentType"], kFloat);
  EXPECT_EQ(position["type"], "VEC3");
  ASSERT_EQ(position["min"].size(), 3u);
  ASSERT_EQ(position["max"].size(), 3u);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (std::size_t v = 0; v < buffers.vertex_count(); ++v) {
      lo = std::min(lo, buffers.positions[3 * v + axis]);
      hi = std::max(hi, buffers.positions[3 * v + axis]);
    }
    EXPECT_EQ(position["min"][axis].get<double>(), static_cast<double>(lo));
    EXPECT_EQ(position["max"][axis].get<double>(), static_cast<double>(hi));
  }
  const json& normal = accessors[attributes["NORMAL"].get<std::size_t>()];
  EXPECT_EQ(normal["count"].get<std::size_t>(), buffers.vertex_count());
  EXPECT_EQ(normal["type"], "VEC3");
  const json& uv = accessors[attributes["TEXCOORD_0"].get<std::size_t>()];
  EXPECT_EQ(uv["count"].get<std::size_t>(), buffers.vertex_count());
  EXPECT_EQ(uv["type"], "VEC2");
  const json& indices = accessors[primitive["indices"].get<std::size_t>()];
  EXPECT_EQ(indices["count"].get<std::size_t>(), buffers.indices.size());
  EXPECT_EQ(indices["componentType"], kUnsignedInt);
  EXPECT_EQ(indices["type"], "SCALAR");

  // The bytes behind the accessors are the mesh's own.
  EXPECT_EQ(ReadAccessor<float>(glb, attributes["POSITION"].get<int>()), buffers.positions);
  EXPECT_EQ(ReadAccessor<float>(glb, attributes["NORMAL"].get<int>()), buffers.normals);
  EXPECT_EQ(ReadAccessor<float>(glb, attributes["TEXCOORD_0"].get<int>()), buffers.uvs);
  EXPECT_EQ(ReadAccessor<uint32_t>(glb, primitive["indices"].get<int>()), buffers.indices);

  const json& mat = glb.gltf["materials"][primitive["material"].get<std::size_t>()];
  EXPECT_EQ(mat["name"], material);
  EXPECT_EQ(mat.value("doubleSided", false), double_sided);
  ASSERT_TRUE(mat.contains("pbrMetallicRoughness"));
  // The colour is the texture's: the factor is white (the default, which tinygltf omits).
  EXPECT_EQ(mat["pbrMetallicRoughness"].value("baseColorFactor", json::array({1.0, 1.0, 1.0, 1.0})),
            json::array({1.0, 1.0, 1.0, 1.0}));
  if (mat.contains("emissiveFactor")) {
    EXPECT_EQ(mat["emissiveFactor"].size(), 3u);
  }
  ExpectTexturedMaterial(glb, mat, double_sided);
}

TEST(GltfExportTest, WritesAGlbWithBarkLeavesAndFlowers) {
  TreeMesh mesh = BuildTreeMesh(Grow("sakura", 8));
  ASSERT_GT(mesh.flowers.vertex_count(), 0u);
  std::vector<unsigned char> bytes;
  ASSERT_EQ(WriteGlb(mesh, &bytes), "");
  Glb glb = ParseGlb(bytes);
  const json& gltf = glb.gltf;
  EXPECT_EQ(gltf["asset"]["version"], "2.0");
  ASSERT_EQ(gltf["scenes"].size(), 1u);
  ASSERT_EQ(gltf["nodes"].size(), 1u);
  EXPECT_EQ(gltf["scenes"][0]["nodes"], json::array({0}));
  EXPECT_EQ(gltf["nodes"][0]["mesh"], 0);
  ASSERT_EQ(gltf["meshes"].size(), 1u);
  const json& primitives = gltf["meshes"][0]["primitives"];
  ASSERT_EQ(primitives.size(), 3u);
  ExpectPrimitiveMatches(glb, primitives[0], mesh.bark, "bark", false);
  ExpectPrimitiveMatches(glb, primitives[1], mesh.leaves, "leaves", true);
  ExpectPrimitiveMatches(glb, primitives[2], mesh.flowers, "flowers", true);

  // One procedural texture per material, embedded byte for byte.
  ASSERT_EQ(gltf["textures"].size(), 3u);
  ASSERT_EQ(gltf["images"].size(), 3u);
  const std::vector<unsigned char> expected[3] = {
      EncodePng(MakeBarkTexture()), EncodePng(MakeLeafTexture()), EncodePng(MakeFlowerTexture())};
  for (std::size_t i = 0; i < 3; ++i) {
    const json& mat = gltf["materials"][primitives[i]["material"].get<std::size_t>()];
    std::size_t texture = mat["pbrMetallicRoughness"]["baseColorTexture"]["index"];
    const json& view =
        gltf["bufferViews"]
            [gltf["images"][gltf["textures"][texture]["source"].get<std::size_t>()]["bufferView"]
                 .get<std::size_t>()];
    std::size_t offset = view.value("byteOffset", std::size_t{0});
    std::size_t length = view["byteLength"].get<std::size_t>();
    ASSERT_LE(offset + length, glb.bin.size());
    EXPECT_EQ(std::vector<unsigned char>(glb.bin.begin() + static_cast<long>(offset),
                                         glb.bin.begin() + static_cast<long>(offset + length)),
              expected[i])
        << i;
  }

  // One buffer (the BIN chunk), aligned views with their targets.
  ASSERT_EQ(gltf["buffers"].size(), 1u);
  EXPECT_FALSE(gltf["buffers"][0].contains("uri"));
  std::size_t buffer_length = gltf["buffers"][0]["byteLength"].get<std::size_t>();
  EXPECT_LE(buffer_length, glb.bin.size());
  EXPECT_LT(glb.bin.size(), buffer_length + 4);
  std::vector<bool> image_view(gltf["bufferViews"].size(), false);
  for (const json& image : gltf["images"]) {
    image_view.at(image["bufferView"].get<std::size_t>()) = true;
  }
  for (std::size_t i = 0; i < gltf["bufferViews"].size(); ++i) {
    const json& view = gltf["bufferViews"][i];
    EXPECT_EQ(view["buffer"], 0);
    EXPECT_EQ(view.value("byteOffset", std::size_t{0}) % 4, 0u);
    EXPECT_LE(view.value("byteOffset", std::size_t{0}) + view["byteLength"].get<std::size_t>(),
              buffer_length);
    if (image_view[i]) {  // image data: no vertex/index target
      EXPECT_FALSE(view.contains("target"));
      EXPECT_FALSE(view.contains("byteStride"));
      continue;
    }
    ASSERT_TRUE(view.contains("target"));
    EXPECT_TRUE(view["target"] == kArrayBuffer || view["target"] == kElementArrayBuffer);
  }
  for (const json& primitive : primitives) {
    std::size_t index_view =
        gltf["accessors"][primitive["indices"].get<std::size_t>()]["bufferView"].get<std::size_t>();
    EXPECT_EQ(gltf["bufferViews"][index_view]["target"], kElementArrayBuffer);
  }
}

TEST(GltfExportTest, SkipsEmptyPrimitives) {
  TreeMesh mesh = BuildTreeMesh(Grow("keyaki", 4));
  ASSERT_EQ(mesh.flowers.vertex_count(), 0u);
  std::vector<unsigned char> bytes;
  ASSERT_EQ(WriteGlb(mesh, &bytes), "");
  Glb glb = ParseGlb(bytes);
  const json& primitives = glb.gltf["meshes"][0]["primitives"];
  ASSERT_EQ(primitives.size(), 2u);
  ExpectPrimitiveMatches(glb, primitives[0], mesh.bark, "bark", false);
  ExpectPrimitiveMatches(glb, primitives[1], mesh.leaves, "leaves", true);
  EXPECT_EQ(glb.gltf["materials"].size(), 2u);
  EXPECT_EQ(glb.gltf["textures"].size(), 2u);  // no flower texture without flowers
  EXPECT_EQ(glb.gltf["images"].size(), 2u);
}

TEST(GltfExportTest, EmptyMeshGivesAValidSceneWithoutMesh) {
  std::vector<unsigned char> bytes{1, 2, 3};  // stale content is replaced
  ASSERT_EQ(WriteGlb(BuildTreeMesh(Grow("sakura", 0)), &bytes), "");
  Glb glb = ParseGlb(bytes);
  EXPECT_TRUE(glb.bin.empty());
  EXPECT_EQ(glb.gltf["asset"]["version"], "2.0");
  ASSERT_EQ(glb.gltf["scenes"].size(), 1u);
  ASSERT_EQ(glb.gltf["nodes"].size(), 1u);
  EXPECT_FALSE(glb.gltf["nodes"][0].contains("mesh"));
  EXPECT_FALSE(glb.gltf.contains("meshes"));
  EXPECT_FALSE(glb.gltf.contains("buffers"));
  EXPECT_FALSE(glb.gltf.contains("accessors"));
  EXPECT_FALSE(glb.gltf.contains("images"));
  EXPECT_FALSE(glb.gltf.contains("textures"));
}

TEST(GltfExportTest, RejectsInconsistentBuffers) {
  TreeMesh good = BuildTreeMesh(Grow("tsutsuji", 3));
  std::vector<unsigned char> bytes;

  TreeMesh out_of_range = good;
  out_of_range.leaves.indices.back() = static_cast<uint32_t>(good.leaves.vertex_count());
  std::string error = WriteGlb(out_of_range, &bytes);
  EXPECT_NE(error.find("leaves"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_TRUE(bytes.empty());

  TreeMesh short_normals = good;
  short_normals.bark.normals.pop_back();
  EXPECT_NE(WriteGlb(short_normals, &bytes), "");

  TreeMesh partial_triangle = good;
  partial_triangle.bark.indices.push_back(0);
  EXPECT_NE(WriteGlb(partial_triangle, &bytes), "");

  EXPECT_NE(WriteGlb(good, nullptr), "");
}

TEST(GltfExportTest, OutputIsDeterministic) {
  TreeMesh mesh = BuildTreeMesh(Grow("sakura", 5));
  std::vector<unsigned char> a, b;
  ASSERT_EQ(WriteGlb(mesh, &a), "");
  ASSERT_EQ(WriteGlb(mesh, &b), "");
  EXPECT_EQ(a, b);
}

// ---- sway export (core/io/gltf_sway): skinned mesh + one animation clip ----

SwayParams ShortGust() {
  TreeParams ps;
  EXPECT_EQ(ps.Set(ParamId::kWindSpeed, 8.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOn, 0.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kGustOff, 5.0).Line(), "");
  EXPECT_EQ(ps.Set(ParamId::kSwayDuration, 1.0).Line(), "");
  return SwayParams(ps);
}

// The skinned position of vertex v of one primitive at key k, evaluated from the .glb alone:
// sum_i w_i (translate(t_i(k)) rotate(q_i(k))) IBM_i p (glTF 2.0 spec, 3.7.3).
struct GlbSkinEval {
  const Glb* glb;
  std::vector<std::vector<float>> translation, rotation;  // per joint, keys (empty: rest)
  std::vector<std::array<float, 3>> rest, inverse_offset;
  glm::dvec3 At(std::size_t key, const std::vector<uint16_t>& joints,
                const std::vector<float>& weights, std::size_t v, const glm::dvec3& p) const {
    glm::dvec3 out(0.0);
    for (std::size_t c = 0; c < 4; ++c) {
      const double w = weights[4 * v + c];
      if (w == 0) continue;
      const std::size_t j = joints[4 * v + c];
      glm::dvec3 t(rest[j][0], rest[j][1], rest[j][2]);
      glm::dquat q(1, 0, 0, 0);
      if (!translation[j].empty()) {
        const float* a = &translation[j][3 * key];
        const float* b = &rotation[j][4 * key];
        t = glm::dvec3(a[0], a[1], a[2]);
        q = glm::dquat(b[3], b[0], b[1], b[2]);
      }
      glm::dvec3 local =
          p + glm::dvec3(inverse_offset[j][0], inverse_offset[j][1], inverse_offset[j][2]);
      out += w * (q * local + t);
    }
    return out;
  }
};

TEST(GltfSwayTest, SkinnedGlbHasJointsClipAndReproducesTheSkinnedPoses) {
  const Tree tree = Grow("sakura", 5);
  const SwayParams params = ShortGust();
  std::vector<unsigned char> bytes;
  SwayGlbInfo info;
  ASSERT_EQ(WriteSwayGlb(tree, params, SwayGlbOptions{}, &bytes, &info), "");
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

TEST(GltfSwayTest, TooManyJointsIsAOneLineError) {
  // 33,000 long thin twigs with leaves on one trunk: every twig moves, 2 joints each.
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
  for (int k = 0; k < 33000; ++k) {
    float a = static_cast<float>(k) * 0.001f;
    add(0, {0, 100, 0}, {60 * std::cos(a), 100, 60 * std::sin(a)}, 0.2f, 5);
  }
  SwayParams params;
  ASSERT_GT(MapSwayJoints(BuildSwayModel(tree, params)).count, kMaxGltfJoints);
  std::vector<unsigned char> bytes;
  SwayGlbInfo info;
  std::string error = WriteSwayGlb(tree, params, SwayGlbOptions{}, &bytes, &info);
  EXPECT_NE(error.find("65536"), std::string::npos) << error;
  EXPECT_NE(error.find("fewer years"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_GT(info.joints, kMaxGltfJoints);
  EXPECT_TRUE(bytes.empty());
}

}  // namespace
}  // namespace niwa
