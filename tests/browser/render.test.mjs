// Browser test of thesis chapter 4 in the page: node tests/browser/render.test.mjs.
// Sakura at 15 years in a 512 x 512 view, full polygons then hybrid (cards + lines) at the same
// camera: the table 4.1 in the panel matches `niwa tree render-stats`, hybrid draws at most 1/20 of
// the primitives in at most 1/5 of the frame time (each frame waited for, GPU work included), the
// two images stay alike (SSIM >= 0.85, computed here), a zoom sequence turns cards into lines and
// back with every branch drawn in every frame, and the hybrid tree sways. Screenshots:
// build/artifacts/render-*.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, snapshotCanvas, snapshotDifference, waitReady, watchPage } from './harness.mjs';
import { ssim } from './ssim.mjs';

const SIZE = 512;
const TREE = 'preset=sakura-thesis&seed=1&years=15';
const problems = [];
const root = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));
const camOf = (hash) => (hash.match(/cam=([^&]*)/) || [])[1];

// Grey values (Rec. 601 luma) of the view's canvas (through the harness's snapshot), and the box
// around the tree's pixels (bark dark, leaves green) with a margin of 8 px.
async function canvasGrey(page, key) {
  await snapshotCanvas(page, key);
  return page.evaluate((k) => {
    const { data: d, width, height } = window.__snapshots[k];
    const grey = new Array(width * height);
    let x0 = width, y0 = height, x1 = 0, y1 = 0;
    for (let i = 0; i < grey.length; ++i) {
      const r = d[4 * i], g = d[4 * i + 1], b = d[4 * i + 2];
      grey[i] = 0.299 * r + 0.587 * g + 0.114 * b;
      if (grey[i] < 80 || g - Math.max(r, b) > 25) {
        const x = i % width, y = Math.floor(i / width);
        x0 = Math.min(x0, x); x1 = Math.max(x1, x + 1); y0 = Math.min(y0, y); y1 = Math.max(y1, y + 1);
      }
    }
    const m = 8;
    return { grey, width, height,
      box: { x0: Math.max(0, x0 - m), y0: Math.max(0, y0 - m), x1: Math.min(width, x1 + m), y1: Math.min(height, y1 + m) } };
  }, key);
}

async function timeFrames(page, key) {
  await page.evaluate((k) => delete document.documentElement.dataset[k], key);
  await page.click('#time-frames');
  await page.waitForFunction((k) => document.documentElement.dataset[k], key, { timeout: TIMEOUT, polling: 200 });
  return JSON.parse((await root(page))[key]);
}

const cell = (page, attr) => page.$$eval(`#render-table [${attr}]`, (cells) =>
  Object.fromEntries(cells.map((c) => [c.dataset.row || c.dataset.full, c.textContent.replace(/,/g, '')])));

await runBrowserTest(async (server, browser) => {
  // The stage is the window less the 340 px panel: a 512 x 512 canvas at device pixel ratio 1.
  const context = await newContext(browser, { viewport: { width: SIZE + 340, height: SIZE }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  watchPage(page, problems);

  // ---- full polygons
  await page.goto(`${server.url}#${TREE}`);
  await waitReady(page, 0, 200);
  const size = await page.evaluate(() => [document.getElementById('view').width, document.getElementById('view').height]);
  check('the view is 512 x 512', size[0] === SIZE && size[1] === SIZE, size.join(' x '));
  check('full mode is the default', (await root(page)).renderMode === 'full' && (await page.inputValue('#render-mode')) === '0');
  const cam = camOf(await page.evaluate(() => location.hash));
  const fullImage = await canvasGrey(page, 'full');
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'render-full.png') });
  const full = await timeFrames(page, 'timedFull');
  const fullCells = await cell(page, 'data-full');
  // Time 10 frames is its own Cancel while it runs (issue 32: a full frame of a big tree takes
  // seconds on a CPU GL): pressed again two animation frames in, it stops with the frames it timed.
  const cancelled = await page.evaluate(() => new Promise((resolve) => {
    const button = document.getElementById('time-frames');
    button.click();
    const running = button.textContent;
    requestAnimationFrame(() => requestAnimationFrame(() => {
      button.click();
      const cancelling = button.textContent;
      new MutationObserver((_, observer) => {
        const d = document.documentElement.dataset;
        if (d.timing === 'running') return;
        observer.disconnect();
        resolve({ running, cancelling, timing: d.timing, frames: d.timedFrames, after: button.textContent,
          cell: document.querySelector('#render-table [data-full="timed_ms"]').textContent });
      }).observe(document.documentElement, { attributes: true, attributeFilter: ['data-timing'] });
    }));
  }));
  check('Time 10 frames: pressed again while it runs, it cancels (the frames timed so far shown)',
    cancelled.running === 'Cancel timing' && cancelled.cancelling === 'Cancelling…' && cancelled.timing === 'cancelled'
    && Number(cancelled.frames) < 10 && cancelled.after === 'Time 10 frames' && /cancelled|of 10\)$/.test(cancelled.cell),
    JSON.stringify(cancelled));

  // ---- hybrid, switched in the panel: the URL keeps it, the camera stays
  const serial = Number((await root(page)).treeSerial);
  await page.selectOption('#render-mode', '1');
  await waitReady(page, serial, 200);
  await page.waitForFunction(() => Number(document.documentElement.dataset.renderViews || 0) >= 1, null, { timeout: TIMEOUT });
  // A whole hybrid frame drawn with the latest draw list (a fixed 500 ms wait once caught an older
  // frame under load: SSIM 0.828 against the usual 0.855).
  await page.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.drawnMode === 'hybrid' && Number(d.drawnViews) >= Math.max(1, Number(d.renderViews || 0));
  }, null, { timeout: TIMEOUT, polling: 50 });
  await page.waitForTimeout(300);
  const hash = await page.evaluate(() => location.hash);
  check('the mode is in the URL', hash.includes('render_mode=1'), hash);
  check('the camera is the same in both modes', camOf(hash) === cam, `${cam} / ${camOf(hash)}`);
  const hybridImage = await canvasGrey(page, 'hybrid');
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'render-hybrid.png') });
  await page.screenshot({ path: path.join(ARTIFACTS, 'render-hybrid-page.png') });
  const hybrid = await timeFrames(page, 'timedHybrid');
  const rowCells = await cell(page, 'data-row');

  // Table 4.1 in the page = the CLI's render-stats for the same tree, view and viewport.
  const cli = JSON.parse(execFileSync(NATIVE, ['tree', 'render-stats', '--url', `${TREE}&render_mode=1`, '--cam', cam,
    '--width', String(SIZE), '--height', String(SIZE)], { encoding: 'utf8' }));
  for (const key of ['lines', 'branch_polygons', 'leaf_polygons', 'total_polygons', 'textures']) {
    check(`table 4.1 "${key}" = niwa tree render-stats`, Number(rowCells[key]) === cli[key], `page ${rowCells[key]}, CLI ${cli[key]}`);
  }
  check('table 4.1 full polygons = niwa tree render-stats full_polygons', Number(fullCells.total_polygons) === cli.full_polygons,
    `page ${fullCells.total_polygons}, CLI ${cli.full_polygons}`);
  check('draw calls and timed frames are shown in both columns', Number(rowCells.draw_calls) > 0 && Number(fullCells.draw_calls) > 0
    && /ms$/.test(rowCells.timed_ms) && /ms$/.test(fullCells.timed_ms), JSON.stringify([rowCells.timed_ms, fullCells.timed_ms]));

  // The speed and quality goals of the issue (sakura 15 y, 512 x 512, one run).
  const primitives = { full: full.triangles + full.lines, hybrid: hybrid.triangles + hybrid.lines };
  const primitiveRatio = primitives.hybrid / primitives.full;
  check('hybrid draws at most 1/20 of the full mode\'s primitives', primitiveRatio <= 1 / 20,
    `${primitives.hybrid} (${hybrid.triangles} triangles + ${hybrid.lines} lines) / ${primitives.full} = ${primitiveRatio.toFixed(4)}`);
  const timeRatio = hybrid.ms / full.ms;
  check('hybrid frame time at most 1/5 of full mode', timeRatio <= 1 / 5,
    `${hybrid.ms.toFixed(1)} ms / ${full.ms.toFixed(1)} ms = ${timeRatio.toFixed(3)} (median of 10, SwiftShader)`);
  const whole = ssim(fullImage.grey, hybridImage.grey, SIZE, SIZE);
  const box = fullImage.box;
  const crown = ssim(fullImage.grey, hybridImage.grey, SIZE, SIZE, box);
  check('hybrid and full images alike: SSIM >= 0.85', whole >= 0.85, `SSIM ${whole.toFixed(3)} (whole view); ${crown.toFixed(3)} over the tree's box ${box.x1 - box.x0} x ${box.y1 - box.y0} px`);
  let state = 12345;
  const noise = fullImage.grey.map(() => (state = (state * 1103515245 + 12345) % 2147483648) % 256);
  const selfSsim = ssim(fullImage.grey, fullImage.grey, SIZE, SIZE), noiseSsim = ssim(fullImage.grey, noise, SIZE, SIZE);
  check('SSIM of an image with itself is 1, with noise near 0', Math.abs(selfSsim - 1) < 1e-12 && noiseSsim < 0.1,
    `${selfSsim}, ${noiseSsim.toFixed(4)}`);
  console.log(`INFO render: ${JSON.stringify({ full, hybrid, primitiveRatio, timeRatio, ssim: whole, ssimTreeBox: crown })}`);

  // ---- the mode survives a reload
  await page.reload();
  await waitReady(page, 0, 200);
  check('reload keeps hybrid mode', (await root(page)).renderMode === 'hybrid' && (await page.inputValue('#render-mode')) === '1');
  await page.waitForFunction(() => Number(document.documentElement.dataset.renderViews || 0) >= 1, null, { timeout: TIMEOUT });

  // ---- zoom out and back in: cards become lines and back; no view leaves a branch undrawn
  const views = [];
  const zoomStep = async (deltaY) => {
    const before = Number((await root(page)).renderViews);
    await page.mouse.move(SIZE / 2, SIZE / 2);
    await page.mouse.wheel(0, deltaY);
    await page.waitForFunction((n) => Number(document.documentElement.dataset.renderViews) > n, before, { timeout: TIMEOUT, polling: 50 });
    await page.waitForTimeout(150);
    const d = await root(page);
    const snap = await snapshotCanvas(page, `zoom${views.length}`);
    views.push({ lines: Number(d.renderLines), polygons: Number(d.renderPolygons), unassigned: Number(d.renderUnassigned), dark: snap.share });
  };
  const start = await root(page);
  for (let i = 0; i < 4; ++i) await zoomStep(200);
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'render-zoomed-out.png') });
  const far = views[views.length - 1];
  for (let i = 0; i < 8; ++i) await zoomStep(-200);
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'render-zoomed-in.png') });
  const near = views[views.length - 1];
  check('every branch is a card or a line in every view', views.every((v) => v.unassigned === 0), JSON.stringify(views.map((v) => v.unassigned)));
  check('zooming out turns cards into lines', far.lines > Number(start.renderLines) && far.polygons < Number(start.renderPolygons),
    `lines ${start.renderLines} -> ${far.lines}, polygons ${start.renderPolygons} -> ${far.polygons}`);
  check('zooming in turns lines back into cards', near.lines < far.lines && near.polygons > Number(start.renderPolygons),
    `lines ${far.lines} -> ${near.lines}, polygons ${far.polygons} -> ${near.polygons}`);
  check('the tree is on screen in every view of the sequence', views.every((v) => v.dark > 0.002), views.map((v) => v.dark.toFixed(4)).join(' '));

  // ---- the hybrid tree sways: cards and lines follow the node points
  await snapshotCanvas(page, 'hybridStill');
  await page.click('#wind');
  // The frame on screen has a pose of t > 3 s (the worker's clock runs ahead of it under load).
  await page.waitForFunction(() => Number(document.documentElement.dataset.drawnSwayTime || 0) > 3, null, { timeout: TIMEOUT, polling: 100 });
  await snapshotCanvas(page, 'hybridBlowing');
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'render-hybrid-wind.png') });
  const moved = await snapshotDifference(page, 'hybridStill', 'hybridBlowing', 30);
  check('cards and lines move in the wind', moved > 0.002, `${(moved * 100).toFixed(2)}% of pixels changed`);
  // The rest pose's frame, once it is finished (data-drawn-pose: the poses a finished frame started
  // with; on a loaded CPU GL it can come later than 400 ms after Still).
  const shownBefore = await page.evaluate(() => Number(document.documentElement.dataset.framesShown || 0));
  await page.click('#wind');
  await page.waitForTimeout(400);
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    return Number(d.framesShown || 0) > n && d.drawnPose === d.latestPose && Number(d.frameScale) === 1;
  }, shownBefore, { timeout: TIMEOUT, polling: 100 });
  await snapshotCanvas(page, 'hybridStilled');
  const back = await snapshotDifference(page, 'hybridStill', 'hybridStilled', 0);
  check('Still puts cards and lines back exactly', back === 0, `${(back * 100).toFixed(3)}% of pixels differ`);

  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
