// The triangles of a terrain heightfield grid (width × height vertices, row 0 north), built on the
// page instead of sent by the worker: the same list as core/terrain/terrain_surface.cpp and the
// .glb's surface (two counter-clockwise triangles per quad seen from above: a, c, b and b, c, d
// with a = (i, j), b = (i + 1, j), c = (i, j + 1), d = (i + 1, j + 1)); tests/browser/terrain.test.mjs
// compares it with the downloaded .glb's indices. One grid size is kept, so a regrow on the same
// grid (every regrow at one res of one seed) reuses the buffer: 6 bytes·4 per cell not copied out
// of the WASM heap, not transferred, not rebuilt.
// Does not: draw, or know heights.

let cached = { width: -1, height: -1, buffer: null };

// An ArrayBuffer of Uint32 indices for a width × height grid (empty below 2 × 2).
export function gridIndices(width, height) {
  if (cached.width === width && cached.height === height) return cached.buffer;
  const quads = width >= 2 && height >= 2 ? (width - 1) * (height - 1) : 0;
  const out = new Uint32Array(quads * 6);
  let q = 0;
  for (let j = 0; j + 1 < height; ++j) {
    for (let i = 0; i + 1 < width; ++i) {
      const a = j * width + i, b = a + 1, c = a + width, d = c + 1;
      out[q++] = a;
      out[q++] = c;
      out[q++] = b;
      out[q++] = b;
      out[q++] = c;
      out[q++] = d;
    }
  }
  cached = { width, height, buffer: out.buffer };
  return out.buffer;
}
