// Tree page edit latency (issue 32 item 5: "an edit's new tree on screen within 1.5× its grow time
// plus one frame"; the issue saw Shoot length's new tree after 3.2 s for a 0.61 s grow): the default
// tree page in headless Debian chromium; Shoot length (#param-D_high) typed `--reps` times with
// different values. Per edit, on the page's clock: `ms` from the input event to the first whole
// frame of the new tree (data-drawn-tree-serial), `worker_ms` the worker's wall time for that grow
// (its request to its 'tree' message: the grow, the mesh, the copies out of the heap), and
// `frame_ms` from the tree's message to that frame (the upload and the frame); `built_ms` the
// worker's time to the built mesh, without the copies out of the heap (until 2026-12-08 that was
// worker_ms: the copies, tens to hundreds of ms under load, counted as the page's). The goal holds when
// ms ≤ 1.5 × worker_ms + frame_ms, i.e. the debounce, the messages and the transfer stay under half
// the grow. Prints one JSON line {"workload": "tree-page/edit-shoot-length", "ms", "worker_ms",
// "frame_ms", "bound_ms", "met", "reps", "runs": [...]} (medians).
//
// node bench/edit_latency.mjs [--reps 5] [--settle 500]
// --settle: ms between one edit's frame and the next edit (at 500 a loaded SwiftShader is often
// still drawing the last tree's frame, which the next edit's frame then waits for).
// Needs build/wasm/web/niwa_web.js and playwright-core. SwiftShader draws on the CPU.
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';
import { median, newBenchPage, wholeNumberArgs } from './page_bench.mjs';

const args = wholeNumberArgs({ reps: 5, settle: 500 }, 'usage: node bench/edit_latency.mjs [--reps N] [--settle MS]');

const server = await startServer({ port: 0 });
const browser = await launchChromium();
let failed = false;
try {
  const { page, errors } = await newBenchPage(browser);
  await page.goto(server.url);
  await page.waitForFunction(() => {  // the default tree's first whole frame (the tree page's hooks)
    const d = document.documentElement.dataset;
    return d.status === 'error' || (Number(d.treeSerial) >= 1 && d.drawnTreeSerial === d.treeSerial && d.framePartial === '0');
  }, null, { timeout: 300_000, polling: 100 });
  const runs = [];
  const values = ['2.5', '3.5', '2', '4', '3', '2.25', '3.25', '2.75'];
  for (let rep = 0; rep < args.reps; ++rep) {
    const value = values[rep % values.length];
    const run = await page.evaluate(({ v }) => new Promise((resolve) => {
      const input = document.getElementById('param-D_high');
      const d = document.documentElement.dataset;
      const serial = Number(d.treeSerial);
      const observer = new MutationObserver(() => {
        if (d.status === 'error') { observer.disconnect(); resolve({ error: d.error || 'error' }); return; }
        if (Number(d.treeSerial) > serial && d.drawnTreeSerial === d.treeSerial && d.framePartial === '0') {
          observer.disconnect();
          const now = performance.now();
          resolve({ ms: now - t0, worker_ms: Number(d.treeWorkerMs), built_ms: Number(d.treeBuiltMs), frame_ms: now - Number(d.treeArrivedMs), value: v });
        }
      });
      observer.observe(document.documentElement, { attributes: true });
      const t0 = performance.now();
      input.value = v;
      input.dispatchEvent(new Event('input', { bubbles: true }));
      input.dispatchEvent(new Event('change', { bubbles: true }));
    }), { v: value });
    if (run.error) throw new Error(`tree page: ${run.error}`);
    runs.push(run);
    await page.waitForTimeout(args.settle);
  }
  const ms = median(runs.map((r) => r.ms)), worker = median(runs.map((r) => r.worker_ms));
  const frame = median(runs.map((r) => r.frame_ms)), built = median(runs.map((r) => r.built_ms));
  const bound = 1.5 * worker + frame;
  console.log(JSON.stringify({
    workload: 'tree-page/edit-shoot-length', note: 'default tree page, Shoot length typed; input to the first whole frame of the new tree',
    ms: Math.round(ms), worker_ms: Math.round(worker), built_ms: Math.round(built), frame_ms: Math.round(frame), bound_ms: Math.round(bound), met: ms <= bound,
    reps: runs.length, settle_ms: args.settle,
    runs: runs.map((r) => ({ value: r.value, ms: Math.round(r.ms), worker_ms: Math.round(r.worker_ms), built_ms: Math.round(r.built_ms), frame_ms: Math.round(r.frame_ms) })),
    errors,
  }));
} catch (e) {
  console.error(`edit_latency bench: ${e.message}`);
  failed = true;
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
