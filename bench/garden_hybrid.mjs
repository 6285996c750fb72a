// Garden hybrid frame benchmark (issue 33 item 7: "the page draws 100 trees at ≥ 20 frames per second in
// hybrid mode where the grove does"): in one headless Debian chromium (SwiftShader), the grove page in
// hybrid mode (public/grove.html#mode=hybrid: 100 instances of 10 unique trees) and the garden page with
// a 100-tree garden (public/garden.html, the scale garden's link without its ivy on four objects: 100 m,
// 512² terrain ground, 100 trees of 10 species by the rules, 100 distinct, 15 years with shade, the
// default wall ivy and moss) switched to Trees: hybrid, each timed the same way: N whole frames of the
// page's first view after one warm-up, each waited for by a 1-pixel read back, median (the grove's
// window.grove.timeFrames, the garden's window.__niwaGardenFrameMs: both web/gl/frame.js-style timing).
// The garden is also timed with its ground's full grid (window.__niwaGardenGroundLod(0): the frame as
// it was before web/garden/ground_lod.js), alternated with the rest.
// Each page is also timed without its trees (no_trees_ms: the grove's ground; the garden's ground,
// objects and ivy), so trees_ratio compares what the trees add.
// Prints one JSON line per page and a last one with the ratio garden / grove (ms per frame):
// {"workload": "garden-hybrid/grove" | "garden-hybrid/garden-100" | "garden-hybrid/ratio", ...}.
// On a GPU the goal reads "≥ 20 fps where the grove does"; on SwiftShader it reads: the garden's hybrid
// frame takes no longer than the grove's (ratio ≤ 1) in the same run (docs/BENCHMARKS.md).
//
// node bench/garden_hybrid.mjs [--frames 10] [--reps 2] [--width 1200 --height 800] [--years 15] [--full-frames 0]
// --reps: the two pages' timings alternated this many times (each page stays open); --full-frames N > 0
// also times N frames of the garden in Trees: full (each takes seconds here).
// Needs build/wasm/web/niwa_web.js and playwright-core. Does not: build anything, or grow anything
// natively.
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';
import { median, wholeNumberArgs } from './page_bench.mjs';

const args = wholeNumberArgs({ frames: 10, reps: 2, width: 1200, height: 800, years: 15, 'full-frames': 0 },
  'usage: node bench/garden_hybrid.mjs [--frames N] [--reps N] [--width PX] [--height PX] [--years N] [--full-frames N]');
const MIX = ['keyaki', 'sakura', 'maple', 'pine', 'ginkgo', 'weeping', 'tsutsuji', 'binary', 'keyaki-thesis',
  'sakura-thesis'].map((s) => `${s}:1`).join(',');
const HASH = `size=100&ground_res=512&years=${args.years}&density=0.0099&spacing=5&slope_max=90&mix=${MIX}`;

const SHOTS = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../build/artifacts/bench');
const loadAvg = () => Number(readFileSync('/proc/loadavg', 'utf8').split(' ')[0]);
const server = await startServer({ port: 0 });
const browser = await launchChromium();
let failed = false;
try {
  const context = await browser.newContext({ viewport: { width: args.width, height: args.height }, deviceScaleFactor: 1 });
  const errors = [];
  const open = async () => {
    const page = await context.newPage();
    page.on('pageerror', (e) => errors.push(e.message));
    return page;
  };

  // The grove, hybrid: every tree and the first view's draw lists on screen.
  let t0 = Date.now();
  const grove = await open();
  await grove.goto(`${server.url}grove.html#mode=hybrid`);
  await grove.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'error' || (d.status === 'ready' && d.drawnMode === 'hybrid' && d.viewPending === '0' && Number(d.viewSerial || 0) > 0);
  }, null, { timeout: 600_000, polling: 200 });
  if ((await grove.evaluate(() => document.documentElement.dataset.status)) === 'error') {
    throw new Error(`grove page: ${await grove.textContent('#message')}`);
  }
  const groveLoadS = (Date.now() - t0) / 1000;

  // The garden: the link grown in the page's worker, then Trees: hybrid with its first round of lists.
  t0 = Date.now();
  const garden = await open();
  await garden.goto(`${server.url}garden.html#${HASH}`);
  await garden.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'error' || (d.status === 'ready' && Number(d.gardenSerial) > 0 && d.drawnSerial === d.gardenSerial);
  }, null, { timeout: 1_200_000, polling: 250 });
  const grown = await garden.evaluate(() => ({ ...document.documentElement.dataset }));
  if (grown.status === 'error') throw new Error(`garden page: ${grown.error || ''} ${await garden.textContent('#notice')}`);
  const gardenGrowS = (Date.now() - t0) / 1000;
  const fullAtLoad = { triangles: Number(grown.drawnTriangles), drawCalls: Number(grown.drawCalls) };
  let gardenFullMs = null;
  if (args['full-frames'] > 0) gardenFullMs = await garden.evaluate((n) => window.__niwaGardenFrameMs(n), args['full-frames']);
  t0 = Date.now();
  await garden.selectOption('#trees-mode', 'hybrid');
  await garden.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'error' || (Number(d.hybridSerial) > 0 && d.hybridPending === '0' && d.drawnHybridSerial === d.hybridSerial);
  }, null, { timeout: 600_000, polling: 200 });
  const gardenHybridS = (Date.now() - t0) / 1000;

  // Alternated timings, each page brought to the front before its frames (a hidden page's
  // requestAnimationFrame does not run).
  // The garden also with its ground's full grid (no level of detail: the frame before it, same view).
  // And each page without its trees (the grove's ground; the garden's ground, objects and ivy).
  const groveMs = [], gardenMs = [], gridMs = [], groveBareMs = [], gardenBareMs = [], loads = [loadAvg()];
  let groveTiming = null;
  // A timing starts only once the page's own frame loop has drawn what the last change asked for
  // (a frame it draws meanwhile would share the GPU with the timed frames): the garden's look serial
  // (data-drawn-look) after __niwaGardenGroundLod; the grove's ground-only timing asks for a frame
  // at its end, so it goes first and the whole grove's warm-up frame absorbs that one.
  const settled = async (px) => {
    const look = await garden.evaluate((v) => window.__niwaGardenGroundLod(v), px);
    await garden.waitForFunction((n) => Number(document.documentElement.dataset.drawnLook) >= n, look, { timeout: 300_000, polling: 100 });
  };
  for (let rep = 0; rep < args.reps; ++rep) {
    await grove.bringToFront();
    groveBareMs.push((await grove.evaluate((n) => window.grove.timeFrames(n, -1), args.frames)).median);
    groveTiming = await grove.evaluate((n) => window.grove.timeFrames(n), args.frames);
    groveMs.push(groveTiming.median);
    await garden.bringToFront();
    await settled(undefined);
    gardenMs.push(await garden.evaluate((n) => window.__niwaGardenFrameMs(n), args.frames));
    await settled(0);
    gridMs.push(await garden.evaluate((n) => window.__niwaGardenFrameMs(n), args.frames));
    await settled(undefined);
    gardenBareMs.push(await garden.evaluate((n) => window.__niwaGardenFrameMs(n, { trees: false }), args.frames));
    loads.push(loadAvg());
  }
  // the hooks of a loop frame with the ground's level of detail
  const look = await garden.evaluate(() => window.__niwaGardenGroundLod(undefined));
  await garden.waitForFunction((n) => Number(document.documentElement.dataset.drawnLook) >= n, look, { timeout: 300_000, polling: 200 });
  const g = await garden.evaluate(async () => {
    const d = document.documentElement.dataset, c = document.getElementById('view');
    return { ...d, width: c.width, height: c.height };
  });
  if (errors.length) throw new Error(`page error: ${errors[0]}`);
  // What was timed, for a look (build/artifacts/bench/).
  mkdirSync(SHOTS, { recursive: true });
  await grove.bringToFront();
  await grove.locator('#view').screenshot({ path: path.join(SHOTS, 'garden-hybrid-grove.png') });
  await garden.bringToFront();
  await garden.locator('#view').screenshot({ path: path.join(SHOTS, 'garden-hybrid-garden.png') });
  const round = (x, k = 1) => (x === null ? null : Number(x.toFixed(k)));
  const groveRow = {
    workload: 'garden-hybrid/grove', note: 'public/grove.html#mode=hybrid, 100 instances of 10 unique trees',
    ms: round(median(groveMs)), ms_reps: groveMs.map((x) => round(x)), frames: args.frames, trees: groveTiming.instances,
    no_trees_ms: round(median(groveBareMs)),
    unique: groveTiming.uniqueDrawn, triangles: groveTiming.triangles, lines: groveTiming.lines, draw_calls: groveTiming.drawCalls,
    width: groveTiming.width, height: groveTiming.height, load_s: round(groveLoadS),
  };
  const gardenRow = {
    workload: `garden-hybrid/garden-100-${args.years}y`, note: 'public/garden.html, the scale garden (wall ivy, moss), Trees: hybrid',
    hash: HASH, ms: round(median(gardenMs)), ms_reps: gardenMs.map((x) => round(x)), frames: args.frames,
    trees: Number(g.trees), distinct: Number(g.distinct), hybrid_trees: Number(g.hybridTrees), full_trees: Number(g.fullTrees),
    triangles: Number(g.drawnTriangles), ground_triangles: Number(g.drawnGround), ground_strides: g.groundStrides,
    lines: Number(g.drawnLines), draw_calls: Number(g.drawCalls),
    no_trees_ms: round(median(gardenBareMs)), full_grid_ms: round(median(gridMs)), full_grid_ms_reps: gridMs.map((x) => round(x)),
    atlas_triangles: Number(g.hybridAtlasTriangles), atlas_sides: g.hybridAtlasSides, atlas_queue_ms: Number(g.hybridAtlasMs),
    full_triangles: fullAtLoad.triangles, full_draw_calls: fullAtLoad.drawCalls, full_ms: round(gardenFullMs),
    width: g.width, height: g.height, grow_s: round(gardenGrowS), page_grow_ms: Number(g.growMs),
    hybrid_s: round(gardenHybridS), lists_ms: Number(g.hybridMs),
  };
  const ratio = median(gardenMs) / median(groveMs);
  const perPixel = ratio / ((g.width * g.height) / (groveTiming.width * groveTiming.height));
  console.log(JSON.stringify(groveRow));
  console.log(JSON.stringify(gardenRow));
  console.log(JSON.stringify({
    workload: 'garden-hybrid/ratio', note: 'garden / grove ms per frame, hybrid, same run (≤ 1: the garden draws at the grove\'s rate)',
    ratio: round(ratio, 2), trees_ratio: round((median(gardenMs) - median(gardenBareMs)) / (median(groveMs) - median(groveBareMs)), 2), ratio_reps: gardenMs.map((x, i) => round(x / groveMs[i], 2)), ratio_per_pixel: round(perPixel, 2),
    load: loads.map((x) => round(x, 2)),
  }));
} catch (e) {
  console.error(`bench/garden_hybrid.mjs: ${e.stack || e}`);
  failed = true;
} finally {
  await browser.close();
  await server.close();
}
process.exit(failed ? 1 : 0);
