// Garden page benchmark (issue 33 item 7: "... grows to 15 years in ≤ 30 s natively and ≤ 2× that in
// the page"): the scale garden (100 m, 512² terrain, 100 trees of 10 species by the rules, 15 years,
// shade on, ivy on the 4 default objects, the default moss: bench/garden_workloads.cpp's
// garden/scale-100-trees-15y) as a link on public/garden.html in headless Debian chromium, and the same
// garden natively (`niwa garden grow --url HASH --stats`) in the same run. Prints one JSON line:
// {"workload": "garden-page/scale-100-trees-15y", "ms": the page's time from setting the link to the
//  frame that shows the grown garden (the worker's years, ivy, moss, buffers, the page's upload and
//  draw), "native_ms": the CLI's `ms` (growth only, no export), "ratio": ms / native_ms, "trees",
//  "ivy_stopped": whether the ivy was stopped by its budget (the page's line), "notice": the page's
//  notices}.
//
// node bench/garden_page.mjs
// Needs build/wasm/web/niwa_web.js, build/native/bin/niwa and playwright-core. Does not: build
// anything. SwiftShader draws on the CPU, so the frame holds a software rasteriser's share.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';
import { linkToFrameMs, newBenchPage, waitDrawn } from './page_bench.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const MIX = ['keyaki', 'sakura', 'maple', 'pine', 'ginkgo', 'weeping', 'tsutsuji', 'binary', 'keyaki-thesis',
  'sakura-thesis'].map((s) => `${s}:1`).join(',');
const HASH = `size=100&ground_res=512&years=15&density=0.0099&spacing=5&slope_max=90&mix=${MIX}` +
  '&ivy=objects[0],objects[1],objects[2],objects[3]';

const t0 = Date.now();
const cli = JSON.parse(execFileSync(path.join(ROOT, 'build/native/bin/niwa'),
  ['garden', 'grow', '--url', HASH, '--stats'], { encoding: 'utf8', maxBuffer: 64 << 20 }));
const nativeWall = Date.now() - t0;

const server = await startServer({ port: 0 });
const browser = await launchChromium();
let failed = false;
try {
  const { page, errors } = await newBenchPage(browser);
  // The opening garden first (the module compiled and the worker warm), then the link.
  await page.goto(`${server.url}garden.html`);
  await waitDrawn(page, 'gardenSerial', 0);
  const ms = await linkToFrameMs(page, 'gardenSerial', `#${HASH}`);
  const data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  const notice = await page.evaluate(() => [...document.querySelectorAll('.notice, #message, [data-notice]')]
    .map((e) => e.textContent.trim()).filter(Boolean).join(' | ').slice(0, 600));
  if (ms < 0) throw new Error(`garden page: ${data.error || data.status}: ${notice}`);
  console.log(JSON.stringify({
    workload: 'garden-page/scale-100-trees-15y',
    note: 'chromium worker, WASM; link to the frame of the grown garden; native: niwa garden grow --url --stats in the same run',
    ms: Math.round(ms), native_ms: Math.round(cli.ms), native_wall_ms: nativeWall, ratio: Number((ms / cli.ms).toFixed(2)),
    grow_ms: Number(data.growMs), trees: cli.trees?.count, page_trees: Number(data.trees),
    ivy_internodes: cli.ivy?.internodes, page_ivy_internodes: JSON.parse(data.stats || '{}').ivy?.internodes,
    truncated: JSON.parse(data.stats || '{}').truncated ?? null, notice, errors,
  }));
} catch (e) {
  console.error(`garden_page bench: ${e.message}`);
  failed = true;
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
