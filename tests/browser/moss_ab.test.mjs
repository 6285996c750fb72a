// Browser test of the moss page's A/B view (public/moss.html, web/moss/moss_page.js): node
// tests/browser/moss_ab.test.mjs (exit 0 = pass). With "Indirect light" the page grows a second
// run beside the first with indirect light switched off: its stats equal `niwa moss grow --url
// HASH_B --stats` (timings aside), it stores no bounced photon on its last day (spec: no photon of
// depth >= 1 with indirect off) while the left run does, and the left run is unchanged; the day
// scrubber replays both (each side's mosses drawn on day k are its stats' population of day k);
// "Temperature" grows the right run at 293.15 K (== the CLI), a field overlay's ramp shared by both
// runs; Off clears the right run.
// Screenshots: build/artifacts/moss-ab-*.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, watchPage } from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const canonical = (v) => (Array.isArray(v) ? v.map(canonical) : v && typeof v === 'object'
  ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canonical(v[k])])) : v);
const text = (stats) => JSON.stringify(canonical(withoutMs(stats)));
const hooks = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));

function sameAsNative(name, hash, statsText) {
  let native = '';
  try {
    native = text(JSON.parse(execFileSync(NATIVE, ['moss', 'grow', '--url', hash, '--stats'], { encoding: 'utf8' }).trim().split('\n').pop()));
  } catch (e) {
    check(name, false, `${NATIVE} moss grow --url ${hash}: ${e.message.split('\n')[0]}`);
    return;
  }
  const web = text(JSON.parse(statsText || '{}'));
  check(`${name} (--url ${hash})`, web === native, web === native ? '' : `web ${web.slice(0, 300)} | native ${native.slice(0, 300)}`);
}

// Waits for run B newer than serial `above` (or its error).
async function waitB(page, above) {
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    return d.statusB === 'error' || (d.statusB === 'ready' && Number(d.serialB) > n && d.drawnSerialB === d.serialB);
  }, above, { timeout: TIMEOUT, polling: 200 });
  return hooks(page);
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 } });
  const page = await context.newPage();
  watchPage(page, problems);
  await page.goto(`${server.url}moss.html#preset=nomura2010&days=20&photons=2048`, { waitUntil: 'load' });
  await page.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'ready' && Number(d.mossSerial) > 0 && d.drawnSerial === d.mossSerial;
  }, null, { timeout: TIMEOUT });
  let a = await hooks(page);
  const statsA = a.stats;

  // Indirect light switched: run B beside run A.
  await page.selectOption('#compare', 'indirect');
  let b = await waitB(page, 0);
  check('the A/B view grows run B with indirect light off', b.statusB === 'ready' && /(^|&)indirect=0(&|$)/.test(b.hashB),
    `${b.statusB} ${b.hashB} ${b.errorB || ''}`);
  sameAsNative('run B == niwa moss grow', b.hashB, b.statsB);
  const sB = JSON.parse(b.statsB || '{}'), sA = JSON.parse(a.stats);
  const bouncedB = (sB.photons_last_day?.stored_by_depth || []).slice(1).reduce((x, y) => x + y, 0);
  const bouncedA = sA.photons_last_day.stored_by_depth.slice(1).reduce((x, y) => x + y, 0);
  check('run B stores no bounced photon, run A does', bouncedB === 0 && bouncedA > 0 && sB.photons_last_day.stored_by_depth[0] > 0,
    `B bounced ${bouncedB}, A bounced ${bouncedA}`);
  a = await hooks(page);
  check('run A is unchanged by the A/B view', a.stats === statsA && a.hash === 'preset=nomura2010&days=20&photons=2048', a.hash);
  await saveCanvasPng(page, 'moss-ab-indirect.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-ab-page.png') });

  // The scrubber replays both sides.
  const shown = [];
  for (const day of [0, 10, 20]) {
    await page.evaluate((k) => {
      const r = document.getElementById('day');
      r.value = String(k);
      r.dispatchEvent(new Event('input', { bubbles: true }));
    }, day);
    await page.waitForFunction((k) => document.documentElement.dataset.drawnDay === String(k), day, { timeout: TIMEOUT });
    const d = await hooks(page);
    const pop = (s) => s.population.by_day[day].reduce((x, y) => x + y, 0);
    shown.push({ day, a: Number(d.drawnMosses), wantA: pop(sA), b: Number(d.drawnMossesB), wantB: pop(sB) });
  }
  check('the day scrubber replays both runs (each == its stats population.by_day)', shown.every((x) => x.a === x.wantA && x.b === x.wantB),
    shown.map((x) => `day ${x.day}: A ${x.a} (${x.wantA}), B ${x.b} (${x.wantB})`).join(', '));
  await saveCanvasPng(page, 'moss-ab-day20.png');

  // Temperature: run B at 293.15 K.
  await page.selectOption('#compare', 'temperature');
  b = await waitB(page, Number(b.serialB));
  check('the temperature A/B grows run B at 293.15 K', b.statusB === 'ready' && /(^|&)T=293\.15(&|$)/.test(b.hashB) && !/indirect=0/.test(b.hashB),
    `${b.statusB} ${b.hashB} ${b.errorB || ''}`);
  sameAsNative('run B at 293.15 K == niwa moss grow', b.hashB, b.statsB);
  await page.selectOption('#overlay', 'T_s');
  await page.waitForFunction(() => document.documentElement.dataset.drawnOverlay === 'T_s', null, { timeout: TIMEOUT });
  await saveCanvasPng(page, 'moss-ab-temperature.png');
  const t = await hooks(page);
  const help = await page.textContent('#overlay-help');
  const meansT = [JSON.parse(t.stats), JSON.parse(b.statsB)].flatMap((s) => Object.values(s.soil_last_day).map((g) => g.T_s));
  check('with the A/B view both runs share the T_s ramp (its range holds both runs\' per-geology means)',
    help.includes('(both runs)') && meansT.every((m) => m >= Number(t.overlayMin) - 1e-3 && m <= Number(t.overlayMax) + 1e-3),
    `'${help}'; means ${meansT.map((m) => m.toFixed(2)).join(', ')}`);
  await page.selectOption('#overlay', 'coverage');

  // Off: the right run goes.
  await page.selectOption('#compare', 'off');
  await page.waitForFunction(() => document.documentElement.dataset.drawnMossesB === '', null, { timeout: TIMEOUT });
  const off = await hooks(page);
  check('Off clears run B', off.compare === 'off' && off.drawnMossesB === '' && off.hashB === '', `${off.compare} '${off.drawnMossesB}'`);

  check('no uncaught error or console error', problems.length === 0, problems.slice(0, 3).join(' | ').slice(0, 400));
  await context.close();
});
