// Browser test of <niwa-garden> (public/niwa-garden.js) on public/embed-garden.html and the iframe
// form public/embed.html?study=garden: node tests/browser/embed_garden.test.mjs (exit 0 = pass).
// Three elements (the garden page's opening garden by default, a 30 m garden by attributes, a flat
// ground by state=) share one worker; the default one grows what `niwa garden grow --url HASH
// --stats` grows (stats equal but the timings); each draws its ground and trees over the background
// (pixels: a blank or ground-only element fails); the arrow keys orbit; a link's bad value is a
// text line in the element naming the field (markup never made elements) while a garden still grows; a
// garden the core refuses (alt_min above alt_max) is the core's one line, and a good state
// recovers; the iframe grows its hash and draws it. (The garden page's Embed dialog is checked in
// garden_page.test.mjs, in its page load.) Screenshots: build/artifacts/embed-garden*.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, watchPage } from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));

// The element's hooks once it is ready (its garden drawn) or shows an error, after `statsBefore`.
function waitElement(page, selector, statsBefore = '') {
  return page.waitForFunction(([sel, before]) => {
    const d = document.querySelector(sel)?.dataset;
    return d && (d.status === 'error' || (d.status === 'ready' && d.stats && d.stats !== before && d.drawnSerial === d.gardenSerial));
  }, [selector, statsBefore], { timeout: TIMEOUT, polling: 200 }).then(() => page.evaluate((sel) => ({ ...document.querySelector(sel).dataset }), selector));
}

// Shares of the element's canvas: the background (219, 230, 240), leaf green (as
// garden_page.test.mjs reads it: the ground's greens are yellower) and everything else drawn.
const looks = (page, selector) => page.evaluate((sel) => {
  const d = window.__niwaCanvasImage(`${sel} >>> canvas`).data;
  let background = 0, leaf = 0;
  for (let i = 0; i < d.length; i += 4) {
    const r = d[i], g = d[i + 1], b = d[i + 2];
    if (Math.abs(r - 219) < 8 && Math.abs(g - 230) < 8 && Math.abs(b - 240) < 8) ++background;
    else if (g > 1.7 * r && g > 2.2 * b && g > 30) ++leaf;
  }
  const n = d.length / 4;
  return { drawn: 1 - background / n, leaf: leaf / n };
}, selector);
const seen = (l) => `${(l.drawn * 100).toFixed(1)}% drawn, ${(l.leaf * 100).toFixed(2)}% leaves`;

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1500, height: 900 } });
  const page = watchPage(await context.newPage(), problems);
  const workers = [];
  page.on('worker', (w) => workers.push(w.url()));
  await page.goto(`${server.url}embed-garden.html`, { waitUntil: 'load' });

  // 1. The default element: the garden page's opening garden, drawn, == native.
  const opening = await waitElement(page, '#opening');
  check('<niwa-garden> grows the garden page\'s opening garden (8 years)', opening.status === 'ready' && /(^|&)years=8(&|$)/.test(opening.hash) && Number(opening.trees) > 3,
    `${opening.status} ${opening.error || ''} ${opening.trees} trees, ${(opening.hash || '').slice(0, 80)}`);
  check('every planted tree is drawn', Number(opening.drawnTrees) === Number(opening.trees) && Number(opening.drawnTriangles) > 1000,
    `drawn ${opening.drawnTrees} of ${opening.trees} trees, ${opening.drawnTriangles} triangles`);
  let native = null;
  try {
    native = JSON.parse(execFileSync(NATIVE, ['garden', 'grow', '--url', opening.hash, '--stats'], { encoding: 'utf8' }).trim().split('\n').pop());
  } catch (e) {
    check('native garden grow runs', false, e.message.split('\n')[0]);
  }
  const web = JSON.parse(opening.stats || '{}');
  check('<niwa-garden> == `niwa garden grow --url HASH --stats` (ms* aside)', native && JSON.stringify(withoutMs(native)) === JSON.stringify(withoutMs(web)),
    `web ${JSON.stringify(withoutMs(web)).slice(0, 160)} native ${JSON.stringify(native ? withoutMs(native) : null).slice(0, 160)}`);

  // 2. Attributes and state=.
  const small = await waitElement(page, '#small');
  check('<niwa-garden years="5" seed="2" size="30"> grows those', small.status === 'ready' && /(^|&)years=5(&|$)/.test(small.hash) && /plant_seed=2/.test(small.hash) && /size=30/.test(small.hash),
    `${small.status} ${small.error || ''} ${(small.hash || '').slice(0, 100)}`);
  const flat = await waitElement(page, '#flat');
  check('<niwa-garden state="years=6&plant_seed=3&ground=flat&density=0.02"> grows a flat ground', flat.status === 'ready' && /^ground=flat/.test(flat.hash) && /plant_seed=3/.test(flat.hash),
    `${flat.status} ${flat.error || ''} ${(flat.hash || '').slice(0, 100)}`);
  check('the three share one worker', workers.length === 1, workers.join(', '));
  for (const id of ['opening', 'small', 'flat']) {
    const l = await looks(page, `#${id}`);
    check(`#${id} draws its ground and its trees' leaves over the background`, l.drawn > 0.2 && l.leaf > 0.002, seen(l));
  }
  await page.screenshot({ path: path.join(ARTIFACTS, 'embed-garden.png') });

  // 3. The arrow keys orbit (the shared element's camera).
  const yaw0 = await page.evaluate(() => document.querySelector('#opening').camera.yaw);
  await page.focus('#opening canvas');
  await page.keyboard.press('ArrowLeft');
  const yaw1 = await page.evaluate(() => document.querySelector('#opening').camera.yaw);
  check('ArrowLeft orbits the garden', Math.abs(yaw1 - yaw0) > 0.01, `yaw ${yaw0} -> ${yaw1}`);

  // 4. A link's bad value: the core's notice as a text line (no markup made), a garden still grows.
  await page.evaluate(() => document.querySelector('#flat').setAttribute('state', 'years=4&plant_seed=<b>x</b>'));
  const noted = await waitElement(page, '#flat', flat.stats);
  const noteLine = await page.evaluate(() => {
    const root = document.querySelector('#flat').shadowRoot;
    return { text: root.querySelector('p').textContent, markup: root.querySelector('p b') !== null };
  });
  check('plant_seed=<b>x</b> is one text line naming plant_seed, and a garden grows', noted.status === 'ready' && /^plant_seed: .*dropped/.test(noteLine.text) && !noteLine.markup && !noteLine.text.includes('\n') && /(^|&)years=4(&|$)/.test(noted.hash),
    `${noted.status}: '${noteLine.text}' (markup ${noteLine.markup}), ${(noted.hash || '').slice(0, 60)}`);
  let l = await looks(page, '#flat');
  check('the garden grown past the notice is drawn', l.drawn > 0.2, seen(l));

  // 5. A garden the core refuses: its one line, as text; a good state recovers.
  await page.evaluate(() => document.querySelector('#flat').setAttribute('state', 'years=4&alt_min=10&alt_max=5'));
  await page.waitForFunction(() => document.querySelector('#flat').dataset.status === 'error', null, { timeout: TIMEOUT });
  const refused = await page.evaluate(() => document.querySelector('#flat').shadowRoot.querySelector('p').textContent);
  check('alt_min above alt_max is the core\'s one line naming alt_min, not a crash', /alt_min/.test(refused) && !refused.includes('\n'), `'${refused}'`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'embed-garden-refused.png') });
  await page.evaluate(() => document.querySelector('#flat').setAttribute('state', 'years=4&plant_seed=7&ground=flat'));
  const recovered = await waitElement(page, '#flat', noted.stats);
  check('a good state recovers', recovered.status === 'ready' && /plant_seed=7/.test(recovered.hash), `${recovered.status} ${recovered.error || ''} ${(recovered.hash || '').slice(0, 60)}`);
  const line = await page.evaluate(() => document.querySelector('#flat').shadowRoot.querySelector('p').textContent);
  check('the recovered element\'s line is empty', line === '', `'${line}'`);

  // 6. The iframe form grows its hash and draws it.
  const frame = watchPage(await context.newPage(), problems);
  const hash = 'years=5&plant_seed=4&size=30';
  await frame.goto(`${server.url}embed.html?study=garden#${hash}`, { waitUntil: 'load' });
  const framed = await waitElement(frame, 'niwa-garden');
  check('embed.html?study=garden grows its hash', framed.status === 'ready' && /(^|&)years=5(&|$)/.test(framed.hash) && /plant_seed=4/.test(framed.hash) && /size=30/.test(framed.hash),
    `${framed.status} ${framed.error || ''} ${(framed.hash || '').slice(0, 100)}`);
  l = await looks(frame, 'niwa-garden');
  check('the iframe form draws the ground and the trees', l.drawn > 0.2 && l.leaf > 0.002, seen(l));
  await frame.screenshot({ path: path.join(ARTIFACTS, 'embed-garden-frame.png') });

  check('no console errors or page errors', problems.length === 0, problems.join(' | '));
});
