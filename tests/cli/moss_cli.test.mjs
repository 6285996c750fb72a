// Moss CLI: native == WASM bytes of `niwa moss soil` (every term of eqs 3.2-3.16) over every
// geology, both presets and both eq 3.15 forms, and of `niwa moss fitness` (eqs 3.17-3.20) for every
// species and both g forms; the spec's §1.4 reference values and the balance's residual as printed;
// `niwa params moss` / `niwa presets moss` in both builds; hostile values one line naming the flag;
// `niwa moss grow` (--stats and --out moss.json) and `niwa moss photons` native == WASM byte for
// byte on every built-in scene, both presets, seeds 1-2, at a few days and photons.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { buildName, check, finish, native, requireWasm, root, run, spawn, wasm, withoutMs } from '../support/cli_pair.mjs';

requireWasm();

const near = (got, want) => Math.abs(got - want) <= 1e-4 * Math.abs(want);

// Soil: one cell, both builds, byte for byte.
let soilCases = 0;
for (const geology of ['humus', 'sandy', 'asphalt']) {
  for (const theta of ['0', '0.01', '0.012']) {
    for (const S of ['0', '25', '250']) {
      for (const extra of [[], ['--preset', 'nomura2010-sky', '--V', '0.4'], ['--set', 'delta_form=1', '--mM', '1', '--T', '293.15']]) {
        const args = ['moss', 'soil', '--geology', geology, '--theta', theta, '--S', S, ...extra];
        const a = run(native, args), b = run(wasm, args);
        ++soilCases;
        if (a !== b) check(`soil ${args.join(' ')}: native == WASM`, false, `${a}\n${b}`);
      }
    }
  }
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
for (const species of ['gingoke', 'haigoke', 'sugigoke', null]) {
  for (const [Ts, rhs, S] of [['278.1', '1.01148', '25'], ['290', '1.3', '0'], ['300', '0.7', '250']]) {
    for (const extra of [[], ['--set', 'g_form=1']]) {
      const args = ['moss', 'fitness', ...(species ? ['--species', species] : []), '--Ts', Ts, '--rhs', rhs, '--S', S, ...extra];
      const a = run(native, args), b = run(wasm, args);
      ++fitnessCases;
      if (a !== b) check(`fitness ${args.join(' ')}: native == WASM`, false, `${a}\n${b}`);
    }
  }
}
check(`moss fitness: ${fitnessCases} places: native == WASM byte for byte`, fitnessCases === 24);
const all = JSON.parse(run(native, ['moss', 'fitness', '--Ts', '278.1', '--rhs', '1.01148', '--S', '25']));
const sugi = all.species.find((s) => s.species === 'sugigoke');
check(`moss fitness (no --species): all three species; sugigoke G ${sugi.G} (by hand 0.494344481506)`,
  all.species.length === 3 && Math.abs(sugi.G - 0.4943444815062233) < 1e-12);

// The table and presets, both builds.
for (const args of [['params', 'moss', '--json'], ['params', 'moss'], ['presets', 'moss']]) {
  const a = run(native, args), b = run(wasm, args);
  check(`niwa ${args.join(' ')}: native == WASM (${a.length} bytes)`, a.length > 100 && a === b);
}

// The run: every scene, both presets, seeds 1-2; --stats (no timing fields) and moss.json.
const dir = mkdtempSync(join(tmpdir(), 'niwa-moss-'));
let growCases = 0, withMosses = 0;
for (const scene of ['plane', 'thesis', 'walls', 'rocks']) {
  for (const preset of ['nomura2010', 'nomura2010-sky']) {
    for (const seed of ['1', '2']) {
      const args = ['moss', 'grow', '--scene', scene, '--preset', preset, '--seed', seed, '--days', '12', '--photons', '1024', '--stats'];
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
      for (const m of list.mosses)
        if (!['gingoke', 'haigoke', 'sugigoke'].includes(m.species) || m.pos.length !== 3 || m.normal.length !== 3 ||
            !(m.birth_day >= 0 && m.birth_day <= 12) || !Number.isFinite(m.G_moss)) {
          check(`grow ${scene}: a moss's fields`, false, JSON.stringify(m));
          break;
        }
    }
  }
}
check(`moss grow: ${growCases} runs (4 scenes x 2 presets x seeds 1-2, 12 days, 1,024 photons): --stats and moss.json native == WASM byte for byte; ${withMosses} with living mosses`,
  growCases === 16 && withMosses >= 8);
rmSync(dir, { recursive: true, force: true });
for (const scene of ['plane', 'thesis', 'walls', 'rocks']) {
  for (const indirect of ['on', 'off']) {
    const args = ['moss', 'photons', '--scene', scene, '--photons', '2048', '--indirect', indirect, '--preset', 'nomura2010-sky'];
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
  const a = JSON.stringify(withoutMs(JSON.parse(run(native, args))));
  const b = JSON.stringify(withoutMs(JSON.parse(run(wasm, args))));
  const s = JSON.parse(a);
  check(`moss grow --mesh materials.glb: native == WASM; ${s.cells.total} cells (${JSON.stringify(s.cells.by_geology)}), ${s.mosses.total} mosses`,
    a === b && s.scene === 'mesh' && s.mesh === 'materials.glb' && s.cells.by_geology.humus > 0 &&
    s.cells.by_geology.sandy > 0 && s.cells.by_geology.asphalt > 0 && s.mosses.total > 0 && !s.url.includes('materials'));
}

for (const [args, field] of [
  [['--mesh', join(root, 'tests/data/meshes/truncated.glb')], '--mesh'],
  [['--mesh', join(root, 'tests/data/meshes/empty.glb')], '--mesh'],
  [['--mesh', join(root, 'tests/data/meshes/materials.glb'), '--scene', 'thesis'], '--mesh'],
  [['--scene', 'garden'], '--scene'], [['--days', '-1'], '--days'], [['--days', '2.5'], '--days'],
  [['--indirect', 'maybe'], '--indirect'], [['--seed', '1e20'], '--seed'], [['--photons', 'nan'], '--photons'],
  [['--max-seconds', '1'], '--max-seconds'], [['--set', 'light_smoothing_days=2', '--days', '1'], 'light_smoothing_days'],
]) {
  for (const cmd of [native, wasm]) {
    const r = spawn(cmd, ['moss', 'grow', ...args]);
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} moss grow ${args.join(' ')}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${field}`) && r.stdout === '');
  }
}
for (const cmd of [native, wasm]) {
  const r = spawn(cmd, ['moss', 'fitness', '--species', 'zenigoke', '--Ts', '286', '--rhs', '1', '--S', '20']);
  check(`${buildName(cmd)} moss fitness --species zenigoke: exit ${r.status}, "${r.stderr.trim()}"`,
    r.status === 2 && r.stderr.trim().split('\n').length === 1 && r.stderr.startsWith('niwa: error: --species'));
}

finish();
