// Shared shapes for the garden's .glb (issue 33 item 7: a 1,000-tree garden within 50 MB): trees of
// one variant grown with their neighbours' shade each differ a little (their crowns lean away from
// their neighbours), so each would be its own mesh; with `shapes` N the .glb keeps at most N meshes
// a variant and draws every such tree as the nearest of them, turned so its crown leans the tree's
// own way and scaled to the tree's height (docs/garden-model.md "Shared shapes"). Written here, not
// taken from a clustering library: the set is small (a variant's trees), the choice must be the
// same bytes natively and in WASM, and farthest-point picking with a nearest assignment is a few
// lines (tests/compose/garden_shapes_test.cpp checks it against a brute-force twin). Does not: grow
// or measure trees (garden_run), or write glTF.
#pragma once

#include <vector>

namespace niwa::compose {

// ---- data ----

// What a tree's shape is compared by (m): its height, its crown's reach from the trunk's axis and
// its lean (the leaves' centroid's horizontal distance from the trunk). The lean's direction is not
// compared: a shape is turned to point its lean the tree's way.
struct TreeShape {
  double height = 0;
  double reach = 0;
  double lean = 0;
};

// The scale a shared shape is drawn at: the tree's height over the shape's, kept within this
// factor either way (a closer shape than that is one more mesh's worth of bytes).
constexpr double kShapeScaleLimit = 1.25;

// ---- the choice ----

// Picks at most `n` (≥ 1) representatives among `shapes` and maps every shape to its nearest one.
// Distances are Euclidean in the set's own units (height over the mean height, reach and lean over
// the mean reach). The first representative is the shape nearest the set's mean, each next one
// the shape farthest from those picked (ties: the lower index); each shape then goes to its nearest
// representative (ties: the earlier picked). Returns, for each shape, the index of its
// representative (a representative maps to itself). Fewer than n + 1 shapes: every one its own.
std::vector<int> ShareShapes(const std::vector<TreeShape>& shapes, int n);

// The distance ShareShapes compares (exposed for its test's brute-force twin).
double ShapeDistance(const TreeShape& a, const TreeShape& b, double mean_height, double mean_reach);

}  // namespace niwa::compose
