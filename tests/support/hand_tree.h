// Test helper: trees built by hand, branch by branch (straight branches of equal internodes), for
// the sway and skinning tests that need a tree of known shape rather than a grown one.
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>

#include "tree/growth.h"

namespace niwa::testing {

// Adds a straight branch from the parent's node `parent_node` (or from `base` for the seedling)
// to `tip` with `segments` internodes, radius (cm) and `leaves` leaves (with a flower at its tip
// when `flower` and it has leaves). Returns its id.
inline int AddBranch(Tree* tree, int parent, int parent_node, glm::vec3 base, glm::vec3 tip,
                     int segments, float radius, int leaves = 0, bool flower = false) {
  Branch b{};
  b.id = static_cast<int>(tree->branches.size());
  b.parent = parent;
  b.parent_node = parent_node;
  b.alive = true;
  b.bud_direction = glm::vec3(0, 1, 0);
  b.azimuth = glm::vec3(1, 0, 0);
  if (parent >= 0)
    base = tree->branches[static_cast<std::size_t>(parent)]
               .nodes[static_cast<std::size_t>(parent_node)];
  for (int k = 0; k <= segments; ++k) {
    float f = static_cast<float>(k) / static_cast<float>(segments);
    b.nodes.push_back(base + (tip - base) * f);
  }
  b.cross_section = 3.14159265f * radius * radius;
  for (int k = 0; k < leaves; ++k) b.leaves.push_back(Leaf{1 + k % segments, glm::vec3(1, 0, 0)});
  if (flower && leaves > 0) b.flowers.push_back(segments);
  if (parent >= 0) tree->branches[static_cast<std::size_t>(parent)].children.push_back(b.id);
  tree->branches.push_back(b);
  return b.id;
}

}  // namespace niwa::testing
