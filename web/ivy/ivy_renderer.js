// The ivy page's WebGL2 view (shaders/ivy/): the support mesh (in stone grey, or a dropped glTF with
// its own look: each material's baseColorTexture, WebP included, decoded by the browser, its
// baseColorFactor and the vertex colours), the ivy's stems,
// leaves and suckers over it (the leaves textured with the .glb's own leaf texture, alpha-cut to
// its outline, when the worker has sent it; one flat green otherwise), and the seed points and (optionally) the buds A/D/Z as dots. Positions stay in the scene's units
// (px for the built-in scenes, metres for most assets); uModel scales the support into a view of
// about ten units so one orbit camera fits every scene. The step scrubber hides what was born after
// step k in the vertex shader (aBirth), so replaying the growth needs no regrow.
// A StudyLayer (web/gl/frame.js), a layer of a Frame (layerSteps, under the frame's camera and
// sun): fitted to a view of ten units in a Frame of fit: true (the ivy page, <niwa-ivy>), else in
// the frame's world (the scene's units times `unitScale`: beside other studies).
// Does not: talk to the worker, pick by id (a click is a ray in scene units; the worker's BVH
// answers it), or know the growth model.
import { floatAttribute, staticBuffer, viewOf } from '../gl/buffers.js';
import { uploadInParts } from '../gl/chunked_upload.js';
import { StudyLayer } from '../gl/frame.js';
import { loadPrograms } from '../gl/program.js';
import { imageTexture } from '../gl/textures.js';

const SHADERS = new URL('../../shaders/ivy/', import.meta.url);
const VIEW_SIZE = 10;  // the support's largest extent in view units

const COLORS = {
  support: { color: [0.64, 0.62, 0.58], variation: [0, 0, 0] },
  stems: { color: [0.36, 0.24, 0.13], variation: [0.06, 0.04, 0.02] },
  leaves: { color: [0.2, 0.5, 0.14], variation: [0.1, 0.16, 0.06] },
  suckers: { color: [0.55, 0.35, 0.2], variation: [0, 0, 0] },
};

// The drawn-triangle counter of a part: how many triangles (by their first vertex's birth step)
// were born at or before step k. Birth steps are whole numbers (core/ivy/ivy_mesh.h), so one pass
// makes cumulative counts per step (O(n); sorting 2 M triangle births was part of a long task);
// other values fall back to a sorted array and a binary search.
export function birthCounter(indices, birth) {
  const triangles = Math.floor(indices.length / 3);
  let maxStep = 0, whole = true;
  for (let t = 0; t < triangles && whole; ++t) {
    const b = birth[indices[3 * t]];
    if (!(b >= 0 && b <= 1e7 && Number.isInteger(b))) whole = false;
    else if (b > maxStep) maxStep = b;
  }
  if (whole) {
    const atMost = new Uint32Array(maxStep + 1);  // atMost[s]: triangles born at step <= s
    for (let t = 0; t < triangles; ++t) atMost[birth[indices[3 * t]]] += 1;
    for (let s = 1; s <= maxStep; ++s) atMost[s] += atMost[s - 1];
    return (k) => {
      if (!(k >= -0.5)) return 0;
      const s = Math.floor(k + 0.5);  // as the sorted search's b <= k + 0.5
      return s >= maxStep ? triangles : atMost[s];
    };
  }
  const sorted = new Float32Array(triangles);
  for (let t = 0; t < triangles; ++t) sorted[t] = birth[indices[3 * t]];
  sorted.sort();
  return (k) => {
    let lo = 0, hi = sorted.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (sorted[mid] <= k + 0.5) lo = mid + 1; else hi = mid;
    }
    return lo;
  };
}

export class IvyRenderer extends StudyLayer {
  // target: a canvas (the renderer makes its context) or a Frame ({canvas, gl}: a layer of it,
  // drawn in metres: one scene unit is `unitScale` metres, 1 for a metric scene such as a tree's).
  // Alone, the support is fitted to a view of VIEW_SIZE units.
  constructor(target, { unitScale = 1 } = {}) {
    super(target, { what: 'the ivy', study: 'ivy' });  // web/gl/sun.js: the one place of the pages' suns
    this.unitScale = unitScale;
    this.parts = {};  // name -> {vao, buffers, count, births}
    this.model = [0, 0, 0, 1];
    this.step = Infinity;
    this.visible = { support: true, stems: true, leaves: true, suckers: true, seeds: true, buds: false, leafTexture: true, supportTexture: true };
    // A dropped glTF's materials ({factor: linear RGBA, image, wrapS, wrapT}) and its base colour
    // textures by glTF image index (decoded and uploaded by setSupportMaterials).
    this.supportMaterials = [];
    this.supportTextures = new Map();
    this.supportLooks = 0;  // setSupportMaterials calls so far (a newer one drops an older decode)
    this.leafTexture = null;  // the worker's leaf texture (core/ivy/ivy_leaf_texture.h), uploaded
    this.buds = { vao: null, buffers: [], count: 0 };
    this.seeds = { vao: null, buffer: null, count: 0 };
    this.ivyUploads = 0;     // setIvy calls so far (a newer one drops an older upload)
    this.uploading = false;  // an ivy is going up in parts
  }

  async init() {
    this.programs = await loadPrograms(this.gl, SHADERS.href, {
      ivy: ['ivy.vert', 'ivy.frag'],
      marker: ['marker.vert', 'marker.frag'],
    });
    await this.#warmUp();
  }

  // Draws one frame of a one-triangle support, stem and seed (every program with the vertex
  // layouts and state render() uses) and waits for the GPU to finish it, before the page asks for
  // its first grow. On SwiftShader the first draw of each program and state compiles its routines
  // in the GPU process: 0.6-1.4 s (docs/budgets.md, "Responsiveness") that held the compositor, so
  // a click during the first grow waited for it. Nothing of it stays (the next frame clears).
  async #warmUp() {
    const gl = this.gl;
    const triangle = {
      positions: new Float32Array([0, 0, 0, 1e-3, 0, 0, 0, 1e-3, 0]).buffer,
      normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]).buffer,
      indices: new Uint32Array([0, 1, 2]).buffer,
    };
    this.#uploadSupport(triangle);
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [staticBuffer(gl, new Float32Array(triangle.positions)), staticBuffer(gl, new Float32Array(triangle.normals)),
      staticBuffer(gl, new Float32Array([0, 0, 0]))];
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 3);
    floatAttribute(gl, 2, buffers[2], 1);
    buffers.push(staticBuffer(gl, new Uint32Array(triangle.indices), gl.ELEMENT_ARRAY_BUFFER));
    gl.bindVertexArray(null);
    this.parts.stems = { vao, buffers, count: 3, births: () => 1 };
    this.setSeeds([[0, 0, 0]]);
    const camera = { viewProjection: () => [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], position: () => [0, 0, 1] };
    this.drawWhole(camera);
    this.#drop('support');
    this.#drop('stems');
    this.seeds.count = 0;
    const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    if (!fence) return;
    await new Promise((resolve) => {
      const poll = () => {
        if (gl.isContextLost() || gl.getSyncParameter(fence, gl.SYNC_STATUS) === gl.SIGNALED) resolve();
        else setTimeout(poll, 16);
      };
      poll();
    });
    if (!gl.isContextLost()) gl.deleteSync(fence);
  }

  // The support (no birth steps: always drawn), uploaded at once; a dropped glTF's with its uvs,
  // vertex colours and material per vertex (its triangles drawn in runs of one material).
  #uploadSupport(b) {
    const gl = this.gl;
    this.progress.abort();
    this.#drop('support');
    // The worker's buffers (ArrayBuffers or views) read in place: uploaded at once, then handed back.
    const indices = viewOf(Uint32Array, b.indices);
    if (indices.length === 0) return;
    const has = (name) => Boolean(b[name] && b[name].byteLength > 0);
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [staticBuffer(gl, viewOf(Float32Array, b.positions)), staticBuffer(gl, viewOf(Float32Array, b.normals))];
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 3);
    gl.disableVertexAttribArray(2);
    gl.vertexAttrib1f(2, 0);
    // An attribute the file may lack: its buffer when given, else the location switched off.
    const optional = (name, location, size) => {
      if (!has(name)) {
        gl.disableVertexAttribArray(location);
        return false;
      }
      buffers.push(staticBuffer(gl, viewOf(Float32Array, b[name])));
      floatAttribute(gl, location, buffers.at(-1), size);
      return true;
    };
    const uvs = optional('uvs', 3, 2);
    const colors = optional('colors', 4, 4);
    buffers.push(staticBuffer(gl, indices, gl.ELEMENT_ARRAY_BUFFER));
    gl.bindVertexArray(null);
    const runs = has('material') ? materialRuns(indices, viewOf(Float32Array, b.material)) : [{ first: 0, count: indices.length / 3, material: -1 }];
    this.parts.support = { vao, buffers, count: indices.length, births: null, uvs, colors, runs };
  }

  #drop(name) {
    const part = this.parts[name];
    if (!part) return;
    this.gl.deleteVertexArray(part.vao);
    for (const b of part.buffers) this.gl.deleteBuffer(b);
    delete this.parts[name];
  }

  // The support's triangles and bounds ({min, max} in scene units, or null for the free scene):
  // sets the scale that fits it in the view. Its materials go until setSupportMaterials.
  setSupport(buffers, bounds) {
    this.#uploadSupport(buffers);
    this.#fit(bounds);
    this.#dropSupportLook();
  }

  // A dropped glTF's look: `materials` as the worker's support description gives them ({name,
  // base_color: linear RGBA, image: glTF image index or -1, wrap_s, wrap_t}) and `images` (a Map
  // from a glTF image index to its encoded bytes as a Blob: PNG, JPEG or WebP, web/mesh/
  // mesh_images.js). Each image is decoded by the browser (createImageBitmap) and uploaded with
  // mipmaps; a frame is asked for (`request`) once they are in place. Resolves to {textures,
  // failed: [lines]} (a material whose image fails keeps its factor), or null when a newer support
  // or look replaced this one.
  async setSupportMaterials(materials, images, request = () => {}) {
    const gl = this.gl;
    this.#dropSupportLook();
    const serial = ++this.supportLooks;
    this.supportMaterials = (materials || []).map((m) => ({
      factor: Array.isArray(m.base_color) && m.base_color.length === 4 ? m.base_color.map(Number) : [1, 1, 1, 1],
      image: Number.isInteger(m.image) ? m.image : -1,
      wrapS: wrapOf(gl, m.wrap_s), wrapT: wrapOf(gl, m.wrap_t),
    }));
    const wanted = [...new Set(this.supportMaterials.map((m) => m.image).filter((i) => i >= 0))];
    const failed = [];
    const max = gl.getParameter(gl.MAX_TEXTURE_SIZE);
    for (const index of wanted) {
      const blob = images?.get(index);
      if (!blob) {
        failed.push(`image ${index}: its bytes are not in the file (an external uri)`);
        continue;
      }
      let bitmap;
      try {
        bitmap = await createImageBitmap(blob, { premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
        if (bitmap.width > max || bitmap.height > max) {  // over this GPU's limit: scaled to fit
          const k = max / Math.max(bitmap.width, bitmap.height);
          const fitted = await createImageBitmap(bitmap, { resizeWidth: Math.max(1, Math.floor(bitmap.width * k)), resizeHeight: Math.max(1, Math.floor(bitmap.height * k)), premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
          bitmap.close();
          bitmap = fitted;
        }
      } catch (e) {
        failed.push(`image ${index} (${blob.type || 'unknown type'}): the browser cannot decode it`);
        continue;
      }
      if (serial !== this.supportLooks || gl.isContextLost()) {
        bitmap.close();
        return null;
      }
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);  // row 0 = v 0, glTF's origin
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, bitmap);
      gl.generateMipmap(gl.TEXTURE_2D);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
      gl.bindTexture(gl.TEXTURE_2D, null);
      bitmap.close();
      this.supportTextures.set(index, texture);
      request();
    }
    if (serial !== this.supportLooks) return null;
    request();
    return { textures: this.supportTextures.size, failed };
  }

  #dropSupportLook() {
    ++this.supportLooks;  // a decode on its way is dropped
    for (const t of this.supportTextures.values()) this.gl.deleteTexture(t);
    this.supportTextures = new Map();
    this.supportMaterials = [];
  }

  #fit(bounds) {
    if (!this.fitView) {  // a Frame's layer: the frame's world, not a fitted view
      const s = this.unitScale;
      this.model = [0, 0, 0, s];
      this.boundsView = bounds ? { min: bounds.min.map((x) => x * s), max: bounds.max.map((x) => x * s) } : null;
      return;
    }
    if (!bounds) {
      this.model = [0, 0, 0, 1];
      this.boundsView = null;
      return;
    }
    const { min, max } = bounds;
    const extent = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2], 1e-9);
    const scale = VIEW_SIZE / extent;
    this.model = [(min[0] + max[0]) / 2, min[1], (min[2] + max[2]) / 2, scale];
    const view = (p) => [(p[0] - this.model[0]) * scale, (p[1] - this.model[1]) * scale, (p[2] - this.model[2]) * scale];
    this.boundsView = { min: view(min), max: view(max) };
  }

  // The leaf texture ({width, height, pixels: RGBA bytes, row 0 = v 0}: the pixels of the .glb's
  // PNG, web/bindings/ivy_bindings.cpp ivyLeafTexture), uploaded once with mipmaps; the leaves'
  // uvs are the .glb's TEXCOORD_0.
  setLeafTexture(t) {
    const gl = this.gl;
    if (!t || !t.pixels || !(t.width > 0) || !(t.height > 0)) return;
    // CLAMP_TO_EDGE as the .glb's sampler.
    const texture = imageTexture(gl, t, gl.CLAMP_TO_EDGE, this.leafTexture || undefined);
    this.leafTexture = texture;
  }

  // The ivy's parts ({stems, leaves, suckers}: {positions, normals, indices, birth}, leaves also
  // uvs); a scene
  // without a support is fitted to the ivy's own bounds. The buffers go up in parts
  // (web/gl/chunked_upload.js: a 125 k-internode ivy was a 1.7 s long task at once) while the old
  // ivy stays; `uploading` is true until the new one is in place. Resolves to true then, or to
  // false when a newer setIvy or clearIvy dropped this one.
  setIvy(mesh) {
    const gl = this.gl;
    const serial = ++this.ivyUploads;
    const names = ['stems', 'leaves', 'suckers'].filter((name) => mesh[name].indices.byteLength > 0);
    const hasUvs = (name) => Boolean(mesh[name].uvs && mesh[name].uvs.byteLength > 0);
    const plan = names.flatMap((name) => [
      { key: `${name}.positions`, bytes: mesh[name].positions, target: gl.ARRAY_BUFFER },
      { key: `${name}.normals`, bytes: mesh[name].normals, target: gl.ARRAY_BUFFER },
      { key: `${name}.birth`, bytes: mesh[name].birth, target: gl.ARRAY_BUFFER },
      { key: `${name}.indices`, bytes: mesh[name].indices, target: gl.ELEMENT_ARRAY_BUFFER },
      ...(hasUvs(name) ? [{ key: `${name}.uvs`, bytes: mesh[name].uvs, target: gl.ARRAY_BUFFER }] : []),
    ]);
    this.uploading = true;
    return uploadInParts(gl, plan, () => serial !== this.ivyUploads).then((uploaded) => {
      if (serial !== this.ivyUploads) {
        uploaded.forEach((b) => gl.deleteBuffer(b));
        return false;
      }
      this.progress.abort();  // a frame in parts of the old buffers ends here
      for (const name of ['stems', 'leaves', 'suckers']) this.#drop(name);
      for (const name of names) {
        const uvs = hasUvs(name);
        const buffers = ['positions', 'normals', 'birth', 'indices', ...(uvs ? ['uvs'] : [])].map((attr) => uploaded.get(`${name}.${attr}`));
        const vao = gl.createVertexArray();
        gl.bindVertexArray(vao);
        floatAttribute(gl, 0, buffers[0], 3);
        floatAttribute(gl, 1, buffers[1], 3);
        floatAttribute(gl, 2, buffers[2], 1);
        if (uvs) floatAttribute(gl, 3, buffers[4], 2);
        else gl.disableVertexAttribArray(3);
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffers[3]);
        gl.bindVertexArray(null);
        const indices = viewOf(Uint32Array, mesh[name].indices);
        this.parts[name] = { vao, buffers, count: indices.length, uvs, births: birthCounter(indices, viewOf(Float32Array, mesh[name].birth)) };
      }
      if (!this.parts.support) {
        const p = viewOf(Float32Array, mesh.stems.positions);
        if (p.length) {
          const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
          for (let i = 0; i < p.length; ++i) {
            min[i % 3] = Math.min(min[i % 3], p[i]);
            max[i % 3] = Math.max(max[i % 3], p[i]);
          }
          this.#fit({ min, max });
        }
      }
      this.uploading = false;
      return true;
    });
  }

  clearIvy() {
    this.progress.abort();
    ++this.ivyUploads;  // an upload on its way is dropped
    this.uploading = false;
    for (const name of ['stems', 'leaves', 'suckers']) this.#drop(name);
    this.#dropBuds();
  }

  // The buds as markers ({positions, kind, birth}).
  setBuds(b) {
    const gl = this.gl;
    this.progress.abort();
    this.#dropBuds();
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [b.positions, b.kind, b.birth].map((a) => staticBuffer(gl, viewOf(Float32Array, a)));
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 1);
    floatAttribute(gl, 2, buffers[2], 1);
    gl.bindVertexArray(null);
    this.buds = { vao, buffers, count: viewOf(Float32Array, b.kind).length };
  }

  #dropBuds() {
    if (!this.buds.vao) return;
    this.gl.deleteVertexArray(this.buds.vao);
    for (const b of this.buds.buffers) this.gl.deleteBuffer(b);
    this.buds = { vao: null, buffers: [], count: 0 };
  }

  // Seed points in scene units ([[x, y, z], ...]).
  setSeeds(points) {
    const gl = this.gl;
    this.progress.abort();
    if (!this.seeds.vao) {
      this.seeds.vao = gl.createVertexArray();
      this.seeds.buffer = gl.createBuffer();
    }
    gl.bindVertexArray(this.seeds.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.seeds.buffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(points.flat()), gl.DYNAMIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    gl.disableVertexAttribArray(1);
    gl.vertexAttrib1f(1, 3);  // kind 3: a seed point
    gl.disableVertexAttribArray(2);
    gl.vertexAttrib1f(2, 0);  // always drawn
    gl.bindVertexArray(null);
    this.seeds.count = points.length;
  }

  setStep(k) {
    this.step = k;
  }

  setVisible(flags) {
    Object.assign(this.visible, flags);
  }

  // Bounds of the support (or the ivy) in view units, for the camera.
  bounds() {
    return this.boundsView;
  }

  // Triangles of each ivy part born at or before the current step.
  drawnCounts() {
    const out = {};
    for (const name of ['stems', 'leaves', 'suckers']) {
      const part = this.parts[name];
      out[name] = part ? part.births(this.step) : 0;
    }
    return out;
  }

  // A ray through canvas pixel (x, y) (CSS pixels from the top left) in scene units.
  rayAt(camera, x, y) {
    const { origin, direction } = camera.ray(x, y, this.canvas.clientWidth, this.canvas.clientHeight);
    const s = this.model[3];
    return { origin: origin.map((e, i) => e / s + this.model[i]), direction };
  }

  // The ivy's steps of a frame (web/gl/progressive_frame.js) under `view` ({viewProjection, eye,
  // light: the unit direction towards the sun, scale: the drawing buffer's}): the support and the
  // ivy's parts, then the markers. Returns {steps, totals} (leavesTextured: the leaves drawn with
  // the leaf texture; supportTextured: the support with a base colour texture of its own). Drawn
  // by its Frame (web/gl/frame.js).
  layerSteps(view) {
    const gl = this.gl;
    const { viewProjection: vp, eye, light } = view;
    const step = Number.isFinite(this.step) ? this.step : 1e9;
    const p = this.programs.ivy;
    const totals = { triangles: 0, drawCalls: 0, primitives: 0, leavesTextured: false, supportTextured: false };
    const steps = [];
    const WHITE = [1, 1, 1], NONE = [0, 0, 0], OPAQUE = [1, 1, 1, 1];
    for (const name of ['support', 'stems', 'suckers', 'leaves']) {
      const part = this.parts[name];
      if (!part || !this.visible[name]) continue;
      // One draw per run of one material (the support of a dropped glTF), else one for the part.
      const runs = part.runs || [{ first: 0, count: part.count / 3, material: -1 }];
      for (const run of runs) {
        const material = name === 'support' ? this.supportMaterials[run.material] : undefined;
        // Leaves with uvs and the worker's texture: the .glb's texels, cut at its outline; a
        // dropped glTF's support with its material's base colour texture once decoded.
        const map = name === 'leaves' ? (part.uvs && this.visible.leafTexture ? this.leafTexture : null)
          : material && part.uvs && this.visible.supportTexture ? this.supportTextures.get(material.image) ?? null : null;
        if (map && name === 'leaves') totals.leavesTextured = true;
        if (map && name === 'support') totals.supportTextured = true;
        // A material's factor and colours replace the stone grey; its texture multiplies them.
        const color = map || material ? WHITE : COLORS[name].color;
        const variation = map || material ? NONE : COLORS[name].variation;
        steps.push({
          primitives: run.count,
          setup: () => {
            gl.useProgram(p.program);
            gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
            gl.uniform4fv(p.uniforms.uModel, this.model);
            gl.uniform1f(p.uniforms.uStep, step);
            gl.uniform3fv(p.uniforms.uLightDirection, light);
            gl.uniform3fv(p.uniforms.uCameraPosition, eye);
            gl.disable(gl.CULL_FACE);
            gl.uniform3fv(p.uniforms.uColor, color);
            gl.uniform3fv(p.uniforms.uVariation, variation);
            gl.uniform4fv(p.uniforms.uFactor, material ? material.factor : OPAQUE);
            gl.uniform1f(p.uniforms.uUseTexture, map ? 1 : 0);
            gl.uniform1f(p.uniforms.uAlphaCut, name === 'leaves' ? 0.5 : 0);
            gl.activeTexture(gl.TEXTURE0);
            gl.bindTexture(gl.TEXTURE_2D, map);
            if (map && material) {  // the material's sampler
              gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, material.wrapS);
              gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, material.wrapT);
            }
            gl.uniform1i(p.uniforms.uMap, 0);
            if (!part.colors) gl.vertexAttrib4f(4, 1, 1, 1, 1);  // no COLOR_0: white (a constant, not VAO state)
            if (name === 'support') {
              gl.enable(gl.POLYGON_OFFSET_FILL);  // ivy lying on a face wins the depth test
              gl.polygonOffset(1, 1);
            }
            gl.bindVertexArray(part.vao);
          },
          draw: (first, n) => gl.drawElements(gl.TRIANGLES, 3 * n, gl.UNSIGNED_INT, 12 * (run.first + first)),
          teardown: () => {
            gl.disable(gl.POLYGON_OFFSET_FILL);
            gl.bindTexture(gl.TEXTURE_2D, null);
          },
        });
        ++totals.drawCalls;
      }
      totals.triangles += part.count / 3;
      totals.primitives += part.count / 3;
    }
    const markers = [];
    if (this.buds.count && this.visible.buds) markers.push(this.buds);
    if (this.seeds.count && this.visible.seeds) markers.push(this.seeds);
    if (markers.length) {
      const m = this.programs.marker;
      const pointSize = 12 * Math.min(window.devicePixelRatio || 1, 2) * (view.scale || 1);
      steps.push({
        primitives: 0,  // a few points: drawn whole
        setup: () => {},
        draw: () => {
          gl.useProgram(m.program);
          gl.uniformMatrix4fv(m.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(m.uniforms.uModel, this.model);
          gl.uniform1f(m.uniforms.uPointSize, pointSize);
          gl.uniform1f(m.uniforms.uStep, step);
          gl.disable(gl.DEPTH_TEST);
          for (const marker of markers) {
            gl.bindVertexArray(marker.vao);
            gl.drawArrays(gl.POINTS, 0, marker.count);
          }
          gl.enable(gl.DEPTH_TEST);
        },
      });
      totals.drawCalls += markers.length;
    }
    return { steps, totals };
  }

  // Frees the context's objects this renderer made.
  dispose() {
    const gl = this.gl;
    super.dispose();
    ++this.ivyUploads;  // an upload on its way is dropped
    for (const name of Object.keys(this.parts)) this.#drop(name);
    this.#dropBuds();
    if (this.seeds.vao) {
      gl.deleteVertexArray(this.seeds.vao);
      gl.deleteBuffer(this.seeds.buffer);
      this.seeds = { vao: null, buffer: null, count: 0 };
    }
    if (this.leafTexture) gl.deleteTexture(this.leafTexture);
    this.leafTexture = null;
    this.#dropSupportLook();
    for (const p of Object.values(this.programs || {})) gl.deleteProgram(p.program);
    this.programs = null;
  }
}

// The runs of consecutive triangles of one material ({first, count} in triangles, material: the
// index at each triangle's first vertex, -1 none): a glTF's primitives are read one after another,
// so a file has about as many runs as primitives.
export function materialRuns(indices, material) {
  const runs = [];
  const triangles = Math.floor(indices.length / 3);
  for (let t = 0; t < triangles; ++t) {
    const m = Number.isFinite(material[indices[3 * t]]) ? material[indices[3 * t]] : -1;
    const last = runs.at(-1);
    if (last && last.material === m) ++last.count;
    else runs.push({ first: t, count: 1, material: m });
  }
  return runs;
}

// A glTF sampler's wrap mode (§5.26) as GL's; glTF's default REPEAT.
function wrapOf(gl, mode) {
  return mode === gl.CLAMP_TO_EDGE || mode === gl.MIRRORED_REPEAT ? mode : gl.REPEAT;
}
