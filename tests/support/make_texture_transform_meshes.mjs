// Writes the small .glb files of tests/data/meshes that test KHR_texture_transform and a texCoord
// other than 0 in the base colour texture's sampling (run by hand: node
// tests/support/make_texture_transform_meshes.mjs; the outputs are committed). Each is
// textured.glb's 2 m square at y = 0 (two triangles, 4,096 soil cells) with its 2 x 1 texture (left
// texel the thesis's humus #4A3322, right its sandy #C29A5B); TEXCOORD_0 is u = (x + 1) / 2,
// v = (z + 1) / 2, TEXCOORD_1 (where given) u = (z + 1) / 2, v = (x + 1) / 2. The expected splits are
// worked out beside each file and checked in tests/moss/texture_geology_test.cpp:
//   texture_offset.glb    offset [0.25, 0], clamp: u' = u + 0.25, seam u' = 0.5 at x = -0.5
//   texture_scale.glb     scale [2, 1], repeat: u' = 2u, humus where frac(u') < 0.5: x in [-1, -0.5)
//                         and [0, 0.5)
//   texture_rotation.glb  rotation pi/2, clamp: u' = v (and v' = -u, clamped to the one row): the
//                         seam is z = 0
//   texture_texcoord1.glb textureInfo.texCoord 1, no transform: u = (z + 1) / 2, the seam is z = 0
//   texture_transform_texcoord1.glb  textureInfo.texCoord 0, KHR_texture_transform {texCoord 1,
//                         offset [0.25, 0]}: the extension's set wins, seam at z = -0.5
//   texture_missing_texcoord.glb (hostile) textureInfo.texCoord 1 on a primitive with TEXCOORD_0
//                         only: refused naming the material and TEXCOORD_1
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { pngBytes } from './png_bytes.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const out = path.join(here, '..', 'data', 'meshes');
const FLOAT = 5126, U16 = 5123;
const CLAMP = 33071, REPEAT = 10497;

// One .glb: the square with `uvSets` (TEXCOORD_0, TEXCOORD_1, ...), the texture sampled with
// `wrap`, and the material's baseColorTexture textureInfo `info`.
function squareGlb({ uvSets, wrap, info }) {
  const parts = [];
  let length = 0;
  const json = {
    asset: { version: '2.0', generator: 'niwa tests/support/make_texture_transform_meshes.mjs' },
    buffers: [], bufferViews: [], accessors: [], scene: 0,
  };
  const view = (bytes) => {
    const pad = (4 - (length % 4)) % 4;
    if (pad) { parts.push(new Uint8Array(pad)); length += pad; }
    json.bufferViews.push({ buffer: 0, byteOffset: length, byteLength: bytes.byteLength });
    parts.push(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength));
    length += bytes.byteLength;
    return json.bufferViews.length - 1;
  };
  const accessor = (array, componentType, type, extra = {}) => {
    const n = { SCALAR: 1, VEC2: 2, VEC3: 3 }[type];
    json.accessors.push({ bufferView: view(array), componentType, count: array.length / n, type, ...extra });
    return json.accessors.length - 1;
  };
  const attributes = {
    POSITION: accessor(new Float32Array([-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1]), FLOAT, 'VEC3', { min: [-1, 0, -1], max: [1, 0, 1] }),
    NORMAL: accessor(new Float32Array([0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0]), FLOAT, 'VEC3'),
  };
  uvSets.forEach((uvs, k) => { attributes[`TEXCOORD_${k}`] = accessor(new Float32Array(uvs), FLOAT, 'VEC2'); });
  const indices = accessor(new Uint16Array([0, 3, 2, 0, 2, 1]), U16, 'SCALAR');
  const png = pngBytes(2, 1, new Uint8Array([0x4a, 0x33, 0x22, 255, 0xc2, 0x9a, 0x5b, 255]));
  json.images = [{ name: 'humus_sand', bufferView: view(new Uint8Array(png)), mimeType: 'image/png' }];
  json.samplers = [{ magFilter: 9728, minFilter: 9728, wrapS: wrap, wrapT: wrap }];
  json.textures = [{ source: 0, sampler: 0 }];
  json.materials = [{ name: 'ground', pbrMetallicRoughness: { baseColorTexture: info, metallicFactor: 0 } }];
  if (info.extensions?.KHR_texture_transform) json.extensionsUsed = ['KHR_texture_transform'];
  json.meshes = [{ name: 'ground', primitives: [{ attributes, indices, material: 0 }] }];
  json.nodes = [{ mesh: 0 }];
  json.scenes = [{ nodes: [0] }];
  const bin = new Uint8Array(length);
  let o = 0;
  for (const p of parts) { bin.set(p, o); o += p.byteLength; }
  json.buffers = [{ byteLength: bin.byteLength }];
  const pad = (b, fill) => Buffer.concat([b, Buffer.alloc((4 - (b.length % 4)) % 4, fill)]);
  const j = pad(Buffer.from(JSON.stringify(json)), 0x20);
  const b = pad(Buffer.from(bin), 0);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + j.length + 8 + b.length, 8);
  const jh = Buffer.alloc(8); jh.writeUInt32LE(j.length, 0); jh.writeUInt32LE(0x4e4f534a, 4);
  const bh = Buffer.alloc(8); bh.writeUInt32LE(b.length, 0); bh.writeUInt32LE(0x004e4942, 4);
  return Buffer.concat([header, jh, j, bh, b]);
}

const uvX = [0, 0, 1, 0, 1, 1, 0, 1];  // TEXCOORD_0: u = (x + 1) / 2, v = (z + 1) / 2
const uvZ = [0, 0, 0, 1, 1, 1, 1, 0];  // TEXCOORD_1: u = (z + 1) / 2, v = (x + 1) / 2
const transform = (t) => ({ extensions: { KHR_texture_transform: t } });
const files = {
  'texture_offset.glb': { uvSets: [uvX], wrap: CLAMP, info: { index: 0, ...transform({ offset: [0.25, 0] }) } },
  'texture_scale.glb': { uvSets: [uvX], wrap: REPEAT, info: { index: 0, ...transform({ scale: [2, 1] }) } },
  'texture_rotation.glb': { uvSets: [uvX], wrap: CLAMP, info: { index: 0, ...transform({ rotation: Math.PI / 2 }) } },
  'texture_texcoord1.glb': { uvSets: [uvX, uvZ], wrap: CLAMP, info: { index: 0, texCoord: 1 } },
  'texture_transform_texcoord1.glb': { uvSets: [uvX, uvZ], wrap: CLAMP, info: { index: 0, texCoord: 0, ...transform({ texCoord: 1, offset: [0.25, 0] }) } },
  'texture_missing_texcoord.glb': { uvSets: [uvX], wrap: CLAMP, info: { index: 0, texCoord: 1 } },
};
for (const [name, spec] of Object.entries(files)) {
  fs.writeFileSync(path.join(out, name), squareGlb(spec));
  console.log(`wrote tests/data/meshes/${name}`);
}
