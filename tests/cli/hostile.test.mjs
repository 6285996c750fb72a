// The shared hostile-input suite (issue 34): every command and flag the CLI declares ('niwa flags')
// and every row of every study's table ('niwa params STUDY --json') fed hostile values, files and
// output paths. A study added later is covered by registering its commands (with a quick example)
// and its table: this file lists no command, flag or row.
//
// Each run must exit 2 with one "niwa: error: ..." line (or 0, where the value may be valid), never
// 1, a signal or a hang (30 s), print no raw control characters, and leave no file behind when it
// fails (and never a temporary). Runs every case on the CLI in NIWA_NATIVE batched (the release build
// under ctest, then an eighth of the cases and every file case again one process each; the ASan +
// UBSan build under scripts/test) and, when built, on the WASM CLI under node (batched; not under the
// sanitized build: NIWA_SANITIZED). Batched runs go through niwa_cli_batch
// (tests/support/cli_batch.mjs): the same RunCli, many cases per process.
import { spawn as spawnChild, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, writeFileSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { basename, join } from 'node:path';
import { batchOf, runBatch } from '../support/cli_batch.mjs';
import { check, cliArgv, finish, native, wasm } from '../support/cli_pair.mjs';
import { glbBytes, triangleBin } from '../support/glb_bytes.mjs';
import { pngBytes, texturedTriangleJson } from '../support/png_bytes.mjs';

// A batched run needs the batch program beside the CLI: its absence is a failure, not a skip.
function requireBatch(cli) {
  if (!batchOf(cli)) {
    check(`niwa_cli_batch beside ${cli}: build it (tests/CMakeLists.txt)`, false);
    finish();
  }
}

const work = mkdtempSync(join(tmpdir(), 'niwa-hostile-'));
const files = join(work, 'in');
mkdirSync(files);
const OUT = '\u0000OUT\u0000';  // stands for the running case's own output folder

const declared = JSON.parse(spawnSync(native, ['flags'], { encoding: 'utf8' }).stdout);
// An example's file under tests/data/ is the source tree's.
for (const c of [...declared.commands, ...declared.studies]) {
  c.example = c.example.map((w) => (w.startsWith('tests/data/') ? join(process.env.NIWA_ROOT, w) : w));
}

// Hostile numbers: none of them is a valid value of any numeric flag.
function hostileNumbers(flag) {
  const values = ['0x10', '0x1p3', '1e400', '-1e400', 'nan', 'inf', '-inf', '', ' 1', '1 ', '1,2', '\x1b[31m1',
    '\uff11', '1e', '+', '9'.repeat(400)];
  if (Number.isFinite(flag.max)) values.push(String(flag.max + Math.max(1, Math.abs(flag.max) * 1e-6)));
  if (Number.isFinite(flag.min)) values.push(String(flag.min - Math.max(1, Math.abs(flag.min) * 1e-6)));
  if (flag.integer) values.push(String(flag.min + 0.5));
  return values;
}
// Hostile text: may be valid (a caption), so exit 0 is allowed; never a crash or two lines.
const TEXT = ['', '\x1b]0;x\x07', 'x'.repeat(100000), 'a\nb', '%00', '../..', '\u202e', '-', '--', '0x10', 'nan'];

// Hostile input files, made once.
const file = (name, bytes) => { const path = join(files, name); writeFileSync(path, bytes); return path; };
const deep = (n) => '['.repeat(n) + ']'.repeat(n);
const glb = (json, binLength = 0, declaredLength = null) =>
  glbBytes(JSON.stringify(json), Buffer.alloc(binLength), { declaredLength });
const fifo = join(files, 'fifo.glb');
const madeFifo = spawnSync('mkfifo', [fifo]).status === 0;
const INPUTS = {
  'a folder': files,
  'a missing file': join(files, 'missing.glb'),
  'an empty file': file('empty.json', ''),
  'garbage': file('garbage.glb', Buffer.from([0, 1, 2, 255, 254, 10, 13, 0x1b])),
  'deep JSON (30,000 levels)': file('deep.json', deep(30000)),
  'deep extras in a .gltf': file('deep.gltf', `{"asset":{"version":"2.0","extras":${deep(30000)}}}`),
  'a truncated .glb': file('truncated.glb', glb({ asset: { version: '2.0' } }).subarray(0, 30)),
  'a .glb declaring 4 GiB': file('huge.glb', glb({ asset: { version: '2.0' } }, 0, 0xffffffff)),
  'a wrapping accessor': file('wrap.glb', glb({
    asset: { version: '2.0' }, buffers: [{ byteLength: 36 }], bufferViews: [{ buffer: 0, byteLength: 36 }],
    accessors: [{ bufferView: 0, componentType: 5126, count: 0x1555555555555556, type: 'VEC3' }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }], nodes: [{ mesh: 0 }], scenes: [{ nodes: [0] }] }, 36)),
  // A Draco buffer (bitstream 2.2 edgebreaker) declaring 2^28 faces in 53 bytes, no plain fallback.
  'a Draco header declaring 2^28 faces': file('draco.glb', glbBytes(JSON.stringify({
    asset: { version: '2.0' }, buffers: [{ byteLength: 56 }], bufferViews: [{ buffer: 0, byteLength: 53 }],
    accessors: [{ componentType: 5126, count: 3, type: 'VEC3' }], extensionsUsed: ['KHR_draco_mesh_compression'],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 },
      extensions: { KHR_draco_mesh_compression: { bufferView: 0, attributes: { POSITION: 0 } } } }] }],
    nodes: [{ mesh: 0 }], scenes: [{ nodes: [0] }] }),
  Buffer.concat([Buffer.from('DRACO'), Buffer.from([2, 2, 1, 1, 0, 0, 0, 49, 0x80, 0x80, 0x80, 0x80, 0x01]), Buffer.alloc(35)]))),
  // One triangle whose NORMAL has a NaN.
  'a NaN normal': file('nan_normal.glb', glbBytes(JSON.stringify({
    asset: { version: '2.0' }, buffers: [{ byteLength: 72 }],
    bufferViews: [{ buffer: 0, byteLength: 36 }, { buffer: 0, byteOffset: 36, byteLength: 36 }],
    accessors: [{ bufferView: 0, componentType: 5126, count: 3, type: 'VEC3' },
      { bufferView: 1, componentType: 5126, count: 3, type: 'VEC3' }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0, NORMAL: 1 } }] }], nodes: [{ mesh: 0 }], scenes: [{ nodes: [0] }] }),
  Buffer.from(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, NaN, 0, 1, 0, 0, 1]).buffer))),
  // One triangle whose material's base colour texture is hostile (the reader checks its header).
  ...Object.fromEntries([
    ['bad bytes', Buffer.from('\x89PNG\r\n\x1a\nnot a png at all', 'latin1'), {}],
    ['a missing image', pngBytes(1, 1, new Uint8Array([1, 2, 3, 255])), { source: 4 }],
    ['0 x 0 pixels', pngBytes(0, 0, null, { declared: { width: 0, height: 0 } }), {}],
    ['100,000 x 100,000 pixels', pngBytes(0, 0, null, { declared: { width: 100000, height: 100000 } }), {}],
  ].map(([what, image, options]) => [`a texture of ${what}`, file(`texture_${what.replace(/\W+/g, '_')}.glb`,
    glbBytes(JSON.stringify(texturedTriangleJson(image.length, options)), Buffer.concat([triangleBin(), image])))])),
  'JSON of the wrong types': file('types.json', '{"type": null, "points": 7, "params": [1], "coordinates": "x", "asset": 3}'),
  'a repeated key': file('repeat.json', '{"steps": 3, "params": {"a": 1}, "steps": 4}'),
  '/dev/zero': '/dev/zero',
};
if (madeFifo) INPUTS['a FIFO'] = fifo;

// Hostile output paths (given the flag's first allowed ending).
mkdirSync(join(files, 'folder.glb'));
function outputs(ext) {
  const list = {
    'a folder': `${OUT}/dir${ext}`,
    'a missing folder': `${OUT}/no/such/o${ext}`,
    'a name too long': `${OUT}/${'x'.repeat(300)}${ext}`,
    '/dev/full': '/dev/full',
    'a symlink to a folder': `${OUT}/link${ext}`,
  };
  return list;
}
// Every ending an output flag declares ('niwa flags'): a folder and a symlink to a folder under
// each name, so a new output kind (moss photons --rays .bin) is covered without a list here.
const ENDINGS = [...new Set(declared.commands.flatMap((c) => c.flags)
  .filter((f) => f.kind === 'output').flatMap((f) => f.extensions || []))];
function prepareOut(dir) {
  for (const ext of ENDINGS) {
    mkdirSync(join(dir, `dir${ext}`));
    symlinkSync(files, join(dir, `link${ext}`));
  }
}
const preset = new Set(ENDINGS.flatMap((ext) => [`dir${ext}`, `link${ext}`]));

// A valid-looking value of a flag (for repeats and for giving an output its flag).
const sample = (flag) => flag.kind === 'number' ? String(flag.min)
  : flag.kind === 'output' ? `${OUT}/o${flag.extensions[0]}` : flag.kind === 'input' ? join(files, 'missing.glb') : 'x';

// args without the given flags and their values (a value is the word after a flag that is not
// itself a flag).
function withoutFlags(args, drop) {
  const out = [];
  for (let i = 0; i < args.length; ++i) {
    if (drop.includes(args[i])) {
      if (i + 1 < args.length && !args[i + 1].startsWith('--')) ++i;
      continue;
    }
    out.push(args[i]);
  }
  return out;
}
const cases = [];  // {name, args, expect: 'refused' | 'any'}
// A flag that several commands of one group share (the tree state flags of 'tree grow', 'tree
// sway', ...: one AddStateOptions) is varied on the first command that has it.
const seen = new Set();
let turn = 0;
for (const command of declared.commands) {
  if (command.command[0] === 'flags') continue;
  const base = [...command.command, ...command.example];
  const word = command.command.join(' ');
  for (const flag of command.flags) {
    // The example without the flags this one excludes (--mesh FILE against the example's --scene).
    const base = withoutFlags([...command.command, ...command.example], [flag.flag, ...(flag.excludes || [])]);
    const key = JSON.stringify([command.command[0], flag.flag, flag.kind, flag.min, flag.max, flag.only_with]);
    if (seen.has(key)) continue;
    seen.add(key);
    const given = flag.only_with ? ['--out'].includes(flag.only_with)
      ? [flag.only_with, `${OUT}/o${flag.only_endings[0]}`] : [] : [];
    if (flag.kind === 'number') {
      // The bounds, hex, nan and octal-looking 010 for every numeric flag; two of the other spellings each, in turn
      // (they all reach the one parser, FlagNumber: the unit tests try each against every rule).
      const all = hostileNumbers(flag);
      const others = all.slice(2, 16).filter((v) => v !== 'nan');
      const picked = [...all.slice(0, 2), 'nan', '010', ...all.slice(16), others[turn % others.length], others[(turn + 7) % others.length]];
      ++turn;
      for (const v of picked) cases.push({ name: `${word} ${flag.flag} ${JSON.stringify(v)}`, args: [...base, ...given, flag.flag, v], expect: 'refused', names: flag.flag });
    } else if (flag.kind === 'text') {
      for (const v of TEXT) cases.push({ name: `${word} ${flag.flag} ${JSON.stringify(v.length > 40 ? `${v.slice(0, 10)}...(${v.length})` : v)}`, args: [...base, ...given, flag.flag, v], expect: 'any' });
    } else if (flag.kind === 'input') {
      for (const [what, path] of Object.entries(INPUTS)) cases.push({ name: `${word} ${flag.flag} ${what}`, args: [...base, flag.flag, path], expect: 'refused', names: flag.flag, input: true });
    } else if (flag.kind === 'output') {
      for (const [what, path] of Object.entries(outputs(flag.extensions[0]))) cases.push({ name: `${word} ${flag.flag} ${what}`, args: [...base, flag.flag, path], expect: 'refused', names: flag.flag });
      cases.push({ name: `${word} ${flag.flag} without an allowed ending`, args: [...base, flag.flag, `${OUT}/o.zzz`], expect: 'refused', names: flag.flag });
    } else if (flag.kind === 'switch') {
      cases.push({ name: `${word} ${flag.flag}=yes`, args: [...base, ...given, `${flag.flag}=yes`], expect: 'refused', names: flag.flag });
    }
    if (flag.kind !== 'switch' && !flag.repeatable) {
      cases.push({ name: `${word} ${flag.flag} given twice`, args: [...base, ...given, flag.flag, sample(flag), flag.flag, sample(flag)], expect: 'refused', names: flag.flag });
    }
    if (flag.only_with) {  // a flag for one output kind, given without it
      cases.push({ name: `${word} ${flag.flag} without ${flag.only_with} ${flag.only_endings.join('|')}`,
        args: [...base, ...(flag.kind === 'switch' ? [flag.flag] : [flag.flag, sample(flag)])], expect: 'refused', names: flag.flag });
    }
  }
  // Two output flags naming one file two ways.
  const outs = command.flags.filter((f) => f.kind === 'output');
  for (let i = 0; i < outs.length; ++i) {
    for (let k = i + 1; k < outs.length; ++k) {
      const common = outs[i].extensions.find((e) => outs[k].extensions.includes(e));
      if (!common) continue;
      cases.push({ name: `${word} ${outs[i].flag} and ${outs[k].flag} name one file`,
        args: [...base, outs[i].flag, `${OUT}/same${common}`, outs[k].flag, `${OUT}/./same${common}`], expect: 'refused', names: outs[k].flag });
    }
  }
}
// Values no flag kind declares (a word from a list, a range only the grown tree decides): table rows
// of a command, its hostile value and the flag its one-line refusal names.
const CHOSEN = [
  // tree grow --bark procedural|sim, --bark-height within the trunk's height a year before the last
  [['tree', 'grow', '--preset', 'binary', '--years', '2', '--out', `${OUT}/o.glb`], '--bark', ['foo', 'SIM', 'sim ', '']],
  [['tree', 'grow', '--preset', 'binary', '--years', '2', '--out', `${OUT}/o.glb`, '--bark', 'sim'], '--bark-height', ['1.3', '99', '1e-3x']],
  [['tree', 'grow', '--preset', 'binary', '--years', '1', '--out', `${OUT}/o.glb`, '--bark', 'sim'], '--bark', []],
  [['tree', 'grow', '--preset', 'binary', '--years', '2', '--out', `${OUT}/o.json`], '--bark', ['sim']],
  [['tree', 'grow', '--preset', 'binary', '--years', '2', '--out', `${OUT}/o.glb`, '--bark', 'sim'], '--bark-species', ['oak', '']],
  [['tree', 'grow', '--preset', 'binary', '--years', '2', '--out', `${OUT}/o.glb`, '--bark', 'sim'], '--bark-map-size', ['300', '1000']],
  [['tree', 'grow', '--preset', 'binary', '--years', '2', '--out', `${OUT}/o.glb`, '--bark', 'sim'], '--bark-model', ['3layer', '4LAYER', '']],
];
for (const [args, flag, values] of CHOSEN) {
  if (!values.length) cases.push({ name: `${args.join(' ')} (refused naming ${flag})`, args, expect: 'refused', names: flag });
  for (const v of values) cases.push({ name: `${args.slice(0, 2).join(' ')} ${flag} ${JSON.stringify(v)}`, args: [...args, flag, v], expect: 'refused', names: flag });
}
// Every table row of every study, through its command's --set and --url.
let rowTurn = 0;
for (const study of declared.studies) {
  if (!study.example.length) continue;
  const table = JSON.parse(spawnSync(native, ['params', study.name, '--json'], { encoding: 'utf8' }).stdout);
  const rows = Array.isArray(table) ? table : (table.params || table.rows || []);
  check(`${study.name}: its table lists rows`, rows.length > 0, `${rows.length} rows`);
  for (const row of rows) {
    const spec = { min: row.min, max: row.max, integer: Boolean(row.integer) };
    // Past each bound (and a fraction for a whole-number row), and one of hex, nan, inf, 010 in turn.
    for (const v of [['0x10', 'nan', 'inf', '010'][rowTurn++ % 4], ...hostileNumbers(spec).slice(16)]) {
      cases.push({ name: `${study.name} --set ${row.key}=${JSON.stringify(v)}`, args: [...study.example, '--set', `${row.key}=${v}`], expect: 'refused', names: row.key, row: true });
    }
    cases.push({ name: `${study.name} --url ${row.key} repeated`, args: [...study.example, '--url', `${row.key}=${row.min}&${row.key}=${row.min}`], expect: 'refused', names: row.key, row: true });
  }
  cases.push({ name: `${study.name} --url over 16,384 characters`, args: [...study.example, '--url', `${rows[0].key}=${rows[0].min}&x=${'1'.repeat(16400)}`], expect: 'refused' });
  cases.push({ name: `${study.name} --set of an unknown key`, args: [...study.example, '--set', 'no_such_row=1'], expect: 'refused' });
}

const show = (args) => JSON.stringify(args.map((a) => (a.length > 60 ? `${a.slice(0, 30)}...(${a.length})` : a)));
function runOnce(cli, args) {
  return new Promise((resolve) => {
    const [cmd, argv] = cliArgv(cli, args);
    const child = spawnChild(cmd, argv, { timeout: 30000, stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.setEncoding('utf8');
    child.stderr.on('data', (chunk) => { if (stderr.length < (1 << 20)) stderr += chunk; });
    let error = null;
    child.on('error', (e) => { error = e; });
    child.on('close', (status, signal) => {
      if (signal === 'SIGTERM' && !error) error = { code: 'ETIMEDOUT' };
      resolve({ status, signal, stderr, error });
    });
  });
}

// The problems of one case's result, its output folder `dir` checked after it ran.
function problemsOf(c, r, dir) {
  const lines = r.stderr ? r.stderr.trimEnd().split('\n').filter((l) => !l.startsWith('niwa: truncated: ')) : [];
  const left = readdirSync(dir).filter((f) => !preset.has(f));
  const problems = [];
  if (r.error) problems.push(`did not finish: ${r.error.code}`);
  else if (r.status !== 0 && r.status !== 2) problems.push(`exit ${r.status} signal ${r.signal}`);
  if (c.expect === 'refused' && r.status === 0) problems.push('accepted');
  // A refusal names what it refuses: another flag's error means the case never reached it.
  if (c.names && r.status === 2 && lines.length === 1 && !lines[0].includes(c.names)) problems.push(`the error does not name ${c.names}`);
  if (r.status === 2 && (lines.length !== 1 || !lines[0].startsWith('niwa: error: '))) problems.push(`${lines.length} stderr lines`);
  if (/[\x00-\x08\x0b-\x1f\x7f]/.test(r.stderr || '')) problems.push('raw control characters on stderr');
  if (r.status !== 0 && left.length > 0) problems.push(`left ${left.join(', ')}`);
  if (readdirSync(dir).some((f) => f.includes('.partial')) || readdirSync(files).some((f) => f.includes('.partial'))) problems.push('left a temporary');
  return problems;
}

// Runs every case of `list` on `cli`: one process per case (as a user runs it), or through
// niwa_cli_batch (batched: many cases per process, each in its own output folder).
async function runAll(cli, list, label, { batched = false } = {}) {
  const JOBS = Math.max(1, Number(process.env.NIWA_HOSTILE_JOBS || 2));
  let bad = 0;
  const started = Date.now();
  const exits = {};
  const report = (c, r, dir, args) => {
    exits[r.status] = (exits[r.status] || 0) + 1;
    const problems = problemsOf(c, r, dir);
    if (problems.length) {
      ++bad;
      check(`${label}: ${c.name}: ${problems.join('; ')} :: ${show(args)} :: ${(r.stderr || '').slice(0, 240)}`, false);
    }
  };
  const program = batched ? batchOf(cli) : null;
  if (program) {
    const dirs = list.map((_, n) => join(work, `${label}-case${n}`));
    const argsList = list.map((c, n) => {
      mkdirSync(dirs[n]);
      prepareOut(dirs[n]);
      return c.args.map((a) => a.split(OUT).join(dirs[n]));
    });
    const results = await runBatch(program, argsList, { jobs: JOBS, work });
    list.forEach((c, n) => report(c, results[n], dirs[n], argsList[n]));
    const slow = list.map((c, n) => [results[n].ms || 0, c.name]).sort((a, b) => b[0] - a[0]).slice(0, 5);
    console.log(`${label}: slowest cases: ${slow.map(([ms, name]) => `${ms} ms ${name.slice(0, 80)}`).join(' | ')}`);
  } else {
    async function worker(job) {
      const dir = join(work, `${label}-out${job}`);
      for (let n = job; n < list.length; n += JOBS) {
        const c = list[n];
        rmSync(dir, { recursive: true, force: true });
        mkdirSync(dir);
        prepareOut(dir);
        const args = c.args.map((a) => a.split(OUT).join(dir));
        report(c, await runOnce(cli, args), dir, args);
      }
    }
    await Promise.all(Array.from({ length: JOBS }, (_, job) => worker(job)));
  }
  const how = program ? `batched in ${basename(program)}` : 'one process each';
  check(`${label}: ${list.length} hostile cases in ${((Date.now() - started) / 1000).toFixed(1)} s, ${how} (exits ${JSON.stringify(exits)}): exit 2 with one line (or 0 where valid), nothing left`, bad === 0);
}

check('the CLI declares its commands (niwa flags)', declared.commands.length >= 10, `${declared.commands.length} commands`);
const only = process.env.NIWA_HOSTILE_FILTER;
const list = only ? cases.filter((c) => c.name.includes(only)) : cases;
console.log(`${list.length} of ${cases.length} cases`);
// Every case batched in niwa_cli_batch (the same RunCli; a process start costs more than most cases:
// 2,839 cases took 90 s one process each on the release build, and 0.12-0.18 s a start under ASan);
// then, on the release build, every NIWA_HOSTILE_NATIVE_EVERY-th case (default 8) and every file case
// again one process per case, as a user runs them, so the binary's own exit codes, stderr and files
// are checked too (NIWA_HOSTILE_NATIVE_EVERY=1: all of them).
requireBatch(native);
await runAll(native, list, 'native', { batched: true });
if (!process.env.NIWA_SANITIZED) {
  const every = Math.max(1, Number(process.env.NIWA_HOSTILE_NATIVE_EVERY || 8));
  await runAll(native, list.filter((c, i) => c.input || i % every === 0), 'native, one process each');
}
if (existsSync(wasm) && !process.env.NIWA_HOSTILE_NO_WASM && !process.env.NIWA_SANITIZED) {
  // In WASM, every case too, batched: one niwa.js run costs about 0.3 CPU s to compile before its work,
  // which made a sample of a fifth of the cases cost more than all of them batched. NIWA_HOSTILE_WASM_EVERY
  // keeps every N-th case only (and every file case: the readers and the file system are where the
  // builds differ).
  const every = Math.max(1, Number(process.env.NIWA_HOSTILE_WASM_EVERY || 1));
  requireBatch(wasm);
  await runAll(wasm, list.filter((c, i) => c.input || i % every === 0), 'wasm', { batched: true });
}
rmSync(work, { recursive: true, force: true });
finish();
