// Runs many CLI cases through niwa_cli_batch (tests/support/cli_batch_main.cpp): one process per job
// instead of one per case, for the WASM and sanitized builds, where a process start costs more than
// a refused case. A case that crashes or hangs ends its process: it is reported as that case's
// result and the job goes on in a new process from the next case.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, writeFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { batchArgv, cliArgv } from './cli_pair.mjs';

// The batch program beside a CLI (bin/niwa -> bin/niwa_cli_batch, bin/niwa.js -> bin/niwa_cli_batch.js),
// or null when that build has none.
export function batchOf(cli) {
  const program = join(dirname(cli), basename(cli).endsWith('.js') ? 'niwa_cli_batch.js' : 'niwa_cli_batch');
  return existsSync(program) ? program : null;
}

function encode(indices, argsList) {
  const parts = [];
  for (const i of indices) {
    const args = argsList[i];
    parts.push(Buffer.from(`${i} ${args.length}\n`));
    for (const a of args) {
      const bytes = Buffer.from(a, 'utf8');
      parts.push(Buffer.from(`${bytes.length}\n`), bytes, Buffer.from('\n'));
    }
  }
  return Buffer.concat(parts);
}

// One process over `indices` (in order) until it ends; fills results[i] = {status, signal, stderr,
// error} (and stdout with keepStdout) and returns the indices it did not reach.
function runProcess(program, argsList, indices, results, file, timeoutMs, keepStdout) {
  return new Promise((resolve) => {
    writeFileSync(file, encode(indices, argsList));
    const [cmd, argv] = batchArgv(program, keepStdout ? ['--stdout', file] : [file]);
    const child = spawn(cmd, argv, { stdio: ['ignore', 'pipe', 'pipe'] });
    let next = 0;  // position in `indices` of the case running now
    let pending = '';
    let stderr = '';
    let timedOut = false;
    let timer = null;
    let since = Date.now();
    const arm = () => {
      clearTimeout(timer);
      timer = setTimeout(() => { timedOut = true; child.kill('SIGKILL'); }, timeoutMs);
    };
    arm();
    child.stdout.setEncoding('utf8');
    child.stdout.on('data', (chunk) => {
      pending += chunk;
      let nl;
      while ((nl = pending.indexOf('\n')) >= 0) {
        const line = pending.slice(0, nl);
        pending = pending.slice(nl + 1);
        const m = keepStdout ? /^(\d+) (-?\d+) (\[".*"\])$/.exec(line) : /^(\d+) (-?\d+) (".*")$/.exec(line);
        if (!m || Number(m[1]) !== indices[next]) continue;
        const now = Date.now();
        const [stderr, stdout] = keepStdout ? JSON.parse(m[3]) : [JSON.parse(m[3]), undefined];
        results[indices[next]] = { status: Number(m[2]), signal: null, stderr, stdout, error: null, ms: now - since };
        since = now;
        ++next;
        arm();
      }
    });
    child.stderr.setEncoding('utf8');
    child.stderr.on('data', (chunk) => { if (stderr.length < (1 << 20)) stderr += chunk; });
    child.on('close', (status, signal) => {
      clearTimeout(timer);
      if (next < indices.length) {
        // The case running when the process ended: a hang, a crash or a sanitizer's report.
        results[indices[next]] = timedOut
          ? { status: null, signal: 'SIGKILL', stderr, error: { code: 'ETIMEDOUT' } }
          : { status: status === 0 ? 1 : status, signal, stderr: `${stderr} (the batch process ended with ${status} ${signal})`, error: null };
        resolve(indices.slice(next + 1));
      } else {
        if (status !== 0 || stderr) {
          // Every case answered but the process failed at its end (a leak report at exit).
          results[indices[indices.length - 1]] = { status: status === 0 ? 1 : status, signal, stderr: `after the last case: ${stderr}`, error: null };
        }
        resolve([]);
      }
    });
  });
}

// Runs argsList[i] for every i, `jobs` processes at a time (case i in job i % jobs); results[i] as
// runOnce gives them ({status, signal, stderr, error}; with keepStdout, stdout too). `work` is a
// folder for the case files.
export async function runBatch(program, argsList, { jobs = 2, timeoutMs = 30000, work, keepStdout = false }) {
  const results = new Array(argsList.length);
  async function job(j) {
    let left = argsList.map((_, i) => i).filter((i) => i % jobs === j);
    let round = 0;
    while (left.length) {
      left = await runProcess(program, argsList, left, results, join(work, `batch-${j}-${round++}.cases`), timeoutMs, keepStdout);
    }
  }
  await Promise.all(Array.from({ length: jobs }, (_, j) => job(j)));
  return results;
}

// The runs of one CLI that a test prepares ahead (the WASM CLI in the native-against-WASM tests:
// starting niwa.js under node costs about 0.3 CPU s before its work, more than most cases):
// prepare(list) runs the listed cases batched in niwa_cli_batch with their stdout, then run(args) and
// spawn(args) answer as cli_pair.mjs's run and spawn do (stdout of a successful run, throwing
// otherwise; {status, stdout, stderr}) from those results. Every `every`-th prepared case, and any case
// not prepared, runs as one process of the CLI itself when asked for, as a user runs it, so the
// shipped program is still checked on a share of the cases. A case's output files are written when
// prepare runs: its input files must exist by then.
export class PreparedCli {
  constructor(cli, { every = 4, work, jobs = 1 }) {
    this.cli = cli;
    this.program = batchOf(cli);
    this.every = every;
    this.work = work;
    this.jobs = jobs;
    this.results = new Map();  // JSON of the args -> result
    this.seen = 0;             // cases prepared so far, for the every-th choice across calls
    this.batched = 0;
    this.single = 0;
  }

  async prepare(list) {
    const fresh = [];
    for (const args of list) {
      const key = JSON.stringify(args);
      if (this.results.has(key) || fresh.some((a) => JSON.stringify(a) === key)) continue;
      if (this.seen++ % this.every === 0) continue;  // left to one process of the CLI
      fresh.push(args);
    }
    if (!fresh.length) return;
    if (!this.program) throw new Error(`niwa_cli_batch beside ${this.cli} is missing: build it (tests/CMakeLists.txt)`);
    const results = await runBatch(this.program, fresh, { jobs: this.jobs, work: this.work, keepStdout: true, timeoutMs: 120000 });
    fresh.forEach((args, i) => this.results.set(JSON.stringify(args), results[i]));
    this.batched += fresh.length;
  }

  spawn(args) {
    const key = JSON.stringify(args);
    if (this.results.has(key)) {
      const r = this.results.get(key);
      return { status: r.status, signal: r.signal, stdout: r.stdout ?? '', stderr: r.stderr };
    }
    ++this.single;
    return spawnSync(...cliArgv(this.cli, args), { encoding: 'utf8' });
  }

  run(args) {
    const r = this.spawn(args);
    if (r.status !== 0) throw new Error(`${basename(this.cli)} ${args.join(' ')}: exit ${r.status} ${r.signal ?? ''}: ${r.stderr}`);
    return r.stdout;
  }

  // "N batched in niwa_cli_batch.js, M one process each", for the test's log.
  summary() {
    return `${this.batched} batched in ${this.program ? basename(this.program) : 'niwa_cli_batch'}, ${this.single} one process each`;
  }
}
