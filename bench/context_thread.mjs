// Where a WebGL2 context's start blocks (issue 32 item 5: "no main-thread task over 200 ms during
// load"): a bare page that makes a WebGL2 context and clears it, its context made on the main thread
// (getContext) or in a Web Worker (transferControlToOffscreen, the worker's getContext), alternating,
// a fresh Chromium per load. Prints one JSON line per load: the main thread's long tasks (ms, from
// PerformanceObserver 'longtask'), the time to the cleared frame, and for the worker the ms its
// getContext and clear took there.
// node bench/context_thread.mjs [--reps 3]
// Does not: draw anything but a clear, or judge the goal (docs/BENCHMARKS.md does, with the load).
import { launchChromium } from '../tests/browser/harness.mjs';
import { median, wholeNumberArgs } from './page_bench.mjs';

const { reps } = wholeNumberArgs({ reps: 3 }, 'node bench/context_thread.mjs [--reps 3]');
const MAIN = `<!doctype html><canvas id="c" width="1100" height="760"></canvas><script>
const gl = document.getElementById('c').getContext('webgl2');
gl.clearColor(0.8, 0.85, 0.9, 1); gl.clear(gl.COLOR_BUFFER_BIT);
requestAnimationFrame(() => { document.documentElement.dataset.drawnAt = String(performance.now()); });
</script>`;
const WORKER = `onmessage = (e) => { const t0 = performance.now(); const gl = e.data.getContext('webgl2');
gl.clearColor(0.8, 0.85, 0.9, 1); gl.clear(gl.COLOR_BUFFER_BIT); postMessage(performance.now() - t0); };`;
const OFFSCREEN = `<!doctype html><canvas id="c" width="1100" height="760"></canvas><script>
const off = document.getElementById('c').transferControlToOffscreen();
const worker = new Worker('/context_worker.js');
worker.postMessage(off, [off]);
worker.onmessage = (e) => requestAnimationFrame(() => {
  document.documentElement.dataset.workerMs = String(e.data);
  document.documentElement.dataset.drawnAt = String(performance.now());
});
</script>`;

const rows = { main: [], worker: [] };
for (let rep = 0; rep < reps; ++rep) {
  for (const [where, body] of [['main', MAIN], ['worker', OFFSCREEN]]) {
    const browser = await launchChromium();
    try {
      const context = await browser.newContext({ viewport: { width: 1100, height: 760 } });
      await context.route('**/*', (route) => {
        const worker = new URL(route.request().url()).pathname === '/context_worker.js';
        return route.fulfill({ body: worker ? WORKER : body, contentType: worker ? 'text/javascript' : 'text/html' });
      });
      await context.addInitScript(() => {
        window.__longtasks = [];
        new PerformanceObserver((list) => {
          for (const e of list.getEntries()) window.__longtasks.push(Math.round(e.duration));
        }).observe({ type: 'longtask', buffered: true });
      });
      const page = await context.newPage();
      await page.goto('http://context.test/');
      await page.waitForFunction(() => document.documentElement.dataset.drawnAt, null, { timeout: 120_000 });
      await page.waitForTimeout(500);  // a long task is reported after it ends
      const r = await page.evaluate(() => ({ longTasks: window.__longtasks,
        drawnMs: Math.round(Number(document.documentElement.dataset.drawnAt)),
        workerMs: document.documentElement.dataset.workerMs ? Math.round(Number(document.documentElement.dataset.workerMs)) : null }));
      const longest = Math.max(0, ...r.longTasks);
      rows[where].push(longest);
      console.log(JSON.stringify({ workload: `context-thread/${where}`, rep, longest_main_task_ms: longest, ...r }));
    } finally {
      await browser.close();
    }
  }
}
for (const where of ['main', 'worker']) {
  console.log(JSON.stringify({ workload: `context-thread/${where}`, longest_main_task_median_ms: median(rows[where]), reps }));
}
