// Walking a grown tree's chain of terminal shoots (its trunk line), for the figure tests.
#pragma once

#include <cstddef>

#include "tree/tree.h"

namespace niwa {

// The living terminal shoot that continues shoot `id`, or -1 when there is none.
inline int LiveTerminalChild(const Tree& tree, int id) {
  int next = -1;
  for (int c : tree.branches[static_cast<std::size_t>(id)].children) {
    const Branch& child = tree.branches[static_cast<std::size_t>(c)];
    if (child.alive && child.kind == ShootKind::kTerminal) next = c;
  }
  return next;
}

}  // namespace niwa
