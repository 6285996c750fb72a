// The terrain page's WebGL2 view (shaders/terrain/): the heightfield surface, hillshaded with the
// hypsometric tint (or plain grey), and the contour lines at their heights over it. Positions stay
// in metres as the worker sends them ((x, h, −y), y up); uModel centres the mountain and scales its
// plan extent to about ten view units so one orbit camera fits every seed. The level scrubber
// (setLevel) shows the mountain as it stands at level k: contours up to k, the surface cut at
// h0 + k·Δh; nothing regrows.
// A StudyLayer (web/gl/frame.js), a layer of a Frame (layerSteps, under the frame's camera and
// sun): fitted to a view of ten units in a Frame of fit: true (the terrain page, <niwa-terrain>),
// else in metres about the mountain's plan centre at its lowest height, times `unitScale` (beside
// other studies).
// Does not: talk to the worker, draw the 2-D plan (plan_view.js), or know the generation methods.
import { floatAttribute, viewOf } from '../gl/buffers.js';
import { uploadInParts } from '../gl/chunked_upload.js';
import { StudyLayer } from '../gl/frame.js';
import { loadPrograms } from '../gl/program.js';
import { ramp } from './plan_view.js';

const SHADERS = new URL('../../shaders/terrain/', import.meta.url);
const VIEW_SIZE = 10;  // the mountain's plan extent in view units

export class TerrainRenderer extends StudyLayer {
  // target: a canvas (the renderer makes its context) or a Frame ({canvas, gl}: a layer of it).
  // Alone, the plan extent is fitted to VIEW_SIZE view units.
  constructor(target, { unitScale = 1 } = {}) {
    super(target, { what: 'the mountain', study: 'terrain' });  // web/gl/sun.js: a low sun from the north-west
    this.unitScale = unitScale;
    this.surface = null;   // {vao, buffers, count}
    this.contours = null;  // {vao, buffers, count}
    this.model = [0, 0, 0, 1];
    this.visible = { contours: true, tint: true };
    this.level = Infinity;
    this.top = Infinity;
    this.lineLevels = new Float32Array(0);  // sorted level of every contour line segment
    this.terrainUploads = 0;  // setTerrain calls so far (a newer one drops an older upload)
    this.uploading = false;   // a mountain is going up in parts
  }

  async init() {
    this.programs = await loadPrograms(this.gl, SHADERS.href, {
      surface: ['surface.vert', 'surface.frag'],
      contour: ['contour.vert', 'contour.frag'],
    });
  }

  #drop(part) {
    if (!part) return;
    this.gl.deleteVertexArray(part.vao);
    for (const b of part.buffers) this.gl.deleteBuffer(b);
  }

  // buffers: {surface: {positions, normals, colours, indices}, contours: {positions, level}}
  // (ArrayBuffers or views from the worker); bounds: {min: [x, y], max: [x, y], h_min, h_max} in metres.
  // The buffers go up in parts (web/gl/chunked_upload.js: a res-1024 surface is 60 MB) while the
  // old mountain stays; `uploading` is true until the new one is in place. Resolves to true then,
  // or to false when a newer setTerrain dropped this one.
  setTerrain(buffers, bounds) {
    const gl = this.gl;
    const serial = ++this.terrainUploads;
    const s = buffers.surface, c = buffers.contours;
    const plan = [];
    if (s.indices.byteLength > 0) {
      plan.push({ key: 'positions', bytes: s.positions, target: gl.ARRAY_BUFFER }, { key: 'normals', bytes: s.normals, target: gl.ARRAY_BUFFER },
        { key: 'colours', bytes: s.colours, target: gl.ARRAY_BUFFER }, { key: 'indices', bytes: s.indices, target: gl.ELEMENT_ARRAY_BUFFER });
    }
    if (c.positions.byteLength > 0) {
      plan.push({ key: 'linePositions', bytes: c.positions, target: gl.ARRAY_BUFFER }, { key: 'lineLevels', bytes: c.level, target: gl.ARRAY_BUFFER });
    }
    this.uploading = true;
    return uploadInParts(gl, plan, () => serial !== this.terrainUploads).then((uploaded) => {
      if (serial !== this.terrainUploads) {
        uploaded.forEach((b) => gl.deleteBuffer(b));
        return false;
      }
      this.#install(buffers, bounds, uploaded);
      this.uploading = false;
      return true;
    });
  }

  #install(buffers, bounds, uploaded) {
    const gl = this.gl;
    this.progress.abort();  // a frame in parts of the old buffers ends here
    this.#drop(this.surface);
    this.#drop(this.contours);
    this.surface = this.contours = null;
    if (uploaded.has('indices')) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const list = ['positions', 'normals', 'colours', 'indices'].map((key) => uploaded.get(key));
      floatAttribute(gl, 0, list[0], 3);
      floatAttribute(gl, 1, list[1], 3);
      floatAttribute(gl, 2, list[2], 3);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, list[3]);
      gl.bindVertexArray(null);
      this.surface = { vao, buffers: list, count: buffers.surface.indices.byteLength / 4 };
    }
    if (uploaded.has('linePositions')) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const list = [uploaded.get('linePositions'), uploaded.get('lineLevels')];
      floatAttribute(gl, 0, list[0], 3);
      floatAttribute(gl, 1, list[1], 1);
      gl.bindVertexArray(null);
      this.contours = { vao, buffers: list, count: buffers.contours.positions.byteLength / 12 };
      const levels = viewOf(Float32Array, buffers.contours.level);
      this.lineLevels = new Float32Array(levels.length / 2).map((_, i) => levels[2 * i]).sort();
    } else {
      this.lineLevels = new Float32Array(0);
    }
    const extent = Math.max(bounds.max[0] - bounds.min[0], bounds.max[1] - bounds.min[1], 1e-9);
    const scale = this.fitView ? VIEW_SIZE / extent : this.unitScale;
    const cx = (bounds.min[0] + bounds.max[0]) / 2, cy = (bounds.min[1] + bounds.max[1]) / 2;
    this.model = [cx, bounds.h_min, -cy, scale];
    this.heights = [bounds.h_min, bounds.h_max];
    const half = [(bounds.max[0] - bounds.min[0]) / 2 * scale, (bounds.max[1] - bounds.min[1]) / 2 * scale];
    this.boundsView = { min: [-half[0], 0, -half[1]], max: [half[0], (bounds.h_max - bounds.h_min) * scale, half[1]] };
  }

  // Level k (Infinity: all) and the surface's cut h0 + k·Δh in metres.
  setLevel(k, top) {
    this.level = k;
    this.top = top;
  }

  // Contour line segments at or below the current level.
  linesShown() {
    let lo = 0, hi = this.lineLevels.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (this.lineLevels[mid] <= this.level + 0.5) lo = mid + 1; else hi = mid;
    }
    return lo;
  }

  setVisible(flags) {
    Object.assign(this.visible, flags);
  }

  // The mountain's box in view units, for the camera.
  bounds() {
    return this.boundsView;
  }

  // The mountain's steps of a frame (web/gl/progressive_frame.js) under `view` ({viewProjection,
  // light: the unit direction towards the sun}): the surface, then the contour lines. Returns
  // {steps, totals}. Drawn by its Frame (web/gl/frame.js; a res-1024 surface is 2 M
  // triangles, drawn in parts).
  layerSteps(view) {
    const gl = this.gl;
    const { viewProjection: vp, light } = view;
    const totals = { triangles: 0, lines: 0, drawCalls: 0, primitives: 0 };
    const steps = [];
    const surface = this.surface;
    if (surface) {
      const p = this.programs.surface;
      const [lo, hi] = this.heights || [0, 1];
      const t = Number.isFinite(this.top) ? Math.min(1, Math.max(0, (this.top - lo) / (hi - lo || 1))) : 1;
      const cut = ramp(t).map((c) => c / 255);
      const tint = this.visible.tint ? 1 : 0;
      const top = Number.isFinite(this.top) ? this.top : 3.0e38;
      steps.push({
        primitives: surface.count / 3,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform1f(p.uniforms.uExaggerate, 1);
          gl.uniform3fv(p.uniforms.uLightDirection, light);
          gl.uniform1f(p.uniforms.uTint, tint);
          gl.uniform1f(p.uniforms.uTop, top);
          gl.uniform3fv(p.uniforms.uCutColour, cut);
          gl.disable(gl.CULL_FACE);
          gl.enable(gl.POLYGON_OFFSET_FILL);  // contour lines lying on the surface win the depth test
          gl.polygonOffset(1, 2);
          gl.bindVertexArray(surface.vao);
        },
        draw: (first, n) => gl.drawElements(gl.TRIANGLES, 3 * n, gl.UNSIGNED_INT, 12 * first),
        teardown: () => gl.disable(gl.POLYGON_OFFSET_FILL),
      });
      totals.triangles = surface.count / 3;
      totals.primitives += surface.count / 3;
      ++totals.drawCalls;
    }
    const contours = this.contours;
    if (contours && this.visible.contours) {
      const p = this.programs.contour;
      const level = Number.isFinite(this.level) ? this.level : 1e9;
      steps.push({
        primitives: contours.count / 2,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform1f(p.uniforms.uExaggerate, 1);
          gl.uniform1f(p.uniforms.uLift, 0.004);
          gl.uniform1f(p.uniforms.uLevel, level);
          gl.bindVertexArray(contours.vao);
        },
        draw: (first, n) => gl.drawArrays(gl.LINES, 2 * first, 2 * n),
      });
      totals.lines = this.linesShown();
      totals.primitives += contours.count / 2;
      ++totals.drawCalls;
    }
    return { steps, totals };
  }

  // Frees the context's objects this renderer made.
  dispose() {
    super.dispose();
    ++this.terrainUploads;  // an upload on its way is dropped
    this.#drop(this.surface);
    this.#drop(this.contours);
    this.surface = this.contours = null;
    for (const p of Object.values(this.programs || {})) this.gl.deleteProgram(p.program);
    this.programs = null;
  }
}
