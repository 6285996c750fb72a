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
else check(false, `WASM CLI missing at ${wasm}: build the wasm-release preset first`);

for (const bin of builds) {
  const label = buildName(bin);
  const grow = (...args) => run(bin, ['tree', 'grow', ...args]);
  const byHash = stats(grow('--url', hash));
  check(JSON.parse(byHash).internodes > 10 && JSON.parse(byHash).preset === 'keyaki-thesis',
    `${label} --url HASH without --stats prints the stats (${byHash.slice(0, 80)}...)`);
  // Whole links, as Copy link gives them.
  for (const link of [`http://127.0.0.1:8080/#${hash}`, `https://example.org/niwa/index.html#${hash}`,
    `http://example.org/niwa/index.html?x=1#${hash}`, `#${hash}`]) {
    check(stats(grow('--url', link, '--stats')) === byHash, `${label} --url ${link.slice(0, 48)}... grows the hash's tree`);
  }
  let r = spawn(bin, ['tree', 'grow', '--url', `http://127.0.0.1:8080/grove.html#wind_speed=3`]);
  check(oneLine(r, /^niwa: error: --url: 'grove\.html' is the grove page, not a tree link; give a link to index\.html/),
    `${label} a grove.html link is refused: ${JSON.stringify(r.stderr.trim())}`);
  r = spawn(bin, ['tree', 'grow', '--url', 'ftp://host/#preset=sakura']);
  check(oneLine(r, /--url: .* must be an http\(s\):\/\/ link or a bare hash/), `${label} an ftp link is refused`);

  // No output flag: the stats; no options at all: the default tree's stats.
  const bare = spawn(bin, ['tree', 'grow']);
  const bareStats = bare.status === 0 ? JSON.parse(bare.stdout) : {};
  check(bare.status === 0 && bareStats.preset === 'sakura' && bareStats.internodes > 0 && bare.stderr === '',
    `${label} 'tree grow' alone prints the default tree's stats (exit ${bare.status}, preset ${bareStats.preset})`);
  const glb = join(dir, `${label}.glb`);
  const quiet = spawn(bin, ['tree', 'grow', '--preset', 'binary', '--years', '3', '--out', glb]);
  check(quiet.status === 0 && quiet.stdout === '' && existsSync(glb), `${label} --out alone prints nothing`);
  const none = spawn(bin, []);
  check(none.status === 2 && /Usage|usage/.test(none.stdout + none.stderr) && /tree/.test(none.stdout + none.stderr),
    `${label} 'niwa' with no command prints usage and exits 2 (exit ${none.status})`);

  // Link -> state file -> the same tree.
  const file = join(dir, `${label}-state.json`);
  run(bin, ['tree', 'state', '--url', `http://127.0.0.1:8080/#${hash}`, '--out', file]);
  const saved = JSON.parse(readFileSync(file, 'utf8'));
  check(saved.preset === 'keyaki-thesis' && saved.seed === 3 && saved.years === 5 &&
    JSON.stringify(saved.params) === '{"gamma":0.3,"wind_speed":12}' &&
    JSON.stringify(saved.prunes) === '["5:b3"]' && saved.camera === '0.6,0.25,10,0,1,0',
    `${label} tree state --url LINK --out writes {preset, seed, years, changed params, prunes, camera}: ${JSON.stringify(saved)}`);
  check(stats(grow('--state', file)) === byHash, `${label} tree grow --state FILE grows the link's tree`);
  check(run(bin, ['tree', 'state', '--state', file]) === readFileSync(file, 'utf8'),
    `${label} tree state --state FILE prints the same file on stdout`);
  check(stats(grow('--state', file, '--set', 'gamma=0.31')) === stats(grow('--url', hash.replace('gamma=0.3', 'gamma=0.31'))),
    `${label} flags go on top of --state`);
  // A file with some keys: the preset's values for the rest.
  const partial = join(dir, 'partial.json');
  writeFileSync(partial, '{"preset": "tsutsuji-thesis", "years": 4}');
  check(stats(grow('--state', partial)) === stats(grow('--preset', 'tsutsuji-thesis', '--years', '4')),
    `${label} a partial state file takes the preset's defaults`);
  writeFileSync(partial, '{"params": {"gamma": 0.31}, "years": 3}');
  check(stats(grow('--state', partial)) === stats(grow('--years', '3', '--set', 'gamma=0.31')),
    `${label} a state file without a preset takes the default preset`);

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
    check(oneLine(r, pattern) && r.stdout === '', `${label} --state ${text} -> ${JSON.stringify(r.stderr.trim())}`);
  }
  const big = join(dir, 'big.json');
  writeFileSync(big, `{"camera": "${' '.repeat(1 << 20)}"}`);
  r = spawn(bin, ['tree', 'grow', '--state', big]);
  check(oneLine(r, /--state: '.*big\.json' has \d+ bytes; the limit is 1 MiB/), `${label} a state file over 1 MiB is refused: ${r.stderr.trim()}`);
  r = spawn(bin, ['tree', 'grow', '--state', join(dir, 'missing.json')]);
  check(oneLine(r, /--state: cannot read/), `${label} a missing state file: ${r.stderr.trim()}`);
  if (label === 'native') {
    r = spawn(bin, ['tree', 'grow', '--state', '/dev/zero']);
    check(oneLine(r, /--state: .*not a regular file|--state: .*/), `${label} --state /dev/zero: ${r.stderr.trim()}`);
  }
  r = spawn(bin, ['tree', 'grow', '--state', file, '--url', hash]);
  check(r.status === 2 && /--state excludes --url|--url excludes --state/.test(r.stderr), `${label} --state with --url is refused: ${r.stderr.trim()}`);
  r = spawn(bin, ['tree', 'state', '--url', hash, '--out', join(dir, 'state.txt')]);
  check(oneLine(r, /--out: '.*state\.txt' must end in \.json/) && !existsSync(join(dir, 'state.txt')), `${label} tree state --out must be .json`);
}
finish();
