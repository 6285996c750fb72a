// The real binaries (native and WASM under node): exit code 2 and one stderr line on bad input, no partial files.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, writeFileSync, readdirSync, chmodSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { cliArgv } from '../support/cli_pair.mjs';

const root = process.env.NIWA_ROOT;
const binaries = [process.env.NIWA_NATIVE, join(root, 'build/wasm/bin/niwa.js')];
let passed = 0, failed = 0;
const check = (ok, what) => { ok ? passed++ : failed++; console.log(`${ok ? 'PASS' : 'FAIL'} ${what}`); };
const dir = mkdtempSync(join(tmpdir(), 'niwa-err-'));
writeFileSync(join(dir, 'bad.json'), '{"alpha_t": 0.5,');
writeFileSync(join(dir, 'range.json'), '{"alpha_t": 5}');
const readonly = join(dir, 'readonly');
writeFileSync(join(dir, 'placeholder'), '');

const cases = [
  [['tree', 'grow', '--preset', 'oak'], /--preset: unknown 'oak', must be one of binary, .*sakura/],
  [['tree', 'grow', '--set', 'alpha_t=2'], /alpha_t: 2 is out of range; must be a number in \[0, 1\]/],
  [['tree', 'grow', '--set', 'wrong=2'], /unknown parameter 'wrong'/],
  [['tree', 'grow', '--years', '101'], /--years: 101 is out of range; must be a whole number in \[0, 100\]/],
  [['tree', 'grow', '--params', join(dir, 'bad.json')], /malformed JSON/],
  [['tree', 'grow', '--params', join(dir, 'range.json')], /alpha_t: 5 is out of range/],
  [['tree', 'grow', '--out', join(dir, 'no/such/dir/t.glb')], /--out: cannot write/],
  [['tree', 'grow', '--url', 'preset=sakura&N_high=1000'], /--url: N_high: clamped to 100/],
  [['fly'], /unknown command 'fly'/],
];
for (const bin of binaries) {
  const label = bin.endsWith('.js') ? 'wasm' : 'native';
  const exec = (args) => spawnSync(...cliArgv(bin, args), { encoding: 'utf8' });
  for (const [args, pattern] of cases) {
    const r = exec(args);
    const lines = r.stderr.trimEnd().split('\n');
    check(r.status === 2 && lines.length === 1 && pattern.test(r.stderr),
      `${label} ${args.join(' ')} -> exit ${r.status}, ${JSON.stringify(r.stderr.trim())}`);
  }
  const help = exec(['tree', 'grow', '--help']);
  check(help.status === 0 && help.stdout.includes('--stats'), `${label} tree grow --help`);
  const left = readdirSync(dir).filter((f) => f.includes('niwa-partial') || f.endsWith('.partial'));
  check(left.length === 0, `${label} left no partial files`);
  const glb = join(dir, `${label}.glb`);
  const ok = exec(['tree', 'grow', '--preset', 'binary', '--years', '4', '--out', glb]);
  check(ok.status === 0 && existsSync(glb), `${label} writes a .glb`);
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
