// Issue 17 item 4 (d): a 15-year sakura (`sakura` and `sakura-thesis`) within 20 k triangles still
// looks like the same tree. Both .glb files (the full `niwa tree grow --out` and the
// `--max-triangles 20000` one) are drawn the same way by three.js (an independent glTF loader) in
// Chromium: same camera framed on the full tree, same lights, transparent background. Checks the
// silhouette IoU (pixels with alpha > 0) >= IOU_FLOOR and the height and width of the silhouettes'
// boxes within 5 %; writes the pair side by side to build/artifacts/lod-<preset>.png.
// Run: NIWA_NATIVE=$PWD/build/native/bin/niwa node tests/browser/lod_look.test.mjs
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ARTIFACTS, NATIVE, ROOT, check, finish, launchChromium } from './harness.mjs';

// Pixel IoU punishes one-pixel twigs (a 0.3 px twig of the full tree covers a pixel as a line);
// the block IoU compares the silhouettes at 1/4 resolution (a 4 x 4 block is set when any pixel
// is): the crown's outline and holes, which is what "looks like the same tree" means at a distance.
const IOU_FLOOR = 0.6;
const BLOCK_IOU_FLOOR = 0.8;
const BUDGET = 20000;
const ORIGIN = 'http://lod.test';
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-lod-look-'));
const TYPES = { '.js': 'text/javascript', '.glb': 'model/gltf-binary', '.html': 'text/html' };

const PAGE = `<!doctype html><html><body style="margin:0;background:#fff">
<canvas id="c" width="512" height="512"></canvas>
<script type="importmap">{"imports":{"three":"${ORIGIN}/three/build/three.module.js","three/addons/":"${ORIGIN}/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
const canvas = document.getElementById('c');
const renderer = new THREE.WebGLRenderer({ canvas, alpha: true, antialias: false, preserveDrawingBuffer: true });
renderer.setClearColor(0x000000, 0);
const load = (url) => new Promise((ok, fail) => new GLTFLoader().load(url, ok, undefined, fail));
// Renders each .glb with the camera framed on the first one; returns PNG data URLs and alpha masks.
window.renderPair = async (urls) => {
  const out = [];
  let camera = null;
  for (const url of urls) {
    const gltf = await load(url);
    const scene = new THREE.Scene();
    scene.add(new THREE.HemisphereLight(0xffffff, 0x665544, 1.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(0.3, 0.8, 0.5);
    scene.add(sun);
    scene.add(gltf.scene);
    if (!camera) {
      const box = new THREE.Box3().setFromObject(gltf.scene);
      const centre = box.getCenter(new THREE.Vector3());
      const radius = box.getSize(new THREE.Vector3()).length() / 2;
      camera = new THREE.PerspectiveCamera(45, 1, 0.05, 1000);
      const distance = radius / Math.sin(Math.PI / 8) * 1.05;
      camera.position.set(centre.x + distance * Math.sin(0.6), centre.y + distance * 0.1, centre.z + distance * Math.cos(0.6));
      camera.lookAt(centre);
    }
    renderer.render(scene, camera);
    const gl = renderer.getContext();
    const pixels = new Uint8Array(512 * 512 * 4);
    gl.readPixels(0, 0, 512, 512, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const mask = [];
    for (let i = 3; i < pixels.length; i += 4) mask.push(pixels[i] > 0 ? 1 : 0);
    out.push({ png: canvas.toDataURL('image/png'), mask });
  }
  return out;
};
window.ready = true;
</script></body></html>`;

function iouOf(a, b) {
  let both = 0, either = 0;
  for (let i = 0; i < a.length; ++i) { both += a[i] & b[i]; either += a[i] | b[i]; }
  return either ? both / either : 0;
}

function blocks(mask, k = 4) {
  const n = 512 / k, out = new Array(n * n).fill(0);
  mask.forEach((m, i) => { if (m) out[Math.floor(Math.floor(i / 512) / k) * n + Math.floor((i % 512) / k)] = 1; });
  return out;
}

function box(mask) {
  let x0 = 512, x1 = -1, y0 = 512, y1 = -1;
  mask.forEach((m, i) => {
    if (!m) return;
    const x = i % 512, y = Math.floor(i / 512);
    x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  });
  return { w: x1 - x0 + 1, h: y1 - y0 + 1 };
}

const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: 1100, height: 600 } });
  await page.route(`${ORIGIN}/**`, (route) => {
    const url = new URL(route.request().url());
    let file = null;
    if (url.pathname === '/index.html') return route.fulfill({ body: PAGE, contentType: 'text/html' });
    if (url.pathname.startsWith('/three/')) file = path.join(ROOT, 'node_modules', url.pathname.slice(1));
    if (url.pathname.startsWith('/glb/')) file = path.join(dir, path.basename(url.pathname));
    if (!file || !fs.existsSync(file)) return route.fulfill({ status: 404, body: 'not found' });
    return route.fulfill({ body: fs.readFileSync(file), contentType: TYPES[path.extname(file)] || 'application/octet-stream' });
  });
  await page.goto(`${ORIGIN}/index.html`);
  await page.waitForFunction(() => window.ready === true, null, { timeout: 60000 });

  for (const preset of ['sakura', 'sakura-thesis']) {
    const grow = ['tree', 'grow', '--preset', preset, '--years', '15'];
    execFileSync(NATIVE, [...grow, '--out', path.join(dir, `${preset}-full.glb`)]);
    execFileSync(NATIVE, [...grow, '--max-triangles', String(BUDGET), '--out', path.join(dir, `${preset}-lod.glb`)]);
    const [full, lod] = await page.evaluate((urls) => window.renderPair(urls),
      [`${ORIGIN}/glb/${preset}-full.glb`, `${ORIGIN}/glb/${preset}-lod.glb`]);
    const iou = iouOf(full.mask, lod.mask);
    const blockIou = iouOf(blocks(full.mask), blocks(lod.mask));
    const a = box(full.mask), b = box(lod.mask);
    check(`${preset} 15 years: silhouette IoU of the ${BUDGET}-triangle .glb against the full one >= ${IOU_FLOOR}`,
      iou >= IOU_FLOOR, `IoU ${iou.toFixed(3)} (full ${full.mask.reduce((s, m) => s + m, 0)} px, budget ${lod.mask.reduce((s, m) => s + m, 0)} px)`);
    check(`${preset}: silhouette IoU in 4 x 4 blocks >= ${BLOCK_IOU_FLOOR}`, blockIou >= BLOCK_IOU_FLOOR,
      `block IoU ${blockIou.toFixed(3)}`);
    check(`${preset}: silhouette height and width within 5 %`,
      Math.abs(b.h - a.h) <= 0.05 * a.h && Math.abs(b.w - a.w) <= 0.05 * a.w, `full ${a.w}x${a.h}, budget ${b.w}x${b.h}`);
    // Side by side on white, full on the left.
    const pair = await page.evaluate(async ([l, r]) => {
      const c = document.createElement('canvas');
      c.width = 1024; c.height = 512;
      const ctx = c.getContext('2d');
      ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, 1024, 512);
      for (const [src, x] of [[l, 0], [r, 512]]) {
        const img = new Image();
        img.src = src;
        await img.decode();
        ctx.drawImage(img, x, 0);
      }
      return c.toDataURL('image/png');
    }, [full.png, lod.png]);
    const file = path.join(ARTIFACTS, `lod-${preset}.png`);
    fs.writeFileSync(file, Buffer.from(pair.split(',')[1], 'base64'));
    console.log(`wrote ${path.relative(ROOT, file)} (left: full, right: ${BUDGET} triangles)`);
  }
} catch (e) {
  check('test ran to the end', false, e.stack || String(e));
} finally {
  await browser.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
finish();
