// WASM/native speed ratios in ONE interleaved run (issue 18 item 6: "WASM <= 2x native" on the
// ivy workloads): runs build/native/bin/niwa_bench_runner and node build/wasm/bin/niwa_bench_runner.js
// alternately, `rounds` times each, on the workloads matching `filter`, and prints per workload the
// fastest rep's ratio (min_ms: the rep least disturbed by other processes) and the ratio of the
// median of the rounds' medians, with both means; a workload whose checksum differs between the
// builds is named (the results must be the same bits). On a machine shared with compiler jobs the
// medians of sub-millisecond workloads swing by 2-5x between rounds; the min ratio does not.
//
//   node bench/wasm_ratio.mjs [filter=ivy/] [rounds=3] [--min-ms MS]
// Does not: build anything or write docs (scripts/bench and bench/report.mjs do).
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const minMsAt = args.indexOf('--min-ms');
const minMs = minMsAt >= 0 ? args.splice(minMsAt, 2)[1] : '600';
const [filter = 'ivy/', roundsText = '3'] = args;
const rounds = Number(roundsText);
if (!Number.isInteger(rounds) || rounds < 1 || rounds > 20) {
  console.error('wasm_ratio: rounds must be a whole number in [1, 20]');
  process.exit(2);
}

const parse = (text) => text.split('\n').filter((l) => l.startsWith('{')).map((l) => JSON.parse(l));
const run = (build) => parse(build === 'native'
  ? execFileSync(path.join(ROOT, 'build/native/bin/niwa_bench_runner'), ['--filter', filter, '--min-ms', minMs], { encoding: 'utf8' })
  : execFileSync('node', [path.join(ROOT, 'build/wasm/bin/niwa_bench_runner.js'), '--filter', filter, '--min-ms', minMs], { encoding: 'utf8' }));

const rows = new Map();  // workload -> {native: [rows], wasm: [rows]}
for (let r = 0; r < rounds; ++r) {
  for (const build of r % 2 === 0 ? ['native', 'wasm'] : ['wasm', 'native']) {
    for (const row of run(build)) {
      if (!rows.has(row.workload)) rows.set(row.workload, { native: [], wasm: [] });
      rows.get(row.workload)[build].push(row);
    }
  }
}
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
};
const out = [];
const mismatched = [];
console.log(`workload                      native min   WASM min  min ratio | native med  WASM med  med ratio   (${rounds} rounds)`);
for (const [name, { native, wasm }] of rows) {
  if (!native.length || !wasm.length) continue;
  const nMin = Math.min(...native.map((r) => r.min_ms)), wMin = Math.min(...wasm.map((r) => r.min_ms));
  const nMed = median(native.map((r) => r.ms)), wMed = median(wasm.map((r) => r.ms));
  if (new Set([...native, ...wasm].map((r) => r.check)).size !== 1) mismatched.push(name);
  out.push({ workload: name, min_ratio: wMin / nMin, median_ratio: wMed / nMed });
  console.log(`${name.padEnd(28)} ${nMin.toFixed(3).padStart(10)} ${wMin.toFixed(3).padStart(10)} ${(wMin / nMin).toFixed(2).padStart(9)}x | ${nMed.toFixed(3).padStart(10)} ${wMed.toFixed(3).padStart(9)} ${(wMed / nMed).toFixed(2).padStart(9)}x`);
}
const mean = (key) => out.reduce((s, r) => s + r[key], 0) / out.length;
const worst = out.reduce((a, b) => (b.min_ratio > a.min_ratio ? b : a), out[0]);
console.log(`mean min ratio ${mean('min_ratio').toFixed(2)}x (worst ${worst?.workload} ${worst?.min_ratio.toFixed(2)}x), mean median ratio ${mean('median_ratio').toFixed(2)}x`);
console.log(JSON.stringify({ filter, rounds, mean_min_ratio: mean('min_ratio'), mean_median_ratio: mean('median_ratio'), mismatched, rows: out }));
if (mismatched.length) {
  console.error(`wasm_ratio: checksums differ between the builds: ${mismatched.join(', ')}`);
  process.exit(1);
}
