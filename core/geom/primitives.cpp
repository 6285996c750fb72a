// Primitive meshes (box, plane, cylinder, icosphere) and midpoint Subdivide.
#include "geom/primitives.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include "math/det_math.h"

namespace niwa::geom {
namespace {

uint32_t U32(std::size_t i) { return static_cast<uint32_t>(i); }

glm::vec3 NormalizeD(const glm::vec3& v) {
  double x = v.x, y = v.y, z = v.z;
  double len = std::sqrt(x * x + y * y + z * z);
  if (!(len > 0.0)) return glm::vec3(0.0f);
  return glm::vec3(static_cast<float>(x / len), static_cast<float>(y / len),
                   static_cast<float>(z / len));
}

// One midpoint level: each triangle (a, b, c) becomes (a, ab, ca), (ab, b, bc), (ca, bc, c),
// (ab, bc, ca); one new vertex per distinct edge {i, j}.
TriMesh SubdivideOnce(const TriMesh& in) {
  TriMesh out;
  out.positions = in.positions;
  out.normals = in.normals;
  out.uvs = in.uvs;
  out.attributes = in.attributes;
  const std::size_t tris = in.triangle_count();
  std::unordered_map<uint64_t, uint32_t> midpoint;
  midpoint.reserve(tris * 2);
  const bool has_normals = in.normals.size() == in.vertex_count();
  const bool has_uvs = in.uvs.size() == in.vertex_count();
  auto mid = [&](uint32_t i, uint32_t j) -> uint32_t {
    uint32_t lo = std::min(i, j), hi = std::max(i, j);
    uint64_t key = (static_cast<uint64_t>(lo) << 32) | hi;
    auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    uint32_t m = U32(out.positions.size());
    // (lo + hi) / 2 from the lower index first: the same bits whichever triangle asks.
    out.positions.push_back((out.positions[lo] + out.positions[hi]) * 0.5f);
    if (has_normals) out.normals.push_back(NormalizeD(out.normals[lo] + out.normals[hi]));
    if (has_uvs) out.uvs.push_back((out.uvs[lo] + out.uvs[hi]) * 0.5f);
    for (VertexAttribute& a : out.attributes) {
      std::size_t k = static_cast<std::size_t>(a.components);
      if (a.values.size() < (static_cast<std::size_t>(hi) + 1) * k) continue;
      for (std::size_t c = 0; c < k; ++c)
        a.values.push_back((a.values[lo * k + c] + a.values[hi * k + c]) * 0.5f);
    }
    midpoint.emplace(key, m);
    return m;
  };
  out.indices.reserve(tris * 12);
  for (std::size_t t = 0; t < tris; ++t) {
    uint32_t a = in.indices[3 * t], b = in.indices[3 * t + 1], c = in.indices[3 * t + 2];
    uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    const uint32_t kids[12] = {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca};
    out.indices.insert(out.indices.end(), kids, kids + 12);
  }
  return out;
}

void AddQuad(TriMesh* m, uint32_t v00, uint32_t v10, uint32_t v11, uint32_t v01) {
  const uint32_t q[6] = {v00, v10, v11, v00, v11, v01};
  m->indices.insert(m->indices.end(), q, q + 6);
}

}  // namespace

TriMesh MakeBox(const glm::vec3& size, const glm::vec3& centre) {
  // Per face: outward normal n and in-face axes u, v with u × v = n (so (-u,-v), (u,-v), (u,v),
  // (-u,v) runs counter-clockwise seen from outside).
  struct Face {
    glm::vec3 n, u, v;
  };
  const Face faces[6] = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                         {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                         {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
  const glm::vec3 half = size * 0.5f;
  TriMesh m;
  for (const Face& f : faces) {
    uint32_t base = U32(m.positions.size());
    const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
      glm::vec3 unit = f.n + su[k] * f.u + sv[k] * f.v;  // components exactly -1, 0 or 1
      m.positions.push_back(centre + half * unit);       // corners shared by faces: same bits
      m.normals.push_back(f.n);
      m.uvs.push_back(glm::vec2(0.5f * (su[k] + 1.0f), 0.5f * (sv[k] + 1.0f)));
    }
    AddQuad(&m, base, base + 1, base + 2, base + 3);
  }
  return m;
}

TriMesh MakePlane(float width, float depth, int segments_x, int segments_z) {
  const int sx = std::max(1, segments_x), sz = std::max(1, segments_z);
  TriMesh m;
  for (int j = 0; j <= sz; ++j) {
    for (int i = 0; i <= sx; ++i) {
      double fx = static_cast<double>(i) / sx, fz = static_cast<double>(j) / sz;
      m.positions.push_back(glm::vec3(static_cast<float>((fx - 0.5) * width), 0.0f,
                                      static_cast<float>((fz - 0.5) * depth)));
      m.normals.push_back(glm::vec3(0, 1, 0));
      m.uvs.push_back(glm::vec2(static_cast<float>(fx), static_cast<float>(fz)));
    }
  }
  auto at = [&](int i, int j) { return U32(static_cast<std::size_t>(j * (sx + 1) + i)); };
  for (int j = 0; j < sz; ++j) {
    for (int i = 0; i < sx; ++i) {
      // (i, j) → (i, j+1) → (i+1, j+1) is counter-clockwise seen from +y.
      AddQuad(&m, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
    }
  }
  return m;
}

TriMesh MakeCylinder(float radius, float height, int segments, bool caps) {
  const int n = std::max(3, segments);
  std::vector<glm::vec2> ring(static_cast<std::size_t>(n));  // (cos, sin) · radius
  std::vector<glm::vec2> dir(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double s, c;
    det::SinCos(2.0 * det::kPi * i / n, &s, &c);
    dir[static_cast<std::size_t>(i)] = glm::vec2(static_cast<float>(c), static_cast<float>(s));
    ring[static_cast<std::size_t>(i)] =
        glm::vec2(static_cast<float>(c * radius), static_cast<float>(s * radius));
  }
  TriMesh m;
  for (int i = 0; i <= n; ++i) {  // seam column i == n repeats i == 0 (same bits: watertight)
    std::size_t k = static_cast<std::size_t>(i % n);
    for (int top = 0; top < 2; ++top) {
      m.positions.push_back(glm::vec3(ring[k].x, top ? height : 0.0f, ring[k].y));
      m.normals.push_back(glm::vec3(dir[k].x, 0.0f, dir[k].y));
      m.uvs.push_back(glm::vec2(static_cast<float>(static_cast<double>(i) / n), top ? 1.0f : 0.0f));
    }
  }
  for (int i = 0; i < n; ++i) {
    uint32_t b0 = U32(static_cast<std::size_t>(2 * i)), t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
    // (b_i, t_i, b_i+1): (t_i - b_i) × (b_i+1 - b_i) = h (cos, 0, sin): outward.
    const uint32_t q[6] = {b0, t0, b1, b1, t0, t1};
    m.indices.insert(m.indices.end(), q, q + 6);
  }
  if (caps) {
    for (int top = 0; top < 2; ++top) {
      float y = top ? height : 0.0f;
      glm::vec3 normal(0.0f, top ? 1.0f : -1.0f, 0.0f);
      uint32_t centre = U32(m.positions.size());
      m.positions.push_back(glm::vec3(0.0f, y, 0.0f));
      m.normals.push_back(normal);
      m.uvs.push_back(glm::vec2(0.5f));
      for (int i = 0; i < n; ++i) {
        std::size_t k = static_cast<std::size_t>(i);
        m.positions.push_back(glm::vec3(ring[k].x, y, ring[k].y));
        m.normals.push_back(normal);
        m.uvs.push_back(glm::vec2(0.5f + 0.5f * dir[k].x, 0.5f + 0.5f * dir[k].y));
      }
      for (int i = 0; i < n; ++i) {
        uint32_t r0 = centre + 1 + U32(static_cast<std::size_t>(i));
        uint32_t r1 = centre + 1 + U32(static_cast<std::size_t>((i + 1) % n));
        // ring(θ) × ring(θ + δ) points along -y: the bottom fan runs centre, r0, r1.
        const uint32_t tri[3] = {centre, top ? r1 : r0, top ? r0 : r1};
        m.indices.insert(m.indices.end(), tri, tri + 3);
      }
    }
  }
  return m;
}

TriMesh MakeIcosphere(float radius, int level) {
  const int levels = std::clamp(level, 0, 8);
  const float t = static_cast<float>((1.0 + std::sqrt(5.0)) / 2.0);
  TriMesh m;
  m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
               6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (glm::vec3& p : m.positions) p = NormalizeD(p);
  for (int l = 0; l < levels; ++l) {
    m = SubdivideOnce(m);
    for (glm::vec3& p : m.positions) p = NormalizeD(p);
  }
  m.normals = m.positions;
  m.uvs.clear();
  for (glm::vec3& p : m.positions) {
    m.uvs.push_back(glm::vec2(
        static_cast<float>(0.5 + det::Atan2(p.z, p.x) / (2.0 * det::kPi)),
        static_cast<float>(1.0 -
                           det::Acos(std::clamp(static_cast<double>(p.y), -1.0, 1.0)) / det::kPi)));
    p *= radius;
  }
  return m;
}

TriMesh Subdivide(const TriMesh& mesh, int levels) {
  TriMesh m = mesh;
  for (int l = 0; l < std::clamp(levels, 0, 10); ++l) m = SubdivideOnce(m);
  return m;
}

}  // namespace niwa::geom
