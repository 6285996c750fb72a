// Terrain outputs across builds: for every built-in seed (improved method), native == WASM byte for
// byte for the .glb, the 16-bit heightmap .png and its .json sidecar, the .geojson and the .svg
// contours; every .glb is gltf-validator clean (0 errors, 0 warnings); `--url` of the stats regrows
// the same .glb; `terrain compare` on the real DEM prints the same JSON in both builds; `terrain
// render` (Fig 17's views) draws the same PNG in both builds from a grown heightmap and the real DEM
// (framed, floored), and refuses bad flags in one line, exit 2, no file.
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { check, finish, native, requireWasm, root, run, spawn, wasm } from '../support/cli_pair.mjs';

requireWasm();
const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;

const dir = mkdtempSync(join(tmpdir(), 'niwa-terrain-out-'));
const seeds = JSON.parse(run(native, ['terrain', 'seeds'])).map((s) => s.name);
for (const seed of seeds) {
  const files = {};
  for (const [build, cmd] of [['n', native], ['w', wasm]]) {
    const f = (ext) => join(dir, `${seed}-${build}.${ext}`);
    const stats = JSON.parse(run(cmd, ['terrain', 'grow', '--builtin', seed, '--method', 'improved', '--seed', '2',
      '--res', '96', '--stats', '--out', f('glb'), '--heightmap', f('png'), '--contours', f('geojson')]));
    run(cmd, ['terrain', 'grow', '--builtin', seed, '--method', 'improved', '--seed', '2', '--contours', f('svg')]);
    files[build] = { stats, f };
  }
  for (const ext of ['glb', 'png', 'json', 'geojson', 'svg']) {
    const a = readFileSync(files.n.f(ext)), b = readFileSync(files.w.f(ext));
    check(`${seed}: .${ext} native == WASM (${a.length} bytes)`, a.length > 100 && a.equals(b));
  }
  const report = await validator.validateBytes(new Uint8Array(readFileSync(files.n.f('glb'))), { maxIssues: 20 });
  check(`${seed}: .glb gltf-validator ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`,
    report.issues.numErrors === 0 && report.issues.numWarnings === 0);
  const again = join(dir, `${seed}-url.glb`);
  run(wasm, ['terrain', 'grow', '--url', files.n.stats.url, '--out', again]);
  check(`${seed}: the WASM CLI's --url '${files.n.stats.url}' regrows the native .glb`,
    readFileSync(again).equals(readFileSync(files.n.f('glb'))));
}

const dem = join(root, 'tests/data/terrain/jacksboro_dem.png');
for (const method of ['simple', 'improved']) {
  const args = ['terrain', 'compare', '--dem', dem, '--builtin', 'jacksboro', '--method', method, '--seed', '3'];
  const a = run(native, args), b = run(wasm, args);
  check(`compare ${method}: native == WASM (mean IoU ${JSON.parse(a).mean_iou.toFixed(3)})`,
    a === b && JSON.parse(a).levels.length > 3);
}

// The second real DEM (topobathy, 2.43 km cells, bathymetry below 0 m) with a contour file: the
// same JSON in both builds, the contour's 46 cells and the DEM's relief inside it (451 m) read back.
{
  const args = ['terrain', 'compare', '--dem', join(root, 'tests/data/terrain/topobathy_dem.png'), '--contour',
    join(root, 'tests/data/terrain/topobathy_1200.json'), '--method', 'improved', '--seed', '1',
    '--set', 'h0=1200', '--set', 'd=600', '--set', 'dh=95.8'];
  const a = run(native, args), b = run(wasm, args);
  const j = JSON.parse(a);
  check(`compare on topobathy 1200 m: native == WASM, ${j.real.cells} cells, real relief ${j.real.relief.toFixed(0)} m, mean IoU ${j.mean_iou.toFixed(3)}`,
    a === b && j.real.cells === 46 && Math.abs(j.real.relief - 451) < 1 && j.levels.length >= 3 && j.mean_iou > 0.1);
}

// terrain render: the last seed's grown heightmap, and the real DEM framed on it and floored.
const grown = join(dir, `${seeds[seeds.length - 1]}-n.png`);
for (const [label, args] of [
  ['grown heightmap', ['--dem', grown, '--width', '200', '--height', '120']],
  ['real DEM, framed and floored', ['--dem', dem, '--width', '160', '--height', '100', '--frame', '8000,17000,13000,23000',
    '--floor', '800', '--exaggeration', '3', '--tint', '800,1072', '--view-from', '150', '--elevation', '50']],
]) {
  const out = (b) => join(dir, `render-${label.length}-${b}.png`);
  const jn = JSON.parse(run(native, ['terrain', 'render', ...args, '--out', out('n')]));
  run(wasm, ['terrain', 'render', ...args, '--out', out('w')]);
  const a = readFileSync(out('n')), w = readFileSync(out('w'));
  check(`render ${label}: native == WASM PNG (${a.length} bytes, ${jn.width} x ${jn.height})`,
    a.length > 1000 && a.equals(w) && a.readUInt32BE(16) === jn.width && a.readUInt32BE(20) === jn.height);
}
for (const [args, text] of [
  [['--elevation', '3'], '--elevation: 3 is out of range'],
  [['--frame', '1,2,3'], "--frame: '1,2,3' must be X_MIN,Y_MIN,X_MAX,Y_MAX (m)"],
  [['--frame', '0,0,10,10'], '--frame: the frame holds no cell of the grid'],
  [['--frame', '-9000,-9000,-8000,-8000'], '--frame: the frame holds no cell of the grid'],
  [['--tint', '5,1'], "--tint: '5,1' must have LOW < HIGH"],
]) {
  const out = join(dir, 'refused.png');
  const r = spawn(native, ['terrain', 'render', '--dem', dem, ...args, '--out', out]);
  check(`render ${args.join(' ')}: exit 2, one line naming the flag, no file`,
    r.status === 2 && r.stderr.trim().split('\n').length === 1 && r.stderr.includes(text) && !existsSync(out), r.stderr.trim());
}
finish();
