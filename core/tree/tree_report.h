// What the tree study reports: the stats JSON (the CLI's --stats and the page's stats line) and the
// mappings CSV (tree mappings). Does not: grow or mesh the tree, or write files.
#pragma once

#include <string>
#include <vector>

#include "tree/growth.h"
#include "tree/mesh.h"

namespace niwa {

// The crown's form from the grown tree's node points (cm; docs/tree-species.md defines each).
struct TreeForm {
  double crown_width = 0;          // larger of the x and z extents of all living node points
  double crown_base_height = 0;    // height of the lowest node that carries a leaf (0: no leaves)
  double drooping_tips_share = 0;  // of the last year's living shoots, the share whose tip
                                   // internode points below the horizontal (0: no such shoots)
};

TreeForm ComputeTreeForm(const Tree& tree);

// What the page adds to the stats: the prunes to check once the tree is whole, and the mesh whose
// bounds frame the camera.
struct TreeStatsExtras {
  const std::vector<Prune>* idle_prunes = nullptr;  // listed as "idle_prunes" (when not null)
  const TreeMesh* mesh = nullptr;                   // its bounds as "bounds" (when not null)
};

// {preset, seed, years, internodes, branches, leaves, flowers, height (cm), truncated, ms,
// ms_light, ms_hormone, ms_branching, crown_width (cm), crown_base_height (cm),
// drooping_tips_share} plus, when given, idle_prunes ["prune 12:b40: why it cut
// nothing"] and bounds {min: [x, y, z], max: [x, y, z]} (metres) of the mesh. One line.
std::string TreeStatsJson(const Tree& tree, const GrowthTimings& timings,
                          const TreeStatsExtras& extras = {});

// "prune 12:b40: why" for each prune of the list that cut nothing from the grown tree.
std::vector<std::string> IdlePruneNotices(const std::vector<Prune>& prunes, const Tree& grown);

// The hormone- and age-dependent ranges of table 2.2 and figs. 2.5-2.9 as CSV, computed by the
// growth model's own functions (docs/growth-model.md plots them through scripts/figures).
std::string TreeMappingsCsv(const TreeParams& params);

}  // namespace niwa
