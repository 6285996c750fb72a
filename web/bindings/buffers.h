// One generic named-buffer accessor for the bindings: a session hands JavaScript all typed views
// of one buffer group in one call ({positions: Float32Array, indices: Uint32Array, ...}), as
// Draco's GetAttributeDataArrayForAllPoints does, instead of one getter per buffer.
// Does not: copy (the views point into the WASM heap and are valid only until the next call that
// may allocate; web/worker/transfer.js copies each once), or own the vectors it views.
#pragma once

#include <emscripten/val.h>

#include <vector>

namespace niwa {

class NamedBuffers {
 public:
  // Adds `data` under `name` as a typed view of its element type (Float32Array for float,
  // Uint32Array for uint32_t, Int32Array for int32_t, Uint8Array for unsigned char).
  template <typename T>
  NamedBuffers& Add(const char* name, const std::vector<T>& data) {
    // The key is a C string: building the object allocates nothing on the WASM heap, so views
    // added earlier stay valid while later ones are added.
    object_.set(name, emscripten::val(emscripten::typed_memory_view(data.size(), data.data())));
    return *this;
  }

  // The JavaScript object of every view added.
  emscripten::val ToJs() const { return object_; }

 private:
  emscripten::val object_ = emscripten::val::object();
};

}  // namespace niwa
