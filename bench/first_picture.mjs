// First picture against ez-tree (issue 32 item 5: "the tree page shows its first tree within 2× an
// ez-tree page's load in the same run"): a fresh Chromium per load (no HTTP or V8 code cache), the
// pages interleaved so a slow spell of this shared machine hits all alike, each timed from the
// navigation's start (performance.now() in the page is 0 there) to its first whole tree on screen:
//   niwa/tree    /            the tree page's default tree: status ready, the tree's frame finished
//                             (not in parts) with its mesh uploaded (the hooks load_tasks.test reads)
//   bare-webgl2  a page that makes a WebGL2 context and clears it (the floor of any WebGL page's load)
//   ez-tree      a page of three.js + @dgreenheck/ez-tree from node_modules (served here by route):
//                             Tree(), loadPreset(PRESET) (which generates it), rendered once its
//                             textures are in (three's loading manager), then a pixel read back so
//                             the frame is finished on the GPU before it counts; its first render
//                             before the textures is the row ez-tree-untextured
// node bench/first_picture.mjs [--reps 5] [--preset "Oak Large"] [--shots DIR]
// --shots DIR: the first load of each page saved as DIR/first-picture-<page>.png (after its time).
// Prints one JSON line per load, then one summary line per page (median, min) and the ratios of the
// medians against ez-tree's, in the format of niwa_bench_runner's rows (workload, ms, min_ms, reps).
// Does not: judge the goal (docs/BENCHMARKS.md does, with the machine's load), or warm anything up.
import fs from 'node:fs';
import path from 'node:path';
import { startServer } from '../scripts/serve.mjs';
import { ROOT, launchChromium } from '../tests/browser/harness.mjs';

const args = { reps: '5', preset: 'Oak Large', shots: '' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args)) {
    console.error('usage: node bench/first_picture.mjs [--reps N] [--preset "Oak Large"] [--shots DIR]');
    process.exit(2);
  }
  args[key] = process.argv[i + 1];
}
const reps = Math.max(1, Number(args.reps));
const TIMEOUT = 300_000;

// The ez-tree page, with an import map to the packages' own builds (three's module imports its core).
const EZ_PAGE = `<!doctype html><html><head><meta charset="utf-8"><title>ez-tree peer</title>
<style>html,body{margin:0;height:100%;background:#dde6ee}canvas{display:block;width:100%;height:100%}</style>
<script type="importmap">{"imports":{"three":"/__peer/three/three.module.js"}}</script></head><body>
<script type="module">
import * as THREE from 'three';
import { Tree } from '/__peer/ez-tree/ez-tree.es.js';
const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setSize(innerWidth, innerHeight);
document.body.append(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xdde6ee);
scene.add(new THREE.HemisphereLight(0xffffff, 0x445533, 1.5));
const sun = new THREE.DirectionalLight(0xffffff, 2);
sun.position.set(50, 100, 30);
scene.add(sun);
const tree = new Tree();
tree.loadPreset(${JSON.stringify(args.preset)});
scene.add(tree);
const box = new THREE.Box3().setFromObject(tree);
const size = box.getSize(new THREE.Vector3()).length();
const camera = new THREE.PerspectiveCamera(45, innerWidth / innerHeight, 0.1, 10 * size);
camera.position.set(0, box.getCenter(new THREE.Vector3()).y, size * 0.9);
camera.lookAt(box.getCenter(new THREE.Vector3()));
const gl = renderer.getContext();
const draw = () => {
  renderer.render(scene, camera);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));  // the frame finished
  return String(performance.now());
};
document.documentElement.dataset.untexturedAt = draw();
// ez-tree's bark and leaf textures are data: URLs its module starts loading on import: the picture
// a user sees is the one drawn once every texture of the tree's materials has its image.
const maps = [];
tree.traverse((o) => {
  for (const m of [].concat(o.material || [])) for (const t of [m.map, m.aoMap, m.normalMap, m.roughnessMap]) if (t) maps.push(t);
});
const loaded = (t) => t.image && (t.image.complete === undefined || (t.image.complete && t.image.naturalWidth > 0));
const waitTextures = () => {
  if (maps.every(loaded)) document.documentElement.dataset.drawnAt = draw();
  else requestAnimationFrame(waitTextures);
};
waitTextures();
</script></body></html>`;

const PEER_FILES = {
  '/__peer/three/': path.join(ROOT, 'node_modules/three/build/'),
  '/__peer/ez-tree/': path.join(ROOT, 'node_modules/@dgreenheck/ez-tree/build/'),
};

const PAGES = {
  'niwa/tree': {
    path: '',
    drawn: () => {
      const d = document.documentElement.dataset;
      return d.status === 'ready' && Number(d.treeSerial) >= 1 && d.drawnTreeSerial === d.treeSerial && d.framePartial === '0';
    },
  },
  'ez-tree': { path: '__peer/ez-tree.html', drawn: () => document.documentElement.dataset.drawnAt !== undefined },
  // The floor of any WebGL2 page here: one context made and one clear drawn (its long task is the
  // browser's own, e.g. the software rasteriser's start).
  'bare-webgl2': { path: '__peer/bare.html', drawn: () => document.documentElement.dataset.drawnAt !== undefined },
};
const BARE_PAGE = `<!doctype html><html><head><meta charset="utf-8"><title>WebGL2 floor</title></head>
<body><canvas id="c" width="1100" height="760"></canvas><script>
const gl = document.getElementById('c').getContext('webgl2');
gl.clearColor(0.8, 0.85, 0.9, 1); gl.clear(gl.COLOR_BUFFER_BIT);
requestAnimationFrame(() => { document.documentElement.dataset.drawnAt = String(performance.now()); });
</script></body></html>`;

async function once(server, name, shoot) {
  const browser = await launchChromium();
  try {
    const context = await browser.newContext({ viewport: { width: 1100, height: 760 } });
    await context.route('**/__peer/**', (route) => {
      const url = new URL(route.request().url());
      if (url.pathname === '/__peer/ez-tree.html') return route.fulfill({ body: EZ_PAGE, contentType: 'text/html' });
      if (url.pathname === '/__peer/bare.html') return route.fulfill({ body: BARE_PAGE, contentType: 'text/html' });
      for (const [prefix, dir] of Object.entries(PEER_FILES)) {
        if (url.pathname.startsWith(prefix)) {
          const file = path.join(dir, path.basename(url.pathname));
          return route.fulfill({ body: fs.readFileSync(file), contentType: 'text/javascript' });
        }
      }
      return route.fulfill({ status: 404, body: '' });
    });
    // The main thread's long tasks until the first picture (issue 32 item 5: none over 200 ms),
    // for both pages alike (tests/browser/load_tasks.test.mjs reads the tree page's alone).
    await context.addInitScript(() => {
      window.__longtasks = [];
      try {
        new PerformanceObserver((list) => {
          for (const e of list.getEntries()) window.__longtasks.push(e.duration);
        }).observe({ type: 'longtask', buffered: true });
      } catch (e) { /* no long tasks in this browser */ }
    });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(`${server.url}${PAGES[name].path}`, { timeout: TIMEOUT });
    await page.waitForFunction(PAGES[name].drawn, null, { timeout: TIMEOUT, polling: 20 });
    const ms = await page.evaluate(() => Number(document.documentElement.dataset.drawnAt ?? performance.now()));
    longest[name].push(await page.evaluate(() => Math.max(0, ...window.__longtasks)));
    if (name === 'ez-tree') untextured.push(await page.evaluate(() => Number(document.documentElement.dataset.untexturedAt)));
    if (errors.length) throw new Error(`${name}: ${errors[0]}`);
    if (args.shots && shoot) {
      fs.mkdirSync(args.shots, { recursive: true });
      await page.screenshot({ path: path.join(args.shots, `first-picture-${name.replace('/', '-')}.png`) });
    }
    return ms;
  } finally {
    await browser.close();
  }
}

const server = await startServer({ port: 0 });
const times = Object.fromEntries(Object.keys(PAGES).map((k) => [k, []]));
const untextured = [];  // ez-tree's first render, before its textures are in
const longest = Object.fromEntries(Object.keys(PAGES).map((k) => [k, []]));  // longest task a load
try {
  for (let r = 0; r < reps; ++r) {
    for (const name of Object.keys(PAGES)) {
      const ms = await once(server, name, r === 0);
      times[name].push(ms);
      console.log(JSON.stringify({ page: name, rep: r + 1, ms: Math.round(ms), longest_task_ms: Math.round(longest[name].at(-1)) }));
    }
  }
} finally {
  await server.close();
}
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const ez = median(times['ez-tree']);
times['ez-tree-untextured'] = untextured;
for (const [name, xs] of Object.entries(times)) {
  const m = median(xs);
  console.log(JSON.stringify({
    build: 'browser', workload: `first-picture/${name}`, ms: Math.round(m), min_ms: Math.round(Math.min(...xs)), reps: xs.length,
    ratio_to_ez_tree: Number((m / ez).toFixed(2)), ez_tree_preset: args.preset,
    ...(longest[name] ? { longest_task_ms: Math.round(median(longest[name])), longest_task_max_ms: Math.round(Math.max(...longest[name])) } : {}),
  }));
}
