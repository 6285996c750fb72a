// Browser test of the tree page's game-ready downloads (issue 17 item 4, web/tree/export_panel.js):
// the triangle budget field refuses bad input beside the field, "Download budget .glb" stays within
// the budget, "Download LOD .glb" holds tree_LOD0..2 within 25 % / 5 % and is byte-identical to
// `niwa tree grow ... --max-triangles N --lod --out x.glb` (same tree, WASM against native),
// "Download sway .glb" is a skinned, animated .glb; every download passes gltf-validator.
// Run: NIWA_NATIVE=$PWD/build/native/bin/niwa node tests/browser/export_panel.test.mjs
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import validator from 'gltf-validator';
import { ARTIFACTS, NATIVE, TIMEOUT, check, newContext, runBrowserTest, waitReady, watchPage } from './harness.mjs';

const BUDGET = 5000;
const TREE = ['--preset', 'sakura', '--years', '10', '--seed', '1'];

function parseGlb(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const length = view.getUint32(12, true);
  const gltf = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + length)));
  const triangles = (mesh) => mesh.primitives.reduce((s, p) =>
    s + ((p.mode ?? 4) === 4 ? gltf.accessors[p.indices].count / 3 : 0), 0);
  return { gltf, triangles };
}

async function download(page, selector, file) {
  const [d] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click(selector)]);
  const out = path.join(ARTIFACTS, file);
  await d.saveAs(out);
  return { name: d.suggestedFilename(), bytes: new Uint8Array(fs.readFileSync(out)) };
}

async function validates(label, bytes) {
  const report = await validator.validateBytes(bytes, { maxIssues: 50 });
  check(`${label}: gltf-validator 0 errors`, report.issues.numErrors === 0,
    report.issues.messages.filter((m) => m.severity === 0).map((m) => m.message).slice(0, 3).join('; '));
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1280, height: 900 }, acceptDownloads: true });
  const page = watchPage(await context.newPage(), problems);
  await page.goto(new URL("#preset=sakura&years=10&seed=1", server.url).href, { waitUntil: 'load' });
  await waitReady(page, 0);
  check('export panel is on the page', await page.isVisible('#export-max-triangles'));

  // Bad input: the one-line reason beside the field, nothing requested.
  await page.fill('#export-max-triangles', '12x');
  await page.click('#download-budget-glb');
  const error = (await page.textContent('#export-budget-error')).trim();
  check('a bad budget is refused beside its field', error === "triangle budget: '12x' must be a whole number in [6, 100000000]" &&
    (await page.getAttribute('#export-max-triangles', 'aria-invalid')) === 'true', error);
  await page.fill('#export-max-triangles', '3');
  check('a budget below 6 is refused', (await page.textContent('#export-budget-error')).includes('[6, 100000000]'));

  await page.fill('#export-max-triangles', String(BUDGET));
  check('a good budget clears the error', (await page.textContent('#export-budget-error')).trim() === '');
  const budget = await download(page, '#download-budget-glb', 'export-budget.glb');
  const b = parseGlb(budget.bytes);
  const bt = b.triangles(b.gltf.meshes[0]);
  check(`budget .glb within ${BUDGET} triangles`, bt <= BUDGET && bt >= BUDGET / 2, `${budget.name}: ${bt} triangles`);
  await validates('budget .glb', budget.bytes);

  const lod = await download(page, '#download-lod-glb', 'export-lod.glb');
  const l = parseGlb(lod.bytes);
  const names = l.gltf.scenes[0].nodes.map((n) => l.gltf.nodes[n].name);
  const counts = l.gltf.scenes[0].nodes.map((n) => l.triangles(l.gltf.meshes[l.gltf.nodes[n].mesh]));
  check('LOD .glb: nodes tree_LOD0, tree_LOD1, tree_LOD2', names.join() === 'tree_LOD0,tree_LOD1,tree_LOD2', `${lod.name}: ${names}`);
  check('LOD .glb: LOD0 within the budget, LOD1 <= 25 %, LOD2 <= 5 %',
    counts[0] <= BUDGET && counts[1] * 100 <= counts[0] * 25 && counts[2] * 100 <= counts[0] * 5 && counts[2] > 0, counts.join(' / '));
  await validates('LOD .glb', lod.bytes);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-export-panel-'));
  const cli = path.join(dir, 'lod.glb');
  execFileSync(NATIVE, ['tree', 'grow', ...TREE, '--max-triangles', String(BUDGET), '--lod', '--out', cli]);
  const cliBytes = fs.readFileSync(cli);
  check('LOD .glb equals the native CLI\'s bytes', Buffer.compare(Buffer.from(lod.bytes), cliBytes) === 0,
    `page ${lod.bytes.length} bytes, CLI ${cliBytes.length} bytes`);
  fs.rmSync(dir, { recursive: true, force: true });

  const sway = await download(page, '#download-sway-glb', 'export-sway.glb');
  const s = parseGlb(sway.bytes);
  check('sway .glb: one skin and an animation clip with channels',
    (s.gltf.skins?.length ?? 0) === 1 && (s.gltf.animations?.[0]?.channels?.length ?? 0) > 0,
    `${sway.name}: ${s.gltf.animations?.[0]?.channels?.length ?? 0} channels`);
  await validates('sway .glb', sway.bytes);
  check('no console errors', problems.length === 0, problems.slice(0, 3).join(' | '));
});
