// The tree study's WebGL2 renderer: bark tubes, double-sided leaves and flowers on the shared
// ground (full-polygon mode, textured as the .glb: shaders/tree/tree_textured.frag), or the hybrid mode of thesis chapter 4: texture cards from a card
// atlas plus lines. Shaders (GLSL ES 3.00) are shaders/tree/*, including shaders/common/*.
// The tree casts the sun's shadow (shadowKey, shadowSteps: its full mesh's parts into the frame's
// shadow map, web/gl/shadow_map.js, leaves cut out by alpha, in both modes) and full mode receives
// it on every part, with the crown's ambient occlusion per vertex (the worker's `occlusion`,
// core/tree/crown_occlusion.h) darkening the sky light of inner leaves; hybrid mode's cards
// receive it too (card_lit.frag), its lines do not.
// A StudyLayer (web/gl/frame.js): a layer of a Frame (layerSteps: the tree under the frame's
// camera and sun; the frame draws the ground under its footprint), on the tree page, the grove's
// neighbours to come, <niwa-tree> and beside other studies (tests/browser/frame_layers.test.mjs).
// Does not: grow or mesh trees (the worker does), keep page state, or own the camera.
import { drawingBufferSize } from '../gl/context.js';
import { StudyLayer } from '../gl/frame.js';
import { BufferPool } from '../gl/buffer_pool.js';
import { UPLOAD_PARTS_ABOVE, gpuDone, planBytes, uploadInParts } from '../gl/chunked_upload.js';
import { copyOf, floatAttribute, staticBuffer, uintAttribute, viewOf } from '../gl/buffers.js';
import { PickTarget } from '../gl/pick.js';
import { ProgressiveFrame } from '../gl/progressive_frame.js';
import { loadPrograms } from '../gl/program.js';
import { ShadowMap } from '../gl/shadow_map.js';
import { dataTexture, imageTexture, restPoses, uploadPoses } from '../gl/textures.js';

export { BACKGROUND } from '../gl/context.js';
export const SHADERS = new URL('../../shaders/tree/', import.meta.url).href;
const NONE = 0xffffffff;  // "no branch" for the branch-id attribute and the selection
// The selection's x-ray pass draws the selected branch this many drawing-buffer pixels wider than
// it is (half on each side; clip space spans 2 units, so the offset is XRAY_WIDEN_PX / size): a twig
// thinner than a pixel still shows its highlight.
const XRAY_WIDEN_PX = 3;

// The worker's textures per part (mesh.textures, core/tree/tree_textures.h), as the .glb's
// materials: wrap, alpha cutoff (glTF MASK 0.5) and the bark's normal map.
const TEXTURED = {
  bark: { map: 'bark', normalMap: 'barkNormal', repeat: true, alphaCutoff: 0 },
  leaves: { map: 'leaf', normalMap: null, repeat: false, alphaCutoff: 0.5 },
  flowers: { map: 'flower', normalMap: null, repeat: false, alphaCutoff: 0.5 },
};

export const PARTS = {
  bark: { color: [0.36, 0.25, 0.18], variation: [0.04, 0.03, 0.02], doubleSided: 0, specular: 0.03 },
  leaves: { color: [0.30, 0.55, 0.20], variation: [0.10, 0.14, 0.06], doubleSided: 1, specular: 0.05 },
  flowers: { color: [0.98, 0.74, 0.84], variation: [0.02, 0.08, 0.06], doubleSided: 1, specular: 0.08 },
};

// Unbinds units 0-2, which the atlas program's samplers read (uBaseMap 1, uNormalMap 2, and any
// sampler left at unit 0): the cards leave the atlas itself bound on unit 1 and #allocateAtlas on
// unit 0, and drawing into the atlas while it is bound to a sampled unit is a feedback loop
// (GL_INVALID_OPERATION), even where the shader does not read that sampler.
function clearAtlasSamplers(gl) {
  for (const unit of [gl.TEXTURE0, gl.TEXTURE1, gl.TEXTURE2]) {
    gl.activeTexture(unit);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }
  gl.activeTexture(gl.TEXTURE0);
}

// The look of one atlas part (PARTS' colours; with `map`, the {texture} of its TEXTURED map: the
// cut-out leaf or blossom, the bark colour). The bark's normal map is left out: the atlas has no
// world positions for its tangent frame. Shared by paintAtlas and paintAtlasInParts.
function atlasPartLook(gl, program, name, map) {
  const look = PARTS[name];
  gl.uniform3fv(program.uniforms.uColor, look.color);
  gl.uniform3fv(program.uniforms.uColorVariation, look.variation);
  gl.uniform1f(program.uniforms.uDoubleSided, look.doubleSided);
  gl.uniform1f(program.uniforms.uUseTexture, map ? 1 : 0);
  gl.uniform1f(program.uniforms.uUseNormalMap, 0);
  gl.uniform1f(program.uniforms.uAlphaCutoff, map ? TEXTURED[name].alphaCutoff : 0);
  gl.activeTexture(gl.TEXTURE1);
  gl.bindTexture(gl.TEXTURE_2D, map ? map.texture : null);
  gl.uniform1i(program.uniforms.uBaseMap, 1);
  gl.activeTexture(gl.TEXTURE2);
  gl.bindTexture(gl.TEXTURE_2D, null);
  gl.uniform1i(program.uniforms.uNormalMap, 2);
  gl.activeTexture(gl.TEXTURE0);
}

// Paints a card atlas (thesis 4.2.1) into the framebuffer `fb` (hybrid.atlasSize square, colour =
// `texture`, with a depth buffer) from the worker's clip-space triangles of the group
// representatives and leaf clusters, lit by `light` like the full view and transparent elsewhere,
// then mipmaps `texture` for distant cards. Returns the triangles drawn. Used by the page and the grove.
// With `textures` (kind -> {texture}: the worker's bark, leaf and flower textures, as the full
// view) and a program over tree_textured.frag, each part is painted from its own texture through
// the atlas triangles' uvs (leaf blades and blossoms cut out by alpha, as the full view and the
// .glb's cards_* atlas); without, in the parts' plain colours (PARTS).
// uploaded: Map('part.attr' -> buffer) of geometry already uploaded (in parts), deleted here.
// shadowMap: a ShadowMap whose texture the program's shadow sampler reads (tree_textured.frag
// declares one; the atlas is drawn unshadowed), or null for a program without one (tree.frag).
export function paintAtlas(gl, program, hybrid, fb, texture, light, textures = null, uploaded = null, shadowMap = null) {
  const size = hybrid.atlasSize;
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.viewport(0, 0, size, size);
  gl.clearColor(0, 0, 0, 0);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.enable(gl.DEPTH_TEST);
  gl.disable(gl.BLEND);
  gl.useProgram(program.program);
  gl.uniform3fv(program.uniforms.uLightDirection, light);
  gl.uniform3fv(program.uniforms.uCameraPosition, [0, 0, 10]);
  gl.uniform1f(program.uniforms.uXray, 0);
  gl.uniform1f(program.uniforms.uSpecular, 0);
  clearAtlasSamplers(gl);
  shadowMap?.bindFor(program, null);
  let triangles = 0;
  for (const name of ['bark', 'leaves', 'flowers']) {
    const part = hybrid[name];
    const count = part.indices.byteLength / 4;
    if (count === 0) continue;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const ready = (attr) => uploaded?.get(`${name}.${attr}`);
    const buffers = [ready('positions') || staticBuffer(gl, part.positions), ready('normals') || staticBuffer(gl, part.normals)];
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 3);
    const spec = TEXTURED[name];
    const map = textures && part.uvs && textures[spec.map];
    if (map) {
      buffers.push(staticBuffer(gl, part.uvs));
      floatAttribute(gl, 2, buffers[buffers.length - 1], 2);
    }
    const indices = ready('indices');
    if (indices) gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indices);
    buffers.push(indices || staticBuffer(gl, part.indices, gl.ELEMENT_ARRAY_BUFFER));
    atlasPartLook(gl, program, name, map);
    gl.drawElements(gl.TRIANGLES, count, gl.UNSIGNED_INT, 0);
    triangles += count / 3;
    gl.bindVertexArray(null);
    buffers.forEach((b) => gl.deleteBuffer(b));
    gl.deleteVertexArray(vao);
  }
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.generateMipmap(gl.TEXTURE_2D);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return triangles;
}

// A card atlas to paint into: a mipmapped RGBA8 texture `size` texels square (levels allocated, not
// filled) with a depth buffer, and the framebuffer joining them (left bound, as is the texture).
// {texture, depth, fb, size}; the caller deletes the three.
export function createAtlasTarget(gl, size) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texStorage2D(gl.TEXTURE_2D, Math.floor(Math.log2(size)) + 1, gl.RGBA8, size, size);
  const depth = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, size, size);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  return { texture, depth, fb, size };
}

// paintAtlas over several tasks (the cheap representation of a moving full-mode tree, issue 16):
// the atlas geometry of a 141 k-internode sakura is 66 MB and about 1.6 M triangles, seconds of
// SwiftShader time at once, so it is drawn `budget` triangles at a time, each part once the GPU
// has finished the last (gpuDone), then mipmapped. uploaded: its buffers (chunked_upload.js),
// deleted here. Resolves to the triangles drawn, or -1 when cancelled() turned true.
export async function paintAtlasInParts(gl, program, hybrid, fb, texture, light, uploaded, budget, cancelled, textures = null, shadowMap = null) {
  const size = hybrid.atlasSize;
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.viewport(0, 0, size, size);
  gl.clearColor(0, 0, 0, 0);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  const owned = [];
  const steps = [];
  for (const name of ['bark', 'leaves', 'flowers']) {
    const part = hybrid[name];
    const count = part.indices.byteLength / 4;
    if (count === 0) continue;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const ready = (attr) => uploaded?.get(`${name}.${attr}`);
    const buffers = [ready('positions') || staticBuffer(gl, part.positions), ready('normals') || staticBuffer(gl, part.normals)];
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 3);
    const map = textures && part.uvs && textures[TEXTURED[name].map];
    if (map) {
      buffers.push(ready('uvs') || staticBuffer(gl, part.uvs));
      floatAttribute(gl, 2, buffers[buffers.length - 1], 2);
    }
    const indices = ready('indices') || staticBuffer(gl, part.indices, gl.ELEMENT_ARRAY_BUFFER);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indices);
    buffers.push(indices);
    gl.bindVertexArray(null);
    owned.push({ vao, buffers });
    steps.push({
      primitives: count / 3,
      setup: () => {
        gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
        gl.viewport(0, 0, size, size);
        gl.enable(gl.DEPTH_TEST);
        gl.disable(gl.BLEND);
        gl.useProgram(program.program);
        gl.uniform3fv(program.uniforms.uLightDirection, light);
        gl.uniform3fv(program.uniforms.uCameraPosition, [0, 0, 10]);
        gl.uniform1f(program.uniforms.uXray, 0);
        gl.uniform1f(program.uniforms.uSpecular, 0);
        // The textures of the full view (as paintAtlas), or plain colours before they are there.
        clearAtlasSamplers(gl);
        shadowMap?.bindFor(program, null);
        atlasPartLook(gl, program, name, map);
        gl.bindVertexArray(vao);
      },
      draw: (first, n) => gl.drawElements(gl.TRIANGLES, 3 * n, gl.UNSIGNED_INT, 12 * first),
      teardown: () => {
        gl.bindVertexArray(null);
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      },
    });
  }
  const frame = new ProgressiveFrame();  // steps only: the target is bound by each step
  frame.start(steps);
  let triangles = 0;
  while (frame.pending() && !cancelled()) {
    triangles += frame.run(budget).primitives;
    await gpuDone(gl);
  }
  for (const { vao, buffers } of owned) {
    gl.deleteVertexArray(vao);
    buffers.forEach((b) => gl.deleteBuffer(b));
  }
  if (frame.pending()) return -1;
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.generateMipmap(gl.TEXTURE_2D);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return triangles;
}

export class Renderer extends StudyLayer {
  // target: a canvas (the renderer makes its context) or a Frame ({canvas, gl}: a layer of it).
  // Throws an Error with a readable message when WebGL2 is missing. The sun: the tree's sun rows'
  // defaults (setSun follows the page's rows).
  constructor(target) {
    super(target, { what: 'the tree', study: 'tree' });
    const gl = this.gl;
    this.parts = {};
    this.center = [0, 0, 0];
    this.shadowRadius = 1;
    this.extent = 20;
    this.motion = null;  // {hybrid, drawList}: the cheaper representation while moving
    this.pool = new BufferPool(gl);  // the tree's mesh buffers, reused tree after tree
    this.poseTexture = gl.createTexture();
    this.poseNodes = 0;
    this.wind = 0;         // wind speed (m/s) at the tree now: leaf flutter
    this.swayTime = 0;     // simulated time (s) of the pose shown
    this.swaying = false;  // poses differ from rest
    this.leafLength = 0.05;  // metres (the tree's leaf_size)
    this.textures = {};      // kind -> {texture, digest}: the worker's procedural textures
    this.look = null;        // {leaf_shape, season, autumn_colour} of the mesh drawn
    this.meshSerial = 0;     // meshes installed: with poseSerial, what the shadow map holds
    this.poseSerial = 0;
    this.ownShadow = null;   // a renderer alone: a ShadowMap for its samplers (never drawn)
    this.setRestPoses(1);
  }

  // The worker's textures ({look, bark|barkNormal|leaf|flower: {width, height, digest, pixels}}):
  // each is uploaded (mipmapped) only when its digest changes.
  setTextures(textures) {
    const gl = this.gl;
    if (!textures) return;
    this.look = textures.look || null;
    for (const kind of ['bark', 'barkNormal', 'leaf', 'flower']) {
      const t = textures[kind];
      if (!t || !t.pixels) continue;
      const have = this.textures[kind];
      if (have && have.digest === t.digest) continue;
      const repeat = kind === 'bark' || kind === 'barkNormal';
      const texture = imageTexture(gl, t, repeat ? gl.REPEAT : gl.CLAMP_TO_EDGE, have ? have.texture : undefined);
      this.textures[kind] = { texture, digest: t.digest };
    }
  }

  // Binds the part's textures on units 1 and 2 (unit 0 holds the poses) and sets its uniforms.
  #bindPartTextures(program, name) {
    const gl = this.gl;
    const spec = TEXTURED[name];
    const map = spec && this.textures[spec.map];
    const normal = spec && spec.normalMap && this.textures[spec.normalMap];
    gl.uniform1f(program.uniforms.uUseTexture, map ? 1 : 0);
    gl.uniform1f(program.uniforms.uUseNormalMap, normal ? 1 : 0);
    gl.uniform1f(program.uniforms.uAlphaCutoff, spec ? spec.alphaCutoff : 0);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, map ? map.texture : null);
    gl.uniform1i(program.uniforms.uBaseMap, 1);
    gl.activeTexture(gl.TEXTURE2);
    gl.bindTexture(gl.TEXTURE_2D, normal ? normal.texture : null);
    gl.uniform1i(program.uniforms.uNormalMap, 2);
    gl.activeTexture(gl.TEXTURE0);
  }

  // Identity poses for `nodes` node points (the grown shape).
  setRestPoses(nodes) {
    this.setPoses(restPoses(nodes));
    this.swaying = false;
  }

  // poses: Float32Array, 16 per node point (R columns with M in w, then T): the worker's 'pose'.
  setPoses(poses, wind = 0, time = 0) {
    const gl = this.gl;
    const nodes = Math.floor(poses.length / 16);
    this.poseRows = uploadPoses(gl, this.poseTexture, poses, nodes, this.poseRows);
    this.poseNodes = nodes;
    this.poseSerial += 1;
    this.wind = Number(wind) || 0;
    this.swayTime = Number(time) || 0;
    this.swaying = true;
  }

  async init(shaderBase = SHADERS) {
    const gl = this.gl;
    const p = await loadPrograms(gl, shaderBase, {
      tree: ['tree.vert', 'tree_textured.frag'], pick: ['pick.vert', '../common/pick.frag'], atlas: ['atlas.vert', 'tree_textured.frag'],
      card: ['card.vert', 'card_lit.frag'], line: ['line.vert', 'line.frag'], shadow: ['shadow.vert', 'shadow.frag'],
    });
    this.shadowProgram = p.shadow;
    this.treeProgram = p.tree;
    this.pickProgram = p.pick;
    this.atlasProgram = p.atlas;
    this.cardProgram = p.card;
    this.lineProgram = p.line;
    this.pickTarget = new PickTarget(gl);
    this.selected = NONE;
  }

  // mesh: {bark|leaves|flowers: {positions, normals, indices, joints, weights}} as ArrayBuffers or
  // views (bark also has branchIds: Uint32 per vertex; leaves uvs), not read once the promise
  // resolves (the page may hand them back to the worker then); bounds in metres; swayNodes: node
  // points of the sway skin (poses start at rest); hybrid: the worker's card-atlas geometry when the
  // state's render_mode is 1 (then render() draws the draw list of setDrawList), else null.
  // A big mesh (more than UPLOAD_PARTS_ABOVE bytes) is uploaded in parts (web/gl/chunked_upload.js),
  // one part per task, into new buffers while the old tree stays drawn (issue 17: one upload of a
  // 15-year sakura blocked the main thread 3.7 s in Chromium on SwiftShader, with bufferData and
  // with bufferSubData alike); `uploading` is true until the new tree is in place. Returns a
  // promise that resolves then (at once for small meshes); a newer setTree drops an older upload.
  setTree(mesh, bounds, swayNodes = 0, hybrid = null) {
    const serial = (this.treeUploads = (this.treeUploads || 0) + 1);
    const plan = [];
    for (const name of Object.keys(PARTS)) {
      const data = mesh[name];
      if (!data || data.indices.byteLength === 0) continue;
      for (const [attr, bytes] of Object.entries(data)) {
        if (attr === 'branchParents' || !bytes || bytes.byteLength === 0) continue;
        plan.push({ key: `${name}.${attr}`, bytes, target: attr === 'indices' ? this.gl.ELEMENT_ARRAY_BUFFER : this.gl.ARRAY_BUFFER });
      }
      // The selection highlight starts at zero (one float per vertex).
      if (data.branchIds) plan.push({ key: `${name}.highlight`, bytes: new Float32Array(data.branchIds.byteLength / 4), target: this.gl.ARRAY_BUFFER });
    }
    if (planBytes(plan) <= UPLOAD_PARTS_ABOVE) {
      this.uploading = false;
      this.#installTree(mesh, bounds, swayNodes, hybrid, null);
      return Promise.resolve(true);
    }
    this.uploading = true;
    return uploadInParts(this.gl, plan, () => serial !== this.treeUploads).then((buffers) => {
      if (serial !== this.treeUploads) {  // superseded: a newer tree is on its way
        buffers.forEach((b) => this.gl.deleteBuffer(b));
        return false;
      }
      this.#installTree(mesh, bounds, swayNodes, hybrid, buffers);
      this.uploading = false;
      return true;
    });
  }

  #installTree(mesh, bounds, swayNodes, hybrid, uploaded) {
    const gl = this.gl;
    this.progress.abort();  // a frame in parts of the old tree's buffers ends here
    const keepSelection = this.selected;
    this.setRestPoses(swayNodes);
    this.setTextures(mesh.textures);
    this.setHybrid(hybrid);
    // The buffers are the pool's (reused with bufferSubData when the new tree fits: a smaller tree
    // allocates nothing); only the vertex arrays are new.
    for (const part of Object.values(this.parts)) {
      gl.deleteVertexArray(part.vao);
      part.buffers.forEach((b) => { if (!this.pool.owns(b)) gl.deleteBuffer(b); });
    }
    this.parts = {};
    this.highlight = null;
    for (const name of Object.keys(PARTS)) {
      const data = mesh[name];
      if (!data || data.indices.byteLength === 0) continue;
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const upload = (attr, bytes, target = gl.ARRAY_BUFFER) => {
        const ready = uploaded?.get(`${name}.${attr}`);  // uploaded in parts already
        if (!ready) return this.pool.upload(`${name}.${attr}`, bytes, target);
        gl.bindBuffer(target, ready);
        return ready;
      };
      const buffers = [upload('positions', data.positions), upload('normals', data.normals)];
      floatAttribute(gl, 0, buffers[0], 3);
      floatAttribute(gl, 1, buffers[1], 3);
      // Sway skin: node point (uint) and eq. 3.15 weight per vertex; uv for the leaf flutter.
      const vertices = data.positions.byteLength / 12;
      if (data.joints && data.joints.byteLength === vertices * 4) {
        const joints = upload('joints', data.joints), weights = upload('weights', data.weights);
        uintAttribute(gl, 4, joints, 1);
        floatAttribute(gl, 5, weights, 1);
        buffers.push(joints, weights);
      }
      if (data.uvs && data.uvs.byteLength === vertices * 8) {
        const uvs = upload('uvs', data.uvs);
        floatAttribute(gl, 6, uvs, 2);
        buffers.push(uvs);
      }
      // The crown's ambient occlusion per vertex (without it: the constant 0, see layerSteps).
      if (data.occlusion && data.occlusion.byteLength === vertices * 4) {
        const occlusion = upload('occlusion', data.occlusion);
        floatAttribute(gl, 7, occlusion, 1);
        buffers.push(occlusion);
      } else {
        gl.disableVertexAttribArray(7);
      }
      if (data.branchIds && data.branchIds.byteLength === data.positions.byteLength / 3) {
        const buffer = upload('branchIds', data.branchIds);
        uintAttribute(gl, 2, buffer, 1);
        buffers.push(buffer);
        // Selection highlight per vertex (select() fills it).
        // Copies: the worker's buffers go back to it once the tree is in place (recycle).
        this.branchIds = copyOf(Uint32Array, data.branchIds);
        this.branchParents = copyOf(Int32Array, data.branchParents || new ArrayBuffer(0));
        this.highlight = new Float32Array(this.branchIds.length);
        this.highlightBuffer = upload('highlight', this.highlight);
        gl.enableVertexAttribArray(3);
        gl.vertexAttribPointer(3, 1, gl.FLOAT, false, 0, 0);
        buffers.push(this.highlightBuffer);
      } else {
        gl.disableVertexAttribArray(2);
      }
      buffers.push(upload('indices', data.indices, gl.ELEMENT_ARRAY_BUFFER));
      gl.bindVertexArray(null);
      this.parts[name] = { vao, buffers, count: data.indices.byteLength / 4, picking: Boolean(data.branchIds) };
    }
    this.meshSerial += 1;  // the shadow map is redrawn for it
    const min = bounds.min, max = bounds.max;
    this.treeBounds = { min: [...min], max: [...max] };
    this.center = [(min[0] + max[0]) / 2, 0, (min[2] + max[2]) / 2];
    this.crownHeight = Math.max(0, 0.6 * max[1]);
    this.shadowRadius = Math.max(0.3, 0.5 * Math.max(max[0] - min[0], max[2] - min[2]));
    this.extent = Math.max(6, 4 * Math.max(max[1] - min[1], this.shadowRadius * 2));
    // Uploaded buffers no part took (an attribute of the wrong length) are not kept.
    const used = new Set(Object.values(this.parts).flatMap((part) => part.buffers));
    for (const b of uploaded?.values() || []) if (!used.has(b)) gl.deleteBuffer(b);
    this.highlightMarked = false;  // the new highlight buffer is all zero
    if (keepSelection !== NONE && keepSelection !== undefined) this.select(keepSelection);
  }

  // Hybrid mode (thesis 4.2): paints the card atlas once per tree from the worker's clip-space
  // triangles (group representatives and leaf clusters, each projected onto its tile), textured
  // and lit by the sun like the full view, transparent elsewhere; mipmapped for distant cards.
  setHybrid(hybrid) {
    this.hybrid = null;
    this.#deleteDrawList();
    this.clearMotion();  // the atlas is repainted for this hybrid tree
    if (!hybrid) return;
    this.hybrid = this.#paintHybridAtlas(hybrid);
  }

  // Paints the card atlas of `hybrid` into this.atlas (reallocated when its size changes).
  #paintHybridAtlas(hybrid, uploaded = null) {
    this.#allocateAtlas(hybrid.atlasSize);
    const triangles = paintAtlas(this.gl, this.atlasProgram, hybrid, this.atlas.fb, this.atlas.texture, this.light, this.textures, uploaded, this.#shadowMap());
    return { atlasSize: hybrid.atlasSize, atlasTriangles: triangles };
  }

  #allocateAtlas(size) {
    const gl = this.gl;
    if (!this.atlas || this.atlas.size !== size) {
      if (this.atlas) {
        const old = this.atlas;
        this.progress.retire(() => {
          gl.deleteTexture(old.texture);
          gl.deleteFramebuffer(old.fb);
          gl.deleteRenderbuffer(old.depth);
        });
      }
      this.atlas = createAtlasTarget(gl, size);
    }
  }

  // The cheaper representation of a full-mode tree while it moves (issue 16: a FrameGovernor's
  // cheap levels): the hybrid scene of the same tree (thesis ch. 4: cards and lines, skinned by the
  // same poses), its atlas from the worker's 'view' {motion: true}. Full-mode trees only.
  // Its geometry goes up in parts first (web/gl/chunked_upload.js: the atlas of a 141 k-internode
  // sakura held the main thread 0.5-3.4 s at once) and is painted `budget` triangles at a time
  // (paintAtlasInParts); resolves to true once the atlas is painted.
  setMotionHybrid(hybrid, budget = Infinity) {
    this.clearMotion();
    if (this.hybrid || !hybrid) return Promise.resolve(false);
    const gl = this.gl;
    const serial = (this.motionUploads = (this.motionUploads || 0) + 1);
    const plan = [];
    for (const name of ['bark', 'leaves', 'flowers']) {
      const part = hybrid[name];
      if (!part || part.indices.byteLength === 0) continue;
      plan.push({ key: `${name}.positions`, bytes: part.positions, target: gl.ARRAY_BUFFER },
        { key: `${name}.normals`, bytes: part.normals, target: gl.ARRAY_BUFFER },
        { key: `${name}.indices`, bytes: part.indices, target: gl.ELEMENT_ARRAY_BUFFER });
      if (part.uvs && this.textures[TEXTURED[name].map]) plan.push({ key: `${name}.uvs`, bytes: part.uvs, target: gl.ARRAY_BUFFER });
    }
    this.motionPending = true;
    const current = () => serial === this.motionUploads && !this.hybrid;
    return uploadInParts(gl, plan, () => !current()).then(async (uploaded) => {
      if (!current()) {
        uploaded.forEach((b) => gl.deleteBuffer(b));
        return false;
      }
      this.#allocateAtlas(hybrid.atlasSize);
      const triangles = await paintAtlasInParts(gl, this.atlasProgram, hybrid, this.atlas.fb, this.atlas.texture, this.light,
        uploaded, budget, () => !current(), this.textures, this.#shadowMap());
      if (!current() || triangles < 0) return false;
      this.motionPending = false;
      // The parts painted from the full view's textures (the others in plain colours).
      const textured = ['bark', 'leaves', 'flowers'].filter((name) => hybrid[name]?.uvs && this.textures[TEXTURED[name].map]);
      this.motion = { hybrid: { atlasSize: hybrid.atlasSize, atlasTriangles: triangles, textured }, drawList: null };
      if (this.pendingMotionList) this.setMotionDrawList(this.pendingMotionList);  // came meanwhile
      this.pendingMotionList = null;
      return true;
    });
  }

  // The draw list of the motion representation for the current camera.
  setMotionDrawList(msg) {
    if (!this.motion) {
      if (this.motionPending) this.pendingMotionList = msg;  // the atlas is still going up
      return;
    }
    if (this.motion.drawList) this.#deleteList(this.motion.drawList);
    this.motion.drawList = this.#buildDrawList(msg);
  }

  // Triangles of a full-mode frame of the tree (its parts).
  fullPrimitives() {
    return Object.values(this.parts).reduce((n, part) => n + part.count / 3, 0);
  }

  // True when the motion representation can be drawn (its atlas and a draw list are in place).
  hasMotionAtlas() {
    return Boolean(this.motion || this.motionPending);
  }

  motionReady() {
    return Boolean(this.motion?.drawList);
  }

  clearMotion() {
    if (this.motion?.drawList) this.#deleteList(this.motion.drawList);
    this.motion = null;
    this.motionPending = false;
    this.pendingMotionList = null;
    this.motionUploads = (this.motionUploads || 0) + 1;  // an atlas on its way is dropped
  }

  #deleteDrawList() {
    if (!this.drawList) return;
    this.#deleteList(this.drawList);
    this.drawList = null;
  }

  // A frame in parts may still draw the list: deleted when that frame ends (ProgressiveFrame.retire).
  #deleteList(list) {
    const gl = this.gl;
    this.progress.retire(() => {
      for (const part of [list.cards, list.lines]) {
        if (!part) continue;
        gl.deleteVertexArray(part.vao);
        part.buffers.forEach((b) => gl.deleteBuffer(b));
        part.textures?.forEach((t) => gl.deleteTexture(t));
      }
    });
  }

  // The worker's 'drawList' for the current view (hybrid mode): cards and line segments.
  setDrawList(msg) {
    this.#deleteDrawList();
    if (!this.hybrid) return;
    this.drawList = this.#buildDrawList(msg);
  }

  #buildDrawList(msg) {
    const gl = this.gl;
    const list = { stats: msg.stats, cards: null, lines: null };
    const c = msg.cards;
    if (c.indices.byteLength > 0) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const buffers = [c.positions, c.uvs, c.joints, c.weights].map((bytes) => staticBuffer(gl, bytes));
      floatAttribute(gl, 0, buffers[0], 3);
      floatAttribute(gl, 1, buffers[1], 2);
      uintAttribute(gl, 4, buffers[2], 1);
      floatAttribute(gl, 5, buffers[3], 1);
      buffers.push(staticBuffer(gl, c.indices, gl.ELEMENT_ARRAY_BUFFER));
      gl.bindVertexArray(null);
      list.cards = { vao, buffers, count: c.indices.byteLength / 4 };
    }
    // Lines: the per-segment arrays become data textures read by line.vert with texelFetch, and one
    // plain draw of 6 vertices per segment expands them (no instancing: SwiftShader, the CPU WebGL
    // of machines without a GPU, pays a draw's setup per instance).
    const l = msg.lines;
    const segments = l.widths.byteLength / 4;
    if (segments > 0) {
      const textures = [
        dataTexture(gl, viewOf(Float32Array, l.positions), 3, gl.RGB32F, gl.RGB, gl.FLOAT),  // p0, p1
        dataTexture(gl, viewOf(Float32Array, l.colors), 3, gl.RGB32F, gl.RGB, gl.FLOAT),
        dataTexture(gl, viewOf(Float32Array, l.widths), 1, gl.R32F, gl.RED, gl.FLOAT),
        dataTexture(gl, viewOf(Uint32Array, l.joints), 2, gl.RG32UI, gl.RG_INTEGER, gl.UNSIGNED_INT),
        dataTexture(gl, viewOf(Float32Array, l.weights), 2, gl.RG32F, gl.RG, gl.FLOAT),
      ];
      list.lines = { vao: gl.createVertexArray(), buffers: [], textures, count: segments };
    }
    return list;
  }

  // Cards and lines of the current draw list under `view` (the frame's); returns [triangles,
  // lines, draw calls].
  #renderHybrid(view, drawList) {
    const { viewProjection } = view;
    const gl = this.gl;
    let triangles = 0, lines = 0, drawCalls = 0;
    if (!drawList) return [0, 0, 0];
    const { cards, lines: segs } = drawList;
    if (cards) {
      const p = this.cardProgram;
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, viewProjection);
      gl.uniform3fv(p.uniforms.uLightDirection, view.light || this.light);
      this.#bindPoses(p);
      // The sun's shadow map (card_lit.frag), drawn from the full mesh once per mesh and sun.
      (view.shadow || this.#shadowMap()).bindFor(p, view.sun || null);
      gl.activeTexture(gl.TEXTURE1);
      gl.bindTexture(gl.TEXTURE_2D, this.atlas.texture);
      gl.uniform1i(p.uniforms.uAtlas, 1);
      gl.bindVertexArray(cards.vao);
      gl.drawElements(gl.TRIANGLES, cards.count, gl.UNSIGNED_INT, 0);
      triangles += cards.count / 3;
      drawCalls += 1;
      gl.activeTexture(gl.TEXTURE0);
    }
    if (segs) {
      const p = this.lineProgram;
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, viewProjection);
      gl.uniform2f(p.uniforms.uViewport, view.width, view.height);  // the frame's drawing buffer
      this.#bindPoses(p);
      segs.textures.forEach((texture, i) => {
        gl.activeTexture(gl.TEXTURE2 + i);
        gl.bindTexture(gl.TEXTURE_2D, texture);
      });
      for (const [i, name] of ['uLinePositions', 'uLineColors', 'uLineWidths', 'uLineJoints', 'uLineWeights'].entries()) {
        gl.uniform1i(p.uniforms[name], 2 + i);
      }
      gl.activeTexture(gl.TEXTURE0);
      gl.bindVertexArray(segs.vao);
      // Sub-pixel lines blend by their coverage; they leave the depth buffer to the cards.
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      gl.depthMask(false);
      gl.drawArrays(gl.TRIANGLES, 0, 6 * segs.count);
      gl.depthMask(true);
      gl.disable(gl.BLEND);
      lines += segs.count;
      drawCalls += 1;
    }
    gl.bindVertexArray(null);
    return [triangles, lines, drawCalls];
  }

  // The camera the worker needs for the hybrid selection (eq. 4.1) at the canvas's pixel size.
  // Always at the full drawing buffer size (a governed frame's smaller buffer would pick lines
  // for what is a card at full size).
  viewFor(camera) {
    const [width, height] = drawingBufferSize(this.canvas);
    return { eye: camera.position(), target: [...camera.target], fovY: camera.fov, width, height };
  }

  // False before init() (the frame draws nothing of it then).
  ready() {
    return Boolean(this.treeProgram);
  }

  // The ground under the tree (metres): {center, extent, shadowRadius, crownHeight}
  // (web/gl/ground.js groundUnder).
  footprint() {
    return { center: this.center, extent: this.extent, shadowRadius: this.shadowRadius, crownHeight: this.crownHeight || 0 };
  }

  // The tree's steps of a frame (web/gl/progressive_frame.js) under `view` ({viewProjection, eye,
  // light: the unit direction towards the sun}): the hybrid draw list, or the parts and the
  // selection's x-ray pass; cheap > 0 (a FrameGovernor's level while the view moves): a moving
  // full-mode tree as its hybrid scene when it is there, without the x-ray pass. Returns {steps,
  // totals: {triangles, lines, drawCalls, mode, cheap, selected (the highlight this frame draws)}}.
  layerSteps(view, cheap = 0) {
    const gl = this.gl;
    const { viewProjection, eye, light } = view;
    const steps = [];
    const out = { triangles: 0, lines: 0, drawCalls: 0, mode: 'full', cheap, selected: this.selected === NONE ? -1 : this.selected };
    // A moving full-mode tree at a cheap level: its hybrid scene while it is there.
    const motion = !this.hybrid && cheap > 0 && this.motionReady();
    if (this.hybrid || motion) {
      const list = motion ? this.motion.drawList : this.drawList;
      steps.push({ primitives: 0, setup: () => {}, draw: () => this.#renderHybrid(view, list) });
      const [tris, segs, calls] = this.#hybridCounts(list);
      out.triangles += tris;
      out.lines += segs;
      out.drawCalls += calls;
      out.mode = motion ? 'motion' : 'hybrid';
      return { steps, totals: out };
    }
    const t = this.treeProgram;
    const common = () => {
      gl.useProgram(t.program);
      gl.uniformMatrix4fv(t.uniforms.uViewProjection, false, viewProjection);
      gl.uniform3fv(t.uniforms.uLightDirection, light);
      gl.uniform3fv(t.uniforms.uCameraPosition, eye);
      this.#bindPoses(t);
      gl.vertexAttrib1f(3, 0);  // no highlight on parts without branch ids
      gl.vertexAttrib2f(6, 0, 0);  // no flutter on parts without uvs
      gl.vertexAttrib1f(7, 0);     // no occlusion on parts without it
      gl.uniform1f(t.uniforms.uLeafLength, this.leafLength);
      gl.uniform2f(t.uniforms.uXrayWiden, 0, 0);
      (view.shadow || this.#shadowMap()).bindFor(t, view.sun || null);
    };
    const flutter = this.#flutter();
    for (const [name, part] of Object.entries(this.parts)) {
      const look = PARTS[name];
      steps.push({
        primitives: part.count / 3,
        setup: () => {
          common();
          gl.uniform3fv(t.uniforms.uColor, look.color);
          gl.uniform3fv(t.uniforms.uColorVariation, look.variation);
          gl.uniform1f(t.uniforms.uDoubleSided, look.doubleSided);
          gl.uniform1f(t.uniforms.uCrownLight, name === 'leaves' ? 1 : 0);  // tree_textured.frag
          gl.uniform1f(t.uniforms.uSpecular, look.specular);
          gl.uniform1f(t.uniforms.uXray, 0);
          gl.uniform1f(t.uniforms.uFlutter, name === 'leaves' ? flutter : 0);
          this.#bindPartTextures(t, name);
          gl.bindVertexArray(part.vao);
        },
        draw: (first, n) => gl.drawElements(gl.TRIANGLES, 3 * n, gl.UNSIGNED_INT, 12 * first),
      });
      out.triangles += part.count / 3;
      out.drawCalls += 1;
    }
    // The selection once more, faintly through everything, so a branch behind leaves shows.
    const bark = this.parts.bark;
    if (this.selected !== NONE && bark && cheap === 0) {
      steps.push({
        primitives: bark.count / 3,
        setup: () => {
          common();
          gl.uniform1f(t.uniforms.uXray, 1);
          // XRAY_WIDEN_PX wider on screen, so however thin the twig it shows (tree.vert).
          gl.uniform2f(t.uniforms.uXrayWiden, XRAY_WIDEN_PX / gl.drawingBufferWidth, XRAY_WIDEN_PX / gl.drawingBufferHeight);
          gl.uniform1f(t.uniforms.uUseTexture, 0);
          gl.uniform3fv(t.uniforms.uColor, PARTS.bark.color);
          gl.uniform1f(t.uniforms.uDoubleSided, 0);
          gl.uniform1f(t.uniforms.uCrownLight, 0);
          gl.uniform1f(t.uniforms.uFlutter, 0);
          gl.disable(gl.DEPTH_TEST);
          gl.enable(gl.BLEND);
          gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
          gl.bindVertexArray(bark.vao);
        },
        draw: (first, n) => gl.drawElements(gl.TRIANGLES, 3 * n, gl.UNSIGNED_INT, 12 * first),
        teardown: () => {
          gl.disable(gl.BLEND);
          gl.enable(gl.DEPTH_TEST);
        },
      });
      out.triangles += bark.count / 3;
      out.drawCalls += 1;
    }
    return { steps, totals: out };
  }

  // The ShadowMap whose texture the samplers read: the frame's, or (a renderer alone) one of its own.
  #shadowMap() {
    if (this.frame?.shadowMap) return this.frame.shadowMap;
    return (this.ownShadow ||= new ShadowMap(this.gl));
  }

  // What the tree casts into the sun's shadow map now (web/gl/frame.js): its mesh and pose
  // ("mesh#pose"), or null (no tree yet). Hybrid mode casts from its full mesh too (its parts are
  // installed in both modes), so the ground's shadow is the same; its cards receive it, and
  // its map is drawn once per mesh and sun (at the pose then), not again for every pose: a full
  // mesh's shadow pass would cost hybrid mode's frames many times their own primitives.
  shadowKey() {
    if (!this.shadowProgram || Object.keys(this.parts).length === 0) return null;
    return `${this.meshSerial}#${this.hybrid ? 'hybrid' : this.poseSerial}`;
  }

  // The parts' steps into the shadow map (the frame's ShadowMap binds it in each setup), seen
  // through sun.matrix; leaves and flowers cut out by their texture's alpha, as drawn.
  shadowSteps(sun) {
    const gl = this.gl;
    const s = this.shadowProgram;
    const flutter = this.#flutter();
    return Object.entries(this.parts).map(([name, part]) => ({
      primitives: part.count / 3,
      setup: () => {
        gl.useProgram(s.program);
        gl.uniformMatrix4fv(s.uniforms.uSunViewProjection, false, sun.matrix);
        this.#bindPoses(s);
        gl.vertexAttrib2f(6, 0, 0);
        gl.uniform1f(s.uniforms.uLeafLength, this.leafLength);
        gl.uniform1f(s.uniforms.uFlutter, name === 'leaves' ? flutter : 0);
        const spec = TEXTURED[name];
        const map = spec && spec.alphaCutoff > 0 && this.textures[spec.map];
        gl.uniform1f(s.uniforms.uUseTexture, map ? 1 : 0);
        gl.uniform1f(s.uniforms.uAlphaCutoff, spec ? spec.alphaCutoff : 0);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, map ? map.texture : null);
        gl.uniform1i(s.uniforms.uBaseMap, 1);
        gl.activeTexture(gl.TEXTURE0);
        gl.disable(gl.CULL_FACE);
        gl.bindVertexArray(part.vao);
      },
      draw: (first, n) => gl.drawElements(gl.TRIANGLES, 3 * n, gl.UNSIGNED_INT, 12 * first),
      teardown: () => gl.bindVertexArray(null),
    }));
  }

  // ---- As a layer of a Frame (web/gl/frame.js) ----
  // The tree's box in metres (the last setTree's bounds), or null before a tree.
  worldBounds() {
    return this.treeBounds || null;
  }

  // Frees the context's objects this renderer made (a Frame's layer removed, or the page gone).
  dispose() {
    const gl = this.gl;
    super.dispose();
    ++this.treeUploads;  // an upload on its way is dropped
    for (const part of Object.values(this.parts)) {
      gl.deleteVertexArray(part.vao);
      part.buffers.forEach((b) => { if (!this.pool.owns(b)) gl.deleteBuffer(b); });
    }
    this.parts = {};
    this.pool.dispose();
    for (const t of Object.values(this.textures)) gl.deleteTexture(t.texture);
    this.textures = {};
    gl.deleteTexture(this.poseTexture);
    this.ownShadow?.dispose();
    this.ownShadow = null;
    for (const p of [this.treeProgram, this.pickProgram, this.atlasProgram, this.cardProgram, this.lineProgram, this.shadowProgram]) {
      if (p) gl.deleteProgram(p.program);
    }
    this.treeProgram = null;
  }

  // [triangles, lines, draw calls] of a hybrid draw list.
  #hybridCounts(list) {
    if (!list) return [0, 0, 0];
    return [list.cards ? list.cards.count / 3 : 0, list.lines ? list.lines.count : 0, (list.cards ? 1 : 0) + (list.lines ? 1 : 0)];
  }

  // The pose texture on unit 0 for a program with uPoses (and uTime for the flutter).
  #bindPoses(program) {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.poseTexture);
    gl.uniform1i(program.uniforms.uPoses, 0);
    if (program.uniforms.uTime) gl.uniform1f(program.uniforms.uTime, this.swayTime);
  }

  // Leaf flutter amplitude (fraction of the leaf length): grows with the wind, none at rest.
  #flutter() {
    if (!this.swaying) return 0;
    return 0.35 * Math.min(1, this.wind / 12);
  }

  // Highlights one branch (id) and, fainter, every branch growing from it (what a cut removes);
  // null clears the highlight.
  select(id) {
    this.selected = Number.isInteger(id) && id >= 0 ? id : NONE;
    if (!this.highlight || !this.parts.bark) return;
    // Nothing marked and nothing to mark: no upload (a big tree's highlight is megabytes).
    if (this.selected === NONE && !this.highlightMarked) return;
    this.highlightMarked = this.selected !== NONE;
    const parents = this.branchParents;
    const mark = new Float32Array(parents.length);  // per branch: 0, 0.5 above, 1 selected
    if (this.selected !== NONE && this.selected < parents.length) {
      mark[this.selected] = 1;
      // Parents come before their children (ids grow with time), so one pass in id order suffices.
      for (let b = this.selected + 1; b < parents.length; ++b) {
        const p = parents[b];
        if (p >= 0 && mark[p] > 0) mark[b] = 0.5;
      }
    }
    for (let v = 0; v < this.branchIds.length; ++v) this.highlight[v] = mark[this.branchIds[v]] || 0;
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.highlightBuffer);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.highlight);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
  }

  // Branch id under canvas pixel (x, y) in CSS pixels from the top left, or null: draws the bark's
  // branch ids into an offscreen framebuffer and reads a small square around the point (the
  // nearest hit wins, so thin twigs can be clicked).
  pick(camera, x, y, radius = 4) {
    const gl = this.gl;
    const bark = this.parts.bark;
    if (!this.pickProgram || !bark || !bark.picking) return null;
    // The last frame's drawing-buffer size, the canvas left alone (resizing it blanks it).
    const [w, h] = drawingBufferSize(this.canvas, this.scale);
    const scale = w / Math.max(1, this.canvas.clientWidth);
    const px = Math.round(x * scale), py = Math.round(h - 1 - y * scale);
    const r = Math.round(radius * scale);
    this.pickTarget.begin(w, h, px, py, r);
    const p = this.pickProgram;
    gl.useProgram(p.program);
    gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, camera.viewProjection(w / h));
    this.#bindPoses(p);
    gl.bindVertexArray(bark.vao);
    gl.drawElements(gl.TRIANGLES, bark.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
    return this.pickTarget.read(px, py, r);
  }
}
