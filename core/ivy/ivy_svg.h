// Line drawings of a grown ivy as SVG, like the paper's Fig. 3: the internodes as strokes and the
// leaves as dots on the side opposite their sucker, over the support's triangles, orthographic,
// front (x-y) and side (z-y) views next to each other. Does not: shade, draw perspective views,
// or write files.
#pragma once

#include <string>

#include "geom/tri_mesh.h"
#include "ivy/ivy.h"
#include "ivy/ivy_params.h"

namespace niwa::ivy {

struct IvySvgOptions {
  int panel = 480;      // pixels per view (square)
  bool leaves = true;   // one dot per leaf
  int up_to_step = -1;  // draw only what was born at or before this step (-1: everything)
  std::string caption;  // optional text under the views
};

// Supports of more than kSvgMaxSupportTriangles triangles are drawn as a rasterised silhouette.
constexpr std::size_t kSvgMaxSupportTriangles = 20000;

std::string IvySvg(const IvyModel& model, const IvyParams& params, const geom::TriMesh* support,
                   const IvySvgOptions& options);

}  // namespace niwa::ivy
