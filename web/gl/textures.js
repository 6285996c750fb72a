// Data textures read with texelFetch: sway pose textures (shaders/common/skin.glsl's layout) and
// generic rows-of-1024-texels data textures for per-segment arrays; and the one upload of an RGBA8
// image (the core's procedural textures) with mipmaps.
// Does not: manage texture units, or know what the data mean beyond their layout.

// Sway poses (core/sway/skin.h): 16 floats = 4 RGBA32F texels per node point, rows of 1024 texels.
export const POSE_TEXELS = 4;
export const POSE_ROW = 1024;
export const DATA_ROW = 1024;

// Identity poses for `points` node points (the grown shape exactly).
export function restPoses(points) {
  const rest = new Float32Array(Math.max(1, points) * 16);
  for (let i = 0; i < rest.length; i += 16) {
    rest[i] = 1;
    rest[i + 5] = 1;
    rest[i + 10] = 1;
  }
  return rest;
}

// Uploads sway poses of `points` node points into `texture`, straight from the array (no padded
// copy); the texture is reallocated when its row count (`rows`, as last returned) changes.
// Returns the rows.
export function uploadPoses(gl, texture, poses, points, rows) {
  const needed = Math.max(1, Math.ceil((points * POSE_TEXELS) / POSE_ROW));
  gl.bindTexture(gl.TEXTURE_2D, texture);
  if (rows !== needed) {
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, POSE_ROW, needed, 0, gl.RGBA, gl.FLOAT, null);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  }
  const texels = Math.min(points * POSE_TEXELS, Math.floor(poses.length / 4));
  const full = Math.floor(texels / POSE_ROW), rest = texels - full * POSE_ROW;
  if (full > 0) gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, POSE_ROW, full, gl.RGBA, gl.FLOAT, poses.subarray(0, full * POSE_ROW * 4));
  if (rest > 0) gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, full, rest, 1, gl.RGBA, gl.FLOAT, poses.subarray(full * POSE_ROW * 4, texels * 4));
  gl.bindTexture(gl.TEXTURE_2D, null);
  return needed;
}

// A texture of `data` (a typed array of `comps` values per texel) in rows of DATA_ROW texels,
// uploaded straight from the array (no padding copy), for texelFetch in a vertex shader.
export function dataTexture(gl, data, comps, internalFormat, format, type) {
  const texels = data.length / comps;
  const rows = Math.floor(texels / DATA_ROW), rest = texels - rows * DATA_ROW;
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texStorage2D(gl.TEXTURE_2D, 1, internalFormat, DATA_ROW, rows + (rest > 0 ? 1 : 0) || 1);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  if (rows > 0) gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, DATA_ROW, rows, format, type, data.subarray(0, rows * DATA_ROW * comps));
  if (rest > 0) gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, rows, rest, 1, format, type, data.subarray(rows * DATA_ROW * comps));
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return texture;
}

// An RGBA8 image `{width, height, pixels}` (tightly packed rows) into `texture` (a new one when
// absent), with mipmaps, trilinear filtering and `wrap` on both axes; returns the texture. pixels:
// an ArrayBuffer or a view (read in place: a worker reply's view may sit in a bigger buffer).
export function imageTexture(gl, image, wrap, texture = gl.createTexture()) {
  const p = image.pixels;
  const bytes = ArrayBuffer.isView(p) ? new Uint8Array(p.buffer, p.byteOffset, p.byteLength) : new Uint8Array(p);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, image.width, image.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
  gl.generateMipmap(gl.TEXTURE_2D);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wrap);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wrap);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return texture;
}
