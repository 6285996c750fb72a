// Browser test of <niwa-moss> (public/niwa-moss.js) on public/embed-moss.html, the iframe form
// public/embed.html?study=moss and the moss page's Embed dialog: node
// tests/browser/embed_moss.test.mjs (exit 0 = pass). Three elements (the opening run by default,
// walls by attributes with animate, rocks under the sky preset by state=) share one worker and
// each grows what `niwa moss grow --url HASH --stats` grows (stats equal but the timings); animate
// replays the days from 0 to the last without regrowing, the mosses shown each day being the
// stats' population of that day; a bad attribute is one line in the element naming the field and
// a run still grows; the iframe grows its hash; the page's dialog offers both snippets with the
// page's hash. Screenshots: build/artifacts/embed-moss*.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { ARTIFACTS, NATIVE, TIMEOUT, check, hookLog, newContext, runBrowserTest, watchPage } from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const canonical = (v) => (Array.isArray(v) ? v.map(canonical) : v && typeof v === 'object'
  ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canonical(v[k])])) : v);
const text = (stats) => JSON.stringify(canonical(withoutMs(stats)));

function waitElement(page, selector, statsBefore = '') {
  return page.waitForFunction(([sel, before]) => {
    const d = document.querySelector(sel)?.dataset;
    return d && (d.status === 'error' || (d.status === 'ready' && d.stats && d.stats !== before));
  }, [selector, statsBefore], { timeout: TIMEOUT, polling: 200 }).then(() => page.evaluate((sel) => ({ ...document.querySelector(sel).dataset }), selector));
}

// The element's stats against the native CLI's for the hash the element grew.
function same(name, data) {
  let native = '';
  try {
    native = text(JSON.parse(execFileSync(NATIVE, ['moss', 'grow', '--url', data.hash, '--stats'], { encoding: 'utf8' }).trim().split('\n').pop()));
  } catch (e) {
    check(name, false, `${NATIVE} moss grow --url ${data.hash}: ${e.message.split('\n')[0]}`);
    return null;
  }
  const web = text(JSON.parse(data.stats || '{}'));
  check(`${name} (--url ${data.hash})`, web === native, web === native ? `${data.mosses} mosses over ${data.days} days` : `web ${web.slice(0, 300)} | native ${native.slice(0, 300)}`);
  return JSON.parse(data.stats);
}

// Share of the element's canvas that is moss green (the tufts: a few dozen pixels at 360 px high)
// and that is not the background.
const looks = (page, selector) => page.evaluate((sel) => {
  const d = window.__niwaCanvasImage(`${sel} >>> canvas`).data;
  let drawn = 0, green = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (Math.abs(d[i] - 219) > 8 || Math.abs(d[i + 1] - 230) > 8 || Math.abs(d[i + 2] - 240) > 8) ++drawn;
    if (d[i + 1] > d[i] + 25 && d[i + 1] > d[i + 2] + 25) ++green;
  }
  const n = d.length / 4;
  return { drawn: drawn / n, green: green / n };
}, selector);

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1500, height: 900 } });
  const page = await context.newPage();
  watchPage(page, problems);
  const workers = [];
  page.on('worker', (w) => workers.push(w.url()));
  await page.goto(`${server.url}embed-moss.html`, { waitUntil: 'load' });

  const thesis = await waitElement(page, '#thesis');
  check('<niwa-moss> grows the moss page\'s opening run', thesis.status === 'ready' && thesis.hash === 'preset=nomura2010&days=60&photons=4096' && Number(thesis.mosses) > 0,
    `${thesis.status} ${thesis.hash} ${thesis.mosses} mosses ${thesis.error || ''}`);
  same('<niwa-moss> == niwa moss grow', thesis);
  const walls = await waitElement(page, '#walls');
  check('<niwa-moss scene="walls" seed="2" days="30" animate> grows walls', walls.status === 'ready' && /scene=walls/.test(walls.hash) && /seed=2/.test(walls.hash) && walls.days === '30',
    `${walls.status} ${walls.hash} ${walls.error || ''}`);
  const wallStats = same('walls element == niwa moss grow', walls);
  const sky = await waitElement(page, '#sky');
  check('<niwa-moss state="preset=nomura2010-sky&scene=rocks..."> grows rocks under the sky preset', sky.status === 'ready' && /preset=nomura2010-sky/.test(sky.hash) && /scene=rocks/.test(sky.hash),
    `${sky.status} ${sky.hash} ${sky.error || ''}`);
  same('sky element == niwa moss grow', sky);
  check('the three share one worker', workers.length === 1, workers.join(', '));

  // animate: the walls element replays its days 0..30, each day's mosses the stats' population.
  await page.waitForFunction(() => document.querySelector('#walls').dataset.stepShown === '30', null, { timeout: TIMEOUT });
  const steps = await hookLog(page, '#walls', 'data-step-shown');
  const consecutive = steps.length === 31 && steps.every((v, i) => v === String(i));
  const wallGrows = (await hookLog(page, '#walls', 'data-hash')).length;
  check('animate replays the days 0..30 without regrowing', consecutive && wallGrows === 1, `${steps.length} days shown (${steps.slice(0, 3).join(', ')} ... ${steps.slice(-2).join(', ')}), ${wallGrows} grow(s)`);
  const last = await page.evaluate(() => document.querySelector('#walls').dataset.mossesShown);
  const want = wallStats ? wallStats.population.by_day[30].reduce((a, b) => a + b, 0) : NaN;
  check('the last day replayed shows the stats\' population of day 30', Number(last) === want, `${last} shown, stats ${want}`);
  const thesisShown = await hookLog(page, '#thesis', 'data-step-shown');
  check('without animate the last day is shown at once', thesisShown.length === 1 && thesisShown[0] === '60', thesisShown.join(', '));
  for (const id of ['thesis', 'walls', 'sky']) {
    const l = await looks(page, `#${id}`);
    check(`#${id} draws its land and green tufts`, l.drawn > 0.1 && l.green > 0.00005, `${(l.drawn * 100).toFixed(1)}% drawn, ${(l.green * 100).toFixed(2)}% green`);
  }
  await page.screenshot({ path: path.join(ARTIFACTS, 'embed-moss.png') });

  // A bad attribute is one line in the element naming the field; a run still grows (on the
  // preset's scene), and a good value recovers.
  await page.evaluate(() => document.querySelector('#thesis').setAttribute('scene', 'moon'));
  const bad = await waitElement(page, '#thesis', thesis.stats);
  const line = await page.evaluate(() => document.querySelector('#thesis').shadowRoot.querySelector('p').textContent);
  check('scene="moon" is one line naming scene and a moss still grows', /scene/.test(line) && line.includes('moon') && !line.includes('\n') && bad.status === 'ready',
    `${bad.status}: '${line}'`);
  await page.evaluate(() => document.querySelector('#thesis').setAttribute('scene', 'plane'));
  const good = await waitElement(page, '#thesis', bad.stats);
  check('scene="plane" recovers', good.status === 'ready' && /scene=plane/.test(good.hash), `${good.status} ${good.hash}`);
  same('plane element == niwa moss grow', good);

  // The moss page's Embed dialog: both snippets carry the page's hash.
  const studio = await context.newPage();
  watchPage(studio, problems);
  const pageHash = 'preset=nomura2010&scene=walls&days=20&photons=2048';
  await studio.goto(`${server.url}moss.html#${pageHash}`, { waitUntil: 'load' });
  await studio.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'ready' && Number(d.mossSerial) > 0 && (d.drawnSerial === d.mossSerial || d.drawing === 'off');
  }, null, { timeout: TIMEOUT });
  const studioHash = await studio.evaluate(() => location.hash.slice(1));
  await studio.click('#embed');
  const snippets = await studio.evaluate(() => [document.getElementById('embed-element').value, document.getElementById('embed-iframe').value]);
  const escaped = studioHash.replace(/&/g, '&amp;');
  check('the Embed dialog offers <niwa-moss> and the iframe with the page\'s hash',
    studioHash.includes('scene=walls') && snippets[0].includes('niwa-moss.js') && snippets[0].includes(`<niwa-moss state="${escaped}"`) && snippets[1].includes(`embed.html?study=moss#${escaped}`),
    `${studioHash}: ${snippets.join(' | ').slice(0, 400)}`);
  await studio.screenshot({ path: path.join(ARTIFACTS, 'embed-moss-dialog.png') });
  await studio.close();

  // The iframe form grows its hash.
  const frame = await context.newPage();
  watchPage(frame, problems);
  const hash = 'preset=nomura2010&scene=rocks&days=25&seed=3&photons=2048';
  await frame.goto(`${server.url}embed.html?study=moss#${hash}`, { waitUntil: 'load' });
  const framed = await waitElement(frame, 'niwa-moss');
  check('embed.html?study=moss grows its hash', framed.status === 'ready' && framed.hash === hash, `${framed.status} ${framed.hash} ${framed.error || ''}`);
  same('iframe == niwa moss grow', framed);
  await frame.screenshot({ path: path.join(ARTIFACTS, 'embed-moss-frame.png') });

  check('no console errors or page errors', problems.length === 0, problems.join(' | '));
});
