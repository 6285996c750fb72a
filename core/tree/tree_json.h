// JSON of a whole tree (format "niwa-tree-1"): settings, parameters and every living branch.
// Does not: read trees back, or write parameter JSON alone (params/param_json).
#pragma once

#include <string>

#include "tree/tree.h"

namespace niwa {

// The whole tree: settings, parameters and every branch with its internodes, buds, leaves and
// flowers.
std::string TreeToJson(const Tree& tree);

}  // namespace niwa
