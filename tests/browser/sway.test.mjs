// Browser test of the wind sway in the page and in <niwa-tree>: node tests/browser/sway.test.mjs.
// Blow runs the node-point model (thesis ch.3) in the worker and skins the mesh on the GPU: the
// crown bends with the wind (+x is to the right in the view used), the pose clock runs, leaves and
// branches move, and Still restores the grown shape pixel for pixel. Screenshots: build/artifacts/sway-*.png.
import path from 'node:path';
import {
  ARTIFACTS, TIMEOUT, check, newContext, runBrowserTest, snapshotCanvas, snapshotDifference, waitReady, watchPage,
} from './harness.mjs';

const problems = [];
const swayTime = (page) => page.evaluate(() => Number(document.documentElement.dataset.swayTime || -1));

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1100, height: 760 } });
  const page = watchPage(await context.newPage(), problems);
  // A small tree seen from +z (yaw 0): the wind's +x direction (wind_dir 0) is to the right.
  await page.goto(`${server.url}#preset=keyaki-thesis&seed=1&years=7`);
  await waitReady(page, 0, 100);
  const cam = (await page.evaluate(() => location.hash)).match(/cam=([^&]*)/)[1].split(',');
  cam[0] = '0';
  cam[1] = '0.15';
  await page.goto(`${server.url}#preset=keyaki-thesis&seed=1&years=7&cam=${cam.join(',')}`);
  await page.reload();
  await waitReady(page, 0, 100);
  const still = await snapshotCanvas(page, 'still');
  const stillMode = await page.evaluate(() => document.documentElement.dataset.drawnMode);
  await page.screenshot({ path: path.join(ARTIFACTS, 'sway-still.png') });
  check('the tree is drawn before the wind', still.share > 0.01, `${(still.share * 100).toFixed(2)}% tree pixels`);

  // Blow: the default wind (5 m/s along +x from t = 1 s to 6 s, thesis 3.5.1).
  await page.click('#wind');
  check('Blow is pressed', (await page.getAttribute('#wind', 'aria-pressed')) === 'true');
  // The frame on screen, not the worker's clock: under load the canvas can still show a pose of
  // t < 2 s (the wind had pushed it for less than a second) while swayTime reads 3.5 s.
  await page.waitForFunction(() => Number(document.documentElement.dataset.drawnSwayTime || 0) > 3.5, null, { timeout: TIMEOUT, polling: 100 });
  const blowing = await snapshotCanvas(page, 'blowing');
  await page.screenshot({ path: path.join(ARTIFACTS, 'sway-blowing.png') });
  const moved = await snapshotDifference(page, 'still', 'blowing', 30);
  check('the tree moves in the wind', moved > 0.002, `${(moved * 100).toFixed(2)}% of pixels changed`);
  check('the crown bends with the wind (to +x, right)', blowing.centroidX > still.centroidX + 0.002,
    `centroid x ${still.centroidX.toFixed(4)} -> ${blowing.centroidX.toFixed(4)}`);
  const info = await page.textContent('#wind-info');
  check('the wind line shows the time and the wind', /^t = [\d.]+ s · wind [\d.]+ m\/s$/.test(info), info);

  // The simulated clock follows the wall clock (steps of dt; allowed to slip when drawing is slow).
  const t0 = await swayTime(page);
  await page.waitForTimeout(2000);
  const t1 = await swayTime(page);
  const advanced = ((t1 - t0 + 12) % 12);  // the gust schedule loops at its 12 s duration
  check('the sway clock runs', advanced > 0.5 && advanced < 2.6, `${advanced.toFixed(2)} s simulated in 2 s`);

  // Still: back to the grown shape exactly (rest poses are the identity).
  // The frame after Still may be drawn in parts (with the sun's shadow map redrawn for the rest
  // pose, it has about twice the primitives): wait until a finished frame started with the rest pose,
  // at full scale and in the mode the still frame had (under load the governor's cheaper frames
  // can still be on screen).
  const shownBefore = await page.evaluate(() => Number(document.documentElement.dataset.framesShown || 0));
  await page.click('#wind');
  await page.waitForTimeout(400);
  await page.waitForFunction(([n, mode]) => {
    const d = document.documentElement.dataset;
    return Number(d.framesShown || 0) > n && d.drawnPose === d.latestPose && Number(d.frameScale) === 1 && d.drawnMode === mode;
  }, [shownBefore, stillMode], { timeout: TIMEOUT, polling: 100 });
  await snapshotCanvas(page, 'stilled');
  const back = await snapshotDifference(page, 'still', 'stilled', 0);
  check('Still restores the grown shape pixel for pixel', back === 0, `${(back * 100).toFixed(3)}% of pixels differ`);

  // A new tree keeps blowing while Blow is on.
  await page.click('#wind');
  const serial = Number(await page.evaluate(() => document.documentElement.dataset.treeSerial));
  await page.fill('#seed', '2');
  await waitReady(page, serial, 100);
  await page.waitForFunction(() => document.documentElement.dataset.swayTime !== '' && Number(document.documentElement.dataset.swayTime) > 1.5,
    null, { timeout: TIMEOUT, polling: 100 });
  check('a new tree sways too while Blow is on', (await swayTime(page)) > 1.5);
  await page.screenshot({ path: path.join(ARTIFACTS, 'sway-new-tree.png') });
  await page.click('#wind');

  // The wind settings come from the parameter table: the panel has them and the URL keeps them.
  // Wind towards -x (wind_dir 180) bends the crown to the left.
  await page.evaluate(() => document.getElementById('param-wind_dir').closest('details').open = true);
  const serial2 = Number(await page.evaluate(() => document.documentElement.dataset.treeSerial));
  await page.fill('#param-wind_dir', '180');
  await waitReady(page, serial2, 100);
  const windHash = await page.evaluate(() => location.hash);
  check('wind_dir is in the URL', windHash.includes('wind_dir=180'), windHash);
  const still2 = await snapshotCanvas(page, 'still2');
  await page.click('#wind');
  await page.waitForFunction(() => Number(document.documentElement.dataset.drawnSwayTime || 0) > 3.5, null, { timeout: TIMEOUT, polling: 100 });
  const left = await snapshotCanvas(page, 'left');
  check('wind_dir 180 bends the crown the other way (left)', left.centroidX < still2.centroidX - 0.002,
    `centroid x ${still2.centroidX.toFixed(4)} -> ${left.centroidX.toFixed(4)}`);
  await page.click('#wind');

  // <niwa-tree wind>: an embedded tree sways by itself.
  const embed = watchPage(await context.newPage(), problems);
  await embed.goto(`${server.url}embed-example.html`);
  await embed.evaluate(() => {
    const tree = document.createElement('niwa-tree');
    Object.assign(tree, { id: 'windy' });
    tree.setAttribute('preset', 'binary');
    tree.setAttribute('years', '6');
    tree.setAttribute('wind', '');
    tree.style.cssText = 'display:block;width:300px;height:300px';
    document.body.append(tree);
  });
  const embedTime = await embed.waitForFunction(() => Number(document.getElementById('windy')?.dataset.swayTime || 0) > 2,
    null, { timeout: 60_000, polling: 100 }).then(() => embed.evaluate(() => Number(document.getElementById('windy').dataset.swayTime)), () => -1);
  check('<niwa-tree wind> sways', embedTime > 2, `sway time ${embedTime}`);
  await embed.locator('#windy').screenshot({ path: path.join(ARTIFACTS, 'sway-embed.png') });
  await embed.close();

  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
