// Per-vertex tangents from positions, normals and uvs (area-weighted sum of per-triangle dP/du,
// Gram-Schmidt against the normal, handedness from -dP/dv: glTF's "+Y up the image").
#include "geom/tangents.h"

#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace niwa::geom {
namespace {

// A unit vector perpendicular to unit n (the axis least along n, made orthogonal to it).
glm::dvec3 AnyPerpendicular(const glm::dvec3& n) {
  const glm::dvec3 axis = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(axis - n * glm::dot(n, axis));
}

// v / |v|, or zero when |v| is zero or not finite.
glm::dvec3 UnitOrZero(const glm::dvec3& v) {
  const double length = std::sqrt(glm::dot(v, v));
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0);
  return v / length;
}

}  // namespace

std::vector<float> ComputeTangentValues(const TriMesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  if (n == 0 || mesh.normals.size() != n || mesh.uvs.size() != n) return {};
  std::vector<glm::dvec3> tangent_sum(n, glm::dvec3(0.0)), bitangent_sum(n, glm::dvec3(0.0));
  // Without indices the vertices in order are the triangles (as glTF reads them).
  const bool indexed = !mesh.indices.empty();
  const std::size_t corners = indexed ? mesh.indices.size() : n;
  const auto corner = [&](std::size_t k) {
    return indexed ? static_cast<std::size_t>(mesh.indices[k]) : k;
  };
  for (std::size_t t = 0; t + 2 < corners; t += 3) {
    const std::size_t i[3] = {corner(t), corner(t + 1), corner(t + 2)};
    if (i[0] >= n || i[1] >= n || i[2] >= n) continue;
    const glm::dvec3 p0(mesh.positions[i[0]]);
    const glm::dvec3 e1 = glm::dvec3(mesh.positions[i[1]]) - p0;
    const glm::dvec3 e2 = glm::dvec3(mesh.positions[i[2]]) - p0;
    const glm::dvec2 uv0(mesh.uvs[i[0]]);
    const glm::dvec2 d1 = glm::dvec2(mesh.uvs[i[1]]) - uv0, d2 = glm::dvec2(mesh.uvs[i[2]]) - uv0;
    const double du1 = d1.x, dv1 = d1.y, du2 = d2.x, dv2 = d2.y;
    const double det = du1 * dv2 - du2 * dv1;
    if (det == 0.0) continue;  // degenerate uvs: no dP/du
    // e1 = du1 T + dv1 B, e2 = du2 T + dv2 B solved for T = dP/du and B = dP/dv.
    const glm::dvec3 tangent = UnitOrZero((e1 * dv2 - e2 * dv1) / det);
    const glm::dvec3 bitangent = UnitOrZero((e2 * du1 - e1 * du2) / det);
    const double area = 0.5 * std::sqrt(glm::dot(glm::cross(e1, e2), glm::cross(e1, e2)));
    if (!(area > 0.0) || !std::isfinite(area)) continue;
    for (std::size_t v : i) {
      tangent_sum[v] += tangent * area;
      bitangent_sum[v] += bitangent * area;
    }
  }
  std::vector<float> values(n * 4);
  for (std::size_t v = 0; v < n; ++v) {
    const glm::dvec3 normal = UnitOrZero(glm::dvec3(mesh.normals[v]));
    glm::dvec3 tangent(1.0, 0.0, 0.0);
    double w = 1.0;
    if (normal != glm::dvec3(0.0)) {
      const glm::dvec3 along = tangent_sum[v] - normal * glm::dot(normal, tangent_sum[v]);
      // Along the normal (up to rounding) counts as no tangent.
      const bool usable = glm::dot(along, along) > 1e-20 * glm::dot(tangent_sum[v], tangent_sum[v]);
      tangent = usable ? UnitOrZero(along) : glm::dvec3(0.0);
      if (tangent == glm::dvec3(0.0)) {
        tangent = AnyPerpendicular(normal);
      } else if (glm::dot(glm::cross(normal, tangent), bitangent_sum[v]) > 0.0) {
        // glTF's normal texture has +Y up the image, and its uv origin is the image's top-left
        // corner, so the map's +Y runs along -dP/dv: cross(normal, tangent) * w must too.
        w = -1.0;
      }
    }
    values[v * 4 + 0] = static_cast<float>(tangent.x);
    values[v * 4 + 1] = static_cast<float>(tangent.y);
    values[v * 4 + 2] = static_cast<float>(tangent.z);
    values[v * 4 + 3] = static_cast<float>(w);
  }
  return values;
}

bool ComputeTangents(TriMesh* mesh) {
  std::vector<float> values = ComputeTangentValues(*mesh);
  if (values.empty()) return false;
  VertexAttribute& tangents = mesh->AddAttribute(kTangentAttribute, 4);
  tangents.components = 4;
  tangents.values = std::move(values);
  return true;
}

}  // namespace niwa::geom
