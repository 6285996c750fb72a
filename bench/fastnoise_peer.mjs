// Peer reference for scripts/bench (issue 19 item 7): an fBm heightfield from npm fastnoise-lite,
// the noise library a user would pick instead of growing a mountain from contours, at the sizes of
// Niwa's heightfield rows (terrain/heightfield/lobes7-512 and -1024). Prints one JSON line per size
// {"workload", "ms" (median), "min_ms", "reps", "unit": "cell", "units", "ns_per_unit", "check"},
// like niwa_bench_runner.
//
// node bench/fastnoise_peer.mjs [--sizes 512,1024] [--octaves 6]
// The field: OpenSimplex2 fBm (lacunarity 2, gain 0.5), 6 octaves, seed 1337, frequency so the
// lowest octave has about 4 features across the square, written row by row into a Float32Array of
// metres (0..1000 m), as a terrain tool fills its heightmap. Same repetition policy as the C++
// runner: one warm-up, then at least 3 runs and at least 0.3 s (at most 200).
// Does not: compare shapes with Niwa's mountains (a noise field has no contours, peaks on purpose
// or valleys that run downhill); only the cost per cell of a same-size surface.
import FastNoiseLite from 'fastnoise-lite';

const args = { sizes: '512,1024', octaves: '6' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args) || process.argv[i + 1] === undefined) {
    console.error('usage: node bench/fastnoise_peer.mjs [--sizes 512,1024] [--octaves N]');
    process.exit(2);
  }
  args[key] = process.argv[i + 1];
}
const sizes = args.sizes.split(',').map(Number);
const octaves = Number(args.octaves);
if (!sizes.every((s) => Number.isInteger(s) && s >= 2 && s <= 8192) || !Number.isInteger(octaves) || octaves < 1 || octaves > 16) {
  console.error('bench/fastnoise_peer.mjs: --sizes must be integers in [2, 8192], --octaves an integer in [1, 16]');
  process.exit(2);
}

function makeNoise(size) {
  const noise = new FastNoiseLite(1337);
  noise.SetNoiseType(FastNoiseLite.NoiseType.OpenSimplex2);
  noise.SetFractalType(FastNoiseLite.FractalType.FBm);
  noise.SetFractalOctaves(octaves);
  noise.SetFractalLacunarity(2.0);
  noise.SetFractalGain(0.5);
  noise.SetFrequency(4 / size);
  return noise;
}

// One heightfield of size² cells; returns a checksum (the sum of a few cells).
function heightfield(noise, size, out) {
  for (let j = 0; j < size; ++j) {
    const row = j * size;
    for (let i = 0; i < size; ++i) out[row + i] = 500 * (1 + noise.GetNoise(i, j));
  }
  return out[0] + out[(size * size) >> 1] + out[size * size - 1];
}

for (const size of sizes) {
  const noise = makeNoise(size);
  const out = new Float32Array(size * size);
  const check = heightfield(noise, size, out);  // warm-up
  const times = [];
  let total = 0;
  while (times.length < 3 || (total < 300 && times.length < 200)) {
    const t0 = performance.now();
    const c = heightfield(noise, size, out);
    const ms = performance.now() - t0;
    if (c !== check) throw new Error('fastnoise-lite gave two different fields for one seed');
    times.push(ms);
    total += ms;
  }
  times.sort((a, b) => a - b);
  const median = times.length % 2 ? times[times.length >> 1] : 0.5 * (times[times.length / 2 - 1] + times[times.length / 2]);
  const cells = size * size;
  console.log(JSON.stringify({
    workload: `fastnoise-lite fBm heightfield ${size}² (${octaves} octaves)`,
    ms: Number(median.toFixed(4)), min_ms: Number(times[0].toFixed(4)), reps: times.length,
    unit: 'cell', units: cells, ns_per_unit: Number(((median * 1e6) / cells).toFixed(3)), check,
  }));
}
