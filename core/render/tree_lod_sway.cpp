// The sway .glb on a triangle-budgeted mesh: LodMesh parts bound to the sway's node points.
#include "render/tree_lod_sway.h"

#include <utility>

#include "sway/skin.h"

namespace niwa {
namespace {

// Joints and weights of vertices hanging on (branch_id[v], node_index[v]) (sway/skin.h BindNode).
VertexSkin BindIds(const SwayModel& model, const std::vector<uint32_t>& branch_id,
                   const std::vector<uint32_t>& node_index) {
  VertexSkin skin;
  skin.joint.resize(branch_id.size());
  skin.weight.resize(branch_id.size());
  for (std::size_t v = 0; v < branch_id.size(); ++v) {
    const SkinBinding b = BindNode(model, branch_id[v], node_index[v]);
    skin.joint[v] = b.joint;
    skin.weight[v] = b.weight;
  }
  return skin;
}

}  // namespace

Status WriteLodSwayGlb(const Tree& tree, const SwayParams& params, const SwayGlbOptions& options,
                       long max_triangles, std::vector<unsigned char>* bytes, SwayGlbInfo* info,
                       LodChoice* choice, const std::string& field) {
  if (bytes == nullptr) return Status::Error("glb", "no output buffer");
  bytes->clear();
  if (max_triangles < 0) {
    if (choice != nullptr) *choice = LodChoice{};
    return WriteSwayGlb(tree, params, options, bytes, info);
  }
  LodOptions lod;
  lod.atlas_size = kSwayAtlasSize;
  Result<LodMesh> built = BuildLodMesh(tree, max_triangles, lod, field);
  if (!built.ok()) return built.status();
  std::vector<LodMesh> levels;
  levels.push_back(std::move(built).value());
  const LodMesh& level = levels[0];
  if (choice != nullptr) *choice = level.choice;
  if (level.choice.full) return WriteSwayGlb(tree, params, options, bytes, info);

  const SwayModel model = BuildSwayModel(tree, params);
  const TreeMesh& m = level.parts;
  const VertexSkin skins[5] = {BindIds(model, m.bark_branch_id, m.bark_node_index),
                               BindIds(model, m.leaf_branch_id, m.leaf_node_index),
                               BindIds(model, m.flower_branch_id, m.flower_node_index),
                               BindIds(model, level.card_branch_id, level.card_node_index),
                               BindIds(model, level.twig_branch_id, level.twig_node_index)};
  // LodGltfDocument's primitives: the non-empty ones of these, in this order.
  const MeshBuffers* buffers[5] = {&m.bark, &m.leaves, &m.flowers, &level.cards, &level.twigs};
  std::vector<SwaySkinPart> parts;
  for (std::size_t k = 0; k < 5; ++k) {
    if (skins[k].joint.size() != buffers[k]->vertex_count()) {
      return Status::Error("glb", "the budgeted mesh's ids disagree with its vertices");
    }
    parts.push_back({&skins[k], &buffers[k]->positions});
  }
  SwaySkin skin;
  NIWA_RETURN_IF_ERROR(BuildSwaySkin(tree, params, options, parts, &skin, info));

  Result<gltf::Document> doc = LodGltfDocument(levels, "tree");
  if (!doc.ok()) return doc.status();
  if (!doc->meshes.empty()) {
    std::size_t part = 0;
    for (gltf::Primitive& p : doc->meshes[0].primitives) {
      while (part < 5 && buffers[part]->indices.empty()) ++part;
      if (part == 5) return Status::Error("glb", "more primitives than parts");
      p.joints = std::move(skin.joints0[part]);
      p.weights = std::move(skin.weights0[part]);
      ++part;
    }
    GltfSkinning skeleton;
    skeleton.joints = std::move(skin.joints);
    skeleton.times = std::move(skin.times);
    AddTreeSkinAndAnimation(skeleton, &*doc);
  }
  Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
  if (!glb.ok()) return glb.status();
  *bytes = std::move(glb).value();
  return Status::Ok();
}

}  // namespace niwa
