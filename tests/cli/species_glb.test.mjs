// The species' forms measured on the exported .glb itself (issue 32 item 3: "pine reads as a conifer
// ... and weeping droops, measured on the exported .glb"): `niwa tree grow --preset P --out P.glb`,
// the file's POSITION accessors read back (with the node's transform), by the same measures
// tests/tree/species_test.cpp takes on the TreeMesh the writer is given. The pine: conical (the
// widest tenth of the height in its lower four, the ninth tenth under 0.6 of it) and its needle
// fascicles covering its tiers (the leaf primitive's quads reach at least 6 cm from their base: the
// row leaf_card). The weeping cherry (20 years): its crown carried high on the standard (the widest
// tenth in the upper half, no leaf below 30 cm: the trim at 40 cm less a 9 cm card hanging from
// it) and hanging (leaves reach below half the height
// although the first limbs start near 3 m).
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { check, finish, native, run } from '../support/cli_pair.mjs';

const dir = mkdtempSync(join(tmpdir(), 'niwa-species-glb-'));

// Every primitive's positions (metres, after the node's translation and scale; the tree's node has
// no rotation) and whether its material is the leaves' (alpha MASK).
function readGlb(file) {
  const bytes = readFileSync(file);
  const jsonLength = bytes.readUInt32LE(12);
  const json = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  const binStart = 20 + jsonLength + 8;
  const parts = [];
  for (const node of json.nodes) {
    if (node.mesh === undefined) continue;
    if (node.rotation || node.matrix) throw new Error(`node ${node.name} is rotated: not handled here`);
    const t = node.translation || [0, 0, 0], s = node.scale || [1, 1, 1];
    for (const prim of json.meshes[node.mesh].primitives) {
      const accessor = json.accessors[prim.attributes.POSITION];
      const view = json.bufferViews[accessor.bufferView];
      const stride = view.byteStride || 12;
      const base = binStart + (view.byteOffset || 0) + (accessor.byteOffset || 0);
      const points = new Float64Array(3 * accessor.count);
      for (let i = 0; i < accessor.count; ++i)
        for (let k = 0; k < 3; ++k) points[3 * i + k] = bytes.readFloatLE(base + i * stride + 4 * k) * s[k] + t[k];
      const material = json.materials[prim.material] || {};
      parts.push({ points, leaves: material.alphaMode === 'MASK' });
    }
  }
  return parts;
}

// Height, the width (larger horizontal extent) of each tenth of the height, the lowest leaf, and
// each leaf quad's reach from its first corner (metres).
function form(parts) {
  let lo = Infinity, hi = -Infinity;
  for (const { points } of parts) for (let i = 1; i < points.length; i += 3) { lo = Math.min(lo, points[i]); hi = Math.max(hi, points[i]); }
  const height = hi - lo;
  const bands = Array.from({ length: 10 }, () => ({ x0: Infinity, x1: -Infinity, z0: Infinity, z1: -Infinity }));
  let lowestLeaf = Infinity;
  const reach = [];
  for (const { points, leaves } of parts) {
    for (let i = 0; i < points.length; i += 3) {
      const b = bands[Math.min(9, Math.max(0, Math.floor(((points[i + 1] - lo) / height) * 10)))];
      b.x0 = Math.min(b.x0, points[i]); b.x1 = Math.max(b.x1, points[i]);
      b.z0 = Math.min(b.z0, points[i + 2]); b.z1 = Math.max(b.z1, points[i + 2]);
      if (leaves) lowestLeaf = Math.min(lowestLeaf, points[i + 1] - lo);
    }
    if (!leaves) continue;
    // A leaf is a double-sided quad, 8 vertices: its reach is the farthest of its corners from the first.
    for (let q = 0; q + 24 <= points.length; q += 24) {
      let far = 0;
      for (let k = 1; k < 4; ++k) far = Math.max(far, Math.hypot(points[q + 3 * k] - points[q], points[q + 3 * k + 1] - points[q + 1], points[q + 3 * k + 2] - points[q + 2]));
      reach.push(far);
    }
  }
  const widths = bands.map((b) => (b.x1 >= b.x0 ? Math.max(b.x1 - b.x0, b.z1 - b.z0) : 0));
  let widest = 0;
  widths.forEach((w, i) => { if (w > widths[widest]) widest = i; });
  reach.sort((a, b) => a - b);
  return { height, widths, widest, lowestLeaf, leafQuads: reach.length, reachMedian: reach.length ? reach[reach.length >> 1] : 0 };
}

const fmt = (xs) => xs.map((x) => x.toFixed(2)).join(', ');

const pineFile = join(dir, 'pine.glb');
run(native, ['tree', 'grow', '--preset', 'pine', '--seed', '1', '--out', pineFile]);
const pine = form(readGlb(pineFile));
check(`pine .glb: conical, widest in its lower four tenths and the ninth under 0.6 of it (widths by tenth ${fmt(pine.widths)} m)`,
  pine.widest <= 3 && pine.widths[8] < 0.6 * pine.widths[pine.widest]);
check(`pine .glb: needle fascicles drawn at the needles' length, not the 3 cm leaf sphere (${pine.leafQuads} leaf quads, median reach ${(100 * pine.reachMedian).toFixed(1)} cm)`,
  pine.leafQuads > 1000 && pine.reachMedian >= 0.06);

const weepingFile = join(dir, 'weeping.glb');
run(native, ['tree', 'grow', '--preset', 'weeping', '--seed', '1', '--years', '20', '--out', weepingFile]);
const weeping = form(readGlb(weepingFile));
check(`weeping .glb, 20 y: the crown carried high (widest tenth ${weeping.widest + 1} of 10, in the upper half) with no leaf below 30 cm (lowest ${weeping.lowestLeaf.toFixed(2)} m)`,
  weeping.widest >= 5 && weeping.lowestLeaf >= 0.3);
check(`weeping .glb, 20 y: its shoots hang, leaves below half the height of the ${weeping.height.toFixed(2)} m tree (lowest ${weeping.lowestLeaf.toFixed(2)} m)`,
  weeping.lowestLeaf < 0.5 * weeping.height);

rmSync(dir, { recursive: true, force: true });
finish();
