// Hostile glTF files built byte by byte (issue 34): deep JSON in any extras, repeated keys, an
// accessor whose count times stride wraps, a buffer view whose offset wraps, negative short
// indices, a node graph that instances a mesh millions of times and a vertex bomb each give one
// line naming the file, before anything is sized from the hostile numbers; the same lines natively
// and in WASM (the checks are 64-bit on both).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/gltf_preflight.h"
#include "io/gltf_reader.h"
#include "io/mesh_reader.h"

namespace niwa::io {
namespace {

void Append32(std::string* out, uint32_t v) { out->append(reinterpret_cast<const char*>(&v), 4); }

// A .glb: header, the JSON chunk (space-padded), the BIN chunk (zero-padded) when bin is not empty.
std::string Glb(std::string json, std::string bin) {
  while (json.size() % 4 != 0) json.push_back(' ');
  while (bin.size() % 4 != 0) bin.push_back('\0');
  std::string out = "glTF";
  Append32(&out, 2);
  Append32(&out, static_cast<uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  Append32(&out, static_cast<uint32_t>(json.size()));
  out += "JSON";
  out += json;
  if (!bin.empty()) {
    Append32(&out, static_cast<uint32_t>(bin.size()));
    out.append("BIN\0", 4);
    out += bin;
  }
  return out;
}

// Three float VEC3 positions (36 bytes) then three 16-bit indices (6 bytes, 2 of padding).
std::string TriangleBin(int16_t i0 = 0, int16_t i1 = 1, int16_t i2 = 2) {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string bin(reinterpret_cast<const char*>(p), sizeof p);
  const int16_t idx[4] = {i0, i1, i2, 0};
  bin.append(reinterpret_cast<const char*>(idx), sizeof idx);
  return bin;
}

struct Parts {
  std::string asset = R"({"version": "2.0"})";
  std::string scene_nodes = "[0]";
  std::string nodes = R"([{"mesh": 0}])";
  std::string primitive_extra;  // e.g. ", \"extensions\": {...}"
  std::string position_count = "3";
  std::string index_type = "5123";
  std::string views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                          {"buffer": 0, "byteOffset": 36, "byteLength": 6}])";
  std::string buffer_length = "44";
  std::string extra_members;  // e.g. ", \"extensionsUsed\": [...]"
};

std::string Json(const Parts& p) {
  return R"({"asset": )" + p.asset + R"(, "scene": 0, "scenes": [{"nodes": )" + p.scene_nodes +
         R"(}], "nodes": )" + p.nodes +
         R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1)" +
         p.primitive_extra + R"(}]}], "accessors": [{"bufferView": 0, "componentType": 5126,
         "count": )" +
         p.position_count + R"(, "type": "VEC3"}, {"bufferView": 1, "componentType": )" +
         p.index_type + R"(, "count": 3, "type": "SCALAR"}], "bufferViews": )" + p.views +
         R"(, "buffers": [{"byteLength": )" + p.buffer_length + "}]" + p.extra_members + "}";
}

std::string LineOf(const std::string& bytes, const std::string& name = "hostile.glb") {
  Result<geom::TriMesh> mesh = ReadMeshBytes(bytes, name);
  return mesh.ok() ? "(read " + std::to_string(mesh->triangle_count()) + " triangles)"
                   : mesh.status().Line();
}

std::string Deep(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }

TEST(GltfHostile, TheBaseFileReads) {
  EXPECT_EQ(LineOf(Glb(Json(Parts()), TriangleBin())), "(read 1 triangles)");
}

TEST(GltfHostile, DeepJsonAnywhereIsRefusedBeforeParsing) {
  Parts asset;
  asset.asset = R"({"version": "2.0", "extras": )" + Deep(30000) + "}";
  EXPECT_EQ(LineOf(Glb(Json(asset), TriangleBin())), "hostile.glb: nested deeper than 32 levels");
  Parts node;
  node.nodes = R"([{"mesh": 0, "extras": {"a": )" + Deep(30000) + "}}]";
  EXPECT_EQ(LineOf(Glb(Json(node), TriangleBin())), "hostile.glb: nested deeper than 32 levels");
  // The same in a .gltf text file, and beside a Draco extension (the reader's Draco pass parses
  // the JSON too).
  Parts draco = node;
  draco.primitive_extra =
      R"(, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {}}})";
  EXPECT_EQ(LineOf(Glb(Json(draco), TriangleBin())), "hostile.glb: nested deeper than 32 levels");
  EXPECT_EQ(LineOf(Json(node), "hostile.gltf"), "hostile.gltf: nested deeper than 32 levels");
}

TEST(GltfHostile, RepeatedKeysAreRefused) {
  Parts p;
  p.asset = R"({"version": "2.0", "version": "2.0"})";
  EXPECT_EQ(LineOf(Glb(Json(p), TriangleBin())), "hostile.glb: version: given twice in one object");
  Parts q;
  q.nodes = R"([{"mesh": 0, "extras": {"a": {"b": 1}, "a": 2}}])";
  EXPECT_EQ(LineOf(Glb(Json(q), TriangleBin())), "hostile.glb: a: given twice in one object");
}

TEST(GltfHostile, AccessorWhoseSizeWrapsIsRefusedBeforeAnyResize) {
  // 12 * (count - 1) wraps 64 bits to 8: the old check passed and the reader resized to count.
  Parts wrap64;
  wrap64.position_count = "1537228672809129303";  // 0x1555555555555557
  EXPECT_EQ(LineOf(Glb(Json(wrap64), TriangleBin())),
            "hostile.glb: accessor 0 (1537228672809129303 elements) reads past the end of its "
            "buffer view (truncated file?)");
  // 12 * (count - 1) wraps 32 bits (WASM's size_t) to 8.
  Parts wrap32;
  wrap32.position_count = "357913943";  // 0x15555557
  EXPECT_EQ(LineOf(Glb(Json(wrap32), TriangleBin())),
            "hostile.glb: accessor 0 (357913943 elements) reads past the end of its buffer view "
            "(truncated file?)");
}

TEST(GltfHostile, BufferViewWhoseOffsetWrapsIsRefused) {
  Parts p;
  p.views = R"([{"buffer": 0, "byteOffset": 18446744073709551608, "byteLength": 44},
                {"buffer": 0, "byteOffset": 36, "byteLength": 6}])";
  EXPECT_EQ(LineOf(Glb(Json(p), TriangleBin())),
            "hostile.glb: buffer view 0 reads past the end of its buffer (truncated file?)");
  Parts big;
  big.buffer_length = "1099511627776";
  EXPECT_EQ(LineOf(Glb(Json(big), TriangleBin())),
            "hostile.glb: buffer 0 declares 1099511627776 bytes; the limit is 536870912");
}

TEST(GltfHostile, NegativeShortIndicesAreReadUnsignedAndRangeChecked) {
  Parts p;
  p.index_type = "5122";  // SHORT: not allowed for indices, read as UNSIGNED_SHORT
  EXPECT_EQ(LineOf(Glb(Json(p), TriangleBin(0, 1, -1))),
            "hostile.glb: mesh 0 primitive 0 index 65535 is out of range; must be below its 3 "
            "vertices");
  EXPECT_EQ(LineOf(Glb(Json(p), TriangleBin(0, 1, 2))), "(read 1 triangles)");
}

TEST(GltfHostile, MillionfoldInstancingIsRefusedUpFront) {
  // A chain of 21 nodes, each naming the next twice: 2^20 instances of the mesh, 2^21 - 1 nodes.
  std::string nodes = "[";
  for (int i = 0; i < 20; ++i) {
    nodes += "{\"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]},";
  }
  nodes += R"({"mesh": 0}])";
  Parts doubling;
  doubling.nodes = nodes;
  EXPECT_EQ(LineOf(Glb(Json(doubling), TriangleBin())),
            "hostile.glb: the scene places 2097151 node instances; the limit is 1000000 (1 M)");
  // One node named 1 000 001 times by the scene.
  Parts flat;
  flat.scene_nodes = "[0";
  for (int i = 0; i < 1000000; ++i) flat.scene_nodes += ",0";
  flat.scene_nodes += "]";
  EXPECT_EQ(LineOf(Glb(Json(flat), TriangleBin())),
            "hostile.glb: the scene places 1000001 node instances; the limit is 1000000 (1 M)");
  // 2^200 paths through a 201-node graph: counted, saturating, not walked.
  nodes = "[";
  for (int i = 0; i < 200; ++i) {
    nodes += "{\"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]},";
  }
  nodes += R"({"mesh": 0}])";
  Parts huge;
  huge.nodes = nodes;
  EXPECT_EQ(LineOf(Glb(Json(huge), TriangleBin())),
            "hostile.glb: the scene places more than 10^19 node instances; the limit is 1000000 "
            "(1 M)");
}

TEST(GltfHostile, VertexBombIsRefusedBeforeAllocating) {
  // 4 000 positions (one triangle indexed) instanced 3 001 times: 12 004 000 vertices.
  std::string bin(4000 * 12, '\0');
  bin += TriangleBin().substr(36);
  Parts p;
  p.position_count = "4000";
  p.views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 48000},
                {"buffer": 0, "byteOffset": 48000, "byteLength": 6}])";
  p.buffer_length = "48008";
  p.scene_nodes = "[0";
  for (int i = 0; i < 3000; ++i) p.scene_nodes += ",0";
  p.scene_nodes += "]";
  EXPECT_EQ(LineOf(Glb(Json(p), bin)),
            "hostile.glb: 12004000 vertices in the scene; the limit is 12000000 (12 M)");
  // A count with no buffer view (as Draco's accessors) is capped by itself.
  Parts declared;
  declared.extra_members = "";
  std::string json = Json(declared);
  const std::string from = R"({"bufferView": 1, "componentType": 5123, "count": 3,)";
  json.replace(json.find(from), from.size(), R"({"componentType": 5123, "count": 17179869187,)");
  EXPECT_EQ(LineOf(Glb(json, TriangleBin())),
            "hostile.glb: accessor 1 declares 17179869187 elements; the limit is 12000000");
}

// One triangle with NORMAL, TEXCOORD_0 and COLOR_0 (all float): `bad` names the attribute whose
// vertex 1 gets `value` in its first component (nothing when empty).
std::string AttributedTriangle(const std::string& bad, float value) {
  float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  float nrm[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  float uv[6] = {0, 0, 1, 0, 0, 1};
  float col[12] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  if (bad == "POSITION") pos[3] = value;
  if (bad == "NORMAL") nrm[3] = value;
  if (bad == "TEXCOORD_0") uv[2] = value;
  if (bad == "COLOR_0") col[4] = value;
  std::string bin(reinterpret_cast<const char*>(pos), sizeof pos);
  bin.append(reinterpret_cast<const char*>(nrm), sizeof nrm);
  bin.append(reinterpret_cast<const char*>(uv), sizeof uv);
  bin.append(reinterpret_cast<const char*>(col), sizeof col);
  const uint16_t idx[4] = {0, 1, 2, 0};
  bin.append(reinterpret_cast<const char*>(idx), sizeof idx);
  const std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0,
    "NORMAL": 1, "TEXCOORD_0": 2, "COLOR_0": 3}, "indices": 4}]}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
      {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
      {"bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC4"},
      {"bufferView": 4, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
      {"buffer": 0, "byteOffset": 36, "byteLength": 36},
      {"buffer": 0, "byteOffset": 72, "byteLength": 24},
      {"buffer": 0, "byteOffset": 96, "byteLength": 48},
      {"buffer": 0, "byteOffset": 144, "byteLength": 6}],
    "buffers": [{"byteLength": 152}]})";
  return Glb(json, bin);
}

// Issue 34: NaN and infinite normals, UVs and colours were read into the mesh (only positions
// were checked); each is refused naming its primitive, attribute and vertex.
TEST(GltfHostile, NonFiniteAttributesAreRefusedNamingTheAttribute) {
  EXPECT_EQ(LineOf(AttributedTriangle("", 0)), "(read 1 triangles)");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const char* attribute : {"POSITION", "NORMAL", "TEXCOORD_0", "COLOR_0"}) {
    for (const float value : {nan, inf, -inf}) {
      EXPECT_EQ(
          LineOf(AttributedTriangle(attribute, value)),
          std::string("hostile.glb: mesh 0 primitive 0 ") + attribute + " 1 is NaN or infinite")
          << attribute << " " << value;
    }
  }
}

// A Draco header (bitstream 2.2, triangular mesh) declaring `points` and `faces`, then zeros.
std::string DracoHeader(int method, uint64_t points, uint64_t faces) {
  std::string h = "DRACO";
  h += std::string{'\x02', '\x02', '\x01', static_cast<char>(method), '\0', '\0'};
  auto varint = [&](uint64_t v) {
    do {
      const uint8_t c = static_cast<uint8_t>(v & 0x7f);
      v >>= 7;
      h.push_back(static_cast<char>(v != 0 ? c | 0x80 : c));
    } while (v != 0);
  };
  if (method == 1) {
    h.push_back('\0');  // traversal decoder type
    varint(points);
    varint(faces);
  } else {
    varint(faces);
    varint(points);
  }
  return h + std::string(32, '\0');
}

// The base triangle (its plain accessors as the fallback) with a Draco primitive in view 2.
std::string DracoGlb(const std::string& draco) {
  std::string bin = TriangleBin() + draco;
  while (bin.size() % 4 != 0) bin.push_back('\0');
  Parts p;
  p.views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                {"buffer": 0, "byteOffset": 44, "byteLength": )" +
            std::to_string(draco.size()) + "}]";
  p.buffer_length = std::to_string(bin.size());
  p.primitive_extra = R"(, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 2,
                         "attributes": {"POSITION": 0}}})";
  p.extra_members = R"(, "extensionsUsed": ["KHR_draco_mesh_compression"])";
  return Glb(Json(p), bin);
}

// Issue 34: a Draco buffer declaring far more points or faces than the reader's limits is refused
// from its header before the decoder sizes anything (both encodings; the same on every build, as
// the preflight is plain C++). Counts within the limits but beyond the bytes are Draco's own
// refusal (1.5.5 checks them against the buffer: 2^28 faces in 45 bytes peak at 6 MB).
TEST(GltfHostile, DracoCountsBeyondTheLimitsAreRefusedFromTheHeader) {
  for (const int method : {0, 1}) {
    EXPECT_TRUE(PreflightDracoHeader(DracoHeader(method, 3, 1), "m").ok());
    EXPECT_TRUE(
        PreflightDracoHeader(DracoHeader(method, kMaxMeshVertices, kMaxMeshTriangles), "m").ok());
    EXPECT_EQ(PreflightDracoHeader(DracoHeader(method, 49, uint64_t{1} << 28), "m").message(),
              "m: the Draco data declares 49 vertices and 268435456 triangles; the limits are "
              "12000000 and 4000000");
    EXPECT_EQ(PreflightDracoHeader(DracoHeader(method, 0xffffffffu, 1), "m").message(),
              "m: the Draco data declares 4294967295 vertices and 1 triangles; the limits are "
              "12000000 and 4000000");
  }
  // Not a 2.2 mesh header, or too short to say: left to the decoder.
  EXPECT_TRUE(PreflightDracoHeader("DRACO", "m").ok());
  EXPECT_TRUE(PreflightDracoHeader(DracoHeader(1, 1, 1).substr(0, 13) + "\xff\xff", "m").ok());
  // Whole files: natively the header's line; a build without Draco reads the plain fallback.
  const std::string huge = LineOf(DracoGlb(DracoHeader(1, 49, uint64_t{1} << 28)));
  const std::string beyond = LineOf(DracoGlb(DracoHeader(0, 9000000, 3000000)));
  if (GltfReaderDecodesDraco()) {
    EXPECT_EQ(huge,
              "hostile.glb: mesh 0 primitive 0: the Draco data declares 49 vertices and 268435456 "
              "triangles; the limits are 12000000 and 4000000");
    EXPECT_EQ(beyond,
              "hostile.glb: mesh 0 primitive 0: Draco cannot decode it (Failed to decode geometry "
              "data.)");
  } else {
    EXPECT_EQ(huge, "(read 1 triangles)");
    EXPECT_EQ(beyond, "(read 1 triangles)");
  }
}

}  // namespace
}  // namespace niwa::io
