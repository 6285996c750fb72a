// Garden CLI (issue 33 items 4, 8): native == WASM bytes of `niwa garden grow --stats` (timings
// aside), its .glb, 16-bit heightmap and plan .svg, and of `niwa garden plant`; the stats' counts
// (trees by species, distinct trees, refusals by rule adding up to the darts); the link a grow
// prints regrows the same garden; a heightmap ground and a mask read from files named beside the
// garden file; bark=1 (simulated bark per trunk) native == WASM and gltf-validator clean; bad input (a row out of range, a hand-placed tree in a wall, an unknown species, a
// bad heightmap) one line naming the field, exit 2, nothing written.
import { mkdtempSync, readFileSync, writeFileSync, existsSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { buildName, check, finish, native, requireWasm, root, spawn, wasm, withoutMs } from '../support/cli_pair.mjs';
import { gray16PngBytes, pngBytes } from '../support/png_bytes.mjs';

requireWasm();
const work = mkdtempSync(join(tmpdir(), 'niwa-garden-'));
const small = ['--set', 'size=20', '--set', 'ground_res=32', '--set', 'density=0.03', '--set', 'spacing=2',
  '--set', 'max_triangles=2000', '--years', '3'];

// 1. grow: native == WASM bytes (with shapes 1: the shaded trees of a variant drawn with one shared
// shape each, turned and scaled per tree).
const got = {};
for (const cmd of [native, wasm]) {
  const dir = join(work, buildName(cmd));
  spawn('mkdir', ['-p', dir]);
  const r = spawn(cmd, ['garden', 'grow', ...small, '--set', 'shapes=1', '--stats', '--out', join(dir, 'g.glb'), '--heightmap', join(dir, 'h.png'),
    '--svg', join(dir, 'plan.svg')]);
  check(`grow ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr);
  got[buildName(cmd)] = { stats: r.status === 0 ? withoutMs(JSON.parse(r.stdout)) : {}, dir };
}
const a = got.native, b = got.wasm;
check('grow --stats native == WASM (timings aside)', JSON.stringify(a.stats) === JSON.stringify(b.stats),
  `${JSON.stringify(a.stats)}\n${JSON.stringify(b.stats)}`);
for (const name of ['g.glb', 'h.png', 'plan.svg']) {
  const x = readFileSync(join(a.dir, name)), y = readFileSync(join(b.dir, name));
  check(`${name}: native == WASM bytes (${x.length})`, x.length > 0 && x.equals(y));
}
const s = a.stats;
{
  // The .glb's trees: every planted tree an instance, on fewer meshes than distinct trees.
  const glb = readFileSync(join(a.dir, 'g.glb'));
  const doc = JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString('utf8'));
  const treeNodes = doc.nodes.filter((n) => n.extensions?.EXT_mesh_gpu_instancing);
  const instances = treeNodes.reduce((p, n) => p + doc.accessors[n.extensions.EXT_mesh_gpu_instancing.attributes.TRANSLATION].count, 0);
  check('shapes 1: every tree drawn, on fewer meshes than distinct trees (shared shapes, some scaled)',
    instances === s.trees?.count && treeNodes.length < s.trees.distinct
      && treeNodes.some((n) => n.extensions.EXT_mesh_gpu_instancing.attributes.SCALE !== undefined),
    `${treeNodes.length} meshes for ${s.trees?.distinct} distinct trees, ${instances} instances of ${s.trees?.count} trees`);
}
const bySpecies = Object.values(s.trees?.by_species ?? {}).reduce((p, q) => p + q, 0);
check('stats: trees by species add up to the count; hand + rule = count', bySpecies === s.trees?.count
  && s.planting.by_hand + s.planting.by_rule === s.trees.count && s.trees.count > 3, JSON.stringify(s.trees));
const refused = Object.values(s.planting?.refused ?? {}).reduce((p, q) => p + q, 0);
check('stats: every dart kept or refused by one rule', s.planting.candidates === s.planting.by_rule + refused, JSON.stringify(s.planting));
check('stats: the clock ran the garden years, internodes grown', s.years === 3 && s.trees.internodes > 0, `${s.years} ${s.trees.internodes}`);
const m = s.moss ?? {};
check('stats: the moss grew years × moss_days (3 × 10) days over the ground and the objects, under the leaves',
  m.days === 30 && m.cells > 1000 && m.canopy?.spheres > 0 && m.ground_open?.area_m2 > 100
  && Object.values(m.by_region ?? {}).reduce((p, q) => p + q, 0) === m.mosses, JSON.stringify(m).slice(0, 400));
const h = readFileSync(join(a.dir, 'h.png'));
check('heightmap: 16-bit grey PNG of ground_res + 1 samples a side', h.readUInt32BE(16) === 33 && h.readUInt32BE(20) === 33 && h[24] === 16 && h[25] === 0,
  `${h.readUInt32BE(16)} x ${h.readUInt32BE(20)}, depth ${h[24]}, colour ${h[25]}`);
const svg = readFileSync(join(a.dir, 'plan.svg'), 'utf8');
check('plan: one circle a tree, one rect an object', (svg.match(/class="tree"/g) || []).length === s.trees.count
  && (svg.match(/class="object"/g) || []).length === s.objects, `${(svg.match(/class="tree"/g) || []).length} trees`);

// 1a. The garden's wind (the page's Blow): --wind-time sways the grown trees in the state's wind
// (--set wind.wind_dir=180: towards −x, the front entering at the east edge); native == WASM bytes
// of the whole output (each tree's sway after 2 s), the wind row in the link, and 2 s after the
// front entered the 20 m garden the trees east of x = +2 sway while those west of x = −2 are at rest.
const windArgs = ['garden', 'grow', ...small, '--wind-time', '2', '--set', 'wind.wind_dir=180'];
const winds = [native, wasm].map((cmd) => spawn(cmd, windArgs));
check('grow --wind-time: exit 0 both', winds.every((r) => r.status === 0), winds.map((r) => r.stderr).join(''));
check('grow --wind-time: native == WASM bytes (every tree\'s sway)', winds[0].stdout === winds[1].stdout && winds[0].stdout.length > 0);
{
  const w = winds[0].status === 0 ? JSON.parse(winds[0].stdout) : {};
  const trees = w.wind?.trees ?? [];
  const east = trees.filter((t) => t.x > 2), west = trees.filter((t) => t.x < -2);
  check('grow --wind-time: every tree, the east ones swaying, the west ones at rest, the row in the link',
    trees.length === w.trees && Math.abs(w.wind.time - 2) < 1e-9 && east.length > 0 && west.length > 0
      && east.every((t) => t.sway > 1e-3) && west.every((t) => t.sway < 1e-6) && /(^|&)wind\.wind_dir=180(&|$)/.test(w.hash),
    `${trees.length} of ${w.trees} trees; east ${east.map((t) => t.sway.toFixed(4)).join(' ')}; west ${west.map((t) => t.sway.toExponential(1)).join(' ')}; ${w.hash}`);
}

// 2. plant: native == WASM, fast path (no growth).
const plants = [native, wasm].map((cmd) => spawn(cmd, ['garden', 'plant', ...small]));
check('plant: exit 0 both', plants.every((r) => r.status === 0), plants.map((r) => r.stderr).join(''));
check('plant: native == WASM bytes', plants[0].stdout === plants[1].stdout && plants[0].stdout.length > 0);
const planted = JSON.parse(plants[0].stdout);
check('plant: the same trees the grow placed', planted.trees.length === s.trees.count, `${planted.trees.length}`);

// The ivy grows on the clock (ivy_steps a year on that year's trunks): its internodes after each
// year rise, and a garden grown to 2 years has year 2's ivy of the 3-year garden.
const byYear = s.ivy?.internodes_by_year ?? [];
const two = spawn(native, ['garden', 'grow', ...small.slice(0, -1), '2', '--stats']);  // --years 2
const twoIvy = two.status === 0 ? JSON.parse(two.stdout).ivy?.internodes : -1;
check('stats: the ivy grew year by year (internodes_by_year rising, the last the ivy\'s; year 2 the 2-year garden\'s)',
  byYear.length === 3 && byYear[0] > 0 && byYear[0] < byYear[1] && byYear[1] < byYear[2] && byYear[2] === s.ivy.internodes
  && twoIvy === byYear[1], `${JSON.stringify(byYear)}; 2 years: ${twoIvy}`);

// 3. The link a grow prints regrows the same garden.
const plain = spawn(native, ['garden', 'grow', ...small]);
check('grow without --stats: exit 0, a hash', plain.status === 0 && JSON.parse(plain.stdout).hash?.length > 0, plain.stderr);
const hash = JSON.parse(plain.stdout).hash;
const relinked = spawn(native, ['garden', 'grow', '--url', `http://127.0.0.1:8080/garden.html#${hash}`, '--stats']);
check('--url of that hash: the same stats', relinked.status === 0
  && JSON.stringify(withoutMs(JSON.parse(relinked.stdout))) === JSON.stringify(s), relinked.stderr);

// 4. Files beside the garden file: a heightmap ground and a mask.
writeFileSync(join(work, 'ramp.png'), gray16PngBytes(16, 16, (x) => Math.round((x / 15) * 65535)));
writeFileSync(join(work, 'slope.json'), JSON.stringify({ params: { relief: 4, size: 20, ground_res: 16, years: 1, density: 0 },
  ground: { kind: 'heightmap', file: 'ramp.png' }, objects: [], plants: [{ species: 'keyaki', pos: [9, 0] }, { species: 'keyaki', pos: [-9, 0] }] }));
const ramp = spawn(native, ['garden', 'plant', '--garden', join(work, 'slope.json')]);
check('heightmap ground: read beside the garden file, exit 0', ramp.status === 0, ramp.stderr);
if (ramp.status === 0) {
  const t = JSON.parse(ramp.stdout).trees;
  // x = ±9 of a 20 m ramp 0..4 m west to east: 0.2 and 3.8 m.
  check('heightmap ground: the ramp rises west to east to the relief', Math.abs(t[0].pos[1] - 3.8) < 0.02 && Math.abs(t[1].pos[1] - 0.2) < 0.02,
    `${t[0].pos[1]} ${t[1].pos[1]}`);
}

// A mesh ground: the same ramp as an OBJ beside the garden file (its plan's square stretched over
// the garden, its surface from above scaled to the relief, as a heightmap is).
writeFileSync(join(work, 'ramp.obj'), 'v -10 0 -10\nv 10 2 -10\nv 10 2 10\nv -10 0 10\nf 1 3 2\nf 1 4 3\n');
writeFileSync(join(work, 'meshramp.json'), JSON.stringify({ params: { relief: 4, size: 20, ground_res: 16, years: 1, density: 0 },
  ground: { kind: 'mesh', file: 'ramp.obj' }, objects: [], plants: [{ species: 'keyaki', pos: [9, 0] }, { species: 'keyaki', pos: [-9, 0] }] }));
const meshRamp = spawn(native, ['garden', 'plant', '--garden', join(work, 'meshramp.json')]);
check('mesh ground: an OBJ read beside the garden file, exit 0', meshRamp.status === 0, meshRamp.stderr);
if (meshRamp.status === 0) {
  const t = JSON.parse(meshRamp.stdout).trees;
  check('mesh ground: the OBJ ramp rises west to east to the relief', Math.abs(t[0].pos[1] - 3.8) < 0.02 && Math.abs(t[1].pos[1] - 0.2) < 0.02,
    `${t[0].pos[1]} ${t[1].pos[1]}`);
}
// Real assets as the ground: tests/data/meshes/rock1.glb (ez-tree's scanned rock, Draco-compressed: a
// mound seen from above) natively, where Draco is decoded; the WASM CLI names the field and Draco
// (the page decodes Draco before handing a mesh over). The Stanford bunny (bunny.obj) natively and in
// WASM: the same stats and the same .glb.
writeFileSync(join(work, 'rock1.glb'), readFileSync(join(root, 'tests/data/meshes/rock1.glb')));
writeFileSync(join(work, 'bunny.obj'), readFileSync(join(root, 'tests/data/meshes/bunny.obj')));
const meshGround = (file) => JSON.stringify({ params: { relief: 3, size: 16, ground_res: 24, years: 2, density: 0.02,
  spacing: 2, slope_max: 90, moss_days: 2, max_triangles: 1500 }, ground: { kind: 'mesh', file }, objects: [], plants: [] });
writeFileSync(join(work, 'rockground.json'), meshGround('rock1.glb'));
writeFileSync(join(work, 'bunnyground.json'), meshGround('bunny.obj'));
const rock = spawn(native, ['garden', 'grow', '--garden', join(work, 'rockground.json'), '--stats']);
const rockStats = rock.status === 0 ? JSON.parse(rock.stdout) : {};
check('mesh ground rock1.glb (Draco) native: the ground is the mesh, at the relief, and trees stand on it',
  rock.status === 0 && /^mesh rock1\.glb \(1,756 triangles\)/.test(rockStats.ground?.source ?? '')
  && Math.abs((rockStats.ground?.relief ?? 0) - 3) < 1e-9 && (rockStats.trees?.count ?? 0) > 0, `${rock.stderr} ${JSON.stringify(rockStats.ground)}`);
const rockWasm = spawn(wasm, ['garden', 'grow', '--garden', join(work, 'rockground.json'), '--stats']);
check('mesh ground rock1.glb (Draco) WASM CLI: exit 2, one line naming ground.file and Draco', rockWasm.status === 2
  && /^niwa: error: .*ground\.file: rock1\.glb: .*Draco/.test(rockWasm.stderr) && rockWasm.stderr.trim().split('\n').length === 1, rockWasm.stderr);
const bunny = {};
for (const cmd of [native, wasm]) {
  const out = join(work, `bunny-${buildName(cmd)}.glb`);
  const r = spawn(cmd, ['garden', 'grow', '--garden', join(work, 'bunnyground.json'), '--stats', '--out', out]);
  check(`mesh ground bunny.obj ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr);
  bunny[buildName(cmd)] = r.status === 0 ? { stats: withoutMs(JSON.parse(r.stdout)), glb: readFileSync(out) } : { stats: {}, glb: Buffer.alloc(0) };
}
check('mesh ground bunny.obj: native == WASM stats and .glb bytes', JSON.stringify(bunny.native.stats) === JSON.stringify(bunny.wasm.stats)
  && bunny.native.glb.length > 0 && bunny.native.glb.equals(bunny.wasm.glb), JSON.stringify(bunny.native.stats.ground));

// A dropped mesh as an object (the bunny, 0.4 of its 9.9 units, turned 30°), ivy on it: it stands on
// the ground, the rules plant none inside it, the ivy climbs it, natively == WASM.
writeFileSync(join(work, 'bunnyobject.json'), JSON.stringify({ params: { size: 20, ground_res: 32, years: 2, density: 0.05, spacing: 1.5,
  slope_max: 90, moss_days: 2, max_triangles: 1500 }, objects: [{ kind: 'mesh', file: 'bunny.obj', pos: [2, 1], rot: 30, scale: 0.4 }],
  plants: [], ivy: { on: ['objects[0]'] } }));
const bunnyObject = {};
for (const cmd of [native, wasm]) {
  const out = join(work, `bunnyobject-${buildName(cmd)}.glb`);
  const r = spawn(cmd, ['garden', 'grow', '--garden', join(work, 'bunnyobject.json'), '--stats', '--out', out]);
  check(`mesh object bunny.obj ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr);
  bunnyObject[buildName(cmd)] = r.status === 0 ? { stats: withoutMs(JSON.parse(r.stdout)), glb: readFileSync(out) } : { stats: {}, glb: Buffer.alloc(0) };
}
const bo = bunnyObject.native.stats;
check('mesh object: one object, trees refused inside it, the ivy climbs it', bo.objects === 1 && (bo.planting?.refused?.object ?? 0) >= 1
  && (bo.ivy?.internodes ?? 0) > 100, JSON.stringify({ objects: bo.objects, planting: bo.planting, ivy: bo.ivy }));
check('mesh object: native == WASM stats and .glb bytes', JSON.stringify(bo) === JSON.stringify(bunnyObject.wasm.stats)
  && bunnyObject.native.glb.length > 0 && bunnyObject.native.glb.equals(bunnyObject.wasm.glb));

const maskRgba = new Uint8Array(8 * 8 * 4).fill(255);
for (let y = 0; y < 8; ++y) for (let x = 0; x < 4; ++x) maskRgba.fill(0, 4 * (8 * y + x), 4 * (8 * y + x) + 3);
writeFileSync(join(work, 'east.png'), pngBytes(8, 8, maskRgba));
writeFileSync(join(work, 'masked.json'), JSON.stringify({ params: { size: 20, ground_res: 16, density: 0.05, spacing: 1.5, slope_max: 90 },
  mask: 'east.png', plants: [] }));
const masked = spawn(native, ['garden', 'plant', '--garden', join(work, 'masked.json')]);
check('mask: read beside the garden file, exit 0', masked.status === 0, masked.stderr);
if (masked.status === 0) {
  const m = JSON.parse(masked.stdout);
  check('mask: no tree on its black west half, some refused by it', m.trees.length > 5 && m.trees.every((t) => t.pos[0] >= 0)
    && m.report.refused.mask > 0, JSON.stringify(m.report));
}

// 5. bark=1: each distinct tree's simulated bark (the hand keyaki of the default layout, planted at
// 5 years) in the .glb: native == WASM bytes and stats, gltf-validator clean (0 errors, 0
// warnings), the tree's "bark" material with base colour, normal and occlusion maps that are not
// bark 0's; bark 0's file has none.
{
  const require = createRequire(join(root, 'package.json'));
  const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
  const validator = validatorModule.default ?? validatorModule;
  const barkArgs = [...small, '--set', 'density=0', '--set', 'bark=1', '--stats'];
  const grown = {};
  for (const cmd of [native, wasm]) {
    const out = join(work, `bark-${buildName(cmd)}.glb`);
    const r = spawn(cmd, ['garden', 'grow', ...barkArgs, '--out', out]);
    check(`bark=1 ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr);
    grown[buildName(cmd)] = { stats: r.status === 0 ? JSON.parse(r.stdout) : {}, glb: existsSync(out) ? readFileSync(out) : Buffer.alloc(0) };
  }
  const n = grown.native, w = grown.wasm;
  check(`bark=1: native == WASM .glb bytes (${n.glb.length}) and stats`, n.glb.length > 0 && n.glb.equals(w.glb)
    && JSON.stringify(withoutMs(n.stats)) === JSON.stringify(withoutMs(w.stats)));
  check('bark=1 --stats: ms_bark beside the other ms fields, one simulated bark of the tallow species (keyaki)',
    typeof n.stats.ms_bark === 'number' && n.stats.bark?.simulated === 1 && n.stats.bark?.species?.tallow === 1
    && n.stats.bark.trees[0].radii_cm.length >= 2, JSON.stringify(n.stats.bark));
  const report = await validator.validateBytes(new Uint8Array(n.glb), { maxIssues: 50 });
  check(`bark=1 .glb: gltf-validator ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`,
    report.issues.numErrors === 0 && report.issues.numWarnings === 0,
    JSON.stringify(report.issues.messages.filter((m) => m.severity <= 1).slice(0, 3)));
  const gltfOf = (glb) => JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString('utf8'));
  const dressed = gltfOf(n.glb).materials.filter((m) => m.name === 'bark'
    && m.pbrMetallicRoughness?.baseColorTexture && m.normalTexture && m.occlusionTexture);
  check('bark=1 .glb: one bark material with base colour, normal and occlusion maps', dressed.length === 1,
    JSON.stringify(gltfOf(n.glb).materials.map((m) => m.name)));
  const plainOut = join(work, 'bark0.glb');
  const plain = spawn(native, ['garden', 'grow', ...small, '--set', 'density=0', '--out', plainOut]);
  const plainDoc = plain.status === 0 ? gltfOf(readFileSync(plainOut)) : { materials: [] };
  check('bark=0 (the default) .glb: a bark material, no occlusion map on any material', plain.status === 0
    && plainDoc.materials.some((m) => m.name === 'bark') && plainDoc.materials.every((m) => !m.occlusionTexture), plain.stderr);
}

// 6. Bad input: one line naming the field, exit 2, nothing written.
writeFileSync(join(work, 'in-wall.json'), JSON.stringify({ plants: [{ species: 'keyaki', pos: [0, -12] }] }));
writeFileSync(join(work, 'oak.json'), JSON.stringify({ plants: [{ species: 'oak', pos: [0, 0] }] }));
writeFileSync(join(work, 'badmap.json'), JSON.stringify({ ground: { kind: 'heightmap', file: 'slope.json' } }));
writeFileSync(join(work, 'badmoss.json'), JSON.stringify({ moss: { params: { photons: -5 } } }));
writeFileSync(join(work, 'badground.json'), JSON.stringify({ ground: { kind: 'mesh', file: 'slope.json' } }));
writeFileSync(join(work, 'noground.json'), JSON.stringify({ ground: { kind: 'mesh' } }));
writeFileSync(join(work, 'nofileobject.json'), JSON.stringify({ objects: [{ kind: 'mesh', pos: [0, 0] }] }));
writeFileSync(join(work, 'badobject.json'), JSON.stringify({ objects: [{ kind: 'mesh', file: 'slope.json', pos: [0, 0] }] }));
const bad = [
  [['--set', 'size=2'], /--set: size/],
  [['--years', '99'], /--years/],
  [['--garden', join(work, 'in-wall.json')], /plants\[0\]\.pos.*objects\[0\] \(wall\)/],
  [['--garden', join(work, 'oak.json')], /plants\[0\]\.species/],
  [['--garden', join(work, 'badmap.json'), '--set', 'ground_res=16'], /ground\.file/],
  [['--url', 'plants=oak:1:0:0:0:0'], /--url: plants/],
  [['--garden', join(work, 'badmoss.json')], /moss.*photons/],
  [['--garden', join(work, 'badground.json')], /ground\.file.*slope\.json/],
  [['--garden', join(work, 'noground.json')], /ground\.file: a mesh ground needs a \.glb, \.gltf or \.obj file/],
  [['--garden', join(work, 'nofileobject.json')], /objects\[0\]\.file: a mesh object needs a \.glb, \.gltf or \.obj file/],
  [['--garden', join(work, 'badobject.json')], /objects\[0\]\.file.*slope\.json/],
  [['--url', 'moss.photons=abc'], /--url: moss\.photons/],
  [['--set', 'bark=1', '--set', 'bark_map_size=300'], /bark_map_size/],
  [['--set', 'bark=1', '--set', 'moss_days=0', '--max-seconds', '2'], /error: bark: the simulated bark of \d+ distinct trees .* set bark 0/],
  [['--max-seconds', '2'], /error: moss_days: the moss: --max-seconds: .* set moss_days 0/],
  [['--set', 'wind.wind_speed=500'], /--set: wind\.wind_speed: .*100/],
  [['--set', 'wind.gust_on=3'], /--set: wind\.gust_on is not a wind row/],
  [['--url', 'wind.gust_off=1'], /--url: wind\.gust_off/],
  [['--set', 'wind.gust_off=1'], /wind\.gust_off: .*gust_on/],
  [['--wind-time', '700'], /--wind-time/],
];
for (const [args, pattern] of bad) {
  for (const cmd of [native, wasm]) {
    const out = join(work, `bad-${buildName(cmd)}.glb`);
    const r = spawn(cmd, ['garden', 'grow', ...args, '--out', out]);
    const lines = r.stderr.trim().split('\n');
    check(`${args.join(' ').replace(work, '')} ${buildName(cmd)}: exit 2, one line naming the field, nothing written`,
      r.status === 2 && lines.length === 1 && pattern.test(lines[0]) && !existsSync(out), `${r.status}: ${r.stderr.trim()}`);
  }
}
finish();
