// The spheres each cell of a uniform grid holds, as lists: the mosses' grid (photons.h
// MossOccluders) and the canopy's (canopy.h CanopyShade) both index spheres so. Does not: choose
// the grid (each caller sizes its cells), walk a ray through it, or test a sphere.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace niwa::moss {

// For count spheres (centre(i), radius(i)) and the grid of dims[0] × dims[1] × dims[2] cells of
// side `cell` from `lo` (cell (x, y, z) at k = (z·dims[1] + y)·dims[0] + x), the spheres whose box
// overlaps cell k are items[start[k] .. start[k + 1]), in index order. Reuses the arrays.
template <class Centre, class Radius>
void ListSpheresInCells(std::size_t count, Centre centre, Radius radius, const glm::dvec3& lo,
                        double cell, const int dims[3], std::vector<uint32_t>* start,
                        std::vector<uint32_t>* items) {
  const std::size_t n_cells = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  start->assign(n_cells + 1, 0);
  auto range = [&](const glm::dvec3& c, double r, int a, int* i0, int* i1) {
    *i0 = std::clamp(static_cast<int>(std::floor((c[a] - r - lo[a]) / cell)), 0, dims[a] - 1);
    *i1 = std::clamp(static_cast<int>(std::floor((c[a] + r - lo[a]) / cell)), 0, dims[a] - 1);
  };
  std::vector<uint32_t> fill;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t k = 0; k < n_cells; ++k) (*start)[k + 1] += (*start)[k];
      items->assign((*start)[n_cells], 0);
      fill.assign(start->begin(), start->end() - 1);
    }
    for (uint32_t s = 0; s < count; ++s) {
      const glm::dvec3& c = centre(s);
      const double r = radius(s);
      int x0, x1, y0, y1, z0, z1;
      range(c, r, 0, &x0, &x1);
      range(c, r, 1, &y0, &y1);
      range(c, r, 2, &z0, &z1);
      for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const std::size_t k = (static_cast<std::size_t>(z) * dims[1] + y) * dims[0] + x;
            if (pass == 0)
              ++(*start)[k + 1];
            else
              (*items)[fill[k]++] = s;
          }
    }
  }
}

}  // namespace niwa::moss
