// One frame of several studies in one canvas: the WebGL2 context, one orbit camera, one sun
// (web/gl/sun.js), one ground (web/gl/ground.js), with layers added to it (the tree, grove, ivy
// and terrain renderers are layers), drawn whole or in parts. Every study page and embed draws
// through one Frame (the tree page, the grove, the ivy and terrain pages, <niwa-*>), so any of them
// can draw several studies; the garden (issue 33) draws its studies this way. The world is the
// studies' one frame: metres, y up.
//
//   const frame = new Frame(canvas, { camera });
//   await frame.init();
//   const tree = await frame.addLayer(new Renderer(frame));      // web/tree/tree_renderer.js
//   const ivy = await frame.addLayer(new IvyRenderer(frame));    // web/ivy/ivy_renderer.js
//   tree.setTree(...); ivy.setIvy(...); frame.frameAll(); frame.render();
//
// A layer: init() (async: its programs in frame.gl), layerSteps(view, cheap) -> {steps, totals}
// (the steps of web/gl/progressive_frame.js and what they draw: {triangles, lines, drawCalls, ...};
// or draw(gl, view) for a layer drawn whole), worldBounds() (its box in metres, or null),
// footprint() (optional: the ground under it, {center, extent, shadowRadius, crownHeight,
// shadowOffset?}), ready() (optional: false until it can draw), uploading (optional: true while its
// new buffers go up), dispose(); a layer that casts the sun's shadow also gives shadowKey() (a
// string that changes with what it casts: its mesh and pose; null: casts nothing now) and
// shadowSteps(sun) (its steps into the shadow map, sun: {matrix, texel}). view: {viewProjection,
// eye, light (unit, towards the sun), scale (the drawing buffer's), width, height, shadow (the
// frame's ShadowMap, web/gl/shadow_map.js: every receiver binds its texture), sun ({matrix, texel}
// of the map this frame reads, or null: no shadow)}. A study's renderer extends StudyLayer (below).
//
// The shadow map is redrawn only when it is stale (a caster's key or the sun changed): its steps
// come first in the frame and count against the frame's budget like any other (a frame in parts
// draws them in parts). While only the camera moves, the map is reused. A moving frame (a
// FrameGovernor's quality.moving: a sway's poses, a drag) or one at a cheap level (> 0) never redraws
// it: it reuses a map of the same casters and sun drawn at an older pose (a swaying tree's shadow
// stays at the pose it had when the motion began, and is redrawn once the view is still), or draws
// without the sun's shadow.
// Does not: talk to the worker, know any study's meshes, or pace its frames (the page's FrameLoop,
// FrameGovernor or ProgressiveLoop call render; a frame alone asks its own FrameLoop).
import { createContext, drawingBufferSize, finishGpu, resizeCanvas } from './context.js';
import { FrameLoop } from './frame_loop.js';
import { Ground, groundUnder } from './ground.js';
import { OrbitCamera } from './orbit_camera.js';
import { ProgressiveFrame } from './progressive_frame.js';
import { loadPrograms } from './program.js';
import { ShadowMap, sunViewProjection } from './shadow_map.js';
import { DEFAULT_SUNS, defaultSunDirection, sunDirection } from './sun.js';

const COMMON_SHADERS = new URL('../../shaders/common/', import.meta.url).href;

// Layers' totals that add up in a frame of several (the others: the first layer's that has one).
const SUMMED = new Set(['triangles', 'lines', 'drawCalls']);

export class Frame {
  // canvas: the one canvas; camera: the page's orbit camera (default: a new one); sun: {elevation,
  // azimuth} in degrees (default: the tree's); ground: false leaves the ground out (a terrain
  // layer is its own ground, the ivy's support is its); fit: a page of one study draws it fitted
  // to its view (ten units, the ivy and terrain pages' look) instead of in metres (the layers
  // added read frame.fit: StudyLayer.fitView); request: how the frame asks for a frame (the
  // page's loop; default: its own FrameLoop drawing it whole); what: the view's name in the error
  // when WebGL2 is missing; antialias: the context's MSAA (createContext: 'hardware', the
  // default, true or false).
  constructor(canvas, { camera = new OrbitCamera(), sun = DEFAULT_SUNS.tree, ground = true, fit = false, request = null, what = 'the scene', antialias = 'hardware' } = {}) {
    this.canvas = canvas;
    this.gl = createContext(canvas, what, { antialias });
    this.camera = camera;
    this.layers = [];
    this.withGround = ground;
    this.showGround = ground;
    this.fit = fit;
    this.ground = null;
    this.light = sunDirection(sun.elevation, sun.azimuth);
    this.progress = new ProgressiveFrame(this.gl);  // the frame being drawn (in parts when over budget)
    this.requestFrame = request;
    this.loop = null;
    this.scale = 1;  // the drawing buffer's scale of the last frame (FrameGovernor)
    this.frameTotals = {};
    this.frameCpuMs = 0;
    this.lastFrame = { layers: 0, steps: 0 };
    this.shadows = true;     // the sun's shadow map on (setShadows)
    this.shadowMap = null;   // made by init()
  }

  // Sun shadows on or off (off: neither the shadow map nor the ground's stand-in shadow).
  setShadows(on) {
    this.shadows = Boolean(on);
    this.request();
  }

  // Compiles the ground's program (when the frame has a ground); call once before the first frame.
  async init() {
    this.shadowMap ||= new ShadowMap(this.gl);
    if (!this.withGround) return;
    const p = await loadPrograms(this.gl, COMMON_SHADERS, { ground: ['ground.vert', 'ground.frag'] });
    this.groundProgram = p.ground;
    this.ground = new Ground(this.gl, p.ground);
  }

  // Adds a layer (its init() runs first); resolves to the layer, drawn from the next frame on. The
  // layer takes the frame's sun.
  async addLayer(layer) {
    layer.light = this.light;
    await layer.init?.();
    this.layers.push(layer);
    this.request();
    return layer;
  }

  // Takes a layer out and disposes of it.
  removeLayer(layer) {
    const i = this.layers.indexOf(layer);
    if (i < 0) return;
    this.layers.splice(i, 1);
    layer.dispose?.();
    this.request();
  }

  // The one sun of every layer: elevation and azimuth in degrees (core/light's convention).
  setSun(elevationDeg, azimuthDeg) {
    const light = sunDirection(elevationDeg, azimuthDeg);
    if (light) {
      this.light = light;
      for (const layer of this.layers) layer.light = light;
    }
    this.request();
  }

  // The union of the layers' boxes (metres), or null when none has one.
  bounds() {
    let box = null;
    for (const layer of this.layers) {
      const b = layer.worldBounds?.();
      if (!b) continue;
      if (!box) box = { min: [...b.min], max: [...b.max] };
      else for (let i = 0; i < 3; ++i) {
        box.min[i] = Math.min(box.min[i], b.min[i]);
        box.max[i] = Math.max(box.max[i], b.max[i]);
      }
    }
    return box;
  }

  // Frames every layer with the camera (keeping its yaw and pitch).
  frameAll(margin = 1.12) {
    const box = this.bounds();
    if (box) this.camera.frame(box, margin);
    this.request();
  }

  // The ground under the layers: the first layer's footprint with the others' extents.
  #groundOptions() {
    let footprint = null;
    for (const layer of this.layers) {
      const f = layer.footprint?.();
      if (!f) continue;
      if (!footprint) footprint = { ...f };
      else footprint.extent = Math.max(footprint.extent, f.extent);
    }
    const box = this.bounds();
    if (!footprint) {
      const c = box ? [(box.min[0] + box.max[0]) / 2, 0, (box.min[2] + box.max[2]) / 2] : [0, 0, 0];
      const size = box ? Math.max(box.max[0] - box.min[0], box.max[2] - box.min[2]) : 0;
      footprint = { center: c, extent: Math.max(6, 2 * size), shadowRadius: 0, crownHeight: 0 };
    }
    return groundUnder(footprint, this.light);
  }

  // The shadow map for a frame at governor level `cheap`, `moving` (a FrameGovernor's quality: the
  // view or the tree's pose moves): {steps (its redrawing, or none), sun ({matrix, texel} the
  // receivers read, or null)}. See the file's opening comment.
  #shadowPass(cheap, moving) {
    const map = this.shadowMap;
    const none = { steps: [], sun: null };
    if (!this.shadows || !map || !map.complete) return none;
    const casters = this.layers.filter((layer) => layer.shadowSteps && layer.shadowKey?.() && layer.worldBounds?.());
    if (casters.length === 0) return none;
    const keys = casters.map((layer) => layer.shadowKey());
    const lightKey = this.light.map((x) => x.toFixed(6)).join(',');
    const key = `${keys.join('|')}@${lightKey}`;
    const current = { matrix: map.matrix, texel: map.texel };
    if (map.key === key) return { steps: [], sun: current };
    if (cheap > 0 || moving) {
      // The same casters' (mesh ids before the pose's '#') and sun's map at an older pose, or none.
      const loose = (k) => k && k.split('@').map((part, i) => (i === 0 ? part.split('|').map((c) => c.split('#')[0]).join('|') : part)).join('@');
      return map.key && loose(map.key) === loose(key) ? { steps: [], sun: current } : none;
    }
    let box = null;
    for (const layer of casters) {
      const b = layer.worldBounds();
      if (!box) box = { min: [...b.min], max: [...b.max] };
      else for (let i = 0; i < 3; ++i) {
        box.min[i] = Math.min(box.min[i], b.min[i]);
        box.max[i] = Math.max(box.max[i], b.max[i]);
      }
    }
    const sun = sunViewProjection(box, this.light, map.size);
    const steps = map.steps(key, sun, casters.flatMap((layer) => layer.shadowSteps(sun)));
    return { steps, sun };
  }

  // False while the frame cannot draw (its ground or a layer's programs not made yet).
  ready() {
    return !(this.withGround && !this.ground) && this.layers.every((layer) => layer.ready?.() !== false);
  }

  // True while a layer's new buffers go up in parts (the page keeps the last frame meanwhile).
  get uploading() {
    return this.layers.some((layer) => layer.uploading);
  }

  // Draws the frame under `camera` (default: the frame's): cleared to the background, the ground,
  // then every layer in the order added. quality: {scale, cheap} from a FrameGovernor
  // (web/gl/frame_governor.js), or omitted for full quality; scale < 1 draws into a smaller
  // drawing buffer (the browser stretches it), cheap > 0 lets a layer draw its cheaper
  // representation. budget: primitives this call may draw; a bigger frame is drawn over several
  // calls and returns partial: true until the call that finishes it: call again with resume: true
  // (the same frame goes on; anything else starts a new frame). Returns what the whole frame draws
  // (the layers' totals, the ground's included), with cpuMs (this frame's CPU time so far),
  // scale, partial, drawnPrimitives (this call's), layers and steps; undefined before it can draw.
  render(camera = this.camera, quality = null, { budget = Infinity, resume = false } = {}) {
    if (!this.ready()) return undefined;
    const start = performance.now();
    if (!resume || !this.progress.pending()) this.#startFrame(camera, quality, budget);
    const { primitives, done } = this.progress.run(budget);
    this.frameCpuMs += performance.now() - start;
    this.gl.bindVertexArray(null);
    this.lastFrame = { ...this.frameTotals, cpuMs: this.frameCpuMs, scale: this.scale, partial: !done, drawnPrimitives: primitives };
    return this.lastFrame;
  }

  // Lists the frame's steps under the camera and starts it (cleared by progress.begin, on the
  // canvas or an offscreen target). The canvas's drawing buffer takes the frame's size only when
  // the frame is drawn (whole) or presented (in parts): resizing it blanks it, and a frame in parts
  // must leave the last finished one on screen. Layers size what they draw by view.width and
  // view.height, not the canvas's. GPU time is not measured here (no timer queries on SwiftShader).
  #startFrame(camera, quality, budget) {
    this.scale = quality?.scale || 1;
    const [width, height] = drawingBufferSize(this.canvas, this.scale);
    this.frameCpuMs = 0;
    const view = {
      viewProjection: camera.viewProjection(width / height), eye: camera.position(),
      light: this.light, scale: this.scale, width, height,
    };
    const gl = this.gl;
    const shadow = this.#shadowPass(quality?.cheap || 0, Boolean(quality?.moving));
    view.shadow = this.shadowMap;
    view.sun = shadow.sun;
    const steps = [...shadow.steps];
    // The shadow pass's primitives are in totals.primitives (the budget's count), not in triangles
    // (what the layers show: table 4.1's counts).
    const totals = { triangles: 0, lines: 0, drawCalls: 0,
      shadowPrimitives: shadow.steps.reduce((n, step) => n + step.primitives, 0),
      shadow: shadow.sun ? (shadow.steps.length ? 'drawn' : 'reused') : 'off' };
    if (this.showGround && this.ground) {
      const ground = this.#groundOptions();
      // The stand-in shadow under the crown only where no layer casts the sun's (shadows on).
      ground.blob = this.shadows && !shadow.sun ? 0.45 : 0;
      steps.push({ primitives: 0, setup: () => {}, draw: () => this.ground.draw(view.viewProjection, ground, this.shadowMap, shadow.sun) });
      totals.triangles += 2;
      totals.drawCalls += 1;
    }
    for (const layer of this.layers) {
      layer.scale = this.scale;
      if (layer.layerSteps) {
        const part = layer.layerSteps(view, quality?.cheap || 0);
        steps.push(...part.steps);
        for (const [key, value] of Object.entries(part.totals || {})) {
          if (SUMMED.has(key)) totals[key] += value;
          else if (!(key in totals)) totals[key] = value;
        }
      } else if (layer.draw) {
        steps.push({ primitives: 0, setup: () => {}, draw: () => layer.draw(gl, view) });
      }
    }
    totals.primitives = steps.reduce((n, step) => n + step.primitives, 0);  // what the budget counts
    totals.layers = this.layers.length;
    totals.steps = steps.length;
    this.frameTotals = totals;
    this.progress.begin(this.canvas, steps, budget, [width, height]);
  }

  // Frame time with the GPU's work included: draws `frames` whole frames, each followed by reading
  // one pixel back (which returns only once the frame is finished), and resolves to the median and
  // what a frame draws. One animation frame between draws keeps the page responsive.
  // cancelled(): asked before each frame; once true the timing stops and resolves to the frames
  // timed so far ({cancelled: true}, ms null when none was) — a frame of a big tree on a CPU GL
  // takes seconds, so a timing button is its own Cancel (issue 32).
  async timeFrames(frames = 10, { cancelled = () => false } = {}) {
    const times = [];
    let drawn = null;
    let stopped = false;
    for (let i = 0; i <= frames; ++i) {
      await new Promise((resolve) => requestAnimationFrame(resolve));
      if (cancelled()) {
        stopped = true;
        break;
      }
      const start = performance.now();
      drawn = this.render();
      finishGpu(this.gl);
      if (i > 0) times.push(performance.now() - start);  // the first is a warm-up
    }
    times.sort((a, b) => a - b);
    return { ...drawn, ms: times.length ? times[Math.floor(times.length / 2)] : null, frames: times.length, cancelled: stopped };
  }

  // Asks for a frame (several requests before it runs make one): the page's loop, or the frame's own.
  request() {
    if (this.requestFrame) {
      this.requestFrame();
      return;
    }
    this.loop ||= new FrameLoop(() => this.render(), { gl: this.gl });
    this.loop.request();
  }

  // Disposes of every layer and the frame's own objects.
  dispose() {
    for (const layer of this.layers.splice(0)) layer.dispose?.();
    this.progress.abort();
    this.ground?.dispose();
    this.shadowMap?.dispose();
    this.shadowMap = null;
    if (this.groundProgram) this.gl.deleteProgram(this.groundProgram.program);
    this.ground = null;
  }
}

// What every study's renderer shares as a layer of a Frame (the tree's, the grove's, the ivy's
// and the terrain's extend it; moss, bark and the garden's next): the frame's context and its
// frame in parts (a layer aborts it when its buffers change), its sun (the frame's, given by addLayer and
// setSun), its box in the frame's world, and whether it is fitted to a page's view (a Frame of
// fit: true) or in metres. A renderer may also be made on a canvas of its own (its own context:
// tests that use one program, web/tree/tree_renderer.js's atlas painting), drawn whole with
// drawWhole.
// A subclass gives layerSteps(view, cheap) -> {steps, totals} (the steps of its study under `view`,
// and what they draw), and may give ready() (false until its programs exist), worldBounds() (when
// it is not boundsView), footprint() (its ground), dispose() (calling super.dispose()).
export class StudyLayer {
  // target: a Frame ({canvas, gl}: a layer of it) or a canvas (the layer makes its context; `what`
  // names it in the error when WebGL2 is missing); study: its default sun (web/gl/sun.js) until a
  // frame gives it its own.
  constructor(target, { what, study }) {
    const frame = target && target.gl && target.canvas ? target : null;
    this.frame = frame;
    this.canvas = frame ? frame.canvas : target;
    this.gl = frame ? frame.gl : createContext(this.canvas, what);
    // Fitted to the page's view (a Frame of fit: true, or alone) or in the frame's world (metres).
    this.fitView = frame ? Boolean(frame.fit) : true;
    this.light = frame ? frame.light : defaultSunDirection(study);
    this.boundsView = null;  // the study's box in view units (fitted) or the frame's world (metres)
    this.progress = frame ? frame.progress : new ProgressiveFrame(this.gl);  // the frame in parts its buffers are in
    this.scale = 1;  // the drawing buffer's scale of the last frame (the Frame sets it)
  }

  // The sun (core/light's convention): elevation and azimuth in degrees; in a Frame, the frame's
  // (every layer's).
  setSun(elevationDeg, azimuthDeg) {
    if (this.frame) {
      this.frame.setSun(elevationDeg, azimuthDeg);
      return;
    }
    const light = sunDirection(elevationDeg, azimuthDeg);
    if (light) this.light = light;
  }

  // False while the layer cannot draw (its programs not made yet): a frame draws nothing.
  ready() {
    return true;
  }

  // Draws the layer's steps whole now under `camera` at full scale, on its canvas (the warm-up
  // draws of a renderer's init).
  drawWhole(camera) {
    resizeCanvas(this.canvas, 1);
    const { width, height } = this.canvas;
    const view = { viewProjection: camera.viewProjection(width / height), eye: camera.position(), light: this.light, scale: 1, width, height };
    this.progress.begin(this.canvas, this.layerSteps(view, 0).steps);
    this.progress.run();
    this.gl.bindVertexArray(null);
  }

  // The study's box in the frame's world (metres), or null (fitted, or before a result).
  worldBounds() {
    return this.fitView ? null : this.boundsView;
  }

  // Frees what the layer made (a Frame's layer removed, or the page gone): the frame in parts
  // ends; a subclass frees its own objects after calling this.
  dispose() {
    this.progress.abort();
  }
}
