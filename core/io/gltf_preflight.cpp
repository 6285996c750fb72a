// The glTF JSON preflight (see gltf_preflight.h): one nlohmann document, read only through find()
// and is_* checks, numbers in uint64_t with overflow-checked arithmetic, the node graph walked
// iteratively with memoized instance counts.
#include "io/gltf_preflight.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "io/mesh_reader.h"
#include "params/json_guard.h"

namespace niwa::io {
namespace {

using nlohmann::json;
constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max();
constexpr int kMaxNodeDepth = 1000;  // as the reader's scene walk

const json* Member(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// An unsigned integer member; `fallback` when absent, nullopt when present but not one (tinygltf
// then refuses the file or ignores the member: either way it is its call).
std::optional<uint64_t> Unsigned(const json& object, const char* key, uint64_t fallback) {
  const json* v = Member(object, key);
  if (v == nullptr) return fallback;
  if (!v->is_number_unsigned()) return std::nullopt;
  return v->get<uint64_t>();
}

// An integer as tinygltf reads it (GetInt: any JSON integer, cast to int), or -1.
int IntLike(const json* v) {
  if (v == nullptr || !(v->is_number_integer())) return -1;
  return static_cast<int>(v->get<int64_t>());
}

// An integer array as tinygltf reads it: the integers up to the first element that is not one.
std::vector<int> IntArray(const json& object, const char* key) {
  std::vector<int> out;
  const json* v = Member(object, key);
  if (v == nullptr || !v->is_array()) return out;
  for (const json& item : *v) {
    if (!item.is_number_integer()) break;
    out.push_back(static_cast<int>(item.get<int64_t>()));
  }
  return out;
}

uint64_t SatMul(uint64_t a, uint64_t b) { return a != 0 && b > kMax / a ? kMax : a * b; }
uint64_t SatAdd(uint64_t a, uint64_t b) { return b > kMax - a ? kMax : a + b; }

int ComponentBytes(int64_t component_type) {
  switch (component_type) {
    case 5120:  // BYTE
    case 5121:  // UNSIGNED_BYTE
      return 1;
    case 5122:  // SHORT
    case 5123:  // UNSIGNED_SHORT
      return 2;
    case 5125:  // UNSIGNED_INT
    case 5126:  // FLOAT
      return 4;
    default:
      return 0;
  }
}

int Components(const json* type) {
  if (type == nullptr || !type->is_string()) return 0;
  const std::string& t = type->get_ref<const std::string&>();
  if (t == "SCALAR") return 1;
  if (t == "VEC2") return 2;
  if (t == "VEC3") return 3;
  if (t == "VEC4" || t == "MAT2") return 4;
  if (t == "MAT3") return 9;
  if (t == "MAT4") return 16;
  return 0;
}

std::string Text(uint64_t n) { return n == kMax ? "more than 10^19" : std::to_string(n); }

class Preflight {
 public:
  Preflight(const json& doc, const std::string& name) : doc_(doc), name_(name) {}

  Status Run() {
    NIWA_RETURN_IF_ERROR(CheckBuffers());
    NIWA_RETURN_IF_ERROR(CheckAccessors());
    return CheckScene();
  }

 private:
  Status Error(const std::string& message) const { return Status::Error(name_, message); }
  const json& Array(const char* key) const {
    static const json kEmpty = json::array();
    const json* v = Member(doc_, key);
    return v != nullptr && v->is_array() ? *v : kEmpty;
  }

  // Declared buffer lengths at most a whole mesh file; buffer views inside their buffers.
  Status CheckBuffers() {
    const json& buffers = Array("buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      std::optional<uint64_t> length = Unsigned(buffers[i], "byteLength", 0);
      if (length && *length > kMaxMeshFileBytes) {
        return Error("buffer " + std::to_string(i) + " declares " + Text(*length) +
                     " bytes; the limit is " + std::to_string(kMaxMeshFileBytes));
      }
      buffer_bytes_.push_back(length.value_or(0));
    }
    const json& views = Array("bufferViews");
    for (std::size_t i = 0; i < views.size(); ++i) {
      std::optional<uint64_t> buffer = Unsigned(views[i], "buffer", kMax);
      std::optional<uint64_t> offset = Unsigned(views[i], "byteOffset", 0);
      std::optional<uint64_t> length = Unsigned(views[i], "byteLength", 0);
      std::optional<uint64_t> stride = Unsigned(views[i], "byteStride", 0);
      view_bytes_.push_back(length.value_or(0));
      view_stride_.push_back(stride && *stride <= 252 ? *stride : 0);
      if (!buffer || !offset || !length || *buffer >= buffer_bytes_.size()) continue;
      const uint64_t size = buffer_bytes_[*buffer];
      if (*offset > size || *length > size - *offset) {
        return Error("buffer view " + std::to_string(i) +
                     " reads past the end of its buffer (truncated file?)");
      }
    }
    return Status::Ok();
  }

  // Each accessor's count times its stride inside its buffer view (checked before anything is
  // sized from the count); an accessor without a buffer view (Draco's) declares at most the vertex
  // limit. Counts are kept for the scene estimate.
  Status CheckAccessors() {
    const json& accessors = Array("accessors");
    counts_.assign(accessors.size(), 0);
    for (std::size_t i = 0; i < accessors.size(); ++i) {
      const json& a = accessors[i];
      std::optional<uint64_t> count = Unsigned(a, "count", 0);
      if (!count) continue;
      counts_[i] = *count;
      const int components = Components(Member(a, "type"));
      const json* ct = Member(a, "componentType");
      const int bytes =
          ct != nullptr && ct->is_number_integer() ? ComponentBytes(ct->get<int64_t>()) : 0;
      const json* view_member = Member(a, "bufferView");
      if (view_member == nullptr) {
        if (*count > kMaxMeshVertices) {
          return Error("accessor " + std::to_string(i) + " declares " + Text(*count) +
                       " elements; the limit is " + std::to_string(kMaxMeshVertices));
        }
        continue;
      }
      std::optional<uint64_t> view = Unsigned(a, "bufferView", kMax);
      std::optional<uint64_t> offset = Unsigned(a, "byteOffset", 0);
      if (!view || !offset || *view >= view_bytes_.size() || components == 0 || bytes == 0 ||
          *count == 0) {
        continue;  // tinygltf or the reader refuses it by name
      }
      const uint64_t element = static_cast<uint64_t>(components) * static_cast<uint64_t>(bytes);
      const uint64_t stride = view_stride_[*view] > 0 ? view_stride_[*view] : element;
      // offset + stride * (count - 1) + element <= the view's length, without wrapping.
      const uint64_t length = view_bytes_[*view];
      const bool fits = *offset <= length && element <= length - *offset &&
                        (*count - 1) <= (length - *offset - element) / stride;
      if (!fits) {
        return Error("accessor " + std::to_string(i) + " (" + Text(*count) +
                     " elements) reads past the end of its buffer view (truncated file?)");
      }
    }
    return Status::Ok();
  }

  uint64_t CountOf(int accessor) const {
    return accessor >= 0 && static_cast<std::size_t>(accessor) < counts_.size()
               ? counts_[static_cast<std::size_t>(accessor)]
               : 0;
  }

  // Triangles and vertices one instance of each mesh gives (triangle modes only, as the reader
  // assembles them: indices or POSITION count, /3 for lists, n - 2 for strips and fans).
  void CountMeshes() {
    const json& meshes = Array("meshes");
    mesh_triangles_.assign(meshes.size(), 0);
    mesh_vertices_.assign(meshes.size(), 0);
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      const json* primitives = Member(meshes[m], "primitives");
      if (primitives == nullptr || !primitives->is_array()) continue;
      for (const json& p : *primitives) {
        const json* mode_member = Member(p, "mode");
        const int mode = mode_member == nullptr ? 4 : IntLike(mode_member);
        const json* attributes = Member(p, "attributes");
        const int position = attributes != nullptr ? IntLike(Member(*attributes, "POSITION")) : -1;
        const int indices = IntLike(Member(p, "indices"));
        const uint64_t n = indices >= 0 ? CountOf(indices) : CountOf(position);
        uint64_t triangles = 0;
        if (mode == 4 || mode < 0) triangles = n / 3;
        if (mode == 5 || mode == 6) triangles = n >= 3 ? n - 2 : 0;
        if (mode < 0 || mode >= 4) {
          mesh_triangles_[m] = SatAdd(mesh_triangles_[m], triangles);
          mesh_vertices_[m] = SatAdd(mesh_vertices_[m], CountOf(position));
        }
      }
    }
  }

  // The scene walk the reader will do, counted before it is done: the same roots, the same first
  // cycle or missing node, then instances per node (paths from the roots, saturating) times each
  // mesh's triangles and vertices.
  Status CheckScene() {
    const json& nodes = Array("nodes");
    if (nodes.size() > kMaxNodeInstances) {
      return Error(std::to_string(nodes.size()) + " nodes; the limit is " +
                   std::to_string(kMaxNodeInstances));
    }
    const std::size_t n = nodes.size();
    std::vector<std::vector<int>> children(n);
    std::vector<int> mesh(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
      children[i] = IntArray(nodes[i], "children");
      mesh[i] = IntLike(Member(nodes[i], "mesh"));
    }
    std::vector<int> roots;
    const json& scenes = Array("scenes");
    if (!scenes.empty()) {
      const int chosen = IntLike(Member(doc_, "scene"));
      const std::size_t s =
          chosen >= 0 && static_cast<std::size_t>(chosen) < scenes.size() ? chosen : 0;
      roots = IntArray(scenes[s], "nodes");
    } else {
      std::vector<bool> is_child(n, false);
      for (const std::vector<int>& c : children)
        for (int k : c)
          if (k >= 0 && static_cast<std::size_t>(k) < n)
            is_child[static_cast<std::size_t>(k)] = true;
      for (std::size_t i = 0; i < n; ++i)
        if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    // Depth-first in the reader's order; a finished node is not walked again (nothing below it
    // is wrong), only its height is added to the depth it is reached at.
    enum : uint8_t { kNew, kOnPath, kDone };
    std::vector<uint8_t> state(n, kNew);
    std::vector<int> height(n, 0);  // levels below a finished node
    std::vector<int> finished;      // postorder
    struct Frame {
      int node;
      std::size_t next;
      int depth;
    };
    std::vector<Frame> stack;
    auto enter = [&](int node, int depth) -> Status {
      if (node < 0 || static_cast<std::size_t>(node) >= n) {
        return Error("node " + std::to_string(node) + " does not exist");
      }
      const std::size_t u = static_cast<std::size_t>(node);
      if (state[u] == kOnPath || depth > kMaxNodeDepth ||
          (state[u] == kDone && depth + height[u] > kMaxNodeDepth)) {
        return Error("the node hierarchy has a cycle through node " + std::to_string(node));
      }
      if (state[u] == kDone) return Status::Ok();
      state[u] = kOnPath;
      stack.push_back({node, 0, depth});
      return Status::Ok();
    };
    for (int root : roots) {
      NIWA_RETURN_IF_ERROR(enter(root, 0));
      while (!stack.empty()) {
        Frame& f = stack.back();
        const std::size_t u = static_cast<std::size_t>(f.node);
        if (f.next < children[u].size()) {
          const int child = children[u][f.next++];
          NIWA_RETURN_IF_ERROR(enter(child, f.depth + 1));
          continue;
        }
        for (int c : children[u])
          height[u] = std::max(height[u], height[static_cast<std::size_t>(c)] + 1);
        state[u] = kDone;
        finished.push_back(f.node);
        stack.pop_back();
      }
    }
    // Instances: reverse postorder is a topological order of the walked graph.
    std::vector<uint64_t> paths(n, 0);
    for (int root : roots)
      paths[static_cast<std::size_t>(root)] = SatAdd(paths[static_cast<std::size_t>(root)], 1);
    CountMeshes();
    uint64_t instances = 0, triangles = 0, vertices = 0;
    for (auto it = finished.rbegin(); it != finished.rend(); ++it) {
      const std::size_t u = static_cast<std::size_t>(*it);
      instances = SatAdd(instances, paths[u]);
      if (mesh[u] >= 0 && static_cast<std::size_t>(mesh[u]) < mesh_triangles_.size()) {
        const std::size_t m = static_cast<std::size_t>(mesh[u]);
        triangles = SatAdd(triangles, SatMul(paths[u], mesh_triangles_[m]));
        vertices = SatAdd(vertices, SatMul(paths[u], mesh_vertices_[m]));
      }
      for (int c : children[u]) {
        paths[static_cast<std::size_t>(c)] = SatAdd(paths[static_cast<std::size_t>(c)], paths[u]);
      }
    }
    if (instances > kMaxNodeInstances) {
      return Error("the scene places " + Text(instances) + " node instances; the limit is " +
                   std::to_string(kMaxNodeInstances) + " (1 M)");
    }
    if (triangles > kMaxMeshTriangles) {
      return Error(Text(triangles) + " triangles in the scene; the limit is " +
                   std::to_string(kMaxMeshTriangles) + " (4 M)");
    }
    if (vertices > kMaxMeshVertices) {
      return Error(Text(vertices) + " vertices in the scene; the limit is " +
                   std::to_string(kMaxMeshVertices) + " (12 M)");
    }
    return Status::Ok();
  }

  const json& doc_;
  const std::string& name_;
  std::vector<uint64_t> buffer_bytes_, view_bytes_, view_stride_, counts_;
  std::vector<uint64_t> mesh_triangles_, mesh_vertices_;
};

}  // namespace

Status PreflightGltfJson(std::string_view json_text, const std::string& name) {
  NIWA_RETURN_IF_ERROR(CheckJsonDepth(json_text, name));
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(json_text, name).Within(name));
  const json doc = json::parse(json_text.begin(), json_text.end(), nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return Status::Ok();  // tinygltf says why
  return Preflight(doc, name).Run();
}

namespace {

// Draco's varint (LEB128, at most 5 bytes for 32 bits); false past the end or when too long.
bool DracoVarint(std::string_view b, std::size_t* at, uint64_t* out) {
  *out = 0;
  for (int shift = 0; shift < 35; shift += 7) {
    if (*at >= b.size()) return false;
    const uint8_t c = static_cast<uint8_t>(b[(*at)++]);
    *out |= static_cast<uint64_t>(c & 0x7f) << shift;
    if ((c & 0x80) == 0) return true;
  }
  return false;
}

}  // namespace

Status PreflightDracoHeader(std::string_view b, const std::string& label) {
  // "DRACO", major, minor, encoder type (1: triangular mesh), method (0 sequential, 1 edgebreaker),
  // flags (uint16, 0x8000: metadata follows).
  if (b.size() < 11 || b.substr(0, 5) != "DRACO") return Status::Ok();
  const uint8_t major = static_cast<uint8_t>(b[5]), minor = static_cast<uint8_t>(b[6]);
  const uint8_t type = static_cast<uint8_t>(b[7]), method = static_cast<uint8_t>(b[8]);
  const uint16_t flags =
      static_cast<uint16_t>(static_cast<uint8_t>(b[9]) | (static_cast<uint8_t>(b[10]) << 8));
  if (major != 2 || minor != 2 || type != 1 || (flags & 0x8000) != 0) return Status::Ok();
  std::size_t at = 11;
  uint64_t points = 0, faces = 0;
  if (method == 0) {  // sequential: faces, points
    if (!DracoVarint(b, &at, &faces) || !DracoVarint(b, &at, &points)) return Status::Ok();
  } else if (method == 1) {  // edgebreaker: traversal type, encoded vertices, faces
    ++at;
    if (!DracoVarint(b, &at, &points) || !DracoVarint(b, &at, &faces)) return Status::Ok();
  } else {
    return Status::Ok();
  }
  if (faces > kMaxMeshTriangles || points > kMaxMeshVertices) {
    return Status::Error("", label + ": the Draco data declares " + std::to_string(points) +
                                 " vertices and " + std::to_string(faces) +
                                 " triangles; the limits are " + std::to_string(kMaxMeshVertices) +
                                 " and " + std::to_string(kMaxMeshTriangles));
  }
  return Status::Ok();
}

}  // namespace niwa::io
