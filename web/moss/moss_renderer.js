// The moss page's WebGL2 view (shaders/moss/): the land (one flat triangle per soil cell in its
// geology's colour) lit by the frame's sun and tinted by an overlay (the coverage of the day
// shown, replayed from the mosses' lives; a field of the last day: irradiance S, T_s, rh_s, theta
// or best-species G on a colour ramp over its range; the last day's photon points, direct and
// bounced in two colours as figs 4.1/4.2; or none), and every
// moss ever alive as an instanced tuft of six triangles coloured by species, drawn only on the
// days it was alive (birth ≤ day < death, in tuft.vert), so the day scrubber (setDay) replays
// the run without a new grow. Positions stay in metres as the worker sends them; uModel centres
// the land and scales its extent to about ten view units (a Frame of fit: true), else metres.
// A StudyLayer (web/gl/frame.js), a layer of a Frame (layerSteps, under its camera and sun).
// Does not: talk to the worker, know the moss model, or draw seeds.
import { copyOf, floatAttribute, staticBuffer, viewOf } from '../gl/buffers.js';
import { StudyLayer } from '../gl/frame.js';
import { loadPrograms } from '../gl/program.js';

const SHADERS = new URL('../../shaders/moss/', import.meta.url);
const VIEW_SIZE = 10;        // the land's extent in view units
const INSTANCE_FLOATS = 9;   // position 3, normal 3, species 1, birth 1, death 1
// A tuft's radius in units of the moss size s (row moss_size): drawn three times the moss's own
// size, so a 1 cm moss on a 2 m scene shows as more than a pixel or two in a fitted view.
export const TUFT_SIZE = 3;
// The land's fields of the last day an overlay can show on its ramp (the worker's land buffers).
export const FIELDS = ['irradiance', 'T_s', 'rh_s', 'theta', 'fitness'];
// Overlays: [shader mode (0 none, 1 coverage, 2 a field on the ramp, 3 photon points), field].
const OVERLAY_MODES = {
  none: [0], coverage: [1], photons: [3], ...Object.fromEntries(FIELDS.map((f) => [f, [2, f]])),
};
const PHOTON_POINT_PX = 3;

// The tuft: three upright blades around the normal and a low cap (x, z across, y up; units of s).
function tuftCorners() {
  const v = [];
  for (let k = 0; k < 3; ++k) {
    const a = (2 * Math.PI * k) / 3, c = Math.cos(a), s = Math.sin(a);
    // A blade: two triangles leaning out from the centre.
    v.push(-0.5 * s, 0, 0.5 * c, 0.5 * s, 0, -0.5 * c, 0.9 * c, 1.6, 0.9 * s);
    v.push(0.5 * s, 0, -0.5 * c, 0.2 * c - 0.3 * s, 1.1, 0.2 * s + 0.3 * c, 0.9 * c, 1.6, 0.9 * s);
  }
  return new Float32Array(v.map((x) => x * TUFT_SIZE));
}

export class MossRenderer extends StudyLayer {
  // target: a canvas or a Frame (a layer of it); beside: draw the land that many widths of it to
  // the right (+x) of where it stands (the A/B view's right-hand run: 1.15), 0 in place.
  constructor(target, { unitScale = 1, beside = 0 } = {}) {
    super(target, { what: 'the moss', study: 'ivy' });
    this.unitScale = unitScale;
    this.beside = beside;
    this.land = null;    // {vao, buffers, count}
    this.mosses = null;  // {vao, buffers, count, life: Float32Array (birth, death pairs)}
    this.model = [0, 0, 0, 1];
    this.size = 0.01;
    this.day = Infinity;
    this.overlay = 'coverage';
    this.fields = {};    // name -> {values: Float32Array per vertex, min, max}
    this.sharedRange = null;  // {min, max}: the ramp's ends shared with another run (the A/B view)
    this.photons = null; // {vao, buffers, count, direct, bounced}
  }

  async init() {
    this.programs = await loadPrograms(this.gl, SHADERS.href, {
      land: ['land.vert', 'land.frag'],
      tuft: ['tuft.vert', 'tuft.frag'],
      photon: ['photon.vert', 'photon.frag'],
    });
    const gl = this.gl;
    this.tuft = staticBuffer(gl, tuftCorners());
    this.tuftCount = tuftCorners().length / 3;
  }

  #drop(part) {
    if (!part) return;
    this.gl.deleteVertexArray(part.vao);
    for (const b of part.buffers) this.gl.deleteBuffer(b);
  }

  // buffers: {land: {positions, normals, coverage, geology, and the FIELDS}, mosses: {positions,
  // normals, species, birth, death, cell, on_moss}, photons: {positions, depth}} (views from the
  // worker, used at once: the page may recycle them after this returns); bounds: {min, max (m)};
  // size: the moss size s (m).
  setMoss(buffers, bounds, size) {
    const gl = this.gl;
    this.progress.abort();
    this.#drop(this.land);
    this.#drop(this.mosses);
    this.#drop(this.photons);
    const l = buffers.land;
    // Each field kept (the buffers go back to the worker) with its range over the land.
    this.fields = {};
    for (const f of FIELDS) {
      const values = l[f] ? copyOf(Float32Array, l[f]) : new Float32Array(l.positions.byteLength / 12);
      let min = Infinity, max = -Infinity;
      for (let i = 0; i < values.length; i += 3) {
        min = Math.min(min, values[i]);
        max = Math.max(max, values[i]);
      }
      if (!(min <= max)) min = max = 0;
      this.fields[f] = { values, min, max };
    }
    let vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const land = [l.positions, l.normals, l.coverage, this.#fieldOf(this.overlay).values, l.geology].map((b) => staticBuffer(gl, b));
    floatAttribute(gl, 0, land[0], 3);
    floatAttribute(gl, 1, land[1], 3);
    floatAttribute(gl, 2, land[2], 1);
    floatAttribute(gl, 3, land[3], 1);
    floatAttribute(gl, 4, land[4], 1);
    gl.bindVertexArray(null);
    this.land = { vao, buffers: land, count: l.positions.byteLength / 12, field: this.#fieldName(this.overlay) };
    // Each cell's area (m²), for the coverage of any day (min(1, n·s²/A), as the run's stats).
    const p = viewOf(Float32Array, l.positions);
    const cells = this.land.count / 3;
    this.area = new Float64Array(cells);
    for (let c = 0; c < cells; ++c) {
      const o = 9 * c;
      const u = [p[o + 3] - p[o], p[o + 4] - p[o + 1], p[o + 5] - p[o + 2]];
      const v = [p[o + 6] - p[o], p[o + 7] - p[o + 1], p[o + 8] - p[o + 2]];
      this.area[c] = 0.5 * Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    }
    this.coverage = new Float32Array(3 * cells);

    const m = buffers.mosses;
    const n = m.birth.byteLength / 4;
    const pos = viewOf(Float32Array, m.positions), nor = viewOf(Float32Array, m.normals);
    const species = viewOf(Float32Array, m.species), birth = viewOf(Float32Array, m.birth), death = viewOf(Float32Array, m.death);
    const data = new Float32Array(n * INSTANCE_FLOATS);
    const life = new Float32Array(2 * n);
    for (let i = 0; i < n; ++i) {
      const o = i * INSTANCE_FLOATS;
      data.set(pos.subarray(3 * i, 3 * i + 3), o);
      data.set(nor.subarray(3 * i, 3 * i + 3), o + 3);
      data[o + 6] = species[i];
      data[o + 7] = life[2 * i] = birth[i];
      data[o + 8] = life[2 * i + 1] = death[i];
    }
    vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    floatAttribute(gl, 0, this.tuft, 3);
    const instances = staticBuffer(gl, data);
    gl.bindVertexArray(null);
    this.mosses = {
      vao, buffers: [instances], count: n, life, species: new Float32Array(species),
      cell: new Uint32Array(viewOf(Uint32Array, m.cell)), onMoss: new Float32Array(viewOf(Float32Array, m.on_moss)),
    };

    this.size = size;
    // The replay of the last day against the run's own coverage (what the worker sent).
    const last = viewOf(Float32Array, l.coverage);
    this.#fillCoverage(Infinity);
    this.coverageReplayError = 0;
    for (let i = 0; i < last.length; ++i) this.coverageReplayError = Math.max(this.coverageReplayError, Math.abs(last[i] - this.coverage[i]));
    this.coverageDay = Infinity;
    // The last day's photon points and how many of each kind.
    const ph = buffers.photons || { positions: new Float32Array(0), depth: new Float32Array(0) };
    const depth = viewOf(Float32Array, ph.depth);
    let direct = 0;
    for (let i = 0; i < depth.length; ++i) if (depth[i] === 0) ++direct;
    vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const photonBuffers = [staticBuffer(gl, ph.positions), staticBuffer(gl, ph.depth)];
    floatAttribute(gl, 0, photonBuffers[0], 3);
    floatAttribute(gl, 1, photonBuffers[1], 1);
    gl.bindVertexArray(null);
    this.photons = { vao, buffers: photonBuffers, count: depth.length, direct, bounced: depth.length - direct };
    const ext = [0, 1, 2].map((k) => bounds.max[k] - bounds.min[k]);
    const extent = Math.max(ext[0], ext[1], ext[2], 1e-9);
    const scale = this.fitView ? VIEW_SIZE / extent : this.unitScale;
    const cx = (bounds.min[0] + bounds.max[0]) / 2, cz = (bounds.min[2] + bounds.max[2]) / 2;
    const shift = this.beside * ext[0] * scale;  // view units to the right
    this.model = [cx - shift / scale, bounds.min[1], cz, scale];
    this.boundsView = {
      min: [-ext[0] / 2 * scale + shift, 0, -ext[2] / 2 * scale],
      max: [ext[0] / 2 * scale + shift, ext[1] * scale, ext[2] / 2 * scale],
    };
  }

  // Instance pointers of the bound moss VAO from instance `first` on (WebGL2 has no base instance).
  #pointInstances(first) {
    const gl = this.gl;
    const stride = INSTANCE_FLOATS * 4, o = first * stride;
    const b = this.mosses.buffers[0];
    floatAttribute(gl, 1, b, 3, stride, o, 1);
    floatAttribute(gl, 2, b, 3, stride, o + 12, 1);
    floatAttribute(gl, 3, b, 1, stride, o + 24, 1);
    floatAttribute(gl, 4, b, 2, stride, o + 28, 1);
  }

  // The day shown (Infinity: the last); the coverage overlay follows it.
  setDay(day) {
    this.day = day;
    if (!this.land || day === this.coverageDay) return;
    this.#fillCoverage(day);
    this.coverageDay = day;
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.land.buffers[2]);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.coverage);
  }

  // this.coverage (per vertex) of the mosses on the land (not on mosses) alive on `day`; returns
  // the land's area-weighted coverage.
  #fillCoverage(day) {
    const cells = this.area.length;
    const count = new Float64Array(cells);
    if (this.mosses) {
      const { life, cell, onMoss } = this.mosses;
      for (let i = 0; i < this.mosses.count; ++i) {
        const b = life[2 * i], d = life[2 * i + 1];
        if (onMoss[i] === 0 && b <= day && (d < 0 || day < d) && cell[i] < cells) ++count[cell[i]];
      }
    }
    const s2 = this.size * this.size;
    let covered = 0, total = 0;
    for (let c = 0; c < cells; ++c) {
      const a = this.area[c];
      const f = a > 0 ? Math.min(1, (count[c] * s2) / a) : 0;
      this.coverage[3 * c] = this.coverage[3 * c + 1] = this.coverage[3 * c + 2] = f;
      covered += Math.min(a, count[c] * s2);
      total += a;
    }
    this.coverageShown = total > 0 ? covered / total : 0;
    return this.coverageShown;
  }

  #fieldName(overlay) {
    const [, field] = OVERLAY_MODES[overlay] || [];
    return field || 'irradiance';
  }

  #fieldOf(overlay) {
    return this.fields[this.#fieldName(overlay)] || { values: new Float32Array(0), min: 0, max: 0 };
  }

  // overlay: 'none', 'coverage', 'photons' or one of FIELDS. Returns what it shows: {overlay,
  // field, min, max} (a field's range over the land) or {overlay, direct, bounced} (photon points).
  setOverlay(overlay) {
    this.overlay = OVERLAY_MODES[overlay] ? overlay : 'coverage';
    const field = this.#fieldName(this.overlay);
    if (this.land && this.land.field !== field) {
      const gl = this.gl;
      gl.bindBuffer(gl.ARRAY_BUFFER, this.land.buffers[3]);
      gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.#fieldOf(this.overlay).values);
      this.land.field = field;
    }
    return this.overlayShown();
  }

  overlayShown() {
    const [mode] = OVERLAY_MODES[this.overlay];
    if (mode === 3) return { overlay: this.overlay, direct: this.photons?.direct ?? 0, bounced: this.photons?.bounced ?? 0 };
    if (mode !== 2) return { overlay: this.overlay };
    const { min, max } = this.#range();
    return { overlay: this.overlay, field: this.#fieldName(this.overlay), min, max };
  }

  // The field overlay's own range over this land ({min, max}), or null for other overlays or no land.
  fieldRange() {
    if (!this.land || OVERLAY_MODES[this.overlay][0] !== 2) return null;
    const { min, max } = this.#fieldOf(this.overlay);
    return { min, max };
  }

  #range() {
    return this.sharedRange || this.#fieldOf(this.overlay);
  }

  // Mosses alive on the day shown, and by species [gingoke, haigoke, sugigoke].
  aliveOn(day = this.day) {
    const counts = [0, 0, 0];
    let total = 0;
    if (!this.mosses) return { total, bySpecies: counts };
    const { life, species, count } = this.mosses;
    for (let i = 0; i < count; ++i) {
      const b = life[2 * i], d = life[2 * i + 1];
      if (b <= day && (d < 0 || day < d)) {
        ++total;
        ++counts[Math.round(species[i])];
      }
    }
    return { total, bySpecies: counts };
  }

  bounds() {
    return this.boundsView;
  }

  // Draws nothing until the next setMoss (the A/B view turned off).
  clear() {
    this.progress.abort();
    this.#drop(this.land);
    this.#drop(this.mosses);
    this.#drop(this.photons);
    this.land = this.mosses = this.photons = null;
    this.boundsView = null;
  }

  // The land, then the tufts, as steps of a frame (web/gl/progressive_frame.js) under `view`.
  layerSteps(view) {
    const gl = this.gl;
    const { viewProjection: vp, light } = view;
    const totals = { triangles: 0, lines: 0, drawCalls: 0, primitives: 0, mosses: 0 };
    const steps = [];
    if (this.land) {
      const p = this.programs.land, land = this.land;
      steps.push({
        primitives: land.count / 3,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform3fv(p.uniforms.uLightDirection, light);
          const [mode] = OVERLAY_MODES[this.overlay];
          const { min, max } = this.#range();
          gl.uniform1i(p.uniforms.uOverlay, mode);
          gl.uniform2f(p.uniforms.uRange, min, max);
          gl.disable(gl.CULL_FACE);
          gl.bindVertexArray(land.vao);
        },
        draw: (first, n) => gl.drawArrays(gl.TRIANGLES, 3 * first, 3 * n),
      });
      totals.triangles += land.count / 3;
      totals.primitives += land.count / 3;
      ++totals.drawCalls;
    }
    if (this.photons && this.photons.count > 0 && OVERLAY_MODES[this.overlay][0] === 3) {
      const p = this.programs.photon, photons = this.photons;
      steps.push({
        primitives: photons.count,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform1f(p.uniforms.uPointSize, PHOTON_POINT_PX * (window.devicePixelRatio || 1));
          gl.bindVertexArray(photons.vao);
        },
        draw: (first, n) => gl.drawArrays(gl.POINTS, first, n),
      });
      totals.primitives += photons.count;
      ++totals.drawCalls;
    }
    if (this.mosses && this.mosses.count > 0) {
      const p = this.programs.tuft, mosses = this.mosses;
      const day = Number.isFinite(this.day) ? this.day : 1e9;
      steps.push({
        primitives: mosses.count,
        setup: () => {
          gl.useProgram(p.program);
          gl.uniformMatrix4fv(p.uniforms.uViewProjection, false, vp);
          gl.uniform4fv(p.uniforms.uModel, this.model);
          gl.uniform3fv(p.uniforms.uLightDirection, light);
          gl.uniform1f(p.uniforms.uSize, this.size);
          gl.uniform1f(p.uniforms.uDay, day);
          gl.disable(gl.CULL_FACE);
          gl.bindVertexArray(mosses.vao);
        },
        draw: (first, n) => {
          this.#pointInstances(first);
          gl.drawArraysInstanced(gl.TRIANGLES, 0, this.tuftCount, n);
        },
      });
      const alive = this.aliveOn(day).total;
      totals.mosses = alive;
      totals.triangles += alive * (this.tuftCount / 3);
      totals.primitives += mosses.count;
      ++totals.drawCalls;
    }
    return { steps, totals };
  }

  dispose() {
    super.dispose();
    this.#drop(this.land);
    this.#drop(this.mosses);
    this.#drop(this.photons);
    this.land = this.mosses = this.photons = null;
    if (this.tuft) this.gl.deleteBuffer(this.tuft);
    for (const p of Object.values(this.programs || {})) this.gl.deleteProgram(p.program);
    this.programs = null;
  }
}
