// web/mesh/mesh_import.js: Draco primitives decoded in JS (npm draco3d) give the same mesh the native reader decodes
// with libdraco: same stats and query answers natively, and the WASM CLI (which cannot decode Draco) reads the output.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';
import draco3d from 'draco3d';
import { importMesh, parseGlb, dracoPrimitiveCount, dracoHeaderCounts, MAX_MESH_TRIANGLES, MAX_MESH_VERTICES } from '../../web/mesh/mesh_import.js';
import { dracoGlb, encodeDracoMesh } from '../support/draco_encode.mjs';
import { cliArgv } from '../support/cli_pair.mjs';

const root = process.env.NIWA_ROOT;
const native = process.env.NIWA_NATIVE;
const wasm = join(root, 'build/wasm/bin/niwa.js');
const data = join(root, 'tests/data/meshes');
let passed = 0, failed = 0;
const check = (ok, what) => { ok ? passed++ : failed++; console.log(`${ok ? 'PASS' : 'FAIL'} ${what}`); };
const run = (bin, args) => {
  const r = spawnSync(...cliArgv(bin, args), { encoding: 'utf8' });
  if (r.status !== 0) return { error: r.stderr.trim() };
  const o = JSON.parse(r.stdout);
  for (const k of Object.keys(o)) if (k.startsWith('ms_') || k === 'draco_primitives') delete o[k];
  return o;
};
const haveWasm = existsSync(wasm);
check(haveWasm, `WASM CLI at ${wasm}`);
const draco = await draco3d.createDecoderModule({});
const require = createRequire(import.meta.url);
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;
const dir = mkdtempSync(join(tmpdir(), 'niwa-import-'));

for (const file of ['draco.glb', 'rock1.glb']) {
  const input = readFileSync(join(data, file));
  const out = importMesh(input, { draco });
  const { json } = parseGlb(out.bytes);
  check(out.dracoPrimitives === 1 && dracoPrimitiveCount(json) === 0 && !(json.extensionsRequired ?? []).includes('KHR_draco_mesh_compression'),
    `${file}: 1 Draco primitive decoded, extension gone (required now ${JSON.stringify(json.extensionsRequired ?? [])})`);
  // Khronos' validator: no errors in the rewritten file (images are not decoded: webp is not its concern here).
  const report = await validator.validateBytes(new Uint8Array(out.bytes), { maxIssues: 50 });
  const errors = (report.issues.messages ?? []).filter((m) => m.severity === 0);
  check(report.issues.numErrors === 0, `${file}: gltf-validator on the rewritten file: ${report.issues.numErrors} errors ${JSON.stringify(errors.slice(0, 3).map((m) => m.code + ' ' + m.pointer))}`);
  const plain = join(dir, file.replace('.glb', '_plain.glb'));
  writeFileSync(plain, out.bytes);
  const queries = [['stats'], ['closest', '--point', '0.3,0.9,0.2'], ['closest', '--point', '-2,4,1'],
    ['ray', '--origin', '0.4,5,0.3', '--dir', '0,-1,0'], ['ray', '--origin', '6,0.5,0.2', '--dir', '-1,0.05,0']];
  for (const q of queries) {
    const want = JSON.stringify(run(native, ['mesh', q[0], '--mesh', join(data, file), ...q.slice(1)]));
    const got = JSON.stringify(run(native, ['mesh', q[0], '--mesh', plain, ...q.slice(1)]));
    check(want === got && !want.includes('error'), `${file} ${q.join(' ')}: JS-decoded == libdraco-decoded natively: ${got.slice(0, 100)}`);
    if (haveWasm) {
      const w = JSON.stringify(run(wasm, ['mesh', q[0], '--mesh', plain, ...q.slice(1)]));
      check(w === want, `${file} ${q.join(' ')}: WASM on the JS-decoded file == native on the original`);
    }
  }
}
// The hand-made valid test meshes are valid glTF themselves (so the reader tests test real glTF).
for (const file of ['hierarchy.glb', 'draco.glb', 'draco_twin.glb', 'embedded.gltf']) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(join(data, file))), { maxIssues: 50 });
  check(report.issues.numErrors === 0, `${file}: gltf-validator ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`);
}
// A file without Draco comes back byte for byte.
const grass = readFileSync(join(data, 'grass.glb'));
const same = importMesh(grass, { draco });
check(same.dracoPrimitives === 0 && Buffer.compare(Buffer.from(same.bytes), grass) === 0, 'grass.glb (no Draco) is returned unchanged');

// Issue 34: the page's Draco path applies io::PreflightDracoHeader's caps before draco3d sizes anything. The caps are
// the core's (core/io/mesh_reader.h).
const header = readFileSync(join(root, 'core/io/mesh_reader.h'), 'utf8');
const coreTriangles = Number((/kMaxMeshTriangles = ([\d']+);/.exec(header) || [])[1]?.replaceAll("'", ''));
check(coreTriangles === MAX_MESH_TRIANGLES && /kMaxMeshVertices = 3 \* kMaxMeshTriangles;/.test(header) &&
  MAX_MESH_VERTICES === 3 * MAX_MESH_TRIANGLES, `the page's Draco caps are the core's: ${MAX_MESH_TRIANGLES} triangles, ${MAX_MESH_VERTICES} vertices`);
const firstLine = (bin, file) => {
  const r = spawnSync(...cliArgv(bin, ['mesh', 'stats', '--mesh', file]), { encoding: 'utf8' });
  const lines = r.stderr.split('\n').filter((l) => l);
  return { status: r.status, lines };
};
// A header (bitstream 2.2, edgebreaker) declaring 2^28 faces in 53 bytes; with the metadata flag, or as version 2.1,
// the header is not read (its layout differs) and Draco's own checks refuse it, natively and in the page alike.
const hostileDraco = (major, minor, flags) => {
  const draco = Buffer.concat([Buffer.from('DRACO'), Buffer.from([major, minor, 1, 1, flags & 0xff, flags >> 8, 0, 49, 0x80, 0x80, 0x80, 0x80, 0x01]), Buffer.alloc(35)]);
  const file = join(dir, `draco_${major}${minor}_${flags}.glb`);
  writeFileSync(file, dracoGlb(draco, 3));
  return { file, draco };
};
const capped = hostileDraco(2, 2, 0).file;
let pageError = '';
try { importMesh(readFileSync(capped), { draco }); } catch (e) { pageError = e.message; }
const cappedLine = 'mesh 0 primitive 0: the Draco data declares 49 vertices and 268435456 triangles; the limits are 12000000 and 4000000';
check(pageError === cappedLine, `a Draco header over the cap is refused by the page's import before decoding: ${pageError}`);
const nativeCapped = firstLine(native, capped);
check(nativeCapped.status === 2 && nativeCapped.lines.length === 1 && nativeCapped.lines[0].endsWith(cappedLine),
  `... with the native reader's line: ${nativeCapped.lines[0]}`);
for (const [major, minor, flags, what] of [[2, 2, 0x8000, 'metadata'], [2, 1, 0, 'bitstream 2.1']]) {
  const { file, draco: bytes } = hostileDraco(major, minor, flags);
  check(dracoHeaderCounts(bytes) === null, `a Draco header with ${what}: not read (left to Draco)`);
  let e = '';
  try { importMesh(readFileSync(file), { draco }); } catch (x) { e = x.message; }
  const n = firstLine(native, file);
  check(/Draco cannot decode it/.test(e) && n.status === 2 && n.lines.length === 1 && !/the limits are/.test(n.lines[0]),
    `a Draco header with ${what} declaring 2^28 faces: Draco's own refusal in the page (${e}) and natively (${n.lines[0]})`);
}
// Real Draco bitstreams (npm draco3d's encoder): the header's counts as encoded, both methods; a NaN position is
// refused with one line naming the attribute natively (libdraco) and in WASM (draco3d in JS, then the core).
for (const method of ['sequential', 'edgebreaker']) {
  const positions = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0];
  const encoded = await encodeDracoMesh(positions, [0, 1, 2, 2, 1, 3], method);
  const counts = dracoHeaderCounts(encoded);
  check(counts?.points === 4 && counts?.faces === 2, `${method} Draco header read: ${JSON.stringify(counts)} (4 points, 2 faces encoded)`);
  const nan = join(dir, `nan_${method}.glb`);
  writeFileSync(nan, dracoGlb(await encodeDracoMesh(positions.map((v, i) => (i === 7 ? NaN : v)), [0, 1, 2, 2, 1, 3], method), 4));
  const n = firstLine(native, nan);
  check(n.status === 2 && n.lines.length === 1 && /: mesh 0 primitive 0 POSITION \d is NaN or infinite$/.test(n.lines[0]),
    `${method} Draco with a NaN position, native: ${n.lines[0]}`);
  if (haveWasm) {
    const plainNan = join(dir, `nan_${method}_plain.glb`);
    writeFileSync(plainNan, importMesh(readFileSync(nan), { draco }).bytes);
    const w = firstLine(wasm, plainNan);
    check(w.status === 2 && w.lines.length === 1 && /: mesh 0 primitive 0 POSITION \d is NaN or infinite$/.test(w.lines[0]),
      `${method} Draco with a NaN position, WASM (decoded by draco3d in JS): ${w.lines[0]}`);
  }
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
