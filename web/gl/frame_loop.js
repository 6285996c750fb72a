// Frames on demand, at most one in flight on the GPU: request() asks for one animation frame
// (several requests before it runs make one frame), and the draw callback runs in it. The pages
// draw only when something changed.
// With a WebGL2 context (issue 16, "the page stays responsive"), every frame ends with a fence
// (gl.fenceSync + flush) and the next frame is drawn only once that fence has signalled: while the
// GPU (SwiftShader on a CPU: seconds per frame of a big tree) is still busy, the frame is skipped
// and polled again at the next animation frame, so frames never queue up behind each other and a
// click's effect waits for at most the frame being drawn. The time from a frame's fence to its
// signal is its latency (`gpuMs`, measured at animation-frame granularity), which a
// FrameGovernor (frame_governor.js) turns into a cheaper frame while things move.
// Chromium updates a sync's status only when a query finds control has been back in the event loop
// since the last one, so a status read once per animation frame lags a whole animation frame (on
// SwiftShader they are 100-150 ms apart while the compositor draws): while a frame is wanted and
// the GPU is busy, the fence is also read every few milliseconds between animation frames, so the
// wanted frame is drawn at the first animation frame after the fence signals (issue 29: the moss
// day scrubber's answer).
// A request marked urgent (a discrete action such as Still: its frame must show now) is drawn at
// the next animation frame even while the last frame is still on the GPU.
// Does not: run a steady loop, know what is drawn, or choose the frame's quality (the governor
// and the renderer do).

export class FrameLoop {
  // draw(): called once per requested animation frame (returns false when it drew nothing: no
  // fence). Options: gl (a WebGL2 context: one frame in flight, latency measured), governor (told
  // each frame's latency: frameDone(ms)).
  constructor(draw, { gl = null, governor = null } = {}) {
    this.draw = draw;
    this.gl = gl;
    this.governor = governor;
    this.requested = false;  // a frame is wanted
    this.urgent = false;     // ... at the next animation frame, whatever the GPU is doing
    this.ticking = false;    // an animation frame callback is pending
    this.fence = null;       // the last frame's fence, until it signals
    this.fenceAt = 0;
    this.watching = 0;       // the timer reading the fence between animation frames
    this.stats = { drawn: 0, skippedBusy: 0, gpuMs: 0 };
  }

  // The context once the renderer exists: from now on one frame in flight.
  attach(gl) {
    this.gl = gl;
  }

  request(urgent = false) {
    this.requested = true;
    this.urgent ||= urgent;
    this.#watch();
    this.#tick();
  }

  // Reads the fence every 4 ms while a frame is wanted and the last one is on the GPU (the status
  // the next animation frame reads is then at most that old).
  #watch() {
    if (this.watching || !this.fence || !this.requested) return;
    const read = () => {
      this.watching = 0;
      const gl = this.gl;
      if (!this.fence || !this.requested || gl.isContextLost()) return;
      if (gl.getSyncParameter(this.fence, gl.SYNC_STATUS) !== gl.SIGNALED) this.watching = setTimeout(read, 4);
    };
    this.watching = setTimeout(read, 0);
  }

  // True while the last frame drawn has not finished on the GPU.
  busy() {
    return this.fence !== null;
  }

  #tick() {
    if (this.ticking) return;
    this.ticking = true;
    requestAnimationFrame(() => {
      this.ticking = false;
      this.#frame();
    });
  }

  #frame() {
    const gl = this.gl;
    if (this.fence) {
      if (gl.isContextLost() || gl.getSyncParameter(this.fence, gl.SYNC_STATUS) === gl.SIGNALED) {
        this.stats.gpuMs = performance.now() - this.fenceAt;
        if (!gl.isContextLost()) gl.deleteSync(this.fence);
        this.fence = null;
        this.governor?.frameDone(this.stats.gpuMs);
      } else if (this.requested && this.urgent) {
        gl.deleteSync(this.fence);  // not measured: the urgent frame goes in after it
        this.fence = null;
      } else {
        if (this.requested) this.stats.skippedBusy += 1;
        this.#watch();
        this.#tick();  // poll again next frame (the last frame still being drawn)
        return;
      }
    }
    if (!this.requested) return;
    this.requested = false;
    this.urgent = false;
    if (this.draw() === false) return;  // nothing drawn (e.g. a mesh still going up in parts)
    this.stats.drawn += 1;
    if (gl && !gl.isContextLost()) {
      this.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
      this.fenceAt = performance.now();
      if (this.fence) this.#tick();  // watch it signal (the governor learns the latency)
    }
  }
}

// Resolves at the next animation frame.
export const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));
