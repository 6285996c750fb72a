// glTF 2.0 reader: tinygltf parses (its one implementation lives elsewhere in core/io), this file
// walks the scene, reads accessors, decodes Draco primitives natively and builds one world TriMesh.
#include "io/gltf_reader.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "image/png.h"
#include "io/gltf_preflight.h"
#include "math/det_math.h"
#include "io/tinygltf.h"  // declarations only: the implementation is io/tinygltf_impl.cpp

#ifdef NIWA_HAVE_DRACO
#include <draco/compression/decode.h>
#endif

namespace niwa::io {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

// Required extensions that do not change geometry (materials, textures) or that this reader
// handles (quantized accessors are read through their component type and `normalized` flag).
bool ExtensionIsHarmless(const std::string& ext) {
  return ext.rfind("KHR_materials_", 0) == 0 || ext == "KHR_texture_transform" ||
         ext == "KHR_texture_basisu" || ext == "EXT_texture_webp" || ext == "EXT_texture_avif" ||
         ext == "KHR_mesh_quantization" || ext == "KHR_lights_punctual";
}

std::string OneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  std::size_t lead = text.find_first_not_of(' ');
  return lead == std::string::npos ? "" : text.substr(lead);
}

// Images are not decoded here: a data: URI image's bytes are kept by index (tinygltf hands them
// over only through this callback; a buffer view image is read later with its bounds checked).
bool KeepUriImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
  if (image->bufferView != -1 || index < 0 || size < 0) return true;
  auto* kept = static_cast<std::map<int, std::string>*>(user);
  (*kept)[index] =
      std::string(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size));
  return true;
}

// External files of a .gltf: read through ReadFileCapped, refused when no base folder was given.
struct FsContext {
  bool allow = false;
  bool refused = false;
  std::string refused_path;
};
bool ExternalExists(const std::string& path, void* user) {
  auto* context = static_cast<FsContext*>(user);
  if (!context->allow) {
    context->refused = true;
    context->refused_path = path.rfind("./", 0) == 0 ? path.substr(2) : path;
    return false;
  }
  return tinygltf::FileExists(path, nullptr);
}
bool ReadExternal(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                  void* user) {
  if (!static_cast<FsContext*>(user)->allow) {
    *err =
        "external file '" + path + "' cannot be read here; embed buffers as data: URIs or use .glb";
    return false;
  }
  Result<std::string> bytes = ReadFileCapped(path);
  if (!bytes.ok()) {
    *err = bytes.status().message();
    return false;
  }
  out->assign(bytes->begin(), bytes->end());
  return true;
}

// (mesh, primitive) -> the index count of a Draco primitive whose indices accessor has no buffer
// view (the compressed data holds the indices).
using DracoIndexCounts = std::map<std::pair<int, int>, std::size_t>;

// Debian's tinygltf 2.7 (built without TINYGLTF_ENABLE_DRACO) refuses a primitive whose indices
// accessor has no buffer view ("accessor[N] invalid bufferView"), which is how every
// KHR_draco_mesh_compression primitive is written. Such primitives lose their `indices` here before
// tinygltf parses the JSON; the counts are kept for the triangle limit. Returns "" when nothing
// needed patching, else the patched file (.glb: the JSON chunk replaced, the BIN chunk kept).
std::string DetachDracoIndices(const std::string& bytes, bool binary, DracoIndexCounts* counts) {
  std::string json_text;
  uint32_t json_length = 0;
  if (binary) {
    if (bytes.size() < 20) return "";
    std::memcpy(&json_length, bytes.data() + 12, 4);
    if (std::size_t{20} + json_length > bytes.size()) return "";
    json_text = bytes.substr(20, json_length);
  } else {
    json_text = bytes;
  }
  if (json_text.find(kDraco) == std::string::npos) return "";  // the common case: parse once
  nlohmann::json j = nlohmann::json::parse(json_text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("meshes") || !j["meshes"].is_array() ||
      !j.contains("accessors") || !j["accessors"].is_array()) {
    return "";
  }
  const nlohmann::json& accessors = j["accessors"];
  bool changed = false;
  for (std::size_t m = 0; m < j["meshes"].size(); ++m) {
    nlohmann::json& mesh = j["meshes"][m];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      continue;
    for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
      nlohmann::json& prim = mesh["primitives"][p];
      if (!prim.is_object() || !prim.contains("indices") || !prim["indices"].is_number_unsigned() ||
          !prim.contains("extensions") || !prim["extensions"].is_object() ||
          !prim["extensions"].contains(kDraco)) {
        continue;
      }
      std::size_t a = prim["indices"].get<std::size_t>();
      if (a >= accessors.size() || !accessors[a].is_object() ||
          accessors[a].contains("bufferView")) {
        continue;
      }
      const nlohmann::json& count = accessors[a].value("count", nlohmann::json());
      (*counts)[{static_cast<int>(m), static_cast<int>(p)}] =
          count.is_number_unsigned() ? count.get<std::size_t>() : 0;
      prim.erase("indices");
      changed = true;
    }
  }
  if (!changed) return "";
  std::string patched = j.dump();
  if (!binary) return patched;
  while (patched.size() % 4 != 0) patched.push_back(' ');
  std::string rest = bytes.substr(20 + json_length);  // the BIN chunk (and anything after)
  std::string out = bytes.substr(0, 12);
  uint32_t chunk_length = static_cast<uint32_t>(patched.size());
  uint32_t total = static_cast<uint32_t>(12 + 8 + patched.size() + rest.size());
  std::memcpy(out.data() + 8, &total, 4);
  out.append(reinterpret_cast<const char*>(&chunk_length), 4);
  out.append("JSON", 4);
  out += patched;
  out += rest;
  return out;
}

// One primitive in its own (mesh) space before the node transform.
struct LocalPrimitive {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // empty or one per position
  std::vector<glm::vec2> uvs;       // empty or one per position
  std::vector<glm::vec4> colors;    // empty or one per position (COLOR_0)
  std::vector<glm::vec2> base_uvs;  // TEXCOORD_<set> of the material's baseColorTexture, or empty
  std::vector<uint32_t> indices;    // the primitive's index list (or 0..n-1), before mode assembly
};

// A typed, bounds-checked window on an accessor's bytes.
struct AccessorView {
  const unsigned char* data = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int components = 0;
  int component_type = 0;
  bool normalized = false;
};

// Where a material's baseColorTexture is sampled: its UV set (-1: the material has no
// baseColorTexture) and its KHR_texture_transform (glTF: uv' = T(offset) * R(rotation) * S(scale)
// * uv; the extension's texCoord overrides textureInfo.texCoord).
struct BaseColorUv {
  int set = -1;
  bool transform = false;
  double offset[2] = {0.0, 0.0};
  double rotation = 0.0;
  double scale[2] = {1.0, 1.0};
  double sin_r = 0.0, cos_r = 1.0;  // of rotation (det_math: the same bits in every build)
  std::string label;                // "material 0 'ground' baseColorTexture"
  // The transformed UV, in double then rounded to float as the attribute keeps it.
  glm::vec2 Apply(const glm::vec2& uv) const {
    if (!transform) return uv;
    const double u = uv.x, v = uv.y;
    const double su = scale[0] * u, sv = scale[1] * v;
    return glm::vec2(static_cast<float>(cos_r * su + sin_r * sv + offset[0]),
                     static_cast<float>(-sin_r * su + cos_r * sv + offset[1]));
  }
};

class Reader {
 public:
  Reader(const tinygltf::Model& model, std::string name, const DracoIndexCounts& draco_counts,
         const std::map<int, std::string>& uri_images, std::string base_dir, MeshReadStats* stats)
      : model_(model),
        name_(std::move(name)),
        draco_counts_(draco_counts),
        uri_images_(uri_images),
        base_dir_(std::move(base_dir)),
        stats_(stats) {}

  Status Run(geom::TriMesh* out);

 private:
  Status Error(const std::string& message) const { return Status::Error(name_, message); }
  std::string MeshLabel(int mesh, int prim) const {
    const std::string& n = model_.meshes[static_cast<std::size_t>(mesh)].name;
    return "mesh " + std::to_string(mesh) + (n.empty() ? "" : " '" + n + "'") + " primitive " +
           std::to_string(prim);
  }
  Status View(int accessor, const std::string& what, AccessorView* view) const;
  Status ReadPrimitive(int mesh, int prim, LocalPrimitive* local);
  Status ReadDraco(int mesh, int prim, const tinygltf::Value& ext, LocalPrimitive* local);
  Status VisitNode(int node, const glm::dmat4& parent, int depth);
  Status AddMesh(int mesh, const glm::dmat4& world);
  // Triangles a mesh will give, from accessor counts alone (the limit is checked before reading).
  std::size_t CountTriangles(int mesh) const;
  Status VisitScene();
  // Every material with its baseColorTexture's image (bounds, format and declared size checked).
  Status ReadMaterials(std::vector<MeshMaterial>* materials, std::vector<MeshImage>* images) const;
  Status ReadImage(int index, MeshImage* out) const;
  // Every material's BaseColorUv (texCoord and KHR_texture_transform checked) into base_uv_.
  Status ReadBaseColorUvs();
  // The BaseColorUv of a primitive's material (nullptr: no material or no baseColorTexture).
  const BaseColorUv* BaseColorUvOf(int material) const {
    if (material < 0 || static_cast<std::size_t>(material) >= base_uv_.size()) return nullptr;
    const BaseColorUv& b = base_uv_[static_cast<std::size_t>(material)];
    return b.set >= 0 ? &b : nullptr;
  }
  // The attribute name of a UV set ("TEXCOORD_1").
  static std::string TexCoordName(int set) { return "TEXCOORD_" + std::to_string(set); }

  const tinygltf::Model& model_;
  std::string name_;
  const DracoIndexCounts& draco_counts_;
  const std::map<int, std::string>& uri_images_;
  std::string base_dir_;
  MeshReadStats* stats_;
  geom::TriMesh mesh_;
  bool all_normals_ = true, all_uvs_ = true, any_color_ = false;
  std::vector<float> colors_, materials_;  // per vertex: kColorAttribute, kMaterialAttribute
  std::vector<float> base_uv_values_;      // per vertex: kBaseColorUvAttribute (2 floats)
  bool any_base_uv_ = false;               // some primitive's material has a baseColorTexture
  std::vector<BaseColorUv> base_uv_;       // per material
  std::size_t triangle_primitives_ = 0, line_point_primitives_ = 0;
  std::vector<bool> on_path_;  // nodes on the current root-to-node path (cycle check)
  bool counting_ = false;      // first pass: count triangles only
  std::size_t counted_ = 0;
};

std::size_t Reader::CountTriangles(int mesh) const {
  std::size_t total = 0;
  const auto& primitives = model_.meshes[static_cast<std::size_t>(mesh)].primitives;
  for (std::size_t pi = 0; pi < primitives.size(); ++pi) {
    const tinygltf::Primitive& p = primitives[pi];
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    std::size_t n = 0;
    int accessor = p.indices;
    if (accessor < 0) {
      auto it = p.attributes.find("POSITION");
      accessor = it == p.attributes.end() ? -1 : it->second;
    }
    if (accessor >= 0 && static_cast<std::size_t>(accessor) < model_.accessors.size()) {
      n = model_.accessors[static_cast<std::size_t>(accessor)].count;
    }
    auto draco = draco_counts_.find({mesh, static_cast<int>(pi)});
    if (draco != draco_counts_.end()) n = draco->second;
    if (mode == TINYGLTF_MODE_TRIANGLES) total += n / 3;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      total += n >= 3 ? n - 2 : 0;
    }
  }
  return total;
}

Status Reader::View(int accessor, const std::string& what, AccessorView* view) const {
  if (accessor < 0 || static_cast<std::size_t>(accessor) >= model_.accessors.size()) {
    return Error(what + " names accessor " + std::to_string(accessor) + ", which does not exist");
  }
  const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(accessor)];
  if (a.sparse.isSparse) return Error(what + " uses a sparse accessor, which is not supported");
  if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size()) {
    return Error(what + " accessor " + std::to_string(accessor) + " has no buffer view");
  }
  const tinygltf::BufferView& bv = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model_.buffers.size()) {
    return Error(what + " buffer view " + std::to_string(a.bufferView) + " has no buffer");
  }
  const std::vector<unsigned char>& buffer =
      model_.buffers[static_cast<std::size_t>(bv.buffer)].data;
  int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
  if (components <= 0 || size <= 0 || size > 4) {
    return Error(what + " accessor " + std::to_string(accessor) + " has an unsupported type");
  }
  const std::size_t element = static_cast<std::size_t>(components) * static_cast<std::size_t>(size);
  const std::size_t stride = bv.byteStride > 0 ? bv.byteStride : element;
  // The view inside its buffer and offset + stride * (count - 1) + element inside the view, each
  // step checked so that nothing wraps (size_t is 32 bits in WASM).
  const bool view_fits =
      bv.byteOffset <= buffer.size() && bv.byteLength <= buffer.size() - bv.byteOffset;
  const bool fits =
      view_fits &&
      (a.count == 0 || (a.byteOffset <= bv.byteLength && element <= bv.byteLength - a.byteOffset &&
                        a.count - 1 <= (bv.byteLength - a.byteOffset - element) / stride));
  if (!fits) {
    return Error(what + " accessor " + std::to_string(accessor) +
                 " reads past the end of its buffer (truncated file?)");
  }
  const std::size_t start = bv.byteOffset + a.byteOffset;
  view->data = buffer.data() + start;
  view->stride = stride;
  view->count = a.count;
  view->components = components;
  view->component_type = a.componentType;
  view->normalized = a.normalized;
  return Status::Ok();
}

// Component c of element i as a double; normalized integers map to [0, 1] or [-1, 1] as the glTF
// 2.0 spec decodes them (f = c / 255 for UNSIGNED_BYTE, max(c / 127, -1) for BYTE, and so on).
double Component(const AccessorView& v, std::size_t i, int c) {
  const unsigned char* p = v.data + i * v.stride;
  switch (v.component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p + 4 * c, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t u;
      std::memcpy(&u, p + 4 * c, 4);
      return u;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
      int32_t s;
      std::memcpy(&s, p + 4 * c, 4);
      return s;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t u;
      std::memcpy(&u, p + 2 * c, 2);
      return v.normalized ? u / 65535.0 : u;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t s;
      std::memcpy(&s, p + 2 * c, 2);
      return v.normalized ? std::max(s / 32767.0, -1.0) : s;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      uint8_t u = p[c];
      return v.normalized ? u / 255.0 : u;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t s;
      std::memcpy(&s, p + c, 1);
      return v.normalized ? std::max(s / 127.0, -1.0) : s;
    }
    default:
      return 0.0;
  }
}

// Index i of an index accessor, read as the unsigned type of its component size (glTF 2.0 allows
// only UNSIGNED_BYTE, UNSIGNED_SHORT and UNSIGNED_INT indices; a signed type's bits are read the
// same way, so -1 becomes 65535 and is refused by the range check against the vertex count).
uint32_t IndexAt(const AccessorView& v, std::size_t i) {
  const unsigned char* p = v.data + i * v.stride;
  switch (tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(v.component_type))) {
    case 1:
      return p[0];
    case 2: {
      uint16_t u;
      std::memcpy(&u, p, 2);
      return u;
    }
    default: {
      uint32_t u;
      std::memcpy(&u, p, 4);
      return u;
    }
  }
}

Status Reader::ReadDraco(int mesh, int prim, const tinygltf::Value& ext, LocalPrimitive* local) {
  const std::string label = MeshLabel(mesh, prim);
#ifndef NIWA_HAVE_DRACO
  (void)ext;
  (void)local;
  return Error(
      label + " is Draco-compressed (" + std::string(kDraco) +
      "); this build cannot decode Draco: the page decodes it before handing the mesh over");
#else
  if (!ext.IsObject() || !ext.Get("bufferView").IsInt() || !ext.Get("attributes").IsObject()) {
    return Error(label + ": " + kDraco + " needs a bufferView and attributes");
  }
  int bv_index = ext.Get("bufferView").GetNumberAsInt();
  if (bv_index < 0 || static_cast<std::size_t>(bv_index) >= model_.bufferViews.size()) {
    return Error(label + ": " + kDraco + " names buffer view " + std::to_string(bv_index) +
                 ", which does not exist");
  }
  const tinygltf::BufferView& bv = model_.bufferViews[static_cast<std::size_t>(bv_index)];
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model_.buffers.size() ||
      bv.byteOffset + bv.byteLength >
          model_.buffers[static_cast<std::size_t>(bv.buffer)].data.size()) {
    return Error(label + ": the Draco buffer view reads past the end of its buffer (truncated?)");
  }
  const auto& buffer = model_.buffers[static_cast<std::size_t>(bv.buffer)].data;
  const Status header = PreflightDracoHeader(
      std::string_view(reinterpret_cast<const char*>(buffer.data() + bv.byteOffset), bv.byteLength),
      label);
  if (!header.ok()) return Error(header.message());
  draco::DecoderBuffer in;
  in.Init(reinterpret_cast<const char*>(buffer.data() + bv.byteOffset), bv.byteLength);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&in);
  if (!decoded.ok()) {
    return Error(label + ": Draco cannot decode it (" +
                 OneLine(decoded.status().error_msg_string()) + ")");
  }
  std::unique_ptr<draco::Mesh> dm = std::move(decoded).value();
  const tinygltf::Value& attributes = ext.Get("attributes");
  auto attribute = [&](const char* key) -> const draco::PointAttribute* {
    if (!attributes.Has(key) || !attributes.Get(key).IsInt()) return nullptr;
    return dm->GetAttributeByUniqueId(static_cast<uint32_t>(attributes.Get(key).GetNumberAsInt()));
  };
  const draco::PointAttribute* pos = attribute("POSITION");
  if (pos == nullptr || pos->num_components() < 3) {
    return Error(label + ": the Draco data has no 3-component POSITION attribute");
  }
  const draco::PointAttribute* nrm = attribute("NORMAL");
  const draco::PointAttribute* uv = attribute("TEXCOORD_0");
  const draco::PointAttribute* color = attribute("COLOR_0");
  const int material_index =
      model_.meshes[static_cast<std::size_t>(mesh)].primitives[static_cast<std::size_t>(prim)].material;
  const BaseColorUv* base_uv = BaseColorUvOf(material_index);
  const draco::PointAttribute* base =
      base_uv != nullptr ? attribute(TexCoordName(base_uv->set).c_str()) : nullptr;
  if (base_uv != nullptr && (base == nullptr || base->num_components() < 2)) {
    return Error(label + ": " + base_uv->label + " reads " + TexCoordName(base_uv->set) +
                 ", which the primitive does not have");
  }
  const std::size_t n = dm->num_points();
  if (n > kMaxMeshVertices || dm->num_faces() > kMaxMeshTriangles) {
    return Error(label + ": the Draco data decodes to " + std::to_string(n) + " vertices and " +
                 std::to_string(dm->num_faces()) + " triangles; the limits are " +
                 std::to_string(kMaxMeshVertices) + " and " + std::to_string(kMaxMeshTriangles));
  }
  local->positions.resize(n);
  if (nrm != nullptr && nrm->num_components() >= 3) local->normals.resize(n);
  if (uv != nullptr && uv->num_components() >= 2) local->uvs.resize(n);
  if (color != nullptr && color->num_components() >= 3) local->colors.resize(n);
  if (base != nullptr) local->base_uvs.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    draco::PointIndex point(static_cast<uint32_t>(i));
    float v[3];
    pos->ConvertValue<float>(pos->mapped_index(point), 3, v);
    local->positions[i] = glm::dvec3(v[0], v[1], v[2]);
    if (!local->normals.empty()) {
      nrm->ConvertValue<float>(nrm->mapped_index(point), 3, v);
      local->normals[i] = glm::dvec3(v[0], v[1], v[2]);
    }
    if (!local->uvs.empty()) {
      uv->ConvertValue<float>(uv->mapped_index(point), 2, v);
      local->uvs[i] = glm::vec2(v[0], v[1]);
    }
    if (!local->base_uvs.empty()) {
      base->ConvertValue<float>(base->mapped_index(point), 2, v);
      local->base_uvs[i] = glm::vec2(v[0], v[1]);
    }
    if (!local->colors.empty()) {
      float c[4] = {1.0f, 1.0f, 1.0f, 1.0f};
      color->ConvertValue<float>(color->mapped_index(point), color->num_components() >= 4 ? 4 : 3,
                                 c);
      local->colors[i] = glm::vec4(c[0], c[1], c[2], c[3]);
    }
  }
  local->indices.resize(static_cast<std::size_t>(dm->num_faces()) * 3);
  for (uint32_t f = 0; f < dm->num_faces(); ++f) {
    const draco::Mesh::Face& face = dm->face(draco::FaceIndex(f));
    for (int k = 0; k < 3; ++k) local->indices[3 * f + static_cast<uint32_t>(k)] = face[k].value();
  }
  if (stats_ != nullptr) ++stats_->draco_primitives;
  return Status::Ok();
#endif
}

Status Reader::ReadPrimitive(int mesh, int prim, LocalPrimitive* local) {
  const tinygltf::Primitive& p =
      model_.meshes[static_cast<std::size_t>(mesh)].primitives[static_cast<std::size_t>(prim)];
  const std::string label = MeshLabel(mesh, prim);
  auto draco = p.extensions.find(kDraco);
  if (draco != p.extensions.end()) {
    auto pos_it = p.attributes.find("POSITION");
    bool has_fallback = pos_it != p.attributes.end() && pos_it->second >= 0 &&
                        static_cast<std::size_t>(pos_it->second) < model_.accessors.size() &&
                        model_.accessors[static_cast<std::size_t>(pos_it->second)].bufferView >= 0;
    if (!GltfReaderDecodesDraco() && has_fallback) {
      // Not required: the uncompressed fallback below is read instead.
    } else {
      return ReadDraco(mesh, prim, draco->second, local);
    }
  }
  auto pos_it = p.attributes.find("POSITION");
  if (pos_it == p.attributes.end()) return Error(label + " has no POSITION attribute");
  AccessorView pos;
  NIWA_RETURN_IF_ERROR(View(pos_it->second, label + " POSITION", &pos));
  if (pos.components != 3) return Error(label + " POSITION is not VEC3");
  local->positions.resize(pos.count);
  for (std::size_t i = 0; i < pos.count; ++i) {
    local->positions[i] =
        glm::dvec3(Component(pos, i, 0), Component(pos, i, 1), Component(pos, i, 2));
  }
  auto nrm_it = p.attributes.find("NORMAL");
  if (nrm_it != p.attributes.end()) {
    AccessorView nrm;
    NIWA_RETURN_IF_ERROR(View(nrm_it->second, label + " NORMAL", &nrm));
    if (nrm.components == 3 && nrm.count == pos.count) {
      local->normals.resize(pos.count);
      for (std::size_t i = 0; i < pos.count; ++i) {
        local->normals[i] =
            glm::dvec3(Component(nrm, i, 0), Component(nrm, i, 1), Component(nrm, i, 2));
      }
    }
  }
  auto uv_it = p.attributes.find("TEXCOORD_0");
  if (uv_it != p.attributes.end()) {
    AccessorView uv;
    NIWA_RETURN_IF_ERROR(View(uv_it->second, label + " TEXCOORD_0", &uv));
    if (uv.components == 2 && uv.count == pos.count) {
      local->uvs.resize(pos.count);
      for (std::size_t i = 0; i < pos.count; ++i) {
        local->uvs[i] = glm::vec2(static_cast<float>(Component(uv, i, 0)),
                                  static_cast<float>(Component(uv, i, 1)));
      }
    }
  }
  auto color_it = p.attributes.find("COLOR_0");
  if (color_it != p.attributes.end()) {
    AccessorView color;
    NIWA_RETURN_IF_ERROR(View(color_it->second, label + " COLOR_0", &color));
    if ((color.components == 3 || color.components == 4) && color.count == pos.count) {
      local->colors.resize(pos.count);
      for (std::size_t i = 0; i < pos.count; ++i) {
        local->colors[i] = glm::vec4(
            static_cast<float>(Component(color, i, 0)), static_cast<float>(Component(color, i, 1)),
            static_cast<float>(Component(color, i, 2)),
            color.components == 4 ? static_cast<float>(Component(color, i, 3)) : 1.0f);
      }
    }
  }
  if (const BaseColorUv* base_uv = BaseColorUvOf(p.material); base_uv != nullptr) {
    const std::string set = TexCoordName(base_uv->set);
    auto base_it = p.attributes.find(set);
    if (base_it == p.attributes.end()) {
      return Error(label + ": " + base_uv->label + " reads " + set +
                   ", which the primitive does not have");
    }
    AccessorView base;
    NIWA_RETURN_IF_ERROR(View(base_it->second, label + " " + set, &base));
    if (base.components != 2 || base.count != pos.count) {
      return Error(label + " " + set + " (read by " + base_uv->label + ") must be VEC2 with " +
                   std::to_string(pos.count) + " elements, one per POSITION");
    }
    local->base_uvs.resize(pos.count);
    for (std::size_t i = 0; i < pos.count; ++i) {
      local->base_uvs[i] = glm::vec2(static_cast<float>(Component(base, i, 0)),
                                     static_cast<float>(Component(base, i, 1)));
    }
  }
  if (p.indices >= 0) {
    AccessorView idx;
    NIWA_RETURN_IF_ERROR(View(p.indices, label + " indices", &idx));
    if (idx.components != 1 || idx.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
      return Error(label + " indices must be unsigned integer scalars");
    }
    local->indices.resize(idx.count);
    for (std::size_t i = 0; i < idx.count; ++i) local->indices[i] = IndexAt(idx, i);
  } else {
    local->indices.resize(pos.count);
    for (std::size_t i = 0; i < pos.count; ++i) local->indices[i] = static_cast<uint32_t>(i);
  }
  return Status::Ok();
}

Status Reader::AddMesh(int mesh_index, const glm::dmat4& world) {
  const tinygltf::Mesh& m = model_.meshes[static_cast<std::size_t>(mesh_index)];
  if (stats_ != nullptr) ++stats_->meshes;
  const glm::dmat3 linear(world);
  const double det = glm::determinant(linear);
  const bool mirrored = det < 0.0;
  // Normals by the inverse transpose of the linear part; a singular one (a zero scale) has no
  // inverse, so its normals go through the linear part itself and are re-normalized where possible.
  const glm::dmat3 normal_matrix = det != 0.0 ? glm::transpose(glm::inverse(linear)) : linear;
  for (std::size_t pi = 0; pi < m.primitives.size(); ++pi) {
    const tinygltf::Primitive& p = m.primitives[pi];
    const int prim = static_cast<int>(pi);
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
      ++line_point_primitives_;
      if (stats_ != nullptr) ++stats_->skipped_points_lines;
      continue;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      return Error(MeshLabel(mesh_index, prim) + " has mode " + std::to_string(mode) +
                   "; must be 0-6 (glTF primitive modes)");
    }
    LocalPrimitive local;
    NIWA_RETURN_IF_ERROR(ReadPrimitive(mesh_index, prim, &local));
    const int material =
        p.material >= 0 && static_cast<std::size_t>(p.material) < model_.materials.size()
            ? p.material
            : -1;
    ++triangle_primitives_;
    if (stats_ != nullptr) ++stats_->primitives;
    const std::string label = MeshLabel(mesh_index, prim);
    const std::size_t n = local.positions.size();
    const BaseColorUv* base_uv_of = BaseColorUvOf(material);
    if (base_uv_of != nullptr) any_base_uv_ = true;
    for (std::size_t i = 0; i < local.indices.size(); ++i) {
      if (local.indices[i] >= n) {
        return Error(label + " index " + std::to_string(local.indices[i]) +
                     " is out of range; must be below its " + std::to_string(n) + " vertices");
      }
    }
    // Assemble triangles (glTF 2.0 spec 3.7.2.1: strips p_i = {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}},
    // fans p_i = {v_{i+1}, v_{i+2}, v_0}).
    std::vector<uint32_t> tris;
    const std::size_t k = local.indices.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      tris.assign(local.indices.begin(), local.indices.begin() + static_cast<long>(k - k % 3));
    } else if (k >= 3) {
      tris.reserve(3 * (k - 2));
      for (std::size_t i = 0; i + 2 < k; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
          tris.insert(tris.end(), {local.indices[i], local.indices[i + 1 + i % 2],
                                   local.indices[i + 2 - i % 2]});
        } else {
          tris.insert(tris.end(), {local.indices[i + 1], local.indices[i + 2], local.indices[0]});
        }
      }
    }
    if (mesh_.triangle_count() + tris.size() / 3 > kMaxMeshTriangles) {
      return Error("more than " + std::to_string(kMaxMeshTriangles) +
                   " triangles in the scene; the limit is " + std::to_string(kMaxMeshTriangles) +
                   " (4 M)");
    }
    if (n > kMaxMeshVertices - mesh_.positions.size()) {
      return Error("more than " + std::to_string(kMaxMeshVertices) +
                   " vertices in the scene; the limit is " + std::to_string(kMaxMeshVertices) +
                   " (12 M)");
    }
    // Transform the vertices (positions by the world matrix, normals by its inverse transpose).
    const uint32_t base = static_cast<uint32_t>(mesh_.positions.size());
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3& lp = local.positions[i];
      if (!std::isfinite(lp.x) || !std::isfinite(lp.y) || !std::isfinite(lp.z)) {
        return Error(label + " POSITION " + std::to_string(i) + " is NaN or infinite");
      }
      glm::dvec4 wp = world * glm::dvec4(lp, 1.0);
      glm::vec3 fp(static_cast<float>(wp.x), static_cast<float>(wp.y), static_cast<float>(wp.z));
      if (!std::isfinite(fp.x) || !std::isfinite(fp.y) || !std::isfinite(fp.z)) {
        return Error(label + " POSITION " + std::to_string(i) +
                     " is infinite after its node transform");
      }
      mesh_.positions.push_back(fp);
      // Normals, UVs and colours must be finite too (the glTF validator's ACCESSOR_INVALID_FLOAT):
      // a NaN there is a corrupt file, refused naming the attribute rather than replaced, since a
      // replaced value would hide the damage and change shading without a word.
      glm::dvec3 wn(0.0);
      if (!local.normals.empty()) {
        const glm::dvec3& ln = local.normals[i];
        if (!std::isfinite(ln.x) || !std::isfinite(ln.y) || !std::isfinite(ln.z)) {
          return Error(label + " NORMAL " + std::to_string(i) + " is NaN or infinite");
        }
        wn = normal_matrix * ln;
        double len = std::sqrt(wn.x * wn.x + wn.y * wn.y + wn.z * wn.z);
        if (len > 0.0 && std::isfinite(len)) wn /= len;
        if (!std::isfinite(len))
          wn = glm::dvec3(0.0);  // overflowed: no direction, as a zero normal
      }
      if (!local.uvs.empty() &&
          (!std::isfinite(local.uvs[i].x) || !std::isfinite(local.uvs[i].y))) {
        return Error(label + " TEXCOORD_0 " + std::to_string(i) + " is NaN or infinite");
      }
      if (!local.colors.empty()) {
        const glm::vec4& lc = local.colors[i];
        if (!std::isfinite(lc.x) || !std::isfinite(lc.y) || !std::isfinite(lc.z) ||
            !std::isfinite(lc.w)) {
          return Error(label + " COLOR_0 " + std::to_string(i) + " is NaN or infinite");
        }
      }
      glm::vec2 base_uv(0.0f);
      if (base_uv_of != nullptr) {
        const glm::vec2& lb = local.base_uvs[i];
        base_uv = base_uv_of->Apply(lb);
        if (!std::isfinite(lb.x) || !std::isfinite(lb.y)) {
          return Error(label + " " + TexCoordName(base_uv_of->set) + " " + std::to_string(i) +
                       " is NaN or infinite");
        }
        if (!std::isfinite(base_uv.x) || !std::isfinite(base_uv.y)) {
          return Error(label + " " + TexCoordName(base_uv_of->set) + " " + std::to_string(i) +
                       " is infinite after " + base_uv_of->label + "'s KHR_texture_transform");
        }
      }
      base_uv_values_.insert(base_uv_values_.end(), {base_uv.x, base_uv.y});
      mesh_.normals.push_back(glm::vec3(wn));
      mesh_.uvs.push_back(local.uvs.empty() ? glm::vec2(0.0f) : local.uvs[i]);
      const glm::vec4 c = local.colors.empty() ? glm::vec4(1.0f) : local.colors[i];
      colors_.insert(colors_.end(), {c.x, c.y, c.z, c.w});
      materials_.push_back(static_cast<float>(material));
    }
    if (!local.colors.empty()) any_color_ = true;
    if (local.normals.empty()) all_normals_ = false;
    if (local.uvs.empty()) all_uvs_ = false;
    for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
      uint32_t a = base + tris[t], b = base + tris[t + 1], c = base + tris[t + 2];
      if (a == b || b == c || a == c ||
          DegenerateTriangle(mesh_.positions[a], mesh_.positions[b], mesh_.positions[c])) {
        if (stats_ != nullptr) ++stats_->degenerate;
        continue;
      }
      if (mirrored) std::swap(b, c);  // a mirroring transform flips winding
      mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    }
  }
  return Status::Ok();
}

// Local matrix of a node: `matrix` (column-major) or T * R * S (glTF 2.0 spec 3.5.3).
Result<glm::dmat4> LocalMatrix(const tinygltf::Node& node) {
  glm::dmat4 m(1.0);
  if (node.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<std::size_t>(4 * c + r)];
    return m;
  }
  glm::dmat4 t(1.0), r(1.0), s(1.0);
  if (node.translation.size() == 3) {
    t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (node.rotation.size() == 4) {
    // glTF stores (x, y, z, w); glm::dquat takes (w, x, y, z).
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    r = glm::mat4_cast(q);
  }
  if (node.scale.size() == 3) {
    s[0][0] = node.scale[0];
    s[1][1] = node.scale[1];
    s[2][2] = node.scale[2];
  }
  return t * r * s;
}

Status Reader::VisitNode(int node, const glm::dmat4& parent, int depth) {
  if (node < 0 || static_cast<std::size_t>(node) >= model_.nodes.size()) {
    return Error("node " + std::to_string(node) + " does not exist");
  }
  if (on_path_[static_cast<std::size_t>(node)] || depth > 1000) {
    return Error("the node hierarchy has a cycle through node " + std::to_string(node));
  }
  const tinygltf::Node& n = model_.nodes[static_cast<std::size_t>(node)];
  Result<glm::dmat4> local = LocalMatrix(n);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite((*local)[c][r])) {
        return Error("node " + std::to_string(node) + " has a NaN or infinite transform");
      }
  const glm::dmat4 world = parent * *local;
  if (n.mesh >= 0) {
    if (static_cast<std::size_t>(n.mesh) >= model_.meshes.size()) {
      return Error("node " + std::to_string(node) + " names mesh " + std::to_string(n.mesh) +
                   ", which does not exist");
    }
    if (counting_) {
      counted_ += CountTriangles(n.mesh);
    } else {
      NIWA_RETURN_IF_ERROR(AddMesh(n.mesh, world));
    }
  }
  on_path_[static_cast<std::size_t>(node)] = true;
  for (int child : n.children) NIWA_RETURN_IF_ERROR(VisitNode(child, world, depth + 1));
  on_path_[static_cast<std::size_t>(node)] = false;
  return Status::Ok();
}

Status Reader::VisitScene() {
  on_path_.assign(model_.nodes.size(), false);
  const glm::dmat4 identity(1.0);
  if (!model_.scenes.empty()) {
    std::size_t scene = model_.defaultScene >= 0 &&
                                static_cast<std::size_t>(model_.defaultScene) < model_.scenes.size()
                            ? static_cast<std::size_t>(model_.defaultScene)
                            : 0;
    for (int root : model_.scenes[scene].nodes) NIWA_RETURN_IF_ERROR(VisitNode(root, identity, 0));
    return Status::Ok();
  }
  // No scene: every node that is nobody's child is a root.
  std::vector<bool> is_child(model_.nodes.size(), false);
  for (const tinygltf::Node& n : model_.nodes)
    for (int c : n.children)
      if (c >= 0 && static_cast<std::size_t>(c) < is_child.size()) {
        is_child[static_cast<std::size_t>(c)] = true;
      }
  for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
    if (!is_child[i]) NIWA_RETURN_IF_ERROR(VisitNode(static_cast<int>(i), identity, 0));
  }
  return Status::Ok();
}

Status Reader::ReadImage(int index, MeshImage* out) const {
  const tinygltf::Image& im = model_.images[static_cast<std::size_t>(index)];
  const std::string label =
      "image " + std::to_string(index) + (im.name.empty() ? "" : " '" + im.name + "'");
  out->name =
      !im.name.empty() ? im.name : (!im.uri.empty() ? im.uri : "image " + std::to_string(index));
  std::string bytes;
  if (im.bufferView >= 0) {
    if (static_cast<std::size_t>(im.bufferView) >= model_.bufferViews.size()) {
      return Error(label + " names buffer view " + std::to_string(im.bufferView) +
                   ", which does not exist");
    }
    const tinygltf::BufferView& bv = model_.bufferViews[static_cast<std::size_t>(im.bufferView)];
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model_.buffers.size()) {
      return Error(label + " buffer view " + std::to_string(im.bufferView) + " has no buffer");
    }
    const std::vector<unsigned char>& buffer =
        model_.buffers[static_cast<std::size_t>(bv.buffer)].data;
    if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset) {
      return Error(label + " reads past the end of its buffer (truncated file?)");
    }
    bytes.assign(reinterpret_cast<const char*>(buffer.data()) + bv.byteOffset, bv.byteLength);
  } else if (auto kept = uri_images_.find(index); kept != uri_images_.end()) {
    bytes = kept->second;
  } else if (!im.uri.empty() && !base_dir_.empty()) {
    const std::string uri = im.uri.rfind("./", 0) == 0 ? im.uri.substr(2) : im.uri;
    if (uri.find("..") != std::string::npos || uri.find(':') != std::string::npos ||
        uri.front() == '/') {
      return Error(label + " uri '" + uri + "' must be a file beside the .gltf");
    }
    Result<std::string> file = ReadFileCapped(base_dir_ + "/" + uri);
    if (!file.ok()) return Error(label + ": " + file.status().Line());
    bytes = std::move(*file);
  } else if (!im.uri.empty()) {
    return Status::Ok();  // an external file of a .gltf given as bytes: not readable here
  } else {
    return Error(label + " has neither a buffer view nor a uri");
  }
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const image::ImageFormat format = image::SniffImageFormat(data, bytes.size());
  if (format == image::ImageFormat::kWebp || format == image::ImageFormat::kKtx2 ||
      (format == image::ImageFormat::kUnknown &&
       (im.mimeType == "image/webp" || im.mimeType == "image/ktx2"))) {
    return Status::Ok();  // a format this build does not decode: no bytes kept
  }
  if (bytes.empty()) return Error(label + " has no bytes");
  Result<image::ImageSize> size = image::ReadImageSize(data, bytes.size());
  if (!size.ok()) return Error(label + ": " + size.status().message());
  if (size->width < 1 || size->height < 1 || size->width > kMaxTextureSide ||
      size->height > kMaxTextureSide ||
      static_cast<std::size_t>(size->width) * static_cast<std::size_t>(size->height) >
          kMaxTexturePixels) {
    return Error(label + " is " + std::to_string(size->width) + " x " +
                 std::to_string(size->height) + " pixels; each side must be in [1, " +
                 std::to_string(kMaxTextureSide) + "] with at most " +
                 std::to_string(kMaxTexturePixels) + " pixels");
  }
  out->width = size->width;
  out->height = size->height;
  out->bytes = std::move(bytes);
  return Status::Ok();
}

Status Reader::ReadBaseColorUvs() {
  base_uv_.assign(model_.materials.size(), BaseColorUv{});
  for (std::size_t mi = 0; mi < model_.materials.size(); ++mi) {
    const tinygltf::Material& m = model_.materials[mi];
    const tinygltf::TextureInfo& info = m.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) continue;
    BaseColorUv& b = base_uv_[mi];
    b.label = "material " + std::to_string(mi) + (m.name.empty() ? "" : " '" + m.name + "'") +
              " baseColorTexture";
    // A set above 31 is refused with the rest: no primitive can have it under the preflight's
    // attribute limits, and the number stays short in the error line.
    auto check_set = [&](int set, const std::string& where) -> Status {
      if (set < 0 || set > 31) {
        return Error(b.label + (where.empty() ? "" : " " + where) + " texCoord " +
                     std::to_string(set) +
                     " is out of range; must be an integer in [0, 31]");
      }
      return Status::Ok();
    };
    NIWA_RETURN_IF_ERROR(check_set(info.texCoord, ""));
    b.set = info.texCoord;
    auto ext = info.extensions.find("KHR_texture_transform");
    if (ext == info.extensions.end()) continue;
    const tinygltf::Value& t = ext->second;
    const std::string where = b.label + " KHR_texture_transform";
    if (!t.IsObject()) return Error(where + " must be an object");
    auto pair = [&](const char* key, double* out) -> Status {
      if (!t.Has(key)) return Status::Ok();
      const tinygltf::Value& v = t.Get(key);
      if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber() ||
          !std::isfinite(v.Get(0).GetNumberAsDouble()) ||
          !std::isfinite(v.Get(1).GetNumberAsDouble())) {
        return Error(where + " " + key + " must be two finite numbers");
      }
      out[0] = v.Get(0).GetNumberAsDouble();
      out[1] = v.Get(1).GetNumberAsDouble();
      return Status::Ok();
    };
    NIWA_RETURN_IF_ERROR(pair("offset", b.offset));
    NIWA_RETURN_IF_ERROR(pair("scale", b.scale));
    if (t.Has("rotation")) {
      const tinygltf::Value& r = t.Get("rotation");
      if (!r.IsNumber() || !std::isfinite(r.GetNumberAsDouble())) {
        return Error(where + " rotation must be a finite number (radians)");
      }
      b.rotation = r.GetNumberAsDouble();
    }
    if (t.Has("texCoord")) {
      const tinygltf::Value& c = t.Get("texCoord");
      if (!c.IsInt()) {
        return Error(where + " texCoord must be an integer in [0, 31]");
      }
      NIWA_RETURN_IF_ERROR(check_set(c.GetNumberAsInt(), "KHR_texture_transform"));
      b.set = c.GetNumberAsInt();
    }
    det::SinCos(b.rotation, &b.sin_r, &b.cos_r);
    b.transform = b.offset[0] != 0.0 || b.offset[1] != 0.0 || b.rotation != 0.0 ||
                  b.scale[0] != 1.0 || b.scale[1] != 1.0;
  }
  return Status::Ok();
}

Status Reader::ReadMaterials(std::vector<MeshMaterial>* materials,
                             std::vector<MeshImage>* images) const {
  images->assign(model_.images.size(), MeshImage{});
  for (std::size_t i = 0; i < images->size(); ++i) {
    (*images)[i].name = "image " + std::to_string(i);
  }
  std::vector<bool> read(model_.images.size(), false);
  for (std::size_t mi = 0; mi < model_.materials.size(); ++mi) {
    const tinygltf::Material& m = model_.materials[mi];
    MeshMaterial material;
    material.name = m.name;
    const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4) {
      material.base_color = glm::vec4(static_cast<float>(f[0]), static_cast<float>(f[1]),
                                      static_cast<float>(f[2]), static_cast<float>(f[3]));
    }
    if (m.extras.IsObject() && m.extras.Has("niwa_ivy") && m.extras.Get("niwa_ivy").IsBool()) {
      material.ivy_support = m.extras.Get("niwa_ivy").Get<bool>();
    }
    const tinygltf::TextureInfo& info = m.pbrMetallicRoughness.baseColorTexture;
    if (info.index >= 0) {
      const std::string label = "material " + std::to_string(mi) +
                                (m.name.empty() ? "" : " '" + m.name + "'") + " baseColorTexture";
      if (static_cast<std::size_t>(info.index) >= model_.textures.size()) {
        return Error(label + " names texture " + std::to_string(info.index) +
                     ", which does not exist");
      }
      const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(info.index)];
      int source = texture.source;
      for (const char* ext : {"EXT_texture_webp", "KHR_texture_basisu", "EXT_texture_avif"}) {
        auto it = texture.extensions.find(ext);
        if (source < 0 && it != texture.extensions.end() && it->second.IsObject() &&
            it->second.Get("source").IsInt()) {
          source = it->second.Get("source").GetNumberAsInt();
        }
      }
      if (source < 0 || static_cast<std::size_t>(source) >= model_.images.size()) {
        return Error(label + " texture " + std::to_string(info.index) + " names image " +
                     std::to_string(source) + ", which does not exist");
      }
      if (!read[static_cast<std::size_t>(source)]) {
        NIWA_RETURN_IF_ERROR(ReadImage(source, &(*images)[static_cast<std::size_t>(source)]));
        read[static_cast<std::size_t>(source)] = true;
      }
      material.base_color_source = source;
      if (!(*images)[static_cast<std::size_t>(source)].bytes.empty()) {
        material.base_color_image = source;
      }
      if (mi < base_uv_.size() && base_uv_[mi].set >= 0) {
        const BaseColorUv& b = base_uv_[mi];
        material.base_color_tex_coord = b.set;
        material.has_uv_transform = b.transform;
        material.uv_offset[0] = b.offset[0];
        material.uv_offset[1] = b.offset[1];
        material.uv_rotation = b.rotation;
        material.uv_scale[0] = b.scale[0];
        material.uv_scale[1] = b.scale[1];
      }
      if (texture.sampler >= 0 &&
          static_cast<std::size_t>(texture.sampler) < model_.samplers.size()) {
        const tinygltf::Sampler& sampler =
            model_.samplers[static_cast<std::size_t>(texture.sampler)];
        auto wrap = [](int mode) {
          return mode == kWrapClampToEdge || mode == kWrapMirroredRepeat ? mode : kWrapRepeat;
        };
        material.wrap_s = wrap(sampler.wrapS);
        material.wrap_t = wrap(sampler.wrapT);
      }
    }
    materials->push_back(std::move(material));
  }
  return Status::Ok();
}

Status Reader::Run(geom::TriMesh* out) {
  for (const std::string& ext : model_.extensionsRequired) {
    if (ext == kDraco || ExtensionIsHarmless(ext)) continue;
    return Error("required extension " + ext + " is not supported");
  }
  NIWA_RETURN_IF_ERROR(ReadBaseColorUvs());
  counting_ = true;
  NIWA_RETURN_IF_ERROR(VisitScene());
  if (counted_ > kMaxMeshTriangles) {
    return Error(std::to_string(counted_) + " triangles in the scene; the limit is " +
                 std::to_string(kMaxMeshTriangles) + " (4 M)");
  }
  counting_ = false;
  // The materials and their images before the triangles: a texture's own fault is named before a
  // primitive's missing UV set for it.
  std::vector<MeshMaterial> materials;
  std::vector<MeshImage> images;
  NIWA_RETURN_IF_ERROR(ReadMaterials(&materials, &images));
  NIWA_RETURN_IF_ERROR(VisitScene());
  if (triangle_primitives_ == 0) {
    if (line_point_primitives_ > 0) {
      return Error("only points or lines (" + std::to_string(line_point_primitives_) +
                   " primitives), no triangles");
    }
    return Error("no triangle meshes in the scene");
  }
  if (mesh_.indices.empty()) return Error("every triangle is degenerate (zero area)");
  if (!all_normals_) mesh_.normals.clear();
  if (!all_uvs_) mesh_.uvs.clear();
  if (!model_.materials.empty()) {
    mesh_.attributes.push_back({kMaterialAttribute, 1, std::move(materials_)});
  }
  if (any_color_) mesh_.attributes.push_back({kColorAttribute, 4, std::move(colors_)});
  if (any_base_uv_) {
    mesh_.attributes.push_back({kBaseColorUvAttribute, 2, std::move(base_uv_values_)});
  }
  if (stats_ != nullptr) {
    stats_->materials = std::move(materials);
    stats_->images = std::move(images);
    stats_->metres_per_unit = 1;  // glTF 2.0 §3.4
  }
  *out = std::move(mesh_);
  return Status::Ok();
}

}  // namespace

bool GltfReaderDecodesDraco() {
#ifdef NIWA_HAVE_DRACO
  return true;
#else
  return false;
#endif
}

Result<geom::TriMesh> ReadGltfMesh(const std::string& bytes, const std::string& name,
                                   const std::string& base_dir, MeshReadStats* stats) {
  if (bytes.empty()) return Status::Error(name, "the file is empty");
  if (bytes.size() > kMaxMeshFileBytes) {
    return Status::Error(name, "the file has " + std::to_string(bytes.size()) +
                                   " bytes; the limit is " + std::to_string(kMaxMeshFileBytes));
  }
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (binary) {
    if (bytes.size() < 20) {
      return Status::Error(
          name, "truncated: a .glb needs a 12-byte header and a JSON chunk, the file has " +
                    std::to_string(bytes.size()) + " bytes");
    }
    uint32_t length;
    std::memcpy(&length, bytes.data() + 8, 4);
    if (length > bytes.size()) {
      return Status::Error(name, "truncated: the .glb header says " + std::to_string(length) +
                                     " bytes, the file has " + std::to_string(bytes.size()));
    }
  } else {
    std::size_t first = bytes.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || bytes[first] != '{') {
      return Status::Error(name, "not glTF: neither a binary .glb (magic 'glTF') nor glTF JSON");
    }
  }
  // The JSON (a .glb's first chunk) is checked before tinygltf parses it: its extras are turned
  // into tinygltf::Value recursively, and its counts are read into size_t.
  std::string_view json_text(bytes);
  if (binary) {
    uint32_t json_length = 0;
    std::memcpy(&json_length, bytes.data() + 12, 4);
    json_text =
        json_length <= bytes.size() - 20 ? json_text.substr(20, json_length) : std::string_view();
  }
  NIWA_RETURN_IF_ERROR(PreflightGltfJson(json_text, name));
  tinygltf::TinyGLTF loader;
  std::map<int, std::string> uri_images;
  loader.SetImageLoader(KeepUriImage, &uri_images);
  FsContext fs_context;
  fs_context.allow = !base_dir.empty();
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&ExternalExists, &tinygltf::ExpandFilePath,
                                              &ReadExternal, &tinygltf::WriteWholeFile,
                                              &fs_context});
  tinygltf::Model model;
  std::string err, warn;
  DracoIndexCounts draco_counts;
  const std::string patched = DetachDracoIndices(bytes, binary, &draco_counts);
  const std::string& input = patched.empty() ? bytes : patched;
  bool ok = binary ? loader.LoadBinaryFromMemory(
                         &model, &err, &warn, reinterpret_cast<const unsigned char*>(input.data()),
                         static_cast<unsigned int>(input.size()), base_dir)
                   : loader.LoadASCIIFromString(&model, &err, &warn, input.data(),
                                                static_cast<unsigned int>(input.size()), base_dir);
  if (!ok && fs_context.refused) {
    return Status::Error(name,
                         "external file '" + fs_context.refused_path +
                             "' cannot be read here; embed buffers as data: URIs or use .glb");
  }
  if (!ok) {
    return Status::Error(
        name, "cannot parse glTF: " + (err.empty() ? std::string("unknown error") : OneLine(err)));
  }
  if (stats != nullptr) *stats = MeshReadStats{};
  geom::TriMesh mesh;
  Reader reader(model, name, draco_counts, uri_images, base_dir, stats);
  NIWA_RETURN_IF_ERROR(reader.Run(&mesh));
  return mesh;
}

Result<geom::TriMesh> ReadGltfFile(const std::string& path, MeshReadStats* stats) {
  Result<std::string> bytes = ReadFileCapped(path);
  if (!bytes.ok()) return bytes.status();
  std::size_t slash = path.find_last_of("/\\");
  std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
  return ReadGltfMesh(*bytes, BaseName(path), dir, stats);
}

}  // namespace niwa::io
