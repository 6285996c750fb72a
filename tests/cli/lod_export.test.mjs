// Issue 17 item 4 on the CLI: `niwa tree grow --max-triangles N --out x.glb` stays within N
// triangles (counted from the .glb's own accessors, parsed here), `--lod` writes sibling nodes
// tree_LOD0..2 with LOD1 <= 25 % and LOD2 <= 5 % of LOD0 (or, with --lod-layout msft, LOD0 naming
// the others through MSFT_lod); issue 32 item 2: no primitive of any of them is LINES (mode 1:
// engines draw those as one-pixel threads or not at all), the twigs are triangles the budget
// counts, and every kind of primitive (bark, leaves, flowers, cards, twigs: vertices and
// triangles) shrinks from LOD0 to LOD1 to LOD2; all validate with Khronos'
// gltf-validator (0 errors), the WASM CLI (when built) writes the same bytes, and bad input is one
// line naming the flag, exit 2, no file. Run: NIWA_NATIVE=... NIWA_ROOT=... node tests/cli/lod_export.test.mjs
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, finish, native, root, run, spawn, wasm } from '../support/cli_pair.mjs';

if (!native || !root) {
  console.log('FAIL set NIWA_NATIVE (native niwa binary) and NIWA_ROOT (repo root)');
  process.exit(2);
}
const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;

// The JSON chunk and per-mesh triangle counts of a .glb (TRIANGLES primitives: mode 4 or absent).
function parseGlb(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (view.getUint32(0, true) !== 0x46546c67) throw new Error('not a .glb');
  const length = view.getUint32(12, true);
  const gltf = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + length)));
  const triangles = (mesh) => mesh.primitives.reduce((sum, p) =>
    sum + ((p.mode ?? 4) === 4 ? gltf.accessors[p.indices].count / 3 : 0), 0);
  const lines = (mesh) => mesh.primitives.filter((p) => p.mode === 1).length;
  // Every primitive of the file that is not TRIANGLES (any mesh, in the scene or not).
  const nonTriangles = gltf.meshes.flatMap((m) => m.primitives).filter((p) => (p.mode ?? 4) !== 4).length;
  // {kind: {vertices, triangles}} of one mesh, the kind being the material's name without a
  // level suffix (cards_0 -> cards).
  const kinds = (mesh) => {
    const out = {};
    for (const p of mesh.primitives) {
      const kind = gltf.materials[p.material].name.replace(/_\d+$/, '');
      const k = (out[kind] ??= { vertices: 0, triangles: 0 });
      k.vertices += gltf.accessors[p.attributes.POSITION].count;
      k.triangles += gltf.accessors[p.indices].count / 3;
    }
    return out;
  };
  return { gltf, triangles, lines, nonTriangles, kinds };
}

// The kinds (and counts) of `lower` that exceed `upper`'s: '' when every kind shrinks or stays.
function grown(upper, lower, except = []) {
  const out = [];
  for (const [kind, k] of Object.entries(lower)) {
    if (except.includes(kind)) continue;
    const u = upper[kind] ?? { vertices: 0, triangles: 0 };
    if (k.vertices > u.vertices || k.triangles > u.triangles) {
      out.push(`${kind} ${k.vertices} v/${k.triangles} t > ${u.vertices}/${u.triangles}`);
    }
  }
  return out.join('; ');
}

const dir = mkdtempSync(join(tmpdir(), 'niwa-lod-'));
const tree = ['tree', 'grow', '--preset', 'sakura', '--years', '15'];
try {
  // The full tree, for scale.
  const full = join(dir, 'full.glb');
  run(native, [...tree, '--out', full]);
  const fullGlb = parseGlb(readFileSync(full));
  const fullTriangles = fullGlb.triangles(fullGlb.gltf.meshes[0]);
  check(`full 15-year sakura has ${fullTriangles} triangles (> 100 k: the budget has work)`, fullTriangles > 100000);

  for (const budget of [20000, 5000, 500]) {
    const out = join(dir, `budget-${budget}.glb`);
    run(native, [...tree, '--max-triangles', String(budget), '--out', out]);
    const bytes = readFileSync(out);
    const { gltf, triangles, lines } = parseGlb(bytes);
    const count = triangles(gltf.meshes[0]);
    check(`--max-triangles ${budget}: one node 'tree'`, gltf.nodes.length === 1 && gltf.nodes[0].name === 'tree');
    check(`--max-triangles ${budget}: ${count} triangles (within, and at least half used)`, count <= budget && count >= budget / 2);
    const k = parseGlb(bytes).kinds(gltf.meshes[0]);
    check(`--max-triangles ${budget}: no LINES primitive; twigs as ${k.twigs?.triangles} triangles (counted in the ${count})`,
      lines(gltf.meshes[0]) === 0 && parseGlb(bytes).nonTriangles === 0 && k.twigs?.triangles > 0);
    const cards = gltf.materials.filter((m) => m.name.startsWith('cards'));
    check(`--max-triangles ${budget}: card material with the atlas, alpha mask, double-sided`,
      cards.length === 1 && cards[0].alphaMode === 'MASK' && cards[0].doubleSided === true);
    const report = await validator.validateBytes(new Uint8Array(bytes), { maxIssues: 50 });
    check(`--max-triangles ${budget}: validator 0 errors`, report.issues.numErrors === 0,
      report.issues.messages.filter((m) => m.severity === 0).map((m) => m.message).slice(0, 3).join('; '));
  }

  const lodOut = join(dir, 'lod.glb');
  run(native, [...tree, '--max-triangles', '20000', '--lod', '--out', lodOut]);
  const lodBytes = readFileSync(lodOut);
  const lod = parseGlb(lodBytes);
  const names = lod.gltf.scenes[0].nodes.map((n) => lod.gltf.nodes[n].name);
  check(`--lod: scene nodes ${names.join(', ')}`,
    JSON.stringify(names) === JSON.stringify(['tree_LOD0', 'tree_LOD1', 'tree_LOD2']));
  const counts = lod.gltf.scenes[0].nodes.map((n) => lod.triangles(lod.gltf.meshes[lod.gltf.nodes[n].mesh]));
  check(`--lod LOD0 ${counts[0]} triangles <= 20000`, counts[0] <= 20000);
  check(`--lod LOD1 ${counts[1]} <= 25 % of ${counts[0]}`, counts[1] * 100 <= counts[0] * 25);
  check(`--lod LOD2 ${counts[2]} <= 5 % of ${counts[0]}`, counts[2] * 100 <= counts[0] * 5 && counts[2] > 0);
  check('--lod: no primitive is LINES (or anything but TRIANGLES)', lod.nonTriangles === 0);
  const lodKinds = lod.gltf.scenes[0].nodes.map((n) => lod.kinds(lod.gltf.meshes[lod.gltf.nodes[n].mesh]));
  console.log(`  kinds: ${lodKinds.map((k, l) => `LOD${l} ${Object.entries(k).map(([n, c]) => `${n} ${c.vertices} v/${c.triangles} t`).join(', ')}`).join(' | ')}`);
  check(`--lod: LOD1 holds no more of any kind than LOD0 ${grown(lodKinds[0], lodKinds[1])}`, grown(lodKinds[0], lodKinds[1]) === '');
  check(`--lod: LOD2 holds no more of any kind than LOD1 ${grown(lodKinds[1], lodKinds[2])}`, grown(lodKinds[1], lodKinds[2]) === '');
  check('--lod: every level has twigs as triangles (the thinnest wood stays drawn)', lodKinds.every((k) => k.twigs?.triangles > 0));
  const lodReport = await validator.validateBytes(new Uint8Array(lodBytes), { maxIssues: 50 });
  check('--lod: validator 0 errors', lodReport.issues.numErrors === 0,
    lodReport.issues.messages.filter((m) => m.severity === 0).map((m) => m.message).slice(0, 3).join('; '));

  // --lod-layout msft: LOD0 alone in the scene, MSFT_lod naming the other two (the same meshes).
  const msftOut = join(dir, 'lod-msft.glb');
  run(native, [...tree, '--max-triangles', '20000', '--lod', '--lod-layout', 'msft', '--out', msftOut]);
  const msftBytes = readFileSync(msftOut);
  const msft = parseGlb(msftBytes);
  const root0 = msft.gltf.nodes[msft.gltf.scenes[0].nodes[0]];
  const ids = root0.extensions?.MSFT_lod?.ids ?? [];
  const msftCounts = [root0, ...ids.map((i) => msft.gltf.nodes[i])].map((n) => msft.triangles(msft.gltf.meshes[n.mesh]));
  check(`--lod-layout msft: scene holds tree_LOD0 only, MSFT_lod ids ${JSON.stringify(ids)}, used not required`,
    msft.gltf.scenes[0].nodes.length === 1 && root0.name === 'tree_LOD0' && JSON.stringify(ids) === '[1,2]' &&
    msft.gltf.extensionsUsed?.includes('MSFT_lod') && !msft.gltf.extensionsRequired);
  check(`--lod-layout msft: the same levels as the siblings layout (${msftCounts.join(', ')} triangles)`,
    JSON.stringify(msftCounts) === JSON.stringify(counts));
  const cover = root0.extras?.MSFT_screencoverage ?? [];
  check(`--lod-layout msft: MSFT_screencoverage ${JSON.stringify(cover)} (level n from its triangle share)`,
    cover.length === 3 && cover[0] > cover[1] && cover[1] > cover[2] && cover[2] > 0 &&
    Math.abs(cover[0] - counts[1] / counts[0]) < 1e-4);
  const msftReport = await validator.validateBytes(new Uint8Array(msftBytes), { maxIssues: 50 });
  // Beyond the siblings layout's warnings: only infos that the validator does not know MSFT_lod
  // and that the lower levels are not in the scene (which is MSFT_lod's point).
  const infos = msftReport.issues.messages.filter((m) => m.severity === 2).map((m) => `${m.code} ${m.pointer}`).sort();
  check(`--lod-layout msft: validator 0 errors, ${msftReport.issues.numWarnings} warnings as the siblings layout, infos ${infos.join(', ')}`,
    msftReport.issues.numErrors === 0 && msftReport.issues.numWarnings === lodReport.issues.numWarnings &&
    JSON.stringify(infos) === JSON.stringify(['UNSUPPORTED_EXTENSION /extensionsUsed/0', 'UNUSED_OBJECT /nodes/1', 'UNUSED_OBJECT /nodes/2']));

  const lodFull = join(dir, 'lod-full.glb');
  run(native, [...tree, '--lod', '--out', lodFull]);
  const lf = parseGlb(readFileSync(lodFull));
  const lf0 = lf.triangles(lf.gltf.meshes[lf.gltf.nodes[lf.gltf.scenes[0].nodes[0]].mesh]);
  check(`--lod alone: LOD0 is the full mesh (${lf0} triangles)`, lf0 === fullTriangles);
  // Below the full mesh, cards (and twigs) replace the leaves and thin tubes: only they may appear
  // at LOD1; from LOD1 to LOD2 nothing grows.
  const lfKinds = lf.gltf.scenes[0].nodes.map((n) => lf.kinds(lf.gltf.meshes[lf.gltf.nodes[n].mesh]));
  check(`--lod alone: no LINES; LOD1 grows only cards/twigs ${grown(lfKinds[0], lfKinds[1], ['cards', 'twigs'])}, LOD2 nothing ${grown(lfKinds[1], lfKinds[2])}`,
    lf.nonTriangles === 0 && grown(lfKinds[0], lfKinds[1], ['cards', 'twigs']) === '' && grown(lfKinds[1], lfKinds[2]) === '');

  // Bad input: one line naming the flag, exit 2, nothing written.
  const bad = [
    [['--max-triangles', '3', '--out', join(dir, 'a.glb')], '--max-triangles: 3 is out of range'],
    [['--max-triangles', '2x', '--out', join(dir, 'b.glb')], '--max-triangles'],
    [['--max-triangles', '100', '--out', join(dir, 'c.json')], '--max-triangles: only applies with --out FILE.glb'],
    [['--lod', '--out', join(dir, 'd.svg')], '--lod: only applies with --out FILE.glb'],
    [['--lod-layout', 'msft', '--out', join(dir, 'e.glb')], '--lod-layout: only applies with --lod'],
    [['--lod', '--lod-layout', 'unity', '--out', join(dir, 'f.glb')], "--lod-layout: 'unity' must be siblings or msft"],
  ];
  for (const [args, wanted] of bad) {
    const r = spawn(native, [...tree, ...args]);
    const out = args[args.indexOf('--out') + 1];
    check(`${args.slice(0, 2).join(' ')}: exit ${r.status}, '${r.stderr.trim()}'`,
      r.status === 2 && r.stderr.trim().split('\n').length === 1 && r.stderr.includes(wanted) && !existsSync(out));
  }

  if (existsSync(wasm)) {
    const wasmOut = join(dir, 'wasm-lod.glb');
    run(wasm, [...tree, '--max-triangles', '20000', '--lod', '--out', wasmOut]);
    check('WASM CLI: --lod .glb byte-identical to native', Buffer.compare(readFileSync(wasmOut), lodBytes) === 0);
    const wasmMsft = join(dir, 'wasm-lod-msft.glb');
    run(wasm, [...tree, '--max-triangles', '20000', '--lod', '--lod-layout', 'msft', '--out', wasmMsft]);
    check('WASM CLI: --lod-layout msft .glb byte-identical to native', Buffer.compare(readFileSync(wasmMsft), msftBytes) === 0);
  } else {
    console.log(`SKIP WASM CLI not built at ${wasm}`);
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
