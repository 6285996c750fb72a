// Runs many CLI cases through niwa_cli_batch (tests/support/cli_batch_main.cpp): one process per job
// instead of one per case, for the WASM and sanitized builds, where a process start costs more than
// a refused case. A case that crashes or hangs ends its process: it is reported as that case's
// result and the job goes on in a new process from the next case.
import { spawn } from 'node:child_process';
import { existsSync, writeFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { cliArgv } from './cli_pair.mjs';

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
// error} and returns the indices it did not reach.
function runProcess(program, argsList, indices, results, file, timeoutMs) {
  return new Promise((resolve) => {
    writeFileSync(file, encode(indices, argsList));
    const [cmd, argv] = cliArgv(program, [file]);
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
        const m = /^(\d+) (-?\d+) (".*")$/.exec(line);
        if (!m || Number(m[1]) !== indices[next]) continue;
        const now = Date.now();
        results[indices[next]] = { status: Number(m[2]), signal: null, stderr: JSON.parse(m[3]), error: null, ms: now - since };
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
// runOnce gives them ({status, signal, stderr, error}). `work` is a folder for the case files.
export async function runBatch(program, argsList, { jobs = 2, timeoutMs = 30000, work }) {
  const results = new Array(argsList.length);
  async function job(j) {
    let left = argsList.map((_, i) => i).filter((i) => i % jobs === j);
    let round = 0;
    while (left.length) left = await runProcess(program, argsList, left, results, join(work, `batch-${j}-${round++}.cases`), timeoutMs);
  }
  await Promise.all(Array.from({ length: jobs }, (_, j) => job(j)));
  return results;
}
