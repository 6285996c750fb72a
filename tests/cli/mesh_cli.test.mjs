// `niwa mesh` end to end: bad mesh input gives one line and exit 2 (nothing written); closest and ray answers match
// npm three-mesh-bvh (an independent oracle, meshes loaded by three's GLTFLoader) on real ez-tree assets and the
// hand-made hierarchy; native and WASM print the same stats/closest/ray JSON (timings aside).
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { MeshBVH } from 'three-mesh-bvh';
import { glbBytes as glb, triangleBin } from '../support/glb_bytes.mjs';
import { cliArgv } from '../support/cli_pair.mjs';

const root = process.env.NIWA_ROOT;
const native = process.env.NIWA_NATIVE;
const wasm = join(root, 'build/wasm/bin/niwa.js');
const data = join(root, 'tests/data/meshes');
let passed = 0, failed = 0;
const check = (ok, what) => { ok ? passed++ : failed++; console.log(`${ok ? 'PASS' : 'FAIL'} ${what}`); };
const exec = (bin, args, cwd) => spawnSync(...cliArgv(bin, args), { encoding: 'utf8', cwd });
const json = (bin, args) => {
  const r = exec(bin, args);
  if (r.status !== 0) throw new Error(`${bin} ${args.join(' ')}: exit ${r.status}: ${r.stderr}`);
  return JSON.parse(r.stdout);
};
const haveWasm = existsSync(wasm);
if (!haveWasm) check(false, `WASM CLI missing at ${wasm}: build the wasm-release preset first`);
const binaries = haveWasm ? [native, wasm] : [native];

// 1. Bad input: one stderr line naming the flag and file, exit 2, empty stdout, no file left in the working folder.
const cases = [
  [['mesh', 'stats', '--mesh', join(data, 'empty.glb')], /^niwa: error: --mesh: empty\.glb: the file is empty$/],
  [['mesh', 'stats', '--mesh', join(data, 'truncated.glb')], /^niwa: error: --mesh: truncated\.glb: truncated: the \.glb header says 3316 bytes, the file has 1989$/],
  [['mesh', 'stats', '--mesh', join(data, 'not_gltf.glb')], /^niwa: error: --mesh: not_gltf\.glb: not glTF/],
  [['mesh', 'stats', '--mesh', join(data, 'nan.glb')], /^niwa: error: --mesh: nan\.glb: mesh 0 'nan' primitive 0 POSITION 1 is NaN or infinite$/],
  [['mesh', 'stats', '--mesh', join(data, 'lines_only.glb')], /^niwa: error: --mesh: lines_only\.glb: only points or lines \(2 primitives\), no triangles$/],
  [['mesh', 'stats', '--mesh', join(data, 'required_ext.glb')], /^niwa: error: --mesh: required_ext\.glb: required extension EXT_niwa_unknown is not supported$/],
  [['mesh', 'stats', '--mesh', join(data, 'too_many_triangles.glb')], /^niwa: error: --mesh: too_many_triangles\.glb: 4096000 triangles in the scene; the limit is 4000000 \(4 M\)$/],
  [['mesh', 'stats', '--mesh', join(data, 'no_such.glb')], /^niwa: error: --mesh: no_such\.glb: cannot open '.*no_such\.glb' \(missing or unreadable\)$/],
  [['mesh', 'stats', '--mesh', join(data, 'bad_index.obj')], /^niwa: error: --mesh: bad_index\.obj: line 5: vertex index 9 is out of range; must be in \[1, 3\] or \[-3, -1\]$/],
  [['mesh', 'stats', '--mesh', join(data, 'README.md')], /^niwa: error: --mesh: README\.md: unknown mesh file extension '\.md'; must be \.glb, \.gltf or \.obj$/],
  [['mesh', 'stats'], /^niwa: error: --mesh: required/],
  [['mesh', 'stats', '--scene', 'torus'], /^niwa: error: --scene: 'torus' is unknown; must be one of box, plane, cylinder, icosphere$/],
  [['mesh', 'stats', '--scene', 'box', '--subdivide', '9'], /^niwa: error: --subdivide: 9 is out of range; must be a whole number in \[0, 8\]$/],
  [['mesh', 'stats', '--scene', 'box', '--mesh', join(data, 'grass.glb')], /^niwa: error: --mesh: give only one of --mesh and --scene$/],
  [['mesh', 'closest', '--scene', 'box', '--point', '1,2'], /^niwa: error: --point: '1,2' is not three numbers; must be three numbers X,Y,Z/],
  [['mesh', 'closest', '--scene', 'box', '--point', '1,2,nan'], /^niwa: error: --point: '1,2,nan' is out of range/],
  [['mesh', 'closest', '--scene', 'box', '--point', '0,0,0', '--max-distance', '-1'], /^niwa: error: --max-distance: '-1' is out of range; must be a number in \[0, 1e30\] or inf/],
  [['mesh', 'ray', '--scene', 'box', '--origin', '0,0,0', '--dir', '0,0,0'], /^niwa: error: --dir: '0,0,0' is zero; must be a non-zero direction X,Y,Z$/],
  [['mesh', 'ray', '--scene', 'box', '--dir', '0,0,1'], /^niwa: error: --origin: required; must be three numbers X,Y,Z/],
];
for (const bin of binaries) {
  const label = bin.endsWith('.js') ? 'wasm' : 'native';
  const cwd = mkdtempSync(join(tmpdir(), 'niwa-mesh-'));
  for (const [args, pattern] of cases) {
    const r = exec(bin, args, cwd);
    const lines = r.stderr.trimEnd().split('\n');
    check(r.status === 2 && lines.length === 1 && pattern.test(lines[0]) && r.stdout === '',
      `${label} ${args.slice(0, 2).join(' ')} ${args.slice(2).map((a) => a.replace(data + '/', '')).join(' ')} -> exit ${r.status}, ${JSON.stringify(r.stderr.trim())}`);
  }
  check(readdirSync(cwd).length === 0, `${label}: bad input left no file in the working folder`);
}

// 1b. Hostile files built here (issue 34): deep JSON in extras (a stack overflow before), an accessor whose size
// wraps 64 and 32 bits, a negative short index, a millionfold instancing node graph, a FIFO: exit 2, one line, the
// same line natively and in WASM, quickly.
const gltfJson = ({ asset = '{"version": "2.0"}', sceneNodes = '[0]', nodes = '[{"mesh": 0}]', count = '3', indexType = 5123 } = {}) =>
  `{"asset": ${asset}, "scene": 0, "scenes": [{"nodes": ${sceneNodes}}], "nodes": ${nodes}, ` +
  '"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}], ' +
  `"accessors": [{"bufferView": 0, "componentType": 5126, "count": ${count}, "type": "VEC3"}, ` +
  `{"bufferView": 1, "componentType": ${indexType}, "count": 3, "type": "SCALAR"}], ` +
  '"bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}], ' +
  '"buffers": [{"byteLength": 44}]}';
const hostileDir = mkdtempSync(join(tmpdir(), 'niwa-hostile-mesh-'));
const deep = '['.repeat(30000) + ']'.repeat(30000);
let doubling = '[';
for (let i = 0; i < 20; i++) doubling += `{"children": [${i + 1}, ${i + 1}]},`;
doubling += '{"mesh": 0}]';
const hostile = {
  'deep_asset.glb': glb(gltfJson({ asset: `{"version": "2.0", "extras": ${deep}}` }), triangleBin()),
  'deep_node.glb': glb(gltfJson({ nodes: `[{"mesh": 0, "extras": {"a": ${deep}}}]` }), triangleBin()),
  'dup_key.glb': glb(gltfJson({ asset: '{"version": "2.0", "version": "2.0"}' }), triangleBin()),
  'wrap64.glb': glb(gltfJson({ count: '1537228672809129303' }), triangleBin()),
  'wrap32.glb': glb(gltfJson({ count: '357913943' }), triangleBin()),
  'negative_index.glb': glb(gltfJson({ indexType: 5122 }), triangleBin(-1)),
  'instances.glb': glb(gltfJson({ nodes: doubling }), triangleBin()),
  'flat_instances.glb': glb(gltfJson({ sceneNodes: `[${Array(1000001).fill(0).join(',')}]` }), triangleBin()),
};
for (const [name, bytes] of Object.entries(hostile)) writeFileSync(join(hostileDir, name), bytes);
const fifo = join(hostileDir, 'pipe.glb');
const made = spawnSync('mkfifo', [fifo]);
check(made.status === 0, 'mkfifo for the FIFO case');
const hostileCases = [
  ['deep_asset.glb', 'nested deeper than 32 levels'],
  ['deep_node.glb', 'nested deeper than 32 levels'],
  ['dup_key.glb', 'version: given twice in one object'],
  ['wrap64.glb', 'accessor 0 (1537228672809129303 elements) reads past the end of its buffer view (truncated file?)'],
  ['wrap32.glb', 'accessor 0 (357913943 elements) reads past the end of its buffer view (truncated file?)'],
  ['negative_index.glb', 'mesh 0 primitive 0 index 65535 is out of range; must be below its 3 vertices'],
  ['instances.glb', 'the scene places 2097151 node instances; the limit is 1000000 (1 M)'],
  ['flat_instances.glb', 'the scene places 1000001 node instances; the limit is 1000000 (1 M)'],
  ['pipe.glb', `cannot read '${fifo}': not a regular file`],
];
const hostileLines = {};
for (const bin of binaries) {
  const label = bin.endsWith('.js') ? 'wasm' : 'native';
  hostileLines[label] = [];
  for (const [name, message] of hostileCases) {
    for (const args of [['mesh', 'stats', '--mesh', join(hostileDir, name)],
      ['ivy', 'grow', '--mesh', join(hostileDir, name)]]) {
      const started = Date.now();
      const r = spawnSync(...cliArgv(bin, args),
        { encoding: 'utf8', cwd: hostileDir, timeout: 30000 });
      const ms = Date.now() - started;
      const line = r.stderr.trimEnd();
      hostileLines[label].push(line);
      check(r.status === 2 && line === `niwa: error: --mesh: ${name}: ${message}` && r.stdout === '' && ms < 10000,
        `${label} ${args.slice(0, 2).join(' ')} hostile ${name} -> exit ${r.status}, ${JSON.stringify(line.slice(0, 200))} (${ms} ms)`);
    }
  }
}
if (haveWasm) {
  check(JSON.stringify(hostileLines.native) === JSON.stringify(hostileLines.wasm),
    `native and WASM give the same ${hostileLines.native.length} lines for the hostile files`);
}

// 2. The oracle: three's GLTFLoader (textures stripped: node has no image decoder) + three-mesh-bvh.
function stripTextures(buf) {
  const len = buf.readUInt32LE(12);
  const j = JSON.parse(buf.subarray(20, 20 + len).toString());
  delete j.images; delete j.textures; delete j.samplers;
  for (const m of j.materials ?? []) {
    for (const k of Object.keys(m)) if (k.endsWith('Texture')) delete m[k];
    if (m.pbrMetallicRoughness) for (const k of Object.keys(m.pbrMetallicRoughness)) if (k.endsWith('Texture')) delete m.pbrMetallicRoughness[k];
    delete m.extensions;
  }
  let text = Buffer.from(JSON.stringify(j));
  text = Buffer.concat([text, Buffer.alloc((4 - (text.length % 4)) % 4, 0x20)]);
  const rest = buf.subarray(20 + len);
  const header = Buffer.alloc(20);
  header.writeUInt32LE(0x46546c67, 0); header.writeUInt32LE(2, 4); header.writeUInt32LE(20 + text.length + rest.length, 8);
  header.writeUInt32LE(text.length, 12); header.writeUInt32LE(0x4e4f534a, 16);
  const out = Buffer.concat([header, text, rest]);
  return out.buffer.slice(out.byteOffset, out.byteOffset + out.byteLength);
}
const loadOracle = (file) => new Promise((resolve, reject) => {
  new GLTFLoader().parse(stripTextures(readFileSync(join(data, file))), '', (gltf) => {
    gltf.scene.updateMatrixWorld(true);
    const tris = [];
    gltf.scene.traverse((o) => {
      if (!o.isMesh) return;
      const g = o.geometry, p = g.attributes.position, idx = g.index;
      const n = idx ? idx.count : p.count;
      const v = (i) => new THREE.Vector3().fromBufferAttribute(p, idx ? idx.getX(i) : i).applyMatrix4(o.matrixWorld);
      for (let i = 0; i + 2 < n; i += 3) {
        const a = v(i), b = v(i + 1), c = v(i + 2);
        if (new THREE.Vector3().crossVectors(b.clone().sub(a), c.clone().sub(a)).lengthSq() === 0) continue;
        tris.push(a, b, c);
      }
    });
    const geometry = new THREE.BufferGeometry().setFromPoints(tris);
    resolve({ bvh: new MeshBVH(geometry), tris, triangles: tris.length / 3 });
  }, reject);
});

// Deterministic query points: an LCG over the mesh bounds grown by 30 %.
function* lcgPoints(bounds, count, seed) {
  let s = seed >>> 0;
  const next = () => { s = (Math.imul(s, 1664525) + 1013904223) >>> 0; return s / 4294967296; };
  const lo = bounds.min, hi = bounds.max;
  for (let i = 0; i < count; i++) {
    yield [0, 1, 2].map((k) => { const pad = 0.3 * (hi[k] - lo[k]); return lo[k] - pad + next() * (hi[k] - lo[k] + 2 * pad); });
  }
}
const fmt = (v) => v.map((x) => String(Math.fround(x))).join(',');
const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const triangleDistance = (oracle, t, p) => {
  const tri = new THREE.Triangle(oracle.tris[3 * t], oracle.tris[3 * t + 1], oracle.tris[3 * t + 2]);
  const q = new THREE.Vector3();
  tri.closestPointToPoint(new THREE.Vector3(...p), q);
  return q.distanceTo(new THREE.Vector3(...p));
};

for (const file of ['flower_blue.glb', 'grass.glb', 'hierarchy.glb']) {
  const oracle = await loadOracle(file);
  const stats = json(native, ['mesh', 'stats', '--mesh', join(data, file)]);
  check(stats.triangles === oracle.triangles, `${file}: ${stats.triangles} triangles, three.js ${oracle.triangles}`);
  const size = dist(stats.bounds.min, stats.bounds.max);
  const tol = 1e-5 * size;
  let closestOk = 0, closestN = 0, worst = 0;
  for (const p of lcgPoints(stats.bounds, 12, 7)) {
    const got = json(native, ['mesh', 'closest', '--mesh', join(data, file), '--point', fmt(p)]);
    const want = oracle.bvh.closestPointToPoint(new THREE.Vector3(...p.map(Math.fround)));
    const d = Math.abs(got.distance - want.distance);
    worst = Math.max(worst, d, dist(got.point, want.point.toArray()));
    // The triangle named by the CLI is (one of) the closest: its own distance matches.
    const own = Math.abs(triangleDistance(oracle, got.triangle, p.map(Math.fround)) - got.distance);
    closestN++;
    if (got.found && d <= tol && own <= tol) closestOk++;
  }
  check(closestOk === closestN, `${file}: closest matches three-mesh-bvh on ${closestOk}/${closestN} points (worst ${worst.toExponential(2)} m, tolerance ${tol.toExponential(2)})`);
  let rayOk = 0, rayN = 0, hits = 0;
  for (const p of lcgPoints(stats.bounds, 12, 11)) {
    // Aim at the centroid of a triangle so that most rays hit (a nearer one may be hit first).
    const t = (rayN * 37) % oracle.triangles;
    const target = [0, 1, 2].map((k) => [0, 1, 2].reduce((acc, c) => acc + oracle.tris[3 * t + c].getComponent(k), 0) / 3);
    const dir = target.map((x, k) => x - p[k]);
    const got = json(native, ['mesh', 'ray', '--mesh', join(data, file), '--origin', fmt(p), '--dir', fmt(dir)]);
    const ray = new THREE.Ray(new THREE.Vector3(...p.map(Math.fround)), new THREE.Vector3(...dir.map(Math.fround)).normalize());
    const want = oracle.bvh.raycastFirst(ray, THREE.DoubleSide);
    rayN++;
    if (!!want !== got.hit) continue;
    if (!want) { rayOk++; continue; }
    hits++;
    if (Math.abs(got.distance - want.distance) <= tol && dist(got.point, want.point.toArray()) <= tol) rayOk++;
  }
  check(rayOk === rayN && hits > 0, `${file}: ray matches three-mesh-bvh on ${rayOk}/${rayN} rays (${hits} hits)`);
}

// 3. Native == WASM: the same JSON apart from the ms_* timings.
const noTimes = (o) => JSON.stringify(Object.fromEntries(Object.entries(o).filter(([k]) => !k.startsWith('ms_'))));
if (haveWasm) {
  const runs = [
    ['mesh', 'stats', '--mesh', join(data, 'flower_blue.glb')],
    ['mesh', 'stats', '--mesh', join(data, 'hierarchy.glb'), '--subdivide', '2'],
    ['mesh', 'stats', '--mesh', join(data, 'shapes.obj')],
    ['mesh', 'stats', '--scene', 'icosphere'],
    ['mesh', 'closest', '--mesh', join(data, 'flower_blue.glb'), '--point', '0.1,0.2,0.05'],
    ['mesh', 'closest', '--mesh', join(data, 'grass.glb'), '--point', '0.3,-0.1,0.7', '--max-distance', '5'],
    ['mesh', 'closest', '--scene', 'cylinder', '--point', '0.2,0.5,0.1'],
    ['mesh', 'ray', '--mesh', join(data, 'flower_blue.glb'), '--origin', '0,1,0', '--dir', '0.01,-1,0.02'],
    ['mesh', 'ray', '--mesh', join(data, 'hierarchy.glb'), '--origin', '10.2,0.3,5', '--dir', '0,0,-1'],
    ['mesh', 'ray', '--scene', 'icosphere', '--origin', '3,0.1,0.2', '--dir', '-1,0,0'],
  ];
  for (const args of runs) {
    const a = noTimes(json(native, args)), b = noTimes(json(wasm, args));
    check(a === b, `native == wasm: ${args.slice(1).map((x) => x.replace(data + '/', '')).join(' ')} -> ${a.slice(0, 120)}`);
  }
  // Draco: decoded natively; the WASM build says in one line that the page decodes it.
  const n = exec(native, ['mesh', 'stats', '--mesh', join(data, 'rock1.glb')]);
  const w = exec(wasm, ['mesh', 'stats', '--mesh', join(data, 'rock1.glb')]);
  check(n.status === 0 && JSON.parse(n.stdout).triangles === 1756 && JSON.parse(n.stdout).draco_primitives === 1,
    `native decodes Draco rock1.glb: ${n.stdout.trim().slice(0, 80)}`);
  check(w.status === 2 && w.stderr.trim().split('\n').length === 1 && /this build cannot decode Draco: the page decodes it/.test(w.stderr),
    `wasm rock1.glb -> exit ${w.status}, ${JSON.stringify(w.stderr.trim())}`);
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
