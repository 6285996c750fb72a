// Browser test of the grove page (public/grove.html): node tests/browser/grove.test.mjs.
// 100 instanced trees from 10 unique trees in full and hybrid mode: every instance and every unique
// tree is drawn in both modes, hybrid draws far fewer primitives and frames faster, the mode and the
// camera live in the hash, orbiting asks for new draw lists. Screenshots: build/artifacts/grove-*.png.
import path from 'node:path';
import { ARTIFACTS, TIMEOUT, check, newContext, runBrowserTest, waitGroveDrawn, watchPage } from './harness.mjs';

const problems = [];
const data = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 900, height: 620 } });
  const page = await context.newPage();
  watchPage(page, problems);

  // Full mode from the hash.
  const started = Date.now();
  await page.goto(`${server.url}grove.html#mode=full`);
  await waitGroveDrawn(page, 'full');
  let d = await data(page);
  check('the grove loads (10 unique trees grown in the worker)', d.status === 'ready',
    `${((Date.now() - started) / 1000).toFixed(1)} s${d.status === 'error' ? `: ${await page.textContent('#message')}` : ''}`);
  check('the mode comes from the hash (#mode=full)', d.mode === 'full' && (await page.inputValue('#mode')) === 'full');
  check('full: 100 tree instances drawn', d.instances === '100', `instances ${d.instances}`);
  check('full: 10 unique trees drawn', d.unique === '10' && d.uniqueDrawn === '10', `${d.uniqueDrawn} of ${d.unique}`);
  const full = { triangles: Number(d.triangles), lines: Number(d.lines), drawCalls: Number(d.drawCalls) };
  check('full: one instanced draw per part and unique tree (few draw calls)', full.drawCalls > 10 && full.drawCalls <= 31,
    `${full.drawCalls} draw calls, ${full.triangles.toLocaleString('en-US')} triangles`);
  const coverFull = await page.evaluate(() => window.grove.coverage());
  check('full: every unique tree shows (its instances alone cover > 0.05% of the view)', coverFull.length === 10 && coverFull.every((c) => c > 0.0005),
    coverFull.map((c) => (c * 100).toFixed(2)).join(' ') + ' %');
  await page.screenshot({ path: path.join(ARTIFACTS, 'grove-full.png') });
  // One full frame, without the warm-up frame: the grove has just drawn in full mode (the first frame
  // and the coverage draws), and each full frame is about 12 s here.
  const fullTiming = await page.evaluate(() => window.grove.timeFrames(1, undefined, false));

  // Hybrid mode from the page's control: the hash follows.
  await page.selectOption('#mode', 'hybrid');
  await waitGroveDrawn(page, 'hybrid');
  d = await data(page);
  check('the mode switch writes the hash (#mode=hybrid)', (await page.evaluate(() => location.hash)).includes('mode=hybrid'));
  check('hybrid: 100 tree instances drawn', d.instances === '100', `instances ${d.instances}`);
  check('hybrid: 10 unique trees drawn', d.unique === '10' && d.uniqueDrawn === '10', `${d.uniqueDrawn} of ${d.unique}`);
  const hybrid = { triangles: Number(d.triangles), lines: Number(d.lines), drawCalls: Number(d.drawCalls) };
  const ratio = (hybrid.triangles + hybrid.lines) / full.triangles;
  check('hybrid draws far fewer primitives than full (< 1/10)', hybrid.lines > 0 && ratio < 0.1,
    `${(hybrid.triangles + hybrid.lines).toLocaleString('en-US')} (${hybrid.triangles} triangles + ${hybrid.lines} lines) vs ${full.triangles.toLocaleString('en-US')}: ${ratio.toFixed(4)}`);
  const coverHybrid = await page.evaluate(() => window.grove.coverage());
  check('hybrid: every unique tree shows (its instances alone cover > 0.05% of the view)', coverHybrid.length === 10 && coverHybrid.every((c) => c > 0.0005),
    coverHybrid.map((c) => (c * 100).toFixed(2)).join(' ') + ' %');
  await page.screenshot({ path: path.join(ARTIFACTS, 'grove-hybrid.png') });

  // The "Time N frames" button (2 frames here to keep the test short; the benchmark times 20).
  await page.fill('#frames', '2');
  await page.click('#time');
  await page.waitForFunction(() => document.documentElement.dataset.timing === 'done' && document.documentElement.dataset.timedMode === 'hybrid',
    null, { timeout: TIMEOUT, polling: 100 });
  d = await data(page);
  const text = await page.textContent('#timing');
  check('"Time 2 frames" shows the median ms per frame', /^hybrid: [\d.]+ ms per frame \(median of 2;/.test(text) && Number(d.frameMs) > 0, text);
  check('a hybrid frame takes less time than a full one', Number(d.frameMs) < fullTiming.median,
    `${Number(d.frameMs).toFixed(0)} ms vs ${fullTiming.median.toFixed(0)} ms (SwiftShader)`);
  // While timing, the button is its Cancel: 200 frames asked, cancelled after the first few.
  await page.fill('#frames', '200');
  await page.click('#time');
  await page.waitForFunction(() => document.documentElement.dataset.timing === 'running', null, { timeout: TIMEOUT, polling: 20 });
  const cancelLabel = await page.textContent('#time');
  await page.waitForTimeout(400);
  await page.click('#time');
  await page.waitForFunction(() => document.documentElement.dataset.timing === 'cancelled', null, { timeout: 60_000, polling: 50 });
  d = await data(page);
  const cancelledText = await page.textContent('#timing');
  check('Time frames can be cancelled (the button is its Cancel while it runs)', cancelLabel === 'Cancel timing' &&
    Number(d.timedFrames) < 200 && (await page.textContent('#time')) === 'Time 200 frames' &&
    (Number(d.timedFrames) === 0 || /median of \d+, cancelled/.test(cancelledText)),
    `label "${cancelLabel}", ${d.timedFrames} frames timed: ${cancelledText}`);

  // Orbiting asks the worker for the draw lists of the new view and keeps the camera in the hash.
  const serial = Number(d.viewSerial);
  const hashBefore = await page.evaluate(() => location.hash);
  const box = await page.locator('#view').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 + 30, { steps: 4 });
  await page.mouse.up();
  await waitGroveDrawn(page, 'hybrid', serial);
  d = await data(page);
  const hashAfter = await page.evaluate(() => location.hash);
  check('orbiting re-selects cards and lines (new draw lists) and updates cam= in the hash',
    Number(d.viewSerial) > serial && hashAfter !== hashBefore && /cam=/.test(hashAfter) && d.instances === '100',
    `${d.viewSerial} rounds, ${d.viewMs} ms for the last`);

  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
  console.log(`grove test took ${((Date.now() - started) / 1000).toFixed(0)} s`);
});
