// Native vs WASM CLI: for every preset, same --stats counts, same JSON topology, positions within 1e-5 of height.
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { check, finish, native, requireWasm, run, wasm } from '../support/cli_pair.mjs';

const years = Number(process.env.NIWA_DETERMINISM_YEARS || 15);
requireWasm();

const dir = mkdtempSync(join(tmpdir(), 'niwa-det-'));
const presets = run(native, ['presets']).trim().split('\n').map((l) => l.split('\t')[0]);
check(presets.length >= 4, `presets listed: ${presets.join(', ')}`);
for (const preset of presets) {
  for (const seed of [1, 7]) {
    const args = ['tree', 'grow', '--preset', preset, '--years', String(years), '--seed', String(seed)];
    const a = JSON.parse(run(native, [...args, '--stats', '--out', join(dir, `${preset}-n.json`)]));
    const b = JSON.parse(run(wasm, [...args, '--stats', '--out', join(dir, `${preset}-w.json`)]));
    const keys = ['internodes', 'branches', 'leaves', 'flowers', 'years', 'seed', 'preset',
      'crown_width', 'crown_base_height', 'drooping_tips_share'];
    const same = keys.every((k) => a[k] === b[k]);
    check(same, `${preset} seed ${seed}: stats native ${JSON.stringify(keys.map((k) => a[k]))} wasm ${JSON.stringify(keys.map((k) => b[k]))}`);
    const ta = JSON.parse(readFileSync(join(dir, `${preset}-n.json`), 'utf8'));
    const tb = JSON.parse(readFileSync(join(dir, `${preset}-w.json`), 'utf8'));
    let topology = ta.branches.length === tb.branches.length;
    let worst = 0;
    for (let i = 0; topology && i < ta.branches.length; i++) {
      const x = ta.branches[i], y = tb.branches[i];
      topology = x.id === y.id && x.parent === y.parent && x.parent_node === y.parent_node &&
        x.nodes.length === y.nodes.length && x.leaves.length === y.leaves.length &&
        x.buds.length === y.buds.length && x.flowers.length === y.flowers.length;
      for (let n = 0; topology && n < x.nodes.length; n++) {
        for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(x.nodes[n][c] - y.nodes[n][c]));
      }
    }
    check(topology, `${preset} seed ${seed}: same topology (${ta.branches.length} branches)`);
    const tolerance = 1e-5 * Math.max(a.height, 1e-9);
    check(worst <= tolerance, `${preset} seed ${seed}: largest position difference ${worst.toExponential(2)} cm <= ${tolerance.toExponential(2)}`);
  }
}
// Sway (thesis ch. 3): the tip trajectories are the same bytes in both builds.
for (const preset of ['keyaki', 'tsutsuji']) {
  const args = ['tree', 'sway', '--preset', preset, '--years', '8', '--wind', '12', '--gust', '0.5:3',
    '--duration', '5'];
  run(native, [...args, '--csv', join(dir, `${preset}-n.csv`)]);
  run(wasm, [...args, '--csv', join(dir, `${preset}-w.csv`)]);
  const a = readFileSync(join(dir, `${preset}-n.csv`), 'utf8'), b = readFileSync(join(dir, `${preset}-w.csv`), 'utf8');
  check(a.length > 100 && a === b, `${preset} sway: native and WASM tip trajectories identical (${a.split('\n').length} lines)`);
}
finish();
