// Browser test of the moss page's Land control (public/moss.html; issue 29 item 2): node
// tests/browser/moss_land.test.mjs (exit 0 = pass). A link holding a Niwa tree as the land (scene
// tree, tree, tree_years) opens with the Land control on the tree and its fields filled, grows
// mosses on the bark and the ground whose stats equal the native CLI's `niwa moss grow --url HASH
// --stats` (every field but the ms* timings), and Copy link's hash is that link; picking a Niwa
// terrain in the Land control grows on the mountain, its stats again equal the CLI's for the
// page's hash; a bad tree preset is one line beside its field and the page keeps working; back
// on a built-in scene the link has no land fields.
// Screenshots: build/artifacts/moss-land-tree.png, moss-land-terrain.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const canonical = (v) => (Array.isArray(v) ? v.map(canonical) : v && typeof v === 'object'
  ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canonical(v[k])])) : v);
const same = (a, b) => JSON.stringify(canonical(withoutMs(a))) === JSON.stringify(canonical(withoutMs(b)));

const waitMoss = (page, serialAbove) => waitStudyRun(page, 'mossSerial', serialAbove);

function compareWithNative(name, data) {
  const args = ['moss', 'grow', '--url', data.hash, '--stats'];
  let native = null;
  try {
    native = JSON.parse(execFileSync(NATIVE, args, { encoding: 'utf8' }).trim().split('\n').pop());
  } catch (e) {
    check(`${name}: native CLI runs`, false, `${NATIVE} ${args.join(' ')}: ${e.message.split('\n')[0]}`);
    return null;
  }
  const web = JSON.parse(data.stats);
  const ok = same(web, native);
  check(`${name}: page stats == native \`niwa ${args.join(' ')}\` (ms* aside)`, ok,
    ok ? `${web.mosses.total} mosses, cells ${JSON.stringify(web.cells.by_region)}`
      : `web ${JSON.stringify(withoutMs(web)).slice(0, 300)} native ${JSON.stringify(withoutMs(native)).slice(0, 300)}`);
  return web;
}

// Shares of the canvas: background, and moss-green pixels.
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

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 }, permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await context.newPage();
  watchPage(page, problems);

  // 1. A link with a tree as the land.
  const treeHash = 'preset=nomura2010&scene=tree&days=8&tree=sakura&tree_years=4&photons=1024';
  await page.goto(`${server.url}moss.html#${treeHash}`, { waitUntil: 'load' });
  let data = await waitMoss(page, 0);
  check('a tree link grows on the tree', data.status === 'ready' && data.sceneShown === 'tree:sakura' && Number(data.mosses) > 0,
    `status ${data.status}, ${data.sceneShown}, ${data.mosses} mosses ${data.error || ''}`);
  check('the page\'s hash is the link', data.hash === treeHash, data.hash);
  const controls = await page.evaluate(() => ({
    land: document.getElementById('land').value, tree: document.getElementById('tree-preset').value,
    years: document.getElementById('tree-years').value, treeShown: !document.getElementById('land-tree').hidden,
    terrainShown: !document.getElementById('land-terrain').hidden,
  }));
  check('the Land control shows the tree and its fields', controls.land === 'tree' && controls.tree === 'sakura' && controls.years === '4' &&
    controls.treeShown && !controls.terrainShown, JSON.stringify(controls));
  const tree = compareWithNative('tree land', data);
  check('mosses on the bark and the ground', tree && tree.cells.by_region.bark > 0 && tree.mosses.total > 0,
    tree ? JSON.stringify(tree.mosses.by_region) : '');
  const look = await looks(page);
  check('the tree land is drawn with every living moss', look.background < 0.97 && Number(data.drawnMosses) === Number(data.mosses),
    `background ${(look.background * 100).toFixed(1)}%, ${data.drawnMosses} of ${data.mosses} mosses drawn`);
  await saveCanvasPng(page, 'moss-land-tree.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-land-tree-page.png') });
  await page.click('#copy-link');
  await page.waitForFunction(() => document.getElementById('share-status').textContent !== '', null, { timeout: TIMEOUT });
  const copied = await page.evaluate(() => navigator.clipboard.readText()).catch(() => '');
  check('Copy link holds the tree', copied.endsWith(`#${treeHash}`), copied);

  // 2. A bad tree preset: one line beside its field; the run shown stays.
  let serial = Number(data.mossSerial);
  await page.fill('#tree-preset', 'Bad!');
  await page.waitForFunction(() => !document.getElementById('tree-preset-error').hidden, null, { timeout: TIMEOUT });
  const line = await page.evaluate(() => document.getElementById('tree-preset-error').textContent);
  check('a bad tree preset is one line beside its field', /tree/.test(line) && !line.includes('\n'), line);
  await page.fill('#tree-preset', 'sakura');
  data = await waitMoss(page, serial);
  check('the page keeps working after it', data.status === 'ready' && data.hash === treeHash, `${data.status} ${data.hash}`);

  // 3. A Niwa terrain picked in the Land control (coarse soil cells and few days, to stay quick).
  serial = Number(data.mossSerial);
  await page.evaluate(() => {
    const days = document.getElementById('days');
    days.value = '3';
    const edge = document.querySelector('#params input[data-key="soil_edge"]');
    if (edge) edge.value = '10';
    const land = document.getElementById('land');
    land.value = 'terrain';
    land.dispatchEvent(new Event('change', { bubbles: true }));
  });
  data = await waitMoss(page, serial);
  check('the terrain grows', data.status === 'ready' && data.sceneShown === 'terrain:improved', `${data.status} ${data.sceneShown} ${data.error || ''}`);
  check('its hash holds the terrain', /(^|&)scene=terrain&/.test(data.hash) && data.hash.includes('terrain=improved&terrain_seed=1'), data.hash);
  const terrain = compareWithNative('terrain land', data);
  check('cells by height and geology on the mountain', terrain && terrain.cells.by_region.foot > 0 && terrain.cells.by_region.top > 0 &&
    terrain.cells.by_geology.sandy > 0, terrain ? `${JSON.stringify(terrain.cells)}` : '');
  await saveCanvasPng(page, 'moss-land-terrain.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-land-terrain-page.png') });

  // 4. Back to a built-in scene: no land fields in the link.
  serial = Number(data.mossSerial);
  await page.evaluate(() => {
    const land = document.getElementById('land');
    land.value = 'scene';
    land.dispatchEvent(new Event('change', { bubbles: true }));
  });
  data = await waitMoss(page, serial);
  check('back on a built-in scene, the link has no land fields', data.status === 'ready' && !/tree|terrain/.test(data.hash), data.hash);
  check('no page errors', problems.length === 0, problems.join('\n'));
  await context.close();
});
