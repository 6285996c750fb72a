// Moss page benchmark (issue 29 item 6: "the page reaches day 300 on `thesis` in ≤ 10 s and the
// scrubber answers in ≤ 100 ms"): public/moss.html in headless Debian chromium. Prints two JSON lines:
// {"workload": "moss-page/grow-thesis-300", "ms": median from setting the link of the thesis workload
//  (300 days, 8,192 photons a day, thesis scene, the 16,384-moss cap: the table's defaults) to the
//  frame that shows day 300 (the worker's grow, its buffers, the page's upload and draw), "min_ms",
//  "reps", "worker_ms": the worker's median wall time from the update to the posted run, "grow_ms":
//  MossLab.grow's, "mosses": the run's mosses on day 300}
// {"workload": "moss-page/scrub-thesis-300", "ms": median from the scrubber's input event to the frame
//  that shows the day (no regrow: the page replays the mosses' birth and death days), "max_ms",
//  "reps": days scrubbed (a fixed spread over 0..300)}.
//
// node bench/moss_page.mjs [--reps 3] [--scrubs 20]
// Needs build/wasm/web/niwa_web.js (cmake --build build/wasm --target niwa_web) and playwright-core.
// SwiftShader draws on the CPU, so the frame times hold a software rasteriser's share.
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';
import { linkToFrameMs, median, newBenchPage, waitDrawn, wholeNumberArgs } from './page_bench.mjs';

const args = wholeNumberArgs({ reps: 3, scrubs: 20 }, 'usage: node bench/moss_page.mjs [--reps N] [--scrubs N]');
const round = (x, digits = 1) => Number(x.toFixed(digits));

const THESIS = 'preset=nomura2010&scene=thesis&days=300&photons=8192&max_mosses=16384';
const DAYS = 300;

const server = await startServer({ port: 0 });
const browser = await launchChromium();
let failed = false;
try {
  const { page, errors } = await newBenchPage(browser);
  // A short run first (the module compiled and the worker warm), then the workload `reps` times:
  // each rep changes the seed so that the page grows again (a link it shows already is no change).
  await page.goto(`${server.url}moss.html#preset=nomura2010&scene=thesis&days=5&photons=1024`);
  await waitDrawn(page, 'mossSerial', 0);
  const grows = [];
  let last = null;
  for (let rep = 0; rep < args.reps; ++rep) {
    // Page time from the link's change to the frame that shows the run (data-drawn-serial moves).
    const ms = await linkToFrameMs(page, 'mossSerial', `#${THESIS}&seed=${rep + 1}`);
    last = await page.evaluate(() => ({ ...document.documentElement.dataset }));
    if (ms < 0 || last.status !== 'ready') throw new Error(`moss page: ${last.error || last.status}`);
    if (Number(last.days) !== DAYS) throw new Error(`moss page: the run has ${last.days} days, not ${DAYS}`);
    grows.push({ ms, worker: Number(last.wallMs), grow: Number(last.growMs), mosses: Number(last.mosses) });
  }
  console.log(JSON.stringify({
    workload: `moss-page/grow-thesis-${DAYS}`, note: 'chromium worker, WASM; link to the frame of day 300, 8,192 photons a day, nomura2010',
    ms: round(median(grows.map((g) => g.ms))), min_ms: round(Math.min(...grows.map((g) => g.ms))), reps: grows.length,
    worker_ms: round(median(grows.map((g) => g.worker))), grow_ms: round(median(grows.map((g) => g.grow))), mosses: grows[grows.length - 1].mosses,
  }));

  // The scrubber on the last run: days spread over 0..299 in a jumping order (37k + 11 mod 300: no
  // day twice, never the day shown), each from its input event to the frame that shows it
  // (data-drawn-day).
  const days = Array.from({ length: Math.min(args.scrubs, DAYS) }, (_, k) => (37 * k + 11) % DAYS);
  const scrubs = [];
  for (const day of days) {
    const ms = await page.evaluate((k) => new Promise((resolve) => {
      const r = document.getElementById('day');
      const t0 = performance.now();
      const observer = new MutationObserver(() => {
        if (document.documentElement.dataset.drawnDay === String(k)) {
          observer.disconnect();
          resolve(performance.now() - t0);
        }
      });
      observer.observe(document.documentElement, { attributes: true, attributeFilter: ['data-drawn-day'] });
      r.value = String(k);
      r.dispatchEvent(new Event('input', { bubbles: true }));
    }), day);
    scrubs.push(ms);
  }
  console.log(JSON.stringify({
    workload: `moss-page/scrub-thesis-${DAYS}`, note: `chromium, SwiftShader; input event to the frame of the day, ${last.mosses} mosses on day 300`,
    ms: round(median(scrubs)), max_ms: round(Math.max(...scrubs)), reps: scrubs.length,
  }));
  if (errors.length) throw new Error(`moss page: ${errors[0]}`);
  await page.close();
} catch (e) {
  console.error(`bench/moss_page.mjs: ${e.stack || e}`);
  failed = true;
} finally {
  await browser.close();
  await server.close();
}
process.exit(failed ? 1 : 0);
