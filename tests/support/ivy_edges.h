// Test helper: the convex and concave edges of a support mesh (pairs of non-coplanar triangles that
// share a segment, T-junctions included) and the ivy apices that died (p3: no valid position)
// within reach of a convex one — the failure docs/ivy-model.md "Convex edges" is about.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "geom/tri_mesh.h"
#include "ivy/ivy.h"

namespace niwa::testing {

struct MeshEdge {
  glm::dvec3 a{0.0}, b{0.0};  // the shared segment
  bool convex = false;        // the surface turns away from the outside (a solid's outer corner)
  double dihedral_deg = 0;    // angle between the two faces' outward normals
};

inline glm::dvec3 Corner(const geom::TriMesh& m, std::size_t tri, int k) {
  return glm::dvec3(m.positions[m.indices[3 * tri + static_cast<std::size_t>(k)]]);
}

// Outward normal from the winding (TriMesh: counter-clockwise seen from outside).
inline glm::dvec3 OutwardNormal(const geom::TriMesh& m, std::size_t tri) {
  const glm::dvec3 n =
      glm::cross(Corner(m, tri, 1) - Corner(m, tri, 0), Corner(m, tri, 2) - Corner(m, tri, 0));
  const double len = std::sqrt(glm::dot(n, n));
  return len > 0 ? n / len : n;
}

inline double PointSegmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const glm::dvec3 d = p - (a + t * ab);
  return std::sqrt(glm::dot(d, d));
}

// Every segment two triangles share whose normals differ by more than min_angle_deg (coplanar
// neighbours are no edge), found by brute force over triangle pairs and their collinear edges
// (so a T-junction counts with the overlap). Convex when the second triangle's centroid lies
// behind the first one's plane. For the small built-in scenes (O(T²)).
inline std::vector<MeshEdge> MeshEdges(const geom::TriMesh& m, double min_angle_deg = 1.0) {
  std::vector<MeshEdge> edges;
  const std::size_t n = m.triangle_count();
  const double tol = 1e-4;
  const double cos_min = std::cos(min_angle_deg * 3.14159265358979323846 / 180.0);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 ni = OutwardNormal(m, i);
    for (std::size_t j = i + 1; j < n; ++j) {
      const glm::dvec3 nj = OutwardNormal(m, j);
      const double c = std::clamp(glm::dot(ni, nj), -1.0, 1.0);
      if (c > cos_min) continue;
      for (int ei = 0; ei < 3; ++ei) {
        const glm::dvec3 a0 = Corner(m, i, ei), a1 = Corner(m, i, (ei + 1) % 3);
        const glm::dvec3 dir = a1 - a0;
        const double len = std::sqrt(glm::dot(dir, dir));
        if (len <= tol) continue;
        const glm::dvec3 u = dir / len;
        for (int ej = 0; ej < 3; ++ej) {
          const glm::dvec3 b0 = Corner(m, j, ej), b1 = Corner(m, j, (ej + 1) % 3);
          auto off_line = [&](const glm::dvec3& q) {
            const glm::dvec3 r = q - a0;
            const glm::dvec3 perp = r - glm::dot(r, u) * u;
            return std::sqrt(glm::dot(perp, perp)) > tol;
          };
          if (off_line(b0) || off_line(b1)) continue;
          const double t0 = glm::dot(b0 - a0, u), t1 = glm::dot(b1 - a0, u);
          const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(len, std::max(t0, t1));
          if (hi - lo <= tol) continue;
          const glm::dvec3 cj = (Corner(m, j, 0) + Corner(m, j, 1) + Corner(m, j, 2)) / 3.0;
          MeshEdge e;
          e.a = a0 + lo * u;
          e.b = a0 + hi * u;
          e.convex = glm::dot(cj - a0, ni) < 0;
          e.dihedral_deg = std::acos(c) * 180.0 / 3.14159265358979323846;
          edges.push_back(e);
        }
      }
    }
  }
  return edges;
}

// Distance from p to the nearest convex edge (infinity when the mesh has none).
inline double ConvexEdgeDistance(const std::vector<MeshEdge>& edges, const glm::dvec3& p) {
  double best = INFINITY;
  for (const MeshEdge& e : edges)
    if (e.convex) best = std::min(best, PointSegmentDistance(p, e.a, e.b));
  return best;
}

struct EdgeDeath {
  int bud = 0, axis = 0, step = 0;
  glm::dvec3 pos{0.0};
  double edge_distance = 0;
};

// The apices that ended by p3 (a Z with neither a continuation nor a lateral: its search found no
// valid position) within `reach` of a convex edge.
inline std::vector<EdgeDeath> ConvexEdgeDeaths(const ivy::IvyModel& model,
                                               const std::vector<MeshEdge>& edges, double reach) {
  std::vector<EdgeDeath> deaths;
  for (const ivy::Bud& b : model.buds) {
    if (b.kind != ivy::BudKind::kEnding || b.died_step < 0) continue;
    if (b.child[0] >= 0 || b.child[1] >= 0) continue;  // a D's p3 or a p1: not an apex death
    const double dist = ConvexEdgeDistance(edges, b.pos);
    if (dist <= reach) deaths.push_back({b.id, b.axis, b.died_step, b.pos, dist});
  }
  return deaths;
}

}  // namespace niwa::testing
