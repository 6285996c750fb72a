// Peer reference for scripts/bench: times @dgreenheck/ez-tree's "Oak Large" generate() in node.
// Prints one JSON line {"workload": ..., "ms": median, "reps": n} like niwa_bench_runner.
// ez-tree loads its textures through three's ImageLoader at import time, which needs a DOM; a stub
// `document` whose images never load is enough, since generate() only builds geometry.

const noop = () => {};
globalThis.document = {
  createElementNS: () => ({
    style: {},
    addEventListener: noop,
    removeEventListener: noop,
    setAttribute: noop,
  }),
  createElement: () => ({style: {}, addEventListener: noop, removeEventListener: noop}),
};

const preset = process.argv[2] || 'Oak Large';
const {Tree} = await import('@dgreenheck/ez-tree');

const tree = new Tree();
tree.loadPreset(preset);  // also generates once (warm-up)
const times = [];
let total = 0;
// Same policy as the C++ runner: at least 3 repetitions and at least 0.3 s, at most 200.
while (times.length < 3 || (total < 300 && times.length < 200)) {
  const t0 = performance.now();
  tree.generate();
  const ms = performance.now() - t0;
  times.push(ms);
  total += ms;
}
times.sort((a, b) => a - b);
const median = times[Math.floor(times.length / 2)];
console.log(JSON.stringify({
  workload: `ez-tree ${preset} generate()`,
  ms: median,
  reps: times.length,
  vertices: tree.vertexCount,
  triangles: tree.triangleCount,
}));
