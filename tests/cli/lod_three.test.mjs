// Issue 17 item 4: what an importer that groups LOD levels by name does with `niwa tree grow --lod`.
// three.js has no automatic grouping, so this test does what Unity's model importer does with
// `<name>_LOD<n>` (docs/lod-export.md): loads the .glb with three.js' own GLTFLoader, groups the
// scene's objects by the `_LOD<n>` suffix, builds a THREE.LOD from them (level n at a distance
// growing with n), and checks the triangle ratios counted from three.js' geometries (LOD1 <= 25 %,
// LOD2 <= 5 % of LOD0), that each lower level carries its own card atlas, and that the LOD shows exactly
// one level at each camera distance. Run: NIWA_NATIVE=... NIWA_ROOT=... node tests/cli/lod_three.test.mjs
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, finish, native, root, run } from '../support/cli_pair.mjs';

if (!native || !root) {
  console.log('FAIL set NIWA_NATIVE (native niwa binary) and NIWA_ROOT (repo root)');
  process.exit(2);
}
const three = join(root, 'node_modules', 'three');
const THREE = await import(pathToFileURL(join(three, 'build', 'three.module.js')).href);
const { GLTFLoader } = await import(pathToFileURL(join(three, 'examples', 'jsm', 'loaders', 'GLTFLoader.js')).href);

// GLTFLoader decodes embedded PNGs through Blob -> object URL -> createImageBitmap; node has no
// `self` and no createImageBitmap: a stand-in that reads the PNG header's size.
globalThis.self ??= globalThis;
globalThis.createImageBitmap ??= async (blob) => {
  const bytes = new Uint8Array(await blob.arrayBuffer());
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  return { width: view.getUint32(16), height: view.getUint32(20), close() {} };
};

function load(bytes) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

// Triangles of every triangle mesh under `object` (three.js' geometries: index count / 3).
function triangles(object) {
  let sum = 0;
  object.traverse((o) => {
    if (!o.isMesh || o.isLine) return;
    const g = o.geometry;
    sum += (g.index ? g.index.count : g.attributes.position.count) / 3;
  });
  return sum;
}

function materialNames(object) {
  const names = new Set();
  object.traverse((o) => {
    if (!o.material) return;
    for (const m of [o.material].flat()) names.add(m.name);
  });
  return [...names].sort();
}

// The name convention an LOD-grouping importer reads: `<base>_LOD<n>`, grouped by <base>.
function groupByLodSuffix(scene) {
  const groups = new Map();
  for (const child of scene.children) {
    const m = /^(.*)_LOD(\d+)$/.exec(child.name);
    if (!m) continue;
    if (!groups.has(m[1])) groups.set(m[1], []);
    groups.get(m[1])[Number(m[2])] = child;
  }
  return groups;
}

const dir = mkdtempSync(join(tmpdir(), 'niwa-lod-three-'));
try {
  for (const [preset, extra] of [['sakura', ['--max-triangles', '20000']], ['tsutsuji', []]]) {
    const out = join(dir, `${preset}.glb`);
    run(native, ['tree', 'grow', '--preset', preset, '--years', '15', ...extra, '--lod', '--out', out]);
    const gltf = await load(readFileSync(out));
    const groups = groupByLodSuffix(gltf.scene);
    check(`${preset}: one LOD group 'tree' from the names (${[...groups.keys()].join(', ')})`, groups.size === 1 && groups.has('tree'));
    const levels = groups.get('tree') ?? [];
    check(`${preset}: levels tree_LOD0, tree_LOD1, tree_LOD2 found`, levels.length === 3 && levels.every(Boolean));
    if (levels.length !== 3 || !levels.every(Boolean)) continue;

    const counts = levels.map(triangles);
    check(`${preset}: LOD0 ${counts[0]} triangles`, counts[0] > 0);
    check(`${preset}: LOD1 ${counts[1]} <= 25 % of LOD0 (${(100 * counts[1] / counts[0]).toFixed(2)} %)`, counts[1] * 100 <= counts[0] * 25);
    check(`${preset}: LOD2 ${counts[2]} <= 5 % of LOD0 (${(100 * counts[2] / counts[0]).toFixed(2)} %)`, counts[2] > 0 && counts[2] * 100 <= counts[0] * 5);
    for (let n = 1; n < 3; ++n) {
      const names = materialNames(levels[n]);
      // Its own card atlas (cards_<n>); bark tubes only where some wood is still thick enough.
      check(`${preset}: LOD${n} has its card-atlas material cards_${n} (${names.join(', ')})`, names.includes(`cards_${n}`));
    }

    // THREE.LOD from the group: the whole tree's size sets the switching distances.
    const box = new THREE.Box3().setFromObject(levels[0]);
    const size = box.getSize(new THREE.Vector3()).length();
    const lod = new THREE.LOD();
    levels.forEach((object, n) => lod.addLevel(object, n === 0 ? 0 : size * 4 * n));
    check(`${preset}: THREE.LOD with 3 levels`, lod.levels.length === 3 && lod.levels.every((l, n) => l.object === levels[n]));
    const camera = new THREE.PerspectiveCamera(45, 1, 0.1, 10000);
    const shown = [];
    for (const distance of [size, size * 6, size * 12]) {
      camera.position.set(0, 0, distance);
      camera.updateMatrixWorld();
      lod.updateMatrixWorld(true);
      lod.update(camera);
      shown.push(levels.map((o) => o.visible));
    }
    const expected = [[true, false, false], [false, true, false], [false, false, true]];
    check(`${preset}: near, middle, far camera show LOD0, LOD1, LOD2 only (${JSON.stringify(shown)})`,
      JSON.stringify(shown) === JSON.stringify(expected));
  }
  // --lod-layout msft, read by a client without MSFT_lod (three.js' own GLTFLoader): LOD0 alone.
  const siblings = join(dir, 'siblings.glb'), msft = join(dir, 'msft.glb');
  const base = ['tree', 'grow', '--preset', 'sakura', '--years', '15', '--max-triangles', '20000', '--lod'];
  run(native, [...base, '--out', siblings]);
  run(native, [...base, '--lod-layout', 'msft', '--out', msft]);
  const all = await load(readFileSync(siblings));
  const lod0 = all.scene.children.find((c) => c.name === 'tree_LOD0');
  const only = await load(readFileSync(msft));
  const names = only.scene.children.map((c) => c.name);
  check(`msft layout in three.js (no MSFT_lod plugin): the scene shows LOD0 only (${names.join(', ')}; ${triangles(only.scene)} triangles)`,
    JSON.stringify(names) === '["tree_LOD0"]' && triangles(only.scene) === triangles(lod0));
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
