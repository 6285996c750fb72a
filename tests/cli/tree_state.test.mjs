// The tree state on the CLI (issue 17 item 6), native and WASM: --url takes a whole link or a bare
// hash, 'tree grow' without an output prints its --stats, 'tree state' writes a state file and
// 'tree grow --state FILE' grows the same tree; bad files are one line and exit 2.
import { mkdtempSync, writeFileSync, readFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { native, wasm, check, run, spawn, buildName, withoutMs, finish } from '../support/cli_pair.mjs';

const dir = mkdtempSync(join(tmpdir(), 'niwa-state-'));
const hash = 'preset=keyaki-thesis&seed=3&years=5&gamma=0.3&wind_speed=12&prune=5:b3&cam=0.6,0.25,10,0,1,0';
const stats = (out) => JSON.stringify(withoutMs(JSON.parse(out)));
const oneLine = (r, pattern) => r.status === 2 && r.stderr.trimEnd().split('\n').length === 1 && pattern.test(r.stderr);

const builds = [native];
if (existsSync(wasm)) builds.push(wasm);
else check(`WASM CLI missing at ${wasm}: build the wasm-release preset first`, false);

for (const bin of builds) {
  const label = buildName(bin);
  const grow = (...args) => run(bin, ['tree', 'grow', ...args]);
  const byHash = stats(grow('--url', hash));
  check(`${label} --url HASH without --stats prints the stats (${byHash.slice(0, 80)}...)`,
    JSON.parse(byHash).internodes > 10 && JSON.parse(byHash).preset === 'keyaki-thesis');
  // Whole links, as Copy link gives them.
  for (const link of [`http://127.0.0.1:8080/#${hash}`, `https://example.org/niwa/index.html#${hash}`,
    `http://example.org/niwa/index.html?x=1#${hash}`, `#${hash}`]) {
    check(`${label} --url ${link.slice(0, 48)}... grows the hash's tree`, stats(grow('--url', link, '--stats')) === byHash);
  }
  let r = spawn(bin, ['tree', 'grow', '--url', `http://127.0.0.1:8080/grove.html#wind_speed=3`]);
  check(`${label} a grove.html link is refused: ${JSON.stringify(r.stderr.trim())}`,
    oneLine(r, /^niwa: error: --url: 'grove\.html' is the grove page, not a tree link; give a link to index\.html/));
  r = spawn(bin, ['tree', 'grow', '--url', 'ftp://host/#preset=sakura']);
  check(`${label} an ftp link is refused`, oneLine(r, /--url: .* must be an http\(s\):\/\/ link or a bare hash/));

  // No output flag: the stats; no options at all: the default tree's stats.
  const bare = spawn(bin, ['tree', 'grow']);
  const bareStats = bare.status === 0 ? JSON.parse(bare.stdout) : {};
  check(`${label} 'tree grow' alone prints the default tree's stats (exit ${bare.status}, preset ${bareStats.preset})`,
    bare.status === 0 && bareStats.preset === 'sakura' && bareStats.internodes > 0 && bare.stderr === '');
  const glb = join(dir, `${label}.glb`);
  const quiet = spawn(bin, ['tree', 'grow', '--preset', 'binary', '--years', '3', '--out', glb]);
  check(`${label} --out alone prints nothing`, quiet.status === 0 && quiet.stdout === '' && existsSync(glb));
  const none = spawn(bin, []);
  check(`${label} 'niwa' with no command prints usage and exits 2 (exit ${none.status})`,
    none.status === 2 && /Usage|usage/.test(none.stdout + none.stderr) && /tree/.test(none.stdout + none.stderr));

  // Link -> state file -> the same tree.
  const file = join(dir, `${label}-state.json`);
  run(bin, ['tree', 'state', '--url', `http://127.0.0.1:8080/#${hash}`, '--out', file]);
  const saved = JSON.parse(readFileSync(file, 'utf8'));
  check(`${label} tree state --url LINK --out writes {preset, seed, years, changed params, prunes, camera}: ${JSON.stringify(saved)}`,
    saved.preset === 'keyaki-thesis' && saved.seed === 3 && saved.years === 5 &&
    JSON.stringify(saved.params) === '{"gamma":0.3,"wind_speed":12}' &&
    JSON.stringify(saved.prunes) === '["5:b3"]' && saved.camera === '0.6,0.25,10,0,1,0');
  check(`${label} tree grow --state FILE grows the link's tree`, stats(grow('--state', file)) === byHash);
  check(`${label} tree state --state FILE prints the same file on stdout`,
    run(bin, ['tree', 'state', '--state', file]) === readFileSync(file, 'utf8'));
  check(`${label} flags go on top of --state`,
    stats(grow('--state', file, '--set', 'gamma=0.31')) === stats(grow('--url', hash.replace('gamma=0.3', 'gamma=0.31'))));
  // A file with some keys: the preset's values for the rest.
  const partial = join(dir, 'partial.json');
  writeFileSync(partial, '{"preset": "tsutsuji-thesis", "years": 4}');
  check(`${label} a partial state file takes the preset's defaults`,
    stats(grow('--state', partial)) === stats(grow('--preset', 'tsutsuji-thesis', '--years', '4')));
  writeFileSync(partial, '{"params": {"gamma": 0.31}, "years": 3}');
  check(`${label} a state file without a preset takes the default preset`,
    stats(grow('--state', partial)) === stats(grow('--years', '3', '--set', 'gamma=0.31')));

  // Bad files: one line naming the field, exit 2.
  const bad = [
    ['{"preset": "maple", "colour": "red"}', /--state .*unknown\.json: colour: unknown state key; the keys are preset, seed, years, params, prunes, camera/],
    ['{"years": 101}', /years: 101 is out of range; must be a whole number in \[0, 100\]/],
    ['{"params": {"gama": 1}}', /unknown parameter 'gama'/],
    ['{"years": 3', /malformed JSON/],
    ['{"years": 3, "years": 4}', /years: given twice in one object/],
    ['{"params": {"gust_on": 9, "gust_off": 2}}', /--state: gust_off: 2 must be greater than gust_on \(9\)/],
  ];
  for (const [text, pattern] of bad) {
    const path = join(dir, 'unknown.json');
    writeFileSync(path, text);
    r = spawn(bin, ['tree', 'grow', '--state', path]);
    check(`${label} --state ${text} -> ${JSON.stringify(r.stderr.trim())}`, oneLine(r, pattern) && r.stdout === '');
  }
  const big = join(dir, 'big.json');
  writeFileSync(big, `{"camera": "${' '.repeat(1 << 20)}"}`);
  r = spawn(bin, ['tree', 'grow', '--state', big]);
  check(`${label} a state file over 1 MiB is refused: ${r.stderr.trim()}`, oneLine(r, /--state: '.*big\.json' has \d+ bytes; the limit is 1 MiB/));
  r = spawn(bin, ['tree', 'grow', '--state', join(dir, 'missing.json')]);
  check(`${label} a missing state file: ${r.stderr.trim()}`, oneLine(r, /--state: cannot read/));
  if (label === 'native') {
    r = spawn(bin, ['tree', 'grow', '--state', '/dev/zero']);
    check(`${label} --state /dev/zero: ${r.stderr.trim()}`, oneLine(r, /--state: .*not a regular file|--state: .*/));
  }
  r = spawn(bin, ['tree', 'grow', '--state', file, '--url', hash]);
  check(`${label} --state with --url is refused: ${r.stderr.trim()}`, r.status === 2 && /--state excludes --url|--url excludes --state/.test(r.stderr));
  r = spawn(bin, ['tree', 'state', '--url', hash, '--out', join(dir, 'state.txt')]);
  check(`${label} tree state --out must be .json`, oneLine(r, /--out: '.*state\.txt' must end in \.json/) && !existsSync(join(dir, 'state.txt')));
}
finish();
