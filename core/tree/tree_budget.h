// Memory and time budgets of the tree study (issue 16): the growth limits a Grower checks as it
// grows (stopping with Tree::truncated and a line naming the limit), and the estimates of the
// exports (.json, .glb, .svg, the page's mesh) from a grown tree's counts, made before the export
// starts. Does not: measure memory or wall-clock time (every figure is a count times a constant
// calibrated in docs/budgets.md, so native and WASM stop at the same point), grow or mesh trees.
#pragma once

#include <string>

#include "base/budget.h"
#include "tree/tree.h"
#include "tree/tree_params.h"

namespace niwa {

// What a Grower may use (unlimited when max_bytes and max_seconds are negative). The estimates,
// checked before each shoot is made: memory = base_bytes + bytes_per_branch · branches made +
// bytes_per_internode · internodes made (dead ones stay in memory; an internode's leaves and
// lateral buds are made with it); seconds = seconds_per_internode_year · Σ_years alive internodes
// + seconds_per_branch · branches made + seconds_per_internode · internodes made.
struct GrowLimits {
  double max_bytes = -1, max_seconds = -1;
  double base_bytes = 0, bytes_per_branch = 0, bytes_per_internode = 0;
  // Memory an output held alongside takes per alive internode (the page's mesh: 0 on the CLI,
  // whose exports are checked exactly once the tree has grown). Not part of Grower::estimate().
  double bytes_per_alive_internode = 0;
  double seconds_per_internode_year = 0, seconds_per_branch = 0, seconds_per_internode = 0;
  std::string memory_limit = "max_memory", seconds_limit = "max_seconds";
  std::string years_name = "years";  // what the lines tell the user to lower (the CLI: "--years")
  // Most alive internodes (-1: none), e.g. what the page can mesh and draw; named internode_limit.
  long max_internodes = -1;
  std::string internode_limit;
};

// The limits of growing `params` within `budget` (the per-internode costs depend on N, B_l, B_tl).
GrowLimits TreeGrowLimits(const TreeParams& params, const Budget& budget,
                          const std::string& years_name = "years");

// Bytes the page's mesh (TreeExport::kMesh) takes per internode of `params`: a typical tube's
// ring and every internode bearing this year's leaves. The page sets it as
// GrowLimits::bytes_per_alive_internode, so the growth stops where the mesh most likely still fits
// (the exact check of the grown tree's mesh still refuses the rest).
double MeshBytesPerInternode(const TreeParams& params);

enum class TreeExport {
  kJson,  // tree_json: TreeToJson
  kGlb,   // mesh + tree_gltf: BuildTreeMesh then WriteTreeGlb
  kSvg,   // tree_svg: TreeToSvg
  kMesh,  // the page: BuildTreeMesh, the sway skin and the buffers copied out of the heap
};

// The counts an export's size follows.
struct TreeCounts {
  double branches = 0, internodes = 0, buds = 0, leaves = 0, flowers = 0;  // alive only
  // The bark tubes' vertices and indices as tree/mesh sizes them (sides from each radius).
  double bark_vertices = 0, bark_indices = 0;
};
TreeCounts CountTree(const Tree& tree);

// Memory and time of one export of a grown tree (upper bounds; `what` names it, e.g. "writing
// the .json (1,234 internodes, ...)").
Estimate EstimateTreeExport(const TreeCounts& counts, TreeExport kind);

}  // namespace niwa
