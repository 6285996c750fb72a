// Shared steps of the page benchmarks (bench/garden_page.mjs, moss_page.mjs, terrain_page.mjs): a
// fresh 1200 × 800 page that collects page errors, waiting for a study's run to be drawn, and the
// time from setting a link to the frame that shows its run; their whole-number flags and medians
// (edit_latency.mjs too). Does not: start the server or browser, or print anything.

// A new page of `browser` at 1200 × 800 (device scale 1) and the list its page errors go to.
export async function newBenchPage(browser) {
  const context = await browser.newContext({ viewport: { width: 1200, height: 800 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  return { page, errors };
}

// Waits until the page's run serial (data-<serialKey>) passes `above` and that run is drawn
// (data-drawn-serial), or the page shows an error.
export function waitDrawn(page, serialKey, above, timeout = 600_000) {
  return page.waitForFunction(({ key, n }) => {
    const d = document.documentElement.dataset;
    return d.status === 'error' || (d.status === 'ready' && Number(d[key]) > n && d.drawnSerial === d[key]);
  }, { key: serialKey, n: above }, { timeout, polling: 100 });
}

// Milliseconds (page clock) from setting location.hash to `hash` until the next run (data-<serialKey>
// above its value now) is drawn; -1 when the page shows an error instead.
export async function linkToFrameMs(page, serialKey, hash) {
  const n = Number(await page.evaluate((key) => document.documentElement.dataset[key], serialKey));
  return page.evaluate(({ key, h, above }) => new Promise((resolve) => {
    const t0 = performance.now();
    const observer = new MutationObserver(() => {
      const d = document.documentElement.dataset;
      if ((d.status === 'ready' && Number(d[key]) > above && d.drawnSerial === d[key]) || d.status === 'error') {
        observer.disconnect();
        resolve(d.status === 'error' ? -1 : performance.now() - t0);
      }
    });
    observer.observe(document.documentElement, { attributes: true });
    location.hash = h;
  }), { key: serialKey, h: hash, above: n });
}

// `--key N` pairs of process.argv over `defaults` (each a whole number ≥ 1); anything else prints
// `usage` and exits 2.
export function wholeNumberArgs(defaults, usage) {
  const args = { ...defaults };
  for (let i = 2; i < process.argv.length; i += 2) {
    const key = process.argv[i].replace(/^--/, '');
    if (!(key in args) || !Number.isInteger(Number(process.argv[i + 1])) || Number(process.argv[i + 1]) < 1) {
      console.error(usage);
      process.exit(2);
    }
    args[key] = Number(process.argv[i + 1]);
  }
  return args;
}

// The median of numbers (the mean of the middle two for an even count).
export function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[s.length >> 1] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
}
