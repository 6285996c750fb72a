// The terrain page's WebGL2 view (shaders/terrain/): the heightfield surface, hillshaded with the
// hypsometric tint (or plain grey), and the contour lines at their heights over it. Positions stay
// in metres as the worker sends them ((x, h, −y), y up); uModel centres the mountain and scales its
// plan extent to about ten view units so one orbit camera fits every seed. The level scrubber
// (setLevel) shows the mountain as it stands at level k: contours up to k, the surface cut at
// h0 + k·Δh; nothing regrows.
// Does not: talk to the worker, draw the 2-D plan (plan_view.js), or know the generation methods.
import { beginFrame, createContext, sunDirection } from '../gl/context.js';
import { floatAttribute, staticBuffer } from '../gl/buffers.js';
import { loadPrograms } from '../gl/program.js';
import { ramp } from './plan_view.js';

const SHADERS = new URL('../../shaders/terrain/', import.meta.url);
const VIEW_SIZE = 10;  // the mountain's plan extent in view units

export class TerrainRenderer {
  constructor(canvas) {
    this.canvas = canvas;
    this.gl = createContext(canvas, 'the mountain');
    this.surface = null;   // {vao, buffers, count}
    this.contours = null;  // {vao, buffers, count}
    this.model = [0, 0, 0, 1];
    this.visible = { contours: true, tint: true };
    this.light = sunDirection(35, 225);  // from the north-west (−x, −z is north-west in view)
    this.boundsView = null;
    this.level = Infinity;
    this.top = Infinity;
    this.lineLevels = new Float32Array(0);  // sorted level of every contour line segment
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
  // (ArrayBuffers from the worker); bounds: {min: [x, y], max: [x, y], h_min, h_max} in metres.
  setTerrain(buffers, bounds) {
    const gl = this.gl;
    this.#drop(this.surface);
    this.#drop(this.contours);
    this.surface = this.contours = null;
    const s = buffers.surface;
    const indices = new Uint32Array(s.indices);
    if (indices.length) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const list = [staticBuffer(gl, new Float32Array(s.positions)), staticBuffer(gl, new Float32Array(s.normals)),
        staticBuffer(gl, new Float32Array(s.colours))];
      floatAttribute(gl, 0, list[0], 3);
      floatAttribute(gl, 1, list[1], 3);
      floatAttribute(gl, 2, list[2], 3);
      list.push(staticBuffer(gl, indices, gl.ELEMENT_ARRAY_BUFFER));
      gl.bindVertexArray(null);
      this.surface = { vao, buffers: list, count: indices.length };
    }
    const c = buffers.contours;
    const linePositions = new Float32Array(c.positions);
    if (linePositions.length) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const list = [staticBuffer(gl, linePositions), staticBuffer(gl, new Float32Array(c.level))];
      floatAttribute(gl, 0, list[0], 3);
      floatAttribute(gl, 1, list[1], 1);
      gl.bindVertexArray(null);
      this.contours = { vao, buffers: list, count: linePositions.length / 3 };
      const levels = new Float32Array(c.level);
      this.lineLevels = new Float32Array(levels.length / 2).map((_, i) => levels[2 * i]).sort();
    } else {
      this.lineLevels = new Float32Array(0);
    }
    const extent = Math.max(bounds.max[0] - bounds.min[0], bounds.max[1] - bounds.min[1], 1e-9);
    const scale = VIEW_SIZE / extent;
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

  render(camera) {
    const gl = this.gl;
    beginFrame(gl, this.canvas);
    const vp = camera.viewProjection(this.canvas.width / this.canvas.height);
    let triangles = 0, lines = 0, drawCalls = 0;
    if (this.surface) {
      const p = this.programs.surface;
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
      gl.uniform4fv(p.uniforms.uModel, this.model);
      gl.uniform1f(p.uniforms.uExaggerate, 1);
      gl.uniform3fv(p.uniforms.uLightDirection, this.light);
      gl.uniform1f(p.uniforms.uTint, this.visible.tint ? 1 : 0);
      gl.uniform1f(p.uniforms.uTop, Number.isFinite(this.top) ? this.top : 3.0e38);
      const [lo, hi] = this.heights || [0, 1];
      const t = Number.isFinite(this.top) ? Math.min(1, Math.max(0, (this.top - lo) / (hi - lo || 1))) : 1;
      gl.uniform3fv(p.uniforms.uCutColour, ramp(t).map((c) => c / 255));
      gl.disable(gl.CULL_FACE);
      gl.enable(gl.POLYGON_OFFSET_FILL);  // contour lines lying on the surface win the depth test
      gl.polygonOffset(1, 2);
      gl.bindVertexArray(this.surface.vao);
      gl.drawElements(gl.TRIANGLES, this.surface.count, gl.UNSIGNED_INT, 0);
      gl.disable(gl.POLYGON_OFFSET_FILL);
      triangles = this.surface.count / 3;
      ++drawCalls;
    }
    if (this.contours && this.visible.contours) {
      const p = this.programs.contour;
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
      gl.uniform4fv(p.uniforms.uModel, this.model);
      gl.uniform1f(p.uniforms.uExaggerate, 1);
      gl.uniform1f(p.uniforms.uLift, 0.004);
      gl.uniform1f(p.uniforms.uLevel, Number.isFinite(this.level) ? this.level : 1e9);
      gl.bindVertexArray(this.contours.vao);
      gl.drawArrays(gl.LINES, 0, this.contours.count);
      lines = this.linesShown();
      ++drawCalls;
    }
    gl.bindVertexArray(null);
    return { triangles, lines, drawCalls };
  }
}
