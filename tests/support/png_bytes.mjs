// Builds PNG bytes for the tests that feed readers hand-made (often hostile) textures: 8-bit RGBA,
// one deflated IDAT, every chunk's CRC (node's zlib). Shared by tests/data/meshes/make_meshes.mjs
// and tests/cli.
import { crc32, deflateSync } from 'node:zlib';

function chunk(type, data) {
  const head = Buffer.alloc(8);
  head.writeUInt32BE(data.length, 0);
  head.write(type, 4, 'latin1');
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), data])) >>> 0, 0);
  return Buffer.concat([head, data, crc]);
}

// width x height RGBA pixels (rgba: width * height * 4 bytes, row 0 first). declared: the IHDR's
// {width, height} instead of the real ones (a lie, for hostile files: no pixel data then).
export function pngBytes(width, height, rgba, { declared = null } = {}) {
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(declared ? declared.width : width, 0);
  ihdr.writeUInt32BE(declared ? declared.height : height, 4);
  ihdr[8] = 8; ihdr[9] = 6;  // 8-bit RGBA
  const rows = Buffer.alloc(declared ? 0 : height * (1 + 4 * width));
  if (!declared) {
    for (let y = 0; y < height; ++y) {
      rows[y * (1 + 4 * width)] = 0;  // filter: none
      Buffer.from(rgba.subarray(4 * width * y, 4 * width * (y + 1))).copy(rows, y * (1 + 4 * width) + 1);
    }
  }
  return Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), chunk('IHDR', ihdr),
    chunk('IDAT', deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
}

// width x height 16-bit grey samples, value(x, y) in 0..65535 (row 0 first): a heightmap.
export function gray16PngBytes(width, height, value) {
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0);
  ihdr.writeUInt32BE(height, 4);
  ihdr[8] = 16; ihdr[9] = 0;  // 16-bit grey
  const rows = Buffer.alloc(height * (1 + 2 * width));
  for (let y = 0; y < height; ++y)
    for (let x = 0; x < width; ++x) rows.writeUInt16BE(value(x, y), y * (1 + 2 * width) + 1 + 2 * x);
  return Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), chunk('IHDR', ihdr),
    chunk('IDAT', deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
}

// A one-triangle glTF JSON whose material's baseColorTexture is image 0 at buffer view 1 (the
// image bytes after the triangle's 44): with glbBytes and triangleBin (glb_bytes.mjs) a textured
// .glb; `image` overrides the image entry (e.g. {uri: ...}), `source` the texture's image index.
export function texturedTriangleJson(imageLength, { image = null, source = 0 } = {}) {
  return {
    asset: { version: '2.0' }, buffers: [{ byteLength: 44 + imageLength }],
    bufferViews: [{ buffer: 0, byteLength: 36 }, { buffer: 0, byteOffset: 36, byteLength: 6 },
      { buffer: 0, byteOffset: 44, byteLength: imageLength }],
    accessors: [{ bufferView: 0, componentType: 5126, count: 3, type: 'VEC3' },
      { bufferView: 1, componentType: 5123, count: 3, type: 'SCALAR' }],
    images: [image ?? { bufferView: 2, mimeType: 'image/png' }], textures: [{ source }],
    materials: [{ name: 'ground', pbrMetallicRoughness: { baseColorTexture: { index: 0 } } }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1, material: 0 }] }],
    nodes: [{ mesh: 0 }], scenes: [{ nodes: [0] }],
  };
}
