// Bark on a grown tree (issue 30 item 3, core/compose/bark_on_tree): `niwa tree grow --bark sim`
// gives the same .glb bytes and --stats natively and in WASM (a small tree, 256 px maps), the .glb
// is validator-clean (Khronos gltf-validator, 0 errors) with materials bark and bark_young carrying
// base colour, normal and occlusion textures (sampler REPEAT) that are not the procedural ones; the
// default (no --bark, or --bark procedural) writes the procedural .glb byte for byte; the tree
// table's rows bark and bark_model (--set, a page link) are the same setting as --bark sim and
// --bark-model (the same bytes); bad values of
// --bark and its flags are one line naming the flag, exit 2, nothing written. Issue 32 item 2: both
// .glb carry TANGENT (VEC4 floats: unit xyz perpendicular to NORMAL, w = +-1) on exactly the
// primitives whose material has a normal texture, and the validator has no missing-tangent warning;
// their handedness turns the map's +Y along -dP/dv, as glTF's "+Y up the image" asks.
import { mkdtempSync, readFileSync, readdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { buildName, check, finish, native, requireWasm, root, spawn, wasm, withoutMs } from '../support/cli_pair.mjs';
import { mapUpAgreement } from '../support/tangent_frame.mjs';

requireWasm();
const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;

const work = mkdtempSync(join(tmpdir(), 'niwa-tree-bark-'));
const tree = ['tree', 'grow', '--preset', 'binary', '--years', '6'];
const sim = ['--bark', 'sim', '--bark-height', '0.02', '--bark-map-size', '256'];

// The JSON chunk and the images (PNG bytes by texture index) of a .glb.
function parseGlb(bytes) {
  const jsonLength = bytes.readUInt32LE(12);
  const json = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  const bin = bytes.subarray(20 + jsonLength + 8);
  const image = (texture) => {
    const view = json.bufferViews[json.images[json.textures[texture].source].bufferView];
    return bin.subarray(view.byteOffset || 0, (view.byteOffset || 0) + view.byteLength);
  };
  const floats = (accessor) => {
    const a = json.accessors[accessor];
    const view = json.bufferViews[a.bufferView];
    const start = (view.byteOffset || 0) + (a.byteOffset || 0);
    const size = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 }[a.type];
    return new Float32Array(bin.buffer.slice(bin.byteOffset + start, bin.byteOffset + start + a.count * size * 4));
  };
  return { json, bin, image, floats };
}

// TANGENT on every normal-mapped primitive (and on no other), well formed; no validator warning.
async function checkTangents(label, bytes) {
  const report = await validator.validateBytes(new Uint8Array(bytes), { maxIssues: 200 });
  const missing = report.issues.messages.filter((m) => m.code === 'MESH_PRIMITIVE_GENERATED_TANGENT_SPACE');
  check(`${label}: gltf-validator 0 errors, no missing-tangent warning (${report.issues.numWarnings} warnings)`,
    report.issues.numErrors === 0 && missing.length === 0,
    JSON.stringify(report.issues.messages.slice(0, 3)));
  const glb = parseGlb(bytes);
  let mapped = 0, vertices = 0, triangles = 0, agree = 0;
  const bad = [];
  glb.json.meshes.forEach((mesh, i) => mesh.primitives.forEach((p, j) => {
    const normalMapped = p.material !== undefined && glb.json.materials[p.material].normalTexture !== undefined;
    const where = `meshes[${i}].primitives[${j}]`;
    if (!normalMapped) {
      if (p.attributes.TANGENT !== undefined) bad.push(`${where}: TANGENT without a normal map`);
      return;
    }
    mapped += 1;
    const a = glb.json.accessors[p.attributes.TANGENT];
    if (!a || a.type !== 'VEC4' || a.componentType !== 5126) {
      bad.push(`${where}: no float VEC4 TANGENT`);
      return;
    }
    const t = glb.floats(p.attributes.TANGENT), n = glb.floats(p.attributes.NORMAL);
    for (let v = 0; v < a.count; v += 1) {
      const [x, y, z, w] = t.subarray(4 * v, 4 * v + 4);
      const length = Math.hypot(x, y, z);
      const dot = (x * n[3 * v] + y * n[3 * v + 1] + z * n[3 * v + 2]) / Math.max(Math.hypot(...n.subarray(3 * v, 3 * v + 3)), 1e-30);
      if (!(Math.abs(length - 1) < 1e-4 && Math.abs(dot) < 1e-3 && (w === 1 || w === -1))) {
        bad.push(`${where} vertex ${v}: (${x}, ${y}, ${z}, ${w}), normal dot ${dot}`);
        break;
      }
    }
    vertices += a.count;
    const up = mapUpAgreement(glb.json, glb.bin, p);
    triangles += up.triangles;
    agree += up.agree;
  }));
  check(`${label}: TANGENT on the ${mapped} normal-mapped primitives (${vertices} vertices), unit, perpendicular to NORMAL, w = +-1`,
    mapped > 0 && bad.length === 0, bad.slice(0, 3).join('; '));
  // glTF's map +Y is -dP/dv (tests/support/tangent_frame.mjs): bumps lit from the right side.
  check(`${label}: cross(N, T) * w runs along -dP/dv (glTF's normal-map +Y) on ${agree} of ${triangles} uv triangles`,
    triangles > 0 && agree >= 0.99 * triangles);
}

// The sim .glb in both builds.
const got = {};
for (const cmd of [native, wasm]) {
  const out = join(work, `sim-${buildName(cmd)}.glb`);
  const r = spawn(cmd, [...tree, ...sim, '--out', out, '--stats']);
  check(`--bark sim ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr.trim());
  got[buildName(cmd)] = { bytes: r.status === 0 ? readFileSync(out) : Buffer.alloc(0),
    stats: r.status === 0 ? withoutMs(JSON.parse(r.stdout)) : {} };
}
check(`--bark sim: native == WASM .glb bytes (${got.native.bytes.length})`,
  got.native.bytes.length > 0 && got.native.bytes.equals(got.wasm.bytes));
check('--bark sim: native == WASM --stats (timings aside)', JSON.stringify(got.native.stats) === JSON.stringify(got.wasm.stats));
const bark = got.native.stats.bark || {};
// dR: the window's strain and the turnover's combined as rates (docs/bark-model.md, "On Niwa's trees" item 4), below both.
const surfaceStrain = bark.hoop_strain * bark.turnover_strain / (bark.hoop_strain + bark.turnover_strain);
check(`--stats bark: ${bark.cycles} cycle at dR ${bark.dR} (the window's strain ${bark.hoop_strain} with the turnover's ${bark.turnover_strain}; ` +
  `young ${bark.young_dR}), surface ${bark.surface_years} years, years ${bark.years}, N_R ${bark.N_R} even, radii rising`,
  bark.cycles === 1 && bark.years?.[1] === 6 && bark.N_R % 2 === 0 &&
  Math.abs(bark.dR - surfaceStrain) <= 1e-9 * surfaceStrain && bark.dR < bark.hoop_strain &&
  bark.dR < bark.turnover_strain && bark.young_dR === bark.dR / 2 &&
  bark.surface_years > 0 && bark.surface_years <= 4 &&
  bark.radii_cm.every((r, i) => i === 0 || r >= bark.radii_cm[i - 1]) && bark.tile_cm[0] > 0);

// --bark-model 4layer: the old bark is the 4-layer model (3 cycles, peeling), the same bytes and
// stats natively and in WASM, validator-clean; its maps are not the 2-layer run's.
const four = {};
for (const cmd of [native, wasm]) {
  const out = join(work, `sim4-${buildName(cmd)}.glb`);
  const r = spawn(cmd, [...tree, ...sim, '--bark-model', '4layer', '--out', out, '--stats']);
  check(`--bark sim --bark-model 4layer ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr.trim());
  four[buildName(cmd)] = { bytes: r.status === 0 ? readFileSync(out) : Buffer.alloc(0),
    stats: r.status === 0 ? withoutMs(JSON.parse(r.stdout)) : {} };
}
const bark4 = four.native.stats.bark || {};
check(`--bark-model 4layer: native == WASM .glb bytes (${four.native.bytes.length}) and --stats`,
  four.native.bytes.length > 0 && four.native.bytes.equals(four.wasm.bytes) &&
  JSON.stringify(four.native.stats) === JSON.stringify(four.wasm.stats));
check(`--bark-model 4layer --stats: model ${bark4.model}, ${bark4.cycles} cycles at dR ${bark4.dR} (the surface's ${bark.dR} over 2), ` +
  `young ${bark4.young_dR}, hash ${bark4.hash}`,
  bark4.model === '4layer' && bark.model === '2layer' && bark4.cycles === 3 &&
  Math.abs(bark4.dR - bark.dR / 2) <= 1e-12 && bark4.young_dR === bark.young_dR && bark4.hash !== bark.hash &&
  String(bark4.hash).includes('model=4layer'));
// The tree table's rows are the same setting (the page's panel and link: bark=1&bark_model=4):
// --set bark=1 --set bark_model=4 writes the bytes of --bark sim --bark-model 4layer, in both builds.
for (const cmd of [native, wasm]) {
  const out = join(work, `rows4-${buildName(cmd)}.glb`);
  const r = spawn(cmd, [...tree, '--set', 'bark=1', '--set', 'bark_model=4', '--bark-height', '0.02', '--bark-map-size', '256', '--out', out]);
  check(`--set bark=1 --set bark_model=4 ${buildName(cmd)}: the bytes of --bark sim --bark-model 4layer`,
    r.status === 0 && four.native.bytes.length > 0 && readFileSync(out).equals(four.native.bytes), r.stderr.trim());
}
const report4 = await validator.validateBytes(new Uint8Array(four.native.bytes), { maxIssues: 50 });
check('--bark-model 4layer .glb: gltf-validator 0 errors', report4.issues.numErrors === 0,
  JSON.stringify(report4.issues.messages.filter((m) => m.severity === 0).slice(0, 3)));
{
  const g4 = parseGlb(four.native.bytes);
  const m4 = g4.json.materials.find((x) => x.name === 'bark');
  const m2 = parseGlb(got.native.bytes).json.materials.find((x) => x.name === 'bark');
  check('--bark-model 4layer: the bark\'s base colour is not the 2-layer run\'s',
    Boolean(m4 && m2) && !g4.image(m4.pbrMetallicRoughness.baseColorTexture.index).equals(
      parseGlb(got.native.bytes).image(m2.pbrMetallicRoughness.baseColorTexture.index)));
}

// Validator-clean, the two bark materials dressed in the maps.
const report = await validator.validateBytes(new Uint8Array(got.native.bytes), { maxIssues: 50 });
check('--bark sim .glb: gltf-validator 0 errors', report.issues.numErrors === 0,
  JSON.stringify(report.issues.messages.filter((m) => m.severity === 0).slice(0, 3)));
const simGlb = parseGlb(got.native.bytes);
const procedural = join(work, 'procedural.glb');
const plain = spawn(native, [...tree, '--out', procedural]);
check('procedural .glb: exit 0', plain.status === 0, plain.stderr.trim());
await checkTangents('--bark sim .glb', got.native.bytes);
await checkTangents('procedural .glb', readFileSync(procedural));
const proceduralGlb = parseGlb(readFileSync(procedural));
const proceduralBark = proceduralGlb.json.materials.find((m) => m.name === 'bark');
for (const name of ['bark', 'bark_young']) {
  const m = simGlb.json.materials.find((x) => x.name === name);
  const ok = m && m.pbrMetallicRoughness?.baseColorTexture && m.normalTexture && m.occlusionTexture;
  check(`material ${name}: baseColor, normal and occlusion textures`, Boolean(ok), JSON.stringify(m));
  if (!ok) continue;
  const textures = [m.pbrMetallicRoughness.baseColorTexture.index, m.normalTexture.index, m.occlusionTexture.index];
  const repeat = textures.every((t) => {
    const s = simGlb.json.samplers[simGlb.json.textures[t].sampler];
    return s.wrapS === undefined || (s.wrapS === 10497 && (s.wrapT === undefined || s.wrapT === 10497));
  });
  check(`material ${name}: sampler REPEAT`, repeat);
  const colour = simGlb.image(textures[0]);
  const before = proceduralGlb.image(proceduralBark.pbrMetallicRoughness.baseColorTexture.index);
  check(`material ${name}: its base colour is not the procedural bark (${colour.length} vs ${before.length} bytes)`, !colour.equals(before));
  check(`material ${name}: 256 px wide maps`, colour.readUInt32BE(16) === 256);
}
check('the young bark is a primitive of its own', simGlb.json.meshes[0].primitives.some(
  (p) => simGlb.json.materials[p.material].name === 'bark_young'));

// The default keeps its bytes: no --bark and --bark procedural write the same file, in both builds.
for (const cmd of [native, wasm]) {
  const out = join(work, `procedural-${buildName(cmd)}.glb`);
  const r = spawn(cmd, [...tree, '--bark', 'procedural', '--out', out]);
  check(`--bark procedural ${buildName(cmd)}: the default's bytes`, r.status === 0 && readFileSync(out).equals(readFileSync(procedural)), r.stderr.trim());
}

// Bad input: one line naming the flag, exit 2, nothing written.
for (const [args, flag, text] of [
  [['--bark', 'foo'], '--bark', 'must be procedural or sim'],
  [['--bark', 'sim', '--bark-height', '5', '--bark-map-size', '256'], '--bark-height', 'must be a number in [0, '],
  [['--bark', 'sim', '--bark-height', 'nan'], '--bark-height', ''],
  [['--bark', 'sim', '--bark-height', '-1'], '--bark-height', ''],
  [['--bark-height', '0.02'], '--bark-height', 'only applies with --bark sim'],
  [['--bark', 'sim', '--bark-species', 'oak'], '--bark-species', 'camphor, tallow or pine'],
  [['--bark', 'sim', '--bark-map-size', '300'], '--bark-map-size', 'power of two'],
  [['--bark', 'sim', '--bark-model', '3layer'], '--bark-model', 'must be 2layer or 4layer'],
  [['--bark-model', '4layer'], '--bark-model', 'only applies with --bark sim'],
  [['--bark', 'sim', '--bark-height', '0.02', '--bark-model', '4layer', '--max-seconds', '1'], '--bark', 'use --bark-model 2layer'],
  [['--bark', 'sim', '--lod'], '--bark', ''],
  [['--set', 'bark=1', '--set', 'bark_model=3', '--bark-height', '0.02'], 'bark_model', 'must be 2 (the 2-layer model) or 4'],
  [['--set', 'bark=2'], '--set', ''],
  [['--bark', 'sim', '--bark-height', '0.02', '--bark-map-size', '4096', '--max-memory', '512M'], '--bark', 'the bark'],
]) {
  for (const cmd of [native, wasm]) {
    const dir = mkdtempSync(join(work, 'bad-'));
    const r = spawn(cmd, [...tree, ...args, '--out', join(dir, 't.glb')]);
    const lines = r.stderr.trim().split('\n');
    check(`${args.join(' ')} ${buildName(cmd)}: exit 2, one line naming ${flag}`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${flag}:`) && lines[0].includes(text) &&
      readdirSync(dir).length === 0, r.stderr.trim());
  }
}
finish();
