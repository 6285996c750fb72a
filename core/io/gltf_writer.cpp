// Generic glTF 2.0 writer over tinygltf: checks a Document, lays out one buffer, serializes .glb
// or .gltf (see gltf_writer.h for what is written and in which order).
#include "io/gltf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/budget.h"
#include "geom/tangents.h"
#include "io/tinygltf.h"
#include "params/json_guard.h"

namespace niwa::gltf {
namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "glm::vec3 must be tightly packed");
static_assert(sizeof(glm::vec2) == 2 * sizeof(float), "glm::vec2 must be tightly packed");

// bufferView targets (spec 5.11.2).
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

std::string Quoted(const std::string& name) { return name.empty() ? "" : " '" + name + "'"; }

// Whether the writer computes the primitive's TANGENT (geom::ComputeTangentValues): triangles whose
// material has a normal texture, with normals and uvs and no TANGENT of their own (glTF 3.9.3 reads
// a normal texture in the tangent space these give; without them the validator warns).
bool NeedsTangents(const Primitive& p, const Document& doc) {
  if (p.mode != Mode::kTriangles || p.material < 0 ||
      static_cast<std::size_t>(p.material) >= doc.materials.size() ||
      doc.materials[static_cast<std::size_t>(p.material)].normal_texture < 0 ||
      p.mesh.normals.empty() || p.mesh.uvs.empty()) {
    return false;
  }
  return std::none_of(
      p.mesh.attributes.begin(), p.mesh.attributes.end(),
      [](const geom::VertexAttribute& a) { return a.name == geom::kTangentAttribute; });
}

// Converts parsed JSON to tinygltf's extras value.
tinygltf::Value ToValue(const nlohmann::json& j) {
  if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
  if (j.is_number_integer() && j.get<long long>() >= std::numeric_limits<int>::min() &&
      j.get<long long>() <= std::numeric_limits<int>::max()) {
    return tinygltf::Value(static_cast<int>(j.get<long long>()));
  }
  if (j.is_number()) return tinygltf::Value(j.get<double>());
  if (j.is_string()) return tinygltf::Value(j.get<std::string>());
  if (j.is_array()) {
    tinygltf::Value::Array array;
    for (const nlohmann::json& item : j) array.push_back(ToValue(item));
    return tinygltf::Value(std::move(array));
  }
  if (j.is_object()) {
    tinygltf::Value::Object object;
    for (auto it = j.begin(); it != j.end(); ++it) object[it.key()] = ToValue(it.value());
    return tinygltf::Value(std::move(object));
  }
  return tinygltf::Value();  // null: no extras
}

Status ParseExtras(const std::string& text, const std::string& field, tinygltf::Value* out) {
  if (text.empty()) return Status::Ok();
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, field));  // ToValue recurses: depth is capped first
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return Status::Error(field, "extras must be JSON text");
  *out = ToValue(j);
  return Status::Ok();
}

template <typename T>
bool AllFinite(const std::vector<T>& values) {
  return std::all_of(values.begin(), values.end(), [](const T& v) {
    const float* f = reinterpret_cast<const float*>(&v);
    for (std::size_t k = 0; k < sizeof(T) / sizeof(float); ++k)
      if (!std::isfinite(f[k])) return false;
    return true;
  });
}

bool IsStandard(const std::string& name, const char* prefix) {
  const std::size_t n = std::strlen(prefix);
  if (name.size() <= n || name.compare(0, n, prefix) != 0) return false;
  return std::all_of(name.begin() + static_cast<long>(n), name.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

// Checks one primitive; `where` names it.
Status CheckPrimitive(const Primitive& p, const Document& doc, const std::string& where) {
  const geom::TriMesh& m = p.mesh;
  const std::size_t n = m.vertex_count();
  if (n == 0) return Status::Error(where, "no vertices; a primitive needs at least one");
  if (n > std::numeric_limits<uint32_t>::max()) {
    return Status::Error(where, "too many vertices for 32-bit indices");
  }
  if (!m.normals.empty() && m.normals.size() != n) {
    return Status::Error(where, std::to_string(m.normals.size()) + " normals for " +
                                    std::to_string(n) + " vertices; must be 0 or " +
                                    std::to_string(n));
  }
  if (!m.uvs.empty() && m.uvs.size() != n) {
    return Status::Error(where, std::to_string(m.uvs.size()) + " uvs for " + std::to_string(n) +
                                    " vertices; must be 0 or " + std::to_string(n));
  }
  if (!AllFinite(m.positions)) return Status::Error(where, "a position is not finite");
  if (!AllFinite(m.normals)) return Status::Error(where, "a normal is not finite");
  if (!AllFinite(m.uvs)) return Status::Error(where, "a uv is not finite");
  const std::size_t count = m.indices.empty() ? n : m.indices.size();
  switch (p.mode) {
    case Mode::kTriangles:
      if (count % 3 != 0) {
        return Status::Error(
            where, std::to_string(count) + " indices for TRIANGLES; must be a multiple of 3");
      }
      break;
    case Mode::kLines:
      if (count % 2 != 0) {
        return Status::Error(where,
                             std::to_string(count) + " indices for LINES; must be a multiple of 2");
      }
      break;
    case Mode::kLineStrip:
    case Mode::kLineLoop:
      if (count < 2) {
        return Status::Error(
            where, std::to_string(count) + " points for a line strip or loop; must be at least 2");
      }
      break;
    case Mode::kPoints:
      break;
    default:
      return Status::Error(where, "mode must be POINTS, LINES, LINE_LOOP, LINE_STRIP or TRIANGLES");
  }
  for (uint32_t index : m.indices) {
    if (index >= n) {
      return Status::Error(where, "index " + std::to_string(index) + " out of range; must be < " +
                                      std::to_string(n) + " (the vertex count)");
    }
  }
  if (p.index_type == IndexType::kUint16 && n > 65535) {
    return Status::Error(
        where, std::to_string(n) + " vertices with 16-bit indices; must be at most 65535");
  }
  std::vector<std::string> semantics = {"POSITION", "NORMAL", "TEXCOORD_0", "JOINTS_0",
                                        "WEIGHTS_0"};
  for (const geom::VertexAttribute& a : m.attributes) {
    const std::string semantic = AttributeSemantic(a.name);
    const std::string field = where + " attribute '" + a.name + "'";
    if (semantic.empty()) {
      return Status::Error(field, "name must be non-empty letters, digits and '_'");
    }
    if (std::find(semantics.begin(), semantics.end(), semantic) != semantics.end()) {
      return Status::Error(field, "written as " + semantic + ", which is already written");
    }
    semantics.push_back(semantic);
    const bool colour = IsStandard(semantic, "COLOR_");
    const bool texcoord = IsStandard(semantic, "TEXCOORD_");
    if (colour && a.components != 3 && a.components != 4) {
      return Status::Error(field,
                           std::to_string(a.components) + " components; a colour must have 3 or 4");
    }
    if (semantic == "TANGENT" && a.components != 4) {
      return Status::Error(field, std::to_string(a.components) +
                                      " components; a tangent must have 4 (xyz, w = +-1)");
    }
    if (texcoord && a.components != 2) {
      return Status::Error(
          field, std::to_string(a.components) + " components; a texture coordinate must have 2");
    }
    if (a.components < 1 || a.components > 4) {
      return Status::Error(field, std::to_string(a.components) + " components; must be 1 to 4");
    }
    if (a.values.size() != n * static_cast<std::size_t>(a.components)) {
      return Status::Error(field, std::to_string(a.values.size()) + " values; must be " +
                                      std::to_string(n * static_cast<std::size_t>(a.components)) +
                                      " (components x vertices)");
    }
    if (!AllFinite(a.values)) return Status::Error(field, "a value is not finite");
  }
  if (p.joints.size() != p.weights.size() || (!p.joints.empty() && p.joints.size() != 4 * n)) {
    return Status::Error(where, "joints and weights must both be empty or 4 per vertex (" +
                                    std::to_string(4 * n) + ")");
  }
  if (!AllFinite(p.weights)) return Status::Error(where, "a weight is not finite");
  if (p.material < -1 || p.material >= static_cast<int>(doc.materials.size())) {
    return Status::Error(where, "material " + std::to_string(p.material) +
                                    " out of range; must be -1 or < " +
                                    std::to_string(doc.materials.size()));
  }
  return Status::Ok();
}

Status CheckTextureIndex(int index, const Document& doc, const std::string& field) {
  if (index < -1 || index >= static_cast<int>(doc.textures.size())) {
    return Status::Error(field, "texture " + std::to_string(index) +
                                    " out of range; must be -1 or < " +
                                    std::to_string(doc.textures.size()));
  }
  return Status::Ok();
}

Status CheckNodeIndex(int index, const Document& doc, const std::string& field) {
  if (index < 0 || index >= static_cast<int>(doc.nodes.size())) {
    return Status::Error(field, "node " + std::to_string(index) + " out of range; must be < " +
                                    std::to_string(doc.nodes.size()));
  }
  return Status::Ok();
}

Status CheckDocument(const Document& doc) {
  for (std::size_t i = 0; i < doc.textures.size(); ++i) {
    const Texture& t = doc.textures[i];
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    if (t.png.size() < 8 || !std::equal(kPng, kPng + 8, t.png.begin())) {
      return Status::Error("textures[" + std::to_string(i) + "]" + Quoted(t.name),
                           "png must hold PNG file bytes");
    }
  }
  for (std::size_t i = 0; i < doc.materials.size(); ++i) {
    const Material& m = doc.materials[i];
    const std::string field = "materials[" + std::to_string(i) + "]" + Quoted(m.name);
    for (int t : {m.base_color_texture, m.metallic_roughness_texture, m.normal_texture,
                  m.occlusion_texture}) {
      NIWA_RETURN_IF_ERROR(CheckTextureIndex(t, doc, field));
    }
    if (!(m.alpha_cutoff >= 0)) return Status::Error(field, "alpha_cutoff must be >= 0");
  }
  for (std::size_t i = 0; i < doc.meshes.size(); ++i) {
    const Mesh& mesh = doc.meshes[i];
    const std::string field = "meshes[" + std::to_string(i) + "]" + Quoted(mesh.name);
    if (mesh.primitives.empty()) return Status::Error(field, "no primitives; needs at least one");
    for (std::size_t k = 0; k < mesh.primitives.size(); ++k) {
      const Primitive& p = mesh.primitives[k];
      std::string where = field + " primitives[" + std::to_string(k) + "]";
      if (p.material >= 0 && p.material < static_cast<int>(doc.materials.size()) &&
          !doc.materials[static_cast<std::size_t>(p.material)].name.empty()) {
        where += " (" + doc.materials[static_cast<std::size_t>(p.material)].name + ")";
      }
      NIWA_RETURN_IF_ERROR(CheckPrimitive(p, doc, where));
    }
  }
  std::vector<int> parent(doc.nodes.size(), -1);
  for (std::size_t i = 0; i < doc.nodes.size(); ++i) {
    const Node& node = doc.nodes[i];
    const std::string field = "nodes[" + std::to_string(i) + "]" + Quoted(node.name);
    if (node.mesh < -1 || node.mesh >= static_cast<int>(doc.meshes.size())) {
      return Status::Error(field, "mesh " + std::to_string(node.mesh) +
                                      " out of range; must be -1 or < " +
                                      std::to_string(doc.meshes.size()));
    }
    if (node.skin < -1 || node.skin >= static_cast<int>(doc.skins.size()) ||
        (node.skin >= 0 && node.mesh < 0)) {
      return Status::Error(field, "skin " + std::to_string(node.skin) + " must be -1 or < " +
                                      std::to_string(doc.skins.size()) + ", on a node with a mesh");
    }
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) return Status::Error(field, "matrix must have 16 values");
      if (node.translation != std::array<double, 3>{0, 0, 0} ||
          node.rotation != std::array<double, 4>{0, 0, 0, 1} ||
          node.scale != std::array<double, 3>{1, 1, 1}) {
        return Status::Error(field, "give a matrix or TRS, not both");
      }
    }
    for (int c : node.children) {
      NIWA_RETURN_IF_ERROR(CheckNodeIndex(c, doc, field + " children"));
      if (parent[static_cast<std::size_t>(c)] >= 0 || c == static_cast<int>(i)) {
        return Status::Error(field, "node " + std::to_string(c) + " has more than one parent");
      }
      parent[static_cast<std::size_t>(c)] = static_cast<int>(i);
    }
    for (int l : node.lod_ids) {
      NIWA_RETURN_IF_ERROR(CheckNodeIndex(l, doc, field + " lod_ids"));
      if (l == static_cast<int>(i)) return Status::Error(field, "lists itself as a lower LOD");
    }
    const std::size_t instances = node.instance_count();
    if (!node.instance_translations.empty() || !node.instance_rotations.empty() ||
        !node.instance_scales.empty()) {
      if (node.mesh < 0 || node.skin >= 0) {
        return Status::Error(field, "instances need a mesh and no skin");
      }
      if (instances == 0 ||
          (!node.instance_translations.empty() &&
           node.instance_translations.size() != 3 * instances) ||
          (!node.instance_rotations.empty() && node.instance_rotations.size() != 4 * instances) ||
          (!node.instance_scales.empty() && node.instance_scales.size() != 3 * instances)) {
        return Status::Error(field,
                             "instance translations (3), rotations (4) and scales (3 per "
                             "instance) must each be empty or agree on the instance count");
      }
      if (!AllFinite(node.instance_translations) || !AllFinite(node.instance_rotations) ||
          !AllFinite(node.instance_scales)) {
        return Status::Error(field, "an instance transform is not finite");
      }
    }
    if (node.skin >= 0) {  // joint indices within the skin
      const std::size_t joints = doc.skins[static_cast<std::size_t>(node.skin)].joints.size();
      for (const Primitive& p : doc.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
        for (uint16_t j : p.joints) {
          if (j >= joints) {
            return Status::Error(field, "joint " + std::to_string(j) +
                                            " out of range; the skin has " +
                                            std::to_string(joints) + " joints");
          }
        }
      }
    }
  }
  for (std::size_t i = 0; i < doc.nodes.size(); ++i) {  // no cycles: every chain of parents ends
    int at = static_cast<int>(i);
    for (std::size_t steps = 0; at >= 0; ++steps) {
      if (steps > doc.nodes.size()) {
        return Status::Error("nodes[" + std::to_string(i) + "]", "is part of a cycle of children");
      }
      at = parent[static_cast<std::size_t>(at)];
    }
  }
  for (int root : doc.scene_nodes) {
    NIWA_RETURN_IF_ERROR(CheckNodeIndex(root, doc, "scene nodes"));
    if (parent[static_cast<std::size_t>(root)] >= 0) {
      return Status::Error("scene nodes", "node " + std::to_string(root) +
                                              " is a child of another node; roots must not be");
    }
  }
  for (std::size_t i = 0; i < doc.skins.size(); ++i) {
    const Skin& skin = doc.skins[i];
    const std::string field = "skins[" + std::to_string(i) + "]" + Quoted(skin.name);
    if (skin.joints.empty()) return Status::Error(field, "no joints; needs at least one");
    for (int j : skin.joints) NIWA_RETURN_IF_ERROR(CheckNodeIndex(j, doc, field + " joints"));
    if (skin.skeleton != -1) NIWA_RETURN_IF_ERROR(CheckNodeIndex(skin.skeleton, doc, field));
    if (!skin.inverse_bind_matrices.empty() &&
        skin.inverse_bind_matrices.size() != 16 * skin.joints.size()) {
      return Status::Error(field, "inverse_bind_matrices must be empty or 16 per joint");
    }
    if (!AllFinite(skin.inverse_bind_matrices)) {
      return Status::Error(field, "an inverse bind matrix is not finite");
    }
  }
  for (std::size_t i = 0; i < doc.animations.size(); ++i) {
    const Animation& a = doc.animations[i];
    const std::string field = "animations[" + std::to_string(i) + "]" + Quoted(a.name);
    if (a.channels.empty()) return Status::Error(field, "no channels; needs at least one");
    for (std::size_t k = 0; k < a.inputs.size(); ++k) {
      const std::vector<float>& t = a.inputs[k];
      const std::string where = field + " inputs[" + std::to_string(k) + "]";
      if (t.empty()) return Status::Error(where, "no key times; needs at least one");
      if (!AllFinite(t) || t.front() < 0) {
        return Status::Error(where, "key times must be finite and >= 0");
      }
      for (std::size_t j = 1; j < t.size(); ++j) {
        if (!(t[j] > t[j - 1])) return Status::Error(where, "key times must increase strictly");
      }
    }
    for (std::size_t k = 0; k < a.channels.size(); ++k) {
      const Channel& c = a.channels[k];
      const std::string where = field + " channels[" + std::to_string(k) + "]";
      NIWA_RETURN_IF_ERROR(CheckNodeIndex(c.node, doc, where));
      if (c.input < 0 || c.input >= static_cast<int>(a.inputs.size())) {
        return Status::Error(where, "input " + std::to_string(c.input) +
                                        " out of range; must be < " +
                                        std::to_string(a.inputs.size()));
      }
      const std::size_t width = c.path == Path::kRotation ? 4 : 3;
      const std::size_t keys = a.inputs[static_cast<std::size_t>(c.input)].size();
      if (c.values.size() != width * keys) {
        return Status::Error(where, std::to_string(c.values.size()) + " values for " +
                                        std::to_string(keys) + " keys; must be " +
                                        std::to_string(width * keys));
      }
      if (!AllFinite(c.values)) return Status::Error(where, "a value is not finite");
    }
  }
  return Status::Ok();
}

// Builds the tinygltf model of a checked Document.
class ModelBuilder {
 public:
  explicit ModelBuilder(const Document& doc) : doc_(doc) {
    material_map_.assign(doc.materials.size(), -1);
    texture_map_.assign(doc.textures.size(), -1);
  }

  Status Build(tinygltf::Model* model) {
    model_ = model;
    model->asset.version = "2.0";
    model->asset.generator = doc_.generator;
    NIWA_RETURN_IF_ERROR(ParseExtras(doc_.asset_extras_json, "asset", &model->asset.extras));
    model->buffers.emplace_back();
    Reserve();
    for (std::size_t i = 0; i < doc_.meshes.size(); ++i) {
      const Mesh& mesh = doc_.meshes[i];
      tinygltf::Mesh out;
      out.name = mesh.name;
      for (const Primitive& p : mesh.primitives) {
        tinygltf::Primitive prim;
        NIWA_RETURN_IF_ERROR(AddPrimitive(p, &prim));
        out.primitives.push_back(std::move(prim));
      }
      model->meshes.push_back(std::move(out));
    }
    for (std::size_t m = 0; m < doc_.materials.size(); ++m) {  // unused ones, after the used
      NIWA_RETURN_IF_ERROR(MaterialIndex(static_cast<int>(m)).status());
    }
    for (std::size_t t = 0; t < doc_.textures.size(); ++t) TextureIndex(static_cast<int>(t));
    for (std::size_t i = 0; i < doc_.nodes.size(); ++i) {
      NIWA_RETURN_IF_ERROR(AddNode(doc_.nodes[i], i));
    }
    for (const Skin& skin : doc_.skins) AddSkin(skin);
    for (const Animation& a : doc_.animations) AddAnimation(a);
    tinygltf::Scene scene;
    scene.name = doc_.scene_name;
    scene.nodes = doc_.scene_nodes;
    model->scenes.push_back(std::move(scene));
    model->defaultScene = 0;
    if (model->buffers[0].data.empty()) model->buffers.clear();
    return Status::Ok();
  }

 private:
  // Room for every buffer byte and glTF object up front: no reallocation moves the buffer or
  // tinygltf's heavy structs while they are appended (these copies cost 3x more in WASM).
  void Reserve() {
    std::size_t bytes = 0, views = 0;
    const auto add = [&](std::size_t size) {
      bytes += (size + 3) / 4 * 4;
      ++views;
    };
    for (const Mesh& mesh : doc_.meshes) {
      for (const Primitive& p : mesh.primitives) {
        const geom::TriMesh& m = p.mesh;
        add(m.positions.size() * sizeof(glm::vec3));
        add(m.normals.size() * sizeof(glm::vec3));
        add(m.uvs.size() * sizeof(glm::vec2));
        for (const geom::VertexAttribute& a : m.attributes) add(a.values.size() * sizeof(float));
        if (NeedsTangents(p, doc_)) add(m.vertex_count() * 4 * sizeof(float));
        add(m.indices.size() * sizeof(uint32_t));
        add(p.joints.size() * sizeof(uint16_t));
        add(p.weights.size() * sizeof(float));
      }
    }
    for (const Texture& t : doc_.textures) add(t.png.size());
    for (const Node& node : doc_.nodes) {
      add(node.instance_translations.size() * sizeof(float));
      add(node.instance_rotations.size() * sizeof(float));
      add(node.instance_scales.size() * sizeof(float));
    }
    for (const Skin& skin : doc_.skins) add(skin.inverse_bind_matrices.size() * sizeof(float));
    for (const Animation& a : doc_.animations) {
      for (const std::vector<float>& t : a.inputs) add(t.size() * sizeof(float));
      for (const Channel& c : a.channels) add(c.values.size() * sizeof(float));
    }
    model_->buffers[0].data.reserve(bytes);
    model_->bufferViews.reserve(views);
    model_->accessors.reserve(views);
    model_->meshes.reserve(doc_.meshes.size());
    model_->materials.reserve(doc_.materials.size());
    model_->textures.reserve(doc_.textures.size());
    model_->images.reserve(doc_.textures.size());
    model_->samplers.reserve(doc_.textures.size());
    model_->nodes.reserve(doc_.nodes.size());
  }

  // Appends raw bytes at a 4-byte aligned offset; returns the new bufferView's index.
  int AddBufferView(const void* data, std::size_t size, int target) {
    std::vector<unsigned char>& buffer = model_->buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = size;
    view.target = target;
    const std::size_t offset = buffer.size();
    buffer.resize(offset + size);
    if (size > 0) std::memcpy(buffer.data() + offset, data, size);
    model_->bufferViews.push_back(std::move(view));
    return static_cast<int>(model_->bufferViews.size()) - 1;
  }

  template <typename T>
  int AddView(const std::vector<T>& data, int target) {
    return AddBufferView(data.data(), data.size() * sizeof(T), target);
  }

  int AddAccessor(int view, int component_type, int type, std::size_t count,
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
    model_->accessors.push_back(std::move(accessor));
    return static_cast<int>(model_->accessors.size()) - 1;
  }

  Status AddPrimitive(const Primitive& p, tinygltf::Primitive* prim) {
    const geom::TriMesh& m = p.mesh;
    const std::size_t n = m.vertex_count();
    std::vector<double> lo(3, std::numeric_limits<double>::infinity());
    std::vector<double> hi(3, -std::numeric_limits<double>::infinity());
    for (const glm::vec3& v : m.positions) {
      for (int c = 0; c < 3; ++c) {
        const double x = static_cast<double>(v[c]);  // exact float32 values, as required
        lo[static_cast<std::size_t>(c)] = std::min(lo[static_cast<std::size_t>(c)], x);
        hi[static_cast<std::size_t>(c)] = std::max(hi[static_cast<std::size_t>(c)], x);
      }
    }
    prim->mode = static_cast<int>(p.mode);
    prim->attributes["POSITION"] =
        AddAccessor(AddView(m.positions, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT,
                    TINYGLTF_TYPE_VEC3, n, lo, hi);
    if (!m.normals.empty()) {
      prim->attributes["NORMAL"] = AddAccessor(
          AddView(m.normals, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
    }
    if (!m.uvs.empty()) {
      prim->attributes["TEXCOORD_0"] = AddAccessor(
          AddView(m.uvs, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
    }
    static const int kTypes[5] = {0, TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3,
                                  TINYGLTF_TYPE_VEC4};
    for (const geom::VertexAttribute& a : m.attributes) {
      prim->attributes[AttributeSemantic(a.name)] = AddAccessor(
          AddView(a.values, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT, kTypes[a.components], n);
    }
    if (NeedsTangents(p, doc_)) {
      prim->attributes["TANGENT"] =
          AddAccessor(AddView(geom::ComputeTangentValues(m), kArrayBuffer),
                      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n);
    }
    if (!m.indices.empty()) {
      const bool wide =
          p.index_type == IndexType::kUint32 || (p.index_type == IndexType::kAuto && n > 65535);
      int view;
      if (wide) {
        view = AddView(m.indices, kElementArrayBuffer);
      } else {
        std::vector<uint16_t> narrow(m.indices.begin(), m.indices.end());
        view = AddView(narrow, kElementArrayBuffer);
      }
      prim->indices = AddAccessor(
          view,
          wide ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
          TINYGLTF_TYPE_SCALAR, m.indices.size());
    }
    if (!p.joints.empty()) {
      prim->attributes["JOINTS_0"] =
          AddAccessor(AddView(p.joints, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                      TINYGLTF_TYPE_VEC4, n);
      prim->attributes["WEIGHTS_0"] = AddAccessor(
          AddView(p.weights, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n);
    }
    if (p.material >= 0) {
      Result<int> material = MaterialIndex(p.material);
      if (!material.ok()) return material.status();
      prim->material = *material;
    }
    return Status::Ok();
  }

  // The output index of texture t, writing its image, sampler and texture on first use.
  int TextureIndex(int t) {
    if (t < 0) return -1;
    int& out = texture_map_[static_cast<std::size_t>(t)];
    if (out >= 0) return out;
    const Texture& texture = doc_.textures[static_cast<std::size_t>(t)];
    tinygltf::Image image;
    image.name = texture.name;
    image.mimeType = "image/png";
    image.bufferView = AddView(texture.png, 0);
    model_->images.push_back(std::move(image));
    tinygltf::Sampler sampler;
    sampler.magFilter = texture.mag_filter;
    sampler.minFilter = texture.min_filter;
    sampler.wrapS = static_cast<int>(texture.wrap_s);
    sampler.wrapT = static_cast<int>(texture.wrap_t);
    model_->samplers.push_back(std::move(sampler));
    tinygltf::Texture out_texture;
    out_texture.name = texture.name;
    out_texture.source = static_cast<int>(model_->images.size()) - 1;
    out_texture.sampler = static_cast<int>(model_->samplers.size()) - 1;
    model_->textures.push_back(std::move(out_texture));
    out = static_cast<int>(model_->textures.size()) - 1;
    return out;
  }

  // The output index of material m, writing it (and its textures) on first use.
  Result<int> MaterialIndex(int m) {
    int& out = material_map_[static_cast<std::size_t>(m)];
    if (out >= 0) return out;
    const Material& spec = doc_.materials[static_cast<std::size_t>(m)];
    tinygltf::Material material;
    material.name = spec.name;
    material.emissiveFactor = {spec.emissive_factor[0], spec.emissive_factor[1],
                               spec.emissive_factor[2]};
    material.doubleSided = spec.double_sided;
    if (spec.alpha_mode == AlphaMode::kMask) {
      material.alphaMode = "MASK";
      material.alphaCutoff = spec.alpha_cutoff;
    } else if (spec.alpha_mode == AlphaMode::kBlend) {
      material.alphaMode = "BLEND";
    }
    tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    pbr.baseColorFactor.assign(spec.base_color_factor.begin(), spec.base_color_factor.end());
    pbr.baseColorTexture.index = TextureIndex(spec.base_color_texture);
    pbr.metallicFactor = spec.metallic_factor;
    pbr.roughnessFactor = spec.roughness_factor;
    pbr.metallicRoughnessTexture.index = TextureIndex(spec.metallic_roughness_texture);
    material.normalTexture.index = TextureIndex(spec.normal_texture);
    material.normalTexture.scale = spec.normal_scale;
    material.occlusionTexture.index = TextureIndex(spec.occlusion_texture);
    material.occlusionTexture.strength = spec.occlusion_strength;
    NIWA_RETURN_IF_ERROR(
        ParseExtras(spec.extras_json, "materials[" + std::to_string(m) + "]", &material.extras));
    model_->materials.push_back(std::move(material));
    out = static_cast<int>(model_->materials.size()) - 1;
    return out;
  }

  Status AddNode(const Node& node, std::size_t i) {
    tinygltf::Node out;
    out.name = node.name;
    out.mesh = node.mesh;
    out.skin = node.skin;
    out.children = node.children;
    if (node.translation != std::array<double, 3>{0, 0, 0}) {
      out.translation.assign(node.translation.begin(), node.translation.end());
    }
    if (node.rotation != std::array<double, 4>{0, 0, 0, 1}) {
      out.rotation.assign(node.rotation.begin(), node.rotation.end());
    }
    if (node.scale != std::array<double, 3>{1, 1, 1}) {
      out.scale.assign(node.scale.begin(), node.scale.end());
    }
    out.matrix = node.matrix;
    NIWA_RETURN_IF_ERROR(
        ParseExtras(node.extras_json, "nodes[" + std::to_string(i) + "]", &out.extras));
    if (out.name.empty() && out.mesh < 0 && out.children.empty() && out.translation.empty() &&
        out.rotation.empty() && out.scale.empty() && out.matrix.empty() &&
        out.extras.Type() == tinygltf::NULL_TYPE) {
      // tinygltf writes a node without properties as null, which is not valid glTF: give it an
      // empty extras object, so it is written as {"extras": {}}.
      out.extras = tinygltf::Value(tinygltf::Value::Object());
    }
    if (node.instance_count() > 0) AddInstances(node, &out);
    if (!node.lod_ids.empty()) AddLod(node, &out);
    model_->nodes.push_back(std::move(out));
    return Status::Ok();
  }

  // Puts `extension` on the node under `name` and lists it in extensionsUsed once.
  void SetExtension(const char* name, tinygltf::Value::Object extension, tinygltf::Node* out) {
    out->extensions[name] = tinygltf::Value(std::move(extension));
    if (std::find(model_->extensionsUsed.begin(), model_->extensionsUsed.end(), name) ==
        model_->extensionsUsed.end()) {
      model_->extensionsUsed.push_back(name);
    }
  }

  // EXT_mesh_gpu_instancing: TRANSLATION, ROTATION, SCALE accessors of the node's instances.
  void AddInstances(const Node& node, tinygltf::Node* out) {
    const char* kExtension = "EXT_mesh_gpu_instancing";
    tinygltf::Value::Object attributes;
    auto add = [&](const char* name, const std::vector<float>& values, int type) {
      if (values.empty()) return;
      attributes[name] = tinygltf::Value(AddAccessor(
          AddView(values, 0), TINYGLTF_COMPONENT_TYPE_FLOAT, type, node.instance_count()));
    };
    add("TRANSLATION", node.instance_translations, TINYGLTF_TYPE_VEC3);
    add("ROTATION", node.instance_rotations, TINYGLTF_TYPE_VEC4);
    add("SCALE", node.instance_scales, TINYGLTF_TYPE_VEC3);
    tinygltf::Value::Object extension;
    extension["attributes"] = tinygltf::Value(std::move(attributes));
    SetExtension(kExtension, std::move(extension), out);
  }

  // MSFT_lod on a node: {"ids": [lower levels' nodes, highest first]}.
  void AddLod(const Node& node, tinygltf::Node* out) {
    const char* kExtension = "MSFT_lod";
    tinygltf::Value::Array ids;
    for (int l : node.lod_ids) ids.push_back(tinygltf::Value(l));
    tinygltf::Value::Object extension;
    extension["ids"] = tinygltf::Value(std::move(ids));
    SetExtension(kExtension, std::move(extension), out);
  }

  void AddSkin(const Skin& skin) {
    tinygltf::Skin out;
    out.name = skin.name;
    out.skeleton = skin.skeleton;
    out.joints = skin.joints;
    if (!skin.inverse_bind_matrices.empty()) {
      out.inverseBindMatrices =
          AddAccessor(AddView(skin.inverse_bind_matrices, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                      TINYGLTF_TYPE_MAT4, skin.joints.size());
    }
    model_->skins.push_back(std::move(out));
  }

  void AddAnimation(const Animation& a) {
    tinygltf::Animation clip;
    clip.name = a.name;
    std::vector<int> inputs;
    for (const std::vector<float>& t : a.inputs) {
      inputs.push_back(AddAccessor(AddView(t, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                   TINYGLTF_TYPE_SCALAR, t.size(), {static_cast<double>(t.front())},
                                   {static_cast<double>(t.back())}));
    }
    for (const Channel& c : a.channels) {
      tinygltf::AnimationSampler sampler;
      sampler.input = inputs[static_cast<std::size_t>(c.input)];
      sampler.interpolation = c.interpolation == Interpolation::kStep ? "STEP" : "LINEAR";
      const std::size_t keys = a.inputs[static_cast<std::size_t>(c.input)].size();
      sampler.output =
          AddAccessor(AddView(c.values, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                      c.path == Path::kRotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, keys);
      clip.samplers.push_back(std::move(sampler));
      tinygltf::AnimationChannel channel;
      channel.sampler = static_cast<int>(clip.samplers.size()) - 1;
      channel.target_node = c.node;
      channel.target_path = c.path == Path::kTranslation ? "translation"
                            : c.path == Path::kRotation  ? "rotation"
                                                         : "scale";
      clip.channels.push_back(std::move(channel));
    }
    model_->animations.push_back(std::move(clip));
  }

  const Document& doc_;
  tinygltf::Model* model_ = nullptr;
  std::vector<int> material_map_, texture_map_;
};

// An output stream buffer appending to a byte vector (memcpy per write), so a .glb is written
// straight into the vector it is returned in: no std::ostringstream growth, no str() copy and no
// copy from a string into the vector (libc++'s char-by-char copies were most of the .glb's time
// in WASM).
class ByteSink : public std::streambuf {
 public:
  explicit ByteSink(std::vector<unsigned char>* out) : out_(out) {}

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n <= 0) return 0;
    const std::size_t at = out_->size();
    out_->resize(at + static_cast<std::size_t>(n));
    std::memcpy(out_->data() + at, s, static_cast<std::size_t>(n));
    return n;
  }
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    out_->push_back(static_cast<unsigned char>(traits_type::to_char_type(c)));
    return c;
  }

 private:
  std::vector<unsigned char>* out_;
};

// Writes the document to `stream`; `out` (may be null: the vector `stream` writes to) gets room
// for the buffer and the JSON before the writing starts.
Status SerializeTo(const Document& doc, bool binary, std::ostream& stream,
                   std::vector<unsigned char>* out) {
  NIWA_RETURN_IF_ERROR(CheckDocument(doc));
  tinygltf::Model model;
  NIWA_RETURN_IF_ERROR(ModelBuilder(doc).Build(&model));
  // A .glb's lengths are 32-bit (glTF 2.0, 4.4.3): name the buffer, not just "failed".
  double buffer_bytes = 0;
  for (const tinygltf::Buffer& buffer : model.buffers) buffer_bytes += double(buffer.data.size());
  if (binary && buffer_bytes > 4294967295.0 - 16.0 * 1024 * 1024) {
    return Status::Error("glTF buffer", FormatBytes(buffer_bytes) +
                                            " is more than the 4 GB a .glb can hold; export a "
                                            "smaller tree or fewer frames");
  }
  if (out != nullptr && buffer_bytes < 4294967295.0) {
    out->reserve(static_cast<std::size_t>(buffer_bytes) + 65536);
  }
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, stream, false, binary) || !stream) {
    return Status::Error("glTF buffer", "writing " + FormatBytes(buffer_bytes) +
                                            " of buffers failed (out of memory); export a "
                                            "smaller tree or fewer frames");
  }
  return Status::Ok();
}

Result<std::string> Serialize(const Document& doc, bool binary) {
  std::ostringstream stream;
  NIWA_RETURN_IF_ERROR(SerializeTo(doc, binary, stream, nullptr));
  return stream.str();
}

}  // namespace

std::string AttributeSemantic(const std::string& name) {
  if (name.empty()) return "";
  for (char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return "";
  }
  if (IsStandard(name, "COLOR_") || IsStandard(name, "TEXCOORD_") || name == "TANGENT") {
    return name;
  }
  std::string out = "_";
  for (char c : name[0] == '_' ? name.substr(1) : name) {
    out += (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  }
  return out.size() > 1 ? out : "";
}

Result<std::vector<unsigned char>> WriteGlb(const Document& document) {
  std::vector<unsigned char> glb;
  ByteSink sink(&glb);
  std::ostream stream(&sink);
  NIWA_RETURN_IF_ERROR(SerializeTo(document, true, stream, &glb));
  return glb;
}

Result<std::string> WriteGltfJson(const Document& document) { return Serialize(document, false); }

}  // namespace niwa::gltf
