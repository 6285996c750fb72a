// Test reference: a Luft-style ivy (Thomas Luft's Ivy Generator, 2006), the tool artists use, grown
// on a support so the artist preset's leaf cover can be measured against it (issue 31 item 5). Its
// method as read from the generator's description and source (written anew here, with Niwa's types,
// RNG and BVH queries; none of its code): each step every living root adds a node along a grow
// vector, the weighted sum of its smoothed primary direction (0.5), a random direction with a
// little up (0.2) and an adhesion towards the nearest surface point (0.1), normalised, of length
// ivy_size · R (R: the support's bounding-sphere radius), plus gravity growing with the length
// floating off the support (·(floating / max_float)^0.7); a step that enters a face is mirrored at
// its plane and climbs; a root dies when it floats farther than max_float · R; one new root a step
// may branch off a living root (up to four levels), likelier at mid-length; then ten passes over
// every node place leaf quads (half-size leaf_size · ivy_size · R, bigger mid-root) with a chance
// that grows towards a root's tip, each jittered and turned by the smoothed adhesion.
// Differences from the generator, on purpose: the adhesion is to the nearest point of any face
// (his: a face's interior, seen from its front), collisions are found by a ray through the BVH
// (his: every triangle), and growth stops at a given total stem length, so the reference and
// Niwa's ivy are compared for the same amount of stem. Not a library: no C++ one grows ivy this
// way.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/mesh_metrics.h"
#include "geom/ray_cast.h"
#include "geom/tri_mesh.h"
#include "random/pcg32.h"

namespace niwa::testing {

struct LuftIvyOptions {
  double ivy_size = 0.005;  // a step, in bounding-sphere radii (the generator's default)
  double primary = 0.5, random = 0.2, adhesion = 0.1, gravity = 1.0;
  double branching = 0.95;                     // a root branches where random · weight exceeds it
  double leaf_probability = 0.7;               // a leaf where random · weight exceeds it
  double leaf_size = 1.5;                      // leaf half-size in steps
  double max_float = 0.1, max_adhesion = 0.1;  // in bounding-sphere radii
  double stem_length = 0;                      // stop when the roots' total length reaches it
  int max_steps = 200000;
  uint64_t seed = 1;
};

struct LuftIvy {
  std::vector<std::vector<glm::dvec3>> roots;  // each root's nodes
  double stem_length = 0;
  int steps = 0;
  geom::TriMesh leaves;  // two triangles a leaf quad
};

namespace luft_detail {

constexpr double kLuftPi = 3.14159265358979323846;

inline glm::dvec3 RandomUnit(Pcg32* rng) {
  for (;;) {
    const glm::dvec3 v(rng->Uniform(-1, 1), rng->Uniform(-1, 1), rng->Uniform(-1, 1));
    const double l2 = glm::dot(v, v);
    if (l2 > 1e-6 && l2 <= 1) return v / std::sqrt(l2);
  }
}

inline glm::dvec3 Unit(const glm::dvec3& v, const glm::dvec3& fallback) {
  const double l = glm::length(v);
  return l > 1e-12 ? v / l : fallback;
}

// p rotated by `angle` about the axis through `centre` along unit `axis` (Rodrigues).
inline glm::dvec3 Rotate(const glm::dvec3& p, const glm::dvec3& centre, const glm::dvec3& axis,
                         double angle) {
  const glm::dvec3 v = p - centre;
  const double c = std::cos(angle), s = std::sin(angle);
  return centre + v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1 - c);
}

struct Node {
  glm::dvec3 pos, primary, adhesion;
  double length = 0, floating = 0;
};

struct Root {
  std::vector<Node> nodes;
  bool alive = true;
  int parents = 0;
};

}  // namespace luft_detail

inline LuftIvy GrowLuftIvy(const geom::TriMesh& support, const geom::Bvh& bvh,
                           const glm::dvec3& seed, const LuftIvyOptions& o) {
  using namespace luft_detail;
  const geom::Bounds3 b = geom::MeshBounds(support);
  const double radius = 0.5 * glm::length(glm::dvec3(b.max - b.min));
  const double step = radius * o.ivy_size, max_float = radius * o.max_float;
  const double max_adhesion = radius * o.max_adhesion;
  const double sum = o.primary + o.random + o.adhesion;
  const double wp = o.primary / sum, wr = o.random / sum, wa = o.adhesion / sum;
  const glm::dvec3 up(0, 1, 0);
  Pcg32 rng(o.seed);
  std::vector<Root> roots(1);
  roots[0].nodes.push_back({seed, up, glm::dvec3(0), 0, 0});
  LuftIvy out;
  auto adhesion_at = [&](const glm::dvec3& p) {
    const geom::ClosestHit h =
        geom::ClosestPoint(support, bvh, glm::vec3(p), static_cast<float>(max_adhesion));
    if (!h.found) return glm::dvec3(0);
    const glm::dvec3 to = glm::dvec3(h.point) - p;
    const double d = glm::length(to);
    return d > 1e-12 ? to / d * (1 - d / max_adhesion) : glm::dvec3(0);
  };
  while (out.stem_length < o.stem_length && out.steps < o.max_steps) {
    ++out.steps;
    bool any = false;
    for (Root& root : roots) {
      if (!root.alive) continue;
      const Node last = root.nodes.back();
      if (last.floating > max_float) {
        root.alive = false;
        continue;
      }
      any = true;
      const glm::dvec3 random = Unit(RandomUnit(&rng) + glm::dvec3(0, 0.2, 0), up);
      const glm::dvec3 adhesion = adhesion_at(last.pos);
      glm::dvec3 grow = step * (last.primary * wp + random * wr + adhesion * wa);
      const glm::dvec3 gravity =
          step * o.gravity * std::pow(last.floating / max_float, 0.7) * glm::dvec3(0, -1, 0);
      glm::dvec3 next = last.pos + grow + gravity;
      // A step entering a face (against its normal) is mirrored at the face's plane and climbs.
      bool climbing = false, stuck = false;
      for (int tries = 0;; ++tries) {
        const glm::dvec3 d = next - last.pos;
        const double len = glm::length(d);
        if (len <= 1e-12) break;
        const geom::RayHit hit = geom::FirstHit(support, bvh, glm::vec3(last.pos),
                                                glm::vec3(d / len), static_cast<float>(len));
        if (!hit.hit) break;
        const glm::dvec3 n(hit.normal);
        if (glm::dot(n, d) >= 0) break;  // leaving through the back: as the generator, no test
        if (tries >= 5) {
          stuck = true;
          break;
        }
        const glm::dvec3 on = next - n * glm::dot(n, next - glm::dvec3(hit.point));
        next = on + (on - next);
        climbing = true;
      }
      if (stuck) {
        root.alive = false;
        continue;
      }
      grow = next - last.pos - gravity;
      const double moved = glm::length(next - last.pos);
      Node node;
      node.pos = next;
      node.primary = Unit(0.5 * last.primary + 0.5 * Unit(grow, last.primary), up);
      node.adhesion = adhesion;
      node.length = last.length + moved;
      node.floating = climbing ? 0 : last.floating + moved;
      root.nodes.push_back(node);
      out.stem_length += moved;
    }
    if (!any) break;
    // One new root a step, off a living root's node, likelier at mid-length.
    const std::size_t count = roots.size();
    bool branched = false;
    for (std::size_t r = 0; r < count && !branched; ++r) {
      if (!roots[r].alive || roots[r].parents > 3) continue;
      const double total = roots[r].nodes.back().length;
      if (total <= 0) continue;
      for (std::size_t k = 0; k < roots[r].nodes.size(); ++k) {
        const Node& at = roots[r].nodes[k];
        const double weight = 1 - (std::cos(at.length / total * 2 * kLuftPi) * 0.5 + 0.5);
        if (rng.Uniform() * weight > o.branching) {
          Root child;
          child.nodes.push_back({at.pos, up, glm::dvec3(0), 0, at.floating});
          child.parents = roots[r].parents + 1;
          roots.push_back(child);
          branched = true;
          break;
        }
      }
    }
  }
  // Leaves: the adhesion vectors smoothed five times along each root (a 1-2-4-7-9-10-9-7-4-2-1
  // kernel), then ten passes over the nodes.
  const double leaf = radius * o.ivy_size * o.leaf_size;
  const double kernel[11] = {1, 2, 4, 7, 9, 10, 9, 7, 4, 2, 1};
  for (Root& root : roots) {
    const int n = static_cast<int>(root.nodes.size());
    for (int pass = 0; pass < 5; ++pass) {
      std::vector<glm::dvec3> smooth(root.nodes.size());
      for (int k = 0; k < n; ++k) {
        glm::dvec3 e(0);
        for (int i = -5; i <= 5; ++i)
          e += root.nodes[static_cast<std::size_t>(std::clamp(k + i, 0, n - 1))].adhesion *
               kernel[i + 5];
        smooth[static_cast<std::size_t>(k)] = e / 56.0;
      }
      for (int k = 0; k < n; ++k)
        root.nodes[static_cast<std::size_t>(k)].adhesion = smooth[static_cast<std::size_t>(k)];
    }
  }
  for (const Root& root : roots) {
    const double total = root.nodes.back().length;
    std::vector<glm::dvec3> path;
    for (const Node& node : root.nodes) path.push_back(node.pos);
    out.roots.push_back(path);
    if (total <= 0) continue;
    for (int pass = 0; pass < 10; ++pass) {
      for (const Node& node : root.nodes) {
        double weight = std::pow(node.length / total, 0.7);
        const double ground = std::max(0.0, -glm::dot(up, Unit(node.adhesion, glm::dvec3(0))));
        weight += ground * std::pow(1 - node.length / total, 2.0);
        if (!(rng.Uniform() * weight > o.leaf_probability)) continue;
        const double align = glm::length(node.adhesion);
        const glm::dvec3 a = Unit(node.adhesion, glm::dvec3(0, 0, 1));
        double phi = std::atan2(a.x, a.z) - 0.5 * kLuftPi;  // the adhesion's horizontal angle
        double theta = 0.5 * std::acos(std::clamp(glm::dot(a, -up), -1.0, 1.0));
        const glm::dvec3 centre = node.pos + RandomUnit(&rng) * leaf;
        const double size = leaf * (1.5 - (std::cos(weight * 2 * kLuftPi) * 0.5 + 0.5));
        phi += (rng.Uniform() - 0.5) * (1.3 - align);
        theta += (rng.Uniform() - 0.5) * (1.1 - align);
        const uint32_t base = static_cast<uint32_t>(out.leaves.positions.size());
        for (const auto& [x, z] : {std::pair{-1.0, 1.0}, std::pair{1.0, 1.0}, std::pair{-1.0, -1.0},
                                   std::pair{1.0, -1.0}}) {
          glm::dvec3 p = centre + glm::dvec3(x * size, 0, z * size);
          p = Rotate(p, centre, glm::dvec3(0, 0, 1), theta);
          p = Rotate(p, centre, up, phi);
          p += RandomUnit(&rng) * size * 0.5;
          out.leaves.positions.push_back(glm::vec3(p));
        }
        for (uint32_t i : {base + 3, base + 1, base + 2, base + 2, base + 0, base + 3})
          out.leaves.indices.push_back(i);
      }
    }
  }
  return out;
}

}  // namespace niwa::testing
