// Generic glTF 2.0 writer: a Document (a scene of nodes, meshes of geom::TriMesh primitives, PBR
// materials with embedded PNG textures, skins and animation clips) to .glb bytes or .gltf JSON.
// Does not: know any study (trees, ivy, terrain ... build their Document in <study>_gltf.cpp),
// encode images (callers pass PNG bytes from image/png.h), read glTF (io/gltf_reader), write
// files, or compress (no Draco, no quantization).
//
// What it writes, after the glTF 2.0 spec (numbers are its sections):
// - one buffer (the .glb BIN chunk), one tightly packed, 4-byte aligned bufferView per accessor
//   or image; vertex views get target ARRAY_BUFFER, index views ELEMENT_ARRAY_BUFFER (3.6.2);
// - per primitive: POSITION (float VEC3 with min/max, 3.7.2.1), NORMAL, TEXCOORD_0, then the
//   TriMesh's named attributes (below), indices, JOINTS_0 (unsigned short) and WEIGHTS_0;
// - named attributes: "COLOR_n" (3 or 4 floats), "TEXCOORD_n" (2) and "TANGENT" (4: xyz and the
//   bitangent sign w, for normal textures) keep their glTF semantic;
// - TANGENT computed (geom::ComputeTangentValues, after the named attributes) for a TRIANGLES
//   primitive whose material has a normal texture, with normals and uvs and no "TANGENT" of its
//   own: every normal-mapped primitive carries the tangent frame its normal map was made in;
//   every other name is application-specific and written as "_" + its name in upper case
//   ("birth_step" -> "_BIRTH_STEP", 3.7.2.1: "Application-specific attribute semantics MUST start
//   with an underscore"), 1-4 floats as SCALAR/VEC2/VEC3/VEC4;
// - materials and textures in the order the primitives first use them (then the unused ones), one
//   sampler per texture, so the bytes of a Document are fixed by its content;
// - then per node its EXT_mesh_gpu_instancing accessors (if any), skins, then animations (one
//   sampler per channel; every input accessor has min/max, 3.11).
// Same Document, same bytes (natively and in WASM): no clocks, no hash-ordered containers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "geom/tri_mesh.h"

namespace niwa::gltf {

// Primitive topology (spec 3.7.2.1, mesh.primitive.mode). Indices (or, with none, the vertices in
// order) are read as: TRIANGLES 3 per triangle, LINES 2 per segment, LINE_STRIP / LINE_LOOP one
// per point (at least 2), POINTS one per point.
enum class Mode { kPoints = 0, kLines = 1, kLineLoop = 2, kLineStrip = 3, kTriangles = 4 };

// Index component type. kAuto: unsigned short when every index fits below 65535 (the value glTF
// reserves as primitive restart), else unsigned int.
enum class IndexType { kAuto, kUint16, kUint32 };

enum class AlphaMode { kOpaque, kMask, kBlend };

// Sampler wrap modes and filters (spec 5.26, the GL enums).
enum class Wrap { kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648 };
constexpr int kFilterNearest = 9728;
constexpr int kFilterLinear = 9729;
constexpr int kFilterLinearMipmapLinear = 9987;

// An embedded PNG image with its sampler.
struct Texture {
  std::string name;
  std::vector<unsigned char> png;  // complete PNG file bytes (image/png.h)
  Wrap wrap_s = Wrap::kRepeat;
  Wrap wrap_t = Wrap::kRepeat;
  int mag_filter = kFilterLinear;
  int min_filter = kFilterLinearMipmapLinear;
};

// A metallic-roughness PBR material (spec 3.9). Texture fields are indices into
// Document::textures, -1 for none; all read TEXCOORD_0.
struct Material {
  std::string name;
  std::array<double, 4> base_color_factor{1, 1, 1, 1};
  double metallic_factor = 1.0;  // the spec's defaults
  double roughness_factor = 1.0;
  std::array<double, 3> emissive_factor{0, 0, 0};
  int base_color_texture = -1;
  int metallic_roughness_texture = -1;  // G roughness, B metalness
  int normal_texture = -1;
  double normal_scale = 1.0;
  int occlusion_texture = -1;  // R occlusion
  double occlusion_strength = 1.0;
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  double alpha_cutoff = 0.5;  // kMask only
  bool double_sided = false;
  std::string extras_json;  // "" or a JSON value, written as the material's extras
};

struct Primitive {
  Mode mode = Mode::kTriangles;
  // positions (required, finite), normals / uvs (empty or one per vertex), indices (empty: the
  // vertices in order), named attributes (see the header comment).
  geom::TriMesh mesh;
  int material = -1;  // index into Document::materials, -1 for the default material
  IndexType index_type = IndexType::kAuto;
  // Skinning (spec 3.7.3): 4 joints (indices into the node's skin's joints) and 4 weights per
  // vertex; both empty for a rigid primitive.
  std::vector<uint16_t> joints;
  std::vector<float> weights;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;  // at least one
};

// A node: TRS (written only when not the identity) or a column-major matrix, never both.
struct Node {
  std::string name;
  int mesh = -1;  // index into Document::meshes
  int skin = -1;  // index into Document::skins (needs a mesh)
  std::vector<int> children;
  std::array<double, 3> translation{0, 0, 0};
  std::array<double, 4> rotation{0, 0, 0, 1};  // unit quaternion x, y, z, w
  std::array<double, 3> scale{1, 1, 1};
  std::vector<double> matrix;  // empty, or 16 values column-major
  std::string extras_json;
  // EXT_mesh_gpu_instancing: the node's mesh drawn once per instance, each with its own TRS
  // (translations 3, rotations 4 (unit quaternion x, y, z, w), scales 3 floats per instance; each
  // empty or for every instance). Needs a mesh and no skin; adds the extension to extensionsUsed.
  std::vector<float> instance_translations;
  std::vector<float> instance_rotations;
  std::vector<float> instance_scales;
  // MSFT_lod (a vendor extension read by Babylon.js and UnityGLTF): the nodes of this node's lower
  // levels of detail, highest first; they stay out of the scene, so a client without the
  // extension shows this node alone. Adds the extension to extensionsUsed (never Required).
  std::vector<int> lod_ids;
  std::size_t instance_count() const {
    return !instance_translations.empty() ? instance_translations.size() / 3
           : !instance_rotations.empty()  ? instance_rotations.size() / 4
                                          : instance_scales.size() / 3;
  }
};

struct Skin {
  std::string name;
  std::vector<int> joints;  // node indices
  int skeleton = -1;        // node index of the common root, -1 to leave it out
  // 16 floats per joint, column-major (spec 3.7.3.2); empty: all identity (left out).
  std::vector<float> inverse_bind_matrices;
};

enum class Path { kTranslation, kRotation, kScale };
enum class Interpolation { kLinear, kStep };

// One channel and its sampler: values (3 per key for translation/scale, 4 for rotation x, y, z,
// w) at the times of Animation::inputs[input].
struct Channel {
  int node = -1;
  Path path = Path::kTranslation;
  Interpolation interpolation = Interpolation::kLinear;
  int input = 0;
  std::vector<float> values;
};

struct Animation {
  std::string name;
  std::vector<std::vector<float>> inputs;  // key times in s, each strictly increasing, >= 0
  std::vector<Channel> channels;
};

struct Document {
  std::string generator = "niwa";  // asset.generator
  std::string asset_extras_json;   // "" or a JSON value (e.g. the parameters and seed)
  std::string scene_name;
  std::vector<int> scene_nodes;  // the one scene's root nodes
  std::vector<Node> nodes;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Skin> skins;
  std::vector<Animation> animations;
};

// The .glb bytes (spec 4.4: header, JSON chunk, BIN chunk when there is any data). Errors name the
// part, e.g. "meshes[0] 'tree' primitives[1] (leaves): index 812 out of range; must be < 812".
Result<std::vector<unsigned char>> WriteGlb(const Document& document);

// The same as .gltf JSON text with the buffer embedded as a base64 data URI.
Result<std::string> WriteGltfJson(const Document& document);

// The attribute name written for a TriMesh attribute ("birth_step" -> "_BIRTH_STEP",
// "COLOR_0" -> "COLOR_0", "TANGENT" -> "TANGENT"); "" when the name cannot be one (empty, or not
// [A-Za-z0-9_]).
std::string AttributeSemantic(const std::string& name);

}  // namespace niwa::gltf
