// Issue 16 fuzz test: random flags, values, JSON files and hashes from a fixed seed, a bounded count
// (NIWA_FUZZ_COUNT, default 600; NIWA_FUZZ_JOBS at a time, default 2), against the CLI in NIWA_NATIVE
// (the release build under ctest, the ASan + UBSan build under scripts/test). Every run must exit 0 or 2 (never 1, 134 or a signal),
// within 30 s, with exactly one stderr line when it fails, and leave no file behind on failure
// (no temporary ever). A failing case is printed with its arguments so it can be replayed.
import { spawn } from 'node:child_process';
import { mkdtempSync, readdirSync, rmSync, writeFileSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { batchOf, runBatch } from '../support/cli_batch.mjs';
import { check, finish, native } from '../support/cli_pair.mjs';

const COUNT = Number(process.env.NIWA_FUZZ_COUNT || 600);
const SEED = Number(process.env.NIWA_FUZZ_SEED || 16);
let state = SEED;  // mulberry32, fixed seed (16): the same cases on every run
const random = () => {
  state = (state + 0x6d2b79f5) | 0;
  let t = Math.imul(state ^ (state >>> 15), 1 | state);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
const pick = (list) => list[Math.floor(random() * list.length)];

const work = mkdtempSync(join(tmpdir(), 'niwa-fuzz-'));
const inputs = join(work, 'in');
mkdirSync(inputs);
// Two runs at a time (NIWA_FUZZ_JOBS), each with its own output folder; the cases are drawn first, in
// order, so the seed gives the same cases whatever the number of jobs.
const JOBS = Math.max(1, Number(process.env.NIWA_FUZZ_JOBS || 2));
const OUT = '\u0000OUT\u0000';  // stands for the running job's output folder in a case's arguments

// Hostile and valid values. Valid numbers stay small so that every run is quick.
const NUMBERS = ['', '0', '1', '2', '3', '010', '0x10', '0x1p3', '1e39', '-1', 'nan', 'inf', '1e400',
  '1.5', '+2', ' 2', '2 ', '-0', '9999999999999999999', '-18446744073709551615', '2e0', '.5', '1,2',
  '\x1b[31m2', '２'];
const TEXT = ['', 'binary', 'sakura', 'oak', '\x1b]0;x\x07', 'x'.repeat(5000), 'a\nb', '%00', '../..',
  'disk', 'cubes4', 'wall', 'paper', 'hybrid', 'full', 'cluster', 'bvh', 'linear', 'box', 'plane'];
const VECTORS = ['1,2,3', '0,0,0', '1e39,0,0', 'nan,0,0', '1,2', '1,2,3,4', ',,', '0.5,0.3,10,0,1,0',
  '0,0.3,10,1e39,0,0', '0,9,10,0,0,0', '-1e30,1e30,0', 'seed0'];
const SETS = ['alpha_t=0.5', 'alpha_t=2', 'gamma=0x1', '=', 'k', 'gust_on=7', 'seed=010', 'nope=1',
  'N_high=1e400', 'steps=3', 'd=0', 'gamma=', 'res=64'];
const HASH_KEYS = ['preset', 'seed', 'years', 'gamma', 'prune', 'cam', 'steps', 'wind_speed', 'x',
  'gust_on', '%3Cb%3E', 'ivy.steps'];
const HASH_VALUES = ['1', '2', '010', '0x10', 'sakura', 'binary', '1:b1', '5%26mode%3Dfull', '%1b',
  '1e39', '', '0,0.3,10,0,1,0', '%'];
const JSON_FILES = [
  '{"gamma": 0.5}', '{"gamma": 0.5, "gamma": 0.6}', '{"params": {"gamma": 0.5}, "alpha_t": 1}',
  '[' .repeat(5000) + ']'.repeat(5000), '{"gamma": 1e400}', '{"gamma": "0x1"}', '', '{', 'null',
  '{"points": [[0,0],[10,0],[10,10],[0,10]]}', '{"points": [[0,0],[1e39,0],[0,1]]}',
  '{"preset": "paper", "steps": 3, "params": {}}', '{"seed": "010", "steps": 2}',
  '\u0000\u0001\u00ff', '{"gust_on": 7}', '{"points": []}'];

function hash() {
  if (random() < 0.05) return 'years=1' + '0'.repeat(16400);
  const n = 1 + Math.floor(random() * 5);
  return Array.from({ length: n }, () => `${pick(HASH_KEYS)}=${pick(HASH_VALUES)}`).join('&');
}
let files = 0;
function jsonFile() {
  if (random() < 0.1) return pick(['/dev/zero', join(inputs, 'missing.json'), inputs]);
  const path = join(inputs, `f${files++}.json`);
  writeFileSync(path, pick(JSON_FILES));
  return path;
}
const outPath = () => OUT + '/' + (pick(['o.glb', 'o.json', 'o.svg', 'o.csv', 'o.lsys', 'o.zzz', 'no/such/o.glb', 'x'.repeat(255) + '.json']));

// Each command's base arguments (quick ones) and the flags the fuzzer may add.
const COMMANDS = [
  { base: ['tree', 'grow', '--preset', 'binary', '--years', '2'],
    flags: { '--years': NUMBERS, '--seed': NUMBERS, '--set': SETS, '--params': jsonFile, '--url': hash,
      '--prune': ['1:b1', '2:since1', 'x', '0x1:b1'], '--out': outPath, '--stats': null, '--svg-width': NUMBERS,
      '--svg-leaves': NUMBERS, '--caption': TEXT, '--preset': TEXT } },
  { base: ['tree', 'sway', '--preset', 'binary', '--years', '2', '--duration', '1'],
    flags: { '--wind': NUMBERS, '--dt': ['0.05', '0', '0x1', '-1', ''], '--gust': ['1:6', '7:6', 'a:b', ':', '0x1:2'],
      '--tips': NUMBERS, '--fps': NUMBERS, '--out': outPath, '--csv': outPath, '--svg': outPath,
      '--max-joints': NUMBERS, '--max-triangles': NUMBERS, '--key-error': NUMBERS, '--full-mesh': null,
      '--params': jsonFile, '--url': hash, '--set-sway': SETS, '--stats': null } },
  { base: ['tree', 'render-stats', '--preset', 'binary', '--years', '2'],
    flags: { '--cam': VECTORS, '--target': VECTORS, '--yaw': NUMBERS, '--pitch': NUMBERS, '--width': NUMBERS,
      '--fov': NUMBERS, '--threshold': NUMBERS, '--card-planes': NUMBERS, '--mode': TEXT, '--url': hash } },
  { base: ['tree', 'mappings', '--preset', 'binary', '--years', '2'],
    flags: { '--prune': ['1:b1', 'x', '1:b999'], '--params': jsonFile, '--set': SETS } },
  { base: ['ivy', 'grow', '--steps', '3'],
    flags: { '--steps': NUMBERS, '--seed': NUMBERS, '--scene': TEXT, '--seed-point': VECTORS, '--set': SETS,
      '--params': jsonFile, '--url': hash, '--out': outPath, '--stats': null, '--accel': TEXT,
      '--subdivide': NUMBERS, '--preset': TEXT, '--units': TEXT } },
  { base: ['terrain', 'grow', '--set', 'res=32'],
    flags: { '--builtin': TEXT, '--contour': jsonFile, '--method': ['simple', 'fourier', 'fig9a', 'x', ''],
      '--seed': NUMBERS, '--set': SETS, '--contours': outPath, '--stats': null } },
  { base: ['terrain', 'shrink', '--builtin', 'disk'],
    flags: { '--d': NUMBERS, '--c': NUMBERS, '--steps': NUMBERS, '--join': ['round', 'miter', 'x', ''],
      '--displace': VECTORS, '--contour': jsonFile, '--clean-len': NUMBERS, '--svg': outPath } },
  { base: ['mesh', 'closest', '--scene', 'box'],
    flags: { '--point': VECTORS, '--max-distance': NUMBERS, '--subdivide': NUMBERS, '--mesh': jsonFile } },
  { base: ['params'], flags: { '--json': null } },
];

function caseArgs() {
  const command = pick(COMMANDS);
  const args = [...command.base];
  const names = Object.keys(command.flags);
  const n = Math.floor(random() * 4);
  for (let i = 0; i < n; ++i) {
    const name = pick(names);
    const source = command.flags[name];
    if (source === null) {
      args.push(random() < 0.8 ? name : `${name}=${pick(['yes', '0', ''])}`);
    } else {
      const value = typeof source === 'function' ? source() : pick(source);
      args.push(...(random() < 0.9 ? [name, value] : [`${name}=${value}`]));
    }
  }
  return args;
}

const show = (args) => JSON.stringify(args.map((a) => (a.length > 80 ? `${a.slice(0, 40)}...(${a.length})` : a)));
// One run of the CLI: exit status, signal, stderr, and an error when it did not finish within 30 s.
function run(args) {
  return new Promise((resolve) => {
    const child = spawn(native, args, { timeout: 30000, stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.setEncoding('utf8');
    child.stderr.on('data', (chunk) => { if (stderr.length < (64 << 20)) stderr += chunk; });
    let error = null;
    child.on('error', (e) => { error = e; });
    child.on('close', (status, signal) => {
      if (signal === 'SIGTERM' && !error) error = { code: 'ETIMEDOUT' };
      resolve({ status, signal, stderr, error });
    });
  });
}
const cases = Array.from({ length: COUNT }, caseArgs);
const started = Date.now();
let bad = 0;
const exits = { 0: 0, 2: 0 };
const took = [];  // [ms, case, args]: the slowest are printed, to keep the suite's time in view
// The problems of one case's result, its output folder checked after it ran.
function problemsOf(r, outs) {
  const lines = r.stderr ? r.stderr.trimEnd().split('\n') : [];
  const left = readdirSync(outs);
  if (r.status === 0 || r.status === 2) ++exits[r.status];
  const problems = [];
  if (r.error) problems.push(`did not finish: ${r.error.code}`);
  if (r.status !== 0 && r.status !== 2) problems.push(`exit ${r.status} signal ${r.signal}`);
  if (r.status === 2 && (lines.length !== 1 || !lines[0].startsWith('niwa: error: '))) problems.push(`${lines.length} stderr lines`);
  if (r.status === 0 && lines.length > 0) problems.push('stderr on success');
  if (/[\x00-\x08\x0b-\x1f\x7f]/.test(r.stderr || '')) problems.push('raw control characters on stderr');
  if (r.status !== 0 && left.length > 0) problems.push(`left ${left.join(', ')} on failure`);
  if (left.some((f) => f.includes('.partial'))) problems.push('left a temporary');
  return problems;
}
const report = (n, args, r, outs) => {
  took.push([r.ms ?? 0, n, args]);
  const problems = problemsOf(r, outs);
  if (problems.length) {
    ++bad;
    check(`case ${n} ${show(args)}: ${problems.join('; ')} :: ${(r.stderr || '').slice(0, 300)}`, false);
  }
};
async function worker(job) {
  const outs = join(work, `out${job}`);
  for (let n = job; n < COUNT; n += JOBS) {
    const args = cases[n].map((a) => a.split(OUT).join(outs));
    rmSync(outs, { recursive: true, force: true });
    mkdirSync(outs);
    const t0 = Date.now();
    const r = await run(args);
    report(n, args, { ...r, ms: Date.now() - t0 }, outs);
  }
}
// The sanitized build runs the cases batched (tests/support/cli_batch.mjs: many cases per process,
// each in its own output folder): a process start under ASan costs more than most cases.
const program = process.env.NIWA_SANITIZED ? batchOf(native) : null;
if (process.env.NIWA_SANITIZED && !program) check(`niwa_cli_batch beside ${native}: build it (tests/CMakeLists.txt)`, false);
if (program) {
  const dirs = cases.map((_, n) => join(work, `case${n}`));
  const argsList = cases.map((c, n) => { mkdirSync(dirs[n]); return c.map((a) => a.split(OUT).join(dirs[n])); });
  const results = await runBatch(program, argsList, { jobs: JOBS, work });
  cases.forEach((_, n) => report(n, argsList[n], results[n], dirs[n]));
} else {
  await Promise.all(Array.from({ length: JOBS }, (_, job) => worker(job)));
}
took.sort((a, b) => b[0] - a[0]);
for (const [ms, n, args] of took.slice(0, 8)) console.log(`slowest: case ${n} ${ms} ms ${show(args)}`);
check(`${COUNT} fuzz cases (seed ${SEED}, ${JOBS} at a time${program ? ', batched' : ''}) in ${((Date.now() - started) / 1000).toFixed(1)} s (${exits[0]} exit 0, ${exits[2]} exit 2): exit 0 or 2, one stderr line, nothing left on failure`, bad === 0);
// The sample must reach both sides: runs that succeed (and write) and runs that are refused.
check(`both outcomes reached: ${exits[0]} succeeded, ${exits[2]} refused`, exits[0] >= COUNT / 10 && exits[2] >= COUNT / 10);
rmSync(work, { recursive: true, force: true });
finish();
