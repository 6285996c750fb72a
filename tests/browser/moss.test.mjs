// Browser test of the moss page (public/moss.html): node tests/browser/moss.test.mjs (exit 0 =
// pass). The page opens with no input and grows the opening run (thesis scene, 60 days, 4096
// photons) with mosses drawn; its stats equal the native CLI's `niwa moss grow --url HASH --stats`
// (every field but the ms* timings) for the page's own hash; the day scrubber changes the number
// of mosses drawn, each day's count equal to the stats' population of that day, without a new
// grow; a bad Days value (-1) and a bad hash value are a notice beside the field and the page
// keeps working; Copy link gives a link that reopens the same run (same stats). The population
// chart draws one line per species over the stats' days with its marker on the scrubber's day;
// the stats .json and days .csv downloads hold the stats and their population by day. The land
// overlays of the last day (T_s, rh_s, theta, best-species G) span ranges that hold the stats'
// per-geology means and tint the land differently; the photon points are the last day's stored
// photons (direct and bounced, as the stats count them by depth), drawn yellow and blue. A mesh
// dropped on the view (materials.glb) or picked with the file input (rock1.glb, Draco) grows mosses
// whose stats equal `niwa moss grow --mesh FILE --url HASH --stats`; bad files (not glTF, empty,
// truncated, a .txt) are one line beside the drop control, the run shown stays, and a scene picked
// after them grows.
// Screenshots: build/artifacts/moss-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, ROOT, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const canonical = (v) => (Array.isArray(v) ? v.map(canonical) : v && typeof v === 'object'
  ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canonical(v[k])])) : v);
const same = (a, b) => JSON.stringify(canonical(withoutMs(a))) === JSON.stringify(canonical(withoutMs(b)));

// Waits for a run newer than serialAbove drawn on screen (or an error); returns the dataset.
const waitMoss = (page, serialAbove) => waitStudyRun(page, 'mossSerial', serialAbove);

function compareWithNative(name, data, extra = []) {
  let native = null;
  const args = ['moss', 'grow', ...extra, '--url', data.hash, '--stats'];
  try {
    native = JSON.parse(execFileSync(NATIVE, args, { encoding: 'utf8' }).trim().split('\n').pop());
  } catch (e) {
    check(`${name}: native CLI runs`, false, `${NATIVE} ${args.join(' ')}: ${e.message.split('\n')[0]}`);
    return null;
  }
  const web = JSON.parse(data.stats);
  const ok = same(web, native);
  check(`${name}: page stats == native \`niwa ${args.map((a) => a.replace(ROOT + '/', '')).join(' ')}\` (ms* aside)`, ok,
    ok ? `${web.mosses.total} mosses, ${web.population.by_day.length} days of population`
      : `web ${JSON.stringify(withoutMs(web)).slice(0, 300)} native ${JSON.stringify(withoutMs(native)).slice(0, 300)}`);
  return web;
}

// Shares of the canvas: background, moss-green pixels (the tufts' species colours), the rest.
async function looks(page) {
  return page.evaluate(() => {
    const d = window.__niwaCanvasImage('#view').data;
    let background = 0, green = 0;
    for (let i = 0; i < d.length; i += 4) {
      const r = d[i], g = d[i + 1], b = d[i + 2];
      if (Math.abs(r - 219) < 6 && Math.abs(g - 230) < 6 && Math.abs(b - 240) < 6) { ++background; continue; }
      if (g > r + 25 && g > b + 25) ++green;
    }
    const n = d.length / 4;
    return { background: background / n, green: green / n };
  });
}

// Mean colour of the canvas and its yellow (direct photon) and blue (bounced photon) pixel shares.
async function tint(page) {
  return page.evaluate(() => {
    const d = window.__niwaCanvasImage('#view').data;
    let r = 0, g = 0, b = 0, yellow = 0, blue = 0;
    for (let i = 0; i < d.length; i += 4) {
      r += d[i]; g += d[i + 1]; b += d[i + 2];
      if (d[i] > 200 && d[i + 1] > 150 && d[i + 2] < 80) ++yellow;
      if (d[i + 2] > 180 && d[i] < 90 && d[i + 2] > d[i + 1] + 40) ++blue;
    }
    const n = d.length / 4;
    return { mean: [r / n, g / n, b / n], yellow: yellow / n, blue: blue / n };
  });
}

// The text of a download started by clicking `button`.
async function downloaded(page, button) {
  const [d] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click(button)]);
  const out = path.join(ARTIFACTS, d.suggestedFilename());
  await d.saveAs(out);
  return { name: d.suggestedFilename(), text: fs.readFileSync(out, 'utf8') };
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 }, acceptDownloads: true, permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await context.newPage();
  watchPage(page, problems);
  page.on('request', (r) => {
    if (!r.url().startsWith(server.url) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) problems.push(`external request: ${r.url()}`);
  });

  // 1. Opens with no input and grows the opening run.
  await page.goto(`${server.url}moss.html`, { waitUntil: 'load' });
  let data = await waitMoss(page, 0);
  check('opens with a run grown and mosses', data.status === 'ready' && Number(data.mosses) > 0 && Number(data.drawnMosses) === Number(data.mosses),
    `status ${data.status}, ${data.mosses} mosses, ${data.drawnMosses} drawn, ${data.mossesEver} ever, grow ${data.growMs} ms ${data.error || ''}`);
  check('the hash is the opening state', data.hash === 'preset=nomura2010&days=60&photons=4096', data.hash);
  const stats = compareWithNative('opening run', data);
  const nav = await page.locator('#studies a[aria-current="page"]').textContent().catch(() => '');
  check('the studies nav lists and marks Moss', nav === 'Moss', nav);
  const panelKeys = await page.evaluate(() => [...document.querySelectorAll('#params [data-key]')].map((e) => e.dataset.key));
  check('the panel is the moss table', panelKeys.includes('photons') && panelKeys.includes('moss_size') && panelKeys.length >= 60, `${panelKeys.length} rows`);
  const scenes = await page.evaluate(() => [...document.querySelectorAll('#scene option')].map((o) => o.value));
  check('the scene select lists the built-ins', scenes.join(',') === 'plane,thesis,walls,rocks', scenes.join(','));
  const look = await looks(page);
  check('the land and green tufts are drawn', look.background < 0.9 && look.green > 0.0005,
    `background ${(look.background * 100).toFixed(1)}%, green ${(look.green * 100).toFixed(2)}%`);
  await saveCanvasPng(page, 'moss-opening.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-page.png') });

  // 2. The day scrubber: the mosses alive on each day, as the stats' population, no new grow.
  const grows = Number(data.growRequests);
  const byDay = stats ? stats.population.by_day : [];
  const chart = await page.evaluate(() => [...document.querySelectorAll('#population-chart polyline')].map((l) => ({
    species: l.dataset.species, points: l.getAttribute('points').trim().split(/\s+/).map((p) => p.split(',').map(Number)),
  })));
  const chartOk = stats && chart.length === 3 && chart.map((c) => c.species).join() === stats.population.species.join() &&
    chart.every((c) => c.points.length === byDay.length);
  // Each line's heights are its species' counts: the day of the largest count is the highest point (smallest y).
  const peaksOk = chartOk && chart.every((c, s) => {
    const counts = byDay.map((d) => d[s]);
    const top = Math.min(...c.points.map((p) => p[1]));
    return c.points.every((p, k) => (counts[k] === Math.max(...counts)) === (p[1] === top));
  });
  check('the population chart: a line per species over every day of the stats, highest where the count is', chartOk && peaksOk,
    chart.map((c) => `${c.species} ${c.points.length} points`).join(', '));
  const shown = [];
  const marks = [];
  const framesToDay = [];  // animation frames from the input to the frame that draws the day
  for (const day of [0, 10, 30, 45, 60]) {
    // A neighbouring day is picked first, and the day itself the moment the neighbour's frame is
    // drawn (its fence just made: the GPU still busy with it, as while dragging the scrubber). A
    // counter of animation frames starts with that second input; the day's frame is the n-th
    // after it when data-drawn-day changes in it (0: the page's own callback, asked for earlier,
    // ran first in that same first frame).
    framesToDay.push(await page.evaluate((k) => new Promise((resolve) => {
      const r = document.getElementById('day');
      const neighbour = k > 0 ? k - 1 : k + 1;
      const pick = (d) => {
        r.value = String(d);
        r.dispatchEvent(new Event('input', { bubbles: true }));
      };
      let frames = 0;
      let counting = false;
      const tick = () => {
        frames += 1;
        if (counting) requestAnimationFrame(tick);
      };
      const observer = new MutationObserver(() => {
        const drawn = document.documentElement.dataset.drawnDay;
        if (!counting && drawn === String(neighbour)) {
          counting = true;
          requestAnimationFrame(tick);
          pick(k);
        } else if (counting && drawn === String(k)) {
          counting = false;
          observer.disconnect();
          resolve(frames);
        }
      });
      observer.observe(document.documentElement, { attributes: true, attributeFilter: ['data-drawn-day'] });
      pick(neighbour);
    }), day));
    await page.waitForFunction((k) => document.documentElement.dataset.drawnDay === String(k), day, { timeout: TIMEOUT });
    const d = await page.evaluate(() => ({ ...document.documentElement.dataset }));
    const want = byDay[day] ? byDay[day].reduce((a, b) => a + b, 0) : NaN;
    shown.push({ day, drawn: Number(d.drawnMosses), want, coverage: Number(d.coverageShown) });
    marks.push(await page.evaluate(() => {
      const m = document.getElementById('population-marker');
      return { day: Number(m.dataset.day), x: Number(m.dataset.x), left: m.getBoundingClientRect().left };
    }));
    if (day === 10) await saveCanvasPng(page, 'moss-day10.png');
  }
  check('the day scrubber draws each day\'s mosses (== stats population.by_day)', shown.every((s) => s.drawn === s.want),
    shown.map((s) => `day ${s.day}: ${s.drawn} (stats ${s.want})`).join(', '));
  check('the chart\'s marker follows the scrubber\'s day, left to right', marks.every((m, i) => m.day === shown[i].day && (i === 0 || (m.x > marks[i - 1].x && m.left > marks[i - 1].left))),
    marks.map((m) => `day ${m.day} x ${m.x} (${m.left.toFixed(1)} px)`).join(', '));
  // Issue 29 item 6 (the scrubber answers in ≤ 100 ms) in frames, not milliseconds: a picked day is
  // drawn in the first animation frame after the input, even while the last frame is on the GPU.
  check('each scrubbed day is drawn in the first animation frame after its input', framesToDay.every((n) => n <= 1),
    `frames ${framesToDay.join(', ')}`);
  check('the scrubber changes the number drawn', new Set(shown.map((s) => s.drawn)).size > 1, shown.map((s) => s.drawn).join(','));
  check('the coverage overlay follows the day, and its replay of the last day is the run\'s', new Set(shown.map((s) => s.coverage)).size > 1 &&
    Number(data.coverageReplayError) < 1e-4, `coverage ${shown.map((s) => s.coverage).join(', ')}; replay error ${data.coverageReplayError}`);
  data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  check('scrubbing does not grow again', Number(data.growRequests) === grows, `grow requests ${grows} -> ${data.growRequests}`);
  // Play runs the days from 0 to the end.
  await page.click('#play');
  await page.waitForFunction(() => document.documentElement.dataset.dayShown === '60', null, { timeout: TIMEOUT });
  const log = await page.evaluate(() => document.documentElement.dataset.dayShown);
  check('Play runs to the last day', log === '60', log);

  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-chart-page.png') });

  // 2b. Downloads: the stats as JSON, the days as CSV (day, species..., total).
  const statsFile = await downloaded(page, '#download-stats');
  check('Stats .json downloads the run\'s stats', /\.json$/.test(statsFile.name) && same(JSON.parse(statsFile.text), JSON.parse(data.stats)), statsFile.name);
  const csvFile = await downloaded(page, '#download-csv');
  const rows = csvFile.text.trim().split('\n').map((l) => l.split(','));
  const csvOk = stats && rows[0].join() === ['day', ...stats.population.species, 'total'].join() && rows.length === byDay.length + 1 &&
    rows.slice(1).every((r, k) => Number(r[0]) === k && byDay[k].every((c, s) => Number(r[1 + s]) === c) &&
      Number(r[4]) === byDay[k].reduce((a, b) => a + b, 0));
  check('Days .csv: a row per day with each species\' count and the total, as population.by_day', csvOk,
    `${csvFile.name}: ${rows.length} lines, ${rows[0].join()} / ${(rows[rows.length - 1] || []).join()}`);

  // 2c. The run's .glb and .json: the bytes `niwa moss grow --url HASH --out` writes natively.
  for (const [button, ext] of [['#download-glb', 'glb'], ['#download-json', 'json']]) {
    const [d] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click(button)]);
    const file = path.join(ARTIFACTS, d.suggestedFilename());
    await d.saveAs(file);
    const nativeFile = path.join(ARTIFACTS, `moss-native.${ext}`);
    let nativeBytes = Buffer.alloc(0);
    try {
      execFileSync(NATIVE, ['moss', 'grow', '--url', data.hash, '--out', nativeFile]);
      nativeBytes = fs.readFileSync(nativeFile);
    } catch (e) {
      check(`native moss grow --out .${ext} runs`, false, e.message.split('\n')[0]);
    }
    const pageBytes = fs.readFileSync(file);
    check(`Moss .${ext} downloads the bytes of \`niwa moss grow --url HASH --out moss.${ext}\``,
      d.suggestedFilename().endsWith(`.${ext}`) && pageBytes.length > 1000 && pageBytes.equals(nativeBytes),
      `${d.suggestedFilename()}: ${pageBytes.length} bytes, native ${nativeBytes.length}`);
  }

  // 3. Overlays of the last day: each field's range holds the stats' per-geology means; each tints
  // the land its own way; the photon points are the stored photons, yellow and blue.
  const overlayHooks = async (value) => {
    await page.selectOption('#overlay', value);
    await page.waitForFunction((v) => document.documentElement.dataset.drawnOverlay === v, value, { timeout: TIMEOUT });
    return page.evaluate(() => ({ ...document.documentElement.dataset }));
  };
  const tints = {};
  tints.coverage = await tint(page);
  const fields = [];
  for (const field of ['irradiance', 'T_s', 'rh_s', 'theta', 'fitness']) {
    const h = await overlayHooks(field);
    tints[field] = await tint(page);
    await saveCanvasPng(page, `moss-${field}.png`);
    const key = field === 'irradiance' ? 'S' : field;
    const means = stats && key !== 'fitness' ? Object.values(stats.soil_last_day).map((g) => g[key]) : [];
    const min = Number(h.overlayMin), max = Number(h.overlayMax);
    const span = (max - min) || 1;
    fields.push({ field, shown: h.overlayField, min, max, means, ok: h.overlayField === field && (field === 'rh_s' ? min <= max : min < max) &&
      means.every((m) => m >= min - 1e-4 * span && m <= max + 1e-4 * span) && (field !== 'fitness' || (min >= 0 && max <= 1)),
    help: await page.textContent('#overlay-help') });
  }
  check('T_s, rh_s, theta, S and G overlays: a range over the land that holds the stats\' per-geology means', fields.every((f) => f.ok),
    fields.map((f) => `${f.field} ${f.min.toPrecision(4)}..${f.max.toPrecision(4)}${f.ok ? '' : ` BAD (${f.min}..${f.max}, means ${f.means.join(' ')})`}`).join(', '));
  await overlayHooks('none');
  tints.none = await tint(page);
  // T_s is linear in S on this run (the soil is wet: the energy balance's other terms are the same
  // on every cell), so the two ramps look alike, and 60 days' mosses cover so little (0.05 %) that
  // coverage looks like none; every other pair differs. (rh_s may be 1 on every cell: one colour.)
  const names = Object.keys(tints);
  const apart = (a, b) => Math.max(...a.mean.map((x, i) => Math.abs(x - b.mean[i])));
  let closest = { d: Infinity };
  for (let i = 0; i < names.length; ++i) {
    for (let j = i + 1; j < names.length; ++j) {
      if (`${names[i]}/${names[j]}` === 'irradiance/T_s' || `${names[i]}/${names[j]}` === 'coverage/none') continue;
      const d = apart(tints[names[i]], tints[names[j]]);
      if (d < closest.d) closest = { d, pair: `${names[i]}/${names[j]}` };
    }
  }
  check('each overlay tints the land its own way (mean colours apart; S/T_s and coverage/none aside)', closest.d > 0.5,
    `closest pair ${closest.pair} ${closest.d.toFixed(2)}; ${names.map((n) => `${n} ${tints[n].mean.map((x) => x.toFixed(0)).join('/')}`).join(', ')}`);
  const ph = await overlayHooks('photons');
  const photonTint = await tint(page);
  await saveCanvasPng(page, 'moss-photons.png');
  const depths = stats ? stats.photons_last_day.stored_by_depth : [];
  const direct = depths[0] ?? NaN, bounced = depths.slice(1).reduce((a, b) => a + b, 0);
  check('photon points: the last day\'s stored photons, direct and bounced as the stats count them by depth',
    Number(ph.photonsDirect) === direct && Number(ph.photonsBounced) === bounced && bounced > 0,
    `page ${ph.photonsDirect} direct + ${ph.photonsBounced} bounced, stats ${direct} + ${bounced}`);
  check('photon points drawn in two colours (yellow direct, blue bounced)', photonTint.yellow > 0.0005 && photonTint.blue > 0.00005 &&
    tints.coverage.yellow < photonTint.yellow, `yellow ${(photonTint.yellow * 100).toFixed(3)}%, blue ${(photonTint.blue * 100).toFixed(3)}% (coverage view yellow ${(tints.coverage.yellow * 100).toFixed(3)}%)`);
  await page.selectOption('#overlay', 'coverage');

  // 4. A bad value: days -1 through the panel is a line beside Days, and the page keeps working.
  let serial = Number(data.mossSerial);
  await page.fill('#days', '-1');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const beside = await page.evaluate(() => {
    const line = document.getElementById('days-error');
    return line && !line.hidden ? line.textContent : '';
  });
  const notice = await page.textContent('#notice');
  check('days -1 is a line beside Days', /^days: /.test(beside) && /-1/.test(beside) && notice.includes('days'), `beside '${beside}', notice '${notice}'`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-bad-days.png') });
  await page.fill('#days', '20');
  data = await waitMoss(page, serial);
  check('the page recovers after the bad value', data.status === 'ready' && data.hash.includes('days=20'), `${data.status} ${data.hash} ${data.error || ''}`);
  compareWithNative('days 20', data);
  // The worker copied the 20-day run into the buffers the page gave back (same scene, fewer mosses):
  // the land's 9 and the mosses' 7 at least (the photons' 2 when their count fits).
  check('the second run reuses the returned buffers (land, mosses; photons when they fit)', Number(data.buffersReused) >= 16,
    `reused ${data.buffersReused}, fresh ${data.buffersFresh}`);

  // 4b. A long run shows its days as it grows; Cancel ends it and the last finished run grows again.
  serial = Number(data.mossSerial);
  const goodHash = data.hash;
  await page.fill('#days', '300');
  await page.waitForFunction(() => /growing: day [1-9]/.test(document.getElementById('progress').textContent), null, { timeout: TIMEOUT });
  const progressText = await page.textContent('#progress');
  await page.click('#cancel');
  const cancelled = await page.evaluate(() => document.documentElement.dataset.status);
  data = await waitMoss(page, serial);
  check('progress by day, then Cancel goes back to the last finished run', /growing: day \d+ of 300/.test(progressText) && cancelled === 'cancelled' &&
    data.status === 'ready' && data.hash === goodHash, `'${progressText}', status after Cancel ${cancelled}, then ${data.status} ${data.hash}`);

  // 5. A bad hash value: a notice, and a run still grows.
  serial = Number(data.mossSerial);
  await page.evaluate(() => { location.hash = '#preset=nomura2010&days=-1&photons=2048&scene=thesis'; });
  data = await waitMoss(page, serial);
  const hashNotice = await page.textContent('#notice');
  check('a bad days in the hash is a notice, and a run grows', data.status === 'ready' && /days/.test(hashNotice),
    `${data.status}, ${data.hash}, notice '${hashNotice.replace(/\n/g, ' | ')}'`);

  // 5b. The rocks scene's size knob (rock_triangles): shown only on rocks, in the hash, a bad value beside it.
  serial = Number(data.mossSerial);
  await page.selectOption('#scene', 'rocks');
  data = await waitMoss(page, serial);
  const rocksBefore = JSON.parse(data.stats);
  const knobShown = await page.isVisible('#rock-triangles');
  serial = Number(data.mossSerial);
  await page.fill('#rock-triangles', '6400');
  data = await waitMoss(page, serial);
  const rocksAfter = JSON.parse(data.stats);
  check('Rock triangles shows on rocks and regrows them finer (hash, stats)', knobShown && data.hash.includes('rock_triangles=6400')
    && rocksBefore.rock_triangles === undefined && rocksAfter.rock_triangles === 6400 && rocksAfter.cells.total > rocksBefore.cells.total,
    `shown ${knobShown}, ${data.hash}, stats rock_triangles ${rocksBefore.rock_triangles} (the default is left out) -> ${rocksAfter.rock_triangles}, cells ${rocksBefore.cells.total} -> ${rocksAfter.cells.total}`);
  await page.fill('#rock-triangles', '50');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const rocksLine = await page.evaluate(() => {
    const line = document.getElementById('rock-triangles-error');
    return line && !line.hidden ? line.textContent : '';
  });
  check('Rock triangles 50 is a line beside it naming the range', /rock_triangles/.test(rocksLine) && /100/.test(rocksLine) && /6553600|6,553,600/.test(rocksLine), rocksLine);
  await page.fill('#rock-triangles', '1600');
  data = await waitMoss(page, serial);
  check('after it the rocks grow again, and the hash leaves the default out', data.status === 'ready' && !data.hash.includes('rock_triangles'), `${data.status} ${data.hash}`);
  await page.selectOption('#scene', 'plane');
  const knobHidden = !(await page.isVisible('#rock-triangles'));
  check('Rock triangles hides on other scenes', knobHidden, `hidden ${knobHidden}`);

  // 6. Copy link: the link reopens the same run.
  serial = Number(data.mossSerial);
  await page.selectOption('#scene', 'plane');
  data = await waitMoss(page, serial);
  await page.evaluate(() => { document.getElementById('share-status').textContent = ''; });  // the downloads' "Saved" line
  await page.click('#copy-link');
  await page.waitForFunction(() => document.getElementById('share-status').textContent !== '', null, { timeout: TIMEOUT });
  const status = await page.textContent('#share-status');
  const link = status === 'Link copied.' ? await page.evaluate(() => navigator.clipboard.readText()) : status.replace(/^Copy this link: /, '');
  check('Copy link gives the page\'s link', link.endsWith(`#${data.hash}`) && data.hash.includes('scene=plane'), `${status}: ${link}`);
  const page2 = await context.newPage();
  watchPage(page2, problems);
  await page2.goto(link, { waitUntil: 'load' });
  const data2 = await waitMoss(page2, 0);
  check('the copied link reopens the same run (same stats)', data2.status === 'ready' && data2.hash === data.hash && same(JSON.parse(data2.stats), JSON.parse(data.stats)),
    `${data2.status} ${data2.hash} ${data2.mosses} mosses vs ${data.mosses}`);
  await saveCanvasPng(page2, 'moss-plane.png');
  await page2.close();

  // 7. A dropped mesh: the moss grows on it as `niwa moss grow --mesh FILE` does (the stats agree),
  // by drop on the view (materials.glb: three geologies) and by the file input (rock1.glb: Draco).
  serial = Number(data.mossSerial);
  await page.fill('#days', '20');
  data = await waitMoss(page, serial);
  const dropFile = async (name, bytes) => page.evaluate(async ({ name: n, b64 }) => {
    const raw = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const transfer = new DataTransfer();
    transfer.items.add(new File([raw], n));
    const stage = document.getElementById('stage');
    stage.dispatchEvent(new DragEvent('dragenter', { dataTransfer: transfer, bubbles: true }));
    stage.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true }));
  }, { name, b64: Buffer.from(bytes).toString('base64') });
  const meshes = path.join(ROOT, 'tests/data/meshes');
  serial = Number(data.mossSerial);
  await dropFile('materials.glb', fs.readFileSync(path.join(meshes, 'materials.glb')));
  data = await waitMoss(page, serial);
  const meshStats = data.stats ? JSON.parse(data.stats) : {};
  check('a dropped materials.glb grows mosses on it (three geologies from its materials)', data.status === 'ready' && data.sceneShown === 'mesh:materials.glb' &&
    meshStats.cells && Object.values(meshStats.cells.by_geology).every((n) => n > 0) && Number(data.mosses) > 0,
    `${data.status} ${data.sceneShown} cells ${JSON.stringify(meshStats.cells?.by_geology)} ${data.mosses} mosses ${data.error || data.meshError || ''}`);
  compareWithNative('materials.glb', data, ['--mesh', path.join(meshes, 'materials.glb')]);
  const meshNotice = await page.textContent('#notice');
  check('the notice says a dropped mesh is not part of the link', meshNotice.includes('not part of the link'), meshNotice);
  await saveCanvasPng(page, 'moss-materials-glb.png');
  serial = Number(data.mossSerial);
  await page.setInputFiles('#mesh-file', path.join(meshes, 'rock1.glb'));
  data = await waitMoss(page, serial);
  check('rock1.glb (Draco) picked with the file input grows mosses on it', data.status === 'ready' && data.sceneShown === 'mesh:rock1.glb' && Number(data.mosses) > 0,
    `${data.status} ${data.sceneShown} ${data.mosses} mosses ${data.error || data.meshError || ''}`);
  compareWithNative('rock1.glb', data, ['--mesh', path.join(meshes, 'rock1.glb')]);
  await saveCanvasPng(page, 'moss-rock1-glb.png');

  // 8. Bad files: one line beside the drop control, the run shown stays, and the page keeps working.
  serial = Number(data.mossSerial);
  const bad = [];
  for (const [name, bytes] of [['not_gltf.glb', fs.readFileSync(path.join(meshes, 'not_gltf.glb'))], ['empty.glb', fs.readFileSync(path.join(meshes, 'empty.glb'))],
    ['truncated.glb', fs.readFileSync(path.join(meshes, 'materials.glb')).subarray(0, 200)], ['notes.txt', Buffer.from('moss')]]) {
    await page.evaluate(() => { delete document.documentElement.dataset.meshError; });
    await dropFile(name, bytes);
    await page.waitForFunction(() => (document.documentElement.dataset.meshError || '') !== '', null, { timeout: TIMEOUT });
    const line = await page.evaluate(() => {
      const e = document.getElementById('mesh-error');
      return e.hidden ? '' : e.textContent;
    });
    bad.push({ name, line });
  }
  await page.locator('#mesh-error').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-bad-mesh.png') });
  data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  check('each bad file is one line beside the drop control naming the mesh and the file', bad.every((b) => /^mesh: /.test(b.line) && !b.line.includes('\n') && b.line.includes(b.name)),
    bad.map((b) => `${b.name}: '${b.line}'`).join(' | ').slice(0, 600));
  check('after the bad files the rock\'s run is still shown', Number(data.mossSerial) === serial && data.sceneShown === 'mesh:rock1.glb', `${data.mossSerial} ${data.sceneShown}`);
  await page.selectOption('#scene', 'thesis');
  data = await waitMoss(page, serial);
  check('picking a scene after them grows again on the scene', data.status === 'ready' && data.sceneShown === 'thesis' && data.hash.includes('days=20'),
    `${data.status} ${data.sceneShown} ${data.hash}`);

  check('no uncaught error or console error', problems.length === 0, problems.slice(0, 3).join(' | ').slice(0, 400));
  await context.close();
});
