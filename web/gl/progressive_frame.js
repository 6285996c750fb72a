// One frame drawn over several animation frames (issue 16): a frame is a list of steps (a program,
// its uniforms and vertex array, then one draw of N primitives), and each animation frame draws at
// most `budget` primitives of it, resuming inside a step with a sub-range of its draw (the same
// triangles in the same order as one draw). A frame within the budget is drawn on the canvas at
// once, as before; a bigger one goes into an OffscreenTarget (offscreen_target.js) and is shown
// when it is finished, so the canvas keeps its last finished frame meanwhile: its drawing buffer
// takes the new frame's size (a FrameGovernor's scale) only in the task that draws the frame whole
// or presents it, since a resized buffer is blank (issue 32: "no blank frames"). A 2.5 M-triangle tree
// on SwiftShader (seconds of GPU time) then costs about the budget's time per animation frame, and
// input gets its frames in between.
// Does not: choose the budget (a FrameGovernor measures it) or know what the steps draw.
import { BACKGROUND, setDrawingBufferSize } from './context.js';
import { OffscreenTarget } from './offscreen_target.js';

// A step: {primitives, setup(), draw(first, count), teardown()?, ownTarget?}. primitives 0: an
// atomic step (cheap: the ground, markers), run whole and not counted against the budget; else
// draw(first, count) draws primitives [first, first + count) of it, after setup() (called again on
// every resume: other code may have changed the GL state in between), then teardown(). ownTarget:
// the step draws into a framebuffer of its own (the sun's shadow map, web/gl/shadow_map.js), and
// the frame's target is bound again after it.
export class ProgressiveFrame {
  // gl: the context whose canvas frames are drawn on (omitted: start/run only, no target).
  constructor(gl = null) {
    this.gl = gl;
    this.steps = null;
    this.step = 0;
    this.offset = 0;  // primitives of the current step drawn
    this.offscreen = null;  // the OffscreenTarget of the frame in progress, or null: the canvas
    this.target = null;
    this.canvas = null;
    this.canvasSize = [0, 0];  // the frame's drawing-buffer size, [width, height] pixels
    this.retired = [];  // deletions waiting for the frame in progress to end (retire)
  }

  // Runs `release` (deleting GL objects) now, or, while a frame is in progress whose steps may
  // still bind those objects, once that frame ends (finished, aborted or replaced): a layer that
  // swaps its draw list between two parts of a frame must not leave the rest of the frame binding
  // deleted objects (WebGL: "attempt to use a deleted object"; CI, 2026-12-07, shadow.test).
  retire(release) {
    if (this.pending()) this.retired.push(release);
    else release();
  }

  #release() {
    for (const release of this.retired.splice(0)) release();
  }

  // A new frame of `steps` on `canvas`, `size` ([width, height]: the drawing buffer it is drawn
  // at; default the canvas's now): cleared to the background on the canvas (resized to `size` now:
  // the caller draws it whole in this task), or, when the steps have more primitives than
  // `budget`, in the offscreen target (the canvas keeps its last frame, and its size, until this
  // one is finished and presented).
  begin(canvas, steps, budget = Infinity, size = [canvas.width, canvas.height]) {
    const gl = this.gl;
    const total = steps.reduce((n, s) => n + Math.max(0, s.primitives), 0);
    this.offscreen = total > budget ? (this.target ||= new OffscreenTarget(gl)) : null;
    this.canvas = canvas;
    this.canvasSize = [size[0], size[1]];
    if (!this.offscreen) setDrawingBufferSize(canvas, this.canvasSize);
    this.#bind();
    gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    this.start(steps);
  }

  // True when the frame in progress is drawn offscreen (shown when finished).
  drawingOffscreen() {
    return this.offscreen !== null && this.pending();
  }

  #bind() {
    const gl = this.gl;
    const [w, h] = this.canvasSize;
    if (this.offscreen) this.offscreen.bind(w, h);
    else {
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.viewport(0, 0, w, h);
    }
    gl.enable(gl.DEPTH_TEST);
  }

  start(steps) {
    this.#release();
    this.steps = steps;
    this.step = 0;
    this.offset = 0;
  }

  // Drops a frame in progress (its buffers are gone, or the canvas was resized).
  abort() {
    this.steps = null;
    this.#release();
  }

  pending() {
    return this.steps !== null;
  }

  // Draws up to `budget` primitives (at least one draw, so every frame advances) from where the
  // last call stopped; returns {primitives, done}.
  run(budget = Infinity) {
    let drawn = 0;
    const steps = this.steps;
    if (this.gl && steps) this.#bind();  // picking or an atlas may have bound another target
    while (steps && this.step < steps.length) {
      const s = steps[this.step];
      if (s.primitives <= 0) {
        s.setup();
        s.draw(0, 0);
        s.teardown?.();
        if (s.ownTarget && this.gl) this.#bind();
        this.step += 1;
        continue;
      }
      const room = budget - drawn;
      if (room <= 0 && drawn > 0) break;
      const n = Math.min(s.primitives - this.offset, Math.max(1, Math.floor(room)));
      s.setup();
      s.draw(this.offset, n);
      s.teardown?.();
      if (s.ownTarget && this.gl) this.#bind();
      drawn += n;
      this.offset += n;
      if (this.offset >= s.primitives) {
        this.step += 1;
        this.offset = 0;
      }
    }
    const done = !steps || this.step >= steps.length;
    if (done && steps && this.offscreen) {  // resized and shown in one task: never a blank canvas
      setDrawingBufferSize(this.canvas, this.canvasSize);
      this.offscreen.present();
    }
    if (done) {
      this.steps = null;
      this.#release();
    }
    return { primitives: drawn, done };
  }
}
