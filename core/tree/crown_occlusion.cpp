// Crown ambient occlusion: a leaf-area grid, Beer-Lambert optical depth along sky directions, and
// its trilinear field at the mesh's vertices (see crown_occlusion.h).
#include "tree/crown_occlusion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "math/det_math.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

// Unit directions towards the sky: the zenith, four at 45° elevation (azimuths 0°, 90°, 180°,
// 270°) and four at 15° (azimuths 45°, 135°, 225°, 315°), equally weighted.
constexpr double kHalfSqrt2 = 0.70710678118654752440;  // cos 45° = sin 45°
constexpr double kCos15 = 0.96592582628906828675, kSin15 = 0.25881904510252076235;
constexpr std::array<std::array<double, 3>, 9> kOcclusionDirections = {{
    {0.0, 1.0, 0.0},
    {kHalfSqrt2, kHalfSqrt2, 0.0},
    {0.0, kHalfSqrt2, kHalfSqrt2},
    {-kHalfSqrt2, kHalfSqrt2, 0.0},
    {0.0, kHalfSqrt2, -kHalfSqrt2},
    {kCos15 * kHalfSqrt2, kSin15, kCos15* kHalfSqrt2},
    {-kCos15 * kHalfSqrt2, kSin15, kCos15* kHalfSqrt2},
    {-kCos15 * kHalfSqrt2, kSin15, -kCos15* kHalfSqrt2},
    {kCos15 * kHalfSqrt2, kSin15, -kCos15* kHalfSqrt2},
}};

glm::dvec3 OcclusionVertex(const std::vector<float>& positions, std::size_t v) {
  return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
}

}  // namespace

CrownOcclusionField::CrownOcclusionField(const std::vector<const MeshBuffers*>& occluders,
                                         const std::vector<const MeshBuffers*>& covered,
                                         const std::vector<double>& weights) {
  bool leaves = false;
  for (const MeshBuffers* part : occluders) leaves = leaves || !part->indices.empty();
  if (!leaves) return;
  glm::dvec3 lo(0.0), hi(0.0);
  bool any = false;
  std::vector<const MeshBuffers*> boxed = occluders;
  boxed.insert(boxed.end(), covered.begin(), covered.end());
  for (const MeshBuffers* part : boxed) {
    for (std::size_t v = 0; v < part->vertex_count(); ++v) {
      const glm::dvec3 p = OcclusionVertex(part->positions, v);
      if (!any) lo = hi = p;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      any = true;
    }
  }
  if (!any) return;
  const glm::dvec3 size = hi - lo;
  const double longest = std::max(std::max(size.x, size.y), size.z);
  cell_ = longest > 0 ? longest / kCrownOcclusionCells : 1e-3;
  origin_ = lo - glm::dvec3(0.5 * cell_);  // half a cell of margin all round
  for (int a = 0; a < 3; ++a) {
    dims_[a] = std::max(1, static_cast<int>(std::ceil(size[a] / cell_)) + 1);
  }
  const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  const auto index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x;
  };
  const auto cell_of = [&](const glm::dvec3& p, int out[3]) {
    for (int a = 0; a < 3; ++a) {
      const double c = std::floor((p[a] - origin_[a]) / cell_);
      if (!(c >= 0) || c >= dims_[a]) return false;
      out[a] = static_cast<int>(c);
    }
    return true;
  };
  // Leaf area density (m²/m³): each triangle's area at its centroid's cell. The parts are
  // double-sided, each face its own triangles (tree/mesh.h), so half a triangle's area is the
  // leaf's one-sided area.
  std::vector<double> density(cells, 0.0);
  const double volume = cell_ * cell_ * cell_;
  for (std::size_t k = 0; k < occluders.size(); ++k) {
    const MeshBuffers* part = occluders[k];
    const double weight = k < weights.size() ? weights[k] : 1.0;
    for (std::size_t t = 0; t + 2 < part->indices.size(); t += 3) {
      const glm::dvec3 a = OcclusionVertex(part->positions, part->indices[t]);
      const glm::dvec3 b = OcclusionVertex(part->positions, part->indices[t + 1]);
      const glm::dvec3 c = OcclusionVertex(part->positions, part->indices[t + 2]);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double area = 0.5 * std::sqrt((n.x * n.x + n.y * n.y) + n.z * n.z);
      int at[3];
      if (cell_of((a + b + c) / 3.0, at))
        density[index(at[0], at[1], at[2])] += weight * (0.5 * area / volume);
    }
  }
  // Optical depth from each cell centre along each sky direction, Beer-Lambert: tau = Σ G·LAD·h
  // with h = one cell per step (the cell itself: half a step), to the grid's edge. The k-th step
  // from a cell centre lands in the cell offset by floor(0.5 + k·d) (in cells) whatever the cell,
  // so each direction's offsets are found once.
  const int longest_dim = std::max(std::max(dims_[0], dims_[1]), dims_[2]);
  std::vector<std::array<int, 3>> offsets[kOcclusionDirections.size()];
  for (std::size_t i = 0; i < kOcclusionDirections.size(); ++i) {
    for (int k = 1; k <= 2 * longest_dim; ++k) {
      std::array<int, 3> o;
      for (int a = 0; a < 3; ++a) {
        o[a] = static_cast<int>(std::floor(0.5 + k * kOcclusionDirections[i][a]));
      }
      offsets[i].push_back(o);
    }
  }
  occlusion_.assign(cells, 0.0);
  const double h = cell_;
  for (int z = 0; z < dims_[2]; ++z)
    for (int y = 0; y < dims_[1]; ++y)
      for (int x = 0; x < dims_[0]; ++x) {
        const double own = density[index(x, y, z)];
        double open = 0.0;
        for (const auto& steps : offsets) {
          double depth = 0.5 * own;  // Σ LAD over the steps
          for (const std::array<int, 3>& o : steps) {
            const int cx = x + o[0], cy = y + o[1], cz = z + o[2];
            if (cx < 0 || cy < 0 || cz < 0 || cx >= dims_[0] || cy >= dims_[1] || cz >= dims_[2]) {
              break;
            }
            depth += density[index(cx, cy, cz)];
          }
          open += det::Exp(-kLeafProjection * depth * h);
        }
        occlusion_[index(x, y, z)] = 1.0 - open / kOcclusionDirections.size();
      }
}

double CrownOcclusionField::CellValue(int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) return 0.0;
  return occlusion_[(static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x];
}

double CrownOcclusionField::At(const glm::dvec3& p) const {
  if (occlusion_.empty()) return 0.0;
  int i[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - origin_[a]) / cell_ - 0.5;  // in cell centres
    if (!(u > -1.0) || !(u < dims_[a])) return 0.0;      // outside (or NaN): open sky
    const double base = std::floor(u);
    i[a] = static_cast<int>(base);
    f[a] = u - base;
  }
  double value = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    const double w = (dx ? f[0] : 1.0 - f[0]) * (dy ? f[1] : 1.0 - f[1]) * (dz ? f[2] : 1.0 - f[2]);
    value += w * CellValue(i[0] + dx, i[1] + dy, i[2] + dz);
  }
  return value;
}

std::vector<float> CrownOcclusionField::AtVertices(const MeshBuffers& part) const {
  std::vector<float> out(part.vertex_count());
  for (std::size_t v = 0; v < out.size(); ++v) {
    out[v] = static_cast<float>(At(OcclusionVertex(part.positions, v)));
  }
  return out;
}

CrownOcclusion ComputeCrownOcclusion(const TreeMesh& mesh) {
  // A leaf_spray card (tree_textures.h) is n leaves painted on a card larger than one leaf's quad;
  // it counts as the one grown leaf's quad, so a spray leaves the occlusion as it was (its n× leaf
  // area would darken the crown's inside and the trunk under it to near black).
  const LeafCardSize card = LeafCardOf(mesh.look);
  const double leaf_weight = mesh.look.leaf_spray > 1
                                 ? LeafQuadAspect(mesh.look.leaf_shape) / (card.width * card.length)
                                 : 1.0;
  const CrownOcclusionField field({&mesh.leaves, &mesh.flowers}, {&mesh.bark}, {leaf_weight, 1.0});
  return {field.AtVertices(mesh.bark), field.AtVertices(mesh.leaves),
          field.AtVertices(mesh.flowers)};
}

}  // namespace niwa
