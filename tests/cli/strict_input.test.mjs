// Issue 16 on the real binaries, native against WASM under node: the same one-line message and
// exit 2 for the same bad input, input files capped before reading (quickly), planted links never
// followed, several outputs all or none, and the --caption SVG accepted by an XML parser (Python's
// xml.etree, an independent parser).
import { spawnSync } from 'node:child_process';
import { existsSync, lstatSync, mkdtempSync, readFileSync, readdirSync, symlinkSync, writeFileSync, openSync, ftruncateSync, closeSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { check, finish, native, requireWasm, spawn, wasm } from '../support/cli_pair.mjs';

requireWasm();
const dir = mkdtempSync(join(tmpdir(), 'niwa-strict-'));
const big = join(dir, 'big.json');
const fd = openSync(big, 'w');
ftruncateSync(fd, 100 * 1024 * 1024);  // 100 MB, sparse
closeSync(fd);
writeFileSync(join(dir, 'dup.json'), '{"gamma": 0.1, "gamma": 0.2}');
writeFileSync(join(dir, 'both.json'), '{"params": {"gamma": 0.1}, "alpha_t": 0.2}');
writeFileSync(join(dir, 'gust.json'), '{"gust_on": 7, "gust_off": 6.5}');
const grow = ['tree', 'grow', '--preset', 'binary', '--years', '2'];
// Issue 34: contour files without coordinates, with a type that is not a string, a repeated key or deep nesting; a
// --params file whose key is repeated after a nested object.
const contourRule = '; must be {"points": [[x, y], ...]} in metres or a GeoJSON Polygon or LineString';
const contours = {
  'no_coordinates.json': '{"type": "Polygon"}',
  'feature_no_coordinates.json': '{"type": "Feature", "geometry": {"type": "LineString"}}',
  'type_null.json': '{"type": null}',
  'type_number.json': '{"type": 7}',
  'dup_points.json': '{"points": [[0, 0], [100, 0], [0, 100]], "points": [[0, 0], [50, 0], [0, 50]]}',
  'deep.json': `{"type": "Feature", "properties": ${'['.repeat(30000)}${']'.repeat(30000)}}`,
};
for (const [name, text] of Object.entries(contours)) writeFileSync(join(dir, name), text);
writeFileSync(join(dir, 'dup_after_nested.json'), '{"params": {"gamma": 0.1}, "params": {"gamma": 0.2}}');
writeFileSync(join(dir, 'ivy_dup.json'), '{"seed": 1, "params": {"rho_max": 2}, "seed": 2}');
const cases = [
  [[...grow.slice(0, 4), '--years', '0x10'], "--years: '0x10' is not a decimal number; must be a whole number in [0, 100]"],
  [[...grow.slice(0, 4), '--years', ''], '--years: empty; must be a whole number in [0, 100]'],
  [[...grow, '--seed', '-18446744073709551615'], '--seed: -1.8446744073709552e+19 is out of range; must be a whole number in [0, 4294967295]'],
  [['tree', 'sway', '--preset', 'binary', '--wind', '0x1p3'], "--wind: '0x1p3' is not a decimal number; must be a number in [0, 100]"],
  [[...grow, '--stats=yes'], '--stats: is a flag and takes no value; give --stats alone'],
  [[...grow, '--svg-leaves', '2', '--out', join(dir, 'a.svg')], '--svg-leaves: 2 is out of range; must be a whole number in [0, 1]'],
  [[...grow, '--out', ''], '--out: empty; give a value'],
  [[...grow, '--params', ''], '--params: empty; give a value'],
  [[...grow, '--params', '/dev/zero'], "--params: cannot read '/dev/zero': not a regular file"],
  [[...grow, '--params', big], `--params: '${big}' has 104857600 bytes; the limit is 1 MiB`],
  [['terrain', 'grow', '--contour', big], `--contour: '${big}' has 104857600 bytes; the limit is 16 MiB`],
  [[...grow, '--params', join(dir, 'dup.json')], `--params ${join(dir, 'dup.json')}: gamma: given twice in one object`],
  [[...grow, '--params', join(dir, 'both.json')], `--params ${join(dir, 'both.json')}: alpha_t: beside a "params" object; put every parameter inside "params"`],
  [['tree', 'sway', '--preset', 'binary', '--params', join(dir, 'gust.json')], '--params: gust_off: 6.5 must be greater than gust_on (7)'],
  [['tree', 'grow', '--url', `years=1${'0'.repeat(16400)}`], '--url: hash: 16407 characters; the limit is 16384, nothing was read'],
  [['tree', 'grow', '--url', 'seed=1&seed=2'], '--url: seed: given 2 times; must be given once, nothing was read'],
  [['tree', 'render-stats', '--cam', '1e39,0.3,10,0,0,0'], "--cam: '1e39' is not a number; must be yaw,pitch,distance,tx,ty,tz"],
  [['tree', 'render-stats', '--target', '1e39,0,0'], "--target: '1e39,0,0' must be three numbers x,y,z, each in [-10000, 10000] (metres)"],
  [[...grow, '--out', 'a\x1b[31mb.zzz'], "--out: 'a\\x1b[31mb.zzz' must end in .glb, .json or .svg"],
  [[...grow, '--caption', 'a\x07', '--out', join(dir, 'c.svg')], "--caption: 'a\\x07' holds a control character; must be printable text"],
  [['terrain', 'grow', '--contour', join(dir, 'no_coordinates.json')], `--contour: contour: Polygon without coordinates${contourRule}`],
  [['terrain', 'grow', '--contour', join(dir, 'feature_no_coordinates.json')], `--contour: contour: LineString without coordinates${contourRule}`],
  [['terrain', 'grow', '--contour', join(dir, 'type_null.json')], `--contour: contour: type is not a string${contourRule}`],
  [['terrain', 'grow', '--contour', join(dir, 'type_number.json')], `--contour: contour: type is not a string${contourRule}`],
  [['terrain', 'grow', '--contour', join(dir, 'dup_points.json')], '--contour: points: given twice in one object'],
  [['terrain', 'grow', '--contour', join(dir, 'deep.json')], '--contour: contour: nested deeper than 32 levels'],
  [[...grow, '--params', join(dir, 'dup_after_nested.json')], `--params ${join(dir, 'dup_after_nested.json')}: params: given twice in one object`],
  [['ivy', 'grow', '--params', join(dir, 'ivy_dup.json')], '--params: seed: given twice in one object'],
  [['ivy', 'grow', '--steps', '010x'], "--steps: '010x' is not a decimal number; must be a whole number in [0, 10000]"],
];
const byBuild = {};
for (const bin of [native, wasm]) {
  const label = bin.endsWith('.js') ? 'wasm' : 'native';
  byBuild[label] = [];
  for (const [args, expected] of cases) {
    const started = Date.now();
    const r = spawn(bin, args);
    const ms = Date.now() - started;
    const line = r.stderr.trimEnd();
    byBuild[label].push(line);
    check(`${label} ${JSON.stringify(args).slice(0, 90)} -> exit ${r.status}, ${JSON.stringify(line).slice(0, 160)} (${ms} ms)`,
      r.status === 2 && line === `niwa: error: ${expected}` && ms < 5000);
  }
  // Safe writes: a link at the target is replaced, its target untouched; no temporary remains.
  const victim = join(dir, `${label}-victim.txt`), link = join(dir, `${label}-link.json`);
  writeFileSync(victim, 'keep');
  symlinkSync(victim, link);
  const ok = spawn(bin, [...grow, '--out', link]);
  check(`${label} --out over a planted link replaces the link, never writes through it`,
    ok.status === 0 && readFileSync(victim, 'utf8') === 'keep' && lstatSync(link).isFile());
  // Several outputs: all or none.
  const glb = join(dir, `${label}-ok.glb`);
  const partial = spawn(bin, ['tree', 'sway', '--preset', 'binary', '--years', '2', '--duration', '1', '--out', glb, '--csv', join(dir, 'no/such/t.csv')]);
  check(`${label} sway --out ok.glb --csv /bad/t.csv leaves no ok.glb`, partial.status === 2 && !existsSync(glb));
  const name = join(dir, `${'n'.repeat(250 - label.length)}${label}.json`);
  const long = spawn(bin, [...grow, '--out', name]);
  check(`${label} a 255-character file name works`, long.status === 0 && existsSync(name));
  // The caption's SVG parses as XML.
  const svg = join(dir, `${label}-caption.svg`);
  const cap = spawn(bin, [...grow, '--out', svg, '--caption', `P<1 & "q" 'r' caf\u00e9 ]]> <!--`]);
  const xml = spawnSync('python3', ['-c', 'import sys, xml.etree.ElementTree as E; t = E.parse(sys.argv[1]); print([e.text for e in t.iter() if e.tag.endswith("text")][-1])', svg], { encoding: 'utf8' });
  check(`${label} --caption with markup makes SVG an XML parser reads back: ${JSON.stringify(xml.stdout.trim() || xml.stderr.slice(-120))}`,
    cap.status === 0 && xml.status === 0 && xml.stdout.trim() === `P<1 & "q" 'r' caf\u00e9 ]]> <!--`);
  check(`${label} left no temporary file`, readdirSync(dir).every((f) => !f.includes('.partial')));
}
check(`native and WASM give the same ${cases.length} messages`, JSON.stringify(byBuild.native) === JSON.stringify(byBuild.wasm));
finish();
