// A grown tree's bark as a plain geom::TriMesh (metres, y up) with a seed point at the trunk foot:
// what a climbing-plant study (ivy, paper 004) climbs when it grows on a Niwa tree. Part of the
// composition tier (core/compose may include studies; no study includes it): compose/ivy_on_tree
// turns it into the ivy's support, for the CLI and the ivy page alike, within the same budget as
// `niwa tree grow` (issue 16). Does not: know any climbing plant, add leaves or flowers to the
// support (ivy climbs bark only), or build the climber's BVH.
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <string>

#include "base/budget.h"
#include "base/status.h"
#include "geom/tri_mesh.h"
#include "tree/mesh.h"

namespace niwa::compose {

struct BarkSupport {
  geom::TriMesh mesh;     // the bark tubes (positions and normals in metres)
  glm::dvec3 trunk_seed;  // the bark point nearest to (0, 0.05, 0.001): the +z side of the foot
  std::string description;
  // The tree's growth stopped early at a limit of the budget: its line ("--max-memory: stopped in
  // year 31 of 100: ..."), else "".
  std::string truncated_by;
  // Growing the tree and building its bark (the tree, its mesh, the TriMesh and the seed's BVH at
  // once; what stays held afterwards is `mesh` alone).
  Estimate estimate;
};

// What the tree may use: the budget (its --max-memory / --max-seconds, shared with the climber)
// and what its lines tell the user to lower.
struct BarkBudget {
  Budget budget;
  std::string years_name = "tree_years";  // the CLI: "--tree-years"
};

// The bark buffers of BuildTreeMesh as one TriMesh.
geom::TriMesh BarkTriMesh(const MeshBuffers& bark);

// Grows tree preset `preset` (seed and parameters of the preset) for `years` years and returns its
// bark. Errors name "tree" (an unknown preset, with the list) or "tree_years" (not a whole number
// in [1, kMaxYears], or a tree with no bark); callers rename them to their flags. With a budget,
// the tree grows under `niwa tree grow`'s limits (TreeGrowLimits) with its bark mesh held per
// alive internode, so it stops (truncated_by) where the bark still fits; the grown bark's estimate
// is then checked, and a bark beyond the budget is refused with the line naming the limit
// (field budget.memory_limit or budget.seconds_limit) before the mesh is built.
// on_stage (optional): called after every year ("tree", year, years) and before the bark is built
// ("bark", 0, internodes), so a page's progress line moves through a long tree (issue 31 item 7).
using BarkProgress = std::function<void(const char* stage, double done, double total)>;
Result<BarkSupport> GrowBarkSupport(const std::string& preset, double years,
                                    const BarkBudget* budget = nullptr,
                                    const BarkProgress& on_stage = {});

}  // namespace niwa::compose
