// What the tree page's main thread does while it loads (issue 32 item 5: "no main-thread task over
// 200 ms during load"): a Chrome trace of one fresh load per rep, from the navigation to the first
// tree's first whole frame (+1 s, as tests/browser/load_tasks.test.mjs), and each task of the page's
// main thread over --min ms of wall time or of main-thread CPU time (`tdur`: on this shared machine a
// task's wall time is mostly waiting for a core), with what took its CPU time: the trace events
// inside it by self wall time (script by function and file, style, layout, parsing, GC) and the
// function that posted it (`src`: e.g. Chrome's autofill, FormControlDidChange).
//   node bench/load_trace.mjs [--reps 1] [--min 30] [--root DIR] [--hash '#...'] [--out FILE]
// --root: serve another checkout's public/, web/ and shaders/ (a `git archive` of a commit, for
// before/after runs) with this checkout's build/wasm; --out: keep the last trace's JSON (with
// the V8 CPU profile samples of every thread); TRACE_EXTRA=1: style and layout invalidations too.
// Prints per load one JSON line {load1 (1-min load average), drawnAt, main_cpu (the main thread's CPU
// over the load), longest_wall, longest_cpu, top (the three tasks of most CPU: "cpu/wall src what"),
// tasks: [{at, wall, cpu, src, what: [[name, self ms]...]}]}.
// Does not: judge the goal (docs/BENCHMARKS.md does, with the machine's load), or warm anything up.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { startServer } from '../scripts/serve.mjs';
import { CHROMIUM_OPTIONS } from '../tests/browser/harness.mjs';

const args = { reps: '1', min: '30', root: '', hash: '', out: '' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args)) {
    console.error("usage: node bench/load_trace.mjs [--reps N] [--min MS] [--root DIR] [--hash '#...'] [--out FILE]");
    process.exit(2);
  }
  args[key] = process.argv[i + 1];
}

// Another checkout's page files: a tiny server of its public/, web/, shaders/ beside this build/wasm.
async function serve() {
  if (!args.root) return startServer({ port: 0 });
  const http = await import('node:http');
  const { resolvePath } = await import('../scripts/serve.mjs');
  const here = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');
  const other = path.resolve(args.root);
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://x');
    let file = resolvePath(url.pathname);
    if (file && !file.startsWith(path.join(here, 'build')) && !file.startsWith(path.join(here, 'node_modules'))) {
      file = path.join(other, path.relative(here, file));
    }
    fs.readFile(file || '/nonexistent', (err, data) => {
      if (err) { res.writeHead(404); res.end(); return; }
      const ext = path.extname(file);
      const type = { '.html': 'text/html', '.css': 'text/css', '.js': 'text/javascript', '.mjs': 'text/javascript',
        '.json': 'application/json', '.wasm': 'application/wasm' }[ext] || 'text/plain';
      res.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-cache', 'Access-Control-Allow-Origin': '*' });
      res.end(data);
    });
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { url: `http://127.0.0.1:${server.address().port}/`, close: () => server.close() };
}

const CATEGORIES = ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'v8.execute', 'blink', 'toplevel',
  'disabled-by-default-v8.cpu_profiler', 'v8',
  // TRACE_EXTRA=1: what invalidated style and layout, with stacks (costs time itself)
  ...(process.env.TRACE_EXTRA ? ['disabled-by-default-devtools.timeline.invalidationTracking', 'disabled-by-default-devtools.timeline.stack'] : [])];

// The page's renderer main thread: the CrRendererMain whose process ran the page's ParseHTML/EvaluateScript.
function mainThread(events) {
  const names = new Map();
  for (const e of events) if (e.ph === 'M' && e.name === 'thread_name') names.set(`${e.pid}:${e.tid}`, e.args.name);
  const counts = new Map();
  for (const e of events) {
    const key = `${e.pid}:${e.tid}`;
    if (names.get(key) !== 'CrRendererMain') continue;
    if (e.name === 'EvaluateScript' || e.name === 'v8.compile' || e.name === 'FunctionCall') counts.set(key, (counts.get(key) || 0) + 1);
  }
  return [...counts.entries()].sort((a, b) => b[1] - a[1])[0]?.[0];
}

// Self time of each event under a task, by a readable name.
function label(e) {
  const d = e.args?.data || {};
  if (e.name === 'FunctionCall') return `js ${d.functionName || '(anon)'} ${(d.url || '').replace(/^.*\/(web|public)\//, '$1/')}:${d.lineNumber ?? ''}`;
  if (e.name === 'EvaluateScript' || e.name === 'v8.evaluateModule') return `${e.name} ${(d.url || '').replace(/^.*\/(web|public)\//, '$1/')}`;
  if (e.name === 'EventDispatch') return `event ${d.type || ''}`;
  if (e.name === 'TimerFire') return 'timer';
  return e.name;
}

function analyse(events, minMs) {
  const key = mainThread(events);
  if (!key) return { tasks: [], error: 'no renderer main thread in the trace' };
  const [pid, tid] = key.split(':').map(Number);
  const own = events.filter((e) => e.pid === pid && e.tid === tid && e.ph === 'X' && typeof e.dur === 'number');
  own.sort((a, b) => a.ts - b.ts || b.dur - a.dur);
  const nav = events.find((e) => e.pid === pid && (e.name === 'navigationStart' || e.name === 'markAsMainFrame'))?.ts
    ?? own[0]?.ts ?? 0;
  const tasks = [];
  // Top-level tasks: 'RunTask' (ThreadControllerImpl::RunTask) not inside another; `src`: the
  // function that posted it (the args of the RunTask event of the same span).
  let end = -1;
  let cpuSum = 0;
  for (const e of own) {
    if (/RunTask/.test(e.name) && tasks.length && e.ts === tasks[tasks.length - 1].e.ts && e.args?.src_func) {
      tasks[tasks.length - 1].src = e.args.src_func;
    }
    if (e.ts < end) continue;
    if (e.name !== 'ThreadControllerImpl::RunTask' && e.name !== 'RunTask') continue;
    end = e.ts + e.dur;
    cpuSum += (e.tdur ?? 0) / 1000;
    tasks.push({ e, kids: [], src: e.args?.src_func || '' });
  }
  let t = 0;
  for (const e of own) {
    while (t < tasks.length && tasks[t].e.ts + tasks[t].e.dur <= e.ts) ++t;
    if (t < tasks.length && e !== tasks[t].e && e.ts >= tasks[t].e.ts) tasks[t].kids.push(e);
  }
  const out = [];
  for (const { e, kids, src } of tasks) {
    const wall = e.dur / 1000, cpu = (e.tdur ?? 0) / 1000;
    if (wall < minMs && cpu < minMs) continue;
    // Self wall time per label (children are nested by ts/dur).
    const self = new Map();
    const stack = [];
    const add = (k, ms) => self.set(k, (self.get(k) || 0) + ms);
    for (const k of kids) {
      while (stack.length && stack[stack.length - 1].ts + stack[stack.length - 1].dur <= k.ts) stack.pop();
      if (stack.length) add(label(stack[stack.length - 1]), -k.dur / 1000);
      add(label(k), k.dur / 1000);
      stack.push(k);
    }
    const what = [...self.entries()].filter(([, ms]) => ms >= 2).sort((a, b) => b[1] - a[1]).slice(0, 8)
      .map(([k, ms]) => [k, Math.round(ms)]);
    out.push({ at: Math.round((e.ts - nav) / 1000), wall: Math.round(wall), cpu: Math.round(cpu), src, what });
  }
  return { tasks: out, cpuSum: Math.round(cpuSum) };
}

const server = await serve();
try {
  for (let rep = 0; rep < Number(args.reps); ++rep) {
    const load1 = os.loadavg()[0];
    const browser = await chromium.launch(CHROMIUM_OPTIONS);
    try {
      const context = await browser.newContext({ viewport: { width: 1100, height: 760 }, deviceScaleFactor: 0.75 });
      const page = await context.newPage();
      await browser.startTracing(page, { categories: CATEGORIES });
      await page.goto(server.url + (args.hash || ''));
      await page.waitForFunction(() => {
        const d = document.documentElement.dataset;
        return d.status === 'error' || (d.status === 'ready' && Number(d.treeSerial) >= 1 && d.drawnTreeSerial === d.treeSerial && d.framePartial === '0');
      }, null, { timeout: 300_000, polling: 100 });
      const drawnAt = Math.round(await page.evaluate(() => performance.now()));
      await page.waitForTimeout(1000);
      const buffer = await browser.stopTracing();
      if (args.out) fs.writeFileSync(args.out, buffer);
      const { traceEvents } = JSON.parse(buffer.toString());
      const { tasks, error, cpuSum } = analyse(traceEvents, Number(args.min));
      const longest = tasks.reduce((m, x) => (x.wall > m.wall ? x : m), { wall: 0, cpu: 0 });
      const busiest = tasks.reduce((m, x) => (x.cpu > m.cpu ? x : m), { wall: 0, cpu: 0 });
      // The three tasks of most CPU: "cpu/wall ms what-took-most".
      const top = [...tasks].sort((a, b) => b.cpu - a.cpu).slice(0, 3)
        .map((x) => `${x.cpu}/${x.wall} ${x.src || ''} ${x.what[0]?.[0] || ''}`.replace(/\s+/g, ' '));
      console.log(JSON.stringify({ rep, load1: Number(load1.toFixed(2)), drawnAt, error, main_cpu: cpuSum,
        longest_wall: longest.wall, longest_cpu: busiest.cpu, top, tasks }));
    } finally {
      await browser.close();
    }
  }
} finally {
  server.close();
}
