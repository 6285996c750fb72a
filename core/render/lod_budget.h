// Memory and time of the game-ready exports (core/render/tree_lod: BuildLodMesh, BuildLodLevels and
// WriteLodGlb), estimated from the full mesh's triangles before the work starts (issue 16,
// docs/budgets.md). Does not: build any level or measure anything (counts times constants measured
// natively and in WASM, so both builds refuse at the same point).
#pragma once

#include "base/budget.h"
#include "tree/tree_budget.h"

namespace niwa {

// Triangles of the full BuildTreeMesh of a tree with these counts (bark, 4 a leaf, 20 a flower):
// FullTriangles(BuildTreeMesh(tree)) without building it.
double FullMeshTriangles(const TreeCounts& counts);

// The game-ready .glb within `max_triangles` (< 0: the full mesh's) and, with `lod`, its three
// levels: every level builds the full mesh, up to ten leaf-cluster scenes and its card atlas
// (`atlas_size` texels a side, half and a quarter for LOD1 and LOD2), then the .glb is written
// with the atlases as PNG. A single level whose budget holds the full mesh is the plain .glb's
// work. Does not include the grown tree (add its own estimate).
Estimate EstimateLodExport(const TreeCounts& counts, long max_triangles, bool lod,
                           int atlas_size = 2048);

}  // namespace niwa
