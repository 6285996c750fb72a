// Mesh metrics: triangle and surface area, bounds, degenerate triangles, ValidateMesh.
#include "geom/mesh_metrics.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "geom/triangle_queries.h"

namespace niwa::geom {
namespace {

DVec3 CornerD(const TriMesh& mesh, std::size_t t, int k) {
  return ToD(mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(k)]]);
}

bool Finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

double TriangleArea(const TriMesh& mesh, std::size_t t) {
  DVec3 a = CornerD(mesh, t, 0), b = CornerD(mesh, t, 1), c = CornerD(mesh, t, 2);
  DVec3 n = Cross(Sub(b, a), Sub(c, a));
  return 0.5 * std::sqrt(Dot(n, n));
}

double SurfaceArea(const TriMesh& mesh) {
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) sum += TriangleArea(mesh, t);
  return sum;
}

Bounds3 MeshBounds(const TriMesh& mesh) {
  Bounds3 b;
  for (std::size_t i = 0; i < 3 * mesh.triangle_count(); ++i)
    b.Extend(mesh.positions[mesh.indices[i]]);
  return b;
}

bool IsDegenerateTriangle(const TriMesh& mesh, std::size_t t) {
  uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1], i2 = mesh.indices[3 * t + 2];
  if (i0 == i1 || i1 == i2 || i0 == i2) return true;
  DVec3 a = CornerD(mesh, t, 0), b = CornerD(mesh, t, 1), c = CornerD(mesh, t, 2);
  DVec3 n = Cross(Sub(b, a), Sub(c, a));
  return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

std::size_t CountDegenerateTriangles(const TriMesh& mesh) {
  std::size_t n = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
    n += IsDegenerateTriangle(mesh, t) ? 1 : 0;
  return n;
}

std::size_t RemoveDegenerateTriangles(TriMesh* mesh) {
  std::size_t kept = 0, count = mesh->triangle_count();
  for (std::size_t t = 0; t < count; ++t) {
    if (IsDegenerateTriangle(*mesh, t)) continue;
    for (int k = 0; k < 3; ++k)
      mesh->indices[3 * kept + static_cast<std::size_t>(k)] =
          mesh->indices[3 * t + static_cast<std::size_t>(k)];
    ++kept;
  }
  mesh->indices.resize(3 * kept);
  return count - kept;
}

Status ValidateMesh(const TriMesh& mesh, const std::string& field) {
  const std::size_t n = mesh.vertex_count();
  if (mesh.indices.size() % 3 != 0)
    return Status::Error(field, "index count " + std::to_string(mesh.indices.size()) +
                                    " is not a multiple of 3 (three indices per triangle)");
  if (mesh.triangle_count() == 0)
    return Status::Error(field, "has no triangles; must have at least 1");
  for (std::size_t i = 0; i < n; ++i) {
    if (!Finite(mesh.positions[i]))
      return Status::Error(field, "position of vertex " + std::to_string(i) +
                                      " is NaN or infinite; every coordinate must be finite");
  }
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= n)
      return Status::Error(field, "index " + std::to_string(mesh.indices[i]) + " of triangle " +
                                      std::to_string(i / 3) + " is out of range; must be in [0, " +
                                      std::to_string(n == 0 ? 0 : n - 1) + "]");
  }
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    return Status::Error(field, std::to_string(mesh.normals.size()) + " normals for " +
                                    std::to_string(n) + " vertices; must be 0 or one per vertex");
  if (!mesh.uvs.empty() && mesh.uvs.size() != n)
    return Status::Error(field, std::to_string(mesh.uvs.size()) + " uvs for " + std::to_string(n) +
                                    " vertices; must be 0 or one per vertex");
  for (const VertexAttribute& a : mesh.attributes) {
    if (a.components < 1 || a.values.size() != n * static_cast<std::size_t>(a.components))
      return Status::Error(field, "attribute " + a.name + " has " +
                                      std::to_string(a.values.size()) + " values; must be " +
                                      std::to_string(a.components) +
                                      " per vertex (components >= 1)");
  }
  return Status::Ok();
}

std::vector<glm::vec3> FaceNormals(const TriMesh& mesh) {
  std::vector<glm::vec3> sum(mesh.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                   c = mesh.indices[3 * t + 2];
    const glm::vec3 n =
        glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    sum[a] += n;
    sum[b] += n;
    sum[c] += n;
  }
  std::vector<glm::vec3> out;
  out.reserve(sum.size());
  for (const glm::vec3& n : sum) {
    const float l = std::sqrt(glm::dot(n, n));
    out.push_back(l > 0 ? n / l : glm::vec3(0, 1, 0));
  }
  return out;
}

}  // namespace niwa::geom
