// A page's canvas shows the background, not black, before its first frame, after a resize and while
// a big frame is drawn in parts offscreen (web/gl/context.js clearToBackground): a new or resized
// WebGL drawing buffer is black (alpha: false), and a frame in parts is shown only when finished, so
// a big tree's first frame used to leave the canvas black for seconds on a CPU GL. A frame in parts
// at another size keeps the last finished frame on the canvas until it is presented (issue 32).
// Run: node tests/browser/canvas_background.test.mjs (no build needed: it loads web/ only).
import { check, modulePage, runBrowserTest } from './harness.mjs';

await runBrowserTest(async (server, browser) => {
  const problems = [];
  const page = await modulePage(server, browser, problems);
  const r = await page.evaluate(async () => {
    const { BACKGROUND, createContext, resizeCanvas } = await import('/web/gl/context.js');
    const { ProgressiveFrame } = await import('/web/gl/progressive_frame.js');
    const canvas = document.createElement('canvas');
    canvas.style.cssText = 'width: 40px; height: 30px';
    document.body.append(canvas);
    const gl = createContext(canvas, 'the test');
    const pixel = () => {
      const p = new Uint8Array(4);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.readPixels(1, 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, p);
      return [...p];
    };
    const out = { background: BACKGROUND.map((c) => Math.round(c * 255)).concat(255) };
    out.created = pixel();
    // A resize with another framebuffer bound and another clear colour: both kept.
    const fb = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    gl.clearColor(0.1, 0.2, 0.3, 0.4);
    resizeCanvas(canvas);
    out.size = [canvas.width, canvas.height];
    out.keptFramebuffer = gl.getParameter(gl.FRAMEBUFFER_BINDING) === fb;
    out.keptClear = [...gl.getParameter(gl.COLOR_CLEAR_VALUE)].map((c) => Math.round(c * 10));
    out.resized = pixel();
    // A frame of 1,000 primitives with a budget of 10 goes offscreen: the canvas keeps the background.
    canvas.style.width = '64px';
    resizeCanvas(canvas);
    const frame = new ProgressiveFrame(gl);
    frame.begin(canvas, [{ primitives: 1000, setup() {}, draw() {} }], 10);
    frame.run(10);
    out.offscreen = frame.drawingOffscreen();
    out.inParts = pixel();
    // Issue 32 ("no blank frames"): a frame in parts at another drawing-buffer size (a governor's
    // scale) leaves the last finished frame on the canvas, at its size, until it is presented.
    const paint = (rgb) => ({ primitives: 500, setup() {}, draw() { gl.clearColor(...rgb, 1); gl.clear(gl.COLOR_BUFFER_BIT); } });
    frame.begin(canvas, [paint([1, 0, 0])], Infinity, [64, 30]);  // drawn whole: red
    frame.run();
    out.whole = pixel();
    frame.begin(canvas, [paint([0, 1, 0]), paint([0, 1, 0])], 600, [32, 15]);  // in parts, half size: green
    frame.run(600);
    out.halfway = { pixel: pixel(), size: [canvas.width, canvas.height], pending: frame.pending() };
    frame.run(600);
    out.presented = { pixel: pixel(), size: [canvas.width, canvas.height], pending: frame.pending() };
    return out;
  });
  const same = (p) => p.every((c, i) => Math.abs(c - r.background[i]) <= 1);
  check('a new canvas shows the background before its first frame', same(r.created), `${r.created} (background ${r.background})`);
  check('a resized canvas shows the background', same(r.resized), `${r.resized} at ${r.size}`);
  check('the resize keeps the bound framebuffer and the clear colour', r.keptFramebuffer && r.keptClear.join(',') === '1,2,3,4',
    `framebuffer kept ${r.keptFramebuffer}, clear ${r.keptClear}`);
  check('while a big frame is drawn in parts offscreen, the resized canvas shows the background', r.offscreen && same(r.inParts),
    `offscreen ${r.offscreen}, canvas ${r.inParts}`);
  check('a frame drawn whole at a size resizes the canvas in the same call', r.whole.join(',') === '255,0,0,255', `${r.whole}`);
  check('a frame in parts at another size leaves the last frame, and its size, on the canvas until it is finished',
    r.halfway.pending && r.halfway.pixel.join(',') === '255,0,0,255' && r.halfway.size.join('x') === '64x30',
    `pending ${r.halfway.pending}, ${r.halfway.pixel} at ${r.halfway.size.join('x')}`);
  check('finished, it is presented at its own size', !r.presented.pending && r.presented.pixel.join(',') === '0,255,0,255' && r.presented.size.join('x') === '32x15',
    `pending ${r.presented.pending}, ${r.presented.pixel} at ${r.presented.size.join('x')}`);
  check('no page errors', problems.length === 0, problems.join(' | '));
});
