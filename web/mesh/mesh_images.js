// A dropped glTF's base colour images as Blobs, for a page that draws the mesh with its own look
// (the ivy page: web/ivy/ivy_renderer.js setSupportMaterials decodes them, WebP included, with the
// browser's createImageBitmap, which the WASM core cannot: io/gltf_reader keeps a WebP without
// bytes). Only the images some material's baseColorTexture uses (its source, or EXT_texture_webp's,
// KHR_texture_basisu's or EXT_texture_avif's, as io/gltf_reader picks it), copied out of the file,
// so the file's bytes can go to the worker.
// Does not: decode images, read external files (a dropped file has none), or check the glTF (the
// core does; a malformed image reference is simply left out here).
import { dataUriBytes, isGlb, parseGlb } from './mesh_import.js';
import { extensionOf } from '../shell/file_drop.js';

const SOURCE_EXTENSIONS = ['EXT_texture_webp', 'KHR_texture_basisu', 'EXT_texture_avif'];

// The glTF image index a texture samples (io/gltf_reader's rule: `source`, else an extension's).
export function textureSource(texture) {
  if (Number.isInteger(texture?.source)) return texture.source;
  for (const ext of SOURCE_EXTENSIONS) {
    const source = texture?.extensions?.[ext]?.source;
    if (Number.isInteger(source)) return source;
  }
  return -1;
}

// Map from glTF image index to a Blob of its encoded bytes (type: its mimeType), for the images
// of the materials' baseColorTextures; an empty Map for an .obj or a file that is not glTF.
export function baseColorImages(bytes, name) {
  const out = new Map();
  if (extensionOf(name) === '.obj') return out;
  let json, bin = new Uint8Array(0);
  try {
    if (isGlb(bytes)) ({ json, bin } = parseGlb(bytes));
    else json = JSON.parse(new TextDecoder().decode(bytes));
  } catch {
    return out;
  }
  const wanted = new Set();
  for (const m of json.materials ?? []) {
    const t = m?.pbrMetallicRoughness?.baseColorTexture?.index;
    if (Number.isInteger(t)) wanted.add(textureSource(json.textures?.[t]));
  }
  for (const index of wanted) {
    const image = json.images?.[index];
    if (!image) continue;
    let data = null;
    if (Number.isInteger(image.bufferView)) {
      const view = json.bufferViews?.[image.bufferView];
      const buffer = json.buffers?.[view?.buffer];
      if (!view || !buffer) continue;
      const whole = buffer.uri === undefined ? bin : dataUriBytes(buffer.uri);
      const at = view.byteOffset ?? 0;
      if (!whole || at + view.byteLength > whole.length) continue;
      data = whole.subarray(at, at + view.byteLength);
    } else if (typeof image.uri === 'string') {
      data = dataUriBytes(image.uri);
    }
    if (data) out.set(index, new Blob([data], { type: image.mimeType || '' }));  // a copy
  }
  return out;
}
