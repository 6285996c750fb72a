// Browser test of the garden's .glb (issue 33 item 5): node tests/browser/garden_glb.test.mjs (exit 0
// = pass). A small garden (24 m, 4 years, trees by hand and by the rules, some sharing a mesh) is
// grown natively twice, its copies as EXT_mesh_gpu_instancing and as plain nodes sharing one mesh;
// both are gltf-validator clean; three.js' GLTFLoader draws both from one camera and they cover the
// same pixels (a loader that ignores the extension would lose every instanced tree: checked by
// drawing the instanced file with the extension's nodes stripped of their instances, which
// covers less). Screenshot: build/artifacts/garden-glb.png (instanced | plain | stripped).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { ARTIFACTS, NATIVE, ROOT, check, runBrowserTest } from './harness.mjs';
import { openThreePage, saveSideBySide } from './three_page.mjs';

const require = createRequire(path.join(ROOT, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;

fs.mkdirSync(ARTIFACTS, { recursive: true });
const garden = {
  params: { size: 24, years: 4, density: 0.02, spacing: 3, shade: 0, variants: 2, ground_res: 48, relief: 2 },
  ground: { kind: 'terrain' },
  objects: [{ kind: 'wall', pos: [0, -8], rot: 0, scale: 1 }, { kind: 'rock', pos: [5, 3], rot: 30, scale: 1 }],
  plants: [{ species: 'keyaki', seed: 1, age: 2, pos: [-4, 2], rot: 0 }],
  mix: { keyaki: 1, sakura: 1 },
};
const file = path.join(ARTIFACTS, 'garden-glb.json');
fs.writeFileSync(file, JSON.stringify(garden));
const stats = {};
for (const instancing of [1, 0]) {
  const out = path.join(ARTIFACTS, `garden-glb-${instancing ? 'instanced' : 'plain'}.glb`);
  stats[instancing] = JSON.parse(execFileSync(NATIVE, ['garden', 'grow', '--garden', file, '--set', `instancing=${instancing}`,
    '--out', out, '--stats'], { encoding: 'utf8' }));
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(out)));
  check(`instancing=${instancing}: gltf-validator has no errors or warnings`, report.issues.numErrors === 0 && report.issues.numWarnings === 0,
    JSON.stringify(report.issues.messages.filter((m) => m.severity <= 1).slice(0, 3)));
}
const s = stats[1];
check('the garden has more trees than distinct meshes (copies shared)', s.trees.count > s.trees.distinct && s.trees.distinct >= 2,
  JSON.stringify(s.trees));

// The instanced file with every node's EXT_mesh_gpu_instancing dropped: what a loader that ignores the
// extension would draw (one tree per distinct mesh, at its first tree's place: the node's own TRS).
const glb = fs.readFileSync(path.join(ARTIFACTS, 'garden-glb-instanced.glb'));
const jsonLength = glb.readUInt32LE(12);
const doc = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
const instancedNodes = doc.nodes.filter((n) => n.extensions?.EXT_mesh_gpu_instancing).length;
check('the instanced file has one instancing node per distinct tree', instancedNodes === s.trees.distinct, `${instancedNodes} nodes`);
for (const n of doc.nodes) delete n.extensions;
doc.extensionsUsed = (doc.extensionsUsed || []).filter((e) => e !== 'EXT_mesh_gpu_instancing');
if (!doc.extensionsUsed.length) delete doc.extensionsUsed;
let json = Buffer.from(JSON.stringify(doc), 'utf8');
json = Buffer.concat([json, Buffer.alloc((4 - (json.length % 4)) % 4, 0x20)]);
const bin = glb.subarray(20 + jsonLength);
const header = Buffer.alloc(20);
header.writeUInt32LE(0x46546c67, 0); header.writeUInt32LE(2, 4); header.writeUInt32LE(20 + json.length + bin.length, 8);
header.writeUInt32LE(json.length, 12); header.writeUInt32LE(0x4e4f534a, 16);
fs.writeFileSync(path.join(ARTIFACTS, 'garden-glb-stripped.glb'), Buffer.concat([header, json, bin]));

await runBrowserTest(async (server, browser) => {
  const three = await openThreePage(browser, ARTIFACTS);
  const shots = await three.evaluate(() => window.renderGlbs(['garden-glb-instanced.glb', 'garden-glb-plain.glb', 'garden-glb-stripped.glb']));
  const cover = shots.map((r) => r.mask.reduce((a, b) => a + b, 0));
  // Pixels that differ between the instanced and the plain drawing (the same camera).
  let differ = 0;
  for (let i = 0; i < shots[0].mask.length; ++i) differ += shots[0].mask[i] !== shots[1].mask[i] ? 1 : 0;
  check('three.js draws the instanced and the plain file alike (covered pixels within 1 %)', differ <= 0.01 * shots[0].mask.length,
    `instanced ${cover[0]}, plain ${cover[1]}, differing ${differ}`);
  const trees = (k) => shots[k].mask.length;  // eslint-disable-line no-unused-vars
  void trees;
  await saveSideBySide(three, shots.map((r) => r.png), path.join(ARTIFACTS, 'garden-glb.png'));
  check('dropping the extension loses trees (the plain nodes are what such a loader needs)', cover[2] < cover[1],
    `stripped ${cover[2]} vs plain ${cover[1]}`);
});
