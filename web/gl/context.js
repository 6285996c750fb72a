// WebGL2 context setup shared by every renderer: the context with the options the pages rely on
// (a preserved drawing buffer for PNG downloads and test read-backs), canvas sizing, read-backs.
// Does not: draw anything, own programs or buffers, or handle context loss (the page does).

export const BACKGROUND = [0.86, 0.90, 0.94];

// The canvas's WebGL2 context; throws an Error naming `what` when WebGL2 is missing. antialias:
// 'hardware' (every page's default): MSAA unless the browser rasterises on the CPU
// (softwareRenderer()), where it triples a frame's time (a 16k-triangle frame at 860 × 800 px on
// SwiftShader: 63 ms with it, 22 ms without): there an orbit, a scrubber or Blow answers three
// times sooner with aliased edges; true (MSAA always) or false.
export function createContext(canvas, what = 'the scene', { antialias = 'hardware' } = {}) {
  const msaa = antialias === 'hardware' ? !softwareRenderer() : Boolean(antialias);
  const gl = canvas.getContext('webgl2', { antialias: msaa, preserveDrawingBuffer: true, alpha: false });
  if (!gl) throw new Error(`WebGL2 is not available in this browser, so ${what} cannot be drawn.`);
  clearToBackground(gl);
  return gl;
}

// True when WebGL2 draws on the CPU (SwiftShader, llvmpipe, a "software" renderer), by the
// unmasked renderer string of a throwaway context (a canvas, or in a worker an OffscreenCanvas); read once.
let probed = null;  // {webgl2, software}
function probe() {
  if (probed) return probed;
  probed = { webgl2: false, software: false };
  try {
    const canvas = typeof document !== 'undefined' ? document.createElement('canvas') : new OffscreenCanvas(1, 1);
    const gl = canvas.getContext('webgl2');
    const info = gl?.getExtension('WEBGL_debug_renderer_info');
    const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
    probed = { webgl2: Boolean(gl), software: /swiftshader|llvmpipe|software/i.test(name) };
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
  } catch {
    // no WebGL2 here (an OffscreenCanvas without it, in a worker)
  }
  return probed;
}
export function softwareRenderer() {
  return probe().software;
}

// True when this thread can make a WebGL2 context (the tree page's render worker asks before the
// page hands it the canvas).
export function webgl2Available() {
  return probe().webgl2;
}

// Clears the canvas's own drawing buffer to the background, leaving the bound framebuffer and the
// clear colour as they were. A new or resized drawing buffer is black (alpha: false), and a big
// frame drawn in parts goes offscreen, so without this the canvas shows black, not the background,
// until that frame is finished (seconds for a big tree on a CPU GL).
function clearToBackground(gl) {
  const framebuffer = gl.getParameter(gl.FRAMEBUFFER_BINDING);
  const clear = gl.getParameter(gl.COLOR_CLEAR_VALUE);
  const scissor = gl.isEnabled(gl.SCISSOR_TEST);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.disable(gl.SCISSOR_TEST);
  gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  gl.clearColor(clear[0], clear[1], clear[2], clear[3]);
  if (scissor) gl.enable(gl.SCISSOR_TEST);
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
}

// Matches the drawing buffer to the canvas's CSS size (device pixel ratio at most 2) times `scale`
// (below 1 while a FrameGovernor lowers the cost of moving frames; the browser stretches it); a
// resized buffer starts as the background.
export function resizeCanvas(canvas, scale = 1) {
  setDrawingBufferSize(canvas, drawingBufferSize(canvas, scale));
}

// Sets the drawing buffer to [width, height] pixels when it is another size; a resized buffer
// starts as the background (the last frame on it is gone: call it only in the task that draws the
// next one whole, or presents it, so no composited frame shows the bare background).
export function setDrawingBufferSize(canvas, [w, h]) {
  if (canvas.width !== w || canvas.height !== h) {
    canvas.width = w;
    canvas.height = h;
    const gl = canvas.getContext('webgl2');  // the context the page made (same object)
    if (gl) clearToBackground(gl);
  }
}

// The drawing buffer size resizeCanvas(canvas, scale) gives, [width, height] in pixels. An
// OffscreenCanvas in a worker has no CSS size: the tree page's render worker sets its clientWidth,
// clientHeight and the worker's devicePixelRatio from the page's (web/tree/tree_view.js).
export function drawingBufferSize(canvas, scale = 1) {
  const dpr = Math.min(globalThis.devicePixelRatio || 1, 2) * scale;
  return [Math.max(1, Math.round(canvas.clientWidth * dpr)), Math.max(1, Math.round(canvas.clientHeight * dpr))];
}

// Clears the default framebuffer to the background with depth testing on (drawing buffer at
// `scale` of the canvas's size, see resizeCanvas).
export function beginFrame(gl, canvas, scale = 1) {
  resizeCanvas(canvas, scale);
  gl.viewport(0, 0, canvas.width, canvas.height);
  gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.enable(gl.DEPTH_TEST);
}

// Blocks until the GPU has finished everything drawn so far (reads one pixel back).
export function finishGpu(gl) {
  const pixel = new Uint8Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  return pixel;
}

// The sun's direction lives in sun.js (one place for every page); re-exported for the renderers
// that import it from here.
export { sunDirection } from './sun.js';
