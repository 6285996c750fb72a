// Unit tests of the tree's .glb (tree/tree_gltf over io/gltf_writer): container, JSON chunk,
// accessors, materials, binary payload.
#include "tree/tree_gltf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "image/png.h"
#include "support/glb_parse.h"
#include "support/grow.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

using ::niwa::testing::Glb;
using ::niwa::testing::ParseGlb;
using ::niwa::testing::ReadAccessor;
using nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kRepeat = 10497;
constexpr int kClampToEdge = 33071;

Tree GrowForGltf(const std::string& preset, int years) {
  return testing::GrowPreset(preset, years, 1);
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

TEST(TreeGltf, WritesAGlbWithBarkLeavesAndFlowers) {
  TreeMesh mesh = BuildTreeMesh(GrowForGltf("sakura-thesis", 8));
  ASSERT_GT(mesh.flowers.vertex_count(), 0u);
  std::vector<unsigned char> bytes;
  ASSERT_EQ(WriteTreeGlb(mesh, &bytes).Line(), "");
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

  // One procedural base-colour texture per material (and the bark's normal map), embedded byte
  // for byte.
  ASSERT_EQ(gltf["textures"].size(), 4u);
  ASSERT_EQ(gltf["images"].size(), 4u);
  const std::vector<unsigned char> expected[3] = {
      *image::EncodeRgba8Png(MakeBarkTexture()), *image::EncodeRgba8Png(MakeLeafTexture({})),
      *image::EncodeRgba8Png(MakeBlossomClusterTexture())};
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

// The leaves' sampler: a pine's needles and every leaf spray (leaf_spray > 1) without mipmaps (an
// engine's alpha test on averaged mip levels drops thin needles and a spray's leaves, whose
// gaps average the alpha below the cutoff: docs/figures/species), a single broad leaf with them.
TEST(TreeGltf, NeedlesAndSpraysAreSampledWithoutMipmapsSingleBroadLeavesWith) {
  auto leaf_min_filter = [](const std::string& preset) {
    TreeMesh mesh = BuildTreeMesh(GrowForGltf(preset, 4));
    std::vector<unsigned char> bytes;
    EXPECT_EQ(WriteTreeGlb(mesh, &bytes).Line(), "");
    const json gltf = ParseGlb(bytes).gltf;
    for (const json& mat : gltf["materials"]) {
      if (mat.value("name", "") != "leaves") continue;
      const json& texture =
          gltf["textures"]
              [mat["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<std::size_t>()];
      return gltf["samplers"][texture["sampler"].get<std::size_t>()].value("minFilter", 0);
    }
    return -1;
  };
  EXPECT_EQ(leaf_min_filter("pine"), 9729);           // LINEAR
  EXPECT_EQ(leaf_min_filter("sakura"), 9729);         // leaf_spray 5
  EXPECT_EQ(leaf_min_filter("sakura-thesis"), 9987);  // LINEAR_MIPMAP_LINEAR
}

TEST(TreeGltf, SkipsEmptyPrimitives) {
  TreeMesh mesh = BuildTreeMesh(GrowForGltf("keyaki-thesis", 4));
  ASSERT_EQ(mesh.flowers.vertex_count(), 0u);
  std::vector<unsigned char> bytes;
  ASSERT_EQ(WriteTreeGlb(mesh, &bytes).Line(), "");
  Glb glb = ParseGlb(bytes);
  const json& primitives = glb.gltf["meshes"][0]["primitives"];
  ASSERT_EQ(primitives.size(), 2u);
  ExpectPrimitiveMatches(glb, primitives[0], mesh.bark, "bark", false);
  ExpectPrimitiveMatches(glb, primitives[1], mesh.leaves, "leaves", true);
  EXPECT_EQ(glb.gltf["materials"].size(), 2u);
  EXPECT_EQ(glb.gltf["textures"].size(), 3u);  // bark, its normal map, leaf: no flower texture
  EXPECT_EQ(glb.gltf["images"].size(), 3u);
}

TEST(TreeGltf, EmptyMeshGivesAValidSceneWithoutMesh) {
  std::vector<unsigned char> bytes{1, 2, 3};  // stale content is replaced
  ASSERT_EQ(WriteTreeGlb(BuildTreeMesh(GrowForGltf("sakura-thesis", 0)), &bytes).Line(), "");
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

TEST(TreeGltf, RejectsInconsistentBuffers) {
  TreeMesh good = BuildTreeMesh(GrowForGltf("tsutsuji-thesis", 3));
  std::vector<unsigned char> bytes;

  TreeMesh out_of_range = good;
  out_of_range.leaves.indices.back() = static_cast<uint32_t>(good.leaves.vertex_count());
  std::string error = WriteTreeGlb(out_of_range, &bytes).Line();
  EXPECT_NE(error.find("leaves"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_TRUE(bytes.empty());

  TreeMesh short_normals = good;
  short_normals.bark.normals.pop_back();
  EXPECT_NE(WriteTreeGlb(short_normals, &bytes).Line(), "");

  TreeMesh partial_triangle = good;
  partial_triangle.bark.indices.push_back(0);
  EXPECT_NE(WriteTreeGlb(partial_triangle, &bytes).Line(), "");

  EXPECT_NE(WriteTreeGlb(good, nullptr).Line(), "");
}

TEST(TreeGltf, OutputIsDeterministic) {
  TreeMesh mesh = BuildTreeMesh(GrowForGltf("sakura-thesis", 5));
  std::vector<unsigned char> a, b;
  ASSERT_EQ(WriteTreeGlb(mesh, &a).Line(), "");
  ASSERT_EQ(WriteTreeGlb(mesh, &b).Line(), "");
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace niwa
