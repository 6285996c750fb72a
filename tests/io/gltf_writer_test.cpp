// Unit tests of io/gltf_writer: line primitives, custom attributes, embedded textures, a skin with
// a clip, and bad Documents, each written and parsed back with tinygltf (an independent reader).
#include "io/gltf_writer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "image/png.h"
#include "io/tinygltf.h"

namespace niwa::gltf {
namespace {

// tinygltf is built without an image decoder: keep each image's encoded bytes.
bool KeepImageBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  return true;
}

tinygltf::Model Parse(const std::vector<unsigned char>& glb) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(KeepImageBytes, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, glb.data(),
                                          static_cast<unsigned int>(glb.size())))
      << err;
  EXPECT_EQ(err, "");
  return model;
}

template <typename T>
std::vector<T> Read(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& accessor = model.accessors.at(static_cast<std::size_t>(accessor_index));
  const tinygltf::BufferView& view =
      model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  const std::vector<unsigned char>& data = model.buffers.at(0).data;
  const std::size_t components = static_cast<std::size_t>(
      tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type)));
  std::vector<T> out(accessor.count * components);
  EXPECT_EQ(sizeof(T), static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(
                           static_cast<uint32_t>(accessor.componentType))));
  EXPECT_LE(view.byteOffset + accessor.byteOffset + out.size() * sizeof(T), data.size());
  std::memcpy(out.data(), data.data() + view.byteOffset + accessor.byteOffset,
              out.size() * sizeof(T));
  return out;
}

std::vector<float> Flat(const std::vector<glm::vec3>& v) {
  std::vector<float> out;
  for (const glm::vec3& p : v) out.insert(out.end(), {p.x, p.y, p.z});
  return out;
}

// One node with one mesh of the given primitives.
Document OneMesh(std::vector<Primitive> primitives) {
  Document doc;
  doc.scene_name = "test";
  doc.meshes.push_back({"m", std::move(primitives)});
  Node node;
  node.name = "n";
  node.mesh = 0;
  doc.nodes.push_back(node);
  doc.scene_nodes = {0};
  return doc;
}

void ExpectError(const Document& doc, const std::string& part) {
  Result<std::vector<unsigned char>> glb = WriteGlb(doc);
  ASSERT_FALSE(glb.ok()) << "expected an error with '" << part << "'";
  EXPECT_NE(glb.status().Line().find(part), std::string::npos) << glb.status().Line();
  EXPECT_EQ(glb.status().Line().find('\n'), std::string::npos) << glb.status().Line();
}

Primitive Triangle() {
  Primitive p;
  p.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
  p.mesh.indices = {0, 1, 2};
  return p;
}

TEST(GltfWriter, AttributeSemantics) {
  EXPECT_EQ(AttributeSemantic("birth_step"), "_BIRTH_STEP");
  EXPECT_EQ(AttributeSemantic("_axis_order"), "_AXIS_ORDER");
  EXPECT_EQ(AttributeSemantic("COLOR_0"), "COLOR_0");
  EXPECT_EQ(AttributeSemantic("TEXCOORD_1"), "TEXCOORD_1");
  EXPECT_EQ(AttributeSemantic("TANGENT"), "TANGENT");
  EXPECT_EQ(AttributeSemantic("tangent"), "_TANGENT");
  EXPECT_EQ(AttributeSemantic("color_0"), "_COLOR_0");  // not the glTF spelling: custom
  EXPECT_EQ(AttributeSemantic("COLOR_x"), "_COLOR_X");
  EXPECT_EQ(AttributeSemantic(""), "");
  EXPECT_EQ(AttributeSemantic("_"), "");
  EXPECT_EQ(AttributeSemantic("birth step"), "");
}

TEST(GltfWriter, LineLoopContoursAtTheirHeights) {
  // Two contours: a square at 100 m (no indices: the vertices in order) and a triangle at 150 m
  // (indexed), both LINE_LOOP; a LINE_STRIP and LINES beside them.
  Primitive square;
  square.mode = Mode::kLineLoop;
  square.mesh.positions = {{0, 100, 0}, {10, 100, 0}, {10, 100, 10}, {0, 100, 10}};
  Primitive triangle;
  triangle.mode = Mode::kLineLoop;
  triangle.mesh.positions = {{2, 150, 2}, {8, 150, 2}, {5, 150, 8}};
  triangle.mesh.indices = {2, 1, 0};
  Primitive strip = square;
  strip.mode = Mode::kLineStrip;
  Primitive lines = square;
  lines.mode = Mode::kLines;
  lines.mesh.indices = {0, 2, 1, 3};
  Result<std::vector<unsigned char>> glb = WriteGlb(OneMesh({square, triangle, strip, lines}));
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  const tinygltf::Model model = Parse(*glb);
  ASSERT_EQ(model.meshes.size(), 1u);
  const std::vector<tinygltf::Primitive>& prims = model.meshes[0].primitives;
  ASSERT_EQ(prims.size(), 4u);
  EXPECT_EQ(prims[0].mode, TINYGLTF_MODE_LINE_LOOP);
  EXPECT_EQ(prims[1].mode, TINYGLTF_MODE_LINE_LOOP);
  EXPECT_EQ(prims[2].mode, TINYGLTF_MODE_LINE_STRIP);
  EXPECT_EQ(prims[3].mode, TINYGLTF_MODE_LINE);
  EXPECT_EQ(prims[0].indices, -1);  // drawn in vertex order
  EXPECT_EQ(prims[0].attributes.count("NORMAL"), 0u);
  EXPECT_EQ(Read<float>(model, prims[0].attributes.at("POSITION")), Flat(square.mesh.positions));
  const tinygltf::Accessor& position =
      model.accessors[static_cast<std::size_t>(prims[1].attributes.at("POSITION"))];
  EXPECT_EQ(position.minValues, (std::vector<double>{2, 150, 2}));
  EXPECT_EQ(position.maxValues, (std::vector<double>{8, 150, 8}));
  const tinygltf::Accessor& indices = model.accessors[static_cast<std::size_t>(prims[1].indices)];
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);  // kAuto, few vertices
  EXPECT_EQ(Read<uint16_t>(model, prims[1].indices), (std::vector<uint16_t>{2, 1, 0}));
  EXPECT_EQ(model.bufferViews[static_cast<std::size_t>(indices.bufferView)].target,
            TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  EXPECT_EQ(Read<uint16_t>(model, prims[3].indices), (std::vector<uint16_t>{0, 2, 1, 3}));
  EXPECT_EQ(model.asset.generator, "niwa");
  EXPECT_EQ(model.asset.version, "2.0");
}

TEST(GltfWriter, CustomAttributesAndColoursAreWrittenByName) {
  Primitive p = Triangle();
  p.mesh.attributes.push_back({"birth_step", 1, {0, 3, 7}});
  p.mesh.attributes.push_back({"COLOR_0", 4, {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 0.5f}});
  p.mesh.attributes.push_back({"density", 2, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f}});
  Result<std::vector<unsigned char>> glb = WriteGlb(OneMesh({p}));
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  const tinygltf::Model model = Parse(*glb);
  const tinygltf::Primitive& prim = model.meshes.at(0).primitives.at(0);
  ASSERT_EQ(prim.attributes.count("_BIRTH_STEP"), 1u);
  ASSERT_EQ(prim.attributes.count("COLOR_0"), 1u);
  ASSERT_EQ(prim.attributes.count("_DENSITY"), 1u);
  const tinygltf::Accessor& birth =
      model.accessors[static_cast<std::size_t>(prim.attributes.at("_BIRTH_STEP"))];
  EXPECT_EQ(birth.type, TINYGLTF_TYPE_SCALAR);
  EXPECT_EQ(birth.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(birth.count, 3u);
  EXPECT_EQ(Read<float>(model, prim.attributes.at("_BIRTH_STEP")), (std::vector<float>{0, 3, 7}));
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(prim.attributes.at("COLOR_0"))].type,
            TINYGLTF_TYPE_VEC4);
  EXPECT_EQ(Read<float>(model, prim.attributes.at("COLOR_0")), p.mesh.attributes[1].values);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(prim.attributes.at("_DENSITY"))].type,
            TINYGLTF_TYPE_VEC2);
  EXPECT_EQ(Read<float>(model, prim.attributes.at("NORMAL")), Flat(p.mesh.normals));

  // More than 65535 vertices: 32-bit indices (kAuto), and kUint32 forces them on small meshes.
  Primitive points;
  points.mode = Mode::kPoints;
  for (uint32_t i = 0; i < 70000; ++i) {
    points.mesh.positions.push_back({static_cast<float>(i % 100), 0, static_cast<float>(i / 100)});
    points.mesh.indices.push_back(69999 - i);
  }
  Primitive forced = Triangle();
  forced.index_type = IndexType::kUint32;
  const tinygltf::Model big = Parse(*WriteGlb(OneMesh({points, forced})));
  const auto& big_prims = big.meshes.at(0).primitives;
  EXPECT_EQ(big.accessors[static_cast<std::size_t>(big_prims[0].indices)].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(Read<uint32_t>(big, big_prims[0].indices), points.mesh.indices);
  EXPECT_EQ(big.accessors[static_cast<std::size_t>(big_prims[1].indices)].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

TEST(GltfWriter, EmbeddedTexturesAndMaterials) {
  image::Rgba8Image pixels = image::MakeRgba8(2, 2, 200, 100, 50, 255);
  pixels.At(1, 1)[3] = 0;
  const std::vector<unsigned char> png = *image::EncodeRgba8Png(pixels);
  const std::vector<unsigned char> normal_png =
      *image::EncodeRgba8Png(image::MakeRgba8(1, 1, 128, 128, 255));
  Document doc = OneMesh({Triangle()});
  doc.textures.push_back({"unused", normal_png});
  doc.textures.push_back({"colour", png, Wrap::kClampToEdge, Wrap::kMirroredRepeat});
  doc.textures.push_back({"normal", normal_png});
  Material unused;
  unused.name = "unused";
  Material leaf;
  leaf.name = "leaf";
  leaf.base_color_factor = {0.5, 1, 1, 1};
  leaf.base_color_texture = 1;
  leaf.normal_texture = 2;
  leaf.normal_scale = 0.5;
  leaf.occlusion_texture = 2;
  leaf.metallic_roughness_texture = 2;
  leaf.metallic_factor = 0;
  leaf.roughness_factor = 0.7;
  leaf.alpha_mode = AlphaMode::kMask;
  leaf.alpha_cutoff = 0.3;
  leaf.double_sided = true;
  leaf.extras_json = R"({"niwa_ivy": false})";
  Material glass;
  glass.name = "glass";
  glass.alpha_mode = AlphaMode::kBlend;
  doc.materials = {unused, leaf, glass};
  doc.meshes[0].primitives[0].material = 1;
  Primitive second = Triangle();
  second.material = 2;
  doc.meshes[0].primitives.push_back(second);
  Result<std::vector<unsigned char>> glb = WriteGlb(doc);
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  const tinygltf::Model model = Parse(*glb);

  // First-use order: leaf, glass, then the unused material; textures likewise.
  ASSERT_EQ(model.materials.size(), 3u);
  const tinygltf::Primitive& prim = model.meshes.at(0).primitives.at(0);
  const tinygltf::Material& mat = model.materials.at(static_cast<std::size_t>(prim.material));
  EXPECT_EQ(mat.name, "leaf");
  EXPECT_EQ(prim.material, 0);
  EXPECT_EQ(model.materials[1].name, "glass");
  EXPECT_EQ(model.materials[1].alphaMode, "BLEND");
  EXPECT_EQ(model.materials[2].name, "unused");
  EXPECT_EQ(mat.alphaMode, "MASK");
  EXPECT_DOUBLE_EQ(mat.alphaCutoff, 0.3);
  EXPECT_TRUE(mat.doubleSided);
  EXPECT_EQ(mat.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{0.5, 1, 1, 1}));
  EXPECT_DOUBLE_EQ(mat.pbrMetallicRoughness.roughnessFactor, 0.7);
  EXPECT_DOUBLE_EQ(mat.pbrMetallicRoughness.metallicFactor, 0.0);
  EXPECT_DOUBLE_EQ(mat.normalTexture.scale, 0.5);
  ASSERT_TRUE(mat.extras.Has("niwa_ivy"));
  EXPECT_FALSE(mat.extras.Get("niwa_ivy").Get<bool>());
  ASSERT_EQ(model.textures.size(), 3u);
  const tinygltf::Texture& colour =
      model.textures.at(static_cast<std::size_t>(mat.pbrMetallicRoughness.baseColorTexture.index));
  EXPECT_EQ(colour.name, "colour");
  EXPECT_EQ(mat.pbrMetallicRoughness.baseColorTexture.index, 0);
  EXPECT_EQ(mat.normalTexture.index, 1);
  EXPECT_EQ(mat.occlusionTexture.index, 1);
  EXPECT_EQ(mat.pbrMetallicRoughness.metallicRoughnessTexture.index, 1);
  const tinygltf::Sampler& sampler = model.samplers.at(static_cast<std::size_t>(colour.sampler));
  EXPECT_EQ(sampler.wrapS, TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
  EXPECT_EQ(sampler.wrapT, TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT);
  EXPECT_EQ(sampler.minFilter, TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR);
  const tinygltf::Image& image = model.images.at(static_cast<std::size_t>(colour.source));
  EXPECT_EQ(image.mimeType, "image/png");
  EXPECT_EQ(image.uri, "");
  EXPECT_EQ(image.image, png);  // the PNG bytes, embedded as given
  Result<image::Rgba8Image> decoded = image::DecodeRgba8Png(image.image.data(), image.image.size());
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded->pixels, pixels.pixels);
  EXPECT_EQ(model.images[2].image, normal_png);  // the unused texture comes last
}

// A normal texture brings TANGENT (geom::ComputeTangentValues) to the triangles using it, and to
// nothing else: not to a material without one, not to lines, not over a TANGENT the caller gave,
// not without uvs.
TEST(GltfWriter, TangentsForNormalTextures) {
  const std::vector<unsigned char> normal_png =
      *image::EncodeRgba8Png(image::MakeRgba8(1, 1, 128, 128, 255));
  Primitive mapped = Triangle();
  mapped.material = 0;
  mapped.mesh.uvs = {{1, 0}, {0, 0}, {1, 1}};  // u mirrored: along -x
  Primitive plain = Triangle();
  plain.material = 1;
  Primitive given = Triangle();
  given.material = 0;
  given.mesh.AddAttribute("TANGENT", 4).values = {0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
  Primitive no_uvs = Triangle();
  no_uvs.material = 0;
  no_uvs.mesh.uvs.clear();
  Primitive lines = Triangle();
  lines.material = 0;
  lines.mode = Mode::kLines;
  lines.mesh.indices = {0, 1, 1, 2};
  Document doc = OneMesh({mapped, plain, given, no_uvs, lines});
  doc.textures.push_back({"normal", normal_png});
  Material bark;
  bark.name = "bark";
  bark.normal_texture = 0;
  Material leaf;
  leaf.name = "leaf";
  doc.materials = {bark, leaf};
  Result<std::vector<unsigned char>> glb = WriteGlb(doc);
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  const tinygltf::Model model = Parse(*glb);
  const auto& prims = model.meshes.at(0).primitives;
  ASSERT_EQ(prims.size(), 5u);
  ASSERT_EQ(prims[0].attributes.count("TANGENT"), 1u);
  const tinygltf::Accessor& accessor =
      model.accessors.at(static_cast<std::size_t>(prims[0].attributes.at("TANGENT")));
  EXPECT_EQ(accessor.type, TINYGLTF_TYPE_VEC4);
  EXPECT_EQ(Read<float>(model, prims[0].attributes.at("TANGENT")),
            (std::vector<float>{-1, 0, 0, 1, -1, 0, 0, 1, -1, 0, 0, 1}));  // cross(z, -x) = -dP/dv
  EXPECT_EQ(prims[1].attributes.count("TANGENT"), 0u);
  EXPECT_EQ(Read<float>(model, prims[2].attributes.at("TANGENT")), given.mesh.attributes[0].values);
  EXPECT_EQ(prims[3].attributes.count("TANGENT"), 0u);
  EXPECT_EQ(prims[4].attributes.count("TANGENT"), 0u);
  // Without the normal texture only the caller's own TANGENT is written.
  doc.materials[0].normal_texture = -1;
  doc.textures.clear();
  Result<std::vector<unsigned char>> bare = WriteGlb(doc);
  ASSERT_TRUE(bare.ok()) << bare.status().Line();
  const tinygltf::Model bare_model = Parse(*bare);
  const auto& bare_prims = bare_model.meshes.at(0).primitives;
  ASSERT_EQ(bare_prims.size(), 5u);
  for (std::size_t i = 0; i < bare_prims.size(); ++i) {
    EXPECT_EQ(bare_prims[i].attributes.count("TANGENT"), i == 2 ? 1u : 0u) << "primitive " << i;
  }
}

TEST(GltfWriter, SkinAndClip) {
  // A two-bone strip: vertices 0-1 on joint 0, 2-3 blended, 4-5 on joint 1.
  Primitive strip;
  for (int i = 0; i < 6; ++i) {
    strip.mesh.positions.push_back({static_cast<float>(i % 2), static_cast<float>(i / 2), 0});
  }
  strip.mesh.indices = {0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5};
  strip.joints = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  strip.weights = {1,    0,    0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,
                   0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1,    0,    0, 0};
  Document doc = OneMesh({strip});
  doc.nodes[0].skin = 0;
  Node root;
  root.name = "root";
  root.children = {2};
  Node tip;
  tip.name = "tip";
  tip.translation = {0, 1, 0};
  doc.nodes.push_back(root);
  doc.nodes.push_back(tip);
  doc.scene_nodes = {0, 1};
  Skin skin;
  skin.name = "strip";
  skin.joints = {1, 2};
  skin.skeleton = 1;
  skin.inverse_bind_matrices = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
  doc.skins.push_back(skin);
  Animation clip;
  clip.name = "bend";
  clip.inputs = {{0.0f, 0.5f, 1.0f}, {0.0f, 2.0f}};
  clip.channels.push_back({2,
                           Path::kRotation,
                           Interpolation::kLinear,
                           0,
                           {0, 0, 0, 1, 0, 0, 0.3826834f, 0.9238795f, 0, 0, 0, 1}});
  clip.channels.push_back({2, Path::kTranslation, Interpolation::kStep, 1, {0, 1, 0, 0, 1.5f, 0}});
  clip.channels.push_back({1, Path::kScale, Interpolation::kLinear, 1, {1, 1, 1, 2, 2, 2}});
  doc.animations.push_back(clip);
  Result<std::vector<unsigned char>> glb = WriteGlb(doc);
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  const tinygltf::Model model = Parse(*glb);

  ASSERT_EQ(model.skins.size(), 1u);
  EXPECT_EQ(model.skins[0].joints, (std::vector<int>{1, 2}));
  EXPECT_EQ(model.skins[0].skeleton, 1);
  EXPECT_EQ(Read<float>(model, model.skins[0].inverseBindMatrices), skin.inverse_bind_matrices);
  EXPECT_EQ(model.nodes[0].skin, 0);
  EXPECT_EQ(model.nodes[2].translation, (std::vector<double>{0, 1, 0}));
  EXPECT_TRUE(model.nodes[1].translation.empty());  // identity TRS is left out
  EXPECT_EQ(model.nodes[1].children, (std::vector<int>{2}));
  const tinygltf::Primitive& prim = model.meshes.at(0).primitives.at(0);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(prim.attributes.at("JOINTS_0"))].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  EXPECT_EQ(Read<uint16_t>(model, prim.attributes.at("JOINTS_0")), strip.joints);
  EXPECT_EQ(Read<float>(model, prim.attributes.at("WEIGHTS_0")), strip.weights);

  ASSERT_EQ(model.animations.size(), 1u);
  const tinygltf::Animation& a = model.animations[0];
  EXPECT_EQ(a.name, "bend");
  ASSERT_EQ(a.channels.size(), 3u);
  ASSERT_EQ(a.samplers.size(), 3u);
  EXPECT_EQ(a.channels[0].target_path, "rotation");
  EXPECT_EQ(a.channels[1].target_path, "translation");
  EXPECT_EQ(a.channels[2].target_path, "scale");
  EXPECT_EQ(a.channels[2].target_node, 1);
  EXPECT_EQ(a.samplers[0].interpolation, "LINEAR");
  EXPECT_EQ(a.samplers[1].interpolation, "STEP");
  EXPECT_EQ(a.samplers[1].input, a.samplers[2].input);  // one accessor per input, shared
  EXPECT_NE(a.samplers[0].input, a.samplers[1].input);
  const tinygltf::Accessor& times = model.accessors[static_cast<std::size_t>(a.samplers[0].input)];
  EXPECT_EQ(times.minValues, (std::vector<double>{0.0}));
  EXPECT_EQ(times.maxValues, (std::vector<double>{1.0}));
  EXPECT_EQ(Read<float>(model, a.samplers[0].input), clip.inputs[0]);
  EXPECT_EQ(Read<float>(model, a.samplers[0].output), clip.channels[0].values);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(a.samplers[0].output)].type,
            TINYGLTF_TYPE_VEC4);
  EXPECT_EQ(Read<float>(model, a.samplers[1].output), clip.channels[1].values);
}

TEST(GltfWriter, ExtrasMatrixJsonAndDeterminism) {
  Document doc = OneMesh({Triangle()});
  doc.asset_extras_json = R"({"seed": 3, "params": {"t1": 0.25}, "steps": [10, 20]})";
  doc.nodes[0].matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
  doc.nodes[0].extras_json = R"({"species": "sugigoke", "birth_day": 12})";
  Result<std::vector<unsigned char>> glb = WriteGlb(doc);
  ASSERT_TRUE(glb.ok()) << glb.status().Line();
  EXPECT_EQ(*WriteGlb(doc), *glb);
  const tinygltf::Model model = Parse(*glb);
  EXPECT_EQ(model.asset.extras.Get("seed").Get<int>(), 3);
  EXPECT_DOUBLE_EQ(model.asset.extras.Get("params").Get("t1").Get<double>(), 0.25);
  EXPECT_EQ(model.asset.extras.Get("steps").ArrayLen(), 2u);
  EXPECT_EQ(model.nodes[0].extras.Get("species").Get<std::string>(), "sugigoke");
  EXPECT_EQ(model.nodes[0].matrix[12], 5.0);

  // .gltf JSON: the buffer as a data URI, the same content.
  Result<std::string> json = WriteGltfJson(doc);
  ASSERT_TRUE(json.ok()) << json.status().Line();
  EXPECT_NE(json->find("data:application/octet-stream;base64,"), std::string::npos);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(KeepImageBytes, nullptr);
  tinygltf::Model text_model;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadASCIIFromString(&text_model, &err, &warn, json->data(),
                                         static_cast<unsigned int>(json->size()), ""))
      << err;
  EXPECT_EQ(text_model.accessors.size(), model.accessors.size());
  EXPECT_EQ(text_model.buffers.at(0).data, model.buffers.at(0).data);

  // EXT_mesh_gpu_instancing: three copies of the mesh, translated and scaled.
  Document instanced = OneMesh({Triangle()});
  instanced.nodes[0].instance_translations = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  instanced.nodes[0].instance_scales = {1, 1, 1, 2, 2, 2, 0.5f, 0.5f, 0.5f};
  const tinygltf::Model copies = Parse(*WriteGlb(instanced));
  EXPECT_EQ(copies.extensionsUsed, (std::vector<std::string>{"EXT_mesh_gpu_instancing"}));
  ASSERT_EQ(copies.nodes.at(0).extensions.count("EXT_mesh_gpu_instancing"), 1u);
  const tinygltf::Value& ext = copies.nodes[0].extensions.at("EXT_mesh_gpu_instancing");
  const int translations = ext.Get("attributes").Get("TRANSLATION").Get<int>();
  EXPECT_EQ(Read<float>(copies, translations), instanced.nodes[0].instance_translations);
  EXPECT_EQ(Read<float>(copies, ext.Get("attributes").Get("SCALE").Get<int>()),
            instanced.nodes[0].instance_scales);
  EXPECT_FALSE(ext.Get("attributes").Has("ROTATION"));

  // A scene without meshes has no buffer.
  Document empty;
  empty.nodes.push_back({});
  empty.scene_nodes = {0};
  const tinygltf::Model bare = Parse(*WriteGlb(empty));
  EXPECT_TRUE(bare.buffers.empty());
  EXPECT_EQ(bare.nodes.size(), 1u);
}

TEST(GltfWriter, BadDocumentsAreOneLineErrors) {
  Document doc = OneMesh({Triangle()});
  Material leaves;
  leaves.name = "leaves";
  doc.materials.push_back(leaves);
  doc.meshes[0].primitives[0].material = 0;
  ASSERT_TRUE(WriteGlb(doc).ok());

  Document bad = doc;
  bad.meshes[0].primitives[0].mesh.indices[2] = 3;
  ExpectError(bad, "meshes[0] 'm' primitives[0] (leaves): index 3 out of range; must be < 3");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.indices.push_back(0);
  ExpectError(bad, "must be a multiple of 3");
  bad = doc;
  bad.meshes[0].primitives[0].mode = Mode::kLines;
  ExpectError(bad, "LINES; must be a multiple of 2");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.normals.pop_back();
  ExpectError(bad, "2 normals for 3 vertices");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.positions[1].y = std::nanf("");
  ExpectError(bad, "position is not finite");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.attributes.push_back({"birth_step", 1, {1, 2}});
  ExpectError(bad, "attribute 'birth_step': 2 values; must be 3");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.attributes.push_back({"COLOR_0", 2, {1, 2, 3, 4, 5, 6}});
  ExpectError(bad, "a colour must have 3 or 4");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.attributes.push_back({"TANGENT", 3, std::vector<float>(9, 0)});
  ExpectError(bad, "a tangent must have 4");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.attributes.push_back({"normal", 3, std::vector<float>(9, 0)});
  bad.meshes[0].primitives[0].mesh.attributes.push_back({"NORMAL", 3, std::vector<float>(9, 0)});
  ExpectError(bad, "written as _NORMAL, which is already written");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.attributes.push_back({"birth-step", 1, {1, 2, 3}});
  ExpectError(bad, "letters, digits and '_'");
  bad = doc;
  bad.meshes[0].primitives[0].material = 4;
  ExpectError(bad, "material 4 out of range");
  bad = doc;
  bad.meshes[0].primitives.clear();
  ExpectError(bad, "no primitives");
  bad = doc;
  bad.meshes[0].primitives[0].mesh.positions.clear();
  bad.meshes[0].primitives[0].mesh.normals.clear();
  bad.meshes[0].primitives[0].mesh.uvs.clear();
  bad.meshes[0].primitives[0].mesh.indices.clear();
  ExpectError(bad, "no vertices");
  bad = doc;
  bad.textures.push_back({"bark", {1, 2, 3}});
  ExpectError(bad, "textures[0] 'bark': png must hold PNG file bytes");
  bad = doc;
  bad.materials[0].base_color_texture = 0;
  ExpectError(bad, "texture 0 out of range");
  bad = doc;
  bad.meshes[0].primitives[0].joints = std::vector<uint16_t>(12, 0);
  ExpectError(bad, "joints and weights must both be empty or 4 per vertex");
  bad = doc;
  bad.nodes[0].children = {0};
  ExpectError(bad, "more than one parent");
  bad = doc;
  bad.nodes.push_back({});
  bad.nodes.push_back({});
  bad.nodes[1].children = {2};
  bad.nodes[2].children = {1};
  ExpectError(bad, "cycle");
  bad = doc;
  bad.scene_nodes = {5};
  ExpectError(bad, "scene nodes: node 5 out of range");
  bad = doc;
  bad.nodes[0].lod_ids = {3};
  ExpectError(bad, "lod_ids: node 3 out of range");
  bad = doc;
  bad.nodes[0].lod_ids = {0};
  ExpectError(bad, "lists itself as a lower LOD");
  bad = doc;
  bad.nodes[0].matrix = {1, 0, 0};
  ExpectError(bad, "matrix must have 16 values");
  bad = doc;
  bad.nodes[0].skin = 0;
  ExpectError(bad, "skin 0 must be -1 or < 0");
  bad = doc;
  bad.nodes[0].instance_translations = {0, 0, 0, 1, 0, 0};
  bad.nodes[0].instance_rotations = {0, 0, 0, 1};
  ExpectError(bad, "must each be empty or agree on the instance count");
  bad = doc;
  bad.asset_extras_json = "{seed: 3";
  ExpectError(bad, "asset: extras must be JSON text");
  bad = doc;
  bad.skins.push_back({"s", {0}, -1, {}});
  bad.nodes[0].skin = 0;
  bad.meshes[0].primitives[0].joints = std::vector<uint16_t>(12, 0);
  bad.meshes[0].primitives[0].weights = std::vector<float>(12, 0.25f);
  bad.meshes[0].primitives[0].joints[5] = 1;
  ExpectError(bad, "joint 1 out of range; the skin has 1 joints");
  bad = doc;
  bad.animations.push_back(
      {"a",
       {{0.0f, 1.0f, 1.0f}},
       {{0, Path::kTranslation, Interpolation::kLinear, 0, std::vector<float>(9, 0)}}});
  ExpectError(bad, "key times must increase strictly");
  bad = doc;
  bad.animations.push_back(
      {"a",
       {{0.0f, 1.0f}},
       {{0, Path::kRotation, Interpolation::kLinear, 0, std::vector<float>(6, 0)}}});
  ExpectError(bad, "animations[0] 'a' channels[0]: 6 values for 2 keys; must be 8");
  bad = doc;
  bad.animations.push_back(
      {"a", {{0.0f}}, {{0, Path::kScale, Interpolation::kStep, 1, {1, 1, 1}}}});
  ExpectError(bad, "input 1 out of range");
}

}  // namespace
}  // namespace niwa::gltf
