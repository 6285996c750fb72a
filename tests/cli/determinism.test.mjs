// Native vs WASM CLI, byte for byte: for every preset and seeds 1 and 7, the --stats (minus the ms
// fields), the .json, the .glb and the .svg of the same tree are the same in both builds. The WASM
// runs are batched in niwa_cli_batch.js (the same RunCli; a niwa.js start under node costs about
// 0.3 CPU s), every NIWA_DETERMINISM_WASM_EVERY-th (default 4) as one niwa.js process each
// (support/cli_batch.mjs PreparedCli).
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PreparedCli } from '../support/cli_batch.mjs';
import { check, finish, native, requireWasm, run as runOne, wasm, withoutMs } from '../support/cli_pair.mjs';

const years = Number(process.env.NIWA_DETERMINISM_YEARS || 15);
requireWasm();

const dir = mkdtempSync(join(tmpdir(), 'niwa-det-'));
const W = new PreparedCli(wasm, { every: Math.max(1, Number(process.env.NIWA_DETERMINISM_WASM_EVERY || 4)), work: dir, jobs: 1 });
const run = (cmd, args) => (cmd === wasm ? W.run(args) : runOne(cmd, args));
const presets = run(native, ['presets']).trim().split('\n').map((l) => l.split('\t')[0]);
check(`presets listed: ${presets.join(', ')}`, presets.length >= 4);
const growArgs = (preset, seed) => ['tree', 'grow', '--preset', preset, '--years', String(years), '--seed', String(seed)];
const swayArgs = (preset) => ['tree', 'sway', '--preset', preset, '--years', '8', '--wind', '12', '--gust', '0.5:3', '--duration', '5'];
await W.prepare([
  ...presets.flatMap((preset) => [1, 7].flatMap((seed) => [
    [...growArgs(preset, seed), '--stats', '--out', join(dir, `${preset}-${seed}-w.json`)],
    ...['glb', 'svg'].map((ext) => [...growArgs(preset, seed), '--out', join(dir, `${preset}-${seed}-w.${ext}`)]),
  ])),
  ...['keyaki', 'tsutsuji'].map((preset) => [...swayArgs(preset), '--csv', join(dir, `${preset}-w.csv`)]),
]);
for (const preset of presets) {
  for (const seed of [1, 7]) {
    const args = growArgs(preset, seed);
    const file = (build, ext) => join(dir, `${preset}-${seed}-${build}.${ext}`);
    const a = JSON.parse(run(native, [...args, '--stats', '--out', file('n', 'json')]));
    const b = JSON.parse(run(wasm, [...args, '--stats', '--out', file('w', 'json')]));
    check(`${preset} seed ${seed}: --stats native == WASM (${a.internodes} internodes, ${a.leaves} leaves)`,
      JSON.stringify(withoutMs(a)) === JSON.stringify(withoutMs(b)));
    for (const ext of ['glb', 'svg']) {
      run(native, [...args, '--out', file('n', ext)]);
      run(wasm, [...args, '--out', file('w', ext)]);
    }
    for (const ext of ['json', 'glb', 'svg']) {
      const x = readFileSync(file('n', ext)), y = readFileSync(file('w', ext));
      check(`${preset} seed ${seed}: .${ext} identical (${x.length} bytes native, ${y.length} WASM)`, x.length > 100 && x.equals(y));
    }
  }
}
// Sway (thesis ch. 3): the tip trajectories are the same bytes in both builds.
for (const preset of ['keyaki', 'tsutsuji']) {
  const args = swayArgs(preset);
  run(native, [...args, '--csv', join(dir, `${preset}-n.csv`)]);
  run(wasm, [...args, '--csv', join(dir, `${preset}-w.csv`)]);
  const a = readFileSync(join(dir, `${preset}-n.csv`), 'utf8'), b = readFileSync(join(dir, `${preset}-w.csv`), 'utf8');
  check(`${preset} sway: native and WASM tip trajectories identical (${a.split('\n').length} lines)`, a.length > 100 && a === b);
}
console.log(`(the WASM runs: ${W.summary()})`);
rmSync(dir, { recursive: true, force: true });
finish();
