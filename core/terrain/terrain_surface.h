// The page's flat buffers of a grown mountain: the heightfield as one vertex per cell (glTF's y-up
// (x, h, −y)), normals by central differences, the hypsometric tint and triangle indices, the
// contours as LINES at their elevations with height and level per vertex, and the summits. The
// worker copies them out of the WASM heap once (web/bindings/terrain_bindings.cpp); the same
// surface as terrain_output.h's .glb mesh (tests/terrain/terrain_surface_test.cpp), kept here so
// the page's regrow path runs, and is timed, in both builds (bench/terrain_workloads.cpp).
// Does not: grow, build the heightfield, encode a file or draw.
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/contour.h"
#include "terrain/heightfield.h"

namespace niwa::terrain {

struct SurfaceBuffers {
  // The surface: 3 floats per cell (row 0 north), and 6 indices per quad of four cells.
  std::vector<float> positions, normals, colours;
  std::vector<uint32_t> indices;
  int indices_width = -1, indices_height = -1;  // the grid `indices` was built for
  // The contours: two vertices per ring edge (3 floats each), and per vertex its height (m) and
  // level.
  std::vector<float> line_positions, line_height, line_level;
  // The summits: 3 floats each, and the inscribed-circle radius (m).
  std::vector<float> summit_positions, summit_radius;
};

// Fills `out` from the mountain and its heightfield, reusing its storage (a regrow on the same
// grid rebuilds no indices).
void BuildSurfaceBuffers(const Terrain& terrain, const Heightfield& hf, SurfaceBuffers* out);

}  // namespace niwa::terrain
