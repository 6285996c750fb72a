// Browser test of the ivy page's tree scene, progress and Cancel, and its Embed dialog (issue 18):
// node tests/browser/ivy_tree.test.mjs (exit 0 = pass). A hash with scene=tree&tree=..&tree_years=..
// grows ivy up that Niwa tree and its --stats equal `niwa ivy grow --url HASH` and
// `--tree-preset NAME --tree-years N`; picking another tree regrows and its link regrows the same
// ivy in a fresh page; a bad tree age is one line beside its field and the page recovers; a
// 1 M-triangle glTF dropped on the page shows its read, BVH and step progress and Cancel ends it
// at once, back to the tree (Cancel stays put while the progress text changes); Embed gives the <niwa-ivy> and iframe snippets of the hash; a 100-year
// tree stops at the page budget with the tree's line as a notice (issue 16).
// Screenshots: build/artifacts/ivy-tree-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';
import { buildGlb } from '../../web/mesh/mesh_import.js';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const nativeIvy = (args) => withoutMs(JSON.parse(execFileSync(NATIVE, ['ivy', 'grow', ...args, '--stats'], { encoding: 'utf8' }).trim()));

const waitIvy = (page, serialAbove) => waitStudyRun(page, 'ivySerial', serialAbove);

function same(name, web, native) {
  const a = JSON.stringify(withoutMs(JSON.parse(web))), b = JSON.stringify(native);
  check(name, a === b, a === b ? `${native.internodes} internodes, ${native.leaves} leaves, ${native.tri_count} bark triangles`
    : `web ${a.slice(0, 240)} | native ${b.slice(0, 240)}`);
}

// A flat wall of n x n quads (2 n² triangles), `size` units, in the xy plane facing +z.
function wallGlb(n, size) {
  const positions = new Float32Array((n + 1) * (n + 1) * 3);
  for (let j = 0; j <= n; ++j) {
    for (let i = 0; i <= n; ++i) {
      const k = 3 * (j * (n + 1) + i);
      positions[k] = (i / n - 0.5) * size;
      positions[k + 1] = (j / n) * size;
    }
  }
  const indices = new Uint32Array(n * n * 6);
  for (let j = 0, t = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i, t += 6) {
      const a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      indices.set([a, b, d, a, d, c], t);
    }
  }
  const bin = new Uint8Array(positions.byteLength + indices.byteLength);
  bin.set(new Uint8Array(positions.buffer), 0);
  bin.set(new Uint8Array(indices.buffer), positions.byteLength);
  return buildGlb({
    asset: { version: '2.0' }, scenes: [{ nodes: [0] }], scene: 0, nodes: [{ mesh: 0 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    buffers: [{ byteLength: bin.length }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: positions.byteLength },
      { buffer: 0, byteOffset: positions.byteLength, byteLength: indices.byteLength }],
    accessors: [{ bufferView: 0, componentType: 5126, count: positions.length / 3, type: 'VEC3', min: [-size / 2, 0, 0], max: [size / 2, size, 0] },
      { bufferView: 1, componentType: 5125, count: indices.length, type: 'SCALAR' }],
  }, bin);
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 760 } });
  const page = await context.newPage();
  watchPage(page, problems);

  // 1. The hash's tree: ivy up sakura at 6 years, as the CLI grows it.
  const hash0 = 'preset=metric&seed=1&steps=50&scene=tree&tree=sakura&tree_years=6';
  await page.goto(`${server.url}ivy.html#${hash0}`, { waitUntil: 'load' });
  let data = await waitIvy(page, 0);
  check('a tree hash grows ivy on the tree', data.status === 'ready' && data.supportName === 'tree:sakura' && Number(data.supportTriangles) > 1000 && Number(data.internodes) > 10,
    `${data.status} ${data.supportName} ${data.supportTriangles} tris, ${data.internodes} internodes ${data.error || ''}`);
  check('the page keeps the tree in its hash', data.hash.includes('scene=tree&tree=sakura&tree_years=6'), data.hash);
  same('tree page --stats == niwa ivy grow --url HASH', data.stats, nativeIvy(['--url', data.hash]));
  same('tree page --stats == niwa ivy grow --tree-preset sakura --tree-years 6', data.stats, nativeIvy(['--tree-preset', 'sakura', '--tree-years', '6']));
  const shown = await page.evaluate(() => ({ tree: document.getElementById('tree').value, years: document.getElementById('tree-years').value,
    hidden: document.getElementById('tree').hidden, scene: document.getElementById('scene').value }));
  check('the tree fields show the hash', shown.scene === 'tree' && shown.tree === 'sakura' && shown.years === '6' && !shown.hidden, JSON.stringify(shown));
  await saveCanvasPng(page, 'ivy-tree-sakura.png');

  // 2. Another tree from the panel regrows; its link regrows the same ivy in a fresh page.
  await page.selectOption('#tree', 'maple');
  data = await waitIvy(page, Number(data.ivySerial));
  check('picking maple regrows on maple', data.supportName === 'tree:maple' && data.hash.includes('tree=maple'), `${data.supportName} ${data.hash}`);
  const mapleStats = data.stats, mapleHash = data.hash;
  same('maple --stats == CLI --url', mapleStats, nativeIvy(['--url', mapleHash]));
  await saveCanvasPng(page, 'ivy-tree-maple.png');
  const fresh = await context.newPage();
  watchPage(fresh, problems);
  await fresh.goto(`${server.url}ivy.html#${mapleHash}`, { waitUntil: 'load' });
  const again = await waitIvy(fresh, 0);
  check('the link regrows the same ivy', JSON.stringify(withoutMs(JSON.parse(again.stats))) === JSON.stringify(withoutMs(JSON.parse(mapleStats))),
    `${again.internodes} vs ${data.internodes} internodes`);
  await fresh.close();

  // 3. A bad tree age: one line beside the tree fields; a good one recovers.
  await page.fill('#tree-years', '0');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const line = await page.evaluate(() => ({ text: document.getElementById('tree-error').textContent, hidden: document.getElementById('tree-error').hidden }));
  check('tree_years 0 is one line beside the tree', !line.hidden && /^tree_years: .*\[1, 100\]/.test(line.text) && !line.text.includes('\n'), JSON.stringify(line));
  await page.fill('#tree-years', '5');
  data = await waitIvy(page, Number(data.ivySerial));
  check('tree_years 5 recovers', data.status === 'ready' && data.hash.includes('tree_years=5'), `${data.status} ${data.hash}`);
  const treeSerial = Number(data.ivySerial), treeHash = data.hash;

  // 4. A 1 M-triangle glTF: read, BVH and step progress are shown; Cancel ends it at once.
  const big = path.join(ARTIFACTS, 'ivy-tree-wall-1m.glb');
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  fs.writeFileSync(big, wallGlb(708, 1200));
  await page.evaluate(() => {
    window.__texts = [];
    new MutationObserver(() => window.__texts.push(document.getElementById('progress').textContent))
      .observe(document.getElementById('progress'), { childList: true, characterData: true, subtree: true });
    // Where Cancel is drawn, each frame it shows (it sat after the progress text and jumped with
    // it, so a click could land where it had been: the CI failure of stop 26).
    window.__cancelAt = [];
    const look = () => {
      const b = document.getElementById('cancel');
      if (!b.hidden) {
        const r = b.getBoundingClientRect(), at = `${Math.round(r.x)},${Math.round(r.y)}`;
        if (!window.__cancelAt.includes(at)) window.__cancelAt.push(at);
      }
      requestAnimationFrame(look);
    };
    requestAnimationFrame(look);
  });
  let t0 = Date.now();
  await page.setInputFiles('#mesh-file', big);
  data = await waitIvy(page, treeSerial);
  const loadSeconds = (Date.now() - t0) / 1000;
  const texts = (await page.evaluate(() => window.__texts)).filter(Boolean);
  check('the 1 M-triangle glTF grows ivy', data.status === 'ready' && data.supportTriangles === String(2 * 708 * 708) && Number(data.internodes) > 10,
    `${data.supportTriangles} triangles, ${data.internodes} internodes in ${loadSeconds.toFixed(1)} s (worker read + BVH ${data.supportLoadMs} ms)`);
  check('progress names the read, the BVH and the growth steps', texts.some((t) => t.startsWith('reading the mesh')) &&
    texts.some((t) => t.startsWith('building the BVH of 1,002,528 triangles')) && texts.some((t) => /^growing: step \d+ of 50$/.test(t)),
  [...new Set(texts)].slice(0, 8).join(' | '));
  const cancelAt = await page.evaluate(() => window.__cancelAt);
  check('Cancel stays put while the progress line changes', cancelAt.length === 1, `at ${cancelAt.join(' ')} over ${new Set(texts).size} progress texts`);
  check('progress stages in order', /mesh,read,bvh.*grow/.test(data.progressStages), data.progressStages);
  await saveCanvasPng(page, 'ivy-tree-wall-1m.png');

  // Cancel while it reads the mesh again: the worker restarts and the last built-in state (the
  // tree) grows again; the page keeps working.
  await page.setInputFiles('#mesh-file', { name: 'again.glb', mimeType: 'model/gltf-binary', buffer: fs.readFileSync(big) });
  await page.waitForSelector('#cancel', { state: 'visible', timeout: TIMEOUT });
  const serial = Number(data.ivySerial);
  t0 = Date.now();
  await page.click('#cancel');
  data = await waitIvy(page, serial);
  const back = (Date.now() - t0) / 1000;
  check('Cancel ends the load and regrows the last built-in state', data.status === 'ready' && data.supportName === 'tree:maple' && data.hash === treeHash && Number(data.cancels) === 1,
    `${data.supportName} ${data.hash} (cancels ${data.cancels}) in ${back.toFixed(1)} s`);
  check('Cancel hides itself', await page.isHidden('#cancel'), '');

  // 5. Embed: the <niwa-ivy> and iframe snippets carry the hash.
  await page.click('#embed');
  const snippet = await page.evaluate(() => ({ element: document.getElementById('embed-element').value, iframe: document.getElementById('embed-iframe').value }));
  const escaped = treeHash.replace(/&/g, '&amp;');
  check('Embed gives <niwa-ivy state=HASH>', snippet.element.includes('niwa-ivy.js') && snippet.element.includes(`<niwa-ivy state="${escaped}"`), snippet.element);
  check('Embed gives the iframe form', snippet.iframe.includes(`embed.html?study=ivy#${escaped}`), snippet.iframe);
  await page.keyboard.press('Escape');

  // 6. Issue 16: a 100-year tree grows within the page budget (the tree page's limits): it stops in
  // a year with the tree's line as a notice, and the ivy grows on the bark that fits.
  const century = await context.newPage();
  watchPage(century, problems);
  const t100 = Date.now();
  await century.goto(`${server.url}ivy.html#preset=metric&seed=1&steps=5&scene=tree&tree=sakura&tree_years=100`, { waitUntil: 'load' });
  data = await waitIvy(century, 0);
  const bigStats = data.stats ? JSON.parse(data.stats) : {};
  const bigNotice = await century.textContent('#notice');
  check('a 100-year tree stops at the page budget with the line', data.status === 'ready' &&
    /^page memory budget: stopped in year \d+ of 100: .*lower tree_years/.test(bigStats.tree_truncated_by || '') &&
    bigNotice.includes(bigStats.tree_truncated_by),
    `${data.status} in ${((Date.now() - t100) / 1000).toFixed(1)} s: ${bigStats.tree_truncated_by} (${bigStats.tri_count} bark triangles); notice '${bigNotice.slice(0, 200)}'`);
  await century.close();

  check('no console errors or page errors', problems.length === 0, problems.join(' | '));
});
