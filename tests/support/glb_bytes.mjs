// Builds .glb bytes for the tests that feed readers hand-made (often hostile) files: the one copy of
// the container layout (GLB 2.0: a 12-byte header, a JSON chunk padded with spaces, an optional BIN
// chunk padded with zeros), shared by tests/cli and tests/browser.

// json: the JSON chunk's text; bin: the BIN chunk (none when empty); declaredLength: the header's
// total length (a lie, for hostile files) instead of the real one.
export function glbBytes(json, bin = Buffer.alloc(0), { declaredLength = null } = {}) {
  let text = Buffer.from(json);
  text = Buffer.concat([text, Buffer.alloc((4 - (text.length % 4)) % 4, 0x20)]);
  const body = Buffer.concat([bin, Buffer.alloc((4 - (bin.length % 4)) % 4, 0)]);
  const header = Buffer.alloc(20);
  header.writeUInt32LE(0x46546c67, 0);  // 'glTF'
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(declaredLength ?? 20 + text.length + (body.length ? 8 + body.length : 0), 8);
  header.writeUInt32LE(text.length, 12);
  header.writeUInt32LE(0x4e4f534a, 16);  // 'JSON'
  if (!body.length) return Buffer.concat([header, text]);
  const binHeader = Buffer.alloc(8);
  binHeader.writeUInt32LE(body.length, 0);
  binHeader.writeUInt32LE(0x004e4942, 4);  // 'BIN\0'
  return Buffer.concat([header, text, binHeader, body]);
}

// One triangle (3 float positions) and its three unsigned-short indices, the third i2 (44 bytes).
export function triangleBin(i2 = 2) {
  const b = Buffer.alloc(44);
  [0, 0, 0, 1, 0, 0, 0, 1, 0].forEach((v, i) => b.writeFloatLE(v, 4 * i));
  b.writeInt16LE(0, 36); b.writeInt16LE(1, 38); b.writeInt16LE(i2, 40);
  return b;
}

// Reads .glb bytes back: {json, bin} (the BIN chunk, empty when none), and `floats(accessor)` /
// `indices(accessor)`: an accessor's values as numbers (FLOAT, or UNSIGNED_BYTE/SHORT/INT
// indices; tightly packed or strided), for tests that measure what a page or the CLI wrote.
export function readGlb(bytes) {
  const buf = Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = buf.readUInt32LE(12);
  const json = JSON.parse(buf.subarray(20, 20 + jsonLength).toString('utf8'));
  const at = 20 + jsonLength;
  const bin = at + 8 <= buf.length ? buf.subarray(at + 8, at + 8 + buf.readUInt32LE(at)) : Buffer.alloc(0);
  const COMPONENTS = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };
  const READ = { 5126: [4, 'readFloatLE'], 5121: [1, 'readUInt8'], 5123: [2, 'readUInt16LE'], 5125: [4, 'readUInt32LE'] };
  const values = (index) => {
    const a = json.accessors[index];
    const view = json.bufferViews[a.bufferView];
    const n = COMPONENTS[a.type];
    const [size, read] = READ[a.componentType];
    const stride = view.byteStride || n * size;
    const start = (view.byteOffset || 0) + (a.byteOffset || 0);
    const out = new Array(a.count * n);
    for (let i = 0; i < a.count; ++i) {
      for (let c = 0; c < n; ++c) out[i * n + c] = bin[read](start + i * stride + c * size);
    }
    return out;
  };
  return { json, bin, floats: values, indices: values };
}
