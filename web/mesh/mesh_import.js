// Page-side mesh import: a dropped .glb/.gltf whose primitives use KHR_draco_mesh_compression is rewritten with those
// primitives decoded (Google's draco3d decoder, JS + WASM) into plain accessors, because the WASM core cannot link
// Draco; the result is bytes the core's io/gltf_reader reads. Does not: touch files without Draco, read external
// .bin/.png URIs (only the GLB chunk and data: URIs), keep Draco-compressed skin attributes (JOINTS_n/WEIGHTS_n are
// dropped: the core reads geometry only), or load the decoder module itself (the caller passes it in).

const DRACO = 'KHR_draco_mesh_compression';
const FLOAT = 5126;
const UNSIGNED_INT = 5125;
const TYPES = { 1: 'SCALAR', 2: 'VEC2', 3: 'VEC3', 4: 'VEC4' };
const GEOMETRY = /^(POSITION|NORMAL|TANGENT|TEXCOORD_\d+|COLOR_\d+)$/;

/** @param {Uint8Array} bytes @returns {boolean} */
export function isGlb(bytes) {
  return bytes.length >= 4 && bytes[0] === 0x67 && bytes[1] === 0x6c && bytes[2] === 0x54 && bytes[3] === 0x46;
}

/** Splits a .glb into its JSON and BIN chunk. @param {Uint8Array} bytes */
export function parseGlb(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (bytes.length < 20 || !isGlb(bytes)) throw new Error('not a .glb (magic glTF)');
  const total = view.getUint32(8, true);
  if (total > bytes.length) throw new Error(`truncated: the .glb header says ${total} bytes, the file has ${bytes.length}`);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  let bin = new Uint8Array(0);
  const at = 20 + jsonLength;
  if (at + 8 <= total && view.getUint32(at + 4, true) === 0x004e4942) {
    bin = bytes.subarray(at + 8, at + 8 + view.getUint32(at, true));
  }
  return { json, bin };
}

/** Joins JSON and a BIN chunk into a .glb. @returns {Uint8Array} */
export function buildGlb(json, bin) {
  let text = new TextEncoder().encode(JSON.stringify(json));
  const jsonPad = (4 - (text.length % 4)) % 4;
  const binPad = (4 - (bin.length % 4)) % 4;
  const binChunk = bin.length ? 8 + bin.length + binPad : 0;
  const out = new Uint8Array(12 + 8 + text.length + jsonPad + binChunk);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, out.length, true);
  view.setUint32(12, text.length + jsonPad, true);
  view.setUint32(16, 0x4e4f534a, true);
  out.set(text, 20);
  out.fill(0x20, 20 + text.length, 20 + text.length + jsonPad);
  if (bin.length) {
    const at = 20 + text.length + jsonPad;
    view.setUint32(at, bin.length + binPad, true);
    view.setUint32(at + 4, 0x004e4942, true);
    out.set(bin, at + 8);
  }
  return out;
}

/** Number of primitives that carry KHR_draco_mesh_compression. */
export function dracoPrimitiveCount(json) {
  let n = 0;
  for (const mesh of json.meshes ?? []) for (const p of mesh.primitives ?? []) if (p.extensions?.[DRACO]) n++;
  return n;
}

export function dataUriBytes(uri) {
  const comma = uri.indexOf(',');
  if (!uri.startsWith('data:') || comma < 0 || !uri.slice(0, comma).endsWith(';base64')) return null;
  const text = atob(uri.slice(comma + 1));
  const out = new Uint8Array(text.length);
  for (let i = 0; i < text.length; i++) out[i] = text.charCodeAt(i);
  return out;
}

function base64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

// The mesh readers' caps, as core/io/mesh_reader.h's kMaxMeshTriangles and kMaxMeshVertices (3 a triangle), which
// io::PreflightDracoHeader applies natively; tests/cli/mesh_import.test.mjs checks these against that header.
export const MAX_MESH_TRIANGLES = 4_000_000;
export const MAX_MESH_VERTICES = 3 * MAX_MESH_TRIANGLES;

// A Draco varint (7 bits a byte, low first, at most 5 bytes) at bytes[at.i]; null when cut short or longer.
function dracoVarint(bytes, at) {
  let out = 0;
  for (let shift = 0; shift < 35; shift += 7) {
    if (at.i >= bytes.length) return null;
    const c = bytes[at.i++] & 0xff;
    out += (c & 0x7f) * 2 ** shift;
    if ((c & 0x80) === 0) return out;
  }
  return null;
}

/**
 * The counts a Draco buffer's header declares, read as io::PreflightDracoHeader reads them: bitstream 2.2, a triangle
 * mesh, sequential (faces, points) or edgebreaker (traversal byte, points, faces), no metadata flag. Anything else
 * (another version, metadata, a point cloud, a cut header) gives null, and is left to Draco's own checks as natively.
 * @returns {{points: number, faces: number}|null}
 */
export function dracoHeaderCounts(bytes) {
  const b = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (b.length < 11 || String.fromCharCode(...b.subarray(0, 5)) !== 'DRACO') return null;
  const [major, minor, type, method] = [b[5], b[6], b[7], b[8]];
  const flags = b[9] | (b[10] << 8);
  if (major !== 2 || minor !== 2 || type !== 1 || (flags & 0x8000) !== 0) return null;
  const at = { i: 11 };
  if (method === 0) {
    const faces = dracoVarint(b, at), points = faces === null ? null : dracoVarint(b, at);
    return points === null ? null : { points, faces };
  }
  if (method === 1) {
    at.i += 1;
    const points = dracoVarint(b, at), faces = points === null ? null : dracoVarint(b, at);
    return faces === null ? null : { points, faces };
  }
  return null;
}

// Refuses a Draco buffer whose header declares more than the caps, before the decoder sizes anything (the native
// line, with the page's label).
function checkDracoHeader(bytes, label) {
  const counts = dracoHeaderCounts(bytes);
  if (counts && (counts.faces > MAX_MESH_TRIANGLES || counts.points > MAX_MESH_VERTICES)) {
    throw new Error(`${label}: the Draco data declares ${counts.points} vertices and ${counts.faces} triangles; ` +
      `the limits are ${MAX_MESH_VERTICES} and ${MAX_MESH_TRIANGLES}`);
  }
}

// Decodes one Draco buffer: every attribute as float32, the faces as uint32 triangles.
function decodeDraco(draco, bytes, attributeIds, label) {
  checkDracoHeader(bytes, label);
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  try {
    if (decoder.GetEncodedGeometryType(bytes) !== draco.TRIANGULAR_MESH) {
      throw new Error(`${label}: the Draco data is not a triangle mesh`);
    }
    const status = decoder.DecodeArrayToMesh(bytes, bytes.byteLength, mesh);
    if (!status.ok() || mesh.ptr === 0) throw new Error(`${label}: Draco cannot decode it (${status.error_msg()})`);
    const points = mesh.num_points();
    const faces = mesh.num_faces();
    const indexPtr = draco._malloc(faces * 12);
    decoder.GetTrianglesUInt32Array(mesh, faces * 12, indexPtr);
    const indices = new Uint32Array(draco.HEAPF32.buffer, indexPtr, faces * 3).slice();
    draco._free(indexPtr);
    const attributes = {};
    for (const [name, id] of Object.entries(attributeIds)) {
      const attribute = decoder.GetAttributeByUniqueId(mesh, id);
      if (!attribute || attribute.ptr === 0) throw new Error(`${label}: the Draco data has no attribute ${id} (${name})`);
      const components = attribute.num_components();
      const byteLength = points * components * 4;
      const ptr = draco._malloc(byteLength);
      decoder.GetAttributeDataArrayForAllPoints(mesh, attribute, draco.DT_FLOAT32, byteLength, ptr);
      attributes[name] = { components, values: new Float32Array(draco.HEAPF32.buffer, ptr, points * components).slice() };
      draco._free(ptr);
    }
    return { points, indices, attributes };
  } finally {
    draco.destroy(mesh);
    draco.destroy(decoder);
  }
}

/**
 * Rewrites a .glb/.gltf so that no primitive needs Draco. Files without Draco come back unchanged.
 * @param {ArrayBuffer|Uint8Array} input the dropped file's bytes
 * @param {{draco: object}} options draco: a module from draco3d.createDecoderModule()
 * @returns {{bytes: Uint8Array, kind: 'glb'|'gltf', dracoPrimitives: number}}
 */
export function importMesh(input, { draco }) {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const glb = isGlb(bytes);
  const { json, bin } = glb ? parseGlb(bytes) : { json: JSON.parse(new TextDecoder().decode(bytes)), bin: null };
  const count = dracoPrimitiveCount(json);
  if (count === 0) return { bytes, kind: glb ? 'glb' : 'gltf', dracoPrimitives: 0 };
  if (!draco) throw new Error(`${count} primitives need ${DRACO} and no Draco decoder was given`);

  const buffers = (json.buffers ?? []).map((b, i) => (glb && i === 0 && b.uri === undefined ? bin : b.uri ? dataUriBytes(b.uri) : null));
  const added = [];  // new bytes, 4-byte aligned, for the output buffer
  let addedLength = 0;
  const outBuffer = glb ? 0 : buffers.length;  // .glb: appended to the BIN chunk; .gltf: a new data: URI buffer
  const base = glb ? bin.length + ((4 - (bin.length % 4)) % 4) : 0;
  const addView = (typed) => {
    const pad = (4 - (addedLength % 4)) % 4;
    if (pad) { added.push(new Uint8Array(pad)); addedLength += pad; }
    json.bufferViews.push({ buffer: outBuffer, byteOffset: base + addedLength, byteLength: typed.byteLength });
    added.push(new Uint8Array(typed.buffer, typed.byteOffset, typed.byteLength));
    addedLength += typed.byteLength;
    return json.bufferViews.length - 1;
  };

  json.meshes.forEach((mesh, m) => mesh.primitives.forEach((p, k) => {
    const ext = p.extensions?.[DRACO];
    if (!ext) return;
    const label = `mesh ${m}${mesh.name ? ` '${mesh.name}'` : ''} primitive ${k}`;
    const view = json.bufferViews?.[ext.bufferView];
    const source = view && buffers[view.buffer ?? 0];
    if (!source) throw new Error(`${label}: the Draco buffer view ${ext.bufferView} is not in the file (external URI?)`);
    const start = view.byteOffset ?? 0;
    if (start + view.byteLength > source.length) throw new Error(`${label}: the Draco buffer view reads past the end of its buffer (truncated?)`);
    const decoded = decodeDraco(draco, new Int8Array(source.buffer, source.byteOffset + start, view.byteLength), ext.attributes ?? {}, label);
    const attributes = {};
    for (const [name, a] of Object.entries(decoded.attributes)) {
      if (!GEOMETRY.test(name)) continue;
      const accessor = { bufferView: addView(a.values), componentType: FLOAT, count: decoded.points, type: TYPES[a.components] };
      if (name === 'POSITION') {
        accessor.min = [Infinity, Infinity, Infinity];
        accessor.max = [-Infinity, -Infinity, -Infinity];
        for (let i = 0; i < a.values.length; i++) {
          accessor.min[i % 3] = Math.min(accessor.min[i % 3], a.values[i]);
          accessor.max[i % 3] = Math.max(accessor.max[i % 3], a.values[i]);
        }
      }
      json.accessors.push(accessor);
      attributes[name] = json.accessors.length - 1;
    }
    // Attributes outside the Draco data (allowed by the extension) stay as they were.
    for (const [name, id] of Object.entries(p.attributes)) if (!(name in ext.attributes) && GEOMETRY.test(name)) attributes[name] = id;
    p.attributes = attributes;
    json.accessors.push({ bufferView: addView(decoded.indices), componentType: UNSIGNED_INT, count: decoded.indices.length, type: 'SCALAR' });
    p.indices = json.accessors.length - 1;
    delete p.extensions[DRACO];
    if (Object.keys(p.extensions).length === 0) delete p.extensions;
  }));
  const drop = (list) => list?.filter((e) => e !== DRACO);
  json.extensionsUsed = drop(json.extensionsUsed);
  json.extensionsRequired = drop(json.extensionsRequired);
  if (!json.extensionsUsed?.length) delete json.extensionsUsed;
  if (!json.extensionsRequired?.length) delete json.extensionsRequired;

  const extra = new Uint8Array(addedLength);
  let o = 0;
  for (const part of added) { extra.set(part, o); o += part.length; }
  if (glb) {
    const merged = new Uint8Array(base + extra.length);
    merged.set(bin, 0);
    merged.set(extra, base);
    json.buffers = json.buffers?.length ? json.buffers : [{}];
    json.buffers[0].byteLength = merged.length;
    return { bytes: buildGlb(json, merged), kind: 'glb', dracoPrimitives: count };
  }
  json.buffers = json.buffers ?? [];
  json.buffers.push({ byteLength: extra.length, uri: `data:application/octet-stream;base64,${base64(extra)}` });
  return { bytes: new TextEncoder().encode(JSON.stringify(json)), kind: 'gltf', dracoPrimitives: count };
}
