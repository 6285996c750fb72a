// Browser test of a tree page whose WebGL starts after its first tree came (a slow first shader
// fetch or compile, as on a fresh CI machine): the tree waits for the renderer and is drawn, and the
// link gains the camera (web/tree/tree_page.js pendingTree). Before, such a tree was handed back
// undrawn (the view stayed empty until the next edit) and the link had no cam=, so a reload framed
// another camera. The shaders are held here until the page reports the tree ready.
// Run: node tests/browser/late_renderer.test.mjs (needs build/wasm's niwa_web).
import { check, newContext, runBrowserTest, TIMEOUT, waitReady, watchPage } from './harness.mjs';

await runBrowserTest(async (server, browser) => {
  const problems = [];
  const context = await newContext(browser, { viewport: { width: 1000, height: 700 } });
  const page = watchPage(await context.newPage(), problems);
  let release;
  const released = new Promise((resolve) => { release = resolve; });
  let held = 0;
  await page.route('**/shaders/**', async (route) => {
    held += 1;
    await released;
    await route.continue();
  });
  await page.goto(`${server.url}#preset=maple&seed=2&years=6`);
  await page.waitForFunction(() => document.documentElement.dataset.status === 'ready', null, { timeout: TIMEOUT });
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
  check('no page errors', problems.length === 0, problems.join(' | '));
});
