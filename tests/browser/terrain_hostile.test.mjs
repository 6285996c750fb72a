// Browser test of the terrain page's hostile inputs (issue 34): node tests/browser/terrain_hostile.test.mjs
// (exit 0 = pass). Midpoint displacement at θ = 89 is a line beside θ_max (the worker's run used to
// die with "worker: [object WebAssembly.Exception]") and the page recovers; a 17,000-character link
// and a link with a repeated key are notices with a mountain (a blank canvas before); a link at the
// largest `down` is refused beside `down` while the main thread keeps answering (71 s stalled
// before); a dropped GeoJSON whose "type" is a number settles with a line beside the plan; a
// 2,000-point contour writes a link the page reads back (over 16,384 characters before).
import path from 'node:path';
import { ARTIFACTS, TIMEOUT, check, newContext, runBrowserTest, timedCheck, watchPage } from './harness.mjs';

// Waits for a mountain newer than serialAbove, or an error; returns the dataset.
async function waitSettled(page, serialAbove) {
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    return d.status === 'error' || (d.status === 'ready' && Number(d.terrainSerial) > n);
  }, serialAbove, { timeout: TIMEOUT, polling: 200 });
  return page.evaluate(() => ({ ...document.documentElement.dataset }));
}

const besideField = (page, id) => page.evaluate((key) => {
  const input = document.getElementById(key);
  const line = input?.closest('.field')?.querySelector('.field-error');
  return line && !line.hidden ? line.textContent : '';
}, id);

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 } });
  const open = async (hash) => {
    const page = await context.newPage();
    watchPage(page, problems);
    await page.goto(`${server.url}terrain.html${hash}`, { waitUntil: 'load' });
    return page;
  };

  // 1. θ = 89 on the disk (d'' = 10 m ≥ √3·d0): one line beside θ_max, and the page recovers.
  {
    const page = await open('#preset=improved&builtin=disk&theta_min=89&theta_max=89');
    const d = await waitSettled(page, 0);
    await page.click('#params details:has(#param-theta_max) > summary').catch(() => {});
    const line = await besideField(page, 'param-theta_max');
    check('θ = 89: a line beside theta_max, not a dead worker', d.status === 'error' && /^theta_max: 89: midpoint displacement/.test(line),
      `status ${d.status}: '${line}' ${d.error || ''}`);
    await page.screenshot({ path: path.join(ARTIFACTS, 'terrain-theta89.png') });
    await page.selectOption('#preset', 'improved');  // the preset's own rows again
    const d2 = await waitSettled(page, 0);
    check('θ = 89: the page recovers with the preset', d2.status === 'ready', `${d2.status} ${d2.error || ''}`);
    await page.close();
  }

  // 2. A 17,000-character link, and a link with a repeated key: a notice each, and a mountain.
  for (const [name, hash, expect] of [
    ['a 17,000-character link', `#builtin=disk&d=5${'0'.repeat(17000)}`, /^hash: 17017 characters; the limit is 16384, nothing was read/m],
    ['a repeated key', '#builtin=disk&builtin=lobes7', /^builtin: given 2 times; must be given once, nothing was read/m],
  ]) {
    const page = await open(hash);
    const d = await waitSettled(page, 0);
    const text = await page.textContent('#notice');
    check(`${name}: a notice and a mountain`, d.status === 'ready' && expect.test(text), `${d.status}; notice '${text.replace(/\n/g, ' | ')}'`);
    await page.close();
  }

  // 3. The largest `down`: refused beside down; the main thread answers throughout.
  {
    const page = await open('#preset=improved&builtin=lobes7&down=1000');
    let slowest = 0;
    const t0 = Date.now();
    while (Date.now() - t0 < TIMEOUT) {
      const t = Date.now();
      const status = await page.evaluate(() => document.documentElement.dataset.status);
      slowest = Math.max(slowest, Date.now() - t);
      if (status === 'error' || status === 'ready') break;
      await page.waitForTimeout(200);
    }
    const d = await page.evaluate(() => ({ ...document.documentElement.dataset }));
    await page.click('#params details:has(#param-down) > summary').catch(() => {});
    const line = await besideField(page, 'param-down');
    check('down = 1000: refused beside down', d.status === 'error' && /^down: [0-9,]+ contour vertices are more than the page draws/.test(line),
      `status ${d.status}: '${line}' ${d.error || ''}`);
    timedCheck('down = 1000: the slowest main-thread probe', slowest, 2000, `slowest probe ${slowest} ms`);
    await page.close();
  }

  // 4. A dropped GeoJSON whose "type" is a number settles with a line beside the plan.
  {
    const page = await open('');
    await waitSettled(page, 0);
    const t0 = Date.now();
    await page.setInputFiles('#contour-file', { name: 'typed.geojson', mimeType: 'application/geo+json', buffer: Buffer.from('{"type": 7, "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]}') });
    await page.waitForFunction(() => document.documentElement.dataset.contourNotice === 'file', null, { timeout: TIMEOUT });
    const line = await page.evaluate(() => { const e = document.getElementById('contour-error'); return e.hidden ? '' : e.textContent; });
    check('a GeoJSON "type": 7 settles with a line beside the plan', /^contour: /.test(line), `'${line}' after ${Date.now() - t0} ms`);
    await page.close();
  }

  // 5. A 2,000-point contour (the most a link may carry; the plan keeps 600 of a drawing, so it
  // comes as a file): its link fits and reads back.
  {
    const page = await open('');
    let d = await waitSettled(page, 0);
    const serial = Number(d.terrainSerial);
    const points = Array.from({ length: 2000 }, (_, k) => {
      const phi = (2 * Math.PI * k) / 2000;
      const r = 300 * (1 + 0.15 * Math.cos(5 * phi)) + 3 * Math.sin(160 * phi);
      return [r * Math.cos(phi) + 0.123456789, r * Math.sin(phi) - 0.987654321];
    });
    await page.setInputFiles('#contour-file', { name: 'long.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify({ points })) });
    d = await waitSettled(page, serial);
    const hash = await page.evaluate(() => location.hash);
    const note = await page.textContent('#contour-note');
    const [from] = (d.contourSimplified || '0:0').split(':').map(Number);
    check('a 2,000-point contour: simplified to a link within 16,384 characters', d.status === 'ready' && from >= 1900 &&
      hash.length <= 16384 && hash.includes('contour=') && /Simplified to fit a link/.test(note),
      `${d.status} ${d.error || ''}; ${d.contourSimplified}; ${hash.length} characters; note '${note}'`);
    const again = await open(hash);
    const d2 = await waitSettled(again, 0);
    check('that link reads back to the same mountain', d2.status === 'ready' && `#${d2.hash}` === hash && d2.stats === d.stats,
      `${d2.status} ${d2.error || ''}; same hash ${`#${d2.hash}` === hash}`);
    await again.close();
    await page.close();
  }

  check('no console errors, page errors', problems.length === 0, problems.join(' | '));
});
