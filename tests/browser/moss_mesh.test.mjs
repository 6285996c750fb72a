// Browser test of the moss page's dropped meshes (public/moss.html, web/moss/moss_page.js): node
// tests/browser/moss_mesh.test.mjs (exit 0 = pass). Textured meshes brought as users bring them:
// tests/data/meshes/textured.glb dropped on the view (its 2 x 1 texture gives the geology: 2,048
// humus and 2,048 sandy cells), ez-tree's flower_blue.glb dropped (seven primitives under a node's
// rotation and scale, three PNG textures) and rock1.glb picked with the file input (Draco, decoded
// by the page, under a node's TRS; its WebP texture is not decoded, so its factor decides). Each
// grows mosses whose stats text is the bytes of `niwa moss grow --mesh FILE --url HASH --stats`
// with the ms* timing fields taken out of both, and the file's bytes were transferred to the worker
// (the page's buffer is detached after). The A/B view grows on a dropped mesh: run B (indirect
// light switched) is the bytes of `niwa moss grow --mesh FILE --url HASH_B --stats`; a mesh dropped
// while A/B is on is followed by run B; a scene picked after it is too.
// Screenshots: build/artifacts/moss-mesh-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { ARTIFACTS, NATIVE, ROOT, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, watchPage } from './harness.mjs';

const meshes = path.join(ROOT, 'tests/data/meshes');
// The stats text without its timing fields ("ms", "ms_photons", ...), as written (no reformatting).
const withoutMs = (text) => String(text || '').trim().replace(/"ms(_[a-z]+)?":-?[0-9.eE+-]+,?/g, '').replace(/,}/g, '}');
const hooks = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));

function nativeStats(file, hash) {
  const args = ['moss', 'grow', '--mesh', path.join(meshes, file), '--url', hash, '--stats'];
  try {
    return { text: withoutMs(execFileSync(NATIVE, args, { encoding: 'utf8' }).trim().split('\n').pop()), command: `niwa ${args.join(' ').replace(ROOT + '/', '')}` };
  } catch (e) {
    return { text: '', command: `${NATIVE} ${args.join(' ')}: ${e.message.split('\n')[0]}` };
  }
}

function sameBytes(name, file, hash, statsText) {
  const native = nativeStats(file, hash);
  const web = withoutMs(statsText);
  const ok = web.length > 100 && web === native.text && !/"ms/.test(web);
  let at = 0;
  while (at < web.length && web[at] === native.text[at]) ++at;
  check(`${name}: the page's stats text == \`${native.command}\` byte for byte (ms* taken out)`, ok,
    ok ? `${web.length} bytes` : `first difference at byte ${at}: web '${web.slice(at, at + 80)}' native '${native.text.slice(at, at + 80)}'`);
}

// Waits for a run newer than serialAbove drawn on screen (or an error); returns the dataset.
async function waitMoss(page, serialAbove) {
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    if (d.status === 'error' || (d.meshError || '') !== '') return true;
    return d.status === 'ready' && Number(d.mossSerial) > n && (d.drawnSerial === d.mossSerial || d.drawing === 'off');
  }, serialAbove, { timeout: TIMEOUT, polling: 200 });
  return hooks(page);
}

// Waits for run B newer than serial `above` (or its error).
async function waitB(page, above) {
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    return d.statusB === 'error' || (d.statusB === 'ready' && Number(d.serialB) > n && d.drawnSerialB === d.serialB);
  }, above, { timeout: TIMEOUT, polling: 200 });
  return hooks(page);
}

const dropFile = (page, name) => page.evaluate(async ({ name: n, b64 }) => {
  const raw = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
  const transfer = new DataTransfer();
  transfer.items.add(new File([raw], n));
  const stage = document.getElementById('stage');
  stage.dispatchEvent(new DragEvent('dragenter', { dataTransfer: transfer, bubbles: true }));
  stage.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true }));
}, { name, b64: fs.readFileSync(path.join(meshes, name)).toString('base64') });

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 } });
  const page = await context.newPage();
  watchPage(page, problems);
  await page.goto(`${server.url}moss.html#preset=nomura2010&days=12&photons=2048`, { waitUntil: 'load' });
  let data = await waitMoss(page, 0);
  check('the page grows its run first', data.status === 'ready', `${data.status} ${data.error || ''}`);

  // 1. Textured meshes, dropped or picked as users bring them.
  const brought = [
    { file: 'textured.glb', how: 'drop' },
    { file: 'flower_blue.glb', how: 'drop' },
    { file: 'rock1.glb', how: 'input' },
  ];
  for (const { file, how } of brought) {
    const serial = Number(data.mossSerial);
    await page.evaluate(() => { delete document.documentElement.dataset.meshTransferred; });
    if (how === 'drop') await dropFile(page, file);
    else await page.setInputFiles('#mesh-file', path.join(meshes, file));
    data = await waitMoss(page, serial);
    const stats = JSON.parse(data.stats || '{}');
    check(`${file} (${how === 'drop' ? 'dropped on the view' : 'picked with the file input'}) grows mosses on it`,
      data.status === 'ready' && data.sceneShown === `mesh:${file}` && !data.meshError && stats.cells?.total > 0,
      `${data.status} ${data.sceneShown} ${data.mosses} mosses, cells ${JSON.stringify(stats.cells?.by_geology)} ${data.error || data.meshError || ''}`);
    check(`${file}: its bytes were transferred to the worker, not copied`, data.meshTransferred === 'yes', data.meshTransferred);
    sameBytes(file, file, data.hash, data.statsText);
    if (file === 'textured.glb') {
      const g = stats.cells?.by_geology || {};
      check('textured.glb: the texture\'s halves give 2,048 humus and 2,048 sandy cells', g.humus === 2048 && g.sandy === 2048 && g.asphalt === 0, JSON.stringify(g));
    }
    if (file === 'flower_blue.glb') {
      const g = stats.cells?.by_geology || {};
      check('flower_blue.glb: its textures and colours give more than one geology', Object.values(g).filter((n) => n > 0).length >= 2, JSON.stringify(g));
    }
    await saveCanvasPng(page, `moss-mesh-${path.basename(file, '.glb')}.png`);
  }

  // 2. The A/B view on the dropped mesh (rock1.glb now): run B grows on it with indirect light off.
  await page.selectOption('#compare', 'indirect');
  let b = await waitB(page, 0);
  let statsB = JSON.parse(b.statsB || '{}');
  check('A/B on a dropped mesh: run B grows on it (indirect off)', b.statusB === 'ready' && statsB.scene === 'mesh' && statsB.mesh === 'rock1.glb' &&
    /(^|&)indirect=0(&|$)/.test(b.hashB), `${b.statusB} ${statsB.scene} ${statsB.mesh} ${b.hashB} ${b.errorB || ''}`);
  sameBytes('run B on rock1.glb', 'rock1.glb', b.hashB, b.statsTextB);
  const bouncedB = (statsB.photons_last_day?.stored_by_depth || []).slice(1).reduce((x, y) => x + y, 0);
  check('run B on the mesh stores no bounced photon', bouncedB === 0 && (statsB.photons_last_day?.stored_by_depth?.[0] ?? 0) > 0,
    JSON.stringify(statsB.photons_last_day?.stored_by_depth));
  const a = await hooks(page);
  check('run A stays on the mesh beside it', a.sceneShown === 'mesh:rock1.glb' && a.statsText === data.statsText, a.sceneShown);
  await saveCanvasPng(page, 'moss-mesh-ab-rock1.png');
  await page.screenshot({ path: path.join(ARTIFACTS, 'moss-mesh-ab-page.png') });

  // 3. A mesh dropped while A/B is on: run B follows it.
  let serial = Number(data.mossSerial);
  await dropFile(page, 'textured.glb');
  data = await waitMoss(page, serial);
  b = await page.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.statusB === 'error' || (d.statusB === 'ready' && d.drawnSerialB === d.serialB && JSON.parse(d.statsB || '{}').mesh === 'textured.glb');
  }, null, { timeout: TIMEOUT, polling: 200 }).then(() => hooks(page));
  statsB = JSON.parse(b.statsB || '{}');
  check('a mesh dropped with A/B on: both runs grow on it', data.sceneShown === 'mesh:textured.glb' && b.statusB === 'ready' && statsB.mesh === 'textured.glb',
    `${data.sceneShown} ${b.statusB} ${statsB.mesh} ${b.errorB || ''}`);
  sameBytes('run B on textured.glb', 'textured.glb', b.hashB, b.statsTextB);
  await saveCanvasPng(page, 'moss-mesh-ab-textured.png');

  // 4. A scene picked after it: both runs go back to the scene.
  serial = Number(data.mossSerial);
  const serialB = Number(b.serialB);
  await page.selectOption('#scene', 'plane');
  data = await waitMoss(page, serial);
  b = await waitB(page, serialB);
  statsB = JSON.parse(b.statsB || '{}');
  check('a scene picked after the mesh: both runs grow on it', data.sceneShown === 'plane' && statsB.scene === 'plane' && b.statusB === 'ready',
    `${data.sceneShown} ${statsB.scene} ${b.statusB}`);

  check('no uncaught error or console error', problems.length === 0, problems.slice(0, 3).join(' | ').slice(0, 400));
  await context.close();
});
