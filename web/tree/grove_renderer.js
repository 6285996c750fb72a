// WebGL2 renderer of the grove page: a few unique trees drawn many times with instancing, in full
// mode (bark/leaves/flowers meshes) or hybrid mode (thesis ch. 4: each unique tree's card atlas,
// shared by all its instances, and one draw list of cards + lines per (unique tree, distance band)).
// Wind: every instance is skinned to its own sway poses (one pose texture per unique tree, instance
// k's node point j at texel (k · nodes + j) · 4, as shaders/common/skin.glsl reads them).
// A StudyLayer (web/gl/frame.js): a layer of the page's Frame (layerSteps: the grove under the
// frame's camera and sun; the frame draws the ground under its footprint), so another study's layer
// can be drawn beside it (tests/browser/frame_layers.test.mjs).
// Does not: grow trees, lay out the grove, choose draw lists (grove_page.js and the worker do) or
// pace its frames (the page's FrameLoop calls frame.render).
import { finishGpu } from '../gl/context.js';
import { floatAttribute, staticBuffer, uintAttribute, viewOf } from '../gl/buffers.js';
import { StudyLayer } from '../gl/frame.js';
import { loadPrograms } from '../gl/program.js';
import { restPoses, uploadPoses } from '../gl/textures.js';
import { PARTS, SHADERS, paintAtlas } from './tree_renderer.js';

const SEGMENT_ROW = 1024;  // texels per row of a line-segment texture (grove_line.vert)
const SEGMENT_TEXELS = 4;  // p0 + width, p1, colour, skin (joint0, joint1, weight0, weight1)
// Per band member: x, y, z, scale, width scale, pose block, turn about y (radians; the grove's 0).
export const MEMBER_FLOATS = 7;

export class GroveRenderer extends StudyLayer {
  // target: the page's Frame ({canvas, gl}: a layer of it, in metres) or a canvas (its own
  // context, drawn whole with drawWhole). Throws an Error with a readable message when WebGL2 is
  // missing. The sun: the frame's (StudyLayer.setSun sets every layer's).
  constructor(target) {
    super(target, { what: 'the grove', study: 'tree' });
    this.trees = [];      // per unique tree: {parts: {name: {vao, count}}, atlas, instances, ...}
    this.bands = new Map();  // `${tree}:${band}` -> {tree, vaoCards, cardCount, vaoLines, segments, texture, members}
    this.extent = 60;     // the ground's half-size (metres)
    this.mode = 'hybrid';  // 'full' or 'hybrid': what layerSteps draws
    this.only = undefined;  // a unique tree index drawn alone, -1 for none (the coverage check), undefined for all
  }

  async init(shaderBase = SHADERS) {
    const p = await loadPrograms(this.gl, shaderBase, {
      tree: ['grove_tree.vert', 'tree.frag'], card: ['grove_card.vert', 'card.frag'],
      line: ['grove_line.vert', 'grove_line.frag'], atlas: ['atlas.vert', 'tree.frag'],
    });
    this.treeProgram = p.tree;
    // tree.frag's base map (read only by the atlas, uUseTexture 1) on the pose unit of the full
    // trees' draws: an active sampler never points at another unit's texture of another kind.
    this.gl.useProgram(p.tree.program);
    this.gl.uniform1i(p.tree.uniforms.uBaseMap, 1);
    this.gl.useProgram(null);
    this.cardProgram = p.card;
    this.lineProgram = p.line;
    this.atlasProgram = p.atlas;
  }

  // False before init() (the frame draws nothing of it then).
  ready() {
    return Boolean(this.treeProgram);
  }

  // The ground under the grove (web/gl/ground.js groundUnder): a square of half-size `extent`
  // around the origin, with no single contact shadow (its offset is moved far away).
  footprint() {
    return { center: [0, 0, 0], extent: this.extent, shadowRadius: 0.05, crownHeight: 0, shadowOffset: [1e4, 1e4] };
  }

  // Per-instance attributes on the bound VAO: `location` = vec4 (x, y, z, scale) from `b` (stride
  // `floats` floats) and, when floats is MEMBER_FLOATS, location + 1 = the width scale
  // (grove_line.vert), location + 2 = the instance's pose block (grove_card/line.vert) and
  // location + 3 = its turn about y.
  #instanceAttributes(b, floats, location = 7) {
    floatAttribute(this.gl, location, b, 4, floats * 4, 0, 1);
    if (floats === MEMBER_FLOATS) {
      for (const k of [1, 2, 3]) floatAttribute(this.gl, location + k, b, 1, floats * 4, 12 + 4 * k, 1);
    }
  }

  // Per-vertex sway skin on the bound VAO: joints (Uint32, location 4) and weights (location 5).
  #skinAttributes(joints, weights) {
    const buffers = [staticBuffer(this.gl, joints), staticBuffer(this.gl, weights)];
    uintAttribute(this.gl, 4, buffers[0], 1);
    floatAttribute(this.gl, 5, buffers[1], 1);
    return buffers;
  }

  // Unique tree `index`: the worker's mesh (bark/leaves/flowers ArrayBuffers with their sway skin)
  // drawn at every instance of `instances` (Float32Array, 4 per instance: x, y, z, scale; instance
  // k uses pose block k), `nodes` sway node points (the worker's swayNodes), poses at rest, and its
  // card atlas painted once from the worker's hybrid geometry (null: no hybrid mode for this tree);
  // bounds: the tree's box in its own metres (stats.bounds), which grows the grove's worldBounds.
  addTree(index, mesh, instances, hybrid, nodes = 1, bounds = null) {
    const gl = this.gl;
    const instanceBuffer = staticBuffer(gl, instances);
    const parts = {};
    for (const name of Object.keys(PARTS)) {
      const data = mesh[name];
      if (!data || data.indices.byteLength === 0) continue;
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const buffers = [staticBuffer(gl, data.positions), staticBuffer(gl, data.normals)];
      floatAttribute(gl, 0, buffers[0], 3);
      floatAttribute(gl, 1, buffers[1], 3);
      buffers.push(...this.#skinAttributes(data.joints, data.weights));
      this.#instanceAttributes(instanceBuffer, 4);
      buffers.push(staticBuffer(gl, data.indices, gl.ELEMENT_ARRAY_BUFFER));
      gl.bindVertexArray(null);
      parts[name] = { vao, count: data.indices.byteLength / 4, buffers };
    }
    this.trees[index] = {
      parts, instanceBuffer, instances: instances.length / 4, atlas: hybrid ? this.#paintAtlas(hybrid) : null,
      nodes: Math.max(1, nodes), poseTexture: gl.createTexture(), poseRows: 0,
    };
    this.setRestPoses(index);
    if (bounds) this.#growBounds(instances, bounds);
  }

  // Unique tree `index` drawn only in hybrid mode (the garden's far copies, web/garden/garden_hybrid.js):
  // its card atlas painted from the worker's hybrid geometry (as addTree's), no full mesh, poses at
  // rest for `instances` copies of `nodes` node points (a band member's pose block: its copy's
  // index; setPoses sways them). textures: null (plain colours) or
  // {bark: {texture}}: a simulated bark's base colour map, which the atlas's bark is painted from
  // through the geometry's bark uvs (the worker wraps its tile, as the full trees').
  addCards(index, hybrid, textures = null, instances = 1, nodes = 1) {
    this.#dropTree(this.trees[index]);
    this.trees[index] = { parts: {}, instanceBuffer: null, instances: Math.max(1, instances), atlas: this.#paintAtlas(hybrid, textures), nodes: Math.max(1, nodes), poseTexture: this.gl.createTexture(), poseRows: 0 };
    this.setRestPoses(index);
  }

  // Frees one unique tree's meshes, atlas and pose texture.
  #dropTree(tree) {
    if (!tree) return;
    const gl = this.gl;
    for (const part of Object.values(tree.parts)) {
      gl.deleteVertexArray(part.vao);
      part.buffers.forEach((b) => gl.deleteBuffer(b));
    }
    if (tree.instanceBuffer) gl.deleteBuffer(tree.instanceBuffer);
    if (tree.atlas) gl.deleteTexture(tree.atlas);
    gl.deleteTexture(tree.poseTexture);
  }

  // Every unique tree and band dropped (the garden's trees replaced).
  clearTrees() {
    this.setBands([]);  // (aborts a frame in parts: its steps read these trees)
    for (const tree of this.trees) this.#dropTree(tree);
    this.trees = [];
  }

  // The grove's box (metres, worldBounds) grown by every instance (x, y, z, scale) of a tree of box
  // `bounds` in its own frame.
  #growBounds(instances, bounds) {
    for (let i = 0; i < instances.length; i += 4) {
      const s = instances[i + 3];
      const min = [0, 1, 2].map((k) => instances[i + k] + s * bounds.min[k]);
      const max = [0, 1, 2].map((k) => instances[i + k] + s * bounds.max[k]);
      if (!this.boundsView) this.boundsView = { min, max };
      else for (let k = 0; k < 3; ++k) {
        this.boundsView.min[k] = Math.min(this.boundsView.min[k], min[k]);
        this.boundsView.max[k] = Math.max(this.boundsView.max[k], max[k]);
      }
    }
  }

  // Sway poses of unique tree `index`: Float32Array (the worker's 'pose'), instances × nodes × 16
  // floats; instance k's node point j at floats (k · nodes + j) · 16.
  setPoses(index, poses) {
    const gl = this.gl, tree = this.trees[index];
    if (!tree) return;
    const points = tree.instances * tree.nodes;
    tree.poseRows = uploadPoses(gl, tree.poseTexture, poses, points, tree.poseRows);
  }

  // Every instance of unique tree `index` at rest (identity poses: the grown shape exactly).
  setRestPoses(index) {
    const tree = this.trees[index];
    if (!tree) return;
    this.setPoses(index, restPoses(tree.instances * tree.nodes));
  }

  // The pose texture of a unique tree on unit 1 for a program with uPoses and uNodes.
  #bindPoses(program, tree) {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, tree.poseTexture);
    gl.uniform1i(program.uniforms.uPoses, 1);
    gl.uniform1i(program.uniforms.uNodes, tree.nodes);
    gl.activeTexture(gl.TEXTURE0);
  }

  // The card atlas of one unique tree (thesis 4.2.1), painted once from clip-space triangles, lit
  // by the sun like the full view, transparent elsewhere, mipmapped; shared by all its instances.
  // textures: paintAtlas's (kind -> {texture}), or null for the plain colours.
  #paintAtlas(hybrid, textures = null) {
    const gl = this.gl;
    const size = hybrid.atlasSize;
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texStorage2D(gl.TEXTURE_2D, Math.floor(Math.log2(size)) + 1, gl.RGBA8, size, size);
    if (!this.atlasDepth || this.atlasDepth.size !== size) {
      if (this.atlasDepth) gl.deleteRenderbuffer(this.atlasDepth.rb);
      const rb = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, rb);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, size, size);
      this.atlasDepth = { rb, size };
    }
    const fb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.atlasDepth.rb);
    paintAtlas(gl, this.atlasProgram, hybrid, fb, texture, this.light, textures);
    gl.deleteFramebuffer(fb);
    return texture;
  }

  // Replaces every band's draw list at once. lists: [{tree, band, cards, lines, members}] with the
  // worker's 'drawList' buffers (with the sway skin: cards.joints/weights per vertex,
  // lines.joints/weights 2 per segment) and members = Float32Array, MEMBER_FLOATS per instance
  // (x, y, z, scale, width scale, pose block = the instance's index among its unique tree's
  // instances, turn about y).
  setBands(lists) {
    const gl = this.gl;
    this.progress.abort();  // a frame in parts must not draw the bands deleted here
    for (const band of this.bands.values()) {
      band.buffers.forEach((b) => gl.deleteBuffer(b));
      if (band.vaoCards) gl.deleteVertexArray(band.vaoCards);
      if (band.vaoLines) gl.deleteVertexArray(band.vaoLines);
      if (band.texture) gl.deleteTexture(band.texture);
    }
    this.bands = new Map();
    for (const list of lists) {
      const members = staticBuffer(gl, list.members);
      const band = { tree: list.tree, buffers: [members], instances: list.members.length / MEMBER_FLOATS, cardCount: 0, segments: 0 };
      const c = list.cards;
      if (c.indices.byteLength > 0) {
        band.vaoCards = gl.createVertexArray();
        gl.bindVertexArray(band.vaoCards);
        for (const [location, bytes, size] of [[0, c.positions, 3], [1, c.uvs, 2]]) {
          band.buffers.push(staticBuffer(gl, bytes));
          floatAttribute(gl, location, band.buffers.at(-1), size);
        }
        band.buffers.push(...this.#skinAttributes(c.joints, c.weights));
        this.#instanceAttributes(members, MEMBER_FLOATS);
        band.buffers.push(staticBuffer(gl, c.indices, gl.ELEMENT_ARRAY_BUFFER));
        gl.bindVertexArray(null);
        band.cardCount = c.indices.byteLength / 4;
      }
      const l = list.lines;
      const segments = l.widths.byteLength / 4;
      if (segments > 0) {
        // One texture per draw list: 4 RGBA32F texels per segment (p0 + width, p1, colour, skin:
        // joint0, joint1 as floats (exact below 2^24), weight0, weight1).
        // The width is the draw list's D_i (pixels, may be below 1: grove_line.vert blends by it).
        // Segments no instance of the band sees wider than a pixel go last: they are drawn as
        // gl.LINES (2 vertices each), the others as quads (4 indexed vertices each).
        let widest = 0;
        for (let i = 4; i < list.members.length; i += MEMBER_FLOATS) widest = Math.max(widest, list.members[i]);
        const p = viewOf(Float32Array, l.positions), col = viewOf(Float32Array, l.colors), w = viewOf(Float32Array, l.widths);
        const joints = viewOf(Uint32Array, l.joints), weights = viewOf(Float32Array, l.weights);
        const order = [];
        for (let s = 0; s < segments; ++s) if (w[s] * widest > 1) order.push(s);
        band.thick = order.length;
        for (let s = 0; s < segments; ++s) if (!(w[s] * widest > 1)) order.push(s);
        const rows = Math.ceil((segments * SEGMENT_TEXELS) / SEGMENT_ROW);
        const data = new Float32Array(rows * SEGMENT_ROW * 4);
        const skinned = joints.length === 2 * segments && weights.length === 2 * segments;
        order.forEach((s, k) => {
          const o = k * SEGMENT_TEXELS * 4;
          data.set(p.subarray(s * 6, s * 6 + 3), o);
          data[o + 3] = w[s];
          data.set(p.subarray(s * 6 + 3, s * 6 + 6), o + 4);
          data.set(col.subarray(s * 3, s * 3 + 3), o + 8);
          if (skinned) data.set([joints[2 * s], joints[2 * s + 1], weights[2 * s], weights[2 * s + 1]], o + 12);
        });
        band.texture = gl.createTexture();
        gl.bindTexture(gl.TEXTURE_2D, band.texture);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, SEGMENT_ROW, rows, 0, gl.RGBA, gl.FLOAT, data);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
        gl.bindTexture(gl.TEXTURE_2D, null);
        band.vaoLines = gl.createVertexArray();
        gl.bindVertexArray(band.vaoLines);
        this.#instanceAttributes(members, MEMBER_FLOATS, 0);  // no per-vertex attributes: the segments are a texture
        if (band.thick > 0) gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.#quadIndices(band.thick));
        gl.bindVertexArray(null);
        band.segments = segments;
      }
      this.bands.set(`${list.tree}:${list.band}`, band);
    }
  }

  // Indices of `segments` quads (vertices 4 s .. 4 s + 3; triangles 0 1 2 and 2 1 3), shared by
  // every line draw list and grown when needed: 4 vertices per segment instead of 6.
  #quadIndices(segments) {
    const gl = this.gl;
    if (!this.quads || this.quads.segments < segments) {
      const count = Math.max(segments, 2 * (this.quads?.segments || 1024));
      const indices = new Uint32Array(count * 6);
      for (let s = 0; s < count; ++s) indices.set([4 * s, 4 * s + 1, 4 * s + 2, 4 * s + 2, 4 * s + 1, 4 * s + 3], s * 6);
      if (this.quads) gl.deleteBuffer(this.quads.buffer);  // VAOs keep a deleted buffer alive
      this.quads = { buffer: gl.createBuffer(), segments: count };
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.quads.buffer);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    }
    return this.quads.buffer;
  }

  // The grove's steps of a frame (web/gl/progressive_frame.js) under `view` ({viewProjection, eye,
  // light: the unit direction towards the sun, width, height}), in `this.mode` ('full' or
  // 'hybrid'), every unique tree or `this.only`'s alone (-1: none, the coverage check). Each step
  // is drawn whole (instanced draws: primitives 0). Returns {steps, totals: {triangles, lines
  // (segments), drawCalls, instances (tree instances), uniqueDrawn (unique trees), mode}}.
  layerSteps(view) {
    const gl = this.gl;
    const { viewProjection, eye, light } = view;
    const mode = this.mode, only = this.only;
    const totals = { triangles: 0, lines: 0, drawCalls: 0, instances: 0, uniqueDrawn: 0, mode };
    const drawn = new Set();
    const wanted = (tree) => only === undefined || only === tree;
    const steps = [];
    const step = (draw) => steps.push({ primitives: 0, setup: () => {}, draw });

    if (mode === 'hybrid') {
      const cards = [...this.bands.values()].filter((band) => band.cardCount && wanted(band.tree) && this.trees[band.tree]?.atlas);
      const lines = [...this.bands.values()].filter((band) => band.segments && wanted(band.tree) && this.trees[band.tree]);
      step(() => {
        gl.disable(gl.CULL_FACE);
        gl.disable(gl.BLEND);
        const cp = this.cardProgram;
        gl.useProgram(cp.program);
        gl.uniformMatrix4fv(cp.uniforms.uViewProjection, false, viewProjection);
        gl.uniform1i(cp.uniforms.uAtlas, 0);
        gl.activeTexture(gl.TEXTURE0);
        for (const band of cards) {
          const tree = this.trees[band.tree];
          this.#bindPoses(cp, tree);
          gl.bindTexture(gl.TEXTURE_2D, tree.atlas);
          gl.bindVertexArray(band.vaoCards);
          gl.drawElementsInstanced(gl.TRIANGLES, band.cardCount, gl.UNSIGNED_INT, 0, band.instances);
        }
        const lp = this.lineProgram;
        gl.useProgram(lp.program);
        gl.uniformMatrix4fv(lp.uniforms.uViewProjection, false, viewProjection);
        gl.uniform2f(lp.uniforms.uViewport, view.width, view.height);  // the frame's drawing buffer
        gl.uniform1i(lp.uniforms.uSegments, 0);
        // Sub-pixel lines blend by their coverage; they leave the depth buffer to the cards.
        gl.enable(gl.BLEND);
        gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
        gl.depthMask(false);
        for (const band of lines) {
          this.#bindPoses(lp, this.trees[band.tree]);
          gl.bindTexture(gl.TEXTURE_2D, band.texture);
          gl.bindVertexArray(band.vaoLines);
          if (band.thick > 0) {
            gl.uniform1i(lp.uniforms.uThin, 0);
            gl.drawElementsInstanced(gl.TRIANGLES, band.thick * 6, gl.UNSIGNED_INT, 0, band.instances);
          }
          if (band.segments > band.thick) {
            gl.uniform1i(lp.uniforms.uThin, 1);
            gl.uniform1i(lp.uniforms.uFirst, band.thick);
            gl.drawArraysInstanced(gl.LINES, 0, (band.segments - band.thick) * 2, band.instances);
          }
        }
        gl.depthMask(true);
        gl.disable(gl.BLEND);
        gl.bindTexture(gl.TEXTURE_2D, null);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, null);
        gl.activeTexture(gl.TEXTURE0);
      });
      for (const band of cards) {
        totals.triangles += (band.cardCount / 3) * band.instances;
        totals.drawCalls += 1;
      }
      for (const band of lines) {
        totals.drawCalls += (band.thick > 0 ? 1 : 0) + (band.segments > band.thick ? 1 : 0);
        totals.lines += band.segments * band.instances;
      }
      for (const band of this.bands.values()) {
        if (!wanted(band.tree) || !(band.cardCount || band.segments)) continue;
        totals.instances += band.instances;
        drawn.add(band.tree);
      }
    } else {
      const t = this.treeProgram;
      const trees = [];
      this.trees.forEach((tree, index) => {
        if (!tree || !wanted(index)) return;
        trees.push(tree);
        for (const part of Object.values(tree.parts)) {
          totals.triangles += (part.count / 3) * tree.instances;
          totals.drawCalls += 1;
        }
        totals.instances += tree.instances;
        drawn.add(index);
      });
      step(() => {
        gl.disable(gl.CULL_FACE);
        gl.disable(gl.BLEND);
        gl.useProgram(t.program);
        gl.uniformMatrix4fv(t.uniforms.uViewProjection, false, viewProjection);
        gl.uniform3fv(t.uniforms.uLightDirection, light);
        gl.uniform3fv(t.uniforms.uCameraPosition, eye);
        gl.uniform1f(t.uniforms.uXray, 0);
        for (const tree of trees) {
          this.#bindPoses(t, tree);
          for (const [name, part] of Object.entries(tree.parts)) {
            const look = PARTS[name];
            gl.uniform3fv(t.uniforms.uColor, look.color);
            gl.uniform3fv(t.uniforms.uColorVariation, look.variation);
            gl.uniform1f(t.uniforms.uDoubleSided, look.doubleSided);
            gl.uniform1f(t.uniforms.uSpecular, look.specular);
            gl.bindVertexArray(part.vao);
            gl.drawElementsInstanced(gl.TRIANGLES, part.count, gl.UNSIGNED_INT, 0, tree.instances);
          }
        }
      });
    }
    totals.uniqueDrawn = drawn.size;
    return { steps, totals };
  }

  // Frees the context's objects this renderer made (a Frame's layer removed, or the page gone).
  dispose() {
    const gl = this.gl;
    super.dispose();
    this.clearTrees();
    if (this.atlasDepth) gl.deleteRenderbuffer(this.atlasDepth.rb);
    this.atlasDepth = null;
    if (this.quads) gl.deleteBuffer(this.quads.buffer);
    this.quads = null;
    for (const p of [this.treeProgram, this.cardProgram, this.lineProgram, this.atlasProgram]) {
      if (p) gl.deleteProgram(p.program);
    }
    this.treeProgram = null;
    this.boundsView = null;
  }

  // Blocks until the GPU has finished everything drawn so far: reads one pixel back.
  finish() {
    return finishGpu(this.gl);
  }

  // The whole canvas as RGBA bytes (bottom row first), for the coverage check.
  readCanvas() {
    const gl = this.gl;
    const data = new Uint8Array(this.canvas.width * this.canvas.height * 4);
    gl.readPixels(0, 0, this.canvas.width, this.canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, data);
    return data;
  }
}
