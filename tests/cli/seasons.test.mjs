// The look rows on the .glb (issue 17 items 2-3): `niwa tree grow --set season=N` (and leaf_shape)
// writes a validator-clean .glb whose parts, materials and 512 px textures follow the season
// (winter bare, a cherry's spring blossom on bare wood, autumn without flowers), the leaf texture of
// the preset's leaf shape, bark with a normal map, loaded by three.js; the native and WASM CLIs
// write the same bytes (the procedural textures are deterministic across builds). Bad values are one
// line naming the row and its range, exit 2, no file.
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { buildName, check, finish, native, requireWasm, root, run, spawn, wasm } from '../support/cli_pair.mjs';

if (!native || !root) {
  console.log('FAIL set NIWA_NATIVE (native niwa binary) and NIWA_ROOT (repo root)');
  process.exit(2);
}
requireWasm();

const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;
const three = join(root, 'node_modules', 'three');
await import(pathToFileURL(join(three, 'build', 'three.module.js')).href);
const { GLTFLoader } = await import(pathToFileURL(join(three, 'examples', 'jsm', 'loaders', 'GLTFLoader.js')).href);
// GLTFLoader decodes images through createImageBitmap, which node lacks: a stand-in that reads the
// PNG header (as tests/cli/gltf_validate.test.mjs does).
globalThis.self ??= globalThis;
globalThis.createImageBitmap ??= async (blob) => {
  const bytes = new Uint8Array(await blob.arrayBuffer());
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  return { width: view.getUint32(16), height: view.getUint32(20), close() {} };
};

function gltfJson(bytes) {
  const length = bytes.readUInt32LE(12);
  return JSON.parse(bytes.subarray(20, 20 + length).toString('utf8'));
}

function load(bytes) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

const dir = mkdtempSync(join(tmpdir(), 'niwa-seasons-'));
try {
  const grow = (cmd, preset, years, sets, name) => {
    const out = join(dir, `${name}-${buildName(cmd)}.glb`);
    run(cmd, ['tree', 'grow', '--preset', preset, '--years', String(years),
      ...sets.flatMap((s) => ['--set', s]), '--out', out]);
    return readFileSync(out);
  };
  // preset, years, --set values, expected parts, the leaf texture's name (the species presets draw
  // their leaves as sprays of leaf_spray leaves: '_spray3'; the -thesis presets single leaves).
  const cases = [
    { name: 'sakura-summer', preset: 'sakura-thesis', years: 8, sets: [], parts: ['bark', 'leaves', 'flowers'], leaf: 'leaf_broad_summer' },
    { name: 'sakura-spring', preset: 'sakura-thesis', years: 8, sets: ['season=0'], parts: ['bark', 'flowers'] },
    { name: 'sakura-autumn', preset: 'sakura-thesis', years: 8, sets: ['season=2'], parts: ['bark', 'leaves'], leaf: 'leaf_broad_autumn' },
    { name: 'sakura-winter', preset: 'sakura-thesis', years: 8, sets: ['season=3'], parts: ['bark'] },
    { name: 'pine-winter', preset: 'pine', years: 6, sets: ['season=3'], parts: ['bark', 'leaves'], leaf: 'leaf_needle_winter_spray3' },
    { name: 'maple-autumn', preset: 'maple', years: 6, sets: ['season=2'], parts: ['bark', 'leaves'], leaf: 'leaf_palmate_autumn_spray3' },
    { name: 'ginkgo-autumn', preset: 'ginkgo', years: 6, sets: ['season=2'], parts: ['bark', 'leaves'], leaf: 'leaf_fan_autumn_spray3' },
    { name: 'keyaki-fan', preset: 'keyaki-thesis', years: 4, sets: ['leaf_shape=3'], parts: ['bark', 'leaves'], leaf: 'leaf_fan_summer' },
    { name: 'tsutsuji-spring', preset: 'tsutsuji', years: 8, sets: ['season=0'], parts: ['bark', 'leaves', 'flowers'], leaf: 'leaf_broad_spring' },
  ];
  const seasonOf = (sets) => ['spring', 'summer', 'autumn', 'winter'][Number((sets.find((s) => s.startsWith('season=')) ?? 'season=1').split('=')[1])];
  for (const c of cases) {
    const bytes = grow(native, c.preset, c.years, c.sets, c.name);
    const gltf = gltfJson(bytes);
    const materials = (gltf.materials ?? []).map((m) => m.name);
    check(`${c.name}: materials ${materials.join(', ')} (want ${c.parts.join(', ')})`, JSON.stringify(materials) === JSON.stringify(c.parts));
    const primitives = gltf.meshes[0].primitives.length;
    check(`${c.name}: ${primitives} primitives`, primitives === c.parts.length);
    // One base-colour texture per material, plus the bark's normal map.
    check(`${c.name}: ${gltf.textures.length} textures for ${c.parts.length} materials + the normal map`,
      gltf.textures.length === c.parts.length + 1 && gltf.images.length === c.parts.length + 1);
    const bark = gltf.materials[0];
    check(`${c.name}: bark has its normal map`,
      Number.isInteger(bark.normalTexture?.index) && gltf.textures[bark.normalTexture.index].name === 'bark_normal');
    check(`${c.name}: bark extras carry season ${bark.extras?.season}`, bark.extras?.season === seasonOf(c.sets));
    if (c.leaf) {
      const leaves = gltf.materials.find((m) => m.name === 'leaves');
      const texture = gltf.textures[leaves.pbrMetallicRoughness.baseColorTexture.index];
      check(`${c.name}: leaf texture ${texture.name}`, texture.name === c.leaf);
    }
    const report = await validator.validateBytes(new Uint8Array(bytes), { maxIssues: 20 });
    const images = (report.info?.resources ?? []).filter((r) => r.pointer?.startsWith('/images/'));
    check(`${c.name}: gltf-validator ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`, report.issues.numErrors === 0);
    check(`${c.name}: every embedded texture is at least 512 px (${images.map((r) => `${r.image?.width}x${r.image?.height}`).join(', ')})`,
      images.length === gltf.images.length && images.every((r) => r.image?.width >= 512 && r.image?.height >= 512));
    const scene = await load(bytes);
    const found = {};
    scene.scene.traverse((o) => { if (o.isMesh) found[o.material.name] = o.material; });
    check(`${c.name}: three.js meshes ${Object.keys(found).join(', ')}`, JSON.stringify(Object.keys(found).sort()) === JSON.stringify([...c.parts].sort()));
    check(`${c.name}: three.js bark has map and normalMap`, Boolean(found.bark?.map && found.bark?.normalMap));
    if (found.leaves) check(`${c.name}: three.js leaves alpha-tested with a map`, found.leaves.alphaTest === 0.5 && Boolean(found.leaves.map));
  }

  // The same bytes from the WASM CLI (textures painted in WASM).
  for (const c of [cases[0], cases[4], cases[5], cases[8]]) {  // cases[8]: the azalea's flower texture
    const a = grow(native, c.preset, c.years, c.sets, c.name);
    const b = grow(wasm, c.preset, c.years, c.sets, `${c.name}-w`);
    check(`${c.name}: native and WASM .glb identical (${a.length} bytes)`, a.equals(b));
  }

  // Each flowering species' own flowers (flower_colour, flower_form, terminal_flowers rows):
  // `--season spring` shows the azalea's magenta funnel trusses over its leaves, the weeping
  // cherry's deep pink and Somei-yoshino's pale pink umbels on bare wood.
  for (const [preset, years, colour, form, parts] of [
    ['tsutsuji', 15, 'magenta', 'azalea', ['bark', 'leaves', 'flowers']],
    ['weeping', 20, 'deep-pink', 'cherry', ['bark', 'flowers']],
    ['sakura', 10, 'pale-pink', 'cherry', ['bark', 'flowers']]]) {
    const out = join(dir, `${preset}-spring.glb`);
    run(native, ['tree', 'grow', '--preset', preset, '--years', String(years), '--season', 'spring', '--out', out]);
    const bytes = readFileSync(out);
    const gltf = gltfJson(bytes);
    const names = gltf.materials.map((m) => m.name);
    check(`${preset} --season spring: materials ${names.join(', ')}`, JSON.stringify(names) === JSON.stringify(parts));
    const flowers = gltf.materials.find((m) => m.name === 'flowers');
    check(`${preset} --season spring: flowers ${flowers?.extras?.flower_colour} ${flowers?.extras?.flower_form}`,
      flowers?.extras?.flower_colour === colour && flowers?.extras?.flower_form === form);
    const primitive = gltf.meshes[0].primitives[names.indexOf('flowers')];
    const cards = primitive ? gltf.accessors[primitive.indices].count / 60 : 0;  // 20 triangles a card
    check(`${preset} --season spring: ${cards} flower cards`, cards >= (preset === 'tsutsuji' ? 300 : 100));
    const report = await validator.validateBytes(new Uint8Array(bytes), { maxIssues: 20 });
    check(`${preset} --season spring: gltf-validator ${report.issues.numErrors} errors`, report.issues.numErrors === 0);
  }

  // The season is part of the share link: --url with season=3 gives the bare winter tree.
  {
    const out = join(dir, 'url.glb');
    run(native, ['tree', 'grow', '--url', 'preset=sakura-thesis&seed=1&years=8&season=3', '--out', out]);
    const gltf = gltfJson(readFileSync(out));
    check(`--url ...&season=3: a bare winter tree (${gltf.materials.map((m) => m.name).join(',')})`,
      gltf.materials.map((m) => m.name).join(',') === 'bark' && gltf.materials[0].extras?.season === 'winter');
  }

  // --season and --leaf-shape by name are the rows' values.
  {
    const a = join(dir, 'flag.glb'), b = join(dir, 'set.glb');
    run(native, ['tree', 'grow', '--preset', 'keyaki-thesis', '--years', '4', '--season', 'autumn', '--leaf-shape', 'palmate', '--out', a]);
    run(native, ['tree', 'grow', '--preset', 'keyaki-thesis', '--years', '4', '--set', 'season=2', '--set', 'leaf_shape=2', '--out', b]);
    check('--season autumn --leaf-shape palmate == --set season=2 --set leaf_shape=2', readFileSync(a).equals(readFileSync(b)));
    for (const [flag, value] of [['--season', 'monsoon'], ['--leaf-shape', 'round']]) {
      const out = join(dir, 'bad-flag.glb');
      const r = spawn(native, ['tree', 'grow', '--preset', 'keyaki-thesis', '--years', '2', flag, value, '--out', out]);
      const lines = r.stderr.trim().split('\n');
      check(`${flag} ${value}: exit ${r.status}, "${lines[0]}"`,
        r.status === 2 && lines.length === 1 && lines[0].includes(flag) && lines[0].includes(value) && !existsSync(out));
    }
  }

  // Bad values: one line naming the row and its range, exit 2, no file.
  for (const [set, key] of [['season=4', 'season'], ['season=1.5', 'season'], ['leaf_shape=-1', 'leaf_shape'], ['autumn_colour=9', 'autumn_colour']]) {
    const out = join(dir, 'bad.glb');
    const r = spawn(native, ['tree', 'grow', '--preset', 'sakura-thesis', '--years', '2', '--set', set, '--out', out]);
    const lines = r.stderr.trim().split('\n');
    check(`--set ${set}: exit ${r.status}, "${lines[0]}"`,
      r.status === 2 && lines.length === 1 && lines[0].includes(key) && /in \[0, \d\]/.test(lines[0]) && !existsSync(out));
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
