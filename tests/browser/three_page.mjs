// A blank Chromium page that draws .glb files with three.js' own GLTFLoader (an independent glTF
// reader): the tests of exported assets (lod_look, ivy_glb_look) use it. openThreePage(browser,
// dir) serves node_modules/three and the .glb files of `dir`; in the page,
// window.renderGlbs(names, {plain, rgba}) draws each file with the camera framed on the first
// (same lights, transparent background, 512 x 512) and returns {png (data URL), mask (alpha > 0),
// rgba (the pixels, bottom row first, when asked)} per file; plain: every material's colour map
// dropped (the untextured twin).
// Does not: start Niwa's app or its worker.
import fs from 'node:fs';
import path from 'node:path';
import { ROOT } from './harness.mjs';

const ORIGIN = 'http://three.test';
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
window.renderGlbs = async (names, { plain = false, rgba = false } = {}) => {
  const out = [];
  let camera = null;
  for (const name of names) {
    const gltf = await load('${ORIGIN}/glb/' + name);
    if (plain) gltf.scene.traverse((o) => { for (const m of [o.material ?? []].flat()) { m.map = null; m.needsUpdate = true; } });
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
      const distance = radius / Math.sin(Math.PI / 8) * 1.05;
      // far: 1000, or past the scene when it is larger (a facade in px, docs/figures/ivy/look_*).
      camera = new THREE.PerspectiveCamera(45, 1, 0.05, Math.max(1000, distance + 2 * radius));
      camera.position.set(centre.x + distance * Math.sin(0.6), centre.y + distance * 0.1, centre.z + distance * Math.cos(0.6));
      camera.lookAt(centre);
    }
    renderer.render(scene, camera);
    const gl = renderer.getContext();
    const pixels = new Uint8Array(512 * 512 * 4);
    gl.readPixels(0, 0, 512, 512, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const mask = [];
    for (let i = 3; i < pixels.length; i += 4) mask.push(pixels[i] > 0 ? 1 : 0);
    out.push({ png: canvas.toDataURL('image/png'), mask, rgba: rgba ? Array.from(pixels) : null });
  }
  return out;
};
window.ready = true;
</script></body></html>`;

export async function openThreePage(browser, dir, viewport = { width: 1100, height: 600 }) {
  const page = await browser.newPage({ viewport });
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
  return page;
}

// Writes data-URL PNGs side by side on white into `file`.
export async function saveSideBySide(page, pngs, file) {
  const pair = await page.evaluate(async (srcs) => {
    const c = document.createElement('canvas');
    c.width = 512 * srcs.length; c.height = 512;
    const ctx = c.getContext('2d');
    ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, c.width, 512);
    for (let i = 0; i < srcs.length; ++i) {
      const img = new Image();
      img.src = srcs[i];
      await img.decode();
      ctx.drawImage(img, 512 * i, 0);
    }
    return c.toDataURL('image/png');
  }, pngs);
  fs.writeFileSync(file, Buffer.from(pair.split(',')[1], 'base64'));
}
