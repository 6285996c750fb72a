// Crown ambient occlusion (issue 32, "light and look"): how much of the sky a point of the tree's
// mesh sees through the crown's leaves, one value per vertex, computed once per mesh for the page's
// shading (inner leaves darker than the crown's skin).
//
// The model: the leaves' and flowers' one-sided area (double-sided triangles counted once) is
// binned into a grid over the crown (cell = longest side / kCrownOcclusionCells); each cell's leaf
// area density LAD = area / cell volume (m²/m³). From each cell centre, the optical depth along
// each of kOcclusionDirections (the zenith, four at 45° and four at 15° elevation) is summed cell
// by cell, tau = Σ G · LAD · h (Beer-Lambert through a turbid medium of leaves, Monsi & Saeki; G =
// 0.5, the projection of a spherical leaf-angle distribution, Ross 1981; h = the cell size, half a
// cell for the cell itself), and the cell's occlusion is 1 - mean over the directions of e^-tau. A
// vertex reads the field trilinearly at its position. Deterministic: double arithmetic and det::Exp
// only. Not here: the sun's direct shadow (the page's shadow map), bark or wood as occluders, light
// from below the horizon, the growth's own light model (tree/light.h).
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "tree/mesh.h"

namespace niwa {

constexpr int kCrownOcclusionCells = 32;  // cells along the crown box's longest side
constexpr double kLeafProjection = 0.5;   // G, spherical leaf-angle distribution (Ross 1981)

// One occlusion value per vertex of each part of a mesh, in [0, 1] (0: the whole sky is open).
struct CrownOcclusion {
  std::vector<float> bark, leaves, flowers;
};

// The field over the leaves and flowers of a mesh (see above); queried at any point.
class CrownOcclusionField {
 public:
  // Bins the triangles of the occluding parts (each double-sided: its area counted once) into a
  // grid over their box and the vertices of `covered` (parts queried but not occluding: the bark,
  // whose trunk foot lies below the crown). `weights`: one factor per occluder on its triangles'
  // area (empty: 1 each); a leaf_spray card counts as the one grown leaf it stands for.
  explicit CrownOcclusionField(const std::vector<const MeshBuffers*>& occluders,
                               const std::vector<const MeshBuffers*>& covered = {},
                               const std::vector<double>& weights = {});

  // The occlusion at `p` (metres), trilinear in the cell-centre values; 0 outside the grid's box
  // and everywhere when there are no leaves.
  double At(const glm::dvec3& p) const;

  // One value per vertex of `part` (positions xyz).
  std::vector<float> AtVertices(const MeshBuffers& part) const;

 private:
  double CellValue(int x, int y, int z) const;
  std::vector<double> occlusion_;  // per cell, x fastest
  glm::dvec3 origin_{0.0};
  double cell_ = 1.0;
  int dims_[3] = {0, 0, 0};
};

// The occlusion of every vertex of the mesh's bark, leaves and flowers, the leaves and flowers
// being the occluders.
CrownOcclusion ComputeCrownOcclusion(const TreeMesh& mesh);

}  // namespace niwa
