// Id picking: an offscreen colour + depth target the size of the canvas, into which a renderer
// draws ids as 24-bit RGB (id + 1; 0 = nothing, shaders/common/pick.frag), and the read-back of
// the nearest id around a pixel (so thin parts can be clicked). Only the square read back is
// cleared and drawn (a scissor): on a CPU rasteriser a whole-canvas pick cost as much as a frame.
// Does not: draw (the renderer binds its own program and geometry between begin() and read()).

export class PickTarget {
  constructor(gl) {
    this.gl = gl;
    this.target = null;
  }

  // Binds a target of w x h pixels (recreated when the size changes) whose square of radius r
  // about drawing-buffer pixel (px, py) (y up) is cleared, the only pixels drawn until read().
  begin(w, h, px, py, r) {
    const gl = this.gl;
    if (!this.target || this.target.w !== w || this.target.h !== h) {
      if (this.target) {
        gl.deleteFramebuffer(this.target.fb);
        gl.deleteRenderbuffer(this.target.color);
        gl.deleteRenderbuffer(this.target.depth);
      }
      const fb = gl.createFramebuffer();
      const color = gl.createRenderbuffer();
      const depth = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, color);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, w, h);
      gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, w, h);
      gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, color);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
      this.target = { fb, color, depth, w, h };
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.target.fb);
    gl.viewport(0, 0, w, h);
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(px - r, py - r, 2 * r + 1, 2 * r + 1);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    gl.disable(gl.DITHER);  // ids must come back bit-exact
  }

  // The id nearest to drawing-buffer pixel (px, py) (y up) within `r` pixels, or null; unbinds.
  read(px, py, r) {
    const gl = this.gl;
    const { w, h } = this.target;
    const x0 = Math.max(0, px - r), y0 = Math.max(0, py - r);
    const x1 = Math.min(w - 1, px + r), y1 = Math.min(h - 1, py + r);
    let best = null, bestDistance = Infinity;
    if (x1 >= x0 && y1 >= y0) {
      const rw = x1 - x0 + 1, rh = y1 - y0 + 1;
      const data = new Uint8Array(rw * rh * 4);
      gl.readPixels(x0, y0, rw, rh, gl.RGBA, gl.UNSIGNED_BYTE, data);
      for (let j = 0; j < rh; ++j) {
        for (let i = 0; i < rw; ++i) {
          const k = (j * rw + i) * 4;
          const v = data[k] | (data[k + 1] << 8) | (data[k + 2] << 16);
          const d = (x0 + i - px) ** 2 + (y0 + j - py) ** 2;
          if (v > 0 && d < bestDistance) { bestDistance = d; best = v - 1; }
        }
      }
    }
    gl.disable(gl.SCISSOR_TEST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.enable(gl.DITHER);
    return best;
  }
}
