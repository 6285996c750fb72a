// Browser test of the bark page (public/bark.html): node tests/browser/bark.test.mjs (exit 0 =
// pass). The page opens with no input, shows a 64 × 32 preview and frames of the lattice as it
// cracks, then the camphor preset grown on its 128 × 64 lattice with its maps on the tile and the
// trunk; its stats equal the native CLI's `niwa bark grow --url HASH --stats` (timing fields
// aside) for the page's own hash; the cycle scrubber replays fewer broken springs at an earlier
// cycle without a new grow; a species change regrows (tallow, == native too); Cancel during a
// grow goes back to the last finished bark; a bad panel value
// (kappa1 0.5) is a line beside its row and the page keeps working; Copy link gives a link that
// reopens the same run (same stats); a map downloads as a PNG; Table 3 runs the three species
// (its pine row == the native CLI's); embed.html?study=bark (the iframe
// form of <niwa-bark>) grows a linked state. Screenshots: build/artifacts/bark-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';

const TIMING = new Set(['ms', 'ns_per_spring_step']);
const untimed = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => !TIMING.has(k) && !k.startsWith('ms_')));
const canonical = (v) => (Array.isArray(v) ? v.map(canonical) : v && typeof v === 'object'
  ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canonical(v[k])])) : v);
const same = (a, b) => JSON.stringify(canonical(untimed(a))) === JSON.stringify(canonical(untimed(b)));

// Waits for a run newer than serialAbove drawn on screen (or an error); returns the dataset.
const waitBark = (page, serialAbove) => waitStudyRun(page, 'barkSerial', serialAbove);

function compareWithNative(name, data) {
  let native = null;
  try {
    native = JSON.parse(execFileSync(NATIVE, ['bark', 'grow', '--url', data.hash, '--stats'], { encoding: 'utf8' }).trim().split('\n').pop());
  } catch (e) {
    check(`${name}: native CLI runs`, false, `${NATIVE} bark grow --url ${data.hash}: ${e.message.split('\n')[0]}`);
    return null;
  }
  const web = JSON.parse(data.stats);
  const ok = same(web, native);
  check(`${name}: page stats == native \`niwa bark grow --url ${data.hash} --stats\` (timings aside)`, ok,
    ok ? `${web.broken.axial + web.broken.diagonal} springs broken, ${web.regions.count} regions, hash ${web.hash}`
      : `web ${JSON.stringify(untimed(web)).slice(0, 400)} native ${JSON.stringify(untimed(native)).slice(0, 400)}`);
  return web;
}

// Shares of the canvas: the background, and bark-coloured pixels (browns and greys darker than it).
async function looks(page) {
  return page.evaluate(() => {
    const d = window.__niwaCanvasImage('#view').data;
    let background = 0, bark = 0;
    for (let i = 0; i < d.length; i += 4) {
      const r = d[i], g = d[i + 1], b = d[i + 2];
      if (Math.abs(r - 219) < 8 && Math.abs(g - 230) < 8 && Math.abs(b - 240) < 8) { ++background; continue; }
      if (r >= b && r + g + b < 560) ++bark;
    }
    const n = d.length / 4;
    return { background: background / n, bark: bark / n };
  });
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1280, height: 800 }, acceptDownloads: true, permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await context.newPage();
  watchPage(page, problems);
  page.on('request', (r) => {
    if (!r.url().startsWith(server.url) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) problems.push(`external request: ${r.url()}`);
  });

  // 1. Opens with no input: a preview, frames as it cracks, then the full run with its maps.
  await page.goto(`${server.url}bark.html`, { waitUntil: 'load' });
  let data = await waitBark(page, 0);
  check('opens with a bark grown, its tile drawn', data.status === 'ready' && Number(data.drawnTriangles) > 0 && data.tileShows === 'lit',
    `status ${data.status}, ${data.drawnTriangles} triangles drawn, tile shows ${data.tileShows}, grow ${data.growMs} ms ${data.error || ''}`);
  check('a 64 × 32 preview came first, and frames of the lattice as it grew', Number(data.previews) >= 1 && data.previewNodes === '2048' && Number(data.framesSeen) > 0,
    `${data.previews} previews (${data.previewNodes} nodes, ${data.previewMs} ms), ${data.framesSeen} frames`);
  check('the hash is the opening state', data.hash === 'species=camphor&model=2layer&seed=1', data.hash);
  check('the maps are 1024 wide', data.mapWidth === '1024' && Number(data.mapHeight) >= 256, `${data.mapWidth} × ${data.mapHeight}`);
  const stats = compareWithNative('opening run', data);
  const nav = await page.locator('#studies a[aria-current="page"]').textContent().catch(() => '');
  check('the studies nav lists and marks Bark', nav === 'Bark', nav);
  const panelKeys = await page.evaluate(() => [...document.querySelectorAll('#params [data-key]')].map((e) => e.dataset.key));
  check('the panel is the bark table', ['kappa1', 'kappa2', 'E1', 'N_R', 'N_H', 'dR', 'dH', 'map_size'].every((k) => panelKeys.includes(k)), `${panelKeys.length} rows: ${panelKeys.join(',')}`);
  const species = await page.evaluate(() => [...document.querySelectorAll('#species option')].map((o) => o.value));
  check('the species select lists Table 2', species.join(',') === 'camphor,tallow,pine', species.join(','));
  let look = await looks(page);
  check('the tile and the trunk are drawn in bark colours', look.background < 0.85 && look.bark > 0.1,
    `background ${(look.background * 100).toFixed(1)}%, bark ${(look.bark * 100).toFixed(1)}%`);
  await saveCanvasPng(page, 'bark-opening.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'bark-page.png') });
  const chart = await page.evaluate(() => document.querySelectorAll('#chart path').length);
  check('the broken-fraction chart has a line per spring family', chart === 2, `${chart} paths`);

  // 2. The cycle scrubber replays the cracks: fewer broken at cycle 0.5, no new grow.
  const grows = Number(data.growRequests);
  const finalBroken = stats ? stats.broken.axial + stats.broken.diagonal : NaN;
  await page.evaluate(() => {
    const r = document.getElementById('cycle');
    r.value = '5';
    r.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForFunction(() => document.documentElement.dataset.cycleShown === '5' && !['lit', 'maps'].includes(document.documentElement.dataset.tileShows), null, { timeout: TIMEOUT });
  data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  check('cycle 0.5 shows fewer broken springs (plates view), without a new grow', Number(data.brokenShown) < finalBroken && Number(data.growRequests) === grows && data.tileShows === 'plates',
    `${data.brokenShown} at cycle 0.5 vs ${finalBroken} at the end; grow requests ${grows} -> ${data.growRequests}; tile shows ${data.tileShows}`);
  await page.waitForTimeout(300);
  await saveCanvasPng(page, 'bark-cycle05.png');
  await page.evaluate(() => {
    const r = document.getElementById('cycle');
    r.value = r.max;
    r.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.selectOption('#tile-view', 'plates');
  await page.waitForTimeout(400);
  await saveCanvasPng(page, 'bark-plates.png');
  await page.selectOption('#tile-view', 'strain');
  await page.waitForTimeout(400);
  await saveCanvasPng(page, 'bark-strain.png');
  await page.selectOption('#tile-view', 'maps');
  await page.waitForTimeout(400);
  await saveCanvasPng(page, 'bark-basecolour.png');
  await page.selectOption('#tile-view', 'tiled');
  await page.waitForFunction(() => document.documentElement.dataset.tileShows === 'tiled', null, { timeout: TIMEOUT });
  await page.waitForTimeout(300);
  await saveCanvasPng(page, 'bark-tiled.png');
  await page.selectOption('#tile-view', 'lit');

  // 3. A map downloads as a PNG.
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click('#download-normal')]);
  const file = path.join(ARTIFACTS, 'bark-normal-download.png');
  await download.saveAs(file);
  const bytes = fs.readFileSync(file);
  check('the normal map downloads as a PNG', download.suggestedFilename() === 'bark_camphor_normal.png' && bytes.subarray(1, 4).toString() === 'PNG' && bytes.length > 10000,
    `${download.suggestedFilename()}, ${bytes.length} bytes`);

  // 4. A species change regrows.
  let serial = Number(data.barkSerial);
  // While it grows: frames of the full lattice as it cracks (after the preview's). The page counts the
  // distinct full-lattice frames it drew while the run was live, so a fast machine that finishes before
  // the test looks cannot turn a drawn frame into a failure.
  // Under the machine's other work (scripts/test's second lane and the ASan build, load 9,
  // 2026-12-07) a run drew none of its frames live (0 of 14; alone, 11 of 14; not explained: most
  // likely the page's main thread got no animation frame between them): then the species is
  // changed once more (camphor, then tallow again) and that run is counted; one of the two must.
  const liveRun = async (species, before) => {
    const fullBefore = Number(before.liveFullDrawn || 0), seenBefore = Number(before.framesSeen);
    await page.selectOption('#species', species);
    await page.waitForFunction((sp) => document.documentElement.dataset.status === 'ready' && document.documentElement.dataset.species === sp, species, { timeout: TIMEOUT, polling: 50 });
    const after = await page.evaluate(() => ({ ...document.documentElement.dataset }));
    return { after, full: Number(after.liveFullDrawn) - fullBefore, seen: Number(after.framesSeen) - seenBefore };
  };
  let live = await liveRun('tallow', data);
  const tries = [`${live.full} of ${live.seen}`];
  if (live.full < 2) {
    const camphor = await liveRun('camphor', live.after);
    live = await liveRun('tallow', camphor.after);
    tries.push(`${live.full} of ${live.seen} (after a camphor run)`);
  }
  check('frames of the full lattice are drawn while it grows', live.full >= 2 && live.seen > 2,
    `full-lattice frames drawn live of frames received: ${tries.join('; ')}`);
  data = await waitBark(page, serial);
  check('a species change regrows (tallow)', data.status === 'ready' && data.species === 'tallow' && data.hash.includes('species=tallow') && Number(data.brokenAll) > 0,
    `${data.status} ${data.hash} broken ${data.brokenAll} ${data.error || ''}`);
  compareWithNative('tallow', data);
  await saveCanvasPng(page, 'bark-tallow.png');

  // 4b. A grow shows its steps as it goes; Cancel ends it and the last finished bark grows again.
  serial = Number(data.barkSerial);
  const goodHash = data.hash;
  await page.fill('#rng-seed', '7');
  await page.waitForFunction(() => /(preview|growing): step [1-9]/.test(document.getElementById('progress').textContent), null, { timeout: TIMEOUT, polling: 50 });
  const progressText = await page.textContent('#progress');
  await page.click('#cancel');
  const cancelled = await page.evaluate(() => document.documentElement.dataset.status);
  data = await waitBark(page, serial);
  check('progress by step, then Cancel goes back to the last finished bark', /(preview|growing): step \d+ of \d+/.test(progressText) && cancelled === 'cancelled'
    && data.status === 'ready' && data.hash === goodHash, `'${progressText}', status after Cancel ${cancelled}, then ${data.status} ${data.hash}`);

  // 5. A bad value: kappa1 0.5 through the panel is a line beside its row, and the page keeps working.
  serial = Number(data.barkSerial);
  await page.evaluate(() => { document.getElementById('param-kappa1').closest('details').open = true; });
  await page.fill('#param-kappa1', '0.5');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const beside = await page.evaluate(() => {
    const row = document.getElementById('param-kappa1').closest('.field');
    const line = row && row.querySelector('.field-error');
    return line && !line.hidden ? line.textContent : '';
  });
  const notice = await page.textContent('#notice');
  check('kappa1 0.5 is a line beside its row', /kappa1/.test(beside) && /0\.5/.test(beside) && notice.includes('kappa1'), `beside '${beside}', notice '${notice}'`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'bark-bad-kappa1.png') });
  await page.fill('#param-kappa1', '1.03');
  data = await waitBark(page, serial);
  check('the page recovers after the bad value', data.status === 'ready' && data.hash.includes('kappa1=1.03'), `${data.status} ${data.hash} ${data.error || ''}`);

  // 6. Copy link: the link reopens the same run.
  // (The line beside the buttons still says what the download above saved: wait for Copy link's own.)
  await page.click('#copy-link');
  await page.waitForFunction(() => /^(Link copied\.|Copy this link: )/.test(document.getElementById('share-status').textContent), null, { timeout: TIMEOUT });
  const status = await page.textContent('#share-status');
  const link = status === 'Link copied.' ? await page.evaluate(() => navigator.clipboard.readText()) : status.replace(/^Copy this link: /, '');
  check('Copy link gives the page\'s link', link.endsWith(`#${data.hash}`), `${status}: ${link}`);
  const page2 = await context.newPage();
  watchPage(page2, problems);
  await page2.goto(link, { waitUntil: 'load' });
  const data2 = await waitBark(page2, 0);
  check('the copied link reopens the same run (same stats)', data2.status === 'ready' && data2.hash === data.hash && same(JSON.parse(data2.stats), JSON.parse(data.stats)),
    `${data2.status} ${data2.hash} vs ${data.hash}`);
  look = await looks(page2);
  check('the reopened page draws the bark', look.bark > 0.1, `bark ${(look.bark * 100).toFixed(1)}%`);
  await page2.close();

  // 6b. Table 3: the three species' presets grown at this lattice and seed, beside the paper's.
  await page.click('#table3-run');
  await page.waitForFunction(() => document.documentElement.dataset.table3 !== undefined || !document.getElementById('table3-error').hidden, null, { timeout: TIMEOUT * 2, polling: 500 });
  const table3 = JSON.parse(await page.evaluate(() => document.documentElement.dataset.table3 || '[]'));
  const rows = await page.evaluate(() => [...document.querySelectorAll('#table3 tbody tr')].map((tr) => [...tr.children].map((td) => td.textContent)));
  check('Table 3 lists the three species beside the paper\'s numbers', rows.length === 3 && rows.map((r) => r[0]).join(',') === 'camphor,tallow,pine' && rows[2][1] === '2.34 × 4.28',
    JSON.stringify(rows));
  let nativePine = null;
  try {
    nativePine = JSON.parse(execFileSync(NATIVE, ['bark', 'grow', '--url', 'species=pine&model=2layer&seed=1', '--stats'], { encoding: 'utf8' }).trim().split('\n').pop());
  } catch (e) {
    nativePine = null;
  }
  const pine = table3.find((r) => r.species === 'pine');
  // The paper's measure, the crack spacing along scan lines (as `niwa bark table3` scores it).
  const sp = nativePine ? nativePine.spacing : null;
  check('Table 3\'s pine row == native `niwa bark grow --url species=pine&model=2layer&seed=1 --stats` crack spacing', Boolean(pine && sp
    && pine.mean_w === sp.width.mean && pine.mean_h === sp.height.mean && pine.max_w === sp.width.max && pine.max_h === sp.height.max && pine.open_h === sp.height.open),
    `page ${JSON.stringify(pine)}, native ${sp ? JSON.stringify({ width: sp.width, height: sp.height }) : 'failed'}`);
  await page.locator('#table3').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(ARTIFACTS, 'bark-table3.png') });

  // 6c. On a phone's width the page still grows and draws.
  const phone = await context.newPage();
  watchPage(phone, problems);
  await phone.setViewportSize({ width: 390, height: 844 });
  await phone.goto(`${server.url}bark.html#species=pine&seed=3&N_R=64&N_H=32`, { waitUntil: 'load' });
  const dataPhone = await waitBark(phone, 0);
  const lookPhone = await looks(phone);
  check('on a 390 px wide screen the page grows and draws the bark', dataPhone.status === 'ready' && lookPhone.bark > 0.05,
    `${dataPhone.status}, bark ${(lookPhone.bark * 100).toFixed(1)}%`);
  await phone.screenshot({ path: path.join(ARTIFACTS, 'bark-phone.png') });
  await phone.close();

  // 7. The iframe form of <niwa-bark> (embed.html?study=bark) grows the linked state.
  const page3 = await context.newPage();
  watchPage(page3, problems);
  await page3.setViewportSize({ width: 640, height: 400 });
  await page3.goto(`${server.url}embed.html?study=bark#species=pine&model=2layer&seed=2&N_R=64&N_H=32`, { waitUntil: 'load' });
  await page3.waitForFunction(() => {
    const d = document.querySelector('niwa-bark')?.dataset;
    return d && (d.status === 'ready' || d.status === 'error');
  }, null, { timeout: TIMEOUT, polling: 200 });
  await page3.waitForTimeout(500);
  const embed = await page3.evaluate(() => ({ ...document.querySelector('niwa-bark').dataset }));
  check('<niwa-bark> in embed.html grows the linked state', embed.status === 'ready' && embed.species === 'pine' && embed.hash === 'species=pine&model=2layer&seed=2&N_R=64&N_H=32',
    `${embed.status} ${embed.hash} ${embed.error || ''}`);
  const embedPng = await page3.evaluate(() => document.querySelector('niwa-bark').shadowRoot.querySelector('canvas').toDataURL('image/png'));
  fs.writeFileSync(path.join(ARTIFACTS, 'bark-embed.png'), Buffer.from(embedPng.split(',')[1], 'base64'));
  await page3.close();

  check('no uncaught error or console error', problems.length === 0, problems.slice(0, 3).join(' | ').slice(0, 400));
  await context.close();
});
