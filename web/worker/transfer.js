// Moving WASM buffers to the main thread: each typed view into WASM memory is copied ONCE into a
// fresh ArrayBuffer, which is then transferred (never copied a second time).
// Does not: keep views (they are only valid until the next call into WASM that may allocate).

// Copies one WASM-memory view into a fresh typed array of its own type; returns its buffer.
export function copyView(view) {
  const out = new view.constructor(view.length);
  out.set(view);
  return out.buffer;
}

// A session's named views ({name: typed view}, as the bindings' buffers(group) returns them) as
// {name: ArrayBuffer}; every buffer is pushed onto `transfer`. Copy before any other WASM call.
export function takeBuffers(views, transfer) {
  if (!views) throw new Error('no such buffer group');
  const out = {};
  for (const [name, view] of Object.entries(views)) {
    out[name] = copyView(view);
    transfer.push(out[name]);
  }
  return out;
}
