// The garden's time estimates beside the CPU time they stand for (docs/garden-model.md "The moss's
// estimate", "The ivy's estimate"): `niwa garden grow --stats` on the default garden and on the scale
// garden (bench/garden_workloads.cpp's garden/scale-100-trees-15y), each estimate (moss_s, ivy_s)
// over its CPU time (ms_moss_cpu, ms_ivy_cpu), with the machine's load; a figure taken at a load of
// 1.5 or more is marked "not measured idle" (the machine is shared: CPU time grows with the load).
// Prints one JSON line a garden. The unit tests hold the estimates to counted work, not to a clock
// (tests/compose garden_test TheIvysEstimateCountsItsWork, garden_moss_test
// TheMossEstimateCountsItsWork); the timing comparison is here.
//
// node bench/garden_estimates.mjs [--native build/native/bin/niwa]
// Does not: build anything, or fail on a ratio (it reports).
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const niwa = args[0] === '--native' && args[1] ? args[1] : path.join(ROOT, 'build/native/bin/niwa');
const MIX = ['keyaki', 'sakura', 'maple', 'pine', 'ginkgo', 'weeping', 'tsutsuji', 'binary', 'keyaki-thesis',
  'sakura-thesis'].map((s) => `${s}:1`).join(',');
const GARDENS = [
  { workload: 'garden-estimates/default', hash: '' },
  { workload: 'garden-estimates/scale-100-trees-15y',
    hash: `size=100&ground_res=512&years=15&density=0.0099&spacing=5&slope_max=90&mix=${MIX}` +
      '&ivy=objects[0],objects[1],objects[2],objects[3]' },
];
const load = () => Number(readFileSync('/proc/loadavg', 'utf8').split(' ')[0]);
const round = (x, d = 2) => Number(x.toFixed(d));

for (const g of GARDENS) {
  const before = load();
  const flags = ['garden', 'grow', '--stats', ...(g.hash ? ['--url', g.hash] : [])];
  let stats;
  try {
    stats = JSON.parse(execFileSync(niwa, flags, { encoding: 'utf8', maxBuffer: 64 << 20 }));
  } catch (e) {
    // A truncated garden exits 0 with its stats; anything else is reported and skipped.
    console.error(`garden_estimates: ${g.workload}: ${e.message.split('\n')[0]}`);
    continue;
  }
  const after = load();
  const e = stats.estimates ?? {};
  const mossCpu = stats.ms_moss_cpu / 1000, ivyCpu = stats.ms_ivy_cpu / 1000;
  console.log(JSON.stringify({
    workload: g.workload,
    note: 'niwa garden grow --stats: the budget\'s estimates over the CPU time of the same work',
    moss_estimate_s: round(e.moss_s ?? 0), moss_cpu_s: round(mossCpu), moss_ratio: mossCpu > 0 ? round(e.moss_s / mossCpu) : null,
    ivy_estimate_s: round(e.ivy_s ?? 0), ivy_cpu_s: round(ivyCpu), ivy_ratio: ivyCpu > 0 ? round((e.ivy_s ?? 0) / ivyCpu) : null,
    ivy_support_estimate_s: round(e.ivy_support_s ?? 0), ivy_support_cpu_s: round((stats.ms_ivy_support_cpu ?? 0) / 1000),
    ivy_steps: stats.ivy?.steps ?? null, ivy_internodes: stats.ivy?.internodes ?? null,
    moss_cells: stats.moss?.cells ?? null, moss_days: stats.moss?.days ?? null,
    truncated_by: stats.truncated_by ?? null,
    load: `${before} before, ${after} after`,
    measured: Math.max(before, after) < 1.5 ? 'idle' : 'not measured idle',
  }));
}
