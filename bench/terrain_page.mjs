// Terrain page benchmark (issue 19 item 7: "in the page, redrawing the seed regrows the mountain
// and a 512² surface in ≤ 100 ms"): public/terrain.html in headless Debian chromium, res 512, one
// seed contour drawn with the mouse on the plan after another (each a different shape, so each
// regrows). Prints one JSON line:
// {"workload": "terrain-page/regrow-drawn-512", "ms": median worker regrow (the worker's wall time
//  from the update to the posted mountain: repair, grow, heightfield, buffers, stats, copies),
//  "min_ms", "reps", "units" (cells), "screen_ms": median from the pointer's release to the frame
//  that shows the new mountain (the page's upload and draw on SwiftShader included), "parts": the
//  worker's median split (repair, grow, stats, copy, state; core_grow, core_heightfield and
//  core_buffers inside grow; stats_after: the stats the worker computes and posts right after the
//  mountain, outside "ms", web/worker/terrain_handler.js)}.
//
// node bench/terrain_page.mjs [--reps 7] [--res 512]
// Needs build/wasm/web/niwa_web.js (cmake --build build/wasm --target niwa_web) and playwright-core.
// SwiftShader draws on the CPU: screen_ms is reported, the goal is on the worker's regrow.
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';
import { median, newBenchPage, waitDrawn, wholeNumberArgs } from './page_bench.mjs';

const args = wholeNumberArgs({ reps: 7, res: 512 }, 'usage: node bench/terrain_page.mjs [--reps N] [--res CELLS]');

// A closed loop of n points (fractions of the plan canvas): r = 0.3·(1 + 0.2 cos(3φ + phase) +
// 0.06 sin(11φ)), one shape per repetition.
const loop = (n, phase) => Array.from({ length: n + 1 }, (_, k) => {
  const phi = (2 * Math.PI * k) / n;
  const r = 0.3 * (1 + 0.2 * Math.cos(3 * phi + phase) + 0.06 * Math.sin(11 * phi));
  return [0.5 + r * Math.cos(phi), 0.5 - r * Math.sin(phi)];
});

const waitMountain = (page, above) => waitDrawn(page, 'terrainSerial', above, 300_000);

const server = await startServer({ port: 0 });
const browser = await launchChromium();
let failed = false;
try {
  const { page, errors } = await newBenchPage(browser);
  await page.goto(`${server.url}terrain.html#preset=improved&builtin=lobes7&res=${args.res}`);
  await waitMountain(page, 0);
  // Page side: the time from the pointer's release on the plan to the frame of the next mountain.
  await page.evaluate(() => {
    window.__regrow = { released: 0, shown: [] };
    document.getElementById('plan').addEventListener('pointerup', () => { window.__regrow.released = performance.now(); }, true);
    let last = document.documentElement.dataset.drawnSerial;
    new MutationObserver(() => {
      const now = document.documentElement.dataset.drawnSerial;
      if (now !== last && window.__regrow.released) window.__regrow.shown.push(performance.now() - window.__regrow.released);
      last = now;
    }).observe(document.documentElement, { attributes: true, attributeFilter: ['data-drawn-serial'] });
  });
  const box = await page.locator('#plan').boundingBox();
  const worker = [], parts = [];
  let cells = 0;
  for (let rep = 0; rep <= args.reps; ++rep) {  // rep 0: a warm-up (the first drawn grow)
    const serial = Number(await page.evaluate(() => document.documentElement.dataset.terrainSerial));
    const points = loop(120, 0.7 * rep);
    const at = ([u, v]) => [box.x + u * box.width, box.y + v * box.height];
    await page.mouse.move(...at(points[0]));
    await page.mouse.down();
    for (const p of points.slice(1)) await page.mouse.move(...at(p));
    await page.mouse.up();
    await waitMountain(page, serial);
    const d = await page.evaluate(() => ({ ...document.documentElement.dataset }));
    if (d.status !== 'ready') throw new Error(`terrain page: ${d.error || d.status}`);
    cells = JSON.parse(d.stats).cells;
    if (rep > 0) {
      worker.push(Number(d.wallMs));
      // The worker's steps, and inside its grow step the core's (TerrainLab's timings).
      parts.push({ ...JSON.parse(d.regrowParts || '{}'), core_grow: Number(d.msGrow), core_heightfield: Number(d.msHeightfield), core_buffers: Number(d.msBuffers), stats_after: Number(d.msStatsAfter) });
    }
  }
  const shown = (await page.evaluate(() => window.__regrow.shown)).slice(1);
  if (errors.length) throw new Error(`terrain page: ${errors[0]}`);
  const split = {};
  for (const key of Object.keys(parts[0] || {})) split[key] = Number(median(parts.map((p) => p[key])).toFixed(2));
  console.log(JSON.stringify({
    workload: `terrain-page/regrow-drawn-${args.res}`, note: 'chromium worker, WASM; a drawn 120-point seed, improved',
    ms: Number(median(worker).toFixed(2)), min_ms: Number(Math.min(...worker).toFixed(2)), reps: worker.length,
    units: cells, screen_ms: shown.length ? Number(median(shown).toFixed(1)) : null, parts: split,
  }));
  await page.close();
} catch (e) {
  console.error(`bench/terrain_page.mjs: ${e.stack || e}`);
  failed = true;
} finally {
  await browser.close();
  await server.close();
}
process.exit(failed ? 1 : 0);
