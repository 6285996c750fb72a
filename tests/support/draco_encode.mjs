// Draco test files made with npm draco3d's encoder (the decoder's twin): one triangle mesh's
// positions and faces as a Draco buffer (sequential or edgebreaker, positions unquantised so any
// float, NaN included, is kept), and a .glb whose one primitive needs KHR_draco_mesh_compression.
import draco3d from 'draco3d';
import { glbBytes } from './glb_bytes.mjs';

let encoderModule = null;

// positions: [x, y, z, ...] (floats, NaN allowed), indices: [a, b, c, ...]; method 'sequential' or 'edgebreaker'.
export async function encodeDracoMesh(positions, indices, method = 'sequential') {
  encoderModule ??= await draco3d.createEncoderModule({});
  const m = encoderModule;
  const encoder = new m.Encoder(), builder = new m.MeshBuilder(), mesh = new m.Mesh();
  const out = new m.DracoInt8Array();
  try {
    builder.AddFacesToMesh(mesh, indices.length / 3, new Uint32Array(indices));
    builder.AddFloatAttributeToMesh(mesh, m.POSITION, positions.length / 3, 3, new Float32Array(positions));
    encoder.SetSpeedOptions(5, 5);
    encoder.SetEncodingMethod(method === 'edgebreaker' ? m.MESH_EDGEBREAKER_ENCODING : m.MESH_SEQUENTIAL_ENCODING);
    const length = encoder.EncodeMeshToDracoBuffer(mesh, out);
    if (!(length > 0)) throw new Error('draco3d could not encode the mesh');
    const bytes = Buffer.alloc(length);
    for (let i = 0; i < length; ++i) bytes[i] = out.GetValue(i) & 0xff;
    return bytes;
  } finally {
    m.destroy(out);
    m.destroy(mesh);
    m.destroy(builder);
    m.destroy(encoder);
  }
}

// A .glb of one primitive whose POSITION (points) and faces are in the Draco buffer only.
export function dracoGlb(draco, points) {
  return glbBytes(JSON.stringify({
    asset: { version: '2.0' }, buffers: [{ byteLength: draco.length + ((4 - (draco.length % 4)) % 4) }],
    bufferViews: [{ buffer: 0, byteLength: draco.length }],
    accessors: [{ componentType: 5126, count: points, type: 'VEC3' }],
    extensionsUsed: ['KHR_draco_mesh_compression'], extensionsRequired: ['KHR_draco_mesh_compression'],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 },
      extensions: { KHR_draco_mesh_compression: { bufferView: 0, attributes: { POSITION: 0 } } } }] }],
    nodes: [{ mesh: 0 }], scenes: [{ nodes: [0] }] }), draco);
}
