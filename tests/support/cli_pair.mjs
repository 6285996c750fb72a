// Shared by the node CLI tests that compare the native and the WASM `niwa`: where both are, a
// PASS/FAIL counter, run/spawn for either build, and the closing "N passed, N failed" line.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';

export const root = process.env.NIWA_ROOT;
export const native = process.env.NIWA_NATIVE;
export const wasm = process.env.NIWA_WASM || join(root, 'build/wasm/bin/niwa.js');

let passed = 0, failed = 0;
// check(name, ok, detail): the browser harness's order (tests/browser/harness.mjs). `ok` must be a
// boolean: a string there (the arguments swapped) is a failure, not a pass.
export function check(what, ok, detail = '') {
  const pass = typeof ok === 'boolean' ? ok : (typeof ok !== 'string' && Boolean(ok));
  if (pass) passed++; else failed++;
  const why = typeof ok === 'string' ? ' — check(name, ok): ok is a string (arguments swapped?)' : '';
  console.log(`${pass ? 'PASS' : 'FAIL'} ${what}${detail ? ` — ${detail}` : ''}${why}`);
}

// Stops the test when the WASM CLI has not been built.
export function requireWasm() {
  if (!existsSync(wasm)) {
    console.log(`FAIL WASM CLI missing at ${wasm}: build the wasm-release preset first`);
    process.exit(1);
  }
}

// [program, argv] for one run of either build. The WASM CLI runs under node with V8's baseline
// compiler only (--liftoff-only): a test run is short, and the optimising tier-up then only burns CPU
// in background threads (a 3-year tree: 0.21-0.38 s against 0.59-0.64 s with tier-up; a 25-year
// tree with a .glb: 3.2 s against 2.6 s, the one kind of run where it loses). WebAssembly has one
// result whichever tier compiles it, so the native == WASM comparisons hold. NIWA_WASM_NODE_FLAGS
// replaces the flag (empty: V8's default tiers). The unit-test binaries keep the default tiers (their
// long loops gain from it: ivy_tests 50 s against 62 s liftoff-only).
const flagsOf = (text) => text.split(' ').filter(Boolean);
// [program, argv] of cmd: a .js build under node with `flags`, a native one as it is.
const argvWith = (flags) => (cmd, args) => (cmd.endsWith('.js') ? ['node', [...flags, cmd, ...args]] : [cmd, args]);
export const cliArgv = argvWith(flagsOf(process.env.NIWA_WASM_NODE_FLAGS ?? '--liftoff-only'));
// A batch process (niwa_cli_batch.js: hundreds of cases in one process, tests/support/cli_batch.mjs)
// keeps V8's default tiers: the same code runs case after case, so the optimising tier pays for itself
// (the hostile suite's 2,970 WASM cases: 87.5 s with --liftoff-only, 30.2 s with the default tiers, at
// load 21). NIWA_WASM_BATCH_NODE_FLAGS replaces it (e.g. --liftoff-only).
export const batchArgv = argvWith(flagsOf(process.env.NIWA_WASM_BATCH_NODE_FLAGS ?? ''));
// stdout of a successful run (throws on a non-zero exit).
export const run = (cmd, args) => execFileSync(...cliArgv(cmd, args), { encoding: 'utf8' });
// {status, stdout, stderr} of any run.
export const spawn = (cmd, args) => spawnSync(...cliArgv(cmd, args), { encoding: 'utf8' });
export const buildName = (cmd) => (cmd.endsWith('.js') ? 'wasm' : 'native');
// A --stats object without its timing fields (ms, ms_*), which differ run to run.
export const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => !k.startsWith('ms')));

export function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}
