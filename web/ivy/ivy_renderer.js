// The ivy page's WebGL2 view (shaders/ivy/): the support mesh in stone grey, the ivy's stems,
// leaves and suckers over it, and the seed points and (optionally) the buds A/D/Z as dots. Positions stay in the scene's units
// (px for the built-in scenes, metres for most assets); uModel scales the support into a view of
// about ten units so one orbit camera fits every scene. The step scrubber hides what was born after
// step k in the vertex shader (aBirth), so replaying the growth needs no regrow.
// Does not: talk to the worker, pick by id (a click is a ray in scene units; the worker's BVH
// answers it), or know the growth model.
import { beginFrame, createContext, sunDirection } from '../gl/context.js';
import { floatAttribute, staticBuffer } from '../gl/buffers.js';
import { loadPrograms } from '../gl/program.js';

const SHADERS = new URL('../../shaders/ivy/', import.meta.url);
const VIEW_SIZE = 10;  // the support's largest extent in view units

const COLORS = {
  support: { color: [0.64, 0.62, 0.58], variation: [0, 0, 0] },
  stems: { color: [0.36, 0.24, 0.13], variation: [0.06, 0.04, 0.02] },
  leaves: { color: [0.2, 0.5, 0.14], variation: [0.1, 0.16, 0.06] },
  suckers: { color: [0.55, 0.35, 0.2], variation: [0, 0, 0] },
};

// Sorted birth step of every triangle of a part (its first vertex's), for the drawn counts.
function triangleBirths(indices, birth) {
  const out = new Float32Array(indices.length / 3);
  for (let t = 0; t < out.length; ++t) out[t] = birth[indices[3 * t]];
  return out.sort();
}

// Number of entries of a sorted array that are <= k.
function countAtMost(sorted, k) {
  let lo = 0, hi = sorted.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (sorted[mid] <= k + 0.5) lo = mid + 1; else hi = mid;
  }
  return lo;
}

export class IvyRenderer {
  constructor(canvas) {
    this.canvas = canvas;
    this.gl = createContext(canvas, 'the ivy');
    this.parts = {};  // name -> {vao, buffers, count, births}
    this.model = [0, 0, 0, 1];
    this.step = Infinity;
    this.visible = { support: true, stems: true, leaves: true, suckers: true, seeds: true, buds: false };
    this.buds = { vao: null, buffers: [], count: 0 };
    this.seeds = { vao: null, buffer: null, count: 0 };
    this.light = sunDirection(50, 30);
    this.boundsView = null;
  }

  async init() {
    this.programs = await loadPrograms(this.gl, SHADERS.href, {
      ivy: ['ivy.vert', 'ivy.frag'],
      marker: ['marker.vert', 'marker.frag'],
    });
  }

  #upload(name, b, withBirth) {
    const gl = this.gl;
    this.#drop(name);
    const positions = new Float32Array(b.positions);
    const indices = new Uint32Array(b.indices);
    if (indices.length === 0) return;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [staticBuffer(gl, positions), staticBuffer(gl, new Float32Array(b.normals))];
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 3);
    let births = null;
    if (withBirth) {
      const birth = new Float32Array(b.birth);
      buffers.push(staticBuffer(gl, birth));
      floatAttribute(gl, 2, buffers[2], 1);
      births = triangleBirths(indices, birth);
    } else {
      gl.disableVertexAttribArray(2);
      gl.vertexAttrib1f(2, 0);
    }
    buffers.push(staticBuffer(gl, indices, gl.ELEMENT_ARRAY_BUFFER));
    gl.bindVertexArray(null);
    this.parts[name] = { vao, buffers, count: indices.length, births };
  }

  #drop(name) {
    const part = this.parts[name];
    if (!part) return;
    this.gl.deleteVertexArray(part.vao);
    for (const b of part.buffers) this.gl.deleteBuffer(b);
    delete this.parts[name];
  }

  // The support's triangles and bounds ({min, max} in scene units, or null for the free scene):
  // sets the scale that fits it in the view.
  setSupport(buffers, bounds) {
    this.#upload('support', buffers, false);
    this.#fit(bounds);
  }

  #fit(bounds) {
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

  // The ivy's parts ({stems, leaves, suckers}: {positions, normals, indices, birth}); a scene
  // without a support is fitted to the ivy's own bounds.
  setIvy(mesh) {
    for (const name of ['stems', 'leaves', 'suckers']) this.#upload(name, mesh[name], true);
    if (!this.parts.support) {
      const p = new Float32Array(mesh.stems.positions);
      if (p.length) {
        const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
        for (let i = 0; i < p.length; ++i) {
          min[i % 3] = Math.min(min[i % 3], p[i]);
          max[i % 3] = Math.max(max[i % 3], p[i]);
        }
        this.#fit({ min, max });
      }
    }
  }

  clearIvy() {
    for (const name of ['stems', 'leaves', 'suckers']) this.#drop(name);
    this.#dropBuds();
  }

  // The buds as markers ({positions, kind, birth}).
  setBuds(b) {
    const gl = this.gl;
    this.#dropBuds();
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffers = [new Float32Array(b.positions), new Float32Array(b.kind), new Float32Array(b.birth)].map((a) => staticBuffer(gl, a));
    floatAttribute(gl, 0, buffers[0], 3);
    floatAttribute(gl, 1, buffers[1], 1);
    floatAttribute(gl, 2, buffers[2], 1);
    gl.bindVertexArray(null);
    this.buds = { vao, buffers, count: new Float32Array(b.kind).length };
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
      out[name] = part ? countAtMost(part.births, this.step) : 0;
    }
    return out;
  }

  // A ray through canvas pixel (x, y) (CSS pixels from the top left) in scene units.
  rayAt(camera, x, y) {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    const ndcX = (2 * x) / w - 1, ndcY = 1 - (2 * y) / h;
    const eye = camera.position(), target = camera.target;
    const f = normalize([target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]]);
    const r = normalize(cross(f, [0, 1, 0]));
    const u = cross(r, f);
    const t = Math.tan(camera.fov / 2), aspect = w / h;
    const dir = [0, 1, 2].map((i) => f[i] + r[i] * ndcX * t * aspect + u[i] * ndcY * t);
    const s = this.model[3];
    return { origin: eye.map((e, i) => e / s + this.model[i]), direction: normalize(dir) };
  }

  render(camera) {
    const gl = this.gl;
    beginFrame(gl, this.canvas);
    const vp = camera.viewProjection(this.canvas.width / this.canvas.height);
    const p = this.programs.ivy;
    gl.useProgram(p.program);
    gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
    gl.uniform4fv(p.uniforms.uModel, this.model);
    gl.uniform1f(p.uniforms.uStep, Number.isFinite(this.step) ? this.step : 1e9);
    gl.uniform3fv(p.uniforms.uLightDirection, this.light);
    gl.uniform3fv(p.uniforms.uCameraPosition, camera.position());
    gl.disable(gl.CULL_FACE);
    let triangles = 0, drawCalls = 0;
    for (const name of ['support', 'stems', 'suckers', 'leaves']) {
      const part = this.parts[name];
      if (!part || !this.visible[name]) continue;
      gl.uniform3fv(p.uniforms.uColor, COLORS[name].color);
      gl.uniform3fv(p.uniforms.uVariation, COLORS[name].variation);
      if (name === 'support') {
        gl.enable(gl.POLYGON_OFFSET_FILL);  // ivy lying on a face wins the depth test
        gl.polygonOffset(1, 1);
      }
      gl.bindVertexArray(part.vao);
      gl.drawElements(gl.TRIANGLES, part.count, gl.UNSIGNED_INT, 0);
      gl.disable(gl.POLYGON_OFFSET_FILL);
      triangles += part.count / 3;
      ++drawCalls;
    }
    const markers = [];
    if (this.buds.count && this.visible.buds) markers.push(this.buds);
    if (this.seeds.count && this.visible.seeds) markers.push(this.seeds);
    if (markers.length) {
      const m = this.programs.marker;
      gl.useProgram(m.program);
      gl.uniformMatrix4fv(m.uniforms.uViewProjection, false, vp);
      gl.uniform4fv(m.uniforms.uModel, this.model);
      gl.uniform1f(m.uniforms.uPointSize, 12 * Math.min(window.devicePixelRatio || 1, 2));
      gl.uniform1f(m.uniforms.uStep, Number.isFinite(this.step) ? this.step : 1e9);
      gl.disable(gl.DEPTH_TEST);
      for (const marker of markers) {
        gl.bindVertexArray(marker.vao);
        gl.drawArrays(gl.POINTS, 0, marker.count);
        ++drawCalls;
      }
      gl.enable(gl.DEPTH_TEST);
    }
    gl.bindVertexArray(null);
    return { triangles, drawCalls };
  }
}

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function normalize(v) {
  const l = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / l, v[1] / l, v[2] / l];
}
