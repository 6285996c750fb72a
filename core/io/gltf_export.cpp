// Binary glTF 2.0 (.glb) export of a tree mesh with tinygltf, into memory (the one tinygltf TU).
#include "io/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#ifndef TINYGLTF_USE_CPP14
#define TINYGLTF_USE_CPP14
#endif
#include <tiny_gltf.h>

#include "render/textures.h"

namespace niwa {
namespace {

// glTF enums (spec 5.1.3, 5.11.2).
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// glTF sampler enums (spec 5.26).
constexpr int kLinear = 9729;
constexpr int kLinearMipmapLinear = 9987;
constexpr int kRepeat = 10497;
constexpr int kClampToEdge = 33071;

enum class TextureKind { kBark, kLeaf, kFlower };

// The base colour comes from the texture (factor white); leaves and flowers are cut out by alpha.
struct MaterialSpec {
  const char* name;
  TextureKind texture;
  double roughness;
  bool double_sided;
  bool alpha_mask;
};

// Appends raw bytes to the buffer at a 4-byte aligned offset; returns the new bufferView's index.
template <typename T>
int AddBufferView(tinygltf::Model* model, const std::vector<T>& data, int target) {
  std::vector<unsigned char>& buffer = model->buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = data.size() * sizeof(T);
  view.target = target;
  std::size_t offset = buffer.size();
  buffer.resize(offset + view.byteLength);
  std::memcpy(buffer.data() + offset, data.data(), view.byteLength);
  model->bufferViews.push_back(std::move(view));
  return static_cast<int>(model->bufferViews.size()) - 1;
}

int AddAccessor(tinygltf::Model* model, int view, int component_type, int type, std::size_t count,
                std::vector<double> min_values = {}, std::vector<double> max_values = {}) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  accessor.normalized = false;
  accessor.minValues = std::move(min_values);
  accessor.maxValues = std::move(max_values);
  model->accessors.push_back(std::move(accessor));
  return static_cast<int>(model->accessors.size()) - 1;
}

// Appends a PNG image (its own bufferView, no target), a sampler and a texture; returns the
// texture's index.
int AddPngTexture(tinygltf::Model* model, const std::vector<unsigned char>& png, const char* name,
                  int wrap) {
  if (png.empty()) return -1;  // encoding failed: the material stays untextured
  tinygltf::Image image;
  image.name = name;
  image.mimeType = "image/png";
  image.bufferView = AddBufferView(model, png, 0);
  model->images.push_back(std::move(image));
  tinygltf::Sampler sampler;
  sampler.magFilter = kLinear;
  sampler.minFilter = kLinearMipmapLinear;
  sampler.wrapS = wrap;
  sampler.wrapT = wrap;
  model->samplers.push_back(std::move(sampler));
  tinygltf::Texture texture;
  texture.name = name;
  texture.source = static_cast<int>(model->images.size()) - 1;
  texture.sampler = static_cast<int>(model->samplers.size()) - 1;
  model->textures.push_back(std::move(texture));
  return static_cast<int>(model->textures.size()) - 1;
}

// Bark repeats around (u 0..1) and along the wood (one repeat per metre of v); leaf and flower
// textures cover their quad or star once and are clamped.
int AddTexture(tinygltf::Model* model, TextureKind kind) {
  switch (kind) {
    case TextureKind::kBark:
      return AddPngTexture(model, EncodePng(MakeBarkTexture()), "bark", kRepeat);
    case TextureKind::kLeaf:
      return AddPngTexture(model, EncodePng(MakeLeafTexture()), "leaf", kClampToEdge);
    case TextureKind::kFlower:
    default:
      return AddPngTexture(model, EncodePng(MakeFlowerTexture()), "flower", kClampToEdge);
  }
}

int AddMaterial(tinygltf::Model* model, const MaterialSpec& spec) {
  tinygltf::Material material;
  material.name = spec.name;
  material.emissiveFactor = {0.0, 0.0, 0.0};  // tinygltf would otherwise write an empty array
  material.doubleSided = spec.double_sided;
  if (spec.alpha_mask) {
    material.alphaMode = "MASK";
    material.alphaCutoff = 0.5;  // the default, so tinygltf leaves it out of the JSON
  }
  material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
  material.pbrMetallicRoughness.baseColorTexture.index = AddTexture(model, spec.texture);
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = spec.roughness;
  model->materials.push_back(std::move(material));
  return static_cast<int>(model->materials.size()) - 1;
}

// Checks the buffers of one primitive; returns "" or what is wrong.
std::string CheckBuffers(const MeshBuffers& buffers, const char* name) {
  std::size_t vertices = buffers.vertex_count();
  if (buffers.positions.size() != vertices * 3 || buffers.normals.size() != vertices * 3 ||
      buffers.uvs.size() != vertices * 2) {
    return std::string(name) + ": positions, normals and uvs disagree on the vertex count";
  }
  if (buffers.indices.size() % 3 != 0) {
    return std::string(name) + ": index count is not a multiple of 3";
  }
  if (vertices > std::numeric_limits<uint32_t>::max()) {
    return std::string(name) + ": too many vertices for 32-bit indices";
  }
  for (uint32_t index : buffers.indices) {
    if (index >= vertices) return std::string(name) + ": index out of range";
  }
  for (float x : buffers.positions) {
    if (!std::isfinite(x)) return std::string(name) + ": position is not finite";
  }
  return "";
}

void AddPrimitive(tinygltf::Model* model, const MeshBuffers& buffers, const MaterialSpec& spec,
                  const std::vector<uint16_t>* joints, const std::vector<float>* weights) {
  std::vector<double> lo(3, std::numeric_limits<double>::infinity());
  std::vector<double> hi(3, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < buffers.positions.size(); ++i) {
    double x = static_cast<double>(buffers.positions[i]);  // exact float32 values, as required
    lo[i % 3] = std::min(lo[i % 3], x);
    hi[i % 3] = std::max(hi[i % 3], x);
  }
  std::size_t vertices = buffers.vertex_count();
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      AddAccessor(model, AddBufferView(model, buffers.positions, kArrayBuffer),
                  TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices, lo, hi);
  primitive.attributes["NORMAL"] =
      AddAccessor(model, AddBufferView(model, buffers.normals, kArrayBuffer),
                  TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices);
  primitive.attributes["TEXCOORD_0"] =
      AddAccessor(model, AddBufferView(model, buffers.uvs, kArrayBuffer),
                  TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, vertices);
  primitive.indices = AddAccessor(model, AddBufferView(model, buffers.indices, kElementArrayBuffer),
                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                  buffers.indices.size());
  if (joints != nullptr && weights != nullptr) {
    primitive.attributes["JOINTS_0"] =
        AddAccessor(model, AddBufferView(model, *joints, kArrayBuffer),
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, vertices);
    primitive.attributes["WEIGHTS_0"] =
        AddAccessor(model, AddBufferView(model, *weights, kArrayBuffer),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, vertices);
  }
  primitive.material = AddMaterial(model, spec);
  model->meshes[0].primitives.push_back(std::move(primitive));
}

// Checks the skin against the mesh; returns "" or what is wrong.
std::string CheckSkinning(const GltfSkinning& skin, const MeshBuffers* const (&parts)[3]) {
  if (skin.joints.empty()) return "skin: no joints";
  if (skin.joints.size() > kMaxGltfJoints) return "skin: more than 65536 joints";
  for (std::size_t k = 0; k < 3; ++k) {
    std::size_t n = 4 * parts[k]->vertex_count();
    if (skin.joints0[k].size() != n || skin.weights0[k].size() != n) {
      return "skin: joints/weights disagree with the vertex count";
    }
    for (uint16_t j : skin.joints0[k]) {
      if (j >= skin.joints.size()) return "skin: joint index out of range";
    }
  }
  for (std::size_t k = 1; k < skin.times.size(); ++k) {
    if (!(skin.times[k] > skin.times[k - 1])) return "animation: times must increase";
  }
  for (const GltfJoint& joint : skin.joints) {
    if (joint.translation_keys.empty() && joint.rotation_keys.empty()) continue;
    if (joint.translation_keys.size() != 3 * skin.times.size() ||
        joint.rotation_keys.size() != 4 * skin.times.size()) {
      return "animation: keys disagree with the times";
    }
  }
  return "";
}

// Skeleton nodes, the skin and the clip; `mesh_node` gets the skin.
void AddSkinAndAnimation(tinygltf::Model* model, const GltfSkinning& skin, int mesh_node) {
  const int first = static_cast<int>(model->nodes.size());
  tinygltf::Skin gltf_skin;
  gltf_skin.name = "tree";
  gltf_skin.skeleton = first;
  std::vector<float> inverse_bind;
  for (std::size_t j = 0; j < skin.joints.size(); ++j) {
    const GltfJoint& joint = skin.joints[j];
    tinygltf::Node node;
    node.name = joint.name;
    if (joint.translation != std::array<float, 3>{0, 0, 0}) {
      node.translation = {joint.translation[0], joint.translation[1], joint.translation[2]};
    }
    if (j == 0) {
      for (std::size_t c = 1; c < skin.joints.size(); ++c)
        node.children.push_back(first + static_cast<int>(c));
    }
    model->nodes.push_back(std::move(node));
    gltf_skin.joints.push_back(first + static_cast<int>(j));
    const std::array<float, 3>& o = joint.inverse_bind_offset;  // column-major 4x4
    inverse_bind.insert(inverse_bind.end(),
                        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, o[0], o[1], o[2], 1});
  }
  gltf_skin.inverseBindMatrices =
      AddAccessor(model, AddBufferView(model, inverse_bind, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                  TINYGLTF_TYPE_MAT4, skin.joints.size());
  model->skins.push_back(std::move(gltf_skin));
  model->nodes[static_cast<std::size_t>(mesh_node)].skin = 0;

  if (skin.times.empty()) return;
  tinygltf::Animation clip;
  clip.name = skin.clip_name;
  const int input = AddAccessor(model, AddBufferView(model, skin.times, 0),
                                TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                                skin.times.size(), {static_cast<double>(skin.times.front())},
                                {static_cast<double>(skin.times.back())});
  auto add_channel = [&](int node, const std::vector<float>& keys, int type, const char* path) {
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.interpolation = "LINEAR";
    sampler.output = AddAccessor(model, AddBufferView(model, keys, 0),
                                 TINYGLTF_COMPONENT_TYPE_FLOAT, type, skin.times.size());
    clip.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(clip.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    clip.channels.push_back(std::move(channel));
  };
  for (std::size_t j = 0; j < skin.joints.size(); ++j) {
    const GltfJoint& joint = skin.joints[j];
    if (joint.translation_keys.empty()) continue;
    add_channel(first + static_cast<int>(j), joint.translation_keys, TINYGLTF_TYPE_VEC3,
                "translation");
    add_channel(first + static_cast<int>(j), joint.rotation_keys, TINYGLTF_TYPE_VEC4, "rotation");
  }
  model->animations.push_back(std::move(clip));
}

std::string WriteModel(const TreeMesh& mesh, const GltfSkinning* skin,
                       std::vector<unsigned char>* bytes) {
  if (bytes == nullptr) return "no output buffer";
  bytes->clear();
  struct Part {
    const MeshBuffers* buffers;
    MaterialSpec material;
  };
  const Part parts[] = {
      {&mesh.bark, {"bark", TextureKind::kBark, 0.9, false, false}},
      {&mesh.leaves, {"leaves", TextureKind::kLeaf, 0.7, true, true}},
      {&mesh.flowers, {"flowers", TextureKind::kFlower, 0.6, true, true}},
  };
  for (const Part& part : parts) {
    std::string error = CheckBuffers(*part.buffers, part.material.name);
    if (!error.empty()) return error;
  }
  if (skin != nullptr) {
    const MeshBuffers* const buffers[3] = {&mesh.bark, &mesh.leaves, &mesh.flowers};
    std::string error = CheckSkinning(*skin, buffers);
    if (!error.empty()) return error;
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "niwa";
  tinygltf::Node node;
  node.name = "tree";
  bool any = std::any_of(std::begin(parts), std::end(parts),
                         [](const Part& p) { return !p.buffers->indices.empty(); });
  if (any) {
    model.buffers.emplace_back();
    model.meshes.emplace_back();
    model.meshes[0].name = "tree";
    for (std::size_t k = 0; k < 3; ++k) {
      const Part& part = parts[k];
      if (part.buffers->indices.empty()) continue;
      AddPrimitive(&model, *part.buffers, part.material, skin ? &skin->joints0[k] : nullptr,
                   skin ? &skin->weights0[k] : nullptr);
    }
    node.mesh = 0;
  }
  model.nodes.push_back(std::move(node));
  tinygltf::Scene scene;
  scene.name = "tree";
  scene.nodes.push_back(0);
  if (any && skin != nullptr) {
    AddSkinAndAnimation(&model, *skin, 0);
    scene.nodes.push_back(1);  // the skeleton root
  }
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;

  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, stream, false, true) || !stream) {
    return "glTF serialization failed";
  }
  const std::string glb = stream.str();
  bytes->assign(glb.begin(), glb.end());
  return "";
}

}  // namespace

std::string WriteGlb(const TreeMesh& mesh, std::vector<unsigned char>* bytes) {
  return WriteModel(mesh, nullptr, bytes);
}

std::string WriteSkinnedGlb(const TreeMesh& mesh, const GltfSkinning& skinning,
                            std::vector<unsigned char>* bytes) {
  return WriteModel(mesh, &skinning, bytes);
}

}  // namespace niwa
