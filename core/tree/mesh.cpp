// Triangle meshes of a grown tree: bark tubes, double-sided leaf quads and five-petal flowers.
#include "tree/mesh.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "math/rotation.h"

namespace niwa {
namespace {

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);
constexpr float kEpsilon = 1e-6f;

// Radii (cm) at which tubes get min_sides and max_sides; sides grow with sqrt(radius) in between.
constexpr float kThinRadius = 0.1f;
constexpr float kThickRadius = 4.0f;

constexpr int kFlowerPetals = 5;
constexpr float kFlowerOuterRadius = 1.0f;  // cm: the flower is about 2 cm across
constexpr float kFlowerInnerRadius = 0.4f;  // cm: notches between the petals
constexpr float kFlowerLift = 0.3f;         // cm: offset from the node along the facing direction

// Unit vector, or fallback when v is (nearly) zero or not finite.
glm::vec3 SafeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  float length = glm::length(v);
  if (!(length > kEpsilon) || !std::isfinite(length)) return fallback;
  return v / length;
}

int SidesForRadius(float radius_cm, const MeshOptions& options) {
  int lo = std::max(3, options.min_sides);
  int hi = std::max(lo, options.max_sides);
  float t = (radius_cm - kThinRadius) / (kThickRadius - kThinRadius);
  t = std::sqrt(std::min(1.0f, std::max(0.0f, t)));
  return lo + static_cast<int>(std::lround(t * static_cast<float>(hi - lo)));
}

void PushVertex(MeshBuffers* mesh, const glm::vec3& position, const glm::vec3& normal, float u,
                float v) {
  mesh->positions.insert(mesh->positions.end(), {position.x, position.y, position.z});
  mesh->normals.insert(mesh->normals.end(), {normal.x, normal.y, normal.z});
  mesh->uvs.insert(mesh->uvs.end(), {u, v});
}

void PushTriangle(MeshBuffers* mesh, uint32_t a, uint32_t b, uint32_t c) {
  mesh->indices.insert(mesh->indices.end(), {a, b, c});
}

uint32_t NextIndex(const MeshBuffers& mesh) { return static_cast<uint32_t>(mesh.vertex_count()); }

// Unit tangent of the branch at each node: mean of the neighbouring internode directions.
std::vector<glm::vec3> NodeTangents(const Branch& branch) {
  std::size_t n = branch.nodes.size();
  glm::vec3 fallback = SafeNormalize(branch.bud_direction, kUp);
  std::vector<glm::vec3> segment(n > 1 ? n - 1 : 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    fallback = SafeNormalize(branch.nodes[i + 1] - branch.nodes[i], fallback);
    segment[i] = fallback;
  }
  // Zero-length leading internodes take the first real direction.
  for (std::size_t i = segment.size(); i-- > 1;) {
    if (glm::length(branch.nodes[i] - branch.nodes[i - 1]) <= kEpsilon) segment[i - 1] = segment[i];
  }
  std::vector<glm::vec3> tangent(n, fallback);
  for (std::size_t i = 0; i < n; ++i) {
    if (segment.empty()) break;
    if (i == 0) {
      tangent[i] = segment.front();
    } else if (i + 1 == n) {
      tangent[i] = segment.back();
    } else {
      tangent[i] = SafeNormalize(segment[i - 1] + segment[i], segment[i]);
    }
  }
  return tangent;
}

// Rotates the frame normal by the smallest rotation that carries tangent `from` onto `to`.
glm::vec3 TransportNormal(const glm::vec3& normal, const glm::vec3& from, const glm::vec3& to) {
  glm::vec3 axis = glm::cross(from, to);
  float s = glm::length(axis);
  float c = glm::dot(from, to);
  glm::vec3 moved = normal;
  if (s > kEpsilon) moved = RotateAbout(normal, axis / s, det::Atan2f(s, c));
  return Orthonormalize(moved, to);
}

// Radius of the tube at its tip: that of the thickest living shoot continuing from the tip, so the
// trunk tapers smoothly into its terminal shoot; the branch's own radius when nothing continues.
float TipRadius(const Tree& tree, const Branch& branch, float base_radius) {
  int tip = static_cast<int>(branch.nodes.size()) - 1;
  float radius = -1.0f;
  for (int id : branch.children) {
    if (id < 0 || id >= static_cast<int>(tree.branches.size())) continue;
    const Branch& child = tree.branches[static_cast<std::size_t>(id)];
    if (child.alive && child.parent_node == tip) radius = std::max(radius, BranchRadius(child));
  }
  return radius > 0.0f ? std::min(radius, base_radius) : base_radius;
}

void AddBranchTube(const Tree& tree, const Branch& branch, float v_start,
                   const MeshOptions& options, TreeMesh* out, std::vector<float>* node_v) {
  const float scale = options.cm_to_units;
  const std::size_t rings = branch.nodes.size();
  const float base_radius = BranchRadius(branch);
  const float tip_radius = TipRadius(tree, branch, base_radius);
  const int sides = SidesForRadius(base_radius, options);
  const std::vector<glm::vec3> tangent = NodeTangents(branch);

  // Arc length (metres) of every node, continuing the parent's v at the attachment.
  node_v->assign(rings, v_start);
  for (std::size_t i = 1; i < rings; ++i) {
    (*node_v)[i] = (*node_v)[i - 1] + glm::length(branch.nodes[i] - branch.nodes[i - 1]) * scale;
  }
  const float length = (*node_v)[rings - 1] - v_start;

  MeshBuffers& bark = out->bark;
  const uint32_t first = NextIndex(bark);
  const uint32_t stride = static_cast<uint32_t>(sides) + 1;  // the seam vertex is duplicated
  const uint32_t id = static_cast<uint32_t>(branch.id);
  glm::vec3 normal = Orthonormalize(branch.azimuth, tangent[0]);
  glm::vec3 binormal(0.0f);
  for (std::size_t i = 0; i < rings; ++i) {
    if (i > 0) normal = TransportNormal(normal, tangent[i - 1], tangent[i]);
    binormal = SafeNormalize(glm::cross(tangent[i], normal), AnyPerpendicular(tangent[i]));
    float t = length > 0.0f ? ((*node_v)[i] - v_start) / length : 0.0f;
    float radius = (base_radius + (tip_radius - base_radius) * t) * scale;
    glm::vec3 center = branch.nodes[i] * scale;
    for (int j = 0; j <= sides; ++j) {
      float angle = 2.0f * kPi * static_cast<float>(j % sides) / static_cast<float>(sides);
      glm::vec3 radial =
          SafeNormalize(normal * det::Cosf(angle) + binormal * det::Sinf(angle), normal);
      PushVertex(&bark, center + radial * radius, radial,
                 static_cast<float>(j) / static_cast<float>(sides), (*node_v)[i]);
      out->bark_branch_id.push_back(id);
      out->bark_node_index.push_back(static_cast<uint32_t>(i));
    }
  }
  for (uint32_t i = 0; i + 1 < rings; ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(sides); ++j) {
      uint32_t a = first + i * stride + j, b = a + 1, c = b + stride, d = a + stride;
      PushTriangle(&bark, a, b, c);
      PushTriangle(&bark, a, c, d);
    }
  }

  // End cap: a flat fan facing along the tip tangent, with its own vertices for a crisp normal.
  const glm::vec3 tip_tangent = tangent[rings - 1];
  const glm::vec3 tip_center = branch.nodes[rings - 1] * scale;
  const float cap_radius = tip_radius * scale;
  const uint32_t center_index = NextIndex(bark);
  const uint32_t tip_node = static_cast<uint32_t>(rings - 1);
  PushVertex(&bark, tip_center, tip_tangent, 0.5f, 0.5f);
  out->bark_branch_id.push_back(id);
  out->bark_node_index.push_back(tip_node);
  for (int j = 0; j < sides; ++j) {
    float angle = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(sides);
    float c = det::Cosf(angle), s = det::Sinf(angle);
    PushVertex(&bark, tip_center + (normal * c + binormal * s) * cap_radius, tip_tangent,
               0.5f + 0.5f * c, 0.5f + 0.5f * s);
    out->bark_branch_id.push_back(id);
    out->bark_node_index.push_back(tip_node);
  }
  for (uint32_t j = 0; j < static_cast<uint32_t>(sides); ++j) {
    uint32_t next = (j + 1) % static_cast<uint32_t>(sides);
    PushTriangle(&bark, center_index, center_index + 1 + j, center_index + 1 + next);
  }
}

// One quad seen from the front (normal n) and one from the back (-n), vertex order 0..3 around.
void AddDoubleSidedQuad(MeshBuffers* mesh, const glm::vec3 (&corners)[4], const glm::vec3& n,
                        const glm::vec2 (&uv)[4]) {
  for (int side = 0; side < 2; ++side) {
    uint32_t base = NextIndex(*mesh);
    glm::vec3 normal = side == 0 ? n : -n;
    for (int k = 0; k < 4; ++k) PushVertex(mesh, corners[k], normal, uv[k].x, uv[k].y);
    if (side == 0) {
      PushTriangle(mesh, base, base + 1, base + 2);
      PushTriangle(mesh, base, base + 2, base + 3);
    } else {
      PushTriangle(mesh, base, base + 2, base + 1);
      PushTriangle(mesh, base, base + 3, base + 2);
    }
  }
}

void AddLeaf(const Branch& branch, const Leaf& leaf, float leaf_size, const MeshOptions& options,
             MeshBuffers* leaves) {
  if (leaf.node < 0 || leaf.node >= static_cast<int>(branch.nodes.size())) return;
  const float scale = options.cm_to_units;
  glm::vec3 along = SafeNormalize(leaf.direction, kUp);
  // The blade's width runs horizontally when it can, so the leaf faces the sky.
  glm::vec3 across = SafeNormalize(glm::cross(along, kUp), AnyPerpendicular(along));
  glm::vec3 normal = SafeNormalize(glm::cross(across, along), kUp);
  glm::vec3 base = branch.nodes[static_cast<std::size_t>(leaf.node)] * scale;
  glm::vec3 tip = base + along * (leaf_size * scale);
  glm::vec3 half = across * (0.25f * leaf_size * scale);
  const glm::vec3 corners[4] = {base - half, base + half, tip + half, tip - half};
  const glm::vec2 uv[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
  AddDoubleSidedQuad(leaves, corners, normal, uv);
}

void AddFlower(const Branch& branch, int node, const MeshOptions& options, MeshBuffers* flowers) {
  if (node < 0 || node >= static_cast<int>(branch.nodes.size())) return;
  const float scale = options.cm_to_units;
  glm::vec3 position = branch.nodes[static_cast<std::size_t>(node)];
  // Faces up and away from the trunk axis.
  glm::vec3 outward = SafeNormalize(glm::vec3(position.x, 0.0f, position.z), glm::vec3(0.0f));
  glm::vec3 facing = SafeNormalize(kUp + 0.5f * outward, kUp);
  glm::vec3 a = AnyPerpendicular(facing);
  glm::vec3 b = SafeNormalize(glm::cross(facing, a), AnyPerpendicular(a));
  glm::vec3 center = (position + facing * kFlowerLift) * scale;
  constexpr int kOutline = 2 * kFlowerPetals;
  for (int side = 0; side < 2; ++side) {
    glm::vec3 normal = side == 0 ? facing : -facing;
    uint32_t hub = NextIndex(*flowers);
    PushVertex(flowers, center, normal, 0.5f, 0.5f);
    for (int k = 0; k < kOutline; ++k) {
      float angle = 2.0f * kPi * static_cast<float>(k) / static_cast<float>(kOutline);
      float r = (k % 2 == 0) ? kFlowerOuterRadius : kFlowerInnerRadius;
      float c = det::Cosf(angle) * r, s = det::Sinf(angle) * r;
      PushVertex(flowers, center + (a * c + b * s) * scale, normal,
                 0.5f + 0.5f * c / kFlowerOuterRadius, 0.5f + 0.5f * s / kFlowerOuterRadius);
    }
    // a x b = facing, so increasing angle is counter-clockwise seen from the front.
    for (uint32_t k = 0; k < static_cast<uint32_t>(kOutline); ++k) {
      uint32_t p = hub + 1 + k, q = hub + 1 + (k + 1) % static_cast<uint32_t>(kOutline);
      if (side == 0) {
        PushTriangle(flowers, hub, p, q);
      } else {
        PushTriangle(flowers, hub, q, p);
      }
    }
  }
}

}  // namespace

TreeMesh BuildTreeMesh(const Tree& tree, const MeshOptions& options) {
  TreeMesh mesh;
  const float leaf_size = static_cast<float>(tree.params.Get(ParamId::kLeafSize));
  // v coordinate (metres along the wood) of every node, so children continue their parent's v.
  std::vector<std::vector<float>> node_v(tree.branches.size());
  for (std::size_t n = 0; n < tree.branches.size(); ++n) {
    const Branch& branch = tree.branches[n];
    if (!branch.alive || branch.nodes.size() < 2) continue;
    float v_start = 0.0f;
    if (branch.parent >= 0 && branch.parent < static_cast<int>(n)) {
      const std::vector<float>& parent_v = node_v[static_cast<std::size_t>(branch.parent)];
      if (branch.parent_node >= 0 && branch.parent_node < static_cast<int>(parent_v.size())) {
        v_start = parent_v[static_cast<std::size_t>(branch.parent_node)];
      }
    }
    AddBranchTube(tree, branch, v_start, options, &mesh, &node_v[n]);
    const uint32_t id = static_cast<uint32_t>(branch.id);
    for (const Leaf& leaf : branch.leaves) {
      AddLeaf(branch, leaf, leaf_size, options, &mesh.leaves);
      mesh.leaf_branch_id.resize(mesh.leaves.vertex_count(), id);
      mesh.leaf_node_index.resize(mesh.leaves.vertex_count(), static_cast<uint32_t>(leaf.node));
    }
    for (int node : branch.flowers) {
      AddFlower(branch, node, options, &mesh.flowers);
      mesh.flower_branch_id.resize(mesh.flowers.vertex_count(), id);
      mesh.flower_node_index.resize(mesh.flowers.vertex_count(), static_cast<uint32_t>(node));
    }
  }
  return mesh;
}

}  // namespace niwa
