// The tree's "Getting started" group (issue 17 item 8): the few rows of the tree table that change
// a newcomer's tree the most, each with a plain-words name for what it does and one plain sentence,
// and the table JSON for the page with those two fields on the group's rows.
// Does not: change the table's rows, keys or thesis names (the full table keeps them), or know any
// page layout. The group lives here, beside the table, so the page holds no list of parameters.
#pragma once

#include <string>
#include <vector>

#include "tree/tree_params.h"

namespace niwa {

struct SimpleControl {
  TreeParam row;     // the table row the control edits
  const char* name;  // "Branchiness"
  const char* help;  // one plain sentence: what a larger value does
};

// The group, in table order.
const std::vector<SimpleControl>& TreeSimpleControls();

// ParamTableJson(TreeParamTable()) with "simple" (the name) and "simple_help" on the group's rows.
std::string TreeParamTableJsonWithSimple();

}  // namespace niwa
