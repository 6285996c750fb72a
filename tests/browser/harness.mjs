// Shared parts of the browser tests: paths, PASS/FAIL counting, the native CLI, waiting for a tree, Chromium.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const NATIVE = process.env.NIWA_NATIVE || path.join(ROOT, 'build/native/bin/niwa');
export const ARTIFACTS = path.join(ROOT, 'build/artifacts');
export const TIMEOUT = 180_000;  // SwiftShader and a first WASM compile are slow
fs.mkdirSync(ARTIFACTS, { recursive: true });

const counts = { passed: 0, failed: 0 };
const STARTED_MS = performance.now();
// check(name, ok, detail), the order of tests/support/cli_pair.mjs too. `ok` must not be a string
// (the arguments swapped): that is a failure, not a pass.
export function check(name, ok, detail = '') {
  const pass = typeof ok !== 'string' && Boolean(ok);
  if (pass) ++counts.passed; else ++counts.failed;
  const why = typeof ok === 'string' ? ' — check(name, ok): ok is a string (arguments swapped?)' : '';
  // [t s]: seconds since the test started, so a slow step shows in the log (build/artifacts/*.test.txt).
  const at = ((performance.now() - STARTED_MS) / 1000).toFixed(1);
  console.log(`${pass ? 'PASS' : 'FAIL'} ${name}${detail ? ` — ${detail}` : ''}${why} [${at} s]`);
}

// Page answer times (a click answered within 1 s, no main-thread task over 200 ms) are speed goals,
// and speed goals are met in benchmarks, not in timed tests (the brief). Under scripts/test a timed
// check guards only against a hang (HANG_MS) and prints the time; `scripts/bench` runs the tests that
// use it one at a time with NIWA_TIMED=1, where the target itself is checked and each time is added
// to build/artifacts/bench/page-timings.jsonl for docs/BENCHMARKS.md's speed goals.
export const TIMED = process.env.NIWA_TIMED === '1';
export const HANG_MS = 30_000;
export function timedCheck(name, ms, targetMs, detail = '') {
  if (TIMED) {
    const dir = path.join(ARTIFACTS, 'bench');
    fs.mkdirSync(dir, { recursive: true });
    const test = path.basename(process.argv[1] || '', '.test.mjs');
    fs.appendFileSync(path.join(dir, 'page-timings.jsonl'),
      `${JSON.stringify({ test, name, ms: Number(ms), target_ms: targetMs, detail })}\n`);
    check(`${name} (under ${targetMs} ms)`, ms < targetMs, detail);
  } else {
    check(`${name}: answered (hang guard ${HANG_MS / 1000} s; the ${targetMs} ms goal is scripts/bench's)`,
      ms < HANG_MS, `${Number(ms).toFixed(0)} ms; ${detail}`);
  }
}

// Prints the closing "N passed, N failed" line and exits 0 only when nothing failed.
export function finish() {
  console.log(`${counts.passed} passed, ${counts.failed} failed`);
  process.exit(counts.failed === 0 ? 0 : 1);
}

// The native CLI's --stats for the same tree options.
export function nativeStats(args) {
  const out = execFileSync(NATIVE, ['tree', 'grow', ...args, '--stats'], { encoding: 'utf8' });
  return JSON.parse(out.trim().split('\n').pop());
}

// Waits until the page has drawn a tree newer than serialAbove (the page's data-tree-serial).
export async function waitReady(page, serialAbove, polling = 250) {
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    // Ready with a tree newer than n, and a frame drawn with it (unless the page cannot draw).
    return d.status === 'ready' && Number(d.treeSerial) > n &&
      (d.drawnTreeSerial === d.treeSerial || d.drawing === 'off');
  }, serialAbove, { timeout: TIMEOUT, polling });
  await page.waitForTimeout(300);  // hybrid mode: let the draw list of the new tree arrive
}

// Waits until a study page (ivy, moss, bark, terrain) has a run newer than serialAbove drawn on screen,
// or shows an error; returns the page's dataset. serialKey names the page's run counter (e.g.
// 'mossSerial'); the frame drawn with it is data-drawn-serial (unless the page cannot draw).
export async function waitStudyRun(page, serialKey, serialAbove) {
  await page.waitForFunction(([key, n]) => {
    const d = document.documentElement.dataset;
    if (d.status === 'error') return true;
    return d.status === 'ready' && Number(d[key]) > n && (d.drawnSerial === d[key] || d.drawing === 'off');
  }, [serialKey, serialAbove], { timeout: TIMEOUT, polling: 200 });
  return page.evaluate(() => ({ ...document.documentElement.dataset }));
}

// Adds the console errors and warnings and the uncaught errors of `page` to `problems` (a test
// ends with a check that it stayed empty); returns the page.
export function watchPage(page, problems) {
  page.on('console', (m) => {
    if (m.type() === 'error' || m.type() === 'warning') problems.push(`${m.type()}: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  return page;
}

// A page of the app's origin (embed.html, nothing grown) on which a test imports web/ modules and
// drives them itself, watched by watchPage into `problems`.
export async function modulePage(server, browser, problems) {
  const context = await newContext(browser);
  const page = watchPage(await context.newPage(), problems);
  await page.goto(`${server.url}embed.html`, { timeout: TIMEOUT });
  return page;
}

// One click on a parameter group's <summary> (a control other than the one that is busy: the
// first closed group, else the first), timed from node to the second animation frame after its
// handler (the toggled group painted); the same summary is clicked again untimed, so the group ends
// as it was. Returns ms, or Infinity when there is no group or it did not toggle. The pages' answer
// to a click while they grow, draw or export (responsive.test.mjs, garden_page.test.mjs).
export async function clickToFrame(page) {
  const start = Date.now();
  const toggled = await page.evaluate(() => new Promise((resolve) => {
    const summary = document.querySelector('#params details.group:not([open]) > summary') ||
      document.querySelector('#params details.group > summary');
    window.__niwaClickedSummary = summary;
    if (!summary) { resolve(false); return; }
    const details = summary.parentElement;
    const before = details.open;
    summary.addEventListener('click', () => requestAnimationFrame(() => requestAnimationFrame(() => resolve(details.open !== before))), { once: true });
    summary.click();
  }));
  const ms = Date.now() - start;
  await page.evaluate(() => window.__niwaClickedSummary?.click());  // back as it was (not timed)
  return toggled ? ms : Infinity;
}

// A click (or with tap: true, a tap) on the tree page's view at page pixel (x, y), waiting until the
// page has the pick's answer (the view picks in its render worker, web/tree/tree_view.js, after the
// frame on the GPU: data-picks-answered counts the answers); at most 30 s.
export async function pickAt(page, x, y, { tap = false } = {}) {
  const answered = () => page.evaluate(() => Number(document.documentElement.dataset.picksAnswered || 0));
  const before = await answered();
  if (tap) await page.touchscreen.tap(x, y);
  else await page.mouse.click(x, y);
  await page.waitForFunction((n) => Number(document.documentElement.dataset.picksAnswered || 0) > n, before,
    { timeout: 30_000, polling: 50 }).catch(() => {});
}

// Grove page: waits until it has drawn `mode` with everything it needs (all trees; in hybrid mode a
// frame drawn with the draw lists of a view newer than viewSerialAbove: the lists arrive before the
// frame that draws them, and a snapshot in between shows the previous lists), or shows an error.
export function waitGroveDrawn(page, mode, viewSerialAbove = 0) {
  return page.waitForFunction(([m, v]) => {
    const d = document.documentElement.dataset;
    if (d.status === 'error') return true;
    return d.status === 'ready' && d.drawnMode === m && d.viewPending === '0' &&
      (m === 'full' || Number(d.drawnViewSerial || 0) > v);
  }, [mode, viewSerialAbove], { timeout: TIMEOUT, polling: 200 });
}

// Debian chromium with a real WebGL2 context on SwiftShader (see ../shared/TOOLCHAIN.md).
export const CHROMIUM_OPTIONS = {
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-sandbox',
    '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update',
    '--disable-sync'],
};

// The test's browser. Under scripts/test, each lane's tests connect to that lane's one browser
// (NIWA_BROWSER_WS, tests/browser/lane_browser.mjs) instead of starting their own: a fresh browser's
// first page cost 5-6 CPU s more than the same page in a browser that had drawn before (its GPU
// process compiling SwiftShader's routines and ANGLE's shaders; tree, ivy and garden pages alike,
// measured 2026-12-07), plus 2.4 s to start it; four tests one after another took 204 CPU s with a
// browser each and 187 sharing one (idle, 2026-12-07 14:50), about 4 CPU s a test. Each test
// still gets its own contexts (cookies, storage, caches) and its own server (its own origin); closing
// a connected browser closes this test's contexts only. When the lane's browser is gone (it crashed),
// the test starts its own and says so. Alone (node tests/browser/X.test.mjs) or under scripts/bench,
// a fresh browser as before.
export async function launchChromium() {
  const ws = process.env.NIWA_BROWSER_WS;
  if (ws) {
    try {
      return await chromium.connect(ws, { timeout: 30_000 });
    } catch (e) {
      console.log(`(the lane's browser at ${ws} did not answer: ${String(e.message).split('\n')[0]}; starting one)`);
    }
  }
  return chromium.launch(CHROMIUM_OPTIONS);
}

// Runs one browser test: serves the app on a free port, launches Chromium, awaits
// body(server, browser), counts a throw as the failed check 'test ran to the end', closes both
// whatever happens and prints the results (finish).
export async function runBrowserTest(body) {
  const server = await startServer({ port: 0 });
  const browser = await launchChromium();
  try {
    await body(server, browser);
  } catch (e) {
    check('test ran to the end', false, e.stack || String(e));
  } finally {
    await browser.close();
    await server.close();
  }
  finish();
}

// A browser context whose pages (and their frames) all have window.__niwaCanvasImage(selector):
// the ImageData of a canvas ('#id', or 'host >>> canvas' for one in a shadow root), read through a
// 2D canvas (the page's WebGL canvas keeps its last frame: preserveDrawingBuffer). The one canvas
// reader of the browser tests.
// Its screen has DEVICE_SCALE device pixels per CSS pixel (0.75 unless the test gives its own
// deviceScaleFactor; NIWA_TEST_SCALE=1 for a run at the usual 1): the layout is the same in CSS
// pixels, and the canvases have 0.56 × the pixels. The suite's browser phase is bound by
// SwiftShader filling fragments (73 % of the GPU process's samples, frame time proportional to the
// canvas's pixels: 0.18 MP 100-170 ms, 0.9 MP 660-700 ms for a 12-year sakura).
export const DEVICE_SCALE = Number(process.env.NIWA_TEST_SCALE || 0.75);
export async function newContext(browser, options) {
  const context = await browser.newContext({ deviceScaleFactor: DEVICE_SCALE, ...options });
  await context.addInitScript(() => {
    window.__niwaCanvasImage = (selector) => {
      const [host, inner] = selector.split(' >>> ');
      const src = inner ? document.querySelector(host).shadowRoot.querySelector(inner) : document.querySelector(host);
      const c = document.createElement('canvas');
      c.width = src.width;
      c.height = src.height;
      const ctx = c.getContext('2d', { willReadFrequently: true });
      ctx.drawImage(src, 0, 0);
      return ctx.getImageData(0, 0, c.width, c.height);
    };
    // Every value each element's data-* hooks took, in order, from the page's first script on:
    // window.__niwaHookLog['#id data-step-shown'] = ['0', '1', ...] (see hookLog below).
    window.__niwaHookLog = {};
    new MutationObserver((records) => {
      for (const r of records) {
        const key = `${r.target.id ? `#${r.target.id}` : r.target.tagName.toLowerCase()} ${r.attributeName}`;
        (window.__niwaHookLog[key] ||= []).push(r.target.getAttribute(r.attributeName));
      }
    }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-step-shown', 'data-level-shown', 'data-hash', 'data-year', 'data-drawn-year'] });
  });
  return context;
}

// The values data-<attribute> of `selector` ('#id', or 'html') took since the page loaded, in
// order (data-step-shown, data-level-shown, data-hash and data-year are recorded).
export async function hookLog(page, selector, attribute) {
  return page.evaluate((key) => window.__niwaHookLog[key] || [], `${selector} ${attribute}`);
}

// Whether `values` (strings) are the whole numbers first, first + 1, ..., last in order.
export function isConsecutiveRun(values, first, last) {
  if (values.length !== last - first + 1) return false;
  return values.every((v, i) => v === String(first + i));
}

// Keeps a copy of a canvas's pixels in the page under `name` (selector as in newContext) and
// returns the centroid (x in [0, 1]) and share of the dark pixels (luma < 100: bark, leaves, the
// ground's shadow; not the sky or the ground).
export async function snapshotCanvas(page, name, selector = '#view') {
  return page.evaluate(([key, sel]) => {
    const image = window.__niwaCanvasImage(sel);
    (window.__snapshots ||= {})[key] = image;
    const d = image.data;
    let sx = 0, n = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (0.299 * d[i] + 0.587 * d[i + 1] + 0.114 * d[i + 2] < 100) {
        sx += ((i / 4) % image.width) / image.width;
        ++n;
      }
    }
    return { centroidX: n ? sx / n : 0, share: n / (d.length / 4) };
  }, [name, selector]);
}

// Writes the canvas's current image (drawing buffer preserved) to build/artifacts/FILE as PNG.
// Unlike page.screenshot it needs no new compositor frame, which a grove redrawing in full mode
// every frame under SwiftShader may not give within a timeout on a loaded machine.
export async function saveCanvasPng(page, file, selector = '#view') {
  const url = await page.evaluate((sel) => document.querySelector(sel).toDataURL('image/png'), selector);
  fs.writeFileSync(path.join(ARTIFACTS, file), Buffer.from(url.split(',')[1], 'base64'));
}

// Pans (a right drag: no click, so no seed) the centroid of the canvas pixels of one colour class to
// the view's centre, then zooms in by `wheelSteps` wheel steps there. colourTest: the source of a
// function (r, g, b) => boolean, run in the page. Returns whether any pixel was of that class (no
// pan without one; the zoom happens either way).
export async function panToColourAndZoom(page, colourTest, { wheelSteps = 5 } = {}) {
  const box = await page.locator('#view').boundingBox();
  const centre = await page.evaluate((source) => {
    const keep = (0, eval)(source);
    const image = window.__niwaCanvasImage('#view');
    const d = image.data;
    let sx = 0, sy = 0, n = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (!keep(d[i], d[i + 1], d[i + 2])) continue;
      sx += (i / 4) % image.width;
      sy += Math.floor(i / 4 / image.width);
      ++n;
    }
    const css = image.width / document.getElementById('view').clientWidth;
    return n ? { x: sx / n / css, y: sy / n / css } : null;
  }, colourTest);
  if (centre) {
    await page.mouse.move(box.x + centre.x, box.y + centre.y);
    await page.mouse.down({ button: 'right' });
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 8 });
    await page.mouse.up({ button: 'right' });
  }
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let i = 0; i < wheelSteps; ++i) await page.mouse.wheel(0, -240);
  return centre !== null;
}

// Share of pixels whose colour differs by more than `tolerance` (sum over RGB) between two
// snapshots taken with snapshotCanvas.
export async function snapshotDifference(page, a, b, tolerance = 0) {
  return page.evaluate(([ka, kb, tol]) => {
    const A = window.__snapshots[ka], B = window.__snapshots[kb];
    // Two drawing-buffer sizes (the governor's scale while moving) are compared on the smaller
    // one's grid, each pixel against the nearest of the other (before, any size change counted as
    // every pixel changed, so a check for motion passed on a scale change alone).
    const w = Math.min(A.width, B.width), h = Math.min(A.height, B.height);
    const at = (img, i, j) => 4 * (Math.min(img.height - 1, Math.floor(((j + 0.5) * img.height) / h)) * img.width +
      Math.min(img.width - 1, Math.floor(((i + 0.5) * img.width) / w)));
    let n = 0;
    for (let j = 0; j < h; ++j) {
      for (let i = 0; i < w; ++i) {
        const p = at(A, i, j), q = at(B, i, j);
        const x = A.data, y = B.data;
        if (Math.abs(x[p] - y[q]) + Math.abs(x[p + 1] - y[q + 1]) + Math.abs(x[p + 2] - y[q + 2]) > tol) ++n;
      }
    }
    return n / (w * h);
  }, [a, b, tolerance]);
}

// Frame watch (issue 32, "no blank frames"): from now on, at every animation frame, the canvas
// `selector` ('#view') is drawn into a 64×48 2D canvas (its drawing buffer: preserved, so what is
// on screen) and the share of its pixels that are not the background (web/gl/context.js
// BACKGROUND) is recorded, with the share that changed since the last sample. The first sample,
// taken now, is the reference: the finished picture before the action watched.
export async function startFrameWatch(page, selector = '#view') {
  await page.evaluate((sel) => {
    const src = document.querySelector(sel);
    const W = 64, H = 48, bg = [219, 230, 240];
    const small = document.createElement('canvas');
    small.width = W;
    small.height = H;
    const ctx = small.getContext('2d', { willReadFrequently: true });
    const grab = () => {
      ctx.drawImage(src, 0, 0, W, H);
      const d = ctx.getImageData(0, 0, W, H).data;
      let drawn = 0;
      for (let i = 0; i < d.length; i += 4) {
        if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 24) ++drawn;
      }
      return { d, share: drawn / (W * H) };
    };
    const first = grab();
    const watch = { reference: first.share, samples: [], running: true, start: performance.now(), last: first.d, emptiest: null };
    const tick = () => {
      if (!watch.running) return;
      const now = grab();
      let changed = 0;
      for (let i = 0; i < now.d.length; i += 4) {
        const a = now.d, b = watch.last;
        if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 24) ++changed;
      }
      watch.last = now.d;
      watch.samples.push([performance.now() - watch.start, now.share, changed / (W * H)]);
      if (!watch.emptiest || now.share < watch.emptiest.share) watch.emptiest = { share: now.share, url: small.toDataURL('image/png') };
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
    window.__niwaFrameWatch = watch;
  }, selector);
}

// Ends the frame watch and returns {frames (samples), reference (share of the picture before),
// empty (samples drawn over less than a quarter of the reference's share: no tree, ivy or
// mountain on screen), emptyMs (the longest run of empty samples, from its first to the sample
// after it), minShare, changeMs (the median time between samples that changed: the frame time
// the user sees), changes}. Saves the emptiest sample as build/artifacts/FILE (PNG, 64×48).
export async function stopFrameWatch(page, file) {
  const w = await page.evaluate(() => {
    const watch = window.__niwaFrameWatch;
    watch.running = false;
    return { reference: watch.reference, samples: watch.samples, emptiest: watch.emptiest };
  });
  if (w.emptiest) fs.writeFileSync(path.join(ARTIFACTS, file), Buffer.from(w.emptiest.url.split(',')[1], 'base64'));
  const limit = 0.25 * w.reference;
  let empty = 0, emptyMs = 0, runStart = -1, lastChange = -1;
  const gaps = [];
  w.samples.forEach(([t, share, changed], i) => {
    if (share < limit) {
      ++empty;
      if (runStart < 0) runStart = t;
      const next = w.samples[i + 1];
      emptyMs = Math.max(emptyMs, (next ? next[0] : t) - runStart);
    } else runStart = -1;
    if (changed > 0.002) {
      if (lastChange >= 0) gaps.push(t - lastChange);
      lastChange = t;
    }
  });
  gaps.sort((a, b) => a - b);
  return {
    frames: w.samples.length, reference: w.reference, empty, emptyMs, changes: gaps.length + (lastChange >= 0 ? 1 : 0),
    minShare: Math.min(...w.samples.map((s) => s[1])), changeMs: gaps.length ? gaps[Math.floor(gaps.length / 2)] : NaN,
  };
}
