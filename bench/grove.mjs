// Grove benchmark: ms per frame of public/grove.html (100 instanced trees) in full and hybrid mode in
// headless Debian chromium (SwiftShader: the GPU work runs on the CPU). Prints one JSON line per mode.
//
// node bench/grove.mjs [--frames 20] [--full-frames 10] [--width 1000 --height 700]
// Needs build/wasm/web/niwa_web.js (cmake --build build/wasm --target niwa_web) and playwright-core.
// Each mode: load the page with #mode=..., wait until every tree (and in hybrid mode the draw lists
// of the view) is on screen, then click "Time N frames": N frames of the same view, each drawn and
// waited for by a 1-pixel gl.readPixels, median shown. Also times N frames of the ground alone
// (ground_ms: the fixed cost of a frame) and reports the worker's draw-list round (view_ms).
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';

const args = { frames: 20, 'full-frames': 10, width: 1000, height: 700 };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args) || !Number.isFinite(Number(process.argv[i + 1]))) {
    console.error('usage: node bench/grove.mjs [--frames N] [--full-frames N] [--width PX] [--height PX]');
    process.exit(2);
  }
  args[key] = Number(process.argv[i + 1]);
}

const server = await startServer({ port: 0 });
const browser = await launchChromium();
let failed = false;
try {
  const context = await browser.newContext({ viewport: { width: args.width, height: args.height }, deviceScaleFactor: 1 });
  for (const mode of ['full', 'hybrid']) {
    const frames = mode === 'full' ? args['full-frames'] : args.frames;
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    const loadStart = Date.now();
    await page.goto(`${server.url}grove.html#mode=${mode}`);
    await page.waitForFunction((m) => {
      const d = document.documentElement.dataset;
      return d.status === 'error' || (d.status === 'ready' && d.drawnMode === m && d.viewPending === '0' && (m === 'full' || Number(d.viewSerial || 0) > 0));
    }, mode, { timeout: 300_000, polling: 200 });
    const loadS = (Date.now() - loadStart) / 1000;
    if ((await page.evaluate(() => document.documentElement.dataset.status)) === 'error') {
      throw new Error(`grove page (${mode}): ${await page.textContent('#message')}`);
    }
    const groundOnly = await page.evaluate((n) => window.grove.timeFrames(n, -1), Math.min(frames, 10));
    await page.fill('#frames', String(frames));
    await page.click('#time');
    await page.waitForFunction((m) => document.documentElement.dataset.timing === 'done' && document.documentElement.dataset.timedMode === m
      && window.grove.lastTiming?.mode === m, mode, { timeout: 900_000, polling: 250 });
    const t = await page.evaluate(() => window.grove.lastTiming);
    if (errors.length) throw new Error(`grove page (${mode}): ${errors[0]}`);
    console.log(JSON.stringify({
      workload: `grove/${mode}`, mode, ms: Number(t.median.toFixed(2)), frames: t.frames,
      min_ms: Number(t.min.toFixed(2)), max_ms: Number(t.max.toFixed(2)), ground_ms: Number(groundOnly.median.toFixed(2)),
      instances: t.instances, unique: t.uniqueDrawn, triangles: t.triangles, lines: t.lines,
      primitives: t.triangles + t.lines, draw_calls: t.drawCalls, width: t.width, height: t.height,
      view_ms: mode === 'hybrid' ? Number(t.viewMs.toFixed(1)) : 0, load_s: Number(loadS.toFixed(1)),
    }));
    await page.close();
  }
} catch (e) {
  console.error(`bench/grove.mjs: ${e.stack || e}`);
  failed = true;
} finally {
  await browser.close();
  await server.close();
}
process.exit(failed ? 1 : 0);
