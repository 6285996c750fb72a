#!/usr/bin/env node
// Niwa's species beside the ez-tree presets a user would pick instead (issue 32 item 3): each
// Niwa preset exported by `niwa tree grow --preset P --out P.glb` (the plain .glb a game developer
// takes) and the matching @dgreenheck/ez-tree preset, drawn by three.js in one Chromium page with
// the same lights, the same camera angle and each framed on its own bounds, 512 x 512, side by side
// into docs/figures/species/<niwa>_vs_<ez>.png, with the triangle counts and heights in
// docs/figures/species/species.json. Run by `scripts/figures species` (figures_species.js).
// Does not: judge the looks (docs/tree-species.md does, from these pictures).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchChromium } from '../../tests/browser/harness.mjs';

const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const NIWA = process.env.NIWA || path.join(ROOT, 'build/native/bin/niwa');
const OUT = path.join(ROOT, 'docs/figures/species');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-species-'));
const ORIGIN = 'http://species.test';

// Niwa preset -> the closest ez-tree preset (ez-tree has oak, ash, aspen and pine, small/medium/large).
const PAIRS = [
  { niwa: 'pine', ez: 'Pine Medium' },
  { niwa: 'maple', ez: 'Oak Medium' },
  { niwa: 'keyaki', ez: 'Ash Medium' },
  { niwa: 'sakura', ez: 'Oak Large' },
  { niwa: 'weeping', ez: 'Aspen Medium' },
];

const PAGE = `<!doctype html><html><body style="margin:0;background:#fff">
<canvas id="c" width="512" height="512"></canvas>
<script type="importmap">{"imports":{"three":"${ORIGIN}/three/build/three.module.js","three/addons/":"${ORIGIN}/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { Tree } from '${ORIGIN}/ez-tree/ez-tree.es.js';
const canvas = document.getElementById('c');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setClearColor(0xdde6ee, 1);
const gl = renderer.getContext();
// One light set and one camera angle for both: from the front-right, a little above the middle.
function draw(object) {
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x665544, 1.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(0.3, 0.8, 0.5);
  scene.add(sun);
  scene.add(object);
  const box = new THREE.Box3().setFromObject(object);
  const size = box.getSize(new THREE.Vector3());
  const centre = box.getCenter(new THREE.Vector3());
  const radius = size.length() / 2;
  const distance = radius / Math.sin(Math.PI / 8) * 1.0;
  const camera = new THREE.PerspectiveCamera(45, 1, distance / 100, distance * 4);
  camera.position.set(centre.x + distance * Math.sin(0.6), centre.y + distance * 0.1, centre.z + distance * Math.cos(0.6));
  camera.lookAt(centre);
  renderer.render(scene, camera);
  // The picture's tree pixels (not the clear colour) and, of them, the foliage's (green over red).
  const px = new Uint8Array(512 * 512 * 4);
  gl.readPixels(0, 0, 512, 512, gl.RGBA, gl.UNSIGNED_BYTE, px);
  let tree = 0, green = 0;
  for (let i = 0; i < px.length; i += 4) {
    const [r, g, b] = [px[i], px[i + 1], px[i + 2]];
    if (Math.abs(r - 0xdd) + Math.abs(g - 0xe6) + Math.abs(b - 0xee) < 12) continue;
    tree += 1;
    if (g > r * 1.15 && g > b) green += 1;
  }
  let triangles = 0;
  object.traverse((o) => {
    if (!o.isMesh) return;
    const g = o.geometry;
    triangles += (g.index ? g.index.count : g.attributes.position.count) / 3 * (o.isInstancedMesh ? o.count : 1);
  });
  return { png: canvas.toDataURL('image/png'), height: size.y, width: Math.max(size.x, size.z), triangles,
    tree_share: tree / (512 * 512), foliage_share: tree ? green / tree : 0 };
}
const ready = (t) => t.image && (t.image.complete === undefined || (t.image.complete && t.image.naturalWidth > 0));
window.drawGlb = (url) => new Promise((ok, fail) => new GLTFLoader().load(url, (g) => ok(draw(g.scene)), undefined, fail));
window.drawEz = async (preset) => {
  const tree = new Tree();
  tree.loadPreset(preset);
  const maps = [];
  tree.traverse((o) => { for (const m of [].concat(o.material || [])) for (const t of [m.map, m.aoMap, m.normalMap]) if (t) maps.push(t); });
  while (!maps.every(ready)) await new Promise((r) => requestAnimationFrame(r));
  return draw(tree);
};
window.ready = true;
</script></body></html>`;

const browser = await launchChromium();
const rows = [];
try {
  const page = await browser.newPage({ viewport: { width: 1100, height: 600 } });
  await page.route(`${ORIGIN}/**`, (route) => {
    const url = new URL(route.request().url());
    let file = null;
    if (url.pathname === '/index.html') return route.fulfill({ body: PAGE, contentType: 'text/html' });
    if (url.pathname.startsWith('/three/')) file = path.join(ROOT, 'node_modules', url.pathname.slice(1));
    if (url.pathname.startsWith('/ez-tree/')) file = path.join(ROOT, 'node_modules/@dgreenheck/ez-tree/build', path.basename(url.pathname));
    if (url.pathname.startsWith('/glb/')) file = path.join(dir, path.basename(url.pathname));
    if (!file || !fs.existsSync(file)) return route.fulfill({ status: 404, body: 'not found' });
    const type = file.endsWith('.js') ? 'text/javascript' : file.endsWith('.glb') ? 'model/gltf-binary' : 'application/octet-stream';
    return route.fulfill({ body: fs.readFileSync(file), contentType: type });
  });
  await page.goto(`${ORIGIN}/index.html`);
  await page.waitForFunction(() => window.ready === true, null, { timeout: 60000 });
  fs.mkdirSync(OUT, { recursive: true });
  for (const { niwa, ez } of PAIRS) {
    const glb = path.join(dir, `${niwa}.glb`);
    const args = ['tree', 'grow', '--preset', niwa, '--seed', '1', '--out', glb, '--stats'];
    const stats = JSON.parse(execFileSync(NIWA, args, { encoding: 'utf8', maxBuffer: 1 << 26 }));
    const a = await page.evaluate((u) => window.drawGlb(u), `${ORIGIN}/glb/${niwa}.glb`);
    const b = await page.evaluate((p) => window.drawEz(p), ez);
    const file = `${niwa}_vs_${ez.toLowerCase().replace(/ /g, '_')}.png`;
    const pair = await page.evaluate(async (srcs) => {
      const c = document.createElement('canvas');
      c.width = 1024; c.height = 512;
      const ctx = c.getContext('2d');
      for (let i = 0; i < 2; ++i) {
        const img = new Image();
        img.src = srcs[i];
        await img.decode();
        ctx.drawImage(img, 512 * i, 0);
      }
      return c.toDataURL('image/png');
    }, [a.png, b.png]);
    fs.writeFileSync(path.join(OUT, file), Buffer.from(pair.split(',')[1], 'base64'));
    const round = (x, k = 2) => Math.round(x * 10 ** k) / 10 ** k;
    rows.push({
      niwa, ez, file, years: stats.years, command: `niwa ${args.slice(0, -3).join(' ')} --out ${niwa}.glb`,
      niwa_triangles: Math.round(a.triangles), ez_triangles: Math.round(b.triangles),
      niwa_height_m: round(a.height), ez_height_m: round(b.height),
      niwa_width_over_height: round(a.width / a.height), ez_width_over_height: round(b.width / b.height),
      niwa_picture_share: round(a.tree_share, 3), ez_picture_share: round(b.tree_share, 3),
      niwa_foliage_share: round(a.foliage_share, 3), ez_foliage_share: round(b.foliage_share, 3),
    });
    console.log(`${niwa} (${Math.round(a.triangles)} triangles, tree ${round(a.tree_share, 3)} of the picture, foliage ${round(a.foliage_share, 3)} of the tree) | ${ez} (${Math.round(b.triangles)} triangles, ${round(b.tree_share, 3)}, ${round(b.foliage_share, 3)}) -> docs/figures/species/${file}`);
  }
} finally {
  await browser.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
fs.writeFileSync(path.join(OUT, 'species.json'), `${JSON.stringify(rows, null, 1)}\n`);
