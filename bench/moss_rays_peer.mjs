// Peer reference for scripts/bench (issue 29 item 6): three-mesh-bvh (with three.js) on the rays of
// Niwa's photon tracer. Reads a ray file of `niwa moss photons --rays FILE.bin` (geom/ray_dump.h:
// the land's triangles, then each ray's origin, direction, max distance and the triangle and
// distance Niwa's BVH found), builds a MeshBVH over the same triangles (CENTER, the library's
// default, and SAH), times raycastFirst(ray, DoubleSide, 0, max) over every ray (the runner's
// policy: at least 3 repetitions and 0.3 s, the median), and compares each hit with Niwa's: the
// same triangle, else the same distance within 1e-5 m (a tie on a shared edge), else a
// disagreement. One JSON line a strategy, like niwa_bench_runner's, with ns_per_ray and the
// checksum Σ (triangle + 1) over Niwa's hits in the file (niwa_bench_runner's moss/rays-thesis
// prints the same sum when it casts the same rays).
//
// The machine may be loaded: beside the wall-clock median it prints cpu_ns_per_unit, the process's
// CPU time (user + system, process.cpuUsage) over the timed repetitions per ray.
//
// Usage: node [--single-threaded] bench/moss_rays_peer.mjs FILE.bin [--reps N] (N: exactly N timed
// repetitions; scripts/bench passes --single-threaded so the CPU time is one thread's, GC included)
import { readFileSync } from 'node:fs';
import { BufferAttribute, BufferGeometry, DoubleSide, Ray, Vector3 } from 'three';
import { CENTER, MeshBVH, SAH } from 'three-mesh-bvh';

const file = process.argv[2];
const repsAt = process.argv.indexOf('--reps');
const fixedReps = repsAt > 0 ? Number(process.argv[repsAt + 1]) : 0;
if (!file) {
  console.error('usage: node bench/moss_rays_peer.mjs FILE.bin (from niwa moss photons --rays)');
  process.exit(2);
}
const bytes = readFileSync(file);
const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
if (new TextDecoder().decode(new Uint8Array(buffer, 0, 8)) !== 'NIWARAY1') {
  console.error(`${file}: not a Niwa ray file (it must start with NIWARAY1)`);
  process.exit(2);
}
const header = new Uint32Array(buffer, 8, 4);
const [vertices, triangles, rayCount] = header;
const positionsAt = 24, indicesAt = positionsAt + 12 * vertices, raysAt = indicesAt + 12 * triangles;
if (raysAt + 36 * rayCount !== buffer.byteLength) {
  console.error(`${file}: ${buffer.byteLength} bytes; its header declares ${raysAt + 36 * rayCount}`);
  process.exit(2);
}
const positions = new Float32Array(buffer, positionsAt, 3 * vertices);
const indices = new Uint32Array(buffer, indicesAt, 3 * triangles);
const rayF = new Float32Array(buffer, raysAt, 9 * rayCount);
const rayI = new Int32Array(buffer, raysAt, 9 * rayCount);

// The rays as three.js Rays (directions normalised, as Niwa's FirstHit does), made once.
const rays = [], far = [], niwaTri = [], niwaT = [];
let checksum = 0, niwaHits = 0;
for (let i = 0; i < rayCount; ++i) {
  const o = 9 * i;
  const d = new Vector3(rayF[o + 3], rayF[o + 4], rayF[o + 5]).normalize();
  rays.push(new Ray(new Vector3(rayF[o], rayF[o + 1], rayF[o + 2]), d));
  far.push(rayF[o + 6]);
  niwaTri.push(rayI[o + 7]);
  niwaT.push(rayF[o + 8]);
  if (rayI[o + 7] >= 0) {
    checksum += rayI[o + 7] + 1;
    ++niwaHits;
  }
}

const sequential = indices.every((v, k) => v === k);
for (const [name, strategy] of [['CENTER', CENTER], ['SAH', SAH]]) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions.slice(), 3));
  const index = indices.slice();
  geometry.setIndex(new BufferAttribute(index, 1));
  // MeshBVH reorders the index buffer; a Niwa land mesh gives every triangle its own three
  // corners in order (the soil cells), so a face's first corner / 3 is its triangle in the file.
  // Another mesh is built in the library's indirect mode (the index kept; faceIndex is the file's).
  const indirect = !sequential;
  const b0 = performance.now();
  const bvh = new MeshBVH(geometry, { strategy, indirect });
  const buildMs = performance.now() - b0;
  const triangleOf = (face) => (indirect ? face : Math.floor(geometry.index.array[3 * face] / 3));
  const castAll = () => {
    const hits = new Array(rayCount);
    for (let i = 0; i < rayCount; ++i) hits[i] = bvh.raycastFirst(rays[i], DoubleSide, 0, far[i]);
    return hits;
  };
  const hits = castAll();  // warm-up, and the answers compared
  let sameTriangle = 0, sameDistance = 0, differ = 0, bothMiss = 0, worst = 0;
  for (let i = 0; i < rayCount; ++i) {
    const h = hits[i];
    if (!h && niwaTri[i] < 0) {
      ++bothMiss;
    } else if (h && niwaTri[i] >= 0 && triangleOf(h.faceIndex) === niwaTri[i]) {
      ++sameTriangle;
      worst = Math.max(worst, Math.abs(h.distance - niwaT[i]));
    } else if (h && niwaTri[i] >= 0 && Math.abs(h.distance - niwaT[i]) <= 1e-5) {
      ++sameDistance;
    } else {
      ++differ;
    }
  }
  const times = [];
  let total = 0;
  const cpu0 = process.cpuUsage();
  while (fixedReps ? times.length < fixedReps : times.length < 3 || (total < 300 && times.length < 200)) {
    const t0 = performance.now();
    castAll();
    const ms = performance.now() - t0;
    times.push(ms);
    total += ms;
  }
  const cpu = process.cpuUsage(cpu0);
  const cpuNs = ((cpu.user + cpu.system) * 1e3) / (times.length * rayCount);
  times.sort((a, b) => a - b);
  const median = times.length % 2 ? times[(times.length - 1) / 2] : 0.5 * (times[times.length / 2 - 1] + times[times.length / 2]);
  console.log(JSON.stringify({
    workload: `three-mesh-bvh ${name} raycastFirst (moss thesis rays)`,
    ms: median,
    min_ms: times[0],
    reps: times.length,
    unit: 'ray',
    units: rayCount,
    ns_per_unit: (median * 1e6) / rayCount,
    cpu_ns_per_unit: cpuNs,
    build_ms: buildMs,
    indirect,
    triangles,
    niwa_hits: niwaHits,
    same_triangle: sameTriangle,
    same_distance_other_triangle: sameDistance,
    both_miss: bothMiss,
    differ,
    max_distance_diff_m: worst,
    check: checksum,
  }));
}
