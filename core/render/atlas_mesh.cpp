// Card-atlas geometry (thesis 4.2.1, orthographic renders of group representatives and leaf
// clusters onto their card planes) and the sway skin of hybrid draw lists.
#include "render/atlas_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>

namespace niwa {
namespace {

// Triangles of one mesh part bucketed by the branch of their first vertex.
std::vector<std::vector<uint32_t>> TrianglesByBranch(const MeshBuffers& part,
                                                     const std::vector<uint32_t>& branch_of_vertex,
                                                     std::size_t branches) {
  std::vector<std::vector<uint32_t>> out(branches);
  for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    uint32_t v = part.indices[t];
    if (v >= branch_of_vertex.size()) continue;
    uint32_t b = branch_of_vertex[v];
    if (b < branches) out[b].push_back(static_cast<uint32_t>(t));
  }
  return out;
}

// Maps world points onto one tile: plane basis at `origin`, rectangle -> tile texels -> clip.
struct TileProjection {
  glm::vec3 origin, right, up, normal;
  float u0, u1, v0, v1;
  float x0, x1, y0, y1;  // clip coordinates of the tile's edges
  float depth;           // half the depth range along the normal, metres

  glm::vec3 Project(const glm::vec3& p) const {
    glm::vec3 d = p - origin;
    float u = glm::dot(d, right), v = glm::dot(d, up), w = glm::dot(d, normal);
    float x = x0 + (u - u0) / (u1 - u0) * (x1 - x0);
    float y = y0 + (v - v0) / (v1 - v0) * (y1 - y0);
    // The card is seen from +normal (ChooseCardPlane uses |cos|: both sides show the same texture).
    return {x, y, std::clamp(-w / depth, -1.0f, 1.0f)};
  }
};

TileProjection MakeProjection(const glm::vec3& origin, const CardPlane& plane,
                              const AtlasTile& tile, int atlas_size) {
  TileProjection t;
  t.origin = origin;
  t.right = plane.right;
  t.up = plane.up;
  t.normal = plane.normal;
  t.u0 = plane.u0;
  t.u1 = plane.u1 > plane.u0 ? plane.u1 : plane.u0 + 1e-6f;
  t.v0 = plane.v0;
  t.v1 = plane.v1 > plane.v0 ? plane.v1 : plane.v0 + 1e-6f;
  const float inv = 2.0f / static_cast<float>(atlas_size);
  t.x0 = static_cast<float>(tile.x) * inv - 1.0f;
  t.x1 = static_cast<float>(tile.x + tile.w) * inv - 1.0f;
  t.y0 = static_cast<float>(tile.y) * inv - 1.0f;
  t.y1 = static_cast<float>(tile.y + tile.h) * inv - 1.0f;
  // Depth range: the rectangle's larger side bounds how far geometry reaches off the plane.
  t.depth = std::max({t.u1 - t.u0, t.v1 - t.v0, 1e-4f});
  return t;
}

// Appends the listed triangles of `part`, projected, to `out` (new vertices per triangle corner),
// their texture coordinates from `uvs` (u, v per vertex of `part`).
void AppendProjected(const MeshBuffers& part, const std::vector<float>& uvs,
                     const std::vector<uint32_t>& triangles, const TileProjection& projection,
                     MeshBuffers* out) {
  for (uint32_t t : triangles) {
    for (int k = 0; k < 3; ++k) {
      uint32_t v = part.indices[t + static_cast<uint32_t>(k)];
      glm::vec3 p(part.positions[3 * v], part.positions[3 * v + 1], part.positions[3 * v + 2]);
      glm::vec3 q = projection.Project(p);
      uint32_t index = static_cast<uint32_t>(out->positions.size() / 3);
      out->positions.insert(out->positions.end(), {q.x, q.y, q.z});
      out->normals.insert(out->normals.end(),
                          {part.normals[3 * v], part.normals[3 * v + 1], part.normals[3 * v + 2]});
      out->uvs.insert(out->uvs.end(), {uvs[2 * v], uvs[2 * v + 1]});
      out->indices.push_back(index);
    }
  }
}

}  // namespace

AtlasMesh BuildAtlasMesh(const TreeMesh& mesh, const HybridScene& scene,
                         const std::vector<float>* bark_uvs) {
  AtlasMesh atlas;
  // The override only when it has the bark's length (else the mesh's own).
  const std::vector<float>& bark_uv =
      bark_uvs != nullptr && bark_uvs->size() == mesh.bark.uvs.size() ? *bark_uvs : mesh.bark.uvs;
  const std::size_t branches = scene.frames.size();
  const auto bark = TrianglesByBranch(mesh.bark, mesh.bark_branch_id, branches);
  const auto leaves = TrianglesByBranch(mesh.leaves, mesh.leaf_branch_id, branches);
  const auto flowers = TrianglesByBranch(mesh.flowers, mesh.flower_branch_id, branches);
  const bool leaves_on_cards = scene.options.leaf_mode == LeafMode::kBranchCards;

  for (std::size_t g = 0; g < scene.group_representative.size(); ++g) {
    const std::size_t rep = static_cast<std::size_t>(scene.group_representative[g]);
    if (rep >= branches) continue;
    const CardFrame& frame = scene.frames[rep];
    for (std::size_t k = 0; k < frame.planes.size() && k < scene.group_tiles[g].size(); ++k) {
      TileProjection projection =
          MakeProjection(frame.origin, frame.planes[k], scene.group_tiles[g][k], scene.atlas_size);
      std::size_t before = atlas.bark.indices.size() + atlas.leaves.indices.size();
      AppendProjected(mesh.bark, bark_uv, bark[rep], projection, &atlas.bark);
      if (leaves_on_cards) {
        AppendProjected(mesh.leaves, mesh.leaves.uvs, leaves[rep], projection, &atlas.leaves);
        AppendProjected(mesh.flowers, mesh.flowers.uvs, flowers[rep], projection, &atlas.flowers);
      }
      if (atlas.bark.indices.size() + atlas.leaves.indices.size() > before) ++atlas.tiles;
    }
  }
  for (std::size_t c = 0; c < scene.clusters.size(); ++c) {
    const LeafCluster& cluster = scene.clusters[c];
    for (std::size_t k = 0; k < cluster.planes.size() && k < scene.cluster_tiles[c].size(); ++k) {
      TileProjection projection = MakeProjection(cluster.origin, cluster.planes[k],
                                                 scene.cluster_tiles[c][k], scene.atlas_size);
      std::size_t before = atlas.leaves.indices.size() + atlas.flowers.indices.size();
      for (int b : cluster.branches) {
        if (b < 0 || static_cast<std::size_t>(b) >= branches) continue;
        AppendProjected(mesh.leaves, mesh.leaves.uvs, leaves[static_cast<std::size_t>(b)],
                        projection, &atlas.leaves);
        AppendProjected(mesh.flowers, mesh.flowers.uvs, flowers[static_cast<std::size_t>(b)],
                        projection, &atlas.flowers);
      }
      if (atlas.leaves.indices.size() + atlas.flowers.indices.size() > before) ++atlas.tiles;
    }
  }
  return atlas;
}

DrawListSkin BuildDrawListSkin(const Tree& tree, const HybridScene& scene,
                               const HybridDrawList& list, const SwayModel& model) {
  DrawListSkin skin;
  auto push = [](VertexSkin* s, SkinBinding b) {
    s->joint.push_back(b.joint);
    s->weight.push_back(b.weight);
  };
  auto tip_node = [&](int branch) -> uint32_t {
    const auto& nodes = tree.branches[static_cast<std::size_t>(branch)].nodes;
    return nodes.empty() ? 0u : static_cast<uint32_t>(nodes.size() - 1);
  };
  std::size_t cluster = 0;  // cluster cards come after every branch card, in cluster order
  for (int branch : list.card_branch) {
    if (branch < 0) {
      const bool known =
          cluster < scene.clusters.size() && !scene.clusters[cluster].branches.empty();
      const int owner = known ? scene.clusters[cluster].branches.front() : 0;
      ++cluster;
      SkinBinding top = BindNode(model, static_cast<uint32_t>(owner), tip_node(owner));
      for (int k = 0; k < 4; ++k) push(&skin.cards, top);
      continue;
    }
    SkinBinding base = BindNode(model, static_cast<uint32_t>(branch), 0);
    SkinBinding top = BindNode(model, static_cast<uint32_t>(branch), tip_node(branch));
    // Corner order of CardCorners: (u0,v0), (u1,v0), (u1,v1), (u0,v1); v runs along b_i.
    push(&skin.cards, base);
    push(&skin.cards, base);
    push(&skin.cards, top);
    push(&skin.cards, top);
  }
  for (std::size_t s = 0; s < list.line_branch.size(); ++s) {
    uint32_t branch = static_cast<uint32_t>(list.line_branch[s]);
    push(&skin.lines, BindNode(model, branch, static_cast<uint32_t>(list.line_nodes[2 * s])));
    push(&skin.lines, BindNode(model, branch, static_cast<uint32_t>(list.line_nodes[2 * s + 1])));
  }
  return skin;
}

}  // namespace niwa
