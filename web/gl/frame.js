// One frame of several studies in one canvas: the WebGL2 context, one orbit camera, one sun
// (web/gl/sun.js), one ground (web/gl/ground.js) and the loop that draws them, with layers added
// to it (the tree, ivy and terrain renderers are layers; the garden, issue 33, draws its studies
// this way). The world is the studies' one frame: metres, y up.
//
//   const frame = new Frame(canvas);
//   await frame.init();
//   const tree = await frame.addLayer(new Renderer(frame));      // web/tree/tree_renderer.js
//   const ivy = await frame.addLayer(new IvyRenderer(frame));    // web/ivy/ivy_renderer.js
//   tree.setTree(...); ivy.setIvy(...); frame.frameAll(); frame.request();
//
// A layer: init() (async: its programs in frame.gl), frameSteps(view) -> the steps of
// web/gl/progressive_frame.js (or draw(gl, view) for a layer drawn whole), worldBounds() (its
// box in metres, or null), footprint() (optional: the ground under it, {center, extent,
// shadowRadius, crownHeight}), dispose(). view: {viewProjection, eye, light (unit, towards the
// sun), scale (the drawing buffer's), width, height}. A study's renderer extends StudyLayer
// (below): the one place of what every layer does, in a Frame or alone on a page's canvas.
// Does not: talk to the worker, know any study's meshes, or draw in parts across animation frames
// (a frame is drawn whole; a study page draws its one layer alone, in parts: StudyLayer.render).
import { createContext, resizeCanvas } from './context.js';
import { FrameLoop } from './frame_loop.js';
import { Ground, groundUnder } from './ground.js';
import { OrbitCamera } from './orbit_camera.js';
import { ProgressiveFrame } from './progressive_frame.js';
import { loadPrograms } from './program.js';
import { DEFAULT_SUNS, defaultSunDirection, sunDirection } from './sun.js';

const COMMON_SHADERS = new URL('../../shaders/common/', import.meta.url).href;

export class Frame {
  // canvas: the one canvas; sun: {elevation, azimuth} in degrees (default: the tree's);
  // ground: false leaves the ground out (a terrain layer is its own ground).
  constructor(canvas, { sun = DEFAULT_SUNS.tree, ground = true } = {}) {
    this.canvas = canvas;
    this.gl = createContext(canvas, 'the scene');
    this.camera = new OrbitCamera();
    this.layers = [];
    this.showGround = ground;
    this.ground = null;
    this.light = sunDirection(sun.elevation, sun.azimuth);
    this.progress = new ProgressiveFrame(this.gl);
    this.loop = new FrameLoop(() => this.render(), { gl: this.gl });
    this.lastFrame = { layers: 0, steps: 0 };
  }

  // Compiles the ground's program; call once before the first frame.
  async init() {
    const p = await loadPrograms(this.gl, COMMON_SHADERS, { ground: ['ground.vert', 'ground.frag'] });
    this.groundProgram = p.ground;
    this.ground = new Ground(this.gl, p.ground);
  }

  // Adds a layer (its init() runs first); resolves to the layer, drawn from the next frame on.
  async addLayer(layer) {
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
    if (light) this.light = light;
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

  // Draws one whole frame now: cleared to the background, the ground, then every layer in the
  // order added. Returns {layers, steps}.
  render() {
    if (!this.ground) return false;
    resizeCanvas(this.canvas);
    const view = {
      viewProjection: this.camera.viewProjection(this.canvas.width / this.canvas.height), eye: this.camera.position(),
      light: this.light, scale: 1, width: this.canvas.width, height: this.canvas.height,
    };
    const gl = this.gl;
    const steps = [];
    if (this.showGround) {
      const ground = this.#groundOptions();
      steps.push({ primitives: 0, setup: () => {}, draw: () => this.ground.draw(view.viewProjection, ground) });
    }
    for (const layer of this.layers) {
      if (layer.frameSteps) steps.push(...layer.frameSteps(view));
      else if (layer.draw) steps.push({ primitives: 0, setup: () => {}, draw: () => layer.draw(gl, view) });
    }
    this.progress.begin(this.canvas, steps);
    this.progress.run();
    gl.bindVertexArray(null);
    this.lastFrame = { layers: this.layers.length, steps: steps.length };
    return this.lastFrame;
  }

  // Asks for a frame (several requests before it runs make one).
  request() {
    this.loop.request();
  }

  // Disposes of every layer and the frame's own objects.
  dispose() {
    for (const layer of this.layers.splice(0)) layer.dispose?.();
    this.ground?.dispose();
    if (this.groundProgram) this.gl.deleteProgram(this.groundProgram.program);
    this.ground = null;
  }
}

// What every study's renderer shares as a layer (the tree's, the ivy's and the terrain's extend
// it; moss, bark and the garden's next): the target it draws in (a Frame: the frame's context,
// camera, sun and ground; or a canvas of its own: its own context, fitted view and sun), its sun,
// its box in the frame's world, and, alone on a page's canvas, the frame drawn in parts under
// the page's camera (web/gl/progressive_frame.js; the page's FrameGovernor or ProgressiveLoop
// paces it) from the same steps it gives a Frame.
// A subclass gives layerSteps(view) -> {steps, totals} (the steps of its study under `view`, and
// what they draw), and may give aloneSteps(view, quality) (alone: its own ground, a cheaper
// representation), ready() (false until its programs exist), worldBounds() (when it is not
// boundsView), dispose() (calling super.dispose()).
export class StudyLayer {
  // target: a canvas (the layer makes its context; `what` names it in the error when WebGL2 is
  // missing) or a Frame ({canvas, gl}: a layer of it); study: its default sun (web/gl/sun.js).
  constructor(target, { what, study }) {
    const frame = target && target.gl && target.canvas ? target : null;
    this.canvas = frame ? frame.canvas : target;
    this.gl = frame ? frame.gl : createContext(this.canvas, what);
    this.fitView = !frame;  // alone: the study fitted to the page's view; in a Frame: its world
    this.light = defaultSunDirection(study);
    this.boundsView = null;  // the study's box in view units (alone) or the frame's world (metres)
    this.progress = new ProgressiveFrame(this.gl);  // the frame being drawn in parts (alone)
    this.frameTotals = {};
    this.frameCpuMs = 0;
    this.scale = 1;  // the drawing buffer's scale of the last frame (FrameGovernor)
  }

  // The sun (core/light's convention): elevation and azimuth in degrees; in a Frame, the frame's.
  setSun(elevationDeg, azimuthDeg) {
    const light = sunDirection(elevationDeg, azimuthDeg);
    if (light) this.light = light;
  }

  // False while the layer cannot draw (its programs not made yet): render() draws nothing.
  ready() {
    return true;
  }

  // Alone on its canvas under `camera`. quality: {scale, cheap} from a FrameGovernor
  // (web/gl/frame_governor.js), or omitted for full quality; scale < 1 draws into a smaller
  // drawing buffer (the browser stretches it). budget: primitives this call may draw; a bigger
  // frame is drawn over several calls and returns partial: true until the call that finishes it:
  // call again with resume: true (the same frame goes on; anything else starts a new frame).
  // Returns what the whole frame draws (the layer's totals), with cpuMs (this frame's CPU time so
  // far), scale, partial and drawnPrimitives (this call's).
  render(camera, quality = null, { budget = Infinity, resume = false } = {}) {
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
  // canvas or an offscreen target). GPU time is not measured here (no timer queries on SwiftShader).
  #startFrame(camera, quality, budget) {
    this.scale = quality?.scale || 1;
    resizeCanvas(this.canvas, this.scale);
    this.frameCpuMs = 0;
    const view = { viewProjection: camera.viewProjection(this.canvas.width / this.canvas.height), eye: camera.position(),
      light: this.light, scale: this.scale };
    const { steps, totals } = this.aloneSteps(view, quality);
    this.frameTotals = totals;
    this.progress.begin(this.canvas, steps, budget);
  }

  // The steps of a frame alone (default: the layer's own): {steps, totals}.
  aloneSteps(view) {
    return this.layerSteps(view);
  }

  // As a layer of a Frame: the study's steps under the frame's view (its camera and sun).
  frameSteps(view) {
    return this.layerSteps(view).steps;
  }

  // The study's box in the frame's world (metres), or null (alone, or before a result).
  worldBounds() {
    return this.fitView ? null : this.boundsView;
  }

  // Frees what the layer made (a Frame's layer removed, or the page gone): the frame in parts
  // ends; a subclass frees its own objects after calling this.
  dispose() {
    this.progress.abort();
  }
}
