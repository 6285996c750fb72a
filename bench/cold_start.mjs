// Cold-start timings (issue 17 item 7): what a newcomer waits for, as rows for bench/report.mjs.
// node bench/cold_start.mjs --native build/native/bin/niwa --wasm build/wasm/bin/niwa.js [--reps N]
//   [--build native|wasm]
// Prints one JSON object per line ({build, workload, ms (median), min_ms, reps, check}), the format
// of niwa_bench_runner, so scripts/bench appends them to its native-N.jsonl / wasm-N.jsonl:
//   cold/process-grow-sakura-thesis-15y  the wall time of a fresh 'niwa tree grow --preset
//       sakura-thesis --years 15 --stats' process (native: the binary; WASM: node + niwa.js, so it
//       includes node's own start and the module's compile and instantiation)
//   cold/first-grow-sakura-thesis-15y    the grow's own time in that fresh process (the stats'
//       "ms"): the first grow of a fresh instance, no warm-up
//   cold/start-only                      a fresh process that grows nothing ('niwa presets'): the
//       fixed cost of starting (dynamic linking or node + compile + instantiate)
// check: the tree's internode count (the same in both builds).
// Why the WASM first grow is slow (measured on the loaded 2-core test machine, node 20 / V8 11.3):
// V8 compiles each function lazily on its first call with Liftoff (baseline) and tiers hot ones up
// to TurboFan on background threads (--wasm-dynamic-tiering, budget 1.8 MB "executed"), which
// compete with the grow for the cores. The same first grow ran in 255-275 ms with
// --liftoff-only and 232-388 ms with --no-liftoff against 475-925 ms by default (all inflated by
// the load, same runs interleaved). Memory growth is not it: -sINITIAL_MEMORY=64MB (no growth)
// gave the same main-thread CPU (157-186 ms against 161-184 ms with the default 16 MB).
import { spawnSync } from 'node:child_process';
import { performance } from 'node:perf_hooks';

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].slice(2)] = process.argv[i + 1];
const reps = Math.max(1, Number(args.reps ?? 10));
const grow = ['tree', 'grow', '--preset', 'sakura-thesis', '--years', '15', '--stats'];

function timed(cmd, argv) {
  const start = performance.now();
  const r = spawnSync(cmd, argv, { encoding: 'utf8' });
  const ms = performance.now() - start;
  if (r.status !== 0) throw new Error(`${cmd} ${argv.join(' ')}: exit ${r.status}: ${r.stderr}`);
  return { ms, stdout: r.stdout };
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const row = (build, workload, samples, check) => JSON.stringify({
  build, workload, ms: median(samples), min_ms: Math.min(...samples), reps: samples.length, check,
});

function measure(build, cmd, prefix) {
  const wall = [], first = [], start = [];
  let check = 0;
  for (let i = 0; i < reps; ++i) {  // interleaved, so a slow spell of the machine hits both
    const run = timed(cmd, [...prefix, ...grow]);
    const stats = JSON.parse(run.stdout);
    wall.push(run.ms);
    first.push(stats.ms);
    check = stats.internodes;
    start.push(timed(cmd, [...prefix, 'presets']).ms);
  }
  console.log(row(build, 'cold/process-grow-sakura-thesis-15y', wall, check));
  console.log(row(build, 'cold/first-grow-sakura-thesis-15y', first, check));
  console.log(row(build, 'cold/start-only', start, 0));
}

if (args.native && args.build !== 'wasm') measure('native', args.native, []);
if (args.wasm && args.build !== 'native') measure('wasm', process.execPath, [args.wasm]);
