// Triangle meshes of a grown tree: bark tubes, double-sided leaf quads (one leaf or a spray each)
// and blossom-cluster cards.
#include "tree/mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "math/rotation.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

const glm::vec3 kWorldUp(0.0f, 1.0f, 0.0f);
constexpr float kEpsilon = 1e-6f;

// Radii (cm) at which tubes get min_sides and max_sides; sides grow with sqrt(radius) in between.
constexpr float kThinRadius = 0.1f;
constexpr float kThickRadius = 4.0f;

constexpr int kFlowerPetals = 5;
constexpr int kFlowerOutline = 2 * kFlowerPetals;  // outer and inner points around a flower

// Vertex and index counts of the pieces, for sizing the buffers once.
constexpr std::size_t kLeafVertices = 8, kLeafIndices = 12;  // two quads, two triangles each
constexpr std::size_t kFlowerVertices = 2 * (1 + kFlowerOutline);
constexpr std::size_t kFlowerIndices = 2 * 3 * kFlowerOutline;

// Unit vector, or fallback when v is (nearly) zero or not finite.
glm::vec3 SafeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  float length = glm::length(v);
  if (!(length > kEpsilon) || !std::isfinite(length)) return fallback;
  return Divide(v, length);
}

// SafeNormalize(v, AnyPerpendicular(to)), the fallback computed only when it is needed.
glm::vec3 SafeNormalizeOrPerpendicular(const glm::vec3& v, const glm::vec3& to) {
  float length = glm::length(v);
  if (!(length > kEpsilon) || !std::isfinite(length)) return AnyPerpendicular(to);
  return Divide(v, length);
}

int SidesForRadius(float radius_cm, int lo, int hi) {
  float t = (radius_cm - kThinRadius) / (kThickRadius - kThinRadius);
  t = std::sqrt(std::min(1.0f, std::max(0.0f, t)));
  return lo + static_cast<int>(std::lround(t * static_cast<float>(hi - lo)));
}

// A mesh being filled in place: the buffers are sized once up front and written through cursors,
// so building a tree's mesh allocates a fixed handful of times, not once per vertex.
struct Writer {
  float* position;
  float* normal;
  float* uv;
  uint32_t* index;
  uint32_t* branch_id;
  uint32_t* node_index;
  uint32_t next = 0;  // index of the next vertex

  void Vertex(const glm::vec3& p, const glm::vec3& n, float u, float v, uint32_t branch,
              uint32_t node) {
    position[0] = p.x;
    position[1] = p.y;
    position[2] = p.z;
    position += 3;
    normal[0] = n.x;
    normal[1] = n.y;
    normal[2] = n.z;
    normal += 3;
    uv[0] = u;
    uv[1] = v;
    uv += 2;
    *branch_id++ = branch;
    *node_index++ = node;
    ++next;
  }
  void Triangle(uint32_t a, uint32_t b, uint32_t c) {
    index[0] = a;
    index[1] = b;
    index[2] = c;
    index += 3;
  }
};

Writer StartWriting(MeshBuffers* mesh, std::vector<uint32_t>* branch_id,
                    std::vector<uint32_t>* node_index, std::size_t vertices, std::size_t indices) {
  mesh->positions.resize(3 * vertices);
  mesh->normals.resize(3 * vertices);
  mesh->uvs.resize(2 * vertices);
  mesh->indices.resize(indices);
  branch_id->resize(vertices);
  node_index->resize(vertices);
  return {mesh->positions.data(), mesh->normals.data(), mesh->uvs.data(),
          mesh->indices.data(),   branch_id->data(),    node_index->data()};
}

// cos and sin of the angles 2π·j/sides, j = 0..sides-1, for every side count a tube may have.
struct RingTable {
  int lo = 3;
  std::vector<std::vector<float>> cos, sin, u;  // u: j / sides for j = 0..sides (the seam: 1)
  RingTable(int lo_sides, int hi_sides) : lo(lo_sides) {
    for (int sides = lo_sides; sides <= hi_sides; ++sides) {
      std::vector<float> c(static_cast<std::size_t>(sides)), s(static_cast<std::size_t>(sides));
      std::vector<float> around(static_cast<std::size_t>(sides) + 1);
      for (int j = 0; j < sides; ++j) {
        float angle = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(sides);
        c[static_cast<std::size_t>(j)] = det::Cosf(angle);
        s[static_cast<std::size_t>(j)] = det::Sinf(angle);
      }
      for (int j = 0; j <= sides; ++j) {
        around[static_cast<std::size_t>(j)] = static_cast<float>(j) / static_cast<float>(sides);
      }
      cos.push_back(std::move(c));
      sin.push_back(std::move(s));
      u.push_back(std::move(around));
    }
  }
  const float* U(int sides) const { return u[static_cast<std::size_t>(sides - lo)].data(); }
  const float* Cos(int sides) const { return cos[static_cast<std::size_t>(sides - lo)].data(); }
  const float* Sin(int sides) const { return sin[static_cast<std::size_t>(sides - lo)].data(); }
};

// Unit tangent of the branch at each node: mean of the neighbouring internode directions.
// `segment` and `tangent` are scratch buffers reused from branch to branch.
void NodeTangents(const Branch& branch, std::vector<glm::vec3>* segment_buffer,
                  std::vector<glm::vec3>* tangent_buffer) {
  std::size_t n = branch.nodes.size();
  glm::vec3 fallback = SafeNormalize(branch.bud_direction, kWorldUp);
  std::vector<glm::vec3>& segment = *segment_buffer;
  segment.resize(n > 1 ? n - 1 : 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    fallback = SafeNormalize(branch.nodes[i + 1] - branch.nodes[i], fallback);
    segment[i] = fallback;
  }
  // Zero-length leading internodes take the first real direction.
  for (std::size_t i = segment.size(); i-- > 1;) {
    if (glm::length(branch.nodes[i] - branch.nodes[i - 1]) <= kEpsilon) segment[i - 1] = segment[i];
  }
  std::vector<glm::vec3>& tangent = *tangent_buffer;
  tangent.assign(n, fallback);
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
}

// Rotates the frame normal by the smallest rotation that carries unit tangent `from` onto unit
// `to` (parallel transport): about from × to, by the angle whose sine and cosine are |from × to|
// and from · to, used directly (normalized) instead of through atan2, cos and sin.
glm::vec3 TransportNormal(const glm::vec3& normal, const glm::vec3& from, const glm::vec3& to) {
  glm::vec3 axis = glm::cross(from, to);
  float s = glm::length(axis);
  float c = glm::dot(from, to);
  glm::vec3 moved = normal;
  if (s > kEpsilon) {
    float h = std::sqrt(s * s + c * c);
    moved = RotateAbout(normal, Divide(axis, s), c / h, s / h);
  }
  return Orthonormalize(moved, to);
}

// What TipRadius needs of each branch, packed so the children loop stays in cache: the node of
// its parent it starts from, and its radius (cm), or -1 when it is not alive.
struct ChildInfo {
  int parent_node;
  float radius;
};

// Radius of the tube at its tip: that of the thickest living shoot continuing from the tip, so the
// trunk tapers smoothly into its terminal shoot; the branch's own radius when nothing continues.
float TipRadius(const std::vector<ChildInfo>& info, const Branch& branch, float base_radius) {
  int tip = static_cast<int>(branch.nodes.size()) - 1;
  float radius = -1.0f;
  for (int id : branch.children) {
    if (id < 0 || id >= static_cast<int>(info.size())) continue;
    const ChildInfo& child = info[static_cast<std::size_t>(id)];
    if (child.radius >= 0.0f && child.parent_node == tip) radius = std::max(radius, child.radius);
  }
  return radius > 0.0f ? std::min(radius, base_radius) : base_radius;
}

// Scratch buffers of AddBranchTube, kept across branches.
struct TubeScratch {
  std::vector<glm::vec3> segment, tangent;
};

// One generalized cylinder: a ring of `sides` + 1 vertices (the seam duplicated) per node, frames
// carried along by parallel transport, radius tapering linearly in arc length, and a flat end cap.
// node_v receives the v coordinate (metres of wood from the root) of every node.
void AddBranchTube(const std::vector<ChildInfo>& info, const Branch& branch, float base_radius,
                   int sides, float v_start, const MeshOptions& options, const RingTable& ring,
                   TubeScratch* scratch, Writer* bark, float* node_v) {
  const float scale = options.cm_to_units;
  const std::size_t rings = branch.nodes.size();
  const float tip_radius = TipRadius(info, branch, base_radius);
  NodeTangents(branch, &scratch->segment, &scratch->tangent);
  const std::vector<glm::vec3>& tangent = scratch->tangent;
  const float* ring_cos = ring.Cos(sides);
  const float* ring_sin = ring.Sin(sides);
  const float* ring_u = ring.U(sides);

  // Arc length (metres) of every node, continuing the parent's v at the attachment.
  node_v[0] = v_start;
  for (std::size_t i = 1; i < rings; ++i) {
    node_v[i] = node_v[i - 1] + glm::length(branch.nodes[i] - branch.nodes[i - 1]) * scale;
  }
  const float length = node_v[rings - 1] - v_start;

  const uint32_t first = bark->next;
  const uint32_t stride = static_cast<uint32_t>(sides) + 1;  // the seam vertex is duplicated
  const uint32_t id = static_cast<uint32_t>(branch.id);
  glm::vec3 normal = Orthonormalize(branch.azimuth, tangent[0]);
  glm::vec3 binormal(0.0f);
  for (std::size_t i = 0; i < rings; ++i) {
    if (i > 0) normal = TransportNormal(normal, tangent[i - 1], tangent[i]);
    binormal = SafeNormalizeOrPerpendicular(glm::cross(tangent[i], normal), tangent[i]);
    float t = length > 0.0f ? (node_v[i] - v_start) / length : 0.0f;
    float radius = (base_radius + (tip_radius - base_radius) * t) * scale;
    glm::vec3 center = branch.nodes[i] * scale;
    for (int j = 0; j <= sides; ++j) {
      int k = j % sides;
      // Unit within rounding: normal and binormal are orthonormal, cos² + sin² = 1.
      glm::vec3 radial = normal * ring_cos[k] + binormal * ring_sin[k];
      bark->Vertex(center + radial * radius, radial, ring_u[j], node_v[i], id,
                   static_cast<uint32_t>(i));
    }
  }
  for (uint32_t i = 0; i + 1 < rings; ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(sides); ++j) {
      uint32_t a = first + i * stride + j, b = a + 1, c = b + stride, d = a + stride;
      bark->Triangle(a, b, c);
      bark->Triangle(a, c, d);
    }
  }

  // End cap: a flat fan facing along the tip tangent, with its own vertices for a crisp normal.
  const glm::vec3 tip_tangent = tangent[rings - 1];
  const glm::vec3 tip_center = branch.nodes[rings - 1] * scale;
  const float cap_radius = tip_radius * scale;
  const uint32_t center_index = bark->next;
  const uint32_t tip_node = static_cast<uint32_t>(rings - 1);
  bark->Vertex(tip_center, tip_tangent, 0.5f, 0.5f, id, tip_node);
  for (int j = 0; j < sides; ++j) {
    float c = ring_cos[j], s = ring_sin[j];
    bark->Vertex(tip_center + (normal * c + binormal * s) * cap_radius, tip_tangent,
                 0.5f + 0.5f * c, 0.5f + 0.5f * s, id, tip_node);
  }
  for (uint32_t j = 0; j < static_cast<uint32_t>(sides); ++j) {
    uint32_t next = (j + 1) % static_cast<uint32_t>(sides);
    bark->Triangle(center_index, center_index + 1 + j, center_index + 1 + next);
  }
}

// One quad seen from the front (normal n) and one from the back (-n), vertex order 0..3 around.
void AddDoubleSidedQuad(Writer* mesh, const glm::vec3 (&corners)[4], const glm::vec3& n,
                        const glm::vec2 (&uv)[4], uint32_t branch, uint32_t node) {
  for (int side = 0; side < 2; ++side) {
    uint32_t base = mesh->next;
    glm::vec3 normal = side == 0 ? n : -n;
    for (int k = 0; k < 4; ++k) mesh->Vertex(corners[k], normal, uv[k].x, uv[k].y, branch, node);
    if (side == 0) {
      mesh->Triangle(base, base + 1, base + 2);
      mesh->Triangle(base, base + 2, base + 3);
    } else {
      mesh->Triangle(base, base + 2, base + 1);
      mesh->Triangle(base, base + 3, base + 2);
    }
  }
}

bool ValidNode(const Branch& branch, int node) {
  return node >= 0 && node < static_cast<int>(branch.nodes.size());
}

void AddLeaf(const Branch& branch, const Leaf& leaf, float leaf_size, float aspect,
             const MeshOptions& options, Writer* leaves) {
  const float scale = options.cm_to_units;
  glm::vec3 along = SafeNormalize(leaf.direction, kWorldUp);
  // The blade's width runs horizontally when it can, so the leaf faces the sky.
  glm::vec3 across = SafeNormalizeOrPerpendicular(glm::cross(along, kWorldUp), along);
  glm::vec3 normal = SafeNormalize(glm::cross(across, along), kWorldUp);
  glm::vec3 base = branch.nodes[static_cast<std::size_t>(leaf.node)] * scale;
  glm::vec3 tip = base + along * (leaf_size * scale);
  glm::vec3 half = across * (0.5f * aspect * leaf_size * scale);  // aspect: width / length
  const glm::vec3 corners[4] = {base - half, base + half, tip + half, tip - half};
  const glm::vec2 uv[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
  AddDoubleSidedQuad(leaves, corners, normal, uv, static_cast<uint32_t>(branch.id),
                     static_cast<uint32_t>(leaf.node));
}

// cos and sin of the flower outline's angles 2π·k/10, scaled by the petal or notch radius.
struct FlowerTable {
  float c[kFlowerOutline], s[kFlowerOutline];
  FlowerTable() {
    for (int k = 0; k < kFlowerOutline; ++k) {
      float angle = 2.0f * kPi * static_cast<float>(k) / static_cast<float>(kFlowerOutline);
      float r = (k % 2 == 0) ? kFlowerOuterRadius_cm : kFlowerInnerRadius_cm;
      c[k] = det::Cosf(angle) * r;
      s[k] = det::Sinf(angle) * r;
    }
  }
};

void AddFlower(const Branch& branch, int node, const MeshOptions& options,
               const FlowerTable& outline, Writer* flowers) {
  const float scale = options.cm_to_units;
  const uint32_t id = static_cast<uint32_t>(branch.id), at = static_cast<uint32_t>(node);
  glm::vec3 position = branch.nodes[static_cast<std::size_t>(node)];
  // Faces up and away from the trunk axis.
  glm::vec3 outward = SafeNormalize(glm::vec3(position.x, 0.0f, position.z), glm::vec3(0.0f));
  glm::vec3 facing = SafeNormalize(kWorldUp + 0.5f * outward, kWorldUp);
  glm::vec3 a = AnyPerpendicular(facing);
  glm::vec3 b = SafeNormalizeOrPerpendicular(glm::cross(facing, a), a);
  glm::vec3 center = (position + facing * kFlowerLift_cm) * scale;
  for (int side = 0; side < 2; ++side) {
    glm::vec3 normal = side == 0 ? facing : -facing;
    uint32_t hub = flowers->next;
    flowers->Vertex(center, normal, 0.5f, 0.5f, id, at);
    for (int k = 0; k < kFlowerOutline; ++k) {
      float c = outline.c[k], s = outline.s[k];
      flowers->Vertex(center + (a * c + b * s) * scale, normal,
                      0.5f + 0.5f * c / kFlowerOuterRadius_cm,
                      0.5f + 0.5f * s / kFlowerOuterRadius_cm, id, at);
    }
    // a x b = facing, so increasing angle is counter-clockwise seen from the front.
    for (uint32_t k = 0; k < static_cast<uint32_t>(kFlowerOutline); ++k) {
      uint32_t p = hub + 1 + k, q = hub + 1 + (k + 1) % static_cast<uint32_t>(kFlowerOutline);
      if (side == 0) {
        flowers->Triangle(hub, p, q);
      } else {
        flowers->Triangle(hub, q, p);
      }
    }
  }
}

}  // namespace

TreeMesh BuildTreeMesh(const Tree& tree, const MeshOptions& options) {
  TreeMesh mesh;
  mesh.look = options.look ? *options.look : LookFromParams(tree.params);
  // The card drawn for each leaf: leaf_size (the light model's leaf) times leaf_card is the length
  // of the leaf on it; with leaf_spray > 1 the card holds a twig with several such leaves and is
  // that many leaf lengths long and wide (tree_textures.h LeafCardOf). leaf_spray 1: the leaf's
  // own quad, aspect × 1.
  const LeafCardSize card = LeafCardOf(mesh.look);
  const float leaf_aspect = card.width / card.length;
  const float leaf_size = LeafCardLength(tree.params) * card.length;
  const int lo_sides = std::max(3, options.min_sides);
  const int hi_sides = std::max(lo_sides, options.max_sides);
  const std::size_t count = tree.branches.size();

  // Pass 1: which branches are drawn, their sides, and the size of every buffer.
  std::vector<int> sides(count, 0);                // 0: not drawn
  std::vector<std::size_t> node_offset(count, 0);  // first entry of the branch in node_v
  std::size_t nodes = 0, bark_vertices = 0, bark_indices = 0;
  std::size_t leaf_count = 0, flower_count = 0;
  std::vector<ChildInfo> info(count);
  for (std::size_t n = 0; n < count; ++n) {
    const Branch& branch = tree.branches[n];
    info[n] = {branch.parent_node, branch.alive ? BranchRadius(branch) : -1.0f};
  }
  for (std::size_t n = 0; n < count; ++n) {
    const Branch& branch = tree.branches[n];
    if (!branch.alive || branch.nodes.size() < 2) continue;
    const std::size_t rings = branch.nodes.size();
    const int s = SidesForRadius(info[n].radius, lo_sides, hi_sides);
    const std::size_t side_count = static_cast<std::size_t>(s);
    sides[n] = s;
    node_offset[n] = nodes;
    nodes += rings;
    bark_vertices += rings * (side_count + 1) + 1 + side_count;
    bark_indices += 6 * (rings - 1) * side_count + 3 * side_count;
    for (const Leaf& leaf : branch.leaves) leaf_count += ValidNode(branch, leaf.node) ? 1 : 0;
    for (int node : branch.flowers) flower_count += ValidNode(branch, node) ? 1 : 0;
  }
  // The season: a tree's leaves and flowers may be left off (tree_look.h).
  const bool with_leaves = ShowsLeaves(mesh.look, flower_count > 0);
  const bool with_flowers = ShowsFlowers(mesh.look);
  if (!with_leaves) leaf_count = 0;
  if (!with_flowers) flower_count = 0;
  Writer bark = StartWriting(&mesh.bark, &mesh.bark_branch_id, &mesh.bark_node_index, bark_vertices,
                             bark_indices);
  Writer leaves = StartWriting(&mesh.leaves, &mesh.leaf_branch_id, &mesh.leaf_node_index,
                               leaf_count * kLeafVertices, leaf_count * kLeafIndices);
  Writer flowers = StartWriting(&mesh.flowers, &mesh.flower_branch_id, &mesh.flower_node_index,
                                flower_count * kFlowerVertices, flower_count * kFlowerIndices);

  // Pass 2: the geometry. v coordinate (metres along the wood) of every node, so children continue
  // their parent's v.
  const RingTable ring(lo_sides, hi_sides);
  const FlowerTable outline;
  TubeScratch scratch;
  std::vector<float> node_v(nodes);
  for (std::size_t n = 0; n < count; ++n) {
    if (sides[n] == 0) continue;
    const Branch& branch = tree.branches[n];
    float v_start = 0.0f;
    if (branch.parent >= 0 && branch.parent < static_cast<int>(n)) {
      const std::size_t parent = static_cast<std::size_t>(branch.parent);
      if (sides[parent] != 0 && branch.parent_node >= 0 &&
          branch.parent_node < static_cast<int>(tree.branches[parent].nodes.size())) {
        v_start = node_v[node_offset[parent] + static_cast<std::size_t>(branch.parent_node)];
      }
    }
    AddBranchTube(info, branch, info[n].radius, sides[n], v_start, options, ring, &scratch, &bark,
                  node_v.data() + node_offset[n]);
    for (const Leaf& leaf : branch.leaves) {
      if (with_leaves && ValidNode(branch, leaf.node)) {
        AddLeaf(branch, leaf, leaf_size, leaf_aspect, options, &leaves);
      }
    }
    for (int node : branch.flowers) {
      if (with_flowers && ValidNode(branch, node))
        AddFlower(branch, node, options, outline, &flowers);
    }
  }
  return mesh;
}

}  // namespace niwa
