// Ivy CLI outputs added with the page, native against WASM: --tree-preset (stats and .json equal),
// .svg byte for byte, the share link's scene= and at= (the page's hash) equal to the flags, and
// --with-support's .glb validator-clean with the support node; hostile values of the new flags are
// one line naming the flag, exit 2, no file left behind.
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { buildName, check, finish, native, requireWasm, root, run, spawn, wasm, withoutMs } from '../support/cli_pair.mjs';

requireWasm();
const dir = mkdtempSync(join(tmpdir(), 'niwa-ivy-out-'));

// A tree support: native == WASM.
const tree = ['ivy', 'grow', '--tree-preset', 'sakura', '--tree-years', '6', '--stats'];
const ta = JSON.parse(run(native, [...tree, '--out', join(dir, 'tree-n.json')]));
const tb = JSON.parse(run(wasm, [...tree, '--out', join(dir, 'tree-w.json')]));
check(`--tree-preset sakura --tree-years 6: --stats native == WASM (${ta.tri_count} bark triangles, ${ta.internodes} internodes, rise ${ta.rise.toFixed(3)} m)`,
  JSON.stringify(withoutMs(ta)) === JSON.stringify(withoutMs(tb)) && ta.internodes > 10);
check('--tree-preset .json identical', readFileSync(join(dir, 'tree-n.json'), 'utf8') === readFileSync(join(dir, 'tree-w.json'), 'utf8'));

// The page's tree scene (--url scene=tree&tree=..&tree_years=..): native == WASM, and the same ivy
// as --tree-preset (the page's link regrows it on either build).
const byUrl = ['ivy', 'grow', '--url', 'preset=metric&seed=1&steps=50&scene=tree&tree=sakura&tree_years=6', '--stats'];
const ua = JSON.parse(run(native, byUrl)), ub = JSON.parse(run(wasm, byUrl));
check(`--url ..scene=tree&tree=sakura&tree_years=6: native == WASM == --tree-preset (${ua.internodes} internodes)`,
  JSON.stringify(withoutMs(ua)) === JSON.stringify(withoutMs(ub)) && JSON.stringify(withoutMs(ua)) === JSON.stringify(withoutMs(ta)));

// .svg byte for byte, for a small and a large (silhouette) support.
for (const args of [['--scene', 'overhang', '--seed', '2'], ['--tree-preset', 'pine', '--tree-years', '5', '--svg-leaves', '0']]) {
  run(native, ['ivy', 'grow', ...args, '--out', join(dir, 'n.svg')]);
  run(wasm, ['ivy', 'grow', ...args, '--out', join(dir, 'w.svg')]);
  const a = readFileSync(join(dir, 'n.svg'), 'utf8'), b = readFileSync(join(dir, 'w.svg'), 'utf8');
  check(`${args.join(' ')}: .svg native == WASM (${a.length} bytes, ${(a.match(/<line /g) || []).length} lines)`, a.startsWith('<svg ') && a === b);
}

// The page's hash (scene=, at=) grows what the flags grow, in both builds.
for (const cmd of [native, wasm]) {
  const flags = withoutMs(JSON.parse(run(cmd, ['ivy', 'grow', '--scene', 'pillar', '--seed-point', '0,10,210', '--seed-point', '150,10,150', '--steps', '40', '--stats'])));
  const url = withoutMs(JSON.parse(run(cmd, ['ivy', 'grow', '--url', 'steps=40&scene=pillar&at=0,10,210;150,10,150', '--stats'])));
  check(`${buildName(cmd)}: --url scene=pillar&at=.. == --scene pillar --seed-point ..`, JSON.stringify(flags) === JSON.stringify(url));
}

// --with-support: validator-clean, with the support node; without it, no support node.
const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;
const nodesOf = (glb) => {
  const length = new DataView(glb.buffer, glb.byteOffset).getUint32(12, true);
  return JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + length))).nodes.map((n) => n.name);
};
for (const withSupport of [true, false]) {
  const file = join(dir, `s${withSupport}.glb`);
  run(wasm, ['ivy', 'grow', '--scene', 'stairs', '--out', file, ...(withSupport ? ['--with-support'] : [])]);
  const glb = new Uint8Array(readFileSync(file));
  const report = await validator.validateBytes(glb);
  const names = nodesOf(glb);
  check(`stairs .glb ${withSupport ? 'with' : 'without'} --with-support: ${report.issues.numErrors} validator errors, nodes ${names.join(', ')}`,
    report.issues.numErrors === 0 && names.includes('support') === withSupport);
}

// A mesh without --seed-point grows from the page's default seed "front" (issue 31 item 4: the page
// and the CLI grow the same ivy on a dropped mesh), native == WASM, and `--seed-point front` names it.
const rock = join(root, 'tests/data/meshes/bunny.obj');
const fa = JSON.parse(run(native, ['ivy', 'grow', '--mesh', rock, '--stats']));
const fb = JSON.parse(run(wasm, ['ivy', 'grow', '--mesh', rock, '--stats']));
const named = JSON.parse(run(native, ['ivy', 'grow', '--mesh', rock, '--seed-point', 'front', '--stats']));
const elsewhere = JSON.parse(run(native, ['ivy', 'grow', '--mesh', rock, '--seed-point', 'front', '--seed-point', 'front', '--stats']));
check(`--mesh bunny.obj, no --seed-point: grows from "front" (${fa.internodes} internodes), native == WASM == --seed-point front`,
  fa.internodes > 10 && JSON.stringify(withoutMs(fa)) === JSON.stringify(withoutMs(fb)) &&
  JSON.stringify(withoutMs(fa)) === JSON.stringify(withoutMs(named)) && elsewhere.internodes > fa.internodes);
for (const cmd of [native, wasm]) {
  const r = spawn(cmd, ['ivy', 'grow', '--mesh', rock, '--accel', 'linear', '--stats']);
  const lines = r.stderr.trim().split('\n');
  check(`${buildName(cmd)} --mesh with --accel linear (no front seed without a BVH) and no --seed-point: exit ${r.status}, "${lines[0]}"`,
    r.status === 2 && lines.length === 1 && lines[0].startsWith('niwa: error: --seed-point'));
}

// Hostile values of the new flags and hash keys.
const hostile = [
  [['--tree-preset', 'oak'], '--tree-preset'], [['--tree-preset', 'sakura', '--tree-years', '101'], '--tree-years'],
  [['--tree-preset', 'sakura', '--tree-years', 'x'], '--tree-years'], [['--svg-leaves', '2'], '--svg-leaves'],
  [['--url', 'at=1,2,3,4'], '--url'], [['--url', 'scene=%3Cb%3E'], '--url'], [['--out', join(dir, 'x.png')], '--out'],
];
for (const [args, field] of hostile) {
  for (const cmd of [native, wasm]) {
    const out = join(dir, 'bad.svg');
    const r = spawn(cmd, ['ivy', 'grow', ...args, ...(args.includes('--out') ? [] : ['--out', out])]);
    const lines = r.stderr.trim().split('\n');
    check(`${buildName(cmd)} ${args.join(' ')}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${field}`) && !existsSync(out) && !existsSync(join(dir, 'x.png')));
  }
}
finish();
