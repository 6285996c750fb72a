// The ivy leaf's texture for the .glb: a 3-lobed Parthenocissus blade (the outline of
// ivy_mesh.cpp's leaf fans) with its midrib, lobe veins and side veins, lighter toward the
// petiole, alpha 255 inside the outline and 0 outside. Painted from the outline alone (no RNG, no
// libm): the same pixels natively and in WASM. Does not: decide where leaves go (ivy_mesh.cpp).
#pragma once

#include <utility>
#include <vector>

#include "base/status.h"
#include "image/image.h"

namespace niwa::ivy {

// The outline of a leaf of width 1: x across in [-0.5, 0.5], y from the petiole (0) to the tip
// (1), counter-clockwise.
const std::vector<std::pair<double, double>>& LeafOutlineUnit();

// Texture coordinates of leaf point (x, y) (width 1): u = x + 0.5, v = 1 - y (row 0 = the tip).
inline void LeafUv(double x, double y, float* u, float* v) {
  *u = static_cast<float>(x + 0.5);
  *v = static_cast<float>(1.0 - y);
}

// The size of the .glb's leaf texture (and the page's): 256 × 256 pixels.
constexpr int kLeafTextureSize = 256;

// The leaf texture, size × size pixels (size in 16..2048).
image::Rgba8Image PaintLeafTexture(int size);

// Its PNG bytes at 256 px, encoded once per process.
const Result<std::vector<unsigned char>>& LeafTexturePng();

}  // namespace niwa::ivy
