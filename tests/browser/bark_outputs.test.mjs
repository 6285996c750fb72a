// Browser test of the bark page's outputs and 4-layer views (issue 30 items 2 and 6): node
// tests/browser/bark_outputs.test.mjs (exit 0 = pass). For a linked 2-layer and a linked 4-layer
// state: the Trunk .glb download is the bytes of native `niwa bark grow --url HASH --out trunk.glb`
// (gltf-validator clean); the plate-size chart draws the mean width and height beside the
// broken-fraction chart, its last sample the stats' regions; the Broken springs toggle draws the
// surface's broken springs (as many as the stats count) in red over the tile and takes them away;
// the Layers view colours the tile by the layer showing (the 4-layer run shows more than one) and
// the Peel view by the peel state; the lit trunk segment is drawn. Screenshots:
// build/artifacts/bark-out-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import {
  ARTIFACTS, NATIVE, ROOT, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';
import { openThreePage, saveSideBySide } from './three_page.mjs';

const require = createRequire(path.join(ROOT, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;

const waitBark = (page, serialAbove) => waitStudyRun(page, 'barkSerial', serialAbove);

// Counts of canvas pixels within `tolerance` of each named colour (8-bit sRGB), in the canvas's
// left half (the tile's; the lit trunk stands to the right).
async function colourCounts(page, colours, tolerance = 14) {
  return page.evaluate(([named, tol]) => {
    const image = window.__niwaCanvasImage('#view');
    const d = image.data;
    const out = Object.fromEntries(Object.keys(named).map((k) => [k, 0]));
    for (let i = 0; i < d.length; i += 4) {
      if ((i / 4) % image.width >= image.width / 2) continue;
      for (const [k, [r, g, b]] of Object.entries(named)) {
        if (Math.abs(d[i] - r) <= tol && Math.abs(d[i + 1] - g) <= tol && Math.abs(d[i + 2] - b) <= tol) {
          ++out[k];
          break;
        }
      }
    }
    return out;
  }, [colours, tolerance]);
}

const to8 = (c) => c.map((x) => Math.round(x * 255));
const LAYERS = { S: to8([0.40, 0.34, 0.28]), M1: to8([0.55, 0.30, 0.18]), M2: to8([0.74, 0.60, 0.42]), I: to8([0.16, 0.09, 0.06]) };
const PEEL = { bonded: to8([0.46, 0.41, 0.35]), peeling: to8([0.93, 0.55, 0.12]), peeled: to8([0.80, 0.62, 0.56]) };
const RED = { red: to8([0.86, 0.08, 0.06]) };

// Counts colours until `done(counts)` holds (a big frame is drawn over several), at most ~10 s.
async function countsWhen(page, colours, done) {
  let counts = null;
  for (let k = 0; k < 20; ++k) {
    counts = await colourCounts(page, colours);
    if (done(counts)) break;
    await page.waitForTimeout(500);
  }
  return counts;
}

async function setView(page, view) {
  await page.selectOption('#tile-view', view);
  await page.waitForFunction((v) => document.documentElement.dataset.tileShows === v, view, { timeout: TIMEOUT });
  await page.waitForTimeout(400);
}

async function checkGlb(page, name, hash) {
  const [d] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click('#download-glb')]);
  const file = path.join(ARTIFACTS, `bark-out-${name}.glb`);
  await d.saveAs(file);
  const nativeFile = path.join(ARTIFACTS, `bark-out-${name}-native.glb`);
  let nativeBytes = Buffer.alloc(0);
  try {
    execFileSync(NATIVE, ['bark', 'grow', '--url', hash, '--out', nativeFile]);
    nativeBytes = fs.readFileSync(nativeFile);
  } catch (e) {
    check(`${name}: native bark grow --out trunk.glb runs`, false, e.message.split('\n')[0]);
  }
  const bytes = fs.readFileSync(file);
  check(`${name}: Trunk .glb downloads the bytes of \`niwa bark grow --url ${hash} --out trunk.glb\``,
    d.suggestedFilename().endsWith('_trunk.glb') && bytes.length > 10000 && bytes.equals(nativeBytes),
    `${d.suggestedFilename()}: ${bytes.length} bytes, native ${nativeBytes.length}`);
  const report = await validator.validateBytes(new Uint8Array(bytes), { maxIssues: 20 });
  check(`${name}: the page's .glb is gltf-validator clean`, report.issues.numErrors === 0 && report.issues.numWarnings === 0,
    JSON.stringify(report.issues.messages.slice(0, 2)));
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1280, height: 800 }, acceptDownloads: true });
  const page = await context.newPage();
  watchPage(page, problems);

  // 1. A 2-layer run (64 × 32: no preview).
  await page.goto(`${server.url}bark.html#species=pine&model=2layer&seed=2&N_R=64&N_H=32`, { waitUntil: 'load' });
  let data = await waitBark(page, 0);
  check('2layer: grown and drawn', data.status === 'ready' && data.model === '2layer', `${data.status} ${data.error || ''}`);
  const stats = JSON.parse(data.stats);
  await checkGlb(page, '2layer', data.hash);

  // three.js' own GLTFLoader draws the downloaded trunk, textured and plain.
  const three = await openThreePage(browser, ARTIFACTS);
  const [textured] = await three.evaluate(() => window.renderGlbs(['bark-out-2layer.glb']));
  const [plain] = await three.evaluate(() => window.renderGlbs(['bark-out-2layer.glb'], { plain: true }));
  await saveSideBySide(three, [textured.png, plain.png], path.join(ARTIFACTS, 'bark-out-three.png'));
  await three.close();
  const cover = textured.mask.reduce((a, b) => a + b, 0) / textured.mask.length;
  check(`three.js draws the .glb's trunk (${(100 * cover).toFixed(1)} % of its view), textured unlike its plain twin`,
    cover > 0.05 && textured.png !== plain.png, `${(100 * cover).toFixed(1)} %`);

  // The plate-size chart beside the broken-fraction chart; at the end its sample is the stats'.
  const charts = await page.evaluate(() => [document.querySelectorAll('#chart path').length, document.querySelectorAll('#plate-chart path').length]);
  const [plates, w, h] = (data.plateShown || '').split(':').map(Number);
  check('the plate-size chart has its two lines beside the broken-fraction chart\'s two',
    charts[0] === 2 && charts[1] === 2, JSON.stringify(charts));
  check(`the plate chart's last sample is the stats' regions (${plates} plates, ${w?.toFixed(2)} × ${h?.toFixed(2)} cm)`,
    plates === stats.regions.count && Math.abs(w - stats.regions.mean_w) < 1e-9 && Math.abs(h - stats.regions.mean_h) < 1e-9,
    `${data.plateShown} vs ${JSON.stringify(stats.regions)}`);

  // The lit tile and trunk segment.
  await saveCanvasPng(page, 'bark-out-lit.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'bark-out-page.png') });

  // Broken springs: as many segments as the stats' broken springs, red over the tile, toggled.
  const brokenAll = stats.broken.axial + stats.broken.diagonal;
  check(`the broken springs' segments are the stats' ${brokenAll}`, Number(data.brokenSprings) === brokenAll, data.brokenSprings);
  await setView(page, 'plates');
  const off = await colourCounts(page, RED);
  await page.check('#show-broken');
  await page.waitForFunction(() => document.documentElement.dataset.showBroken === 'true', null, { timeout: TIMEOUT });
  const on = await countsWhen(page, RED, (c) => c.red > 500);
  await saveCanvasPng(page, 'bark-out-broken.png');
  await page.uncheck('#show-broken');
  const offAgain = await countsWhen(page, RED, (c) => c.red < 20);
  check('the Broken springs toggle draws red segments over the tile and takes them away',
    off.red < 20 && on.red > 500 && offAgain.red < 20, `red pixels: off ${off.red}, on ${on.red}, off again ${offAgain.red}`);

  // 2-layer Layers view: S and the inner layer only.
  await setView(page, 'layers');
  const twoLayers = await colourCounts(page, LAYERS);
  await saveCanvasPng(page, 'bark-out-2layer-layers.png');
  check('2layer Layers view: S plates and the inner layer in the cracks, no M1 or M2',
    twoLayers.S > 5000 && twoLayers.I > 500 && twoLayers.M1 < 50 && twoLayers.M2 < 50, JSON.stringify(twoLayers));

  // 2. A 4-layer run: 2 cycles of a short period, thin cork, a tougher bond (kappa_h 0.1: a third of S
  // peels, all four layers show).
  const serial = Number(data.barkSerial);
  const fourHash = 'species=pine&model=4layer&seed=2&N_R=64&N_H=32&cycles=2&T=0.002&cork=0.1&kappa_h=0.1';  // partly peeled
  await page.goto('about:blank');  // a fresh page (a hash change alone would keep the last dataset)
  await page.goto(`${server.url}bark.html#${fourHash}`, { waitUntil: 'load' });
  data = await waitBark(page, 0);
  check('4layer: grown and drawn', data.status === 'ready' && data.model === '4layer', `${data.status} ${data.hash} ${data.error || ''} (serial before ${serial})`);
  const four = JSON.parse(data.stats);
  await checkGlb(page, '4layer', data.hash);
  await setView(page, 'layers');
  const layers = await colourCounts(page, LAYERS);
  await saveCanvasPng(page, 'bark-out-4layer-layers.png');
  const shown = Object.entries(layers).filter(([, n]) => n > 300).map(([k]) => k);
  check(`4layer Layers view: more than one layer shows (${shown.join(', ')}), as the stats' exposed shares say`,
    shown.length >= 2 && ['S', 'M1', 'M2', 'I'].every((k) => (four.exposed[k] > 0.02) === (layers[k] > 100)),
    `${JSON.stringify(layers)} vs exposed ${JSON.stringify(four.exposed)}`);
  await setView(page, 'peel');
  const peel = await colourCounts(page, PEEL);
  await saveCanvasPng(page, 'bark-out-4layer-peel.png');
  check('4layer Peel view: peeled (or peeling) triangles where S peeled, bonded ones elsewhere',
    (four.peeled_fraction > 0.05 ? peel.peeled > 300 : peel.peeled < 300) && (four.peel.bonds_broken > 0) === (peel.peeled + peel.peeling > 0)
      && peel.bonded + peel.peeling + peel.peeled > 5000,
    `${JSON.stringify(peel)}, peeled fraction ${four.peeled_fraction}, bonds broken ${four.peel.bonds_broken}`);
  await page.check('#show-broken');
  const fourRed = await countsWhen(page, RED, (c) => c.red > 500);
  await saveCanvasPng(page, 'bark-out-4layer-broken.png');
  check(`4layer: the Broken springs toggle draws S's ${Number(data.brokenSprings)} broken springs (and its peeled ones) over the peel view`,
    fourRed.red > 500 && Number(data.brokenSprings) >= four.broken.axial + four.broken.diagonal, `red pixels ${fourRed.red}`);
  await page.uncheck('#show-broken');
  await setView(page, 'lit');
  await saveCanvasPng(page, 'bark-out-4layer-lit.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'bark-out-4layer-page.png') });
  const charts4 = await page.evaluate(() => document.querySelectorAll('#plate-chart path').length);
  check('4layer: the plate-size chart is drawn', charts4 === 2, String(charts4));

  check('no uncaught error or console error', problems.length === 0, problems.slice(0, 3).join(' | ').slice(0, 400));
  await context.close();
});
