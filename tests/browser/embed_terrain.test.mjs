// Browser test of <niwa-terrain> (public/niwa-terrain.js) on public/embed-terrain.html, the iframe
// form public/embed.html?study=terrain and the terrain page's Embed dialog: node
// tests/browser/embed_terrain.test.mjs (exit 0 = pass). Three elements (valleys by attributes, a
// drawn contour by state= with animate, jacksboro under a figure preset) share one worker and each
// grows what `niwa terrain grow` grows for the same input (--stats equal but the timings); animate
// steps through the levels to the top without regrowing; a bad attribute is one line in the
// element and a good one recovers; the iframe grows the page's hash; the page's dialog offers both
// snippets. Screenshots: build/artifacts/embed-terrain*.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { ARTIFACTS, NATIVE, TIMEOUT, check, hookLog, newContext, runBrowserTest, watchPage } from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const sorted = (o) => JSON.stringify(Object.fromEntries(Object.entries(o).sort(([a], [b]) => (a < b ? -1 : 1))));
const nativeTerrain = (args) => withoutMs(JSON.parse(execFileSync(NATIVE, ['terrain', 'grow', ...args, '--stats'], { encoding: 'utf8' }).trim()));

function waitElement(page, selector, statsBefore = '') {
  return page.waitForFunction(([sel, before]) => {
    const d = document.querySelector(sel)?.dataset;
    return d && (d.status === 'error' || (d.status === 'ready' && d.stats && d.stats !== before));
  }, [selector, statsBefore], { timeout: TIMEOUT, polling: 200 }).then(() => page.evaluate((sel) => ({ ...document.querySelector(sel).dataset }), selector));
}

function same(name, data, args) {
  const web = sorted(withoutMs(JSON.parse(data.stats || '{}')));
  const native = sorted(nativeTerrain(args));
  check(name, web === native, web === native ? `${data.levels} levels, ${data.peaks} peaks` : `web ${web.slice(0, 300)} | native ${native.slice(0, 300)}`);
}

// Share of the element's canvas that is not the background (the surface and its lines).
const drawnShare = (page, selector) => page.evaluate((sel) => {
  const d = window.__niwaCanvasImage(`${sel} >>> canvas`).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - 219) > 8 || Math.abs(d[i + 1] - 230) > 8 || Math.abs(d[i + 2] - 240) > 8) ++n;
  return n / (d.length / 4);
}, selector);

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1500, height: 900 } });
  const page = await context.newPage();
  watchPage(page, problems);
  const workers = [];
  page.on('worker', (w) => workers.push(w.url()));
  await page.goto(`${server.url}embed-terrain.html`, { waitUntil: 'load' });

  const valleys = await waitElement(page, '#valleys');
  check('<niwa-terrain builtin="valleys" method="improved" seed="4"> grows', valleys.status === 'ready' && Number(valleys.levels) > 5, `${valleys.status} ${valleys.levels} levels ${valleys.error || ''}`);
  same('valleys element == niwa terrain grow --builtin valleys --method improved --seed 4', valleys, ['--builtin', 'valleys', '--method', 'improved', '--seed', '4']);
  const drawn = await waitElement(page, '#drawn');
  check('<niwa-terrain state="..contour=.."> grows the drawn contour', drawn.status === 'ready' && drawn.hash.includes('contour=0,0;400,0;'), `${drawn.status} ${drawn.hash} ${drawn.error || ''}`);
  same('drawn element == niwa terrain grow --url', drawn, ['--url', 'preset=simple&contour=0,0;400,0;400,150;250,150;250,300;0,300']);
  const real = await waitElement(page, '#jacksboro');
  check('<niwa-terrain builtin="jacksboro" method="fig9c"> grows', real.status === 'ready', `${real.status} ${real.error || ''}`);
  same('jacksboro element == niwa terrain grow --builtin jacksboro --method fig9c', real, ['--builtin', 'jacksboro', '--method', 'fig9c']);
  check('the three share one worker', workers.length === 1, workers.join(', '));

  // animate: the drawn element steps through its levels to the top without regrowing.
  await page.waitForFunction(() => document.querySelector('#drawn').dataset.levelShown === 'all', null, { timeout: TIMEOUT });
  const levels = await hookLog(page, '#drawn', 'data-level-shown');
  const numbered = levels.slice(0, -1).map(Number);
  const rising = numbered.length >= 3 && numbered.every((k, i) => Number.isInteger(k) && (i === 0 || k === numbered[i - 1] + 1));
  const drawnGrows = (await hookLog(page, '#drawn', 'data-hash')).length;  // set once per grown mountain
  check('animate replays the levels to the top', rising && levels.at(-1) === 'all' && drawnGrows === 1,
    `${levels.length} levels shown (${levels.slice(0, 3).join(', ')} ... ${levels.slice(-2).join(', ')}), ${drawnGrows} grow(s)`);
  const valleysShown = await hookLog(page, '#valleys', 'data-level-shown');
  check('without animate the top is shown at once', valleysShown.length === 1 && valleysShown[0] === 'all', valleysShown.join(', '));
  for (const id of ['valleys', 'drawn', 'jacksboro']) {
    const share = await drawnShare(page, `#${id}`);
    check(`#${id} draws its mountain`, share > 0.1, `${(share * 100).toFixed(1)}% of the canvas`);
  }
  await page.screenshot({ path: path.join(ARTIFACTS, 'embed-terrain.png') });

  // A bad attribute is one line in the element; a good one recovers.
  await page.evaluate(() => document.querySelector('#valleys').setAttribute('builtin', 'moon'));
  const bad = await waitElement(page, '#valleys', valleys.stats);
  const line = await page.evaluate(() => document.querySelector('#valleys').shadowRoot.querySelector('p').textContent);
  check('builtin="moon" is one line naming builtin and a mountain still grows', /builtin/.test(line) && !line.includes('\n') && bad.status === 'ready', `${bad.status}: '${line}'`);
  await page.evaluate(() => document.querySelector('#valleys').setAttribute('builtin', 'dumbbell'));
  const good = await waitElement(page, '#valleys', bad.stats);
  check('builtin="dumbbell" recovers', good.status === 'ready' && Number(good.peaks) >= 2, `${good.status} ${good.peaks} peaks`);
  same('dumbbell element == CLI', good, ['--builtin', 'dumbbell', '--method', 'improved', '--seed', '4']);

  // The page's Embed dialog: both snippets carry the page's hash.
  const studio = await context.newPage();
  watchPage(studio, problems);
  await studio.goto(`${server.url}terrain.html#preset=improved&builtin=valleys`, { waitUntil: 'load' });
  // Ready and drawn (the dialog's screenshot showed a blank canvas when taken before the first frame).
  await studio.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'ready' && Number(d.terrainSerial) > 0 && (d.drawnSerial === d.terrainSerial || d.drawing === 'off');
  }, null, { timeout: TIMEOUT });
  await studio.click('#embed');
  const snippets = await studio.evaluate(() => [document.getElementById('embed-element').value, document.getElementById('embed-iframe').value]);
  check('the Embed dialog offers <niwa-terrain> and the iframe with the hash',
    snippets[0].includes('niwa-terrain.js') && snippets[0].includes('<niwa-terrain state="preset=improved&amp;builtin=valleys"') && snippets[1].includes('embed.html?study=terrain#preset=improved&amp;builtin=valleys'),
    snippets.join(' | ').slice(0, 300));
  await studio.screenshot({ path: path.join(ARTIFACTS, 'embed-terrain-dialog.png') });
  await studio.close();

  // The iframe form grows the page's hash.
  const frame = await context.newPage();
  watchPage(frame, problems);
  const hash = 'preset=fig13b&builtin=lobes7&seed=5';
  await frame.goto(`${server.url}embed.html?study=terrain#${hash}`, { waitUntil: 'load' });
  const framed = await waitElement(frame, 'niwa-terrain');
  check('embed.html?study=terrain grows its hash', framed.status === 'ready', `${framed.status} ${framed.error || ''}`);
  same('iframe == niwa terrain grow --url', framed, ['--url', hash]);
  await frame.screenshot({ path: path.join(ARTIFACTS, 'embed-terrain-frame.png') });

  check('no console errors or page errors', problems.length === 0, problems.join(' | '));
});
