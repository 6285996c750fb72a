// GL buffers and vertex attributes: static buffers from the worker's ArrayBuffers, float and
// unsigned-int attributes (per vertex or per instance) on the bound vertex array, and typed views and
// copies of the worker's arrays (ArrayBuffers, or views of recycled ones).
// Does not: keep track of what it creates (callers delete their buffers) or know any mesh layout.

// A new STATIC_DRAW buffer holding `bytes`, left bound to `target`.
export function staticBuffer(gl, bytes, target = gl.ARRAY_BUFFER) {
  const b = gl.createBuffer();
  gl.bindBuffer(target, b);
  gl.bufferData(target, bytes, gl.STATIC_DRAW);
  return b;
}

// Attribute `location` of the bound VAO reads `size` floats per vertex (or per instance with a
// divisor) from buffer `b`.
export function floatAttribute(gl, location, b, size, stride = 0, offset = 0, divisor = 0) {
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  gl.enableVertexAttribArray(location);
  gl.vertexAttribPointer(location, size, gl.FLOAT, false, stride, offset);
  gl.vertexAttribDivisor(location, divisor);
}

// The same for unsigned ints (read as uint in the shader).
export function uintAttribute(gl, location, b, size, divisor = 0) {
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  gl.enableVertexAttribArray(location);
  gl.vertexAttribIPointer(location, size, gl.UNSIGNED_INT, 0, 0);
  gl.vertexAttribDivisor(location, divisor);
}

// `bytes` (an ArrayBuffer, or a view as the worker's recycled replies hold) read as a `Type` array,
// without copying: for data used at once, before the page hands the worker's buffers back.
export function viewOf(Type, bytes) {
  if (!ArrayBuffer.isView(bytes)) return new Type(bytes);
  return new Type(bytes.buffer, bytes.byteOffset, Math.floor(bytes.byteLength / Type.BYTES_PER_ELEMENT));
}

// A copy of `bytes` as a new `Type` array: for data a renderer keeps after the page hands the
// worker's buffers back (web/shell/worker_client.js recycle).
export function copyOf(Type, bytes) {
  return viewOf(Type, bytes).slice();
}
