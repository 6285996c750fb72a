// Writes the hand-made test meshes of tests/data/meshes (run by hand: node tests/data/meshes/make_meshes.mjs;
// the outputs are committed). Each file's expected contents are computed by hand in tests/io/gltf_reader_test.cpp.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import draco3d from 'draco3d';
import { pngBytes } from '../../support/png_bytes.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const FLOAT = 5126, U16 = 5123, U32 = 5125;

// A small glTF builder: one binary buffer, tightly packed views, 4-byte aligned.
class Gltf {
  constructor() {
    this.json = { asset: { version: '2.0', generator: 'niwa tests/data/meshes/make_meshes.mjs' },
      buffers: [], bufferViews: [], accessors: [], meshes: [], nodes: [], scenes: [], scene: 0 };
    this.parts = [];
    this.length = 0;
  }
  view(bytes) {
    const pad = (4 - (this.length % 4)) % 4;
    if (pad) { this.parts.push(new Uint8Array(pad)); this.length += pad; }
    this.json.bufferViews.push({ buffer: 0, byteOffset: this.length, byteLength: bytes.byteLength });
    this.parts.push(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength));
    this.length += bytes.byteLength;
    return this.json.bufferViews.length - 1;
  }
  accessor(array, componentType, type, extra = {}) {
    const n = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 }[type];
    const a = { bufferView: this.view(array), componentType, count: array.length / n, type, ...extra };
    this.json.accessors.push(a);
    return this.json.accessors.length - 1;
  }
  positions(list) {
    const f = new Float32Array(list);
    const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < f.length; i++) {
      min[i % 3] = Math.min(min[i % 3], f[i]);
      max[i % 3] = Math.max(max[i % 3], f[i]);
    }
    const finite = min.every(Number.isFinite) && max.every(Number.isFinite);
    return this.accessor(f, FLOAT, 'VEC3', finite ? { min, max } : {});
  }
  normals(list) { return this.accessor(new Float32Array(list), FLOAT, 'VEC3'); }
  indices(list) {
    const big = list.some((i) => i > 65535);
    return this.accessor(big ? new Uint32Array(list) : new Uint16Array(list), big ? U32 : U16, 'SCALAR');
  }
  mesh(name, primitives) { this.json.meshes.push({ name, primitives }); return this.json.meshes.length - 1; }
  node(n) { this.json.nodes.push(n); return this.json.nodes.length - 1; }
  bin() {
    const out = new Uint8Array(this.length);
    let o = 0;
    for (const p of this.parts) { out.set(p, o); o += p.byteLength; }
    return out;
  }
  glb() {
    const bin = this.bin();
    this.json.buffers = [{ byteLength: bin.byteLength }];
    return glb(this.json, bin);
  }
  gltf(uri) {
    const bin = this.bin();
    this.json.buffers = [{ byteLength: bin.byteLength, uri: uri ?? 'data:application/octet-stream;base64,' + Buffer.from(bin).toString('base64') }];
    return { text: JSON.stringify(this.json, null, 1) + '\n', bin };
  }
}

function glb(json, bin) {
  const pad = (b, fill) => { const n = (4 - (b.length % 4)) % 4; return Buffer.concat([b, Buffer.alloc(n, fill)]); };
  const j = pad(Buffer.from(JSON.stringify(json)), 0x20);
  const b = pad(Buffer.from(bin), 0);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + j.length + (b.length ? 8 + b.length : 0), 8);
  const jh = Buffer.alloc(8); jh.writeUInt32LE(j.length, 0); jh.writeUInt32LE(0x4e4f534a, 4);
  const parts = [header, jh, j];
  if (b.length) { const bh = Buffer.alloc(8); bh.writeUInt32LE(b.length, 0); bh.writeUInt32LE(0x004e4942, 4); parts.push(bh, b); }
  return Buffer.concat(parts);
}

function write(name, bytes) {
  fs.writeFileSync(path.join(here, name), bytes);
  console.log(name, bytes.length, 'bytes');
}

// A unit right triangle in z = 0 facing +z.
function addTri(g) {
  const pos = g.positions([0, 0, 0, 1, 0, 0, 0, 1, 0]);
  const nrm = g.normals([0, 0, 1, 0, 0, 1, 0, 0, 1]);
  return g.mesh('tri', [{ attributes: { POSITION: pos, NORMAL: nrm }, indices: g.indices([0, 1, 2]) }]);
}

// hierarchy.glb: scene 1 is the default (scene 0 holds a decoy), nodes use TRS, a matrix, a mirror, a strip,
// a fan, a degenerate triangle, a POINTS primitive and a non-uniform scale of a slanted triangle.
{
  const g = new Gltf();
  const tri = addTri(g);
  const quad = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0];
  const up4 = [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1];
  const strip = g.mesh('strip', [{ attributes: { POSITION: g.positions(quad), NORMAL: g.normals(up4) }, mode: 5 }]);
  const fanPos = g.positions([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
  const fan = g.mesh('fan', [{ attributes: { POSITION: fanPos, NORMAL: g.normals(up4) }, indices: g.indices([0, 1, 2, 3]), mode: 6 }]);
  const mixedPos = g.positions([0, 0, 0, 1, 0, 0, 0, 0, 1, 2, 0, 0]);
  const mixedNrm = g.normals([0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0]);
  const mixed = g.mesh('mixed', [
    { attributes: { POSITION: mixedPos, NORMAL: mixedNrm }, indices: g.indices([0, 1, 2, 0, 1, 3]) },
    { attributes: { POSITION: mixedPos }, mode: 0 },
  ]);
  const s = 1 / Math.sqrt(3);
  const slanted = g.mesh('slanted', [{ attributes: { POSITION: g.positions([1, 0, 0, 0, 1, 0, 0, 0, 1]),
    NORMAL: g.normals([s, s, s, s, s, s, s, s, s]) } }]);
  const h = Math.SQRT1_2;
  g.node({ name: 'root', translation: [10, 0, 0], children: [1, 3, 4, 5] });          // 0
  g.node({ name: 'rotated', rotation: [0, 0, h, h], mesh: tri, children: [2] });      // 1: 90 degrees about +z
  g.node({ name: 'scaled', translation: [0, 0, 1], scale: [2, 3, 4], mesh: tri });    // 2
  g.node({ name: 'matrix', matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 5, 0, 1], mesh: strip });  // 3
  g.node({ name: 'mirror', translation: [0, -5, 0], scale: [-1, 1, 1], mesh: tri });  // 4
  g.node({ name: 'fan', translation: [0, 0, -3], mesh: fan });                        // 5
  g.node({ name: 'mixed', translation: [0, 10, 0], mesh: mixed });                    // 6
  g.node({ name: 'decoy', translation: [100, 100, 100], mesh: tri });                 // 7
  g.node({ name: 'squash', translation: [0, 0, 20], scale: [1, 1, 2], mesh: slanted }); // 8
  g.json.scenes = [{ name: 'decoy', nodes: [7] }, { name: 'main', nodes: [0, 6, 8] }];
  g.json.scene = 1;
  write('hierarchy.glb', g.glb());
}

// embedded.gltf (data: URI buffer), external.gltf + external.bin, missing_bin.gltf: the triangle at (1, 2, 3).
for (const [name, uri] of [['embedded.gltf', undefined], ['external.gltf', 'external.bin'], ['missing_bin.gltf', 'no_such_file.bin']]) {
  const g = new Gltf();
  g.node({ name: 'moved', translation: [1, 2, 3], mesh: addTri(g) });
  g.json.scenes = [{ nodes: [0] }];
  const { text, bin } = g.gltf(uri);
  write(name, text);
  if (uri === 'external.bin') write('external.bin', bin);
}

// draco.glb and its uncompressed twin draco_twin.glb: a 7 x 7 grid of heights (72 triangles) under a node
// with translation and scale. Draco without quantization keeps the float positions exactly.
{
  const n = 7, pos = [], idx = [];
  for (let y = 0; y < n; y++) for (let x = 0; x < n; x++) pos.push(x * 0.25, ((x * 7 + y * 3) % 5) * 0.1, y * 0.25);
  for (let y = 0; y + 1 < n; y++) for (let x = 0; x + 1 < n; x++) {
    const a = y * n + x, b = a + 1, c = a + n, d = c + 1;
    idx.push(a, c, b, b, c, d);
  }
  const node = { name: 'grid', translation: [0, 1, 0], scale: [0.5, 0.5, 0.5], mesh: 0 };
  const twin = new Gltf();
  twin.mesh('grid', [{ attributes: { POSITION: twin.positions(pos) }, indices: twin.indices(idx) }]);
  twin.node({ ...node });
  twin.json.scenes = [{ nodes: [0] }];
  write('draco_twin.glb', twin.glb());

  const enc = await draco3d.createEncoderModule({});
  const builder = new enc.MeshBuilder();
  const mesh = new enc.Mesh();
  builder.AddFacesToMesh(mesh, idx.length / 3, new Uint32Array(idx));
  const posId = builder.AddFloatAttributeToMesh(mesh, enc.POSITION, pos.length / 3, 3, new Float32Array(pos));
  const encoder = new enc.Encoder();
  encoder.SetEncodingMethod(enc.MESH_EDGEBREAKER_ENCODING);
  const out = new enc.DracoInt8Array();
  const len = encoder.EncodeMeshToDracoBuffer(mesh, out);
  if (len <= 0) throw new Error('Draco encoding failed');
  const drc = new Uint8Array(len);
  for (let i = 0; i < len; i++) drc[i] = out.GetValue(i) & 0xff;
  enc.destroy(out); enc.destroy(encoder); enc.destroy(mesh); enc.destroy(builder);

  const g = new Gltf();
  const view = g.view(drc);
  const min = [0, 0, 0], max = [(n - 1) * 0.25, 0.4, (n - 1) * 0.25];
  g.json.accessors.push({ componentType: FLOAT, count: pos.length / 3, type: 'VEC3', min, max });
  g.json.accessors.push({ componentType: U16, count: idx.length, type: 'SCALAR' });
  g.mesh('grid', [{ attributes: { POSITION: 0 }, indices: 1,
    extensions: { KHR_draco_mesh_compression: { bufferView: view, attributes: { POSITION: posId } } } }]);
  g.node({ ...node });
  g.json.scenes = [{ nodes: [0] }];
  g.json.extensionsUsed = ['KHR_draco_mesh_compression'];
  g.json.extensionsRequired = ['KHR_draco_mesh_compression'];
  write('draco.glb', g.glb());
}

// Hostile files.
write('empty.glb', Buffer.alloc(0));
{
  const whole = fs.readFileSync(path.join(here, 'hierarchy.glb'));
  write('truncated.glb', whole.subarray(0, Math.floor(whole.length * 0.6)));
}
write('not_gltf.glb', Buffer.from('This is a text file, not a mesh.\n'));
{
  const g = new Gltf();
  g.mesh('nan', [{ attributes: { POSITION: g.positions([0, 0, 0, NaN, 0, 0, 0, 1, 0]) } }]);
  g.node({ mesh: 0 });
  g.json.scenes = [{ nodes: [0] }];
  write('nan.glb', g.glb());
}
{
  const g = new Gltf();
  const p = g.positions([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]);
  g.mesh('wire', [{ attributes: { POSITION: p }, mode: 1 }, { attributes: { POSITION: p }, mode: 0 }]);
  g.node({ mesh: 0 });
  g.json.scenes = [{ nodes: [0] }];
  write('lines_only.glb', g.glb());
}
{
  const g = new Gltf();
  g.node({ mesh: addTri(g) });
  g.json.scenes = [{ nodes: [0] }];
  g.json.extensionsUsed = ['EXT_niwa_unknown'];
  g.json.extensionsRequired = ['EXT_niwa_unknown'];
  write('required_ext.glb', g.glb());
}
{
  // 4,000 nodes x 1,024 triangles = 4,096,000 > 4 M: refused before any vertex is read.
  const g = new Gltf();
  const w = 33, h = 17, pos = [], idx = [];  // 32 x 16 cells, 2 triangles each
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) pos.push(x, y, 0);
  for (let y = 0; y + 1 < h; y++) for (let x = 0; x + 1 < w; x++) {
    const a = y * w + x;
    idx.push(a, a + 1, a + w, a + 1, a + w + 1, a + w);
  }
  g.mesh('grid', [{ attributes: { POSITION: g.positions(pos) }, indices: g.indices(idx) }]);
  const roots = [];
  for (let i = 0; i < 4000; i++) roots.push(g.node({ mesh: 0 }));
  g.json.scenes = [{ nodes: roots }];
  write('too_many_triangles.glb', g.glb());
}
{
  const g = new Gltf();
  const tri = addTri(g);
  g.node({ mesh: tri, children: [1] });
  g.node({ mesh: tri, children: [0] });
  g.json.scenes = [{ nodes: [0] }];
  write('cycle.glb', g.glb());
}

// materials.glb: an obstacle material (name noivy_glass, extras.niwa_ivy false), a humus material with COLOR_0 as
// normalized unsigned bytes, and a mesh without a material.
{
  const g = new Gltf();
  const tri = [0, 0, 0, 1, 0, 0, 0, 1, 0];
  g.json.materials = [
    { name: 'noivy_glass', pbrMetallicRoughness: { baseColorFactor: [0.5, 0.625, 0.75, 0.875] }, extras: { niwa_ivy: false } },
    { name: 'humus' },
  ];
  g.mesh('glass', [{ attributes: { POSITION: g.positions(tri) }, material: 0 }]);
  const color = g.accessor(new Uint8Array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 51]), 5121, 'VEC4', { normalized: true });
  g.mesh('soil', [{ attributes: { POSITION: g.positions(tri), COLOR_0: color }, material: 1 }]);
  g.mesh('bare', [{ attributes: { POSITION: g.positions(tri) } }]);
  g.node({ mesh: 0 });
  g.node({ mesh: 1, translation: [0, 0, 1] });
  g.node({ mesh: 2, translation: [0, 0, 2] });
  g.json.scenes = [{ nodes: [0, 1, 2] }];
  write('materials.glb', g.glb());
}

// textured.glb: a 2 m square at y = 0 facing up (two triangles), u = (x + 1) / 2 and v = (z + 1) / 2, whose
// material 'ground' (no geology in its name, no factor) has a 2 x 1 PNG base colour texture: the left texel the
// thesis's humus colour #4A3322, the right one its sandy #C29A5B (moss: soil cells at x < 0 are humus, x > 0 sandy),
// clamped to the edge.
{
  const g = new Gltf();
  const pos = g.positions([-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1]);
  const nrm = g.normals([0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0]);
  const uv = g.accessor(new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]), FLOAT, 'VEC2');
  const png = pngBytes(2, 1, new Uint8Array([0x4a, 0x33, 0x22, 255, 0xc2, 0x9a, 0x5b, 255]));
  g.json.images = [{ name: 'humus_sand', bufferView: g.view(new Uint8Array(png)), mimeType: 'image/png' }];
  g.json.samplers = [{ magFilter: 9728, minFilter: 9728, wrapS: 33071, wrapT: 33071 }];
  g.json.textures = [{ source: 0, sampler: 0 }];
  g.json.materials = [{ name: 'ground', pbrMetallicRoughness: { baseColorTexture: { index: 0 }, metallicFactor: 0 } }];
  g.mesh('ground', [{ attributes: { POSITION: pos, NORMAL: nrm, TEXCOORD_0: uv }, indices: g.indices([0, 3, 2, 0, 2, 1]), material: 0 }]);
  g.node({ mesh: 0 });
  g.json.scenes = [{ nodes: [0] }];
  write('textured.glb', g.glb());
}

// OBJ: a unit cube's top as a quad (fan-triangulated), a pentagon with negative indices, the v/vt/vn forms.
write('shapes.obj', `# niwa test OBJ: a quad, a pentagon with negative indices, v/vt, v//vn and v/vt/vn corners
o quad
v 0 0 0
v 1 0 0
v 1 0 1
v 0 0 1
vt 0 0
vt 1 0
vt 1 1
vn 0 1 0
f 1/1 4/2 3/3 2/1
o pentagon
v 0 1 0
v 2 1 0
v 3 1 1
v 1 1 2
v -1 1 1
f -5//1 -4//1 -3//1 -2//1 -1//1
g tri
v 0 5 0
v 0 5 1
v 1 5 0
f 10/1/1 11/2/1 12/3/1
f 10 10 11
l 1 2
`);
write('bad_index.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n');
