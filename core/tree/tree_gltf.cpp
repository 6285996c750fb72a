// The tree's glTF document (three textured parts, optional skin and sway clip) over io/gltf_writer.
#include "tree/tree_gltf.h"

#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "image/png.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

enum class TextureKind { kBark, kBarkNormal, kLeaf, kFlower };

// The base colour comes from the texture (factor white); leaves and flowers are cut out by alpha;
// bark also has its normal map.
struct MaterialSpec {
  const char* name;
  TextureKind texture;
  double roughness;
  bool double_sided;
  bool alpha_mask;
};

// The PNG of one texture, painted and encoded once per process (and per look for the leaf): 512 px
// textures take a noticeable part of a second to paint and deflate, and every export of the same
// look embeds the same bytes.
Result<std::vector<unsigned char>> EncodedTexture(TextureKind kind, const TreeLook& look) {
  static std::mutex mutex;
  static std::map<int, std::vector<unsigned char>> cache;
  const int key =
      kind == TextureKind::kLeaf
          ? 10000 * look.leaf_spray + 100 * static_cast<int>(look.leaf_shape) +
                10 * static_cast<int>(look.season) + static_cast<int>(look.autumn)
      : kind == TextureKind::kFlower
          ? 2000 + 10 * static_cast<int>(look.flower_colour) + static_cast<int>(look.flower_form)
          : static_cast<int>(kind);
  std::lock_guard<std::mutex> lock(mutex);
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  Rgba8Image pixels;
  switch (kind) {
    case TextureKind::kBark:
      pixels = MakeBarkTexture();
      break;
    case TextureKind::kBarkNormal:
      pixels = MakeBarkNormalMap();
      break;
    case TextureKind::kLeaf:
      pixels = MakeLeafTexture(look);
      break;
    case TextureKind::kFlower:
    default:
      pixels = MakeFlowerTexture(look);
      break;
  }
  Result<std::vector<unsigned char>> png = image::EncodeRgba8Png(pixels);
  if (png.ok()) cache.emplace(key, *png);
  return png;
}

// Bark repeats around (u 0..1) and along the wood (one repeat per metre of v); leaf and flower
// textures cover their quad or card once and are clamped. The leaf is painted for the mesh's look.
Result<gltf::Texture> MakeTexture(TextureKind kind, const TreeLook& look) {
  gltf::Texture texture;
  switch (kind) {
    case TextureKind::kBark:
      texture.name = "bark";
      break;
    case TextureKind::kBarkNormal:
      texture.name = "bark_normal";
      break;
    case TextureKind::kLeaf:
      texture.name =
          std::string("leaf_") + LeafShapeName(look.leaf_shape) + "_" + SeasonName(look.season);
      if (look.leaf_spray > 1) texture.name += "_spray" + std::to_string(look.leaf_spray);
      texture.wrap_s = texture.wrap_t = gltf::Wrap::kClampToEdge;
      // Needles without mipmaps, as the LOD cards (render/tree_lod.cpp): an engine's alpha test
      // (cutoff 0.5) on averaged mip levels drops thin needles altogether; a pine drawn by three.js
      // had no foliage pixel (docs/figures/species, 0 against 0.115 of the tree without mips). The
      // page scales alpha by the mip level instead (shaders/tree/tree_textured.frag), which a .glb
      // cannot ask of an engine. Broad leaves keep their mipmaps: there the same measure went
      // both ways (maple 0.44 -> 0.60, sakura 0.33 -> 0.22), and mipmaps spare them the shimmer.
      if (look.leaf_shape == LeafShape::kNeedle || look.leaf_spray > 1) {
        texture.min_filter = gltf::kFilterLinear;
      }
      break;
    case TextureKind::kFlower:
    default:
      texture.name = "flower";
      texture.wrap_s = texture.wrap_t = gltf::Wrap::kClampToEdge;
      break;
  }
  Result<std::vector<unsigned char>> png = EncodedTexture(kind, look);
  if (!png.ok()) return png.status().Within(texture.name + " texture");
  texture.png = std::move(png).value();
  return texture;
}

// Adds a texture to the document; its index.
Result<int> AddTexture(TextureKind kind, const TreeLook& look, gltf::Document* doc) {
  Result<gltf::Texture> texture = MakeTexture(kind, look);
  if (!texture.ok()) return texture.status();
  doc->textures.push_back(std::move(texture).value());
  return static_cast<int>(doc->textures.size()) - 1;
}

gltf::Material MakeMaterial(const MaterialSpec& spec, int texture) {
  gltf::Material material;
  material.name = spec.name;
  material.double_sided = spec.double_sided;
  if (spec.alpha_mask) material.alpha_mode = gltf::AlphaMode::kMask;  // cutoff 0.5
  material.base_color_texture = texture;
  material.metallic_factor = 0.0;
  material.roughness_factor = spec.roughness;
  return material;
}

// Checks that the flat buffers of one part hold whole vertices; returns "" or what is wrong.
Status CheckLayout(const MeshBuffers& buffers, const char* name) {
  const std::size_t vertices = buffers.vertex_count();
  if (buffers.positions.size() != vertices * 3 || buffers.normals.size() != vertices * 3 ||
      buffers.uvs.size() != vertices * 2) {
    return Status::Error(name, "positions, normals and uvs disagree on the vertex count");
  }
  return Status::Ok();
}

geom::TriMesh ToTriMesh(const MeshBuffers& buffers) {
  geom::TriMesh mesh;
  const std::size_t n = buffers.vertex_count();
  mesh.positions.resize(n);
  mesh.normals.resize(n);
  mesh.uvs.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    mesh.positions[v] = {buffers.positions[3 * v], buffers.positions[3 * v + 1],
                         buffers.positions[3 * v + 2]};
    mesh.normals[v] = {buffers.normals[3 * v], buffers.normals[3 * v + 1],
                       buffers.normals[3 * v + 2]};
    mesh.uvs[v] = {buffers.uvs[2 * v], buffers.uvs[2 * v + 1]};
  }
  mesh.indices = buffers.indices;
  return mesh;
}

Status CheckSkinning(const GltfSkinning& skin, const MeshBuffers* const (&parts)[3]) {
  if (skin.joints.empty()) return Status::Error("skin", "no joints");
  if (skin.joints.size() > kMaxGltfJoints) {
    return Status::Error("skin", std::to_string(skin.joints.size()) +
                                     " joints; JOINTS_0 (unsigned short) allows at most 65536");
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t n = 4 * parts[k]->vertex_count();
    if (skin.joints0[k].size() != n || skin.weights0[k].size() != n) {
      return Status::Error("skin", "joints/weights disagree with the vertex count");
    }
    for (const geom::VertexAttribute& a : skin.attributes[k]) {
      if (a.components < 1 ||
          a.values.size() != parts[k]->vertex_count() * static_cast<std::size_t>(a.components)) {
        return Status::Error("skin", "attribute " + a.name + " disagrees with the vertex count");
      }
    }
  }
  for (const GltfJoint& joint : skin.joints) {
    if (joint.translation_keys.empty() && joint.rotation_keys.empty()) continue;
    const std::size_t keys = joint.times.empty() ? skin.times.size() : joint.times.size();
    if (joint.translation_keys.size() != 3 * keys || joint.rotation_keys.size() != 4 * keys) {
      return Status::Error("animation", "keys disagree with the times");
    }
  }
  return Status::Ok();
}

}  // namespace

// Skeleton nodes (joints[0] the root, the others its children), the skin and the clip.
void AddTreeSkinAndAnimation(const GltfSkinning& skin, gltf::Document* doc) {
  const int first = static_cast<int>(doc->nodes.size());
  gltf::Skin out_skin;
  out_skin.name = "tree";
  out_skin.skeleton = first;
  for (std::size_t j = 0; j < skin.joints.size(); ++j) {
    const GltfJoint& joint = skin.joints[j];
    gltf::Node node;
    node.name = joint.name;
    node.translation = {joint.translation[0], joint.translation[1], joint.translation[2]};
    if (j == 0) {
      for (std::size_t c = 1; c < skin.joints.size(); ++c)
        node.children.push_back(first + static_cast<int>(c));
    }
    doc->nodes.push_back(std::move(node));
    out_skin.joints.push_back(first + static_cast<int>(j));
    const std::array<float, 3>& o = joint.inverse_bind_offset;  // column-major 4x4
    out_skin.inverse_bind_matrices.insert(
        out_skin.inverse_bind_matrices.end(),
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, o[0], o[1], o[2], 1});
  }
  doc->skins.push_back(std::move(out_skin));
  doc->nodes[0].skin = 0;
  doc->scene_nodes.push_back(first);  // the skeleton root, at top

  gltf::Animation clip;
  clip.name = skin.clip_name;
  // One input a distinct key-time list, in the order joints first use them (input 0: the shared
  // times when a joint uses them), so an unreduced clip has the one input it always had.
  std::map<std::vector<float>, int> input_of;
  for (std::size_t j = 0; j < skin.joints.size(); ++j) {
    const GltfJoint& joint = skin.joints[j];
    if (joint.translation_keys.empty()) continue;
    const std::vector<float>& times = joint.times.empty() ? skin.times : joint.times;
    if (times.empty()) continue;
    auto found = input_of.find(times);
    if (found == input_of.end()) {
      found = input_of.emplace(times, static_cast<int>(clip.inputs.size())).first;
      clip.inputs.push_back(times);
    }
    const int node = first + static_cast<int>(j);
    clip.channels.push_back({node, gltf::Path::kTranslation, gltf::Interpolation::kLinear,
                             found->second, joint.translation_keys});
    clip.channels.push_back({node, gltf::Path::kRotation, gltf::Interpolation::kLinear,
                             found->second, joint.rotation_keys});
  }
  if (!clip.channels.empty()) doc->animations.push_back(std::move(clip));
}

namespace {

Status WriteTo(const Result<gltf::Document>& doc, std::vector<unsigned char>* bytes) {
  if (bytes == nullptr) return Status::Error("glb", "no output buffer");
  bytes->clear();
  if (!doc.ok()) return doc.status();
  Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
  if (!glb.ok()) return glb.status();
  *bytes = std::move(glb).value();
  return Status::Ok();
}

}  // namespace

Result<gltf::Document> TreeGltfDocument(const TreeMesh& mesh, const GltfSkinning* skinning) {
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
    NIWA_RETURN_IF_ERROR(CheckLayout(*part.buffers, part.material.name));
  }
  if (skinning != nullptr) {
    const MeshBuffers* const buffers[3] = {&mesh.bark, &mesh.leaves, &mesh.flowers};
    NIWA_RETURN_IF_ERROR(CheckSkinning(*skinning, buffers));
  }

  gltf::Document doc;
  doc.scene_name = "tree";
  gltf::Node node;
  node.name = "tree";
  gltf::Mesh out_mesh;
  out_mesh.name = "tree";
  for (std::size_t k = 0; k < 3; ++k) {
    const Part& part = parts[k];
    if (part.buffers->indices.empty()) continue;  // no empty primitives, materials or textures
    Result<int> texture = AddTexture(part.material.texture, mesh.look, &doc);
    if (!texture.ok()) return texture.status();
    gltf::Material material = MakeMaterial(part.material, *texture);
    if (part.material.texture == TextureKind::kBark) {
      Result<int> normal = AddTexture(TextureKind::kBarkNormal, mesh.look, &doc);
      if (!normal.ok()) return normal.status();
      material.normal_texture = *normal;
      // The look the tree was dressed in (the season also decides which parts exist).
      material.extras_json =
          std::string("{\"leaf_shape\":\"") + LeafShapeName(mesh.look.leaf_shape) +
          "\",\"season\":\"" + SeasonName(mesh.look.season) + "\",\"autumn_colour\":\"" +
          AutumnColourName(mesh.look.autumn) + "\"" +
          (mesh.look.leaf_spray > 1 ? ",\"leaf_spray\":" + std::to_string(mesh.look.leaf_spray)
                                    : std::string()) +
          "}";
    } else if (part.material.texture == TextureKind::kFlower) {
      material.extras_json = std::string("{\"flower_colour\":\"") +
                             FlowerColourName(mesh.look.flower_colour) + "\",\"flower_form\":\"" +
                             FlowerFormName(mesh.look.flower_form) + "\"}";
    }
    doc.materials.push_back(std::move(material));
    gltf::Primitive primitive;
    primitive.mesh = ToTriMesh(*part.buffers);
    primitive.material = static_cast<int>(doc.materials.size()) - 1;
    primitive.index_type = gltf::IndexType::kUint32;  // as MeshBuffers (GL/glTF ready)
    if (skinning != nullptr) {
      primitive.joints = skinning->joints0[k];
      primitive.weights = skinning->weights0[k];
      primitive.mesh.attributes = skinning->attributes[k];
    }
    out_mesh.primitives.push_back(std::move(primitive));
  }
  const bool any = !out_mesh.primitives.empty();
  if (any) {
    doc.meshes.push_back(std::move(out_mesh));
    node.mesh = 0;
  }
  doc.nodes.push_back(std::move(node));
  doc.scene_nodes.push_back(0);
  if (any && skinning != nullptr) AddTreeSkinAndAnimation(*skinning, &doc);
  return doc;
}

Status WriteTreeGlb(const TreeMesh& mesh, std::vector<unsigned char>* bytes) {
  return WriteTo(TreeGltfDocument(mesh), bytes);
}

Status WriteSkinnedTreeGlb(const TreeMesh& mesh, const GltfSkinning& skinning,
                           std::vector<unsigned char>* bytes) {
  return WriteTo(TreeGltfDocument(mesh, &skinning), bytes);
}

}  // namespace niwa
