// Orthographic side-view SVG of a tree, drawn like the thesis's line figures. Does not: draw
// meshes, perspective views or other studies.
#pragma once

#include <string>

#include "tree/tree.h"

namespace niwa {

struct SvgOptions {
  int width = 600, height = 600;  // pixels
  bool leaves = true, flowers = true;
  std::string caption;  // optional text under the tree
};

std::string TreeToSvg(const Tree& tree, const SvgOptions& options = {});

}  // namespace niwa
