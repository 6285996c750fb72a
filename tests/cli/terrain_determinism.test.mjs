// Terrain CLI: native == WASM `niwa terrain grow --stats` (minus the ms fields) and the contour-tree
// .json, byte for byte, for every built-in seed × method and two RNG seeds, and `terrain shrink`'s
// JSON and figure SVG for every seed × join; the erosion pass (thermal, hydraulic, both: --stats
// and the --heightmap .png) on jacksboro, valleys and a drawn contour; hostile input is one line naming the field, exit 2, no
// file left behind; --repair grows a crossing contour the same in both builds. The WASM runs are
// batched in niwa_cli_batch.js (the same RunCli; a niwa.js start under node costs about 0.3 CPU s),
// every NIWA_TERRAIN_WASM_EVERY-th (default 4) one niwa.js process each (support/cli_batch.mjs
// PreparedCli).
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PreparedCli } from '../support/cli_batch.mjs';
import { buildName, check, finish, native, requireWasm, run as runOne, spawn as spawnOne, wasm, withoutMs } from '../support/cli_pair.mjs';

requireWasm();

const dir = mkdtempSync(join(tmpdir(), 'niwa-terrain-'));
const W = new PreparedCli(wasm, { every: Math.max(1, Number(process.env.NIWA_TERRAIN_WASM_EVERY || 4)), work: dir, jobs: 1 });
const run = (cmd, args) => (cmd === wasm ? W.run(args) : runOne(cmd, args));
const spawn = (cmd, args) => (cmd === wasm ? W.spawn(args) : spawnOne(cmd, args));
const seeds = JSON.parse(run(native, ['terrain', 'seeds'])).map((s) => s.name);
check(`seeds listed: ${seeds.join(', ')}`, seeds.includes('disk') && seeds.length >= 3);
const methods = ['simple', 'midpoint', 'fourier', 'improved'];
const joins = ['miter', 'bevel', 'round', 'capped'];
const growArgs = (seedName, method, rng) => ['terrain', 'grow', '--builtin', seedName, '--method', method, '--seed', String(rng), '--stats'];
const shrinkArgs = (seedName, joinName) => ['terrain', 'shrink', '--builtin', seedName, '--join', joinName, '--steps', '3',
  '--displace', '20,8,0,30', '--seed', '2', '--clean-len', '1'];
// The erosion pass (core/terrain/erosion.h): the same bytes in both builds.
const drawn = join(dir, 'drawn.json');
writeFileSync(drawn, JSON.stringify({ points: Array.from({ length: 90 }, (_, k) => {
  const a = (2 * Math.PI * k) / 90, r = 250 * (1 + 0.3 * Math.sin(5 * a) + 0.1 * Math.cos(3 * a + 1));
  return [Math.round(r * Math.cos(a) * 100) / 100, Math.round(r * Math.sin(a) * 100) / 100];
}) }));
const erosionCases = [['--builtin', 'jacksboro'], ['--builtin', 'valleys'], ['--contour', drawn]].flatMap((src) =>
  // (thermal at 15°: jacksboro's slopes, 14° on average, are below the default 35°, nothing slips)
  [1, 2, 3].map((mode) => [...src, '--method', 'improved', '--set', `erosion=${mode}`, '--set', 'res=128',
    ...(mode === 1 ? ['--set', 'erosion_talus=15'] : [])]));
const erosionArgs = (args, k, build) => ['terrain', 'grow', ...args, '--stats', '--heightmap', join(dir, `erosion-${k}-${build}.png`)];
await W.prepare([
  ...erosionCases.map((args, k) => erosionArgs(args, k, 'w')),
  ...seeds.flatMap((seedName) => methods.flatMap((method) => [1, 2].map((rng) =>
    [...growArgs(seedName, method, rng), '--contours', join(dir, `${seedName}-${method}-${rng}-w.json`)]))),
  ...seeds.flatMap((seedName) => joins.map((joinName) => [...shrinkArgs(seedName, joinName), '--svg', join(dir, `${seedName}-${joinName}-w.svg`)])),
]);
for (const seedName of seeds) {
  for (const method of methods) {
    for (const rng of [1, 2]) {
      const args = growArgs(seedName, method, rng);
      const na = join(dir, `${seedName}-${method}-${rng}-n.json`), wa = join(dir, `${seedName}-${method}-${rng}-w.json`);
      const a = JSON.parse(run(native, [...args, '--contours', na]));
      const b = JSON.parse(run(wasm, [...args, '--contours', wa]));
      check(`${seedName} ${method} seed ${rng}: --stats native == WASM (${a.levels} levels, ${a.peaks} peaks)`,
        JSON.stringify(withoutMs(a)) === JSON.stringify(withoutMs(b)));
      const ja = readFileSync(na, 'utf8'), jb = readFileSync(wa, 'utf8');
      check(`${seedName} ${method} seed ${rng}: contours .json identical (${ja.length} bytes)`, ja.length > 100 && ja === jb);
    }
  }
}

for (const [k, args] of erosionCases.entries()) {
  const a = JSON.parse(run(native, erosionArgs(args, k, 'n')));
  const b = JSON.parse(run(wasm, erosionArgs(args, k, 'w')));
  const pa = readFileSync(join(dir, `erosion-${k}-n.png`)), pb = readFileSync(join(dir, `erosion-${k}-w.png`));
  check(`${args.slice(0, 2).join(' ').replace(dir, '')} ${args[5]}: --stats (moved ${Math.round(a.erosion?.volume_moved)} m³, pits ${a.erosion?.pits_before} -> ${a.erosion?.pits_after}) and heightmap (${pa.length} bytes) native == WASM`,
    a.erosion?.volume_moved > 0 && typeof a.ms_erosion === 'number' && JSON.stringify(withoutMs(a)) === JSON.stringify(withoutMs(b)) && pa.equals(pb));
}

// The traced shrinking algorithm (Figs 2-8, 12): the JSON (with every ring) and the SVG, byte for byte.
for (const seedName of seeds) {
  for (const joinName of joins) {
    const args = shrinkArgs(seedName, joinName);
    const na = join(dir, `${seedName}-${joinName}-n.svg`), wa = join(dir, `${seedName}-${joinName}-w.svg`);
    const a = run(native, [...args, '--svg', na]);
    const b = run(wasm, [...args, '--svg', wa]);
    const sa = readFileSync(na, 'utf8'), sb = readFileSync(wa, 'utf8');
    check(`${seedName} shrink ${joinName}: JSON (${a.length} bytes) and SVG (${sa.length} bytes) native == WASM`,
      a.length > 100 && a === b && sa === sb);
  }
}

// Hostile input: one line, exit 2, no file.
const crossing = join(dir, 'crossing.json');
writeFileSync(crossing, JSON.stringify({ points: [[0, 0], [100, 100], [100, 0], [0, 100]] }));
const hostile = [
  [['--builtin', 'moon'], '--builtin'], [['--method', 'x'], '--method'], [['--seed', '-1'], '--seed'],
  [['--set', 'c=0.5'], '--set'], [['--set', 'd=0'], '--set'], [['--set', 'd=nan'], '--set'],
  [['--contour', join(dir, 'none.json')], '--contour'], [['--contour', crossing], '--contour'],
  // The seed is a state field, not a table row (issue 28 item 6): --set does not take it.
  [['--set', 'seed=3'], '--set'], [['--seed', '4294967296'], '--seed'],
  // Erosion rows: the table's range in the line.
  [['--set', 'erosion=4'], '--set: erosion: 4 is out of range; must be a whole number in [0, 3]'],
  [['--set', 'erosion_talus=95'], '--set: erosion_talus: 95 is out of range; must be a number in [1, 89]'],
];
const hostileArgs = (args) => ['terrain', 'grow', ...(args[0] === '--builtin' || args[0] === '--contour' ? [] : ['--builtin', 'disk']), ...args,
  '--contours', join(dir, 'bad.json')];
// The seed cases' state files (below) are written here, before the runs are prepared.
const oldState = join(dir, 'old_state.json'), newState = join(dir, 'new_state.json');
writeFileSync(oldState, JSON.stringify({ preset: 'fig16', builtin: 'disk', params: { seed: 6, res: 32 } }));
writeFileSync(newState, JSON.stringify({ preset: 'fig16', builtin: 'disk', seed: 6, params: { res: 32 } }));
const seedCases = [
  [['--url', 'builtin=disk&seed=5&res=32'], 5, 'builtin=disk&seed=5&res=32'],
  [['--url', 'builtin=disk&seed=5&res=32', '--seed', '9'], 9, 'builtin=disk&seed=9&res=32'],
  // (--method resets the rows to the preset's, res too; the seed stays)
  [['--url', 'builtin=disk&seed=5&res=32', '--method', 'fig13b'], 5, 'preset=fig13b&builtin=disk&seed=5'],
  [['--params', oldState], 6, 'preset=fig16&builtin=disk&seed=6&res=32'],
  [['--params', newState], 6, 'preset=fig16&builtin=disk&seed=6&res=32'],
  [['--params', newState, '--seed', '0'], 0, 'preset=fig16&builtin=disk&seed=0&res=32'],
  [['--builtin', 'disk', '--set', 'clean_angle=12', '--set', 'max_levels=50', '--seed', '3', '--set', 'res=32'], 3,
    'builtin=disk&clean_angle=12&seed=3&max_levels=50&res=32'],
];
const repairArgs = ['terrain', 'grow', '--contour', crossing, '--repair', '--stats'];
await W.prepare([...hostile.map(([args]) => hostileArgs(args)), ...seedCases.map(([args]) => ['terrain', 'grow', ...args, '--stats']), repairArgs]);
for (const [args, field] of hostile) {
  for (const cmd of [native, wasm]) {
    const out = join(dir, 'bad.json');
    const r = spawn(cmd, hostileArgs(args));
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} ${args.join(' ')}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${field}`) && !existsSync(out));
  }
}

// The seed as a state field (issue 28 item 6), in both builds: --seed over --url and --params, a
// preset (--method) keeps the link's seed, a state file of when it was a row (params.seed) reads,
// and the link carries it where its row stood (seedCases, above).
for (const [args, seed, url] of seedCases) {
  const [a, b] = [native, wasm].map((cmd) => withoutMs(JSON.parse(run(cmd, ['terrain', 'grow', ...args, '--stats']))));
  check(`${args.join(' ')}: seed ${a.seed}, url ${a.url}, native == WASM`,
    a.seed === seed && a.url === url && JSON.stringify(a) === JSON.stringify(b));
}

// --repair: the crossing contour made simple as the page makes a drawing (core/terrain/
// contour_repair.h), with one notice line; the same mountain in both builds, and its link regrows it.
const repaired = [native, wasm].map((cmd) => spawn(cmd, repairArgs));
for (const [k, r] of repaired.entries()) {
  check(`${buildName([native, wasm][k])} --contour crossing.json --repair: exit ${r.status}, "${r.stderr.trim()}"`,
    r.status === 0 && /^niwa: repaired: the seed contour crossed itself \((\d+ loops? cut, §4\.4 method 2|its largest simple piece kept)\): \d+ points\n$/.test(r.stderr));
}
if (repaired.every((r) => r.status === 0)) {
  const [a, b] = repaired.map((r) => withoutMs(JSON.parse(r.stdout)));
  check(`--repair: --stats native == WASM (${a.levels} levels)`, JSON.stringify(a) === JSON.stringify(b));
  const again = withoutMs(JSON.parse(run(native, ['terrain', 'grow', '--url', a.url, '--stats'])));
  check(`--repair: --url of its stats regrows it (${a.url.slice(0, 60)})`, JSON.stringify(again) === JSON.stringify(a));
}
console.log(`(the WASM runs: ${W.summary()})`);
rmSync(dir, { recursive: true, force: true });
finish();
