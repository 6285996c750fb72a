// Frames on demand: request() asks for one animation frame (several requests before it runs make
// one frame), and the draw callback runs in it. The pages draw only when something changed.
// Does not: run a steady loop, measure frame rates, or know what is drawn.

export class FrameLoop {
  // draw(): called once per requested animation frame.
  constructor(draw) {
    this.draw = draw;
    this.requested = false;
  }

  request() {
    if (this.requested) return;
    this.requested = true;
    requestAnimationFrame(() => {
      this.requested = false;
      this.draw();
    });
  }
}

// Resolves at the next animation frame.
export const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));
