// Procedural RGBA8 textures for the exported materials (bark, leaf, flower) and their PNG encoding.
// Deterministic: integer hashing and det:: math only, so the native and WASM builds give the same
// pixels and the same PNG bytes.
#pragma once

#include <cstdint>
#include <vector>

namespace niwa {

// Row-major RGBA8 pixels; row 0 is texture coordinate v = 0 (glTF's top-left origin).
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;  // 4 bytes per pixel
  const unsigned char* At(int x, int y) const {
    return pixels.data() + 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(x));
  }
};

// Bark: brown with vertical furrows, opaque, tileable in u (around the tube) and in v (along it).
// One repeat spans u 0..1 (the whole circumference) and v 0..1 (one metre of wood).
Rgba8Image MakeBarkTexture(int width = 128, int height = 256);

// Leaf blade in the leaf quad's UV space: u across (midrib at u = 0.5), v from the base (v = 0) to
// the tip (v = 1); green with a lighter midrib and veins; alpha 0 outside the silhouette.
Rgba8Image MakeLeafTexture(int width = 128, int height = 128);

// Five pink petals around (0.5, 0.5) (petal tips at angles 0°, 72°, ... as in the flower mesh),
// with a darker centre; alpha 0 between and outside the petals.
Rgba8Image MakeFlowerTexture(int size = 64);

// PNG file bytes (8-bit RGBA); empty if the image is empty or encoding failed.
std::vector<unsigned char> EncodePng(const Rgba8Image& image);

}  // namespace niwa
