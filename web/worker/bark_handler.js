// The bark study's worker handler (paper 003, Hirota, Kato, Kaneko): one BarkLab
// (web/bindings/bark_bindings.cpp) per client holds the last run. An 'update' grows the state
// ({species, model, seed, params}): a lattice bigger than PREVIEW first grows as a PREVIEW-sized
// patch with small maps (a 'preview' reply, about a second), then the full lattice; while either
// grows, progress (at most every 100 ms) and a 'frame' of the lattice's triangles as they are (the
// tile animating as it cracks). The full run's reply 'bark': the stats (the CLI's `niwa bark grow
// --stats` without its timing fields), the resolved state and hash, the bounds, the cycles CSV
// (per tenth of a cycle), the tile's triangles with each one's break step (the page's cycle
// scrubber replays them) and the base-colour and normal maps' pixels, copied once out of the WASM
// heap into buffers the page gave back ('recycle') where they fit (web/worker/transfer.js
// TransferPool), and the surface's broken springs as segments ('springs'). 'export' gives a map's
// PNG bytes (format 'png', map base_colour | normal | height | orm), the trunk segment's .glb
// (format 'glb': the bytes of `niwa bark grow --url HASH --out trunk.glb`) or the cycles CSV
// (format 'csv'). 'table3' grows the three species of Table 2 (their
// presets, at the lattice and seed asked) in a lab of its own and answers each one's stats.
// Table, presets and hash: the generic tableJson / presetsJson / decodeHash of the compose
// registry (core/compose/studies.cpp, its bark row). Messages: web/worker/protocol.js.
// Does not: load the module, route messages or catch errors (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';
import { TransferPool, closeLabSession, takeBuffers } from './transfer.js';
import { nextTask } from './next_task.js';

// The preview's lattice (columns around × nodes along) and map width.
export const PREVIEW = { N_R: 64, N_H: 32, map_size: 256 };
const FRAME_MS = 100;

// ctx: {post(msg, transfer), isLatest(client, id)} from the router.
export function createHandler(Module, ctx) {
  const { post, isLatest } = ctx;
  const paramTable = JSON.parse(Module.tableJson('bark'));
  const presets = JSON.parse(Module.presetsJson('bark'));
  const decode = (hash) => JSON.parse(Module.decodeHash('bark', hash, ''));
  const labs = new Map();  // client -> {lab, working, lastPost, phase}
  const returned = new TransferPool();  // the tile and map buffers each client gave back

  function labOf(client) {
    if (!labs.has(client)) {
      const entry = { lab: new Module.BarkLab(), working: 0, lastPost: 0, phase: 'full' };
      entry.lab.setProgress((stage, done, total) => {
        const now = performance.now();
        if (done !== total && now - entry.lastPost < FRAME_MS) return true;
        entry.lastPost = now;
        const what = entry.phase === 'preview' ? 'preview' : stage === 'settle' ? 'settling' : 'growing';
        const percent = total > 0 ? Math.floor((100 * done) / total) : 0;
        post({ type: 'progress', id: entry.working, client, stage, phase: entry.phase, done, total, text: `${what}: step ${done} of ${total} (${percent}%)` });
        const transfer = [];
        const tile = takeBuffers(entry.lab.buffers('tile'), transfer);
        post({ type: 'frame', id: entry.working, client, phase: entry.phase, bounds: JSON.parse(entry.lab.boundsJson()), tile }, transfer);
        return true;
      });
      labs.set(client, entry);
    }
    return labs.get(client);
  }

  // The state's lattice (a row left out: the table's default) is bigger than the preview's
  // (numbers only; a bad value is the full run's error).
  const rows = Array.isArray(paramTable) ? paramTable : paramTable.params || [];
  const defaultOf = (key) => rows.find((r) => r.key === key)?.default;
  function wantsPreview(state) {
    const p = state.params || {};
    const nr = Number(p.N_R ?? defaultOf('N_R')), nh = Number(p.N_H ?? defaultOf('N_H'));
    return Number.isFinite(nr) && Number.isFinite(nh) && nr * nh > PREVIEW.N_R * PREVIEW.N_H;
  }

  async function update(msg, client) {
    const { id } = msg;
    const entry = labOf(client);
    await nextTask();  // a newer update that is already queued supersedes this one
    if (!isLatest(client, id)) return;
    entry.working = id;
    const state = msg.state || {};
    const t0 = performance.now();
    // Refused up front: a state the full run would refuse (over the page's budget) grows no preview
    // either (the preview's smaller lattice alone could fit: 100 cycles ran for minutes).
    const refused = errorOf(entry.lab.check(JSON.stringify(state)));
    if (refused) {
      post(errorReply(refused, id, client));
      return;
    }
    if (wantsPreview(state)) {
      entry.phase = 'preview';
      entry.lastPost = 0;
      post({ type: 'progress', id, client, stage: 'grow', phase: 'preview', done: 0, total: 0, text: 'starting the preview' });
      const preview = { ...state, params: { ...state.params, ...PREVIEW } };
      const error = errorOf(entry.lab.grow(JSON.stringify(preview)));
      if (!error) {
        const transfer = [];
        const buffers = { tile: takeBuffers(entry.lab.buffers('tile'), transfer), maps: takeBuffers(entry.lab.buffers('maps'), transfer) };
        post({ type: 'preview', id, client, stats: JSON.parse(entry.lab.statsJson()), bounds: JSON.parse(entry.lab.boundsJson()), buffers, previewMs: performance.now() - t0 }, transfer);
      }
      await nextTask();  // an edit made while the preview grew supersedes the full run
      if (!isLatest(client, id)) return;
    }
    entry.phase = 'full';
    entry.lastPost = 0;
    post({ type: 'progress', id, client, stage: 'grow', phase: 'full', done: 0, total: 0, text: 'starting the run' });
    const t1 = performance.now();
    const error = errorOf(entry.lab.grow(JSON.stringify(state)));
    if (error) {
      post(errorReply(error, id, client));
      return;
    }
    const growMs = performance.now() - t1;
    const stats = JSON.parse(entry.lab.statsJson());
    const bounds = JSON.parse(entry.lab.boundsJson());  // draws the maps
    const transfer = [];
    const counts = { reused: 0, fresh: 0, dropped: 0 };
    const buffers = {};
    for (const group of ['tile', 'springs', 'maps']) buffers[group] = returned.take(client, group, entry.lab.buffers(group), transfer, counts);
    post({
      type: 'bark', id, client, stats, hash: entry.lab.hash(), state: JSON.parse(entry.lab.stateJson()), bounds,
      csv: entry.lab.cyclesCsv(), buffers, bufferCounts: counts, growMs, wallMs: performance.now() - t0,
    }, transfer);
  }

  // A map's PNG, the trunk's .glb or the cycles CSV of the client's last run.
  function exportBark(msg, client) {
    const { lab } = labOf(client);
    const format = String(msg.format);
    let bytes;
    if (format === 'png') {
      const view = lab.mapPng(String(msg.map || 'base_colour'));
      const error = errorOf(lab.lastError());
      if (error) {
        post(errorReply(error, msg.id, client));
        return;
      }
      bytes = new Uint8Array(view).buffer;
    } else if (format === 'glb') {
      const view = lab.glb();
      const error = errorOf(lab.lastError());
      if (error) {
        post(errorReply(error, msg.id, client));
        return;
      }
      bytes = new Uint8Array(view).buffer;
    } else if (format === 'csv') {
      bytes = new TextEncoder().encode(lab.cyclesCsv()).buffer;
    } else {
      throw new Error(`export: format '${format.slice(0, 20)}' is unknown; must be png, glb or csv`);
    }
    if (bytes.byteLength === 0) throw new Error('export: nothing grown yet');
    post({ type: 'export', id: msg.id, client, format, map: msg.map, bytes }, [bytes]);
  }

  // Table 3: the three species' presets at the lattice and seed asked, one after the other.
  async function table3(msg, client) {
    const key = `${client}#table3`;
    const entry = labOf(key);
    entry.working = msg.id;
    entry.phase = 'table3';
    const rows = [];
    for (const preset of presets) {
      post({ type: 'progress', id: msg.id, client, stage: 'table3', phase: 'table3', done: rows.length, total: presets.length, text: `Table 3: growing ${preset.name}` });
      await nextTask();
      const state = { species: preset.name, seed: Number(msg.seed) || 1, params: { N_R: msg.N_R ?? 128, N_H: msg.N_H ?? 64 } };
      // Only progress from this lab (its frames are not drawn).
      entry.lab.setProgress(() => true);
      const error = errorOf(entry.lab.grow(JSON.stringify(state)));
      if (error) {
        post(errorReply(error, msg.id, client, { control: 'table3' }));
        return;
      }
      rows.push({ species: preset.name, stats: JSON.parse(entry.lab.statsJson()) });
    }
    post({ type: 'table3', id: msg.id, client, rows });
  }

  // The client went away (web/worker/worker.js 'close'): its labs are deleted and its returned
  // buffers are dropped. Returns what was let go.
  const close = (client) => {
    const released = closeLabSession(labs, returned, client);
    const extra = `${client}#table3`;
    if (labs.has(extra)) closeLabSession(labs, returned, extra);
    return released;
  };

  return {
    superseding: ['update'],
    close,
    ready: (msg) => ({ paramTable, presets, decoded: decode(String(msg.hash || '')) }),
    messages: {
      decode: (msg, client) => post({ type: 'decoded', id: msg.id, client, ...decode(String(msg.hash || '')) }),
      update,
      export: exportBark,
      table3,
      recycle: (msg, client) => returned.give(client, msg.buffers),
    },
  };
}
