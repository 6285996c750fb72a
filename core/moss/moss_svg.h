// The moss study's photon picture (figs 4.1/4.2's right halves): the land's soil cells in
// perspective from the open side (+z), a little above and to the right (the viewpoint of
// scripts/figures moss's pictures of the mosses, scaled to the land's bounds), shaded by how they
// face the viewer, and the stored photons as dots, first hits (depth 0) in one colour and
// bounced photons in another, painted back to front. Does not: trace photons (photons.h), draw
// mosses or write files.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "moss/photons.h"
#include "moss/soil_cells.h"

namespace niwa::moss {

// The camera: its eye and the point it looks at, in the land's frame.
struct PhotonView {
  glm::dvec3 eye;
  glm::dvec3 at;
};

// The picture's camera for a land: on the thesis scene, the figures' (scripts/lib/figures_moss.js).
PhotonView PhotonViewOf(const SoilCells& cells);

// The SVG text; `title` (escaped) is written as the picture's title and caption.
std::string PhotonSvg(const SoilCells& cells, const PhotonMap& map, const std::string& title);

}  // namespace niwa::moss
