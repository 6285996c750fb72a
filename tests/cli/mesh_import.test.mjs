// web/mesh/mesh_import.js: Draco primitives decoded in JS (npm draco3d) give the same mesh the native reader decodes
// with libdraco: same stats and query answers natively, and the WASM CLI (which cannot decode Draco) reads the output.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';
import draco3d from 'draco3d';
import { importMesh, parseGlb, dracoPrimitiveCount } from '../../web/mesh/mesh_import.js';
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
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
