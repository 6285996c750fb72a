// Game-ready export budgets (core/render/lod_budget.h); constants measured in docs/budgets.md.
#include "render/lod_budget.h"

#include <algorithm>
#include <string>

namespace niwa {
namespace {

constexpr double kLeafTriangles = 4;     // a double-sided quad (tree/mesh.h)
constexpr double kFlowerTriangles = 20;  // two decagon fans (tree/mesh.cpp kFlowerIndices / 3)
// Per full-mesh triangle: the full mesh (held while a level is chosen), its leaf-cluster scenes,
// the level's parts and cards and the .glb's buffers; with the three levels LOD0 is kept while
// LOD1 and LOD2 are built. Measured natively (docs/budgets.md): sakura 40 (6.4 M triangles) one
// level 98 bytes a triangle, --lod 265; the unit test's smaller trees 279-616 with the atlas' part.
constexpr double kBytesPerTriangle = 250;
constexpr double kLodMemoryFactor = 2.4;
// Per full-mesh triangle and level: the mesh, the cluster ladder's scenes, the card painting
// (measured 230-430 ns natively beside the atlas' fixed part; WASM up to about 2 ×).
constexpr double kNsPerTriangleLevel = 1000;
// Per atlas texel: the RGBA image, its depth buffer while painted, the PNG and its copy in the .glb
// (a 2048² level costs about 0.9 s natively and 1 s in WASM whatever the tree).
constexpr double kBytesPerTexel = 20;
constexpr double kNsPerTexel = 500;

}  // namespace

double FullMeshTriangles(const TreeCounts& counts) {
  return counts.bark_indices / 3 + kLeafTriangles * counts.leaves +
         kFlowerTriangles * counts.flowers;
}

Estimate EstimateLodExport(const TreeCounts& counts, long max_triangles, bool lod, int atlas_size) {
  const double full = FullMeshTriangles(counts);
  if (!lod && (max_triangles < 0 || static_cast<double>(max_triangles) >= full)) {
    return EstimateTreeExport(counts, TreeExport::kGlb);  // the full mesh as it is
  }
  const int levels = lod ? 3 : 1;
  double texels = 0;
  for (int k = 0; k < levels; ++k) {
    const double side = std::max(256, atlas_size >> k);
    texels += side * side;
  }
  Estimate e;
  e.memory_bytes =
      kBytesPerTriangle * full * (lod ? kLodMemoryFactor : 1.0) + kBytesPerTexel * texels;
  e.seconds = (kNsPerTriangleLevel * full * levels + kNsPerTexel * texels) * 1e-9;
  e.what = std::string(lod ? "building the three LOD levels" : "building the level") + " of the " +
           FormatCount(full) + " triangles of the full mesh for the .glb";
  return e;
}

}  // namespace niwa
