// The sun's shadow map of a Frame (issue 32, "light and look"): a depth texture seen from the sun
// (an orthographic view fitted to the casters' box and their shadow on the ground y = 0), drawn by
// the casting layers' shadow steps and read by the receivers (the tree's parts, the ground) through
// a sampler2DShadow with hardware compare and linear filtering, 2 × 2 taps (PCF). WebGL2 depth
// textures (DEPTH_COMPONENT24, compare mode LEQUAL) work on SwiftShader (checked by
// tests/browser/shadow.test.mjs on Debian chromium).
// The map is drawn as steps of the frame (web/gl/progressive_frame.js: counted against the budget,
// drawn in parts like any step) only when it is stale (the casters, their pose or the sun changed)
// and the view is still; while the camera or a sway moves it is reused as it is (web/gl/frame.js).
// Does not: know what a caster draws (its layer's shadowSteps), or cascade for big scenes.
import { softwareRenderer } from './context.js';
import { lookAt, multiply } from './orbit_camera.js';

export const SHADOW_UNIT = 7;     // the texture unit receivers read the map from
export const SHADOW_SIZE = 2048;  // texels square
// On a CPU rasteriser (SwiftShader, llvmpipe) a quarter of the texels: clearing and filling the map
// costs as much as the view itself there.
export const SOFTWARE_SHADOW_SIZE = 1024;
export const shadowSize = () => (softwareRenderer() ? SOFTWARE_SHADOW_SIZE : SHADOW_SIZE);
const IDENTITY = new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);

// Column-major orthographic projection of the box [l, r] × [b, t] × [n, f] (view space, -z ahead).
function ortho(l, r, b, t, n, f) {
  return new Float32Array([
    2 / (r - l), 0, 0, 0, 0, 2 / (t - b), 0, 0, 0, 0, -2 / (f - n), 0,
    -(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1,
  ]);
}

function transform(m, p) {
  return [0, 1, 2].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
}

// The sun's view-projection over `box` ({min, max}, metres) lit from `light` (unit, towards the
// sun): the box's corners and where their shadows fall on y = 0 inside the depth range, the box's
// corners inside x and y (a shadow falls where its caster is, seen from the sun) with a margin, so
// that the map's edge texels stay clear. Also returns the size of a texel in metres.
export function sunViewProjection(box, light, size = shadowSize()) {
  const center = [0, 1, 2].map((i) => 0.5 * (box.min[i] + box.max[i]));
  const reach = Math.hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]) || 1;
  const eye = center.map((c, i) => c + light[i] * 2 * reach);
  const up = Math.abs(light[1]) > 0.99 ? [0, 0, -1] : [0, 1, 0];
  const view = lookAt(eye, center, up);
  const elevation = Math.max(light[1], 0.1);  // a sun at the horizon: shadows 10 × the height at most
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity, z0 = Infinity, z1 = -Infinity;
  for (let c = 0; c < 8; ++c) {
    const p = [c & 1 ? box.max[0] : box.min[0], c & 2 ? box.max[1] : box.min[1], c & 4 ? box.max[2] : box.min[2]];
    const height = Math.max(0, p[1]);
    const ground = [p[0] - (light[0] / elevation) * height, 0, p[2] - (light[2] / elevation) * height];
    for (const q of [p, ground]) {
      const v = transform(view, q);
      z0 = Math.min(z0, v[2]);
      z1 = Math.max(z1, v[2]);
      if (q !== p) continue;
      x0 = Math.min(x0, v[0]); x1 = Math.max(x1, v[0]);
      y0 = Math.min(y0, v[1]); y1 = Math.max(y1, v[1]);
    }
  }
  const margin = 0.03 * Math.max(x1 - x0, y1 - y0, 1e-3);
  x0 -= margin; x1 += margin; y0 -= margin; y1 += margin;
  const depthMargin = 0.02 * (z1 - z0 + 1e-3);
  // View space looks down -z: near = -z1, far = -z0.
  const projection = ortho(x0, x1, y0, y1, -z1 - depthMargin, -z0 + depthMargin);
  return { matrix: multiply(projection, view), texel: Math.max(x1 - x0, y1 - y0) / size };
}

export class ShadowMap {
  // size: texels square of the map once it is drawn (until then it is 1 texel: a receiver's
  // sampler always has a depth texture to read, and a frame that never casts pays nothing).
  constructor(gl, size = shadowSize()) {
    this.gl = gl;
    this.size = size;
    this.allocated = 0;
    this.texture = gl.createTexture();
    this.#allocate(1);
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_COMPARE_MODE, gl.COMPARE_REF_TO_TEXTURE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_COMPARE_FUNC, gl.LEQUAL);
    gl.bindTexture(gl.TEXTURE_2D, null);
    this.fb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fb);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, this.texture, 0);
    gl.drawBuffers([gl.NONE]);
    gl.readBuffer(gl.NONE);
    this.complete = gl.checkFramebufferStatus(gl.FRAMEBUFFER) === gl.FRAMEBUFFER_COMPLETE;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.key = null;       // what the map holds: {casters, light} of its last finished drawing
    this.matrix = null;    // the sun's view-projection it was drawn with
    this.texel = 0;        // metres per texel
    this.drawing = null;   // the key of a drawing in progress (a frame in parts)
    this.passes = 0;       // finished drawings (tests: reused while only the camera moves)
  }

  #allocate(size) {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.DEPTH_COMPONENT24, size, size, 0, gl.DEPTH_COMPONENT, gl.UNSIGNED_INT, null);
    gl.bindTexture(gl.TEXTURE_2D, null);
    this.allocated = size;
  }

  // Binds the map's texture on SHADOW_UNIT for `program` ({program, uniforms} in use) and sets its
  // shadow uniforms: `sun` ({matrix, texel} of a map to read) or null (every fragment lit).
  bindFor(program, sun) {
    const gl = this.gl, u = program.uniforms;
    gl.activeTexture(gl.TEXTURE0 + SHADOW_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.activeTexture(gl.TEXTURE0);
    gl.uniform1i(u.uShadowMap, SHADOW_UNIT);
    gl.uniform1f(u.uShadowOn, sun ? 1 : 0);
    gl.uniform1f(u.uShadowTexel, 1 / this.size);
    if (u.uSunViewProjection) gl.uniformMatrix4fv(u.uSunViewProjection, false, sun ? sun.matrix : IDENTITY);
    if (u.uShadowNormalOffset) gl.uniform1f(u.uShadowNormalOffset, sun ? 1.5 * sun.texel : 0);
  }

  // Binds the map as the framebuffer (for a caster's step).
  bind() {
    const gl = this.gl;
    if (this.allocated !== this.size) this.#allocate(this.size);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fb);
    gl.viewport(0, 0, this.size, this.size);
    gl.enable(gl.DEPTH_TEST);
    gl.depthMask(true);
    // Slope-scaled and constant depth offsets against acne on the casters' own lit surfaces.
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(2.0, 4.0);
  }

  unbind() {
    const gl = this.gl;
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  // The steps that redraw the map for `key` (a string naming casters, their poses and the sun) as
  // seen through `sun` (sunViewProjection's {matrix, texel}): a clear, the casters' steps (each
  // binds the map in its setup: a resumed step is set up again), and a last step that marks the map
  // as holding `key`. The receivers of the same frame read it after these steps (they come first).
  steps(key, sun, casterSteps) {
    const { matrix, texel } = sun;
    const gl = this.gl;
    const wrap = (s) => ({
      primitives: s.primitives,
      ownTarget: true,
      setup: () => {
        this.bind();
        s.setup();
      },
      draw: s.draw,
      teardown: () => {
        s.teardown?.();
        this.unbind();
      },
    });
    return [
      {
        primitives: 0, ownTarget: true,
        setup: () => {
          this.drawing = key;
          this.matrix = matrix;
          this.texel = texel;
          this.key = null;  // half drawn until the last step
          this.bind();
        },
        draw: () => {
          gl.clearDepth(1);
          gl.clear(gl.DEPTH_BUFFER_BIT);
        },
        teardown: () => this.unbind(),
      },
      ...casterSteps.map(wrap),
      {
        primitives: 0, setup: () => {}, draw: () => {
          if (this.drawing === key) this.key = key;
          this.drawing = null;
          this.passes += 1;
        },
      },
    ];
  }

  dispose() {
    this.gl.deleteTexture(this.texture);
    this.gl.deleteFramebuffer(this.fb);
  }
}
