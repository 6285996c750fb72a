// Native vs WASM CLI, byte for byte: for every preset and seeds 1 and 7, the --stats (minus the ms
// fields), the .json, the .glb and the .svg of the same tree are the same in both builds.
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { check, finish, native, requireWasm, run, wasm, withoutMs } from '../support/cli_pair.mjs';

const years = Number(process.env.NIWA_DETERMINISM_YEARS || 15);
requireWasm();

const dir = mkdtempSync(join(tmpdir(), 'niwa-det-'));
const presets = run(native, ['presets']).trim().split('\n').map((l) => l.split('\t')[0]);
check(`presets listed: ${presets.join(', ')}`, presets.length >= 4);
for (const preset of presets) {
  for (const seed of [1, 7]) {
    const args = ['tree', 'grow', '--preset', preset, '--years', String(years), '--seed', String(seed)];
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
  const args = ['tree', 'sway', '--preset', preset, '--years', '8', '--wind', '12', '--gust', '0.5:3',
    '--duration', '5'];
  run(native, [...args, '--csv', join(dir, `${preset}-n.csv`)]);
  run(wasm, [...args, '--csv', join(dir, `${preset}-w.csv`)]);
  const a = readFileSync(join(dir, `${preset}-n.csv`), 'utf8'), b = readFileSync(join(dir, `${preset}-w.csv`), 'utf8');
  check(`${preset} sway: native and WASM tip trajectories identical (${a.split('\n').length} lines)`, a.length > 100 && a === b);
}
finish();
