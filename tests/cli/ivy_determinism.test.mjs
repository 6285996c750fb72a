// Ivy CLI: native == WASM `niwa ivy grow --stats` (minus the ms fields) and the .json, byte for byte,
// for every built-in scene and seeds 1-5; the .glb validates with Khronos' gltf-validator (0 errors)
// and carries _BIRTH_STEP; hostile input is one line naming the field, exit 2, no file left behind.
// The WASM runs are batched in niwa_cli_batch.js (the same RunCli; a niwa.js start under node costs
// about 0.3 CPU s), every NIWA_IVY_WASM_EVERY-th (default 4) one niwa.js process each
// (support/cli_batch.mjs PreparedCli).
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { PreparedCli } from '../support/cli_batch.mjs';
import { buildName, check, finish, native, requireWasm, root, run as runOne, spawn as spawnOne, wasm, withoutMs } from '../support/cli_pair.mjs';

requireWasm();

const dir = mkdtempSync(join(tmpdir(), 'niwa-ivy-'));
const W = new PreparedCli(wasm, { every: Math.max(1, Number(process.env.NIWA_IVY_WASM_EVERY || 4)), work: dir, jobs: 1 });
const run = (cmd, args) => (cmd === wasm ? W.run(args) : runOne(cmd, args));
const spawn = (cmd, args) => (cmd === wasm ? W.spawn(args) : spawnOne(cmd, args));
const scenes = run(native, ['ivy', 'scenes']).trim().split('\n').map((l) => l.split('\t')[0]);
check(`scenes listed: ${scenes.join(', ')}`, scenes.includes('cubes4') && scenes.length >= 7);
const growArgs = (scene, seed) => ['ivy', 'grow', '--scene', scene, '--steps', '50', '--seed', String(seed), '--stats'];
const extras = [['--seed-point', 'side', '--seed-point', 'column'], ['--preset', 'improved'],
  ['--preset', 'artist', '--steps', '120']];
// The artist preset on the overhang (tendrils, leaves by light, leaf cover): the .glb byte for byte.
const artistGlb = (tag) => ['ivy', 'grow', '--scene', 'overhang', '--preset', 'artist', '--steps', '100', '--out', join(dir, `artist-${tag}.glb`)];
const hostile = [
  [['--set', 't1=0.9'], 't1'], [['--steps', '-1'], '--steps'], [['--set', 'L=nan'], '--set: L'],
  [['--seed-point', '600,10,450'], '--seed-point'], [['--url', 'steps=-3'], '--url'],
  [['--url', 't1=abc'], '--url'], [['--preset', 'x'], '--preset'], [['--scene', 'moon'], '--scene'],
  [['--seed', '-2'], '--seed'], [['--set', 'eps=30'], 'eps'], [['--mesh', join(dir, 'none.glb'), '--seed-point', '0,0,0'], '--mesh'],
];
await W.prepare([
  ...scenes.flatMap((scene) => [1, 2, 3, 4, 5].map((seed) => [...growArgs(scene, seed), '--out', join(dir, `${scene}-${seed}-w.json`)])),
  ...extras.map((extra) => ['ivy', 'grow', '--scene', 'cubes4', ...extra, '--stats']),
  artistGlb('w'),
  ...hostile.map(([args]) => ['ivy', 'grow', ...args, '--out', join(dir, 'bad.json')]),
]);
for (const scene of scenes) {
  for (let seed = 1; seed <= 5; seed++) {
    const args = growArgs(scene, seed);
    const a = JSON.parse(run(native, [...args, '--out', join(dir, `${scene}-${seed}-n.json`)]));
    const b = JSON.parse(run(wasm, [...args, '--out', join(dir, `${scene}-${seed}-w.json`)]));
    const same = JSON.stringify(withoutMs(a)) === JSON.stringify(withoutMs(b));
    check(`${scene} seed ${seed}: --stats native == WASM (${a.internodes} internodes, ${a.laterals} laterals)`, same);
    const ja = readFileSync(join(dir, `${scene}-${seed}-n.json`), 'utf8');
    const jb = readFileSync(join(dir, `${scene}-${seed}-w.json`), 'utf8');
    check(`${scene} seed ${seed}: .json identical (${ja.length} bytes)`, ja.length > 100 && ja === jb);
  }
}
// cubes4 side with two seed points, and the improved preset, also agree.
for (const extra of extras) {
  const args = ['ivy', 'grow', '--scene', 'cubes4', ...extra, '--stats'];
  const a = JSON.parse(run(native, args)), b = JSON.parse(run(wasm, args));
  check(`cubes4 ${extra.join(' ')}: native == WASM`, JSON.stringify(withoutMs(a)) === JSON.stringify(withoutMs(b)));
}

run(native, artistGlb('n'));
run(wasm, artistGlb('w'));
const artistN = readFileSync(join(dir, 'artist-n.glb')), artistW = readFileSync(join(dir, 'artist-w.glb'));
check(`overhang, artist: .glb native == WASM (${artistN.length} bytes)`, artistN.length > 1000 && artistN.equals(artistW));

// .glb: validator-clean, with _BIRTH_STEP.
const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;
const glbPath = join(dir, 'ivy.glb');
run(native, ['ivy', 'grow', '--scene', 'cubes4', '--out', glbPath]);
const glb = new Uint8Array(readFileSync(glbPath));
const report = await validator.validateBytes(glb);
check(`ivy.glb: ${report.issues.numErrors} validator errors, ${report.issues.numWarnings} warnings`, report.issues.numErrors === 0);
const jsonLength = new DataView(glb.buffer, glb.byteOffset).getUint32(12, true);
const gltf = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + jsonLength)));
const names = gltf.nodes.map((n) => n.name);
check(`ivy.glb nodes: ${names.join(', ')}`, ['ivy_stems', 'ivy_leaves', 'ivy_suckers'].every((n) => names.includes(n)));
const ivyMeshes = gltf.meshes.filter((m) => m.name.startsWith('ivy_'));
check('every ivy_* primitive of ivy.glb has _BIRTH_STEP', ivyMeshes.length === 3 && ivyMeshes.every((m) => '_BIRTH_STEP' in m.primitives[0].attributes));

// Hostile input: one line, exit 2, no file (the cases in `hostile` above).
for (const [args, field] of hostile) {
  for (const cmd of [native, wasm]) {
    const out = join(dir, 'bad.json');
    const r = spawn(cmd, ['ivy', 'grow', ...args, '--out', out]);
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} ${args.join(' ')}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${field}`) && !existsSync(out));
  }
}
console.log(`(the WASM runs: ${W.summary()})`);
rmSync(dir, { recursive: true, force: true });
finish();
