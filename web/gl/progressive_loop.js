// A study page's frames over its Frame (web/gl/frame.js; the ivy and terrain pages): one frame in
// flight (frame_loop.js), a frame bigger than the governor's budget drawn over several animation
// frames (progressive_frame.js), a smaller drawing buffer while the camera moves and frames lag
// (frame_governor.js). A frame in parts goes on until it is finished unless the governor wants
// another level; what changed meanwhile is drawn by the next frame, and only a finished frame with
// nothing pending is reported (onDrawn), so a test's hooks describe what is on screen.
// Does not: know what is drawn (the frame's layers do), or start frames by itself (request, moved).
import { FrameGovernor } from './frame_governor.js';
import { FrameLoop } from './frame_loop.js';

export class ProgressiveLoop {
  // renderer(): the page's Frame or null before it has its layers (render(camera, quality,
  // {budget, resume}), progress, uploading); onDrawn(drawn): called after each finished frame.
  constructor({ renderer, camera, onDrawn }) {
    this.renderer = renderer;
    this.camera = camera;
    this.onDrawn = onDrawn;
    this.governor = new FrameGovernor({ onStill: () => this.request() });
    this.dirty = true;  // something changed since the frame in parts began
    this.level = -1;    // the governor's level of the frame in parts
    this.frames = new FrameLoop(() => this.#frame(), { governor: this.governor });
  }

  #frame() {
    const r = this.renderer();
    if (r.uploading) return false;
    const resume = r.progress.pending() && this.governor.peek(0).level === this.level;
    let quality = null;
    if (!resume) {
      quality = this.governor.quality(0);
      this.level = quality.level;
      this.dirty = false;
    }
    const drawn = r.render(this.camera, quality, { budget: this.governor.budget(), resume });
    this.governor.drew(drawn.drawnPrimitives, !drawn.partial, drawn.primitives, drawn.shadowPrimitives);
    if (drawn.partial || this.dirty) {  // the rest of the frame, or what changed while it was drawn
      this.frames.request();
      return true;  // (and the hooks wait for that frame)
    }
    this.onDrawn(drawn);
    return true;
  }

  // Something on screen changed: draw it (when there is a renderer). urgent: a discrete step the
  // user waits to see (a day picked on a scrubber), drawn at the next animation frame even while
  // the last frame is on the GPU (FrameLoop; the browser's own frame pacing still bounds the queue).
  request(urgent = false) {
    if (!this.renderer()) return;
    this.dirty = true;
    this.frames.request(urgent);
  }

  // The camera moved: the governor may lower the quality while it moves.
  moved() {
    this.governor.motion();
    this.request();
  }

  attach(gl) {
    this.frames.attach(gl);
  }

  // Makes the page's Frame with its layers (async create() also stores it where renderer() finds
  // it), joins it to this loop, the orbit camera and the canvas (a resize draws again; a lost
  // context calls onLost), and draws the first frame. Throws what create throws.
  async start(create, { canvas, camera, onLost }) {
    const r = await create();
    this.attach(r.gl);
    camera.attach(canvas, () => this.moved());
    new ResizeObserver(() => this.request()).observe(canvas);
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();
      onLost();
    });
    this.request();
  }
}
