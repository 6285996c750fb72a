// The first tree grow in the page's Web Worker (issue 17 item 7): a fresh Chromium per repetition
// (no V8 module cache, no HTTP code cache), the worker of every page (web/worker/worker.js), and
// the times a user waits for, each measured separately:
//   ready_ms       new Worker() -> 'ready' (fetch, compile and instantiate niwa_web, the table)
//   first_ms       'update' of sakura-thesis 15 years -> its 'tree' message (grow + mesh + copy)
//   first_grow_ms  that grow's own time inside the worker (stats.ms, the sum of its years)
//   second_ms, second_grow_ms   the same for a second grow (seed 2) in the same worker: warm
// node bench/worker_first_grow.mjs [--reps 5] [--warmup on|off|N|both|LIST] [--years 15]
// --warmup off loads the worker as worker.js?warmup=0 (web/worker/tree_handler.js skips its warm-up
// grow), a number N as worker.js?warmup=N (an N-year warm-up), on as worker.js (its default); a
// comma list (both = on,off) alternates them, so a slow spell of this shared machine hits all alike.
// Prints one JSON line per repetition and a summary line of medians per variant.
import { startServer } from '../scripts/serve.mjs';
import { launchChromium } from '../tests/browser/harness.mjs';

const args = { reps: '5', warmup: 'both', years: '15' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args)) {
    console.error('usage: node bench/worker_first_grow.mjs [--reps N] [--warmup on|off|both] [--years N]');
    process.exit(2);
  }
  args[key] = process.argv[i + 1];
}
const reps = Math.max(1, Number(args.reps));
const variants = (args.warmup === 'both' ? 'on,off' : args.warmup).split(',');

async function once(server, warmup) {
  const browser = await launchChromium();
  try {
    const page = await browser.newPage();
    await page.goto(`${server.url}style.css`);  // any same-origin document: the worker is all we time
    return await page.evaluate(async ({ warmup, years }) => {
      const query = warmup === 'on' ? '' : `?warmup=${warmup === 'off' ? 0 : Number(warmup)}`;
      const url = `/web/worker/worker.js${query}`;
      const start = performance.now();
      const worker = new Worker(url, { type: 'module' });
      const reply = (id) => new Promise((resolve) => {
        const on = (e) => {
          const m = e.data || {};
          if (m.id !== id || !['ready', 'tree', 'error'].includes(m.type)) return;
          worker.removeEventListener('message', on);
          resolve(m);
        };
        worker.addEventListener('message', on);
      });
      worker.postMessage({ type: 'init', id: 1, client: 'bench' });
      const ready = await reply(1);
      if (ready.type === 'error') throw new Error(ready.message);
      const readyAt = performance.now();
      const grow = async (id, seed) => {
        const t = performance.now();
        worker.postMessage({ type: 'update', id, client: 'bench', state: { preset: 'sakura-thesis', seed, years } });
        const tree = await reply(id);
        if (tree.type === 'error') throw new Error(tree.message);
        return { ms: performance.now() - t, grow_ms: tree.stats.ms, internodes: tree.stats.internodes };
      };
      const first = await grow(2, 1);
      const second = await grow(3, 2);
      worker.terminate();
      return {
        warmup, ready_ms: readyAt - start, first_ms: first.ms, first_grow_ms: first.grow_ms,
        second_ms: second.ms, second_grow_ms: second.grow_ms, internodes: first.internodes,
      };
    }, { warmup, years: Number(args.years) });
  } finally {
    await browser.close();
  }
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const server = await startServer({ port: 0 });
const rows = [];
try {
  for (let r = 0; r < reps; ++r) {
    for (const warmup of variants) {
      const row = await once(server, warmup);
      rows.push(row);
      console.log(JSON.stringify(row));
    }
  }
} finally {
  await server.close();
}
for (const warmup of variants) {
  const of = rows.filter((r) => r.warmup === warmup);
  const m = (key) => Number(median(of.map((r) => r[key])).toFixed(1));
  console.log(JSON.stringify({
    summary: `warmup ${warmup}, medians of ${of.length}`, ready_ms: m('ready_ms'), first_ms: m('first_ms'),
    first_grow_ms: m('first_grow_ms'), ready_plus_first_ms: Number(median(of.map((r) => r.ready_ms + r.first_ms)).toFixed(1)),
    second_ms: m('second_ms'), second_grow_ms: m('second_grow_ms'),
  }));
}
