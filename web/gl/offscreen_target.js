// Where a frame drawn in parts (progressive_frame.js) is drawn: a multisampled framebuffer of the
// canvas's drawing-buffer size (colour + depth, the samples the canvas's antialiasing has), shown
// on the canvas only once the frame is finished (resolved into a texture, then one full-canvas
// triangle), so the canvas keeps its last finished frame meanwhile: no half-drawn tree or mountain
// on screen, and a frame dropped for a newer one leaves nothing behind.
// Does not: draw the scene, choose when to use it, or keep more than one frame.

const VERTEX = `#version 300 es
out vec2 vUv;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  vUv = p * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}`;
const FRAGMENT = `#version 300 es
precision highp float;
uniform sampler2D uFrame;
out vec4 colour;
void main() { colour = texelFetch(uFrame, ivec2(gl_FragCoord.xy), 0); }`;

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`offscreen target: ${gl.getShaderInfoLog(shader)}`);
  return shader;
}

export class OffscreenTarget {
  constructor(gl) {
    this.gl = gl;
    this.size = [0, 0];
    this.samples = Math.min(4, gl.getParameter(gl.MAX_SAMPLES) || 0);
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, VERTEX));
    gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, FRAGMENT));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`offscreen target: ${gl.getProgramInfoLog(program)}`);
    this.program = program;
    this.uFrame = gl.getUniformLocation(program, 'uFrame');
    this.vao = gl.createVertexArray();
  }

  // Binds the multisampled framebuffer at width × height (reallocated when the size changes).
  bind(width, height) {
    const gl = this.gl;
    if (this.size[0] !== width || this.size[1] !== height) this.#allocate(width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fb);
    gl.viewport(0, 0, width, height);
  }

  #allocate(width, height) {
    const gl = this.gl;
    this.dispose();
    this.size = [width, height];
    this.colour = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.colour);
    gl.renderbufferStorageMultisample(gl.RENDERBUFFER, this.samples, gl.RGBA8, width, height);
    this.depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorageMultisample(gl.RENDERBUFFER, this.samples, gl.DEPTH_COMPONENT24, width, height);
    this.fb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fb);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, this.colour);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.depth);
    this.texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, width, height);
    gl.bindTexture(gl.TEXTURE_2D, null);
    this.resolveFb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.resolveFb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.texture, 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  // Resolves the finished frame and draws it over the whole canvas (the default framebuffer,
  // whose size must be this target's).
  present() {
    const gl = this.gl;
    const [w, h] = this.size;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.fb);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.resolveFb);
    gl.blitFramebuffer(0, 0, w, h, 0, 0, w, h, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, w, h);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    gl.useProgram(this.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.uniform1i(this.uFrame, 0);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.enable(gl.DEPTH_TEST);
  }

  dispose() {
    const gl = this.gl;
    for (const rb of [this.colour, this.depth]) if (rb) gl.deleteRenderbuffer(rb);
    for (const fb of [this.fb, this.resolveFb]) if (fb) gl.deleteFramebuffer(fb);
    if (this.texture) gl.deleteTexture(this.texture);
    this.colour = this.depth = this.fb = this.resolveFb = this.texture = null;
    this.size = [0, 0];
  }
}
