// A dropped or picked mesh file's bytes as the core reads them, for any study page that takes a
// mesh (ivy, moss): .obj as it is; .glb/.gltf with their Draco primitives decoded here (Google's
// draco3d decoder, loaded once on first need from /vendor/draco3d/; mesh_import.js rewrites them),
// since the WASM core cannot link Draco. A file that is not even glTF goes to the core as it is,
// which names what is wrong with it.
// sendMeshFile hands a file's bytes to a worker's 'mesh' message (moss and garden pages).
// Does not: parse meshes for the core, or show notices (the page does).
import { dracoPrimitiveCount, importMesh, isGlb, parseGlb } from './mesh_import.js';
import { extensionOf } from '../shell/file_drop.js';

let dracoModule = null;
function dracoDecoder() {
  if (!dracoModule) {
    dracoModule = new Promise((resolve, reject) => {
      const script = document.createElement('script');
      script.src = '/vendor/draco3d/draco_decoder_nodejs.js';
      script.onload = () => globalThis.DracoDecoderModule({
        locateFile: (file) => `/vendor/draco3d/${file}`,
      }).then(resolve, reject);
      script.onerror = () => reject(new Error('the Draco decoder could not be loaded'));
      document.head.append(script);
    });
  }
  return dracoModule;
}

// The bytes (Uint8Array) of `file` (a File) for the core; throws with a one-line message when a
// Draco primitive cannot be decoded.
export async function meshFileBytes(file) {
  let bytes = new Uint8Array(await file.arrayBuffer());
  if (extensionOf(file.name) !== '.obj') {
    let json = null;
    try {
      json = isGlb(bytes) ? parseGlb(bytes).json : JSON.parse(new TextDecoder().decode(bytes));
    } catch {
      json = null;
    }
    if (json && dracoPrimitiveCount(json) > 0) bytes = importMesh(bytes, { draco: await dracoDecoder() }).bytes;
  }
  return bytes;
}

// Reads `file` (meshFileBytes) and sends its bytes to `worker` as a 'mesh' request ({name, bytes},
// answered 'meshLoaded'), moved, not copied (a view on part of a buffer is cut out first). Returns
// {id, transferred} (transferred: the page's buffer is detached); throws with a one-line message
// when the file cannot be read (a Draco primitive that does not decode). `group`: the request's
// group (a newer request of the same group supersedes it; default 'mesh').
export async function sendMeshFile(worker, file, { group = 'mesh' } = {}) {
  const bytes = await meshFileBytes(file);
  const buffer = bytes.byteOffset === 0 && bytes.byteLength === bytes.buffer.byteLength ? bytes.buffer : bytes.slice().buffer;
  const request = worker.request('mesh', { name: file.name, bytes: buffer }, { group, done: ['meshLoaded'], transfer: [buffer] });
  return { id: request.id, transferred: buffer.byteLength === 0 };
}
