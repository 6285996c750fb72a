// The bark maps (../shared/specs/bark.md §1.9; Fig. 4 of paper 003 is not in our copy): the
// surface layer's plates (its triangles with three intact springs, at their deformed positions)
// drawn over the layer beneath (a crack shows the inner layer), as base colour, normal (tangent
// space, OpenGL: +y is up the image), 16-bit height and occlusion/roughness/metallic (glTF's
// ORM packing), exactly tileable around and along the trunk (the lattice is a torus; every pixel
// and neighbour lookup wraps). Width a power of two in [256, 4096]; height the power of two
// nearest width·H/C (so texels are near square). Does not: write files (image/png.h), know a
// tree's UVs, or draw peeled layers (the 4-layer model).
#pragma once

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

// Draws the maps of the surface at growth factors s_θ, s_z, for layer thickness D (cm).
BarkMaps DrawBarkMaps(const Lattice& lattice, const Surface& surface, const CrackMeasures& cracks,
                      double s_theta, double s_z, double D, int width);

}  // namespace niwa::bark
