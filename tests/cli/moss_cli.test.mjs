// Moss CLI: native == WASM bytes of `niwa moss soil` (every term of eqs 3.2-3.16) over every
// geology, both presets and both eq 3.15 forms, and of `niwa moss fitness` (eqs 3.17-3.20) for every
// species and both g forms; the spec's §1.4 reference values and the balance's residual as printed;
// `niwa params moss` / `niwa presets moss` in both builds; hostile values one line naming the flag;
// `niwa moss grow` (--stats and --out moss.json) and `niwa moss photons` native == WASM byte for
// byte on every built-in scene, both presets, seeds 1-2, at a few days and photons; moss.json's
// cells; `--out moss.glb` (merged and --instancing, every --map) native == WASM and gltf-validator
// clean, its estimate refused before the days are grown with no file left; --csv days; --weather
// and --params files, hostile ones refused naming the day and field; photons.svg from both commands;
// the rays file of `moss photons --rays`; the rocks scene's --rock-triangles and its budget.
// The WASM runs of each part are prepared ahead, batched in niwa_cli_batch.js (the same RunCli; a
// niwa.js start under node costs about 0.3 CPU s), every NIWA_MOSS_WASM_EVERY-th case (default 4)
// and the few that depend on an earlier result as one niwa.js process each (support/cli_batch.mjs
// PreparedCli).
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { PreparedCli } from '../support/cli_batch.mjs';
import { buildName, check, finish, native, requireWasm, root, run as runOne, spawn as spawnOne, wasm, withoutMs } from '../support/cli_pair.mjs';

requireWasm();
const dir = mkdtempSync(join(tmpdir(), 'niwa-moss-'));
const W = new PreparedCli(wasm, { every: Math.max(1, Number(process.env.NIWA_MOSS_WASM_EVERY || 4)), work: dir, jobs: 1 });
// run/spawn as cli_pair.mjs's, the WASM CLI's answered from the prepared runs.
const run = (cmd, args) => (cmd === wasm ? W.run(args) : runOne(cmd, args));
const spawn = (cmd, args) => (cmd === wasm ? W.spawn(args) : spawnOne(cmd, args));

const near = (got, want) => Math.abs(got - want) <= 1e-4 * Math.abs(want);

// Soil: one cell, both builds, byte for byte.
const soilArgs = [];
for (const geology of ['humus', 'sandy', 'asphalt']) {
  for (const theta of ['0', '0.01', '0.012']) {
    for (const S of ['0', '25', '250']) {
      for (const extra of [[], ['--preset', 'nomura2010-sky', '--V', '0.4'], ['--set', 'delta_form=1', '--mM', '1', '--T', '293.15']]) {
        soilArgs.push(['moss', 'soil', '--geology', geology, '--theta', theta, '--S', S, ...extra]);
      }
    }
  }
}
const fitnessArgs = [];
for (const species of ['gingoke', 'haigoke', 'sugigoke', null]) {
  for (const [Ts, rhs, S] of [['278.1', '1.01148', '25'], ['290', '1.3', '0'], ['300', '0.7', '250']]) {
    for (const extra of [[], ['--set', 'g_form=1']]) {
      fitnessArgs.push(['moss', 'fitness', ...(species ? ['--species', species] : []), '--Ts', Ts, '--rhs', rhs, '--S', S, ...extra]);
    }
  }
}
const tableArgs = [['params', 'moss', '--json'], ['params', 'moss'], ['presets', 'moss']];
await W.prepare([...soilArgs, ...fitnessArgs, ...tableArgs]);
let soilCases = 0;
for (const args of soilArgs) {
  const a = run(native, args), b = run(wasm, args);
  ++soilCases;
  if (a !== b) check(`soil ${args.join(' ')}: native == WASM`, false, `${a}\n${b}`);
}
check(`moss soil: ${soilCases} cells (3 geologies x 3 theta x 3 S x 3 settings): native == WASM byte for byte`, soilCases === 81);

// The spec's reference row "humus theta 0.2, S 25" and the residual, as the CLI prints them.
const cell = JSON.parse(run(native, ['moss', 'soil', '--geology', 'humus', '--theta', '0.2', '--S', '25']));
check(`moss soil humus 0.2 S 25: dT ${cell.dT}, iota_E ${cell.iota_E}, rh_s ${cell.rh_s} (spec §1.4)`,
  near(cell.dT, -10.0326) && near(cell.iota_E, -3.58964) && near(cell.rh_s, 1.01148) && near(cell.beta, 0.989381));
check(`moss soil: linear residual ${cell.residual_linear} < 1e-9 W/m2; every eq 3.2-3.16 term printed`,
  Math.abs(cell.residual_linear) < 1e-9 &&
  ['A', 'C', 'sigma_T4', 'L', 'R', 'C_H', 'theta', 'F', 'beta', 'e_SAT', 'q_SAT', 'Delta', 'dT', 'T_s', 'H', 'iota_E', 'E', 'E_mm_day', 'rh_s', 'residual_nonlinear']
    .every((k) => Number.isFinite(cell[k])));
const literal = JSON.parse(run(native, ['moss', 'soil', '--geology', 'humus', '--theta', '0.49', '--S', '0', '--set', 'delta_form=1']));
check(`moss soil --set delta_form=1: literal Delta ${literal.Delta} (spec: 2.44254e-4)`, literal.delta_form === 'literal' && near(literal.Delta, 2.44254e-4));

// Fitness: every species, both g forms, a few places.
let fitnessCases = 0;
for (const args of fitnessArgs) {
  const a = run(native, args), b = run(wasm, args);
  ++fitnessCases;
  if (a !== b) check(`fitness ${args.join(' ')}: native == WASM`, false, `${a}\n${b}`);
}
check(`moss fitness: ${fitnessCases} places: native == WASM byte for byte`, fitnessCases === 24);
const all = JSON.parse(run(native, ['moss', 'fitness', '--Ts', '278.1', '--rhs', '1.01148', '--S', '25']));
const sugi = all.species.find((s) => s.species === 'sugigoke');
check(`moss fitness (no --species): all three species; sugigoke G ${sugi.G} (by hand 0.494344481506)`,
  all.species.length === 3 && Math.abs(sugi.G - 0.4943444815062233) < 1e-12);

// The table and presets, both builds.
for (const args of tableArgs) {
  const a = run(native, args), b = run(wasm, args);
  check(`niwa ${args.join(' ')}: native == WASM (${a.length} bytes)`, a.length > 100 && a === b);
}

// The run: every scene, both presets, seeds 1-2; --stats (no timing fields) and moss.json.
const growRuns = [];
for (const scene of ['plane', 'thesis', 'walls', 'rocks']) {
  for (const preset of ['nomura2010', 'nomura2010-sky']) {
    for (const seed of ['1', '2']) growRuns.push([scene, preset, seed]);
  }
}
const growArgs = ([scene, preset, seed]) => ['moss', 'grow', '--scene', scene, '--preset', preset, '--seed', seed, '--days', '12', '--photons', '1024', '--stats'];
await W.prepare(growRuns.map((g) => [...growArgs(g), '--out', join(dir, `w-${g.join('-')}.json`)]));
let growCases = 0, withMosses = 0;
for (const [scene, preset, seed] of growRuns) {
  const args = growArgs([scene, preset, seed]);
  const na = join(dir, `n-${scene}-${preset}-${seed}.json`), wa = join(dir, `w-${scene}-${preset}-${seed}.json`);
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, [...args, '--out', na]))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, [...args, '--out', wa]))));
  const ja = readFileSync(na, 'utf8'), jb = readFileSync(wa, 'utf8');
  ++growCases;
  if (a !== b || ja !== jb) check(`grow ${args.join(' ')}: native == WASM`, false, `${a.slice(0, 300)}\n${b.slice(0, 300)}`);
  const stats = JSON.parse(a), list = JSON.parse(ja);
  if (list.mosses.length !== stats.mosses.total || stats.days !== 12)
    check(`grow ${scene} ${preset} ${seed}: moss.json lists the ${stats.mosses.total} living mosses`, false, ja.slice(0, 200));
  if (list.mosses.length > 0) ++withMosses;
  if (list.cells.length !== stats.cells.total || !list.cells.every((c) => ['humus', 'sandy', 'asphalt'].includes(c.geology) &&
      c.centre.length === 3 && c.normal.length === 3 && ['S', 'T_s', 'rh_s', 'theta', 'm_over_M'].every((k) => Number.isFinite(c[k]))))
    check(`grow ${scene} ${preset} ${seed}: moss.json lists the ${stats.cells.total} cells with their soil`, false, JSON.stringify(list.cells[0]));
  for (const m of list.mosses)
    if (!['gingoke', 'haigoke', 'sugigoke'].includes(m.species) || m.pos.length !== 3 || m.normal.length !== 3 ||
        !(m.birth_day >= 0 && m.birth_day <= 12) || !Number.isFinite(m.G_moss)) {
      check(`grow ${scene}: a moss's fields`, false, JSON.stringify(m));
      break;
    }
}
check(`moss grow: ${growCases} runs (4 scenes x 2 presets x seeds 1-2, 12 days, 1,024 photons): --stats and moss.json (mosses and cells) native == WASM byte for byte; ${withMosses} with living mosses`,
  growCases === 16 && withMosses >= 8);

// --out moss.glb: the land's map and the tufts, merged or instanced, every map; both builds' bytes
// equal and gltf-validator clean (0 errors, 0 warnings; the instancing extension is an info).
{
  const require = createRequire(join(root, 'package.json'));
  const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
  const validator = validatorModule.default ?? validatorModule;
  let glbCases = 0;
  const runs = [
    ['thesis', []], ['thesis', ['--instancing']], ['walls', ['--map', 'S']], ['rocks', ['--map', 'T_s', '--instancing']],
    ['thesis', ['--map', 'rh_s']], ['thesis', ['--map', 'theta']], ['thesis', ['--map', 'fitness']],
  ];
  const glbArgs = ([scene, extra]) => ['moss', 'grow', '--scene', scene, '--days', '15', '--photons', '1024', ...extra];
  const csvArgs = ['moss', 'grow', '--scene', 'thesis', '--days', '20', '--photons', '1024', '--seed', '3'];
  await W.prepare([...runs.map((r, i) => [...glbArgs(r), '--out', join(dir, `w-${i}.glb`)]),
    [...csvArgs, '--csv', join(dir, 'w.csv'), '--out', join(dir, 'w-days.glb')]]);
  for (const [scene, extra] of runs) {
    const args = glbArgs([scene, extra]);
    const na = join(dir, `n-${glbCases}.glb`), wa = join(dir, `w-${glbCases}.glb`);
    run(native, [...args, '--out', na]);
    run(wasm, [...args, '--out', wa]);
    const a = readFileSync(na), b = readFileSync(wa);
    const report = await validator.validateBytes(new Uint8Array(a), { maxIssues: 50 });
    const length = a.readUInt32LE(12);
    const gltf = JSON.parse(a.subarray(20, 20 + length).toString('utf8'));
    const land = gltf.nodes.find((n) => n.name === 'land'), tufts = gltf.nodes.find((n) => n.name === 'tufts');
    const instanced = extra.includes('--instancing');
    const map = extra.includes('--map') ? extra[extra.indexOf('--map') + 1] : 'coverage';
    const stats = JSON.parse(run(native, [...args.filter((w) => w !== '--instancing' && w !== '--map' && w !== map), '--stats']));
    const count = instanced
      ? tufts.children.reduce((n, c) => n + gltf.accessors[gltf.nodes[c].extensions.EXT_mesh_gpu_instancing.attributes.TRANSLATION].count, 0)
      : tufts.extras.birth_day.length;
    ++glbCases;
    check(`moss grow ${scene} ${extra.join(' ')} --out moss.glb: native == WASM (${a.length} bytes), validator ${report.issues.numErrors} errors ${report.issues.numWarnings} warnings; map ${land.extras.map}, ${count} tufts of ${stats.mosses.total} mosses`,
      a.equals(b) && report.issues.numErrors === 0 && report.issues.numWarnings === 0 && land.extras.map === map &&
      count === stats.mosses.total && count > 0 && (instanced ? gltf.extensionsUsed.includes('EXT_mesh_gpu_instancing') : tufts.extras.species.length === count));
  }
  // --csv: one row a day, both builds' bytes equal, written with --out in one commit.
  {
    const args = csvArgs;
    const nc = join(dir, 'n.csv'), wc = join(dir, 'w.csv');
    const stats = JSON.parse(run(native, [...args, '--csv', nc, '--out', join(dir, 'n-days.glb'), '--stats']));
    run(wasm, [...args, '--csv', wc, '--out', join(dir, 'w-days.glb')]);
    const a = readFileSync(nc, 'utf8'), b = readFileSync(wc, 'utf8');
    const rows = a.trim().split('\n');
    const last = rows[rows.length - 1].split(',');
    check(`moss grow --csv days.csv: native == WASM (${a.length} bytes), ${rows.length - 1} rows of ${rows[0].split(',').length} columns; day 20's population ${last.slice(1, 4).join('/')} as the stats'`,
      a === b && rows.length === 21 && rows[0].startsWith('day,gingoke,haigoke,sugigoke,seeds,births,deaths,photons_stored,humus_S') &&
      JSON.stringify(last.slice(1, 4).map(Number)) === JSON.stringify(stats.population.by_day[20]) &&
      readFileSync(join(dir, 'n-days.glb')).equals(readFileSync(join(dir, 'w-days.glb'))));
  }
  // --weather FILE.json|.csv and --params FILE: both builds' bytes equal; the file is named in the
  // stats, not in the link; a file repeating the table's rows grows the table's bytes.
  {
    const csv = join(dir, 'w.csv'), json = join(dir, 'w.json'), params = join(dir, 'p.json');
    writeFileSync(csv, 'T,rh,U,N,N0,P\n293.15,0.8,0.5,7,9,12\n283.15,0.6,0.1,2,8,0\n');
    writeFileSync(json, JSON.stringify({ days: [{ T: 293.15, rh: 0.8, U: 0.5, N: 7, N0: 9, P: 12 }, { T: 283.15, rh: 0.6, U: 0.1, N: 2, N0: 8, P: 0 }] }));
    writeFileSync(params, JSON.stringify({ scene: 'walls', days: 6, params: { T: 290, photons: 512 } }));
    const args = ['moss', 'grow', '--scene', 'thesis', '--days', '8', '--photons', '1024', '--stats'];
    const hostileFiles = [
      ['bad1.csv', 'T,rh\n400,0.8\n', '--weather: day 1: T: 400 is out of range; must be a number in [233.15, 323.15]'],
      ['bad2.csv', 'T,Tmax\n290,300\n', "--weather: column 'Tmax' is unknown"],
      ['bad3.csv', 'N\nnan\n', "--weather: day 1: N: 'nan' is not a decimal number"],
      ['bad4.json', '{"days": [{"T": 290}, {"rh": -0.1}]}', '--weather: day 2: rh: -0.1 is out of range; must be a number in [0, 1]'],
      ['bad5.json', '{"days": [{"N": 10, "N0": 9}]}', '--weather: day 1: N: 10 is above N0 9'],
      ['bad6.json', '{"days": []}', '--weather: has 0 days; must have 1 to 3650'],
      ['bad7.txt', 'T\n290\n', '--weather: '],
      ['badp1.json', '{"params": {"rh": 2}}', '--params: rh: 2 is out of range; must be a number in [0, 1]'],
      ['badp2.json', '{"days": -1}', '--params: days'],
      ['badp3.json', '{"params": {"T": 290, "T": 291}}', '--params'],
    ];
    const hostileArgs = (name) => ['moss', 'grow', '--scene', 'plane', '--days', '2', '--photons', '64',
      name.startsWith('badp') ? '--params' : '--weather', join(dir, name), '--out', join(dir, `never-${name}.glb`)];
    for (const [name, text] of hostileFiles) writeFileSync(join(dir, name), text);
    await W.prepare([[...args, '--weather', csv], ['moss', 'grow', '--params', params, '--stats'],
      ...hostileFiles.map(([name]) => hostileArgs(name))]);
    const bytes = (cmd, extra) => JSON.stringify(withoutMs(JSON.parse(run(cmd, [...args, ...extra]))));
    const a = bytes(native, ['--weather', csv]), b = bytes(wasm, ['--weather', csv]);
    const c = bytes(native, ['--weather', json]);
    const plain = bytes(native, []);
    const sa = JSON.parse(a), sc = JSON.parse(c);
    delete sa.weather; delete sc.weather;
    check(`moss grow --weather w.csv: native == WASM; the .json of the same rows grows the same; the file in the stats (${JSON.stringify(JSON.parse(a).weather)}), not the link; differs from the table's climate`,
      a === b && JSON.stringify(sa) === JSON.stringify(sc) && JSON.parse(a).weather.file === 'w.csv' && !JSON.parse(a).url.includes('w.csv') && a !== plain);
    const pa = run(native, ['moss', 'grow', '--params', params, '--stats']), pb = run(wasm, ['moss', 'grow', '--params', params, '--stats']);
    const ps = JSON.parse(pa);
    check(`moss grow --params {scene walls, days 6, T 290, photons 512}: native == WASM; url ${ps.url}`,
      JSON.stringify(withoutMs(ps)) === JSON.stringify(withoutMs(JSON.parse(pb))) && ps.scene === 'walls' && ps.days === 6 && ps.photons === 512 && ps.url.includes('T=290'));
    // Hostile weather and params files: one line naming the flag, the day and field with its range; exit 2; no file written.
    for (const [name, , want] of hostileFiles) {
      const flag = name.startsWith('badp') ? '--params' : '--weather';
      const out = join(dir, `never-${name}.glb`);
      for (const cmd of [native, wasm]) {
        const r = spawn(cmd, hostileArgs(name));
        const lines = r.stderr.trim().split('\n');
        check(`${buildName(cmd)} moss grow ${flag} ${name}: exit ${r.status}, "${lines[0]}", no file`,
          r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${want}`) && r.stdout === '' && !existsSync(out));
      }
    }
  }
  // photons.svg: `moss photons --out` (the next day's map) and `moss grow --out` (the last day's):
  // both builds' bytes equal; first hits and bounced dots in their colours, none bounced with
  // indirect off.
  const svgArgs = (indirect) => ['moss', 'photons', '--scene', 'thesis', '--photons', '2048', '--indirect', indirect];
  const growSvgArgs = ['moss', 'grow', '--scene', 'walls', '--days', '4', '--photons', '1024', '--set', 'sun_altitude=45'];
  const refusedArgs = ['moss', 'grow', '--scene', 'plane', '--days', '2', '--photons', '64', '--set', 'max_mosses=1048576', '--max-memory', '1G', '--out', join(dir, 'refused.glb')];
  await W.prepare([...['on', 'off'].map((i) => [...svgArgs(i), '--out', join(dir, `w-${i}.svg`)]),
    [...growSvgArgs, '--out', join(dir, 'w-grow.svg')], refusedArgs]);
  for (const indirect of ['on', 'off']) {
    const args = svgArgs(indirect);
    const na = join(dir, `n-${indirect}.svg`), wa = join(dir, `w-${indirect}.svg`);
    const day = JSON.parse(run(native, [...args, '--out', na]));
    run(wasm, [...args, '--out', wa]);
    const a = readFileSync(na, 'utf8'), b = readFileSync(wa, 'utf8');
    const direct = (a.match(/fill="#e8a317"\/>/g) || []).length, bounced = (a.match(/fill="#2a6fdb"\/>/g) || []).length;
    check(`moss photons --indirect ${indirect} --out photons.svg: native == WASM (${a.length} bytes); ${direct} first-hit and ${bounced} bounced dots of ${day.stored_by_depth[0]} and ${day.stored_by_depth.slice(1).reduce((x, y) => x + y, 0)} stored`,
      a === b && a.startsWith('<svg ') && direct > 0 && direct <= day.stored_by_depth[0] && (indirect === 'off' ? bounced === 0 : bounced > 0));
  }
  {
    const args = growSvgArgs;
    run(native, [...args, '--out', join(dir, 'n-grow.svg')]);
    run(wasm, [...args, '--out', join(dir, 'w-grow.svg')]);
    const a = readFileSync(join(dir, 'n-grow.svg'), 'utf8');
    check(`moss grow --out photons.svg: the last day's photons (day 4), native == WASM (${a.length} bytes)`,
      a === readFileSync(join(dir, 'w-grow.svg'), 'utf8') && a.includes('moss photons day 4, walls'));
  }
  // The .glb's estimate (the mosses at their cap) is refused before the days are grown, no file.
  const out = join(dir, 'refused.glb');
  for (const cmd of [native, wasm]) {
    const r = spawn(cmd, refusedArgs);
    check(`${buildName(cmd)} moss grow --out moss.glb at 1,048,576 max_mosses under --max-memory 1G: exit ${r.status}, "${r.stderr.trim()}", no file`,
      r.status === 2 && r.stderr.startsWith('niwa: error: --max-memory') && r.stderr.includes('.glb') && !existsSync(out));
  }
}
const photonsArgs = (scene, indirect) => ['moss', 'photons', '--scene', scene, '--photons', '2048', '--indirect', indirect, '--preset', 'nomura2010-sky'];
await W.prepare([...['plane', 'thesis', 'walls', 'rocks'].flatMap((scene) => ['on', 'off'].map((i) => photonsArgs(scene, i))), ['moss', 'scenes']]);
for (const scene of ['plane', 'thesis', 'walls', 'rocks']) {
  for (const indirect of ['on', 'off']) {
    const args = photonsArgs(scene, indirect);
    const a = run(native, args), b = run(wasm, args);
    const day = JSON.parse(a);
    const bounced = day.stored_by_depth.slice(1).reduce((x, y) => x + y, 0);
    check(`moss photons ${scene} indirect ${indirect}: native == WASM; ${day.stored_by_depth[0]} first hits, ${bounced} bounced, ${day.emitted_sky} sky`,
      a === b && day.stored_by_depth[0] > 0 && (indirect === 'off' ? bounced === 0 && day.emitted_sky === 0 : day.emitted_sky > 0));
  }
}
{
  const a = run(native, ['moss', 'scenes']), b = run(wasm, ['moss', 'scenes']);
  check(`moss scenes: native == WASM, ${JSON.parse(a).scenes.map((s) => `${s.name} ${s.cells} cells`).join(', ')}`, a === b);
}

// --rays (geom/ray_dump.h): the day's rays at the land and Niwa's hits, the same bytes in both
// builds, the header's counts and a ray for every stored land photon or escape; --rock-triangles
// (the rocks scene's size) grows the rocks on a million triangles only within the budget:
// refused up front naming --max-seconds at 300 days, and without the rocks scene naming itself.
{
  const raysArgs = (file) => ['moss', 'photons', '--scene', 'walls', '--photons', '1024', '--rays', file];
  const refusedRocks = ['moss', 'grow', '--scene', 'rocks', '--rock-triangles', '1000000', '--max-memory', '3G', '--stats'];
  const overMemory = ['moss', 'grow', '--scene', 'rocks', '--rock-triangles', '1000000', '--days', '3'];
  const notRocks = ['moss', 'grow', '--scene', 'thesis', '--rock-triangles', '2000', '--days', '1'];
  const outOfRange = ['moss', 'grow', '--scene', 'rocks', '--rock-triangles', '99', '--days', '1'];
  const badEnding = ['moss', 'photons', '--scene', 'plane', '--rays', join(dir, 'rays.txt')];
  const rocksLink = ['moss', 'grow', '--scene', 'rocks', '--rock-triangles', '6400', '--days', '2', '--photons', '256', '--stats'];
  await W.prepare([raysArgs(join(dir, 'w-rays.bin')), refusedRocks, overMemory, notRocks, outOfRange, badEnding, rocksLink]);
  const day = JSON.parse(run(native, raysArgs(join(dir, 'n-rays.bin'))));
  run(wasm, raysArgs(join(dir, 'w-rays.bin')));
  const a = readFileSync(join(dir, 'n-rays.bin')), b = readFileSync(join(dir, 'w-rays.bin'));
  const words = new Uint32Array(a.buffer, a.byteOffset + 8, 4);
  const [vertices, triangles, rays] = words;
  const at = 24 + 12 * vertices + 12 * triangles;
  let hits = 0;
  for (let i = 0; i < rays; ++i) hits += a.readInt32LE(at + 36 * i + 28) >= 0 ? 1 : 0;
  const stored = day.stored_by_depth.reduce((x, y) => x + y, 0);
  check(`moss photons --rays: native == WASM (${a.length} bytes): ${triangles} triangles, ${rays} rays, ${hits} hit the land; ${stored} photons stored`,
    a.equals(b) && a.subarray(0, 8).toString() === 'NIWARAY1' && a.length === at + 36 * rays && rays >= 1024 && hits > 0 && hits <= rays);
  for (const cmd of [native, wasm]) {
    const r = spawn(cmd, refusedRocks);
    check(`${buildName(cmd)} moss grow --scene rocks --rock-triangles 1000000 --max-memory 3G (300 days): exit ${r.status}, "${r.stderr.trim()}"`,
      r.status === 2 && r.stderr.startsWith('niwa: error: --max-seconds: growing 300 days') && r.stderr.includes('1,638,400 soil cells') && r.stdout === '');
    const m = spawn(cmd, overMemory);
    check(`${buildName(cmd)} moss grow --scene rocks --rock-triangles 1000000 --days 3 (the default 2 GB): exit ${m.status}, "${m.stderr.trim()}"`,
      m.status === 2 && m.stderr.startsWith('niwa: error: --max-memory: growing 3 days') && m.stderr.includes('1,638,400 soil cells') && m.stdout === '');
    for (const [args, want] of [[notRocks, '--rock-triangles: given without the rocks scene'], [outOfRange, '--rock-triangles'], [badEnding, '--rays']]) {
      const q = spawn(cmd, args);
      check(`${buildName(cmd)} ${args.slice(1).join(' ')}: exit ${q.status}, "${q.stderr.trim()}"`,
        q.status === 2 && q.stderr.trim().split('\n').length === 1 && q.stderr.startsWith(`niwa: error: ${want}`) && !existsSync(join(dir, 'rays.txt')));
    }
  }
  const rocks = run(native, rocksLink), rocksW = run(wasm, rocksLink);
  const st = JSON.parse(rocks);
  check(`moss grow --scene rocks --rock-triangles 6400: native == WASM; rock_triangles ${st.rock_triangles} in the stats, url ${st.url}`,
    JSON.stringify(withoutMs(st)) === JSON.stringify(withoutMs(JSON.parse(rocksW))) && st.rock_triangles === 6400 && st.url.includes('rock_triangles=6400'));
}

// Hostile values: exit 2, one line naming the flag, in both builds.
const hostile = [
  [['--geology', 'clay', '--theta', '0.2', '--S', '25'], '--geology'],
  [['--geology', 'sandy', '--theta', '0.4', '--S', '25'], '--theta'],
  [['--geology', 'humus', '--theta', 'nan', '--S', '25'], '--theta'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '-1'], '--S'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--mM', '2'], '--mM'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--T', '0x120'], '--T'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--preset', 'nope'], '--preset'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--set', 'humus_theta_sat=2'], '--set'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--url', 'T=290&T=291'], '--url'],
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--set', 'N=9'], 'N'],
  // The sky view applies only to the sky-view longwave (nomura2010-sky, longwave=1).
  [['--geology', 'humus', '--theta', '0.2', '--S', '25', '--V', '0.5'], '--V'],
];
await W.prepare(hostile.map(([args]) => ['moss', 'soil', ...args]));
for (const [args, field] of hostile) {
  for (const cmd of [native, wasm]) {
    const r = spawn(cmd, ['moss', 'soil', ...args]);
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} moss soil ${args.slice(6).join(' ') || args.join(' ')}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${field}`) && r.stdout === '');
  }
}
// A land mesh of the user's (--mesh): a glTF whose three materials are named humus, sand and
// asphalt; geology per triangle from them, the same bytes in both builds; the file is not in the link.
{
  const mesh = join(root, 'tests/data/meshes/materials.glb');
  const args = ['moss', 'grow', '--mesh', mesh, '--days', '5', '--photons', '512', '--stats'];
  const textured = ['moss', 'grow', '--mesh', join(root, 'tests/data/meshes/textured.glb'), '--days', '3', '--photons', '512', '--stats'];
  const flower = ['moss', 'grow', '--mesh', join(root, 'tests/data/meshes/flower_blue.glb'), '--days', '2', '--photons', '256', '--stats'];
  await W.prepare([args, textured, flower]);
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
  const s = JSON.parse(a);
  check(`moss grow --mesh materials.glb: native == WASM; ${s.cells.total} cells (${JSON.stringify(s.cells.by_geology)}), ${s.mosses.total} mosses`,
    a === b && s.scene === 'mesh' && s.mesh === 'materials.glb' && s.cells.by_geology.humus > 0 &&
    s.cells.by_geology.sandy > 0 && s.cells.by_geology.asphalt > 0 && s.mosses.total > 0 && !s.url.includes('materials'));
}

// Geology from a base colour texture: textured.glb's 2 x 1 texture is humus on its left half and
// sandy on its right (its material has no geology in its name and a white factor, which alone gives
// sandy everywhere), so --stats counts as many humus cells as sandy ones and no asphalt; ez-tree's
// flower_blue.glb (three PNG textures, four plain colours) reads in both builds alike.
{
  const args = ['moss', 'grow', '--mesh', join(root, 'tests/data/meshes/textured.glb'), '--days', '3', '--photons', '512', '--stats'];
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
  const g = JSON.parse(a).cells.by_geology;
  check(`moss grow --mesh textured.glb: native == WASM; cells by geology ${JSON.stringify(g)} follow the texture's halves`,
    a === b && g.humus > 0 && g.humus === g.sandy && (g.asphalt ?? 0) === 0);
  const flower = ['moss', 'grow', '--mesh', join(root, 'tests/data/meshes/flower_blue.glb'), '--days', '2', '--photons', '256', '--stats'];
  const fa = JSON.stringify(withoutMs(JSON.parse(run(native, flower))));
  const fb = JSON.stringify(withoutMs(JSON.parse(run(wasm, flower))));
  check(`moss grow --mesh flower_blue.glb (textured): native == WASM; ${JSON.stringify(JSON.parse(fa).cells.by_geology)}`,
    fa === fb && JSON.parse(fa).cells.total > 0);
}

// KHR_texture_transform and texCoord 1 (tests/support/make_texture_transform_meshes.mjs): each square's
// texture seam moved by its transform or UV set gives the same cells by geology in both builds, and
// a texCoord naming a UV set the primitive lacks is one line naming it, exit 2, in both.
{
  const split = {
    'texture_offset.glb': [1024, 3072], 'texture_scale.glb': [2048, 2048], 'texture_rotation.glb': [2048, 2048],
    'texture_texcoord1.glb': [2048, 2048], 'texture_transform_texcoord1.glb': [1024, 3072],
  };
  const splitArgs = (file) => ['moss', 'grow', '--mesh', join(root, 'tests/data/meshes', file), '--days', '2', '--photons', '256', '--stats'];
  const missing = join(root, 'tests/data/meshes/texture_missing_texcoord.glb');
  await W.prepare([...Object.keys(split).map(splitArgs), ['moss', 'grow', '--mesh', missing, '--days', '1', '--stats']]);
  for (const [file, [humus, sandy]] of Object.entries(split)) {
    const args = splitArgs(file);
    const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
    const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
    const g = JSON.parse(a).cells.by_geology;
    check(`moss grow --mesh ${file}: native == WASM; cells by geology ${JSON.stringify(g)} (want humus ${humus}, sandy ${sandy})`,
      a === b && g.humus === humus && g.sandy === sandy && (g.asphalt ?? 0) === 0);
  }
  const want = "niwa: error: --mesh: texture_missing_texcoord.glb: mesh 0 'ground' primitive 0: material 0 'ground' baseColorTexture reads TEXCOORD_1, which the primitive does not have";
  for (const cmd of [native, wasm]) {
    const r = spawn(cmd, ['moss', 'grow', '--mesh', missing, '--days', '1', '--stats']);
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} moss grow --mesh texture_missing_texcoord.glb: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0] === want && r.stdout === '');
  }
}

// A Niwa tree as the land (core/compose/moss_on_tree): its bark (sandy) on a humus square; the
// cells and mosses by region name both, the same bytes in both builds.
{
  const args = ['moss', 'grow', '--tree-preset', 'sakura', '--tree-years', '4', '--days', '3', '--photons', '512', '--stats'];
  const everyArgs = ['moss', 'grow', '--scene', 'walls', '--days', '5', '--photons', '512', '--stats', '--every', '2'];
  const terrainArgs = ['moss', 'grow', '--terrain-preset', 'fig13b', '--terrain-seed', '3', '--days', '2', '--photons', '256', '--set', 'soil_edge=2', '--stats'];
  await W.prepare([args, everyArgs, terrainArgs]);
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
  const s = JSON.parse(a);
  check(`moss grow --tree-preset sakura --tree-years 4: native == WASM; cells ${JSON.stringify(s.cells.by_region)} ${JSON.stringify(s.cells.by_geology)}, ${s.mosses.total} mosses`,
    a === b && s.scene === 'tree' && s.tree === 'sakura' && s.tree_years === 4 && s.cells.by_region.bark > 0 && s.cells.by_region.ground > 0 &&
    s.cells.by_geology.sandy === s.cells.by_region.bark && s.cells.by_geology.humus === s.cells.by_region.ground);
  // The land is in the link: --url alone regrows the same stats and moss.json, in both builds.
  check(`moss grow --tree-preset: url ${s.url} holds the tree`, /(^|&)scene=tree(&|$)/.test(s.url) && s.url.includes('tree=sakura&tree_years=4'));
  const again = ['moss', 'grow', '--url', s.url, '--stats'];
  const ua = JSON.stringify(withoutMs(JSON.parse(run(native, again))));
  const ub = JSON.stringify(withoutMs(JSON.parse(run(wasm, again))));
  check('moss grow --url (tree land): the same stats as the flags, native == WASM', ua === a && ub === a);
}

// Stats every K days (--every K with --stats): rows at days K, 2K, ... and the last, native == WASM,
// the last row the stats' own breakdown.
{
  const args = ['moss', 'grow', '--scene', 'walls', '--days', '5', '--photons', '512', '--stats', '--every', '2'];  // prepared above
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
  const s = JSON.parse(a);
  const rows = s.every_days ?? [];
  const last = rows[rows.length - 1] ?? {};
  check(`moss grow --stats --every 2 (5 days): native == WASM; rows on days ${rows.map((r) => r.day)}, by region ${JSON.stringify(rows.map((r) => r.mosses.by_region))}`,
    a === b && s.every === 2 && rows.map((r) => r.day).join() === '2,4,5' &&
    JSON.stringify(last.mosses) === JSON.stringify(s.mosses) && JSON.stringify(last.soil) === JSON.stringify(s.soil_last_day) &&
    JSON.stringify(last.deaths) === JSON.stringify(s.deaths));
  const plain = JSON.parse(run(native, args.slice(0, -2)));
  check('moss grow --stats without --every: no rows', !('every_days' in plain) && !('every' in plain));
}

// A Niwa terrain as the land (core/compose/moss_on_terrain): geology by slope and height, regions
// by height; the flags and the url regrow the same bytes in both builds.
{
  const args = ['moss', 'grow', '--terrain-preset', 'fig13b', '--terrain-seed', '3', '--days', '2', '--photons', '256', '--set', 'soil_edge=2', '--stats'];  // prepared above
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
  const s = JSON.parse(a);
  check(`moss grow --terrain-preset fig13b --terrain-seed 3: native == WASM; cells ${JSON.stringify(s.cells.by_region)} ${JSON.stringify(s.cells.by_geology)}, ${s.mosses.total} mosses`,
    a === b && s.scene === 'terrain' && s.terrain === 'fig13b' && s.terrain_seed === 3 &&
    s.cells.by_region.foot > 0 && s.cells.by_region.top > 0 && s.cells.by_geology.humus > 0 && s.cells.by_geology.sandy > 0);
  const again = ['moss', 'grow', '--url', s.url, '--stats'];
  const ua = JSON.stringify(withoutMs(JSON.parse(run(native, again))));
  const ub = JSON.stringify(withoutMs(JSON.parse(run(wasm, again))));
  check(`moss grow --url ${s.url}: the same stats as the flags, native == WASM`, ua === a && ub === a);
  const other = JSON.parse(run(native, ['moss', 'grow', '--terrain-preset', 'fig13b', '--terrain-seed', '4', '--days', '0', '--set', 'soil_edge=2', '--stats']));
  check(`moss grow --terrain-seed 4: another mountain (${other.cells.total} cells against ${s.cells.total})`,
    JSON.stringify(other.cells) !== JSON.stringify(s.cells) || other.url !== s.url);
  // The default run on a mountain is over the 60 s budget: refused before anything grows.
  const r = spawn(native, ['moss', 'grow', '--terrain-preset', 'improved']);
  check(`moss grow --terrain-preset improved (300 days): refused up front, "${r.stderr.trim()}"`,
    r.status === 2 && r.stderr.startsWith('niwa: error: --max-seconds') && r.stdout === '');
}

const growHostile = [
  [['--mesh', join(root, 'tests/data/meshes/truncated.glb')], '--mesh'],
  [['--mesh', join(root, 'tests/data/meshes/empty.glb')], '--mesh'],
  [['--mesh', join(root, 'tests/data/meshes/materials.glb'), '--scene', 'thesis'], '--mesh'],
  [['--tree-preset', 'baobab'], '--tree-preset'], [['--tree-preset', 'sakura', '--tree-years', '0'], '--tree-years'],
  [['--tree-preset', 'sakura', '--scene', 'thesis'], '--scene'],
  [['--every', '2', '--days', '1'], '--every'], [['--stats', '--every', '0', '--days', '1'], '--every'], [['--stats', '--every', '1.5'], '--every'],
  [['--tree-years', '4'], '--tree-years'], [['--scene', 'thesis', '--tree-years', '4'], '--tree-years'],
  [['--url', 'preset=nomura2010&scene=thesis', '--tree-years', '4'], '--tree-years'],
  [['--terrain-seed', '2'], '--terrain-seed'], [['--tree-preset', 'sakura', '--terrain-seed', '2'], '--terrain-seed'],
  [['--terrain-preset', 'everest', '--days', '1'], '--terrain-preset'], [['--terrain-preset', 'fig16', '--terrain-seed', '-1'], '--terrain-seed'],
  [['--terrain-preset', 'fig16', '--tree-preset', 'sakura'], '--tree-preset'], [['--terrain-preset', 'Bad!'], '--terrain-preset'],
  [['--scene', 'garden'], '--scene'], [['--days', '-1'], '--days'], [['--days', '2.5'], '--days'],
  [['--indirect', 'maybe'], '--indirect'], [['--out', 'x.glb', '--map', 'G'], '--map'], [['--map', 'S'], '--map'],
  [['--instancing'], '--instancing'], [['--out', 'x.json', '--instancing'], '--instancing'], [['--seed', '1e20'], '--seed'], [['--photons', 'nan'], '--photons'],
  [['--max-seconds', '1'], '--max-seconds'], [['--set', 'sun_path=1', '--days', '1'], 'sun_path'],
];
const zenigoke = ['moss', 'fitness', '--species', 'zenigoke', '--Ts', '286', '--rhs', '1', '--S', '20'];
await W.prepare([...growHostile.map(([args]) => ['moss', 'grow', ...args]), zenigoke]);
for (const [args, field] of growHostile) {
  for (const cmd of [native, wasm]) {
    const r = spawn(cmd, ['moss', 'grow', ...args]);
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} moss grow ${args.join(' ')}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${field}`) && r.stdout === '');
  }
}
for (const cmd of [native, wasm]) {
  const r = spawn(cmd, zenigoke);
  check(`${buildName(cmd)} moss fitness --species zenigoke: exit ${r.status}, "${r.stderr.trim()}"`,
    r.status === 2 && r.stderr.trim().split('\n').length === 1 && r.stderr.startsWith('niwa: error: --species'));
}

console.log(`(the WASM runs: ${W.summary()})`);
rmSync(dir, { recursive: true, force: true });
finish();
