// Procedural RGBA8 textures of the tree's exported materials (bark, leaf, flower), as
// image::Rgba8Image (row 0 is texture coordinate v = 0, glTF's top-left origin; PNG encoding is
// image/png.h). Deterministic: integer hashing and det:: math only, so the native and WASM builds
// give the same pixels. Does not: encode files, or texture anything but the tree's glTF materials.
#pragma once

#include "image/image.h"

namespace niwa {

using image::Rgba8Image;

// Bark: brown with vertical furrows, opaque, tileable in u (around the tube) and in v (along it).
// One repeat spans u 0..1 (the whole circumference) and v 0..1 (one metre of wood).
Rgba8Image MakeBarkTexture(int width = 128, int height = 256);

// Leaf blade in the leaf quad's UV space: u across (midrib at u = 0.5), v from the base (v = 0) to
// the tip (v = 1); green with a lighter midrib and veins; alpha 0 outside the silhouette.
Rgba8Image MakeLeafTexture(int width = 128, int height = 128);

// Five pink petals around (0.5, 0.5) (petal tips at angles 0°, 72°, ... as in the flower mesh),
// with a darker centre; alpha 0 between and outside the petals.
Rgba8Image MakeFlowerTexture(int size = 64);

}  // namespace niwa
