// Browser test of the terrain page (public/terrain.html): node tests/browser/terrain.test.mjs
// (exit 0 = pass). The page opens with a mountain grown from a built-in seed and its stats equal
// the native CLI's `niwa terrain grow --url HASH --stats` (every field but the ms* timings) for the
// page's own hash; so do a picked built-in (jacksboro) and a contour drawn with the mouse on the
// plan (the hash gains contour=, and the CLI regrows it identically); a drawing that crosses itself
// and one too small get a notice beside the plan and the page recovers; a bad value is one line
// beside its field and the page recovers; the downloaded .glb and heightmap equal the CLI's bytes
// for the same hash; the contour toggle hides the lines; an erosion row re-erodes the kept surface
// without a regrow (and a view row does not re-erode). Screenshots: build/artifacts/terrain-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, snapshotCanvas, snapshotDifference, waitStudyRun, watchPage,
} from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const sorted = (o) => JSON.stringify(Object.fromEntries(Object.entries(o).sort(([a], [b]) => (a < b ? -1 : 1))));

function nativeTerrain(args) {
  const out = execFileSync(NATIVE, ['terrain', 'grow', ...args], { encoding: 'utf8' });
  return out.trim() ? JSON.parse(out.trim().split('\n').pop()) : null;
}

// Waits for a mountain newer than serialAbove drawn on screen (or an error); returns the dataset.
const waitTerrain = (page, serialAbove) => waitStudyRun(page, 'terrainSerial', serialAbove);

function compareWithNative(name, data) {
  let native = null;
  try {
    native = nativeTerrain(['--url', data.hash, '--stats']);
  } catch (e) {
    check(`${name}: native CLI runs`, false, `${NATIVE} terrain grow --url ${data.hash.slice(0, 80)}: ${e.message.split('\n')[0]}`);
    return;
  }
  const web = withoutMs(JSON.parse(data.stats));
  const same = sorted(web) === sorted(withoutMs(native));
  check(`${name}: page stats == native CLI --url HASH --stats`, same,
    same ? `${web.levels} levels, ${web.contours} contours, ${web.peaks} peaks, relief ${web.relief.toFixed(2)} m, HI ${web.hypsometric_integral.toFixed(4)}`
      : `web ${sorted(web).slice(0, 400)} native ${sorted(withoutMs(native)).slice(0, 400)}`);
}

// Shares of the 3-D canvas: background, contour-line brown, and the luminance spread of the
// surface pixels (a shaded surface is not one flat colour).
async function looks(page) {
  return page.evaluate(() => {
    const d = window.__niwaCanvasImage('#view').data;
    let background = 0, line = 0, surface = 0, sum = 0, sum2 = 0;
    for (let i = 0; i < d.length; i += 4) {
      const r = d[i], g = d[i + 1], b = d[i + 2];
      if (Math.abs(r - 219) < 6 && Math.abs(g - 230) < 6 && Math.abs(b - 240) < 6) { ++background; continue; }
      // The contour colours of shaders/terrain/contour.frag, (84, 51, 26) and (46, 23, 8).
      if ((Math.abs(r - 84) < 10 && Math.abs(g - 51) < 10 && Math.abs(b - 26) < 10) ||
          (Math.abs(r - 46) < 10 && Math.abs(g - 23) < 10 && Math.abs(b - 8) < 10)) { ++line; continue; }
      const y = 0.299 * r + 0.587 * g + 0.114 * b;
      ++surface;
      sum += y;
      sum2 += y * y;
    }
    const n = d.length / 4, mean = surface ? sum / surface : 0;
    return { background: background / n, line: line / n, surface: surface / n, spread: surface ? Math.sqrt(Math.max(0, sum2 / surface - mean * mean)) : 0 };
  });
}

// Drags the mouse along points (fractions of the plan canvas) with the left button down.
async function drawOnPlan(page, fractions) {
  await page.locator('#plan').scrollIntoViewIfNeeded();  // the panel scrolls (downloads, fields)
  const box = await page.locator('#plan').boundingBox();
  const at = ([u, v]) => [box.x + u * box.width, box.y + v * box.height];
  await page.mouse.move(...at(fractions[0]));
  await page.mouse.down();
  for (const f of fractions.slice(1)) await page.mouse.move(...at(f));
  await page.mouse.up();
}

const loop = (n, radius) => Array.from({ length: n + 1 }, (_, k) => {
  const phi = (2 * Math.PI * k) / n;
  const r = radius(phi);
  return [0.5 + r * Math.cos(phi), 0.5 - r * Math.sin(phi)];
});

// The indices of the .glb's "terrain" mesh (its first primitive), as numbers.
function glbSurfaceIndices(bytes) {
  const jsonLength = bytes.readUInt32LE(12);
  const gltf = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  const binStart = 20 + jsonLength + 8;
  const mesh = gltf.meshes.find((m) => m.name === 'terrain');
  const accessor = gltf.accessors[mesh.primitives[0].indices];
  const view = gltf.bufferViews[accessor.bufferView];
  const offset = binStart + (view.byteOffset || 0) + (accessor.byteOffset || 0);
  const out = [];
  for (let k = 0; k < accessor.count; ++k) {
    out.push(accessor.componentType === 5125 ? bytes.readUInt32LE(offset + 4 * k) : bytes.readUInt16LE(offset + 2 * k));
  }
  return out;
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 }, acceptDownloads: true });
  const page = await context.newPage();
  watchPage(page, problems);
  page.on('request', (r) => {
    if (!r.url().startsWith(server.url) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) problems.push(`external request: ${r.url()}`);
  });

  // 1. Opens with a mountain grown from a built-in seed: a result without input.
  await page.goto(`${server.url}terrain.html`, { waitUntil: 'load' });
  let data = await waitTerrain(page, 0);
  check('opens with a mountain grown', data.status === 'ready' && Number(data.levels) > 5, `status ${data.status}, ${data.levels} levels, ${data.error || ''}`);
  const hash0 = await page.evaluate(() => location.hash);
  check('the hash is the terrain state', hash0 === '#preset=improved&builtin=lobes7', hash0);
  compareWithNative('lobes7 improved', data);
  const nav = await page.locator('#studies a[aria-current="page"]').textContent().catch(() => '');
  check('the studies nav marks Terrain', nav === 'Terrain', nav);
  const panelKeys = await page.evaluate(() => [...document.querySelectorAll('#params [data-key]')].map((e) => e.dataset.key));
  check('the panel is the terrain table', panelKeys.includes('d') && panelKeys.includes('theta_max') && panelKeys.includes('f0') && panelKeys.length >= 20, panelKeys.join(','));
  const look = await looks(page);
  check('the mountain is drawn, shaded, with contour lines', look.surface > 0.2 && look.spread > 12 && look.line > 0.002,
    `surface ${(look.surface * 100).toFixed(1)}%, luminance spread ${look.spread.toFixed(1)}, line pixels ${(look.line * 100).toFixed(2)}%, lines ${data.drawnLines}`);
  await saveCanvasPng(page, 'terrain-lobes7.png');
  await saveCanvasPng(page, 'terrain-lobes7-plan.png', '#plan');

  // 2. The contour toggle hides the lines (nothing regrows).
  const grows = Number(data.growRequests);
  await snapshotCanvas(page, 'lines');
  await page.click('#show-contours');
  await page.waitForFunction(() => document.documentElement.dataset.drawnLines === '0', null, { timeout: TIMEOUT });
  await snapshotCanvas(page, 'nolines');
  const noLines = await looks(page);
  const changed = await snapshotDifference(page, 'lines', 'nolines', 30);
  check('Contours off hides the lines', noLines.line < look.line / 5 && changed > 0.003,
    `line pixels ${(noLines.line * 100).toFixed(3)}% (with ${(look.line * 100).toFixed(3)}%), ${(changed * 100).toFixed(2)}% of pixels changed`);
  await saveCanvasPng(page, 'terrain-lobes7-nolines.png');
  await page.click('#show-tint');
  await page.waitForTimeout(500);
  await saveCanvasPng(page, 'terrain-lobes7-grey.png');
  await page.click('#show-tint');
  await page.click('#show-contours');
  await page.waitForFunction(() => document.documentElement.dataset.drawnLines !== '0', null, { timeout: TIMEOUT });
  data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  check('toggles do not regrow', Number(data.growRequests) === grows, `grow requests ${grows} -> ${data.growRequests}`);

  // 2b. The level scrubber shows the mountain contour by contour without regrowing; Play runs it.
  const fullLines = Number(data.drawnLines);
  await page.evaluate(() => {
    const r = document.getElementById('level');
    r.value = '3';
    r.dispatchEvent(new Event('input'));
  });
  await page.waitForFunction(() => document.documentElement.dataset.drawnLevel === '3', null, { timeout: TIMEOUT });
  data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  await snapshotCanvas(page, 'level3');
  const levelChanged = await snapshotDifference(page, 'lines', 'level3', 30);
  check('level 3 draws fewer contours and a cut surface', Number(data.drawnLines) > 0 && Number(data.drawnLines) < fullLines && levelChanged > 0.01,
    `${data.drawnLines} of ${fullLines} line segments, ${(levelChanged * 100).toFixed(2)}% of pixels changed`);
  await saveCanvasPng(page, 'terrain-lobes7-level3.png');
  await saveCanvasPng(page, 'terrain-lobes7-level3-plan.png', '#plan');
  await page.click('#play');
  await page.waitForFunction(() => document.documentElement.dataset.drawnLevel === 'all' && document.getElementById('play').textContent === 'Play', null, { timeout: TIMEOUT });
  data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
  check('Play runs to the top level and draws everything', Number(data.drawnLines) === fullLines && Number(data.growRequests) === grows,
    `${data.drawnLines} line segments, grow requests ${data.growRequests}`);

  // 3. The real contour: jacksboro, picked from the seed picker.
  let serial = Number(data.terrainSerial);
  await page.selectOption('#builtin', 'jacksboro');
  data = await waitTerrain(page, serial);
  check('jacksboro grows', data.status === 'ready' && (await page.evaluate(() => location.hash)).includes('builtin=jacksboro'), `${data.status} ${data.error || ''} ${data.hash}`);
  compareWithNative('jacksboro improved', data);
  await saveCanvasPng(page, 'terrain-jacksboro.png');
  await saveCanvasPng(page, 'terrain-jacksboro-plan.png', '#plan');

  // 4. A contour drawn with the mouse (a five-lobed loop) regrows; the hash carries it.
  serial = Number(data.terrainSerial);
  await drawOnPlan(page, loop(90, (phi) => 0.3 * (1 + 0.22 * Math.cos(5 * phi))));
  data = await waitTerrain(page, serial);
  const drawnHash = await page.evaluate(() => location.hash);
  check('a drawn contour regrows the mountain', data.status === 'ready' && /^#(preset=improved&)?contour=[-0-9.]+,[-0-9.]+;/.test(drawnHash) && Number(data.levels) > 3,
    `${data.status} ${data.error || ''}; ${data.levels} levels; ${drawnHash.slice(0, 100)}…`);
  if (data.status === 'ready') compareWithNative('drawn contour', data);
  await saveCanvasPng(page, 'terrain-drawn.png');
  await saveCanvasPng(page, 'terrain-drawn-plan.png', '#plan');

  // 4b. A pen and a finger draw as the mouse does (pointer events of pointerType 'pen' and 'touch',
  // sent through the DevTools protocol as real input, not synthetic DOM events).
  {
    await page.evaluate(() => {
      window.__pointerTypes = [];
      document.getElementById('plan').addEventListener('pointerdown', (e) => window.__pointerTypes.push(e.pointerType), true);
    });
    const cdp = await context.newCDPSession(page);
    await page.locator('#plan').scrollIntoViewIfNeeded();
    const box = await page.locator('#plan').boundingBox();
    const at = ([u, v]) => ({ x: box.x + u * box.width, y: box.y + v * box.height });
    // Pen: mouse events with pointerType 'pen'.
    serial = Number((await page.evaluate(() => ({ ...document.documentElement.dataset }))).terrainSerial);
    const penStroke = loop(70, (phi) => 0.28 * (1 + 0.18 * Math.cos(4 * phi)));
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...at(penStroke[0]), button: 'left', buttons: 1, clickCount: 1, pointerType: 'pen' });
    for (const f of penStroke.slice(1)) await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...at(f), button: 'left', buttons: 1, pointerType: 'pen' });
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...at(penStroke[penStroke.length - 1]), button: 'left', buttons: 0, clickCount: 1, pointerType: 'pen' });
    data = await waitTerrain(page, serial);
    const penHash = await page.evaluate(() => location.hash);
    check('a pen drawing regrows the mountain', data.status === 'ready' && /contour=/.test(penHash) && penHash !== drawnHash,
      `${data.status} ${data.error || ''}; pointer types ${(await page.evaluate(() => window.__pointerTypes)).join(',')}`);
    // Finger: touch events (touch emulation on, as on a phone).
    await cdp.send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 1 });
    serial = Number(data.terrainSerial);
    const fingerStroke = loop(60, (phi) => 0.3 * (1 + 0.15 * Math.cos(6 * phi)));
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [at(fingerStroke[0])] });
    for (const f of fingerStroke.slice(1)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [at(f)] });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    data = await waitTerrain(page, serial);
    const fingerHash = await page.evaluate(() => location.hash);
    const types = await page.evaluate(() => window.__pointerTypes);
    check('a finger drawing regrows the mountain', data.status === 'ready' && /contour=/.test(fingerHash) && fingerHash !== penHash,
      `${data.status} ${data.error || ''}`);
    check('those strokes arrived as pen and touch pointers', types.includes('pen') && types.includes('touch'), types.join(','));
    if (data.status === 'ready') compareWithNative('finger drawing', data);
    await saveCanvasPng(page, 'terrain-finger-plan.png', '#plan');
    await cdp.send('Emulation.setTouchEmulationEnabled', { enabled: false });
    await cdp.detach();
  }

  // 4c. An imported contour file ({"points", "elevation"}, as `niwa terrain grow --contour` reads
  // it): the seed and h0 come from the file, the link carries it, the CLI regrows it; a broken
  // file and a file of another kind are lines beside the plan and grow nothing.
  {
    serial = Number(data.terrainSerial);
    const ring = Array.from({ length: 160 }, (_, k) => {
      const phi = (2 * Math.PI * k) / 160, r = 260 * (1 + 0.2 * Math.cos(9 * phi));
      return [Number((1000 + r * Math.cos(phi)).toFixed(3)), Number((-500 + r * Math.sin(phi)).toFixed(3))];
    });
    await page.setInputFiles('#contour-file', { name: 'seed.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify({ points: ring, elevation: 300 })) });
    data = await waitTerrain(page, serial);
    const importedHash = await page.evaluate(() => location.hash);
    check('an imported contour file regrows the mountain from its points and elevation',
      data.status === 'ready' && importedHash.includes(`contour=${ring[0][0]},${ring[0][1]};`) && /(^|&|#)h0=300(&|$)/.test(importedHash) && Number(data.levels) >= 2,
      `${data.status} ${data.error || ''}; ${data.levels} levels; ${importedHash.replace(/contour=[^&]*/, 'contour=…')}`);
    if (data.status === 'ready') compareWithNative('imported contour file', data);
    await saveCanvasPng(page, 'terrain-imported-plan.png', '#plan');
    const before = Number(await page.evaluate(() => document.documentElement.dataset.growRequests));
    await page.setInputFiles('#contour-file', { name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from('{"points": [[0, 0], [1, 0], "x"]}') });
    await page.waitForFunction(() => !document.getElementById('contour-error').hidden, null, { timeout: TIMEOUT });
    const broken = await page.textContent('#contour-error');
    await page.setInputFiles('#contour-file', { name: 'notes.txt', mimeType: 'text/plain', buffer: Buffer.from('hello') });
    const other = await page.textContent('#contour-error');
    const after = Number(await page.evaluate(() => document.documentElement.dataset.growRequests));
    check('a broken contour file: the core\'s line beside the plan, nothing grows', /^contour: /.test(broken) && after === before, `'${broken}', grow requests ${before} -> ${after}`);
    check('a file of another kind is refused by name', /^contour: notes\.txt: not a contour file; must end in \.json, \.geojson/.test(other), `'${other}'`);
  }

  // 5. Downloads equal the CLI's bytes for the same hash.
  const cliGlb = path.join(ARTIFACTS, 'terrain-cli.glb');
  const cliPng = path.join(ARTIFACTS, 'terrain-cli-heightmap.png');
  nativeTerrain(['--url', data.hash, '--out', cliGlb, '--heightmap', cliPng]);
  const [glbDownload] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click('#download-glb')]);
  const pageGlb = path.join(ARTIFACTS, 'terrain-page.glb');
  await glbDownload.saveAs(pageGlb);
  const a = fs.readFileSync(pageGlb), b = fs.readFileSync(cliGlb);
  check('the page .glb equals the CLI --out bytes', a.equals(b), `${glbDownload.suggestedFilename()} ${a.length} bytes, CLI ${b.length} bytes`);
  {
    // The page draws triangles it builds itself (web/terrain/grid_indices.js): the .glb's.
    const { gridIndices } = await import('../../web/terrain/grid_indices.js');
    const bounds = await page.evaluate(() => JSON.parse(document.documentElement.dataset.gridSize || '{}'));
    const glb = glbSurfaceIndices(b);
    const mine = new Uint32Array(gridIndices(bounds.width, bounds.height));
    check('the page\'s grid triangles are the .glb surface\'s', glb.length > 0 && glb.length === mine.length && glb.every((v, i) => v === mine[i]),
      `${bounds.width} x ${bounds.height} grid, ${mine.length} indices, .glb ${glb.length}`);
  }
  const downloads = [];
  page.on('download', (d) => downloads.push(d));
  await page.click('#download-heightmap');
  await page.waitForFunction(() => /^sidecar:/.test(document.documentElement.dataset.exported || ''), null, { timeout: TIMEOUT });
  await page.waitForTimeout(500);
  const byName = Object.fromEntries(downloads.map((d) => [d.suggestedFilename(), d]));
  let heightmapSame = false, sidecarSame = false;
  if (byName['terrain-heightmap.png'] && byName['terrain-heightmap.json']) {
    const pngPath = path.join(ARTIFACTS, 'terrain-page-heightmap.png'), jsonPath = path.join(ARTIFACTS, 'terrain-page-heightmap.json');
    await byName['terrain-heightmap.png'].saveAs(pngPath);
    await byName['terrain-heightmap.json'].saveAs(jsonPath);
    heightmapSame = fs.readFileSync(pngPath).equals(fs.readFileSync(cliPng));
    sidecarSame = fs.readFileSync(jsonPath).equals(fs.readFileSync(cliPng.replace(/\.png$/, '.json')));
  }
  check('the heightmap .png and its sidecar equal the CLI --heightmap bytes', heightmapSame && sidecarSame, `downloads ${Object.keys(byName).join(', ')}; png ${heightmapSame}, json ${sidecarSame}`);
  const [svgDownload] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click('#download-svg')]);
  const svgPath = path.join(ARTIFACTS, 'terrain-page-contours.svg');
  await svgDownload.saveAs(svgPath);
  const svg = fs.readFileSync(svgPath, 'utf8');
  check('the contours download as SVG', svg.startsWith('<svg') || svg.startsWith('<?xml'), `${svg.length} bytes`);

  // 6. A drawing that crosses itself (a loop with a small extra loop where the stroke overshoots
  // its start): repaired with a notice beside the plan (§4.4 method 2 cuts the small loop); the
  // repaired ring is the state, so the CLI regrows it from the hash.
  serial = Number(data.terrainSerial);
  const overshoot = loop(80, () => 0.3).concat([[0.8, 0.5], [0.82, 0.58], [0.74, 0.6], [0.76, 0.46]]);
  await drawOnPlan(page, overshoot);
  data = await waitTerrain(page, serial);
  const note = await page.textContent('#contour-note');
  check('a self-crossing drawing is repaired with a notice beside the plan', data.status === 'ready' && /^loops:[1-9]/.test(data.contourRepaired || '') && /crossed itself; repaired/.test(note),
    `status ${data.status}, repaired ${data.contourRepaired}, '${note}' ${data.error || ''}`);
  if (data.status === 'ready') compareWithNative('repaired drawing', data);
  await saveCanvasPng(page, 'terrain-repaired-plan.png', '#plan');
  await page.screenshot({ path: path.join(ARTIFACTS, 'terrain-repaired-notice.png') });

  // 6b. A link whose contour cannot seed a mountain (collinear: no area): the line beside the plan,
  // and the page recovers with a built-in.
  {
    const bad = await context.newPage();
    watchPage(bad, problems);
    await bad.goto(`${server.url}terrain.html#contour=0,0;10,0;20,0;30,0`, { waitUntil: 'load' });
    const d = await waitTerrain(bad, 0);
    const line = await bad.evaluate(() => { const e = document.getElementById('contour-error'); return e.hidden ? '' : e.textContent; });
    check('a link with a contour of no area: a notice beside the plan', d.status === 'error' && /^contour: /.test(line), `status ${d.status}: '${line}'`);
    await bad.screenshot({ path: path.join(ARTIFACTS, 'terrain-bad-contour-notice.png') });
    await bad.selectOption('#builtin', 'disk');
    const d2 = await waitTerrain(bad, 0);
    check('that page recovers with the disk', d2.status === 'ready' && d2.hash.includes('builtin=disk'), `${d2.status} ${d2.hash}`);
    await bad.close();
  }

  // 7. A drawing too small (a few pixels): a notice, nothing sent.
  const growsBefore = Number(await page.evaluate(() => document.documentElement.dataset.growRequests));
  await drawOnPlan(page, loop(12, () => 0.01));
  const smallLine = await page.evaluate(() => { const e = document.getElementById('contour-error'); return e.hidden ? '' : e.textContent; });
  const growsAfter = Number(await page.evaluate(() => document.documentElement.dataset.growRequests));
  check('a too-small drawing gets a notice and grows nothing', /^contour: the drawing is too small/.test(smallLine) && growsAfter === growsBefore, `'${smallLine}', grow requests ${growsBefore} -> ${growsAfter}`);

  // 8. The page recovers: a built-in seed grows again.
  await page.selectOption('#builtin', 'dumbbell');
  data = await waitTerrain(page, serial);
  check('the page recovers with a built-in seed', data.status === 'ready' && Number(data.peaks) >= 2, `${data.status}, ${data.peaks} peaks ${data.error || ''}`);
  compareWithNative('dumbbell improved', data);
  await saveCanvasPng(page, 'terrain-dumbbell.png');

  // 9. A bad value: one line beside its field, and the page recovers.
  serial = Number(data.terrainSerial);
  await page.click('#params details:has(#param-d) > summary');  // the Shrinking group opens
  await page.fill('#param-d', '-5');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const beside = await page.evaluate(() => {
    const line = document.getElementById('param-d').closest('.field').querySelector('.field-error');
    return line && !line.hidden ? line.textContent : '';
  });
  const notice = await page.textContent('#notice');
  check('d = -5 is a notice beside d', /^d: .*-5.*\[0\.01, 100000\]/.test(beside) && notice.includes('d:'), `beside: '${beside}', notice: '${notice}'`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'terrain-bad-d.png') });
  await page.fill('#param-d', '25');
  data = await waitTerrain(page, serial);
  check('the page recovers after the bad value', data.status === 'ready' && data.hash.includes('d=25'), `status ${data.status}, ${data.hash}`);
  compareWithNative('dumbbell d=25', data);

  // 10. The link reopens the same mountain (a fresh page from the drawn contour's hash).
  const page2 = await context.newPage();
  watchPage(page2, problems);
  await page2.goto(`${server.url}terrain.html${drawnHash}`, { waitUntil: 'load' });
  const data2 = await waitTerrain(page2, 0);
  check('the drawn contour\'s link regrows it', data2.status === 'ready' && `#${data2.hash}` === drawnHash, `${data2.status} ${data2.error || ''}`);
  await page2.close();

  // 11. A hostile link: each bad field is a printable notice, and a mountain still grows.
  {
    const hostile = await context.newPage();
    watchPage(hostile, problems);
    await hostile.goto(`${server.url}terrain.html#builtin=nope%3Cb%3E&d=abc&zzz=1&preset=improved`, { waitUntil: 'load' });
    const d = await waitTerrain(hostile, 0);
    const text = await hostile.textContent('#notice');
    check('a hostile link: notices for each bad field, and a mountain grows', d.status === 'ready' && text.includes('builtin') && text.includes('zzz') && /(^|\n)d[: ]/.test(text),
      `${d.status}; notice '${text.replace(/\n/g, ' | ')}'`);
    await hostile.close();
  }

  // 11b. Erosion rows (stage mesh, core/terrain/erosion.h): erosion=3 re-erodes the kept surface
  // (no regrow, no new heightfield: the worker's run counts each), the picture changes, and the
  // stats are the CLI's for the new link; another erosion row re-erodes again; tint does not.
  {
    data = await page.evaluate(() => ({ ...document.documentElement.dataset }));
    serial = Number(data.terrainSerial);
    await page.click('#params details:has(#param-erosion) > summary');
    const was = { grows: Number(data.grows), heightfields: Number(data.heightfields), erosions: Number(data.erosions) };
    // The tint checkbox (a view row) flipped as a user clicks it.
    const toggleTint = () => page.evaluate(() => {
      const box = document.getElementById('param-tint');
      box.checked = !box.checked;
      box.dispatchEvent(new Event('change', { bubbles: true }));
    });
    await snapshotCanvas(page, 'uneroded');
    await saveCanvasPng(page, 'terrain-uneroded.png');
    await page.fill('#param-erosion', '3');
    data = await waitTerrain(page, serial);
    serial = Number(data.terrainSerial);
    await page.waitForTimeout(300);
    await snapshotCanvas(page, 'eroded');
    await saveCanvasPng(page, 'terrain-eroded.png');
    const erodedChange = await snapshotDifference(page, 'uneroded', 'eroded', 12);
    const stats = JSON.parse(data.stats || '{}');
    check('erosion=3 re-erodes the kept surface: no regrow, no new heightfield, the picture changes',
      data.status === 'ready' && Number(data.grows) === was.grows && Number(data.heightfields) === was.heightfields &&
      Number(data.erosions) === was.erosions + 1 && erodedChange > 0.01 && stats.erosion?.volume_moved > 0 && /erosion=3/.test(data.hash),
      `grows ${was.grows} -> ${data.grows}, heightfields ${was.heightfields} -> ${data.heightfields}, erosions ${was.erosions} -> ${data.erosions}, ` +
      `${(erodedChange * 100).toFixed(2)}% of pixels changed, moved ${Math.round(stats.erosion?.volume_moved)} m³, worker erosion ${data.msErosion} ms`);
    if (data.status === 'ready') compareWithNative('erosion=3 (re-eroded in the page)', data);
    await page.fill('#param-erosion_talus', '25');
    data = await waitTerrain(page, serial);
    serial = Number(data.terrainSerial);
    check('another erosion row (talus 25) re-erodes again, nothing regrown',
      data.status === 'ready' && Number(data.grows) === was.grows && Number(data.heightfields) === was.heightfields && Number(data.erosions) === was.erosions + 2,
      `grows ${data.grows}, heightfields ${data.heightfields}, erosions ${data.erosions}`);
    if (data.status === 'ready') compareWithNative('erosion_talus=25 (re-eroded in the page)', data);
    await toggleTint();
    data = await waitTerrain(page, serial);
    serial = Number(data.terrainSerial);
    check('a view row (tint) does not re-erode', Number(data.erosions) === was.erosions + 2, `erosions ${data.erosions}`);
    await toggleTint();
    data = await waitTerrain(page, serial);
    serial = Number(data.terrainSerial);
    await page.fill('#param-erosion', '0');
    data = await waitTerrain(page, serial);
    serial = Number(data.terrainSerial);
    check('erosion back to 0: the uneroded surface, nothing regrown', data.status === 'ready' && Number(data.grows) === was.grows &&
      Number(data.heightfields) === was.heightfields && !JSON.parse(data.stats || '{}').erosion, `grows ${data.grows}, heightfields ${data.heightfields}`);
    await page.fill('#param-erosion_talus', '35');
    data = await waitTerrain(page, serial);
    serial = Number(data.terrainSerial);
  }

  // 12. Measured (not a pass/fail: a shared, loaded machine): a drawn contour regrown with a 512²
  // surface, as the worker times it (grow + heightfield + buffers, WASM).
  serial = Number(data.terrainSerial);
  await page.click('#params details:has(#param-res) > summary');
  const before = { grows: Number(data.grows), heightfields: Number(data.heightfields) };
  await page.fill('#param-res', '512');
  data = await waitTerrain(page, serial);
  serial = Number(data.terrainSerial);
  // res is a mesh-stage row: the worker's run re-samples the heightfield from the kept contours
  // (core TerrainRun::Update), and the mountain is still the CLI's for the new link.
  check('an edit of res re-does the heightfield, not the grow',
    Number(data.grows) === before.grows && Number(data.heightfields) === before.heightfields + 1,
    `grows ${before.grows} -> ${data.grows}, heightfields ${before.heightfields} -> ${data.heightfields}`);
  if (data.status === 'ready') compareWithNative('res 512 from the kept contours', data);
  // 12a. The worker's buffers are reused (web/worker/transfer.js TransferPool): the page hands the
  // surface back once uploaded and the contours and summits once a newer mountain replaced them,
  // so a tint edit (the same grid, the same contours) is copied into returned buffers only.
  await page.evaluate(() => {
    const box = document.getElementById('param-tint');
    box.checked = !box.checked;  // the row's own change event, as a click gives
    box.dispatchEvent(new Event('change', { bubbles: true }));
  });
  data = await waitTerrain(page, serial);
  serial = Number(data.terrainSerial);
  check('a tint edit refills the returned surface, contour and summit buffers, none fresh',
    data.status === 'ready' && data.buffersFresh === '0' && Number(data.buffersReused) >= 7,
    `fresh ${data.buffersFresh}, reused ${data.buffersReused}`);
  await drawOnPlan(page, loop(120, (phi) => 0.32 * (1 + 0.2 * Math.cos(3 * phi) + 0.06 * Math.sin(11 * phi))));
  data = await waitTerrain(page, serial);
  console.log(`MEASURE drawn contour, res 512 (${JSON.parse(data.stats || '{}').cells} cells): worker ${data.wallMs} ms (grow ${data.msGrow}, heightfield ${data.msHeightfield}, buffers ${data.msBuffers}; the rest: stats and copies); issue asks <= 100 ms`);
  if (data.status === 'ready') compareWithNative('drawn contour, res 512', data);

  check('no console errors, page errors or external requests', problems.length === 0, problems.join(' | '));
});
