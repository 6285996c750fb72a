// The bark page's WebGL2 view (shaders/bark/): the unrolled tile (circumference × height of the
// patch, facing the camera) and, beside it, a trunk segment of the patch's radius and height
// wearing the maps (base colour lit through the normal map and the occlusion, shaders/bark/
// bark_light.glsl, by a key light fixed in the world, up and to the front left, that grazes the
// relief). The tile shows the maps lit the same way ('lit'; 'tiled': repeated 2 × 2 at half size,
// so the seams around and along are in view), the base-colour map itself ('maps'),
// or the lattice's triangles as the run has them ('plates':
// the surface's plates with each triangle whose edge broke dropped, so the cracks show the inner
// layer; 'strain': the plates as a heat map of their stretch over their break strain; 'layers':
// each triangle in the colour of the layer showing in it, S, M1, M2 or the inner layer, the
// 4-layer model's layer colouring; 'peel': each triangle by its S nodes' peel state, bonded,
// peeling or peeled off), and over any of them, toggled, the surface's broken springs as red
// segments (setShowBroken); with a
// step set (setStep, the cycle scrubber) the triangles broken by then are dropped, so the cracks
// replay without a new grow (the triangles stay at the run's final positions: the plates' recoil
// is not replayed, only which springs had broken). Coordinates are the patch's centimetres (x around, y up the trunk);
// uModel centres the scene and scales it to about ten view units (a Frame of fit: true).
// A StudyLayer (web/gl/frame.js), a layer of a Frame (layerSteps, under its camera and sun).
// Does not: talk to the worker, know the model, or replay the 4-layer layers and peel states over
// the cycles (they are the end's).
import { floatAttribute, staticBuffer } from '../gl/buffers.js';
import { StudyLayer } from '../gl/frame.js';
import { loadPrograms } from '../gl/program.js';
import { imageTexture } from '../gl/textures.js';

const SHADERS = new URL('../../shaders/bark/', import.meta.url);
const VIEW_SIZE = 10;    // the scene's width in view units
const GAP = 4;           // cm between the tile and the trunk
const AROUND = 96;       // the trunk's segments around
const VIEW_MODES = { plates: 0, strain: 1, layers: 2, peel: 3 };
const QUAD_MODES = { lit: 0, inner: 1, maps: 2, tiled: 0 };
// The key light (unit, towards it): up, to the left and in front of the tile.
const KEY_LIGHT = (() => {
  const v = [-0.55, 0.5, 0.67];
  const n = Math.hypot(...v);
  return new Float32Array(v.map((x) => x / n));
})();

// The cylinder's (angle, height share) vertices as triangles.
function cylinder() {
  const v = [];
  for (let k = 0; k < AROUND; ++k) {
    const a = (2 * Math.PI * k) / AROUND, b = (2 * Math.PI * (k + 1)) / AROUND;
    v.push(a, 0, b, 0, b, 1, a, 0, b, 1, a, 1);
  }
  return new Float32Array(v);
}

export class BarkRenderer extends StudyLayer {
  // target: a canvas or a Frame (a layer of it).
  constructor(target) {
    super(target, { what: 'the bark', study: 'ivy' });
    this.tile = null;     // {vao, buffers, count}: the lattice's triangles
    this.maps = null;     // {base, normal, orm: textures, width, height}
    this.patch = [1, 1];  // circumference, height (cm)
    this.radius = 1;
    this.model = [0, 0, 0, 1];
    this.view = 'lit';
    this.step = Infinity;
    this.live = false;    // the tile is a run still growing (or a preview): no maps for it yet
    this.springs = null;  // {vao, buffers, count}: the broken springs' segments
    this.showBroken = false;
  }

  async init() {
    this.programs = await loadPrograms(this.gl, SHADERS.href, {
      plates: ['plates.vert', 'plates.frag'],
      quad: ['quad.vert', 'quad.frag'],
      trunk: ['trunk.vert', 'trunk.frag'],
      springs: ['springs.vert', 'springs.frag'],
    });
    const gl = this.gl;
    this.quad = { vao: gl.createVertexArray() };
    gl.bindVertexArray(this.quad.vao);
    this.quad.buffer = staticBuffer(gl, new Float32Array([0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1]));
    floatAttribute(gl, 0, this.quad.buffer, 2);
    this.trunk = { vao: gl.createVertexArray(), count: AROUND * 6 };
    gl.bindVertexArray(this.trunk.vao);
    this.trunk.buffer = staticBuffer(gl, cylinder());
    floatAttribute(gl, 0, this.trunk.buffer, 2);
    gl.bindVertexArray(null);
  }

  ready() {
    return Boolean(this.programs);
  }

  #dropTile() {
    if (!this.tile) return;
    this.gl.deleteVertexArray(this.tile.vao);
    for (const b of this.tile.buffers) this.gl.deleteBuffer(b);
    this.tile = null;
  }

  // The lattice's triangles (a frame of a run growing, a preview, or the finished run): tile =
  // {positions, stretch, broken} views (used at once); bounds: {circumference, height, radius}.
  // live: no maps belong to it (the maps drawn stay those of the last finished run, off the tile).
  setTile(tile, bounds, { live = false } = {}) {
    const gl = this.gl;
    this.progress.abort();
    this.#dropTile();
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const n = tile.stretch.byteLength / 4;
    const zeros = new Float32Array(n);
    const buffers = [tile.positions, tile.stretch, tile.broken, tile.layer ?? zeros, tile.peel ?? zeros].map((b) => staticBuffer(gl, b));
    floatAttribute(gl, 0, buffers[0], 2);
    for (let k = 1; k < 5; ++k) floatAttribute(gl, k, buffers[k], 1);
    gl.bindVertexArray(null);
    this.tile = { vao, buffers, count: n };
    this.live = live;
    this.#setPatch(bounds);
  }

  // The surface's broken springs ({positions, broken} views, used at once), or null.
  setSprings(springs) {
    const gl = this.gl;
    if (this.springs) {
      gl.deleteVertexArray(this.springs.vao);
      for (const b of this.springs.buffers) gl.deleteBuffer(b);
      this.springs = null;
    }
    if (!springs || springs.broken.byteLength === 0) return;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [springs.positions, springs.broken].map((b) => staticBuffer(gl, b));
    floatAttribute(gl, 0, buffers[0], 2);
    floatAttribute(gl, 1, buffers[1], 1);
    gl.bindVertexArray(null);
    this.springs = { vao, buffers, count: springs.broken.byteLength / 4 };
  }

  // Draw the broken springs over the tile.
  setShowBroken(on) {
    this.showBroken = Boolean(on);
  }

  // The maps of the finished run (or the preview's): {base_colour, normal, orm} RGBA pixels of
  // width × height.
  setMaps(maps, width, height) {
    const gl = this.gl;
    this.#dropMaps();
    this.maps = {
      base: imageTexture(gl, { pixels: maps.base_colour, width, height }, gl.REPEAT),
      normal: imageTexture(gl, { pixels: maps.normal, width, height }, gl.REPEAT),
      orm: imageTexture(gl, { pixels: maps.orm, width, height }, gl.REPEAT),
      width, height,
    };
    this.live = false;
  }

  #dropMaps() {
    if (!this.maps) return;
    for (const t of [this.maps.base, this.maps.normal, this.maps.orm]) this.gl.deleteTexture(t);
    this.maps = null;
  }

  // The three maps on texture units 0, 1, 2 of program p.
  #bindMaps(p) {
    const gl = this.gl;
    [this.maps.base, this.maps.normal, this.maps.orm].forEach((texture, unit) => {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, texture);
    });
    gl.activeTexture(gl.TEXTURE0);
    gl.uniform1i(p.uniforms.uBaseColour, 0);
    gl.uniform1i(p.uniforms.uNormalMap, 1);
    gl.uniform1i(p.uniforms.uOrm, 2);
  }

  #setPatch(bounds) {
    this.patch = [bounds.circumference, bounds.height];
    this.radius = bounds.radius;
    const width = this.patch[0] + GAP + 2 * this.radius;
    const scale = this.fitView ? VIEW_SIZE / width : 0.01;  // fitted, or metres
    this.model = [width / 2, this.patch[1] / 2, 0, scale];
    const h = (this.patch[1] / 2) * scale, w = (width / 2) * scale, r = this.radius * scale;
    this.boundsView = { min: [-w, -h, -r], max: [w, h, r] };
  }

  // 'lit', 'tiled', 'maps', 'plates', 'strain', 'layers' or 'peel'.
  setView(view) {
    this.view = view;
  }

  // The step shown (Infinity: the end): triangles broken after it are drawn whole.
  setStep(step) {
    this.step = step;
  }

  bounds() {
    return this.boundsView;
  }

  // What the tile shows now: the maps only at the end of a finished run in a maps view.
  get tileShows() {
    if (['lit', 'tiled', 'maps'].includes(this.view) && this.maps && !this.live && !Number.isFinite(this.step)) return this.view;
    return ['strain', 'layers', 'peel'].includes(this.view) ? this.view : 'plates';
  }

  layerSteps(view) {
    const gl = this.gl;
    const { viewProjection: vp, eye } = view;
    const totals = { triangles: 0, lines: 0, drawCalls: 0, primitives: 0 };
    const steps = [];
    if (!this.tile) return { steps, totals };
    const [C, H] = this.patch;
    // The patch and its copies shifted back over the seams (around, along, both): the torus (the
    // bindings put every triangle's and segment's lowest corner inside the patch, so they overhang
    // only past the far edges).
    const shifts = [[0, 0], [-C, 0], [0, -H], [-C, -H]];
    const shows = this.tileShows;
    const quad = (mode, depth, repeat = 1) => {
      const p = this.programs.quad;
      steps.push({
        primitives: 2,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform2f(p.uniforms.uPatch, C, H);
          gl.uniform1f(p.uniforms.uDepth, depth);
          gl.uniform1f(p.uniforms.uRepeat, repeat);
          gl.uniform1i(p.uniforms.uMode, mode);
          gl.uniform3fv(p.uniforms.uKeyLight, KEY_LIGHT);
          gl.uniform3fv(p.uniforms.uEye, eye);
          if (mode !== QUAD_MODES.inner) this.#bindMaps(p);
          gl.disable(gl.CULL_FACE);
          gl.bindVertexArray(this.quad.vao);
        },
        draw: (first, n) => gl.drawArrays(gl.TRIANGLES, 3 * first, 3 * n),
      });
      totals.triangles += 2;
      totals.primitives += 2;
      ++totals.drawCalls;
    };
    if (shows === 'lit' || shows === 'tiled' || shows === 'maps') {
      quad(QUAD_MODES[shows], 0, shows === 'tiled' ? 2 : 1);
    } else {
      quad(QUAD_MODES.inner, -0.05);
      const p = this.programs.plates, tile = this.tile;
      const step = Number.isFinite(this.step) ? this.step : 1e12;
      for (const shift of shifts) {
        steps.push({
          primitives: tile.count / 3,
          setup: () => {
            gl.useProgram(p.program);
            gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
            gl.uniform4fv(p.uniforms.uModel, this.model);
            gl.uniform2f(p.uniforms.uShift, shift[0], shift[1]);
            gl.uniform2f(p.uniforms.uPatch, C, H);
            gl.uniform1f(p.uniforms.uStep, step);
            gl.uniform1i(p.uniforms.uMode, VIEW_MODES[shows] ?? 0);
            gl.disable(gl.CULL_FACE);
            gl.bindVertexArray(tile.vao);
          },
          draw: (first, n) => gl.drawArrays(gl.TRIANGLES, 3 * first, 3 * n),
        });
        totals.triangles += tile.count / 3;
        totals.primitives += tile.count / 3;
        ++totals.drawCalls;
      }
    }
    if (this.showBroken && this.springs) {
      const p = this.programs.springs, lines = this.springs;
      const step = Number.isFinite(this.step) ? this.step : 1e12;
      for (const shift of shifts) {
        steps.push({
          primitives: lines.count / 2,
          setup: () => {
            gl.useProgram(p.program);
            gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
            gl.uniform4fv(p.uniforms.uModel, this.model);
            gl.uniform2f(p.uniforms.uShift, shift[0], shift[1]);
            gl.uniform2f(p.uniforms.uPatch, C, H);
            gl.uniform1f(p.uniforms.uStep, step);
            gl.uniform1f(p.uniforms.uDepth, 0.05);
            gl.bindVertexArray(lines.vao);
          },
          draw: (first, n) => gl.drawArrays(gl.LINES, 2 * first, 2 * n),
        });
        totals.lines += lines.count / 2;
        totals.primitives += lines.count / 2;
        ++totals.drawCalls;
      }
    }
    if (this.maps) {
      const p = this.programs.trunk;
      steps.push({
        primitives: this.trunk.count / 3,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform3f(p.uniforms.uCentre, C + GAP + this.radius, 0, 0);
          gl.uniform2f(p.uniforms.uSize, this.radius, H);
          gl.uniform3fv(p.uniforms.uKeyLight, KEY_LIGHT);
          gl.uniform3fv(p.uniforms.uEye, eye);
          this.#bindMaps(p);
          gl.enable(gl.CULL_FACE);
          gl.cullFace(gl.BACK);
          gl.bindVertexArray(this.trunk.vao);
        },
        draw: (first, n) => gl.drawArrays(gl.TRIANGLES, 3 * first, 3 * n),
      });
      totals.triangles += this.trunk.count / 3;
      totals.primitives += this.trunk.count / 3;
      ++totals.drawCalls;
    }
    return { steps, totals };
  }

  dispose() {
    super.dispose();
    this.#dropTile();
    this.setSprings(null);
    const gl = this.gl;
    this.#dropMaps();
    for (const part of [this.quad, this.trunk]) {
      if (!part) continue;
      gl.deleteVertexArray(part.vao);
      gl.deleteBuffer(part.buffer);
    }
    for (const p of Object.values(this.programs || {})) gl.deleteProgram(p.program);
    this.programs = null;
  }
}
