// Browser test of the textured viewer and the seasons (issue 17 items 2-3): node
// tests/browser/textures.test.mjs. The page draws the .glb's procedural textures (alpha-tested leaf
// shapes, blossom-cluster cards, bark with its normal map); the season row, edited in the panel,
// restages the tree (no regrowth) and the picture follows it, judged by colour histograms of the
// canvas: spring sakura pink without green leaves, summer green with pink, autumn red-orange without
// pink, winter neither; pine keeps green needles in winter, maple turns red and ginkgo yellow in
// autumn, tsutsuji flowers magenta in spring. The page's textures are the native CLI's .glb
// textures (digests). Screenshots to LOOK
// at: build/artifacts/tex-*.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ARTIFACTS, NATIVE, ROOT, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitReady, watchPage } from './harness.mjs';

const SIZE = 512;
const problems = [];
const root = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));

// Shares of the canvas's pixels per colour class (sRGB bytes).
async function histogram(page) {
  return page.evaluate(() => {
    const { data: d } = window.__niwaCanvasImage('#view');
    const n = d.length / 4;
    const c = { pink: 0, green: 0, warm: 0, yellow: 0, magenta: 0, dark: 0 };
    for (let i = 0; i < d.length; i += 4) {
      const r = d[i], g = d[i + 1], b = d[i + 2];
      if (r > 170 && r - g > 20 && b > g && r - b < 60) c.pink++;
      else if (g > r + 12 && g > b + 12) c.green++;
      else if (r > 110 && r - g > 45 && r - b > 70 && b < g + 20) c.warm++;
      else if (r > 140 && g > 110 && b < 0.55 * g && Math.abs(r - g) < 70) c.yellow++;
      else if (r > 120 && r - g > 70 && b - g > 40) c.magenta++;
      if (0.299 * r + 0.587 * g + 0.114 * b < 70) c.dark++;
    }
    for (const k of Object.keys(c)) c[k] /= n;
    return c;
  });
}

const fmt = (h) => Object.entries(h).map(([k, v]) => `${k} ${(100 * v).toFixed(2)}%`).join(', ');

// Sets one panel field (restage for a view row) and waits for the new tree to be drawn.
async function setField(page, key, value) {
  const before = Number((await root(page)).treeSerial || 0);
  await page.evaluate((k) => { document.getElementById(`param-${k}`).closest('details').open = true; }, key);
  await page.fill(`#param-${key}`, String(value));
  await waitReady(page, before, 200);
}

// The digests of the .glb's leaf texture for a look, from the native CLI's .glb, against the page's.
function glbTextureNames(args) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-tex-'));
  try {
    const out = path.join(dir, 't.glb');
    execFileSync(NATIVE, ['tree', 'grow', ...args, '--out', out]);
    const bytes = fs.readFileSync(out);
    const json = JSON.parse(bytes.subarray(20, 20 + bytes.readUInt32LE(12)).toString('utf8'));
    return json.textures.map((t) => t.name);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// three.js (an independent glTF renderer) draws the CLI's .glb of the same tree from the page's
// camera into a 512 x 512 canvas; returns its histogram. Served from node_modules/three by a route.
async function threeHistogram(context, server, glb, cam, file) {
  const page = await context.newPage();
  watchPage(page, problems);
  const three = path.join(ROOT, 'node_modules', 'three');
  await page.route('**/__three/**', (route) => {
    const rel = new URL(route.request().url()).pathname.replace(/^\/__three\//, '');
    const file = path.join(three, rel);
    if (!file.startsWith(three) || !fs.existsSync(file)) return route.fulfill({ status: 404, body: '' });
    return route.fulfill({ status: 200, contentType: 'text/javascript', body: fs.readFileSync(file) });
  });
  await page.route('**/__three.html', (route) => route.fulfill({ status: 200, contentType: 'text/html', body: `<!doctype html>
<script type="importmap">{"imports": {"three": "/__three/build/three.module.js", "three/addons/": "/__three/examples/jsm/"}}</script>
<canvas id="view" width="${SIZE}" height="${SIZE}" style="width:${SIZE}px;height:${SIZE}px"></canvas>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
window.renderGlb = async (base64, cam) => {
  const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
  const gltf = await new Promise((resolve, reject) => new GLTFLoader().parse(bytes.buffer, '', resolve, reject));
  const renderer = new THREE.WebGLRenderer({ canvas: document.getElementById('view'), preserveDrawingBuffer: true, antialias: true });
  renderer.setSize(${SIZE}, ${SIZE}, false);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color().setRGB(0.86, 0.90, 0.94, THREE.SRGBColorSpace);
  scene.add(gltf.scene);
  scene.add(new THREE.HemisphereLight(0xbcd0ea, 0x514c3c, 1.2));
  const sun = new THREE.DirectionalLight(0xfff8e6, 2.4);
  sun.position.set(0.5, 0.866, 0);  // the page's default sun (elevation 60, azimuth 0)
  scene.add(sun);
  const [yaw, pitch, distance, tx, ty, tz] = cam;
  const camera = new THREE.PerspectiveCamera(45, 1, distance / 1000, distance * 20);
  camera.position.set(tx + distance * Math.cos(pitch) * Math.sin(yaw), ty + distance * Math.sin(pitch), tz + distance * Math.cos(pitch) * Math.cos(yaw));
  camera.lookAt(tx, ty, tz);
  renderer.render(scene, camera);
  return true;
};
window.threeReady = true;
</script>` }));
  await page.goto(`${server.url}/__three.html`);
  await page.waitForFunction(() => window.threeReady === true, null, { timeout: TIMEOUT });
  await page.evaluate(([b, c]) => window.renderGlb(b, c), [glb.toString('base64'), cam]);
  const h = await histogram(page);
  await saveCanvasPng(page, file);
  await page.close();
  return h;
}

// The native CLI's .glb of a page state (its hash without cam=).
function cliGlb(hash) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-tex-'));
  try {
    const out = path.join(dir, 't.glb');
    execFileSync(NATIVE, ['tree', 'grow', '--url', hash.replace(/&?cam=[^&]*/, ''), '--out', out]);
    return fs.readFileSync(out);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: SIZE + 340, height: SIZE }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  watchPage(page, problems);

  // ---- Sakura (thesis form, flowering from its 7th year) through the four seasons.
  await page.goto(`${server.url}#preset=sakura-thesis&seed=1&years=10`);
  await waitReady(page, 0, 200);
  const hooks0 = await root(page);
  const seasons = {};
  const threeSeasons = {};
  for (const [value, name] of [[1, 'summer'], [0, 'spring'], [2, 'autumn'], [3, 'winter']]) {
    if (value !== 1) await setField(page, 'season', value);
    seasons[name] = await histogram(page);
    await saveCanvasPng(page, `tex-sakura-${name}.png`);
    console.log(`  sakura ${name}: ${fmt(seasons[name])}`);
    if (name === 'summer' || name === 'autumn') {
      await page.waitForFunction(() => /cam=/.test(location.hash), null, { timeout: TIMEOUT });
      const hash = decodeURIComponent(await page.evaluate(() => location.hash.slice(1)));
      const cam = (hash.match(/cam=([^&]*)/) || [])[1].split(',').map(Number);
      threeSeasons[name] = await threeHistogram(context, server, cliGlb(hash), cam, `tex-three-sakura-${name}.png`);
      console.log(`  three.js ${name}: ${fmt(threeSeasons[name])}`);
    }
  }
  // The page's picture against three.js's of the exported .glb (other lights, same textures): the
  // same colour classes are present in comparable shares.
  const near = (a, b) => a > 0 && b > 0 && a / b < 4 && b / a < 4;
  check('summer: page and three.js show green leaves and pink blossom in comparable shares',
    near(seasons.summer.green, threeSeasons.summer.green) && near(seasons.summer.pink, threeSeasons.summer.pink),
    `page ${fmt(seasons.summer)} | three.js ${fmt(threeSeasons.summer)}`);
  check('autumn: page and three.js show red-orange leaves in comparable shares, no blossom in either',
    near(seasons.autumn.warm, threeSeasons.autumn.warm) && threeSeasons.autumn.pink < 0.1 * threeSeasons.summer.pink,
    `page ${fmt(seasons.autumn)} | three.js ${fmt(threeSeasons.autumn)}`);
  const hooks1 = await root(page);
  check('season edits restage the tree, no regrowth', hooks1.growRequests === hooks0.growRequests &&
    Number(hooks1.restageRequests) >= Number(hooks0.restageRequests) + 3,
  `grows ${hooks0.growRequests} -> ${hooks1.growRequests}, restages ${hooks0.restageRequests} -> ${hooks1.restageRequests}`);
  check('the hash carries the season', /season=3/.test(await page.evaluate(() => location.hash)));
  const s = seasons;
  check('summer: green leaves and pink blossom', s.summer.green > 0.01 && s.summer.pink > 0.001, fmt(s.summer));
  check('spring: blossom on bare wood (pink, no green leaves)', s.spring.pink > 0.002 && s.spring.green < 0.1 * s.summer.green, fmt(s.spring));
  check('autumn: red-orange leaves, no blossom', s.autumn.warm > 0.01 && s.autumn.pink < 0.1 * s.summer.pink && s.autumn.green < 0.2 * s.summer.green, fmt(s.autumn));
  check('winter: bare (no leaves, no blossom), the wood still drawn', s.winter.green < 0.05 * s.summer.green &&
    s.winter.warm < 0.1 * s.autumn.warm && s.winter.pink < 0.1 * s.summer.pink && s.winter.dark > 0.002, fmt(s.winter));

  // ---- Leaf shapes: the species presets, and a close view of each shape on one tree.
  const species = [
    ['pine', 'preset=pine&seed=1&years=8&season=3', (h) => h.green > 0.01, 'winter: keeps green needles'],
    ['maple-autumn', 'preset=maple&seed=1&years=8&season=2', (h) => h.warm > 0.01 && h.green < 0.3 * h.warm, 'autumn: red'],
    ['ginkgo-autumn', 'preset=ginkgo&seed=1&years=8&season=2', (h) => h.yellow > 0.01, 'autumn: yellow'],
    ['keyaki-autumn', 'preset=keyaki&seed=1&years=8&season=2', (h) => h.warm + h.yellow > 0.01, 'autumn: orange-brown'],
    // Each flowering species' own flowers (flower_colour, flower_form, terminal_flowers rows).
    ['tsutsuji-spring', 'preset=tsutsuji&seed=1&years=15&season=0', (h) => h.magenta > 0.01 && h.green > 0.005, 'spring: magenta azalea trusses over green leaves'],
    ['weeping-spring', 'preset=weeping&seed=1&years=20&season=0', (h) => h.pink > 0.0005 && h.magenta < 0.1 * h.pink && h.green < 0.002, 'spring: pink (not magenta) blossom on bare wood'],
  ];
  // A fresh page per tree: a hash link grows it from scratch.
  const openTree = async (hash) => {
    const p = await context.newPage();
    watchPage(p, problems);
    await p.goto(`${server.url}#${hash}`);
    await waitReady(p, 0, 200);
    return p;
  };
  await page.close();
  for (const [name, hash, ok, what] of species) {
    const p = await openTree(hash);
    const h = await histogram(p);
    await saveCanvasPng(p, `tex-${name}.png`);
    check(`${name} ${what}`, ok(h), fmt(h));
    if (name === 'pine') {
      // The pine's leaf_spray 3 card (three fascicles on a twig): the page's texture is the one the
      // gtest pins for both builds (tree_textures_test.cpp LeafSpray), and the CLI's .glb names it.
      const digest = (await root(p)).leafDigest;
      check('pine: the page draws the leaf_spray card the core paints (digest)', digest === '3bd6c76cb188dd1c', digest);
      const names = glbTextureNames(['--preset', 'pine', '--years', '4', '--season', 'winter']);
      check('pine: the CLI .glb carries the same card (leaf_needle_winter_spray3)', names.includes('leaf_needle_winter_spray3'), names.join(','));
    }
    await p.close();
  }
  // Close-ups of the four shapes on keyaki-thesis at 6 years (leaf_shape is a mesh row: restaged):
  // the framed camera's distance cut to a third, aimed at the upper crown.
  const framed = await openTree('preset=keyaki-thesis&seed=1&years=6');
  await framed.waitForFunction(() => /cam=/.test(location.hash), null, { timeout: TIMEOUT });
  const cam = decodeURIComponent(await framed.evaluate(() => location.hash)).match(/cam=([^&]*)/)[1].split(',').map(Number);
  await framed.close();
  const close = [cam[0], 0.35, cam[2] / 3, cam[3], cam[4] * 1.5, cam[5]].map((x) => Number(x.toFixed(3))).join(',');
  const shapes = await openTree(`preset=keyaki-thesis&seed=1&years=6&cam=${close}`);
  const grows = (await root(shapes)).growRequests;
  const shapeShares = {};
  for (const [value, name] of [[0, 'broad'], [1, 'needle'], [2, 'palmate'], [3, 'fan']]) {
    if (value !== 0) await setField(shapes, 'leaf_shape', value);
    const h = await histogram(shapes);
    shapeShares[name] = h.green;
    await saveCanvasPng(shapes, `tex-shape-${name}.png`);
    check(`leaf_shape ${name}: green leaves drawn`, h.green > 0.01, fmt(h));
  }
  // The blades cover their quads differently (tree_textures_test: needle ≈ 0.16 of a narrower
  // quad, broad ≈ 0.53): the needles show the least green.
  check('needles show less green than broad leaves', shapeShares.needle < 0.8 * shapeShares.broad,
    JSON.stringify(shapeShares));
  check('leaf_shape edits do not regrow', (await root(shapes)).growRequests === grows);
  await shapes.close();

  // The textures the page drew are the .glb's (same names from the CLI; same pixels by the
  // digests the gtest pins for both builds).
  const names = glbTextureNames(['--preset', 'keyaki-thesis', '--years', '4', '--set', 'leaf_shape=3']);
  check('the CLI .glb of the same look has bark, bark_normal and leaf_fan_summer', names.join(',') === 'bark,bark_normal,leaf_fan_summer', names.join(','));
  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
