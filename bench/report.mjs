// Formats scripts/bench results: the native/WASM markdown table on stdout, and docs/BENCHMARKS.md.
//
// node bench/report.mjs --native N.jsonl --wasm W.jsonl [--peer P.jsonl] [--gbench G.txt]
//                       [--meta META.json] [--record docs/BENCHMARKS.md]
// N/W/P hold one JSON object per line as printed by niwa_bench_runner / ez_tree_peer.mjs; META holds
// {date, machine, cpu, cores, tools, load, command, seconds}.
import {readFileSync, writeFileSync, existsSync} from 'node:fs';

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].slice(2)] = process.argv[i + 1];

const readLines = (file) =>
  file && existsSync(file)
    ? readFileSync(file, 'utf8').split('\n').filter((l) => l.startsWith('{')).map((l) => JSON.parse(l))
    : [];
const byName = (rows) => new Map(rows.map((r) => [r.workload, r]));

const native = byName(readLines(args.native));
const wasm = byName(readLines(args.wasm));
const peer = readLines(args.peer);
const gbench = args.gbench && existsSync(args.gbench) ? readFileSync(args.gbench, 'utf8').trim() : '';
const meta = args.meta ? JSON.parse(readFileSync(args.meta, 'utf8')) : {};

const fmt = (ms) => (ms === undefined ? '—' : ms >= 100 ? ms.toFixed(0) : ms >= 1 ? ms.toFixed(1) : ms.toFixed(3));
const names = [...new Set([...native.keys(), ...wasm.keys()])];
const mismatched = [];
let table = '| workload | native ms | WASM ms | WASM/native |\n|---|--:|--:|--:|\n';
for (const name of names) {
  const n = native.get(name), w = wasm.get(name);
  const ratio = n && w ? `${(w.ms / n.ms).toFixed(2)}×` : '—';
  if (n && w && n.check !== w.check) mismatched.push(name);
  table += `| ${name} | ${fmt(n?.ms)} | ${fmt(w?.ms)} | ${ratio} |\n`;
}

const notes = [];
const lightRatio = (m) => {
  const g = m.get('light/grid-2000'), r = m.get('light/reference-2000');
  return g && r ? (r.ms / g.ms).toFixed(1) : null;
};
if (lightRatio(native)) {
  notes.push(`Light model: the pairwise reference takes ${lightRatio(native)}× the voxel grid's time ` +
             `natively and ${lightRatio(wasm) ?? '—'}× in WASM (2,000 spheres).`);
}
notes.push(mismatched.length
  ? `**Checksums differ between native and WASM for: ${mismatched.join(', ')}.**`
  : 'Every workload returned the same checksum natively and in WASM (same trees, meshes, .glb sizes and light sums).');

let peerTable = '';
for (const p of peer) {
  if (!peerTable) peerTable = '| peer workload (JavaScript in node, for reference) | ms | vertices |\n|---|--:|--:|\n';
  peerTable += `| ${p.workload} | ${fmt(p.ms)} | ${p.vertices ?? '—'} |\n`;
}
if (peer.length) {
  const g = wasm.get('grow/sakura-15y'), m = wasm.get('mesh/sakura-15y');
  if (g && m) {
    notes.push(`Peer: ez-tree builds a different kind of tree (a recursive branching recipe straight to geometry, ` +
               `no simulation). The closest Niwa job, growing sakura 15 years and building its mesh in WASM, ` +
               `takes ${fmt(g.ms + m.ms)} ms.`);
  }
}

const out = `${table}\n${peerTable ? peerTable + '\n' : ''}${notes.map((n) => `- ${n}`).join('\n')}\n`;
process.stdout.write(out);

if (args.record) {
  const doc = `# Benchmarks

Recorded by \`${meta.command ?? 'scripts/bench --record'}\` (the whole run took ${meta.seconds ?? '?'} s).

- Date: ${meta.date ?? '?'}
- Machine: ${meta.machine ?? '?'}, ${meta.cores ?? '?'} cores, ${meta.cpu ?? '?'}
- Tools: ${meta.tools ?? '?'}
- Load average (1 min): ${meta.load ?? '?'} (a shared 2-core machine: expect a few % noise,
  more when something else runs)

## Native vs WASM

Same workloads (\`bench/workloads.cpp\`, over the public core API) in both builds, run by
\`niwa_bench_runner\`: \`build/native/bin/niwa_bench_runner\` and
\`node build/wasm/bin/niwa_bench_runner.js\` (presets native-release and wasm-release, both \`-O3\`,
no fast-math, \`-ffp-contract=off\`). Each workload is prepared untimed, run once as a warm-up, then
repeated at least 3 times and for at least 0.3 s (at most 200 times); the table shows the median
wall time (\`std::chrono::steady_clock\`).

${out}
Workloads:

- \`grow/<preset>-<N>y\`: \`GrowTree\` of a preset with its parameters for N years, seed 1 (every
  preset at its default age, plus sakura at 10, 20 and 30 years; 40 years would take about 4 s natively).
- \`mesh/sakura-15y\`: \`BuildTreeMesh\` of the sakura 15-year tree (grown untimed).
- \`glb/sakura-15y\`: \`WriteGlb\` of that mesh into memory.
- Native \`glb/sakura-15y\` swings between about 20 ms and 75 ms from run to run: each iteration
  allocates about 13 MB of fresh buffers that glibc maps and unmaps, so page faults dominate (with
  \`GLIBC_TUNABLES=glibc.malloc.mmap_threshold=2000000000:glibc.malloc.trim_threshold=2000000000\`
  it took 19 ms). The WASM heap only grows and is reused, so WASM does not pay this cost.
- \`light/grid-2000\`, \`light/reference-2000\`: \`ComputeLightGrid\` and \`ComputeLightReference\` on
  2,000 leaf spheres drawn from \`Pcg32\` (seed 12345) in a 300 × 300 × 300 cm crown box, sky of the
  default parameters (sun at 60°, weight 0.3), opacity 0.5.

## Google Benchmark (native)

\`build/native/bin/niwa_gbench --benchmark_min_time=0.05\`, same workloads (short run: one
iteration of the long ones, so these are rough):

\`\`\`
${gbench || '(not run)'}
\`\`\`

Run \`scripts/bench\` to print the table without touching this file, \`scripts/bench --record\`
to rewrite it.
`;
  writeFileSync(args.record, doc);
}
