// The moss study's photon picture (figs 4.1/4.2's right halves): the land's soil cells from the
// front and above (from +z at 31° elevation, orthographic: the thesis scene's open side), shaded by
// how they face the viewer, and the stored photons as dots, first hits (depth 0) in one colour and
// bounced photons in another, painted back to front. Does not: trace photons (photons.h), draw
// mosses or write files.
#pragma once

#include <string>

#include "moss/photons.h"
#include "moss/soil_cells.h"

namespace niwa::moss {

// The SVG text; `title` (escaped) is written as the picture's title and caption.
std::string PhotonSvg(const SoilCells& cells, const PhotonMap& map, const std::string& title);

}  // namespace niwa::moss
