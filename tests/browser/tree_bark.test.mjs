// Browser test of the tree page's Bark choice (issue 30 item 3): node tests/browser/tree_bark.test.mjs.
// A grown tree picks "Simulated": the worker dresses the session's tree in the bark study's maps
// (TreeSession.dressBark, core/compose/bark_on_tree) without regrowing it, the bark texture the page
// draws changes (its digest, and the canvas), the link carries bark=sim and opening that link shows
// the simulated bark from the first tree; back to "Procedural" the procedural texture returns.
// Screenshots to LOOK at: build/artifacts/bark-procedural.png, bark-sim.png.
import { TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, snapshotCanvas, snapshotDifference, waitReady, watchPage } from './harness.mjs';

const problems = [];
const root = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));
const TREE = 'preset=sakura-thesis&seed=1&years=6';

// Picks the Bark choice and waits for the tree it sends to be drawn.
async function pickBark(page, value) {
  const before = Number((await root(page)).treeSerial || 0);
  await page.selectOption('#bark', value);
  await waitReady(page, before, 200);
}

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 900, height: 640 } });
  const page = await context.newPage();
  watchPage(page, problems);
  // A close camera on the trunk, so the bark fills the view.
  await page.goto(`${server.url}#${TREE}&cam=0.6,0.15,0.9,0,0.45,0`);
  await waitReady(page, 0, 200);
  const h0 = await root(page);
  check('first tree: procedural bark', h0.barkDigest !== '' && !h0.barkDigest.startsWith('bark-sim-') && h0.barkStats === '', h0.barkDigest);
  await snapshotCanvas(page, 'procedural');
  await saveCanvasPng(page, 'bark-procedural.png');

  await pickBark(page, 'sim');
  const h1 = await root(page);
  check('Simulated: the bark texture is the bark study\'s', h1.barkDigest.startsWith('bark-sim-') && h1.barkDigest !== h0.barkDigest, h1.barkDigest);
  const stats = h1.barkStats ? JSON.parse(h1.barkStats) : {};
  check(`Simulated: the bark ran on the trunk's history (N_R ${stats.N_R}, ${stats.cycles} cycle at dR ${stats.dR}, ` +
    `the surface ${stats.surface_years} of ${stats.radii_cm?.length - 1} years, at ${stats.height_m} m)`,
  stats.N_R % 2 === 0 && stats.cycles === 1 && stats.radii_cm?.length >= 2 &&
    Math.abs(stats.dR - stats.hoop_strain * stats.turnover_strain / (stats.hoop_strain + stats.turnover_strain)) <= 1e-9 * stats.dR &&
    stats.dR < stats.hoop_strain && stats.dR < stats.turnover_strain, h1.barkStats);
  check('Simulated: a restage, not a regrowth', h1.growRequests === h0.growRequests &&
    Number(h1.restageRequests) === Number(h0.restageRequests) + 1,
  `grows ${h0.growRequests} -> ${h1.growRequests}, restages ${h0.restageRequests} -> ${h1.restageRequests}`);
  check('Simulated: no refusal beside the choice', (h1.barkError || '') === '', h1.barkError);
  await snapshotCanvas(page, 'sim');
  await saveCanvasPng(page, 'bark-sim.png');
  const changed = await snapshotDifference(page, 'procedural', 'sim', 24);
  check(`Simulated: the picture changed (${(100 * changed).toFixed(1)} % of pixels)`, changed > 0.01);
  await page.waitForFunction(() => /bark=sim/.test(location.hash), null, { timeout: TIMEOUT });
  const link = await page.evaluate(() => location.hash);
  check('the link carries bark=sim', /bark=sim/.test(link), link);

  // The link opened afresh: the simulated bark on the first tree, no notice about the key.
  const opened = await context.newPage();
  watchPage(opened, problems);
  await opened.goto(`${server.url}${link}`);
  await waitReady(opened, 0, 200);
  const h2 = await root(opened);
  check('the link opens with the simulated bark', h2.barkDigest === h1.barkDigest, `${h2.barkDigest} vs ${h1.barkDigest}`);
  check('the link\'s bark=sim gives no hash notice', (await opened.textContent('#notice')).indexOf('bark') < 0);
  check('the link sets the choice', (await opened.inputValue('#bark')) === 'sim');
  await opened.close();

  await pickBark(page, 'procedural');
  const h3 = await root(page);
  check('Procedural again: the procedural texture returns', h3.barkDigest === h0.barkDigest && h3.barkStats === '', h3.barkDigest);
  check('Procedural again: the link drops bark=sim', !/bark=sim/.test(await page.evaluate(() => location.hash)));
  check('no console errors or warnings', problems.length === 0, problems.join(' | '));
});
