// Grows every preset with the native CLI, validates each .glb with Khronos' gltf-validator (0 errors,
// embedded PNG textures decoded) and loads it with three.js (bark, leaf and flower materials with maps).
// Sway export: `niwa tree sway --out x.glb` (native and, when built, the WASM CLI: NIWA_WASM or
// build/wasm/bin/niwa.js) validates, is a three.js SkinnedMesh whose clip moves the bones, and the
// sway command's --out errors are one line, exit 2, with no file left behind; it carries the wind
// attributes _WIND_LEVEL, _WIND_ALONG and _WIND_PHASE on every part (issue 32 item 2).
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { cliArgv } from '../support/cli_pair.mjs';

const native = process.env.NIWA_NATIVE;
const root = process.env.NIWA_ROOT;
if (!native || !root) {
  console.log('FAIL set NIWA_NATIVE (native niwa binary) and NIWA_ROOT (repo root)');
  process.exit(2);
}

const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;
const three = join(root, 'node_modules', 'three');
const THREE = await import(pathToFileURL(join(three, 'build', 'three.module.js')).href);
const { GLTFLoader } = await import(
  pathToFileURL(join(three, 'examples', 'jsm', 'loaders', 'GLTFLoader.js')).href);

// GLTFLoader decodes embedded images through Blob -> object URL -> fetch -> createImageBitmap (it
// uses `self.URL`). Node 20 has Blob, object URLs and fetch of blob: URLs, but no `self` and no
// createImageBitmap: stand-ins that read the PNG's own header, so a material's `map` proves that
// three.js found PNG bytes of the expected size behind the image's bufferView.
globalThis.self ??= globalThis;
const decodedImages = [];
globalThis.createImageBitmap ??= async (blob) => {
  const bytes = new Uint8Array(await blob.arrayBuffer());
  const magic = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
  if (blob.type !== 'image/png' || !magic.every((b, i) => bytes[i] === b)) {
    throw new Error(`not a PNG (${blob.type}, ${bytes.length} bytes)`);
  }
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const bitmap = { width: view.getUint32(16), height: view.getUint32(20), png: true, close() {} };
  decodedImages.push(bitmap);
  return bitmap;
};

let failures = 0;
function check(ok, label, detail = '') {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${label}${detail ? ` (${detail})` : ''}`);
  if (!ok) failures += 1;
}

function niwa(args) {
  return execFileSync(native, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

async function validate(bytes) {
  return validator.validateBytes(new Uint8Array(bytes), { maxIssues: 50 });
}

function loadGltf(bytes) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => {
    new GLTFLoader().parse(buffer, '', resolve, reject);
  });
}

function meshesByMaterial(gltf) {
  const found = {};
  gltf.scene.traverse((object) => {
    if (!object.isMesh) return;
    const name = object.material?.name ?? '';
    found[name] = (found[name] ?? 0) + object.geometry.getAttribute('position').count;
  });
  return found;
}

function materialsByName(gltf) {
  const found = {};
  gltf.scene.traverse((object) => {
    if (object.isMesh && object.material) found[object.material.name] = object.material;
  });
  return found;
}

// Texture set-up of one three.js material: its map (the embedded PNG), wrapping and cut-out.
function checkTexturedMaterial(label, material, { cutOut }) {
  const map = material?.map;
  const image = map?.image;
  check(Boolean(map && image?.png && image.width > 0 && image.height > 0),
        `${label}: three.js material has a PNG texture map`,
        image ? `${image.width}x${image.height}` : 'no map');
  if (!map) return;
  const wrap = cutOut ? 1001 : 1000;  // THREE.ClampToEdgeWrapping : THREE.RepeatWrapping
  check(map.wrapS === wrap && map.wrapT === wrap, `${label}: texture wrapping`,
        `${map.wrapS}/${map.wrapT}`);
  if (cutOut) {
    check(material.alphaTest === 0.5 && material.side === 2 && !material.transparent,
          `${label}: alpha-masked and double-sided`,
          `alphaTest ${material.alphaTest}, side ${material.side}, transparent ${material.transparent}`);
  }
}

// The same .glb with a wrong POSITION max: the validator must reject it (proves the check can fail).
function withWrongPositionMax(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  const accessor = json.accessors[json.meshes[0].primitives[0].attributes.POSITION];
  accessor.max[1] += 1;
  let text = JSON.stringify(json);
  while (text.length % 4) text += ' ';
  const rest = bytes.subarray(20 + jsonLength);
  const out = new Uint8Array(20 + text.length + rest.length);
  const outView = new DataView(out.buffer);
  out.set(bytes.subarray(0, 12));
  outView.setUint32(8, out.length, true);
  outView.setUint32(12, text.length, true);
  outView.setUint32(16, 0x4e4f534a, true);
  out.set(new TextEncoder().encode(text), 20);
  out.set(rest, 20 + text.length);
  return out;
}

const presets = niwa(['presets'])
  .split('\n')
  .filter((line) => line.trim())
  .map((line) => line.split('\t')[0]);
check(presets.length > 0, 'niwa presets lists presets', presets.join(', '));

let tampered = null;
const dir = mkdtempSync(join(tmpdir(), 'niwa-gltf-'));
try {
  const cases = presets.map((p) => ({ label: p, args: ['--preset', p, '--years', '6'], empty: false }));
  if (presets.includes('sakura-thesis')) {  // sakura flowers from its 7th year on
    cases.push({ label: 'sakura at 8 years', args: ['--preset', 'sakura-thesis', '--years', '8'],
                 empty: false, flowers: true });
  }
  if (presets.length) {
    cases.push({ label: `${presets[0]} at 0 years`, args: ['--preset', presets[0], '--years', '0'],
                 empty: true });
  }
  for (const c of cases) {
    const out = join(dir, `${c.label.replace(/\W+/g, '_')}.glb`);
    try {
      niwa(['tree', 'grow', ...c.args, '--out', out]);
    } catch (error) {
      check(false, `${c.label}: niwa tree grow`, String(error.stderr ?? error.message).trim());
      continue;
    }
    const bytes = readFileSync(out);
    check(bytes.subarray(0, 4).toString('latin1') === 'glTF', `${c.label}: glb magic`);

    const report = await validate(bytes);
    const { numErrors, numWarnings } = report.issues;
    const errors = report.issues.messages.filter((m) => m.severity === 0).slice(0, 5)
      .map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`);
    check(numErrors === 0, `${c.label}: gltf-validator`,
          `${numErrors} errors, ${numWarnings} warnings, ${report.issues.numInfos} infos` +
          (errors.length ? '; ' + errors.join('; ') : ''));
    // Issue 32 item 2: the bark's normal map comes with TANGENT (io/gltf_writer).
    check(!report.issues.messages.some((m) => m.code === 'MESH_PRIMITIVE_GENERATED_TANGENT_SPACE'),
          `${c.label}: no missing-tangent warning`);
    if (!c.empty) {
      // The validator decodes every embedded image: RGBA PNGs in buffer views, one per material.
      const images = (report.info?.resources ?? []).filter((r) => r.pointer?.startsWith('/images/'));
      const decoded = images.filter((r) => r.mimeType === 'image/png' && r.storage === 'buffer-view' &&
                                           r.image?.width > 0 && r.image?.height > 0);
      const jsonLength = bytes.readUInt32LE(12);
      const materials = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8')).materials ?? [];
      // One per material and the bark's normal map.
      check(decoded.length === materials.length + 1 && decoded.length === images.length &&
            decoded.length >= (c.flowers ? 4 : 3),
            `${c.label}: gltf-validator decodes the embedded PNG textures`,
            images.map((r) => `${r.pointer} ${r.image?.width}x${r.image?.height} ${r.image?.format}`)
              .join(', '));
    }
    if (!c.empty && !tampered) tampered = await validate(withWrongPositionMax(bytes));

    let gltf;
    try {
      gltf = await loadGltf(bytes);
    } catch (error) {
      check(false, `${c.label}: three.js GLTFLoader`, String(error?.message ?? error));
      continue;
    }
    const found = meshesByMaterial(gltf);
    const summary = Object.entries(found).map(([k, v]) => `${k} ${v} vertices`).join(', ');
    if (c.empty) {
      check(Object.keys(found).length === 0, `${c.label}: three.js loads an empty scene`, summary);
    } else {
      check((found.bark ?? 0) > 0 && (found.leaves ?? 0) > 0,
            `${c.label}: three.js finds bark and leaf meshes`, summary);
    }
    if (c.flowers) {
      check((found.flowers ?? 0) > 0, `${c.label}: three.js finds the flower mesh`, summary);
    }
    if (!c.empty) {
      const materials = materialsByName(gltf);
      checkTexturedMaterial(`${c.label} bark`, materials.bark, { cutOut: false });
      checkTexturedMaterial(`${c.label} leaves`, materials.leaves, { cutOut: true });
      if (c.flowers) checkTexturedMaterial(`${c.label} flowers`, materials.flowers, { cutOut: true });
    }
  }

  // ---- sway export: skinned mesh + one animation clip ----
  const wasm = process.env.NIWA_WASM ?? join(root, 'build/wasm/bin/niwa.js');
  const runners = [{ label: 'native', cmd: native, pre: [] }];
  if (existsSync(wasm)) runners.push({ label: 'wasm', cmd: cliArgv(wasm, [])[0], pre: cliArgv(wasm, [])[1] });
  else console.log(`note: no WASM CLI at ${wasm}; sway .glb checked on the native CLI only`);
  const swayArgs = ['tree', 'sway', '--preset', 'sakura-thesis', '--years', '6', '--wind', '10', '--gust', '0:4',
                    '--duration', '6'];
  const swayBytes = {};
  for (const r of runners) {
    const out = join(dir, `sway-${r.label}.glb`);
    const run = spawnSync(r.cmd, [...r.pre, ...swayArgs, '--out', out, '--stats'], { encoding: 'utf8' });
    check(run.status === 0, `sway ${r.label}: niwa tree sway --out sway.glb`, run.stderr.trim());
    if (run.status !== 0) continue;
    const stats = JSON.parse(run.stdout);
    const bytes = readFileSync(out);
    swayBytes[r.label] = bytes;
    const report = await validate(bytes);
    const errors = report.issues.messages.filter((m) => m.severity === 0).slice(0, 5)
      .map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`);
    check(report.issues.numErrors === 0 && report.info?.hasSkins && report.info?.animationCount === 1,
          `sway ${r.label}: gltf-validator, a skin and one animation`,
          `${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings, ` +
          `${(bytes.length / 1e6).toFixed(2)} MB` + (errors.length ? '; ' + errors.join('; ') : ''));
    check(!report.issues.messages.some((m) => m.code === 'MESH_PRIMITIVE_GENERATED_TANGENT_SPACE'),
          `sway ${r.label}: no missing-tangent warning`);
    if (r.label !== 'native') continue;

    // The skin within the default joint budget (docs/sway-model.md "Joint budget"): the exact one
    // (1 + 2 x moving + followers) when it fits 128, else the node points grouped.
    const exact = 1 + 2 * stats.moving + stats.followers;
    const joints = stats.glb?.joints;
    check(stats.glb?.exact_joints === exact && joints === Math.min(exact, 128) && stats.glb.clustered === (exact > 128),
          'sway: the skin within the 128-joint budget (--stats glb)', JSON.stringify(stats.glb));
    let gltf;
    try {
      gltf = await loadGltf(bytes);
    } catch (error) {
      check(false, 'sway: three.js GLTFLoader', String(error?.message ?? error));
      continue;
    }
    const skinned = [];
    gltf.scene.traverse((o) => { if (o.isSkinnedMesh) skinned.push(o); });
    const bones = skinned[0]?.skeleton?.bones ?? [];
    check(skinned.length >= 2 && bones.length === joints,
          'sway: three.js finds SkinnedMeshes with one bone per joint',
          `${skinned.length} skinned meshes, ${bones.length} bones, expected ${joints} ` +
          `(of ${exact} for the exact skin: 1 + 2 x ${stats.moving} moving + ${stats.followers} followers)`);
    const clip = gltf.animations[0];
    check(gltf.animations.length === 1 && clip.tracks.length === 2 * (joints - 1) &&
          Math.abs(clip.duration - 6) < 1e-3,
          'sway: one clip, a translation and a rotation track per joint but the root, 6 s',
          `${gltf.animations.length} clips, ${clip?.tracks.length} tracks, ${clip?.duration} s`);
    gltf.scene.updateMatrixWorld(true);
    const rest = bones.map((b) => new THREE.Vector3().setFromMatrixPosition(b.matrixWorld));
    const mixer = new THREE.AnimationMixer(gltf.scene);
    mixer.clipAction(clip).play();
    mixer.update(3.0);  // inside the gust
    gltf.scene.updateMatrixWorld(true);
    let moved = 0;
    bones.forEach((b, k) => {
      moved = Math.max(moved, new THREE.Vector3().setFromMatrixPosition(b.matrixWorld).distanceTo(rest[k]));
    });
    check(moved > 0.01, 'sway: AnimationMixer moves the bones (largest bone displacement at 3 s, m)',
          moved.toFixed(4));
    // The skinned tip of the farthest bark vertex follows: three.js' own CPU skinning.
    const bark = skinned.find((m) => m.material?.name === 'bark');
    let vertexMoved = 0;
    if (bark) {
      const position = bark.geometry.getAttribute('position');
      const a = new THREE.Vector3(), b = new THREE.Vector3();
      for (let v = 0; v < position.count; v += 7) {
        a.fromBufferAttribute(position, v);
        b.copy(a);
        bark.applyBoneTransform(v, b);
        vertexMoved = Math.max(vertexMoved, a.distanceTo(b));
      }
    }
    check(vertexMoved > 0.01, 'sway: three.js skins bark vertices away from rest at 3 s (m)',
          vertexMoved.toFixed(4));
    // Wind data (issue 32 item 2, docs/sway-model.md "Wind attributes"): _WIND_LEVEL (branch
    // hierarchy level), _WIND_ALONG (0 at a branch's base, 1 at its tip) and _WIND_PHASE ([0, 1)
    // per branch) on every part, read by GLTFLoader as the lower-case geometry attributes.
    const wind = skinned.map((m) => {
      const g = m.geometry, n = g.getAttribute('position').count;
      const [level, along, phase] = ['_wind_level', '_wind_along', '_wind_phase'].map((a) => g.getAttribute(a));
      if (!level || !along || !phase || level.count !== n || along.count !== n || phase.count !== n) {
        return { ok: false, what: `${m.material?.name}: missing or short` };
      }
      const levels = Array.from(level.array), alongs = Array.from(along.array), phases = Array.from(phase.array);
      const ok = levels.every((x) => Number.isInteger(x) && x >= 0) && alongs.every((x) => x >= 0 && x <= 1) &&
        phases.every((x) => x >= 0 && x < 1);
      return { ok, what: `${m.material?.name}: levels 0..${Math.max(...levels)}, along ${Math.min(...alongs)}..${Math.max(...alongs)}, ` +
        `${new Set(phases).size} phases`, maxLevel: Math.max(...levels), maxAlong: Math.max(...alongs), phases: new Set(phases).size };
    });
    const barkWind = wind[skinned.indexOf(bark)] ?? {};
    check(wind.every((w) => w.ok) && barkWind.maxLevel >= 2 && barkWind.maxAlong === 1 && barkWind.phases >= 10,
          'sway: every part carries _WIND_LEVEL (whole, >= 0), _WIND_ALONG ([0, 1], the bark reaching 1) and _WIND_PHASE ([0, 1), many)',
          wind.map((w) => w.what).join('; '));
  }
  if (swayBytes.native && swayBytes.wasm) {
    check(Buffer.compare(swayBytes.native, swayBytes.wasm) === 0, 'sway: native and WASM .glb identical',
          `${swayBytes.native.length} vs ${swayBytes.wasm.length} bytes`);
  }
  // One-line errors, exit 2, nothing written.
  for (const [args, label, want] of [
    [['--out', join(dir, 'bad.obj')], 'bad --out extension', '--out:'],
    [['--out', join(dir, 'bad.glb'), '--fps', '0'], '--fps 0', '--fps:'],
    [['--fps', '30'], '--fps without .glb', '--fps:'],
    [['--out', join(dir, 'bad.glb'), '--max-triangles', '3'], '--max-triangles 3', '--max-triangles:'],
    [['--out', join(dir, 'bad.glb'), '--max-triangles', '100', '--full-mesh'], '--full-mesh with --max-triangles', '--full-mesh:'],
    [['--out', join(dir, 'bad.glb'), '--key-error', '2'], '--key-error 2', '--key-error:'],
    [['--key-error', '0.01'], '--key-error without .glb', '--key-error:'],
  ]) {
    const before = readdirSync(dir).length;
    const run = spawnSync(native, [...swayArgs, ...args], { encoding: 'utf8' });
    const lines = run.stderr.trim().split('\n');
    check(run.status === 2 && lines.length === 1 && lines[0].includes(want) &&
          readdirSync(dir).length === before, `sway ${label}: one-line error, exit 2, no file`,
          `exit ${run.status}: ${run.stderr.trim()}`);
  }
  // The sway .glb within its budgets (issue 32 item 2, docs/lod-export.md "The sway .glb"): a 15-year
  // sakura at the defaults is skinned on its 20,000-triangle mesh with 128 joints, its clip's keys
  // reduced within 2 mm, <= 8 MB; three.js moves its cards and twigs with the bones.
  {
    const out = join(dir, 'sway-sakura15.glb');
    const run = spawnSync(native, ['tree', 'sway', '--preset', 'sakura', '--years', '15', '--out', out, '--stats'],
                          { encoding: 'utf8' });
    check(run.status === 0, 'sway budget: niwa tree sway --preset sakura --years 15 --out x.glb', run.stderr.trim());
    if (run.status === 0) {
      const g = JSON.parse(run.stdout).glb;
      const bytes = readFileSync(out);
      check(bytes.length <= 8e6 && g.joints <= 128 && !g.full_mesh && g.triangles <= 20000,
            'sway budget: a 15-year sakura\'s sway .glb <= 8 MB, <= 128 joints, <= 20,000 triangles',
            `${(bytes.length / 1e6).toFixed(2)} MB, ${g.joints} joints of ${g.exact_joints}, ${g.triangles} triangles`);
      check(g.joint_keys < g.full_joint_keys && g.key_error_m > 0 && g.key_error_m <= 0.002,
            'sway budget: the clip\'s keys reduced within 2 mm',
            `${g.joint_keys} of ${g.full_joint_keys} joint keys, largest bound ${(1000 * g.key_error_m).toFixed(3)} mm`);
      const report = await validate(bytes);
      check(report.issues.numErrors === 0 && report.info?.hasSkins && report.info?.animationCount === 1,
            'sway budget: gltf-validator, a skin and one animation',
            `${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`);
      const gltf = await loadGltf(bytes);
      const skinned = [];
      gltf.scene.traverse((o) => { if (o.isSkinnedMesh) skinned.push(o); });
      const names = skinned.map((m) => m.material?.name).sort();
      check(['bark', 'cards_0', 'twigs'].every((n) => names.includes(n)) &&
            skinned.every((m) => m.skeleton.bones.length === g.joints),
            'sway budget: three.js finds skinned bark, cards and twigs on one skeleton', names.join(', '));
      const mixer = new THREE.AnimationMixer(gltf.scene);
      mixer.clipAction(gltf.animations[0]).play();
      mixer.update(3.0);  // inside the default gust (1-6 s)
      gltf.scene.updateMatrixWorld(true);
      const movedBy = (mesh) => {
        const position = mesh.geometry.getAttribute('position');
        const a = new THREE.Vector3(), b = new THREE.Vector3();
        let most = 0;
        for (let v = 0; v < position.count; v += 5) {
          a.fromBufferAttribute(position, v);
          mesh.applyBoneTransform(v, b.copy(a));
          most = Math.max(most, a.distanceTo(b));
        }
        return most;
      };
      const moved = Object.fromEntries(skinned.map((m) => [m.material?.name, movedBy(m)]));
      check(moved.cards_0 > 0.05 && moved.twigs > 0.05,
            'sway budget: at 3 s the cards and twigs move with the bones (largest vertex motion, m)',
            Object.entries(moved).map(([k, v]) => `${k} ${v.toFixed(3)}`).join(', '));
    }
  }
  const csv = join(dir, 'sway.csv');
  const csvRun = spawnSync(native, [...swayArgs, '--out', csv], { encoding: 'utf8' });
  check(csvRun.status === 0 && readFileSync(csv, 'utf8').startsWith('time,node,x,y,z'),
        'sway --out .csv writes the tip trajectories', csvRun.stderr.trim());

  check(tampered !== null && tampered.issues.numErrors > 0,
        'gltf-validator rejects a .glb with a wrong POSITION max',
        tampered ? tampered.issues.messages.filter((m) => m.severity === 0).map((m) => m.code)
          .slice(0, 3).join(', ') : 'no valid tree to tamper with');
} finally {
  rmSync(dir, { recursive: true, force: true });
}

console.log(failures ? `${failures} check(s) failed` : 'all checks passed');
process.exit(failures ? 1 : 0);
