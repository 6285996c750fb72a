// GL buffers and vertex attributes: static buffers from the worker's ArrayBuffers, float and
// unsigned-int attributes (per vertex or per instance) on the bound vertex array.
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
