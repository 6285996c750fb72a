// Which way a .glb's TANGENT frame turns a normal map's +Y, against the frame glTF viewers derive
// when a file has no TANGENT (used by the CLI tests of normal-mapped exports).
// glTF's normalTexture has +Y up the image and its uv origin at the image's top-left, so the map's
// +Y runs along -dP/dv. three.js' GLTFLoader says the same in code: without TANGENT it derives
// B = +dP/dv from screen-space derivatives and negates normalScale.y; with TANGENT its shader uses
// B = cross(N, T.xyz) * T.w as given (normal_vertex.glsl.js). A file whose tangents point B along
// +dP/dv therefore shows its bumps inverted (lit from the wrong side) in every engine reading TANGENT.
// Does not: check unit length or orthogonality (the tests do), read sparse or normalized accessors.

const SIZES = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };
const ARRAYS = { 5121: Uint8Array, 5123: Uint16Array, 5125: Uint32Array, 5126: Float32Array };

// The accessor's values as a typed array (copied out of the binary chunk `bin`, a Buffer).
export function accessorValues(json, bin, index) {
  const a = json.accessors[index];
  const view = json.bufferViews[a.bufferView];
  const Type = ARRAYS[a.componentType];
  const count = a.count * SIZES[a.type];
  const start = bin.byteOffset + (view.byteOffset || 0) + (a.byteOffset || 0);
  return new Type(bin.buffer.slice(start, start + count * Type.BYTES_PER_ELEMENT));
}

// For primitive `prim` (with TANGENT, NORMAL, POSITION and the normal texture's TEXCOORD_n):
// the triangles with a usable uv map, and how many of them have every corner's
// cross(N, T) * w on the -dP/dv side (glTF's map +Y) rather than the +dP/dv side.
export function mapUpAgreement(json, bin, prim) {
  const set = json.materials[prim.material].normalTexture.texCoord ?? 0;
  const p = accessorValues(json, bin, prim.attributes.POSITION);
  const n = accessorValues(json, bin, prim.attributes.NORMAL);
  const t = accessorValues(json, bin, prim.attributes.TANGENT);
  const uv = accessorValues(json, bin, prim.attributes[`TEXCOORD_${set}`]);
  const vertices = json.accessors[prim.attributes.POSITION].count;
  const indices = prim.indices !== undefined ? accessorValues(json, bin, prim.indices)
    : Uint32Array.from({ length: vertices }, (_, i) => i);
  let triangles = 0, agree = 0;
  for (let k = 0; k + 2 < indices.length; k += 3) {
    const [a, b, c] = [indices[k], indices[k + 1], indices[k + 2]];
    const e1 = [0, 1, 2].map((i) => p[3 * b + i] - p[3 * a + i]);
    const e2 = [0, 1, 2].map((i) => p[3 * c + i] - p[3 * a + i]);
    const du1 = uv[2 * b] - uv[2 * a], dv1 = uv[2 * b + 1] - uv[2 * a + 1];
    const du2 = uv[2 * c] - uv[2 * a], dv2 = uv[2 * c + 1] - uv[2 * a + 1];
    const det = du1 * dv2 - du2 * dv1;
    if (!(Math.abs(det) > 1e-12)) continue;
    const dPdv = [0, 1, 2].map((i) => (e2[i] * du1 - e1[i] * du2) / det);
    if (!(Math.hypot(...dPdv) > 0)) continue;
    triangles += 1;
    let ok = true;
    for (const v of [a, b, c]) {
      const [nx, ny, nz] = [n[3 * v], n[3 * v + 1], n[3 * v + 2]];
      const [tx, ty, tz, w] = [t[4 * v], t[4 * v + 1], t[4 * v + 2], t[4 * v + 3]];
      const up = [(ny * tz - nz * ty) * w, (nz * tx - nx * tz) * w, (nx * ty - ny * tx) * w];
      if (!(up[0] * dPdv[0] + up[1] * dPdv[1] + up[2] * dPdv[2] < 0)) ok = false;
    }
    if (ok) agree += 1;
  }
  return { triangles, agree };
}
