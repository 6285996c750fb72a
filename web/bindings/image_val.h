// An RGBA image handed to JavaScript: {width, height, pixels: Uint8Array}, the pixels copied out of
// the WASM heap (so the object stays valid after the image is freed). Used by every binding that
// returns a texture (the tree's, the ivy's leaf, the simulated bark of a tree and of a garden
// tree). Does not: add a digest or any other key (the caller sets its own), or view the heap
// without copying (buffers.h does that for mesh buffers).
#pragma once

#include <emscripten/val.h>

#include "image/image.h"

namespace niwa {

inline emscripten::val ImageToJs(const image::Rgba8Image& image) {
  emscripten::val view(emscripten::typed_memory_view(image.pixels.size(), image.pixels.data()));
  emscripten::val out = emscripten::val::object();
  out.set("width", image.width);
  out.set("height", image.height);
  out.set("pixels", emscripten::val::global("Uint8Array").new_(view));  // a copy
  return out;
}

}  // namespace niwa
