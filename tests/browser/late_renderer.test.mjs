// Browser test of a tree page whose WebGL starts after its first tree came (a slow first shader
// fetch or compile, as on a fresh CI machine): the tree waits for the renderer and is drawn, and the
// link gains the camera (web/tree/tree_view.js keeps the last tree while WebGL starts). Before, such
// a tree was handed back undrawn (the view stayed empty until the next edit) and the link had no
// cam=, so a reload framed another camera. The shaders are held here until the page reports the
// tree ready. Then the view's fallback: without OffscreenCanvas in workers the same view
// (tree_view.js) draws on the main thread, and a click picks a branch.
// Run: node tests/browser/late_renderer.test.mjs (needs build/wasm's niwa_web).
import { check, newContext, pickAt, runBrowserTest, TIMEOUT, waitReady, watchPage } from './harness.mjs';

await runBrowserTest(async (server, browser) => {
  const problems = [];
  const context = await newContext(browser, { viewport: { width: 1000, height: 700 } });
  const page = watchPage(await context.newPage(), problems);
  let release;
  const released = new Promise((resolve) => { release = resolve; });
  let held = 0;
  let firstHeld;
  const someHeld = new Promise((resolve) => { firstHeld = resolve; });
  await page.route('**/shaders/**', async (route) => {
    held += 1;
    firstHeld();
    await released;
    await route.continue();
  });
  await page.goto(`${server.url}#preset=maple&seed=2&years=6`);
  await page.waitForFunction(() => document.documentElement.dataset.status === 'ready', null, { timeout: TIMEOUT });
  // The render worker asks for its shaders once its WebGL2 context is made, which can be after the
  // tree came (the context's start is seconds on SwiftShader): the first held request is awaited.
  await Promise.race([someHeld, new Promise((resolve) => setTimeout(resolve, 30_000))]);
  const before = await page.evaluate(() => ({ hash: location.hash, drawn: document.documentElement.dataset.drawnTreeSerial || '' }));
  check('the tree came while the shaders were held (none drawn yet)', held > 0 && before.drawn === '',
    `${held} shader requests held; drawn serial '${before.drawn}'`);
  release();
  await waitReady(page, 0, 100);
  const frameStats = await page.textContent('#frame-stats');
  const tris = Number((frameStats.match(/^tris ([\d,]+)/) || [, '0'])[1].replace(/,/g, ''));
  check('the waiting tree is drawn once the renderer is up', tris > 1000, frameStats);
  const hash = await page.evaluate(() => location.hash);
  check('the link gains the camera', /&cam=-?[\d.]+(,-?[\d.e-]+){5}$/.test(hash), `${hash} (before: ${before.hash})`);
  await page.unroute('**/shaders/**');
  await page.reload();
  await waitReady(page, 0, 100);
  check('a reload keeps that link', (await page.evaluate(() => location.hash)) === hash);
  check('the view draws in the render worker (web/tree/render_worker.js)',
    (await page.evaluate(() => document.documentElement.dataset.viewThread)) === 'worker');

  // A browser without OffscreenCanvas in workers (transferControlToOffscreen taken away): the same
  // view (web/tree/tree_view.js) draws on the main thread, and a click still picks a branch.
  const fallback = await newContext(browser, { viewport: { width: 1000, height: 700 } });
  await fallback.addInitScript(() => { delete HTMLCanvasElement.prototype.transferControlToOffscreen; });
  const main = watchPage(await fallback.newPage(), problems);
  await main.goto(`${server.url}#preset=maple&seed=2&years=6`);
  await waitReady(main, 0, 100);
  const mainStats = await main.textContent('#frame-stats');
  const drawn = await main.evaluate(() => {
    const image = window.__niwaCanvasImage('#view');
    const d = image.data;
    let dark = 0, at = null;  // bark and leaves: darker than the sky and the ground
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] + d[i + 1] + d[i + 2] >= 200) continue;
      ++dark;
      const x = (i / 4) % image.width, y = Math.floor(i / 4 / image.width);
      if (!at || y > at.y) at = { x, y };  // the lowest: the trunk
    }
    const scale = image.width / document.getElementById('view').clientWidth;
    return { thread: document.documentElement.dataset.viewThread, dark: dark / (d.length / 4),
      trunk: at && { x: at.x / scale, y: (at.y - 4 * scale) / scale } };
  });
  check('without OffscreenCanvas the view draws on the main thread', drawn.thread === 'main' && drawn.dark > 0.002 &&
    /^tris [\d,]+/.test(mainStats), `${JSON.stringify(drawn)}; ${mainStats}`);
  const box = await main.locator('#view').boundingBox();
  if (drawn.trunk) await pickAt(main, box.x + drawn.trunk.x, box.y + drawn.trunk.y);
  const picked = await main.evaluate(() => document.documentElement.dataset.selected);
  check('... and a click on the trunk picks a branch there', /^\d+$/.test(picked || ''), `selected '${picked}'`);
  await fallback.close();
  check('no page errors', problems.length === 0, problems.join(' | '));
});
