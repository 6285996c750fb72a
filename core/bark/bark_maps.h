// The bark maps (../shared/specs/bark.md §1.9, with the relief of docs/bark-model.md item 9; Fig.
// 4 of paper 003 is not in our copy): the surface layer's plates (its triangles with three intact
// springs, at their deformed positions) drawn over the layer beneath (a crack shows the inner
// layer), with crack walls from the signed distance to the plates' outline, a bulge and curl per
// plate, as base colour, normal (tangent space, OpenGL: +y is up the image; with a fibre grain
// along the trunk), 16-bit height and occlusion/roughness/metallic (glTF's ORM packing), exactly
// tileable around and along the trunk (the lattice is a torus; every pixel and neighbour lookup
// wraps). Width a power of two in [256, 4096]; height the power of two nearest width·H/C (so texels
// are near square). The 4-layer model's maps (DrawLayeredMaps) show the visible layer: S's plates,
// and where S is cracked or peeled M1's plates, then M2's, then the inner layer, each in its
// palette (S grey-brown, M1 red-brown, M2 light tan). Does not: write files (image/png.h) or know a
// tree's UVs.
#pragma once

#include <string>

#include "bark/lattice.h"
#include "bark/regions.h"
#include "bark/springs.h"
#include "image/image.h"

namespace niwa::bark {

struct BarkMaps {
  image::Rgba8Image base_colour, normal, orm;
  image::Gray16Image height;  // 0 = top of the inner layer, 65535 = top of the surface (D)
  double texel_cm_x = 0, texel_cm_y = 0;
};

// The map height for a width and patch (power of two nearest width·height_cm/circumference_cm,
// within [256, 4096]).
int MapHeightPx(int width, double circumference_cm, double height_cm);
// The power of two in [lo, hi] nearest `want` by ratio (the smaller on a tie): MapHeightPx's rows,
// and the composition tier's narrow map widths (compose/bark_on_tree FitMapWidth).
int NearestPowerOfTwo(double want, int lo, int hi);

// A species' bark colours (sRGB fractions, before the grain, pillow and cavity shading): the
// plates' tops, the fresh cork of a crack's walls, the crack floor (the inner layer) and the grey
// old tops weather to.
struct BarkPalette {
  double plate[3], wall[3], floor[3], weathered[3];
};
// Read off photographs of each species' bark (docs/bark-model.md): camphor grey-brown plates in
// dark brown furrows, tallow light grey plates in grey-brown fissures, pine red-brown plates with
// orange cork in the walls; any other name gets the stylised palette every species had before.
BarkPalette SpeciesPalette(const std::string& species);

// Draws the maps of the surface at growth factors s_θ, s_z, for layer thickness D (cm), in a
// palette (default: the stylised one).
BarkMaps DrawBarkMaps(const Lattice& lattice, const Surface& surface, const CrackMeasures& cracks,
                      double s_theta, double s_z, double D, int width);
BarkMaps DrawBarkMaps(const Lattice& lattice, const Surface& surface, const CrackMeasures& cracks,
                      double s_theta, double s_z, double D, int width, const BarkPalette& palette);

// One layer of a layered drawing.
struct MapLayer {
  const Surface* surface = nullptr;
  const std::vector<int>* tri_region = nullptr;  // plate id of each triangle (MeasureCracks)
  double s_theta = 1;    // the layer's anchor scale around the trunk (its mid-radius / R_o)
  double top = 0;        // its top above the inner layer (cm)
  double thickness = 0;  // its radial thickness (cm)
  double colour[3] = {0, 0, 0};
};

// The maps of layers (outermost first) over the inner layer, at the axial growth factor s_z.
// The map spans the outermost layer's circumference (texel sizes from it); every layer is drawn
// by angle, so its plates sit over the same (i, j) of the others. Height 65535 = the outermost
// top; each layer is a solid from the inner layer up to its top, so the highest one shows.
BarkMaps DrawLayeredMaps(const Lattice& lattice, const std::vector<MapLayer>& layers, double s_z,
                         int width);
// The same with the walls, floor and weathering of a palette (the layers keep their colours).
BarkMaps DrawLayeredMaps(const Lattice& lattice, const std::vector<MapLayer>& layers, double s_z,
                         int width, const BarkPalette& palette);

}  // namespace niwa::bark
