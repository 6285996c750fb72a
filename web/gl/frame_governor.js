// Frame-time governor (issue 16, "the page stays responsive"): while the view moves (a sway, a
// camera drag), frames whose GPU latency (FrameLoop's fence, frame_loop.js) exceeds the target
// make the next ones cheaper (a smaller drawing buffer, then a cheaper representation the renderer
// chooses; a slow still frame says where the next motion starts); fast frames step back up. When
// nothing has moved for `stillMs`, the next frame is drawn at full quality again (onStill asks for
// it), so a still view is always the full one. The level learned during one motion is where the
// next motion starts.
// Does not: draw, measure time itself (FrameLoop tells it), or know what "cheap" means for a scene.

// Level 0 is full quality. scale: the drawing buffer's size relative to the canvas's CSS size
// (pixels drawn go with its square); cheap: 0, or the renderer's cheaper representation 1, 2, ...
export const LEVELS = Object.freeze([
  { scale: 1, cheap: 0 },
  { scale: 0.7, cheap: 0 },
  { scale: 0.5, cheap: 0 },
  { scale: 0.5, cheap: 1 },
  { scale: 0.35, cheap: 1 },
  { scale: 0.35, cheap: 2 },
  { scale: 0.25, cheap: 2 },
]);

// The smallest ProgressiveFrame budget (primitives per animation frame).
export const MIN_BUDGET = 20_000;
// Frames of fewer primitives keep full quality however long they take.
export const MIN_GOVERNED = 100_000;

export class FrameGovernor {
  // targetMs: the latency above which a moving frame gets cheaper (below targetMs / 3 it gets
  // better again; 300 ms: on SwiftShader the fence of even a tiny frame signals 100-150 ms later); stillMs: how long without motion() before the full-quality frame; onStill():
  // called then, when the last frame drawn was reduced (the page requests a frame).
  // firstBudget: primitives per animation frame before a rate is measured (ProgressiveFrame).
  constructor({ levels = LEVELS, targetMs = 300, stillMs = 500, onStill = () => {}, firstBudget = 50_000 } = {}) {
    this.levels = levels;
    this.targetMs = targetMs;
    this.firstBudget = firstBudget;
    this.rate = 0;            // primitives per ms the GPU was measured to draw (0: not yet)
    this.pendingDraw = null;  // {primitives, complete} of the draw in flight (drew())
    this.stillMs = stillMs;
    this.onStill = onStill;
    this.reset();
    this.lastMotion = -Infinity;
    this.stillTimer = 0;
    this.changes = 0;         // level changes so far (tests, frame stats)
  }

  // A new scene (another tree): what was learned about the last one no longer holds.
  reset() {
    this.motionLevel = 0;     // the level moving frames are drawn at
    this.tooSlow = -1;        // the highest level measured slower than the target
    this.drawn = null;        // {level, moving, capped} of the frame in flight
    this.lastDrawnLevel = 0;
  }

  // Primitives one animation frame may draw so that it takes about targetMs (ProgressiveFrame's
  // budget): the measured rate times the target, at least MIN_BUDGET.
  budget() {
    return this.rate > 0 ? Math.max(MIN_BUDGET, this.rate * this.targetMs) : this.firstBudget;
  }

  // The page drew `primitives` in this animation frame of a frame of `framePrimitives`; complete:
  // the frame is finished (else a ProgressiveFrame continues it, or a moving view starts the next
  // one). once: the frame's primitives that moving frames do not draw again (the sun's shadow map,
  // web/gl/shadow_map.js: redrawn only when the view is still, reused while it moves). A frame is
  // judged for the motion level as if without them (its time scaled by the share of the rest):
  // the still frame that redraws the map after an edit says what a moving frame costs without it,
  // and a frame below MIN_GOVERNED without them is not judged. The rate counts every primitive.
  // Call after drawing, before the FrameLoop's fence signals.
  drew(primitives, complete, framePrimitives = primitives, once = 0) {
    const repeated = Math.max(0, framePrimitives - (once || 0));
    this.pendingDraw = { primitives, complete, framePrimitives, repeated };
  }

  // Something in the view moves now (a new pose, a camera step).
  motion() {
    this.lastMotion = performance.now();
    clearTimeout(this.stillTimer);
    this.stillTimer = setTimeout(() => {
      if (this.lastDrawnLevel > 0) this.onStill();
    }, this.stillMs);
  }

  // Motion has ended (the page knows: Still was pressed): the next frame is the full one.
  stop() {
    this.lastMotion = -Infinity;
    clearTimeout(this.stillTimer);
  }

  // The representation the next moving frame asks for (0: none; the page can prepare it).
  motionCheap() {
    return this.levels[this.motionLevel].cheap;
  }

  moving() {
    return performance.now() - this.lastMotion < this.stillMs;
  }

  // The quality of the frame about to be drawn, {level, scale, cheap, wantCheap}; call once per
  // frame, at its start (not when a ProgressiveFrame resumes it). cheapAvailable: the cheapest representation the renderer has now (a level asking for
  // more is drawn as the last level without it, and its latency does not move the level:
  // wantCheap tells the page what to prepare).
  quality(cheapAvailable = Infinity) {
    const q = this.peek(cheapAvailable);
    this.drawn = { level: q.level, moving: q.moving, capped: q.capped };
    this.frameStart = performance.now();
    this.lastDrawnLevel = q.level;
    return q;
  }

  // What quality() would answer now, without starting a frame (a page keeps drawing a frame in
  // parts while this stays its level).
  peek(cheapAvailable = Infinity) {
    const moving = this.moving();
    const wanted = moving ? this.motionLevel : 0;
    let level = wanted;
    while (level > 0 && this.levels[level].cheap > cheapAvailable) --level;
    return { level, ...this.levels[level], wantCheap: this.levels[wanted].cheap, capped: level !== wanted, moving };
  }

  // The latency (ms) of the draw last made, from its fence (FrameLoop). It updates the rate; the
  // level is judged on whole frames (a frame drawn in parts: from its start to its last part's
  // fence). A slow frame moves the level up by 1 + floor(log2(ms / target)) (a frame 16 times too
  // slow skips four levels: each try of a slow level costs a slow frame); a fast one moves it down
  // one level, never to a level measured slow.
  frameDone(drawMs) {
    const part = this.pendingDraw;
    this.pendingDraw = null;
    const budget = this.budget();
    if (part && part.primitives >= 1000 && drawMs > 0) {
      const rate = part.primitives / drawMs;
      this.rate = this.rate > 0 ? 0.5 * (this.rate + rate) : rate;
    }
    const drawn = this.drawn;
    if (!drawn) return;
    if (part && !part.complete) {
      // A frame too big for one animation frame is too slow by its size over the budget: judged
      // at its first part (a moving frame is not finished: the next one starts cheaper).
      if (!drawn.judged && part.repeated > budget && part.repeated >= MIN_GOVERNED) {
        drawn.judged = true;
        this.#judge(drawn, this.targetMs * (part.repeated / budget));
      }
      return;
    }
    this.drawn = null;
    // A frame of few primitives is never made cheaper: its latency is the page's and the
    // compositor's, not its own (SwiftShader: 100-300 ms for any frame on a loaded machine).
    if (part && part.repeated < MIN_GOVERNED) return;
    const share = part && part.framePrimitives > 0 ? part.repeated / part.framePrimitives : 1;
    if (!drawn.judged) this.#judge(drawn, part ? (performance.now() - this.frameStart) * share : drawMs);
  }

  #judge(drawn, ms) {
    const before = this.motionLevel;
    if (!drawn.moving) {  // a slow still (full) frame: the next motion starts where it would lead
      if (drawn.level === 0 && ms > this.targetMs) {
        this.tooSlow = Math.max(this.tooSlow, 0);
        this.motionLevel = Math.max(this.motionLevel, Math.min(this.levels.length - 1, 1 + Math.floor(Math.log2(ms / this.targetMs))));
      }
    } else if (ms > this.targetMs) {
      this.tooSlow = Math.max(this.tooSlow, drawn.level);
      if (!drawn.capped) {
        const steps = 1 + Math.floor(Math.log2(ms / this.targetMs));
        this.motionLevel = Math.min(this.levels.length - 1, drawn.level + steps);
      }
    } else if (ms < this.targetMs / 3 && !drawn.capped && drawn.level - 1 > this.tooSlow) {
      this.motionLevel = drawn.level - 1;
    }
    if (this.motionLevel !== before) this.changes += 1;
  }
}
