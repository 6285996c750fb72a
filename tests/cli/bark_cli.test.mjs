// Bark CLI: native == WASM bytes of `niwa bark grow --stats` (without its timing fields) and of the
// four maps and the cycles CSV, for the three species of Table 2 at a small size, seed 1; the maps'
// PNG sizes; `niwa bark layers` (Fig. 7) and `niwa bark calibrate` in both builds; `niwa params bark` / `niwa presets bark` in both builds; bad input one line naming the
// flag, exit 2, nothing written.
import { mkdtempSync, readFileSync, existsSync, readdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { buildName, check, finish, native, requireWasm, root, run, spawn, wasm } from '../support/cli_pair.mjs';
import { mapUpAgreement } from '../support/tangent_frame.mjs';

requireWasm();
const require = createRequire(join(root, 'package.json'));
const validatorModule = await import(pathToFileURL(require.resolve('gltf-validator')).href);
const validator = validatorModule.default ?? validatorModule;

const work = mkdtempSync(join(tmpdir(), 'niwa-bark-'));
const timing = (k) => k.startsWith('ms') || k === 'ns_per_spring_step';
const stats = (text) => Object.fromEntries(Object.entries(JSON.parse(text)).filter(([k]) => !timing(k)));
const pngSize = (bytes) => [bytes.readUInt32BE(16), bytes.readUInt32BE(20), bytes[24]];

for (const species of ['camphor', 'tallow', 'pine']) {
  const outputs = {};
  for (const cmd of [native, wasm]) {
    const dir = join(work, `${species}-${buildName(cmd)}`);
    const files = { out: 'c.png', normal: 'n.png', height: 'h.png', orm: 'o.png', csv: 'cycles.csv' };
    const args = ['bark', 'grow', '--species', species, '--size', '32x16', '--seed', '1', '--set', 'map_size=256', '--stats'];
    for (const [flag, name] of Object.entries(files)) args.push(`--${flag}`, join(dir, name));
    spawn('mkdir', ['-p', dir]);
    const r = spawn(cmd, args);
    check(`${species} ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr);
    outputs[buildName(cmd)] = { stats: r.status === 0 ? stats(r.stdout) : {}, dir, files };
  }
  const a = outputs.native, b = outputs.wasm;
  check(`${species}: --stats native == WASM (timings aside)`, JSON.stringify(a.stats) === JSON.stringify(b.stats),
    `${JSON.stringify(a.stats)}\n${JSON.stringify(b.stats)}`);
  check(`${species}: the stats have every field`, ['nodes', 'springs', 'steps', 'broken_fraction', 'vertical_crack_share', 'regions', 'intercept', 'spacing', 'hash']
    .every((k) => k in a.stats) && a.stats.nodes === 512 && a.stats.broken.diagonal > 0
    && a.stats.spacing.width.lines > 0 && a.stats.spacing.width.mean > 0);
  for (const name of Object.values(a.files)) {
    const x = readFileSync(join(a.dir, name)), y = readFileSync(join(b.dir, name));
    check(`${species} ${name}: native == WASM bytes (${x.length})`, x.length > 0 && x.equals(y));
  }
  const [w, h, depth] = pngSize(readFileSync(join(a.dir, 'h.png')));
  check(`${species}: height map 256 wide, power-of-two tall, 16-bit`, w === 256 && (h & (h - 1)) === 0 && depth === 16, `${w}x${h} ${depth}-bit`);
}

// The 4-layer model (role exchange, peeling, shedding): native == WASM bytes of the stats (timings
// aside), the maps, the cycles CSV and the frames, for two species; a frame a cycle.
for (const species of ['pine', 'tallow']) {
  const got = {};
  for (const cmd of [native, wasm]) {
    const dir = join(work, `four-${species}-${buildName(cmd)}`);
    spawn('mkdir', ['-p', join(dir, 'frames')]);
    const r = spawn(cmd, ['bark', 'grow', '--species', species, '--model', '4layer', '--size', '32x16', '--cycles', '3', '--seed', '2',
      '--set', 'T=0.002', '--set', 'cork=0.1', '--set', 'map_size=256', '--stats', '--out', join(dir, 'c.png'), '--height', join(dir, 'h.png'),
      '--csv', join(dir, 'cycles.csv'), '--frames', join(dir, 'frames')]);
    check(`4layer ${species} ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr);
    got[buildName(cmd)] = { stats: r.status === 0 ? stats(r.stdout) : {}, dir };
  }
  const a = got.native, b = got.wasm;
  check(`4layer ${species}: --stats native == WASM (timings aside)`, JSON.stringify(a.stats) === JSON.stringify(b.stats),
    `${JSON.stringify(a.stats)}\n${JSON.stringify(b.stats)}`);
  check(`4layer ${species}: model, 2 exchanges, exposed S+M1+M2+I = 1, something shed`, a.stats.model === '4layer' && a.stats.exchanges === 2 &&
    Math.abs(a.stats.exposed.S + a.stats.exposed.M1 + a.stats.exposed.M2 + a.stats.exposed.I - 1) < 1e-12 && a.stats.shed.area > 0 &&
    'peeled_fraction' in a.stats, JSON.stringify(a.stats));
  const frames = readdirSync(join(a.dir, 'frames')).sort();
  check(`4layer ${species}: a frame a cycle (${frames.join(' ')})`, frames.join(' ') === 'bark_cycle_001.png bark_cycle_002.png bark_cycle_003.png');
  for (const name of ['c.png', 'h.png', 'cycles.csv', ...frames.map((f) => join('frames', f))]) {
    const x = readFileSync(join(a.dir, name)), y = readFileSync(join(b.dir, name));
    check(`4layer ${species} ${name}: native == WASM bytes (${x.length})`, x.length > 0 && x.equals(y));
  }
}

// Fig. 7's layout (bark layers): native == WASM bytes of the JSON and the CSV; the surface moves out
// by ΔR a cycle and r_I ends at R_o + 3·ΔR.
{
  const got = {};
  for (const cmd of [native, wasm]) {
    const csv = join(work, `fig7-${buildName(cmd)}.csv`);
    got[buildName(cmd)] = { json: run(cmd, ['bark', 'layers', '--cycles', '3', '--csv', csv]), csv: readFileSync(csv) };
  }
  check('bark layers: native == WASM (JSON and CSV)', got.native.json === got.wasm.json && got.native.csv.equals(got.wasm.csv));
  const j = JSON.parse(got.native.json);
  check(`bark layers: r_I ${j.R_o} -> ${j.r_I_end} (3 cycles of 0.021·R_o), 34 rows`,
    Math.abs(j.r_I_end - j.R_o * (1 + 3 * 0.021)) < 1e-9 && j.rows === 34 && Math.abs(j.surface_end - (j.r_I_end + 2)) < 1e-9);
}

// Table 3 beside the paper's (bark table3): native == WASM bytes, the three species with the paper's numbers.
{
  const args = ['bark', 'table3', '--seeds', '1-2', '--size', '16x8'];
  const a = run(native, args), b = run(wasm, args);
  check('bark table3: native == WASM bytes', a === b && a.length > 0);
  const j = JSON.parse(a);
  check('bark table3: camphor, tallow, pine with the paper\'s means and our mean ± sd over 2 seeds',
    j.rows.map((r) => r.species).join() === 'camphor,tallow,pine' && j.rows[1].paper.mean[1] === 3.02 && j.rows[0].paper.max[1] === '>20' &&
    j.rows.every((r) => r.ours.mean_w.mean > 0 && r.ours.mean_w.sd >= 0) && j.seeds.join() === '1,2', a);
  for (const [bad, flag] of [[['--seeds', '5-1'], '--seeds'], [['--seeds', '1-30'], '--seeds'], [['--set', 'kappa1=9'], '--set']]) {
    const r = spawn(native, ['bark', 'table3', '--size', '16x8', ...bad]);
    check(`bark table3 ${bad.join(' ')}: exit 2, one line naming ${flag}`, r.status === 2 && r.stderr.trim().split('\n').length === 1 && r.stderr.startsWith(`niwa: error: ${flag}`), r.stderr.trim());
  }
}

// The calibration (bark calibrate): native == WASM bytes of a small grid, every candidate scored
// against Table 3, the best the lowest; the 4-layer search's peel share; bad input one line naming
// the flag, exit 2.
{
  const args = ['bark', 'calibrate', '--species', 'tallow', '--seeds', '1-1', '--size', '16x16', '--vary', 'dH=0.02:0.05:3'];
  const a = run(native, args), b = run(wasm, args);
  check('bark calibrate: native == WASM bytes', a === b && a.length > 0);
  const j = JSON.parse(a);
  check('bark calibrate: 3 candidates, Table 3 target, the best the lowest score',
    j.candidates.length === 3 && j.target.mean[0] === 1.7 && j.target.max[1] === 3.96 &&
    j.best.score === Math.min(...j.candidates.map((c) => c.score)) && typeof j.meets.means === 'boolean', a);
  const f = ['bark', 'calibrate', '--model', '4layer', '--species', 'pine', '--size', '32x16', '--cycles', '2', '--set', 'T=0.002',
    '--set', 'cork=0.1', '--vary', 'kappa_h=0.03:0.6:2'];
  const c = run(native, f), d = run(wasm, f);
  check('bark calibrate 4layer: native == WASM bytes', c === d && c.length > 0);
  const k = JSON.parse(c);
  check('bark calibrate 4layer: less peeled at the larger kappa_h', k.candidates[0].measures.peeled_share > k.candidates[1].measures.peeled_share, c);
  for (const [bad, flag] of [[['--vary', 'kappa1=1.02'], '--vary'], [['--vary', 'dH=0.02:0.01:3'], '--vary'], [['--vary', 'dH=0.02:0.05:12'], '--vary'],
    [['--seeds', '5-1'], '--seeds'], [['--model', '4layer', '--vary', 'kappa_h=0.1'], '--cycles'], [['--species', 'oak'], '--species'],
    [['--vary', 'dH=0.01:0.05:9', '--vary', 'dR=0.01:0.05:9', '--max-seconds', '1'], '--max-seconds']]) {
    for (const cmd of [native, wasm]) {
      const r = spawn(cmd, ['bark', 'calibrate', '--size', '16x16', '--seeds', '1-1', ...bad]);
      check(`bark calibrate ${bad.join(' ')} ${buildName(cmd)}: exit 2, one line naming ${flag}`,
        r.status === 2 && r.stderr.trim().split('\n').length === 1 && r.stderr.startsWith(`niwa: error: ${flag}`), r.stderr.trim());
    }
  }
}

// The table and presets in both builds.
for (const cmd of [native, wasm]) {
  const table = JSON.parse(run(cmd, ['params', 'bark', '--json']));
  check(`params bark ${buildName(cmd)}: Table 2 rows`, ['E1', 'E2', 'G', 'kappa1', 'kappa2', 'N_R', 'N_H', 'map_size'].every((k) => table.some((r) => r.key === k)));
  const presets = run(cmd, ['presets', 'bark']);
  check(`presets bark ${buildName(cmd)}: camphor, tallow, pine`, /^camphor\t/m.test(presets) && /^tallow\t/m.test(presets) && /^pine\t/m.test(presets));
}

// The trunk segment (--out trunk.glb): native == WASM bytes for both models, gltf-validator clean
// (no errors, no warnings), a cylinder of the grown radius (R_o·(1 + strain.theta)) and height
// in metres, y up, the tile once around (u 0..1) and once along, its three textures the very PNG
// bytes of --normal, --orm and a base-colour --out .png of the same state.
for (const model of ['2layer', '4layer']) {
  const state = ['bark', 'grow', '--species', 'pine', '--model', model, '--size', '32x16', '--seed', '3', '--set', 'map_size=256',
    ...(model === '4layer' ? ['--cycles', '2', '--set', 'T=0.002', '--set', 'cork=0.1'] : [])];
  const got = {};
  for (const cmd of [native, wasm]) {
    const dir = mkdtempSync(join(work, `glb-${model}-${buildName(cmd)}-`));
    const r = spawn(cmd, [...state, '--stats', '--out', join(dir, 'trunk.glb'), '--normal', join(dir, 'n.png'), '--orm', join(dir, 'o.png')]);
    check(`--out trunk.glb ${model} ${buildName(cmd)}: exit 0`, r.status === 0, r.stderr.trim());
    got[buildName(cmd)] = { dir, stats: r.status === 0 ? stats(r.stdout) : {}, glb: r.status === 0 ? readFileSync(join(dir, 'trunk.glb')) : Buffer.alloc(0) };
  }
  const { dir, glb } = got.native;
  check(`--out trunk.glb ${model}: native == WASM bytes (${glb.length})`, glb.length > 0 && glb.equals(got.wasm.glb));
  const report = await validator.validateBytes(new Uint8Array(glb), { maxIssues: 50 });
  check(`trunk.glb ${model}: gltf-validator 0 errors, 0 warnings`, report.issues.numErrors === 0 && report.issues.numWarnings === 0,
    JSON.stringify(report.issues.messages.slice(0, 3)));
  const jsonLength = glb.readUInt32LE(12);
  const json = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const bin = glb.subarray(20 + jsonLength + 8);
  const view = (i) => { const v = json.bufferViews[i]; return bin.subarray(v.byteOffset || 0, (v.byteOffset || 0) + v.byteLength); };
  const prim = json.meshes[0].primitives[0];
  const pos = json.accessors[prim.attributes.POSITION];
  const uv = view(json.accessors[prim.attributes.TEXCOORD_0].bufferView);
  const us = [];
  for (let k = 0; k < uv.length; k += 8) us.push(uv.readFloatLE(k));
  const s = got.native.stats;
  const radius = (s.strain.r_S ?? s.R_o * (1 + s.strain.theta)) / 100;
  check(`trunk.glb ${model}: radius ${radius.toFixed(5)} m (the grown patch's), height ${pos.max[1].toFixed(4)} m, y up, u 0..1 (once around)`,
    Math.abs(pos.max[0] - radius) < 1e-5 && Math.abs(pos.max[2] - radius) < 1e-5 && pos.min[1] === 0 && Math.abs(pos.max[1] - s.H_o * (1 + s.strain.z) / 100) < 1e-5 &&
    Math.min(...us) === 0 && Math.max(...us) === 1 && prim.attributes.TANGENT !== undefined,
    `${JSON.stringify(pos.min)} ${JSON.stringify(pos.max)} u ${Math.min(...us)}..${Math.max(...us)}`);
  const up = mapUpAgreement(json, bin, prim);
  check(`trunk.glb ${model}: cross(N, T) * w runs along -dP/dv (glTF's normal-map +Y) on ${up.agree} of ${up.triangles} triangles`,
    up.triangles > 0 && up.agree === up.triangles);
  const m = json.materials[prim.material];
  const image = (t) => view(json.images[json.textures[t].source].bufferView);
  const base = join(dir, 'c.png');
  spawn(native, [...state, '--out', base]);
  check(`trunk.glb ${model}: baseColor, normal, occlusion and metallicRoughness textures are the maps' PNG bytes, REPEAT`,
    image(m.pbrMetallicRoughness.baseColorTexture.index).equals(readFileSync(base)) &&
    image(m.normalTexture.index).equals(readFileSync(join(dir, 'n.png'))) &&
    image(m.occlusionTexture.index).equals(readFileSync(join(dir, 'o.png'))) &&
    m.pbrMetallicRoughness.metallicRoughnessTexture.index === m.occlusionTexture.index &&
    json.samplers.every((x) => (x.wrapS ?? 10497) === 10497 && (x.wrapT ?? 10497) === 10497));
}
{
  // All or none: a .glb beside an output that cannot be written leaves nothing.
  const dir = mkdtempSync(join(work, 'glb-none-'));
  const r = spawn(native, ['bark', 'grow', '--size', '16x8', '--set', 'map_size=256', '--out', join(dir, 't.glb'), '--csv', join(dir, 'no/such/c.csv')]);
  check('--out t.glb with an unwritable --csv: exit 2, one line, nothing written', r.status === 2 && r.stderr.trim().split('\n').length === 1 && readdirSync(dir).length === 0, r.stderr.trim());
  const bad = spawn(native, ['bark', 'grow', '--size', '16x8', '--out', join(dir, 't.obj')]);
  check('--out t.obj: exit 2, one line naming --out and .png, .glb', bad.status === 2 && /^niwa: error: --out.*\.png.*\.glb/.test(bad.stderr.trim()), bad.stderr.trim());
}

// Bad input: one line naming the flag, exit 2, nothing written.
for (const [args, flag] of [
  [['--size', '33x16'], '--size'],
  [['--size', '32by16'], '--size'],
  [['--species', 'oak'], '--species'],
  [['--model', '3layer'], '--model'],
  [['--frames', '/nonexistent-niwa-folder'], '--frames'],
  [['--set', 'kappa1=2'], '--set'],
  [['--size', '2048x512', '--max-memory', '128M'], '--max-memory'],
  [['--url', 'species=pine&N_R=64&N_R=64'], '--url'],
  [['--threads', '3'], '--threads'],
]) {
  for (const cmd of [native, wasm]) {
    const dir = mkdtempSync(join(work, 'bad-'));
    const r = spawn(cmd, ['bark', 'grow', ...args, '--out', join(dir, 'c.png')]);
    const lines = r.stderr.trim().split('\n');
    check(`bark grow ${args.join(' ')} ${buildName(cmd)}: exit 2, one line naming ${flag}`,
      r.status === 2 && lines.length === 1 && lines[0].startsWith(`niwa: error: ${flag}`) && readdirSync(dir).length === 0, r.stderr.trim());
  }
}
finish();
