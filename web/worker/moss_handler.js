// The moss study's worker handler (Nomura 2010): one MossLab (web/bindings/moss_bindings.cpp) per
// client holds the last run. An 'update' grows the state ({preset, scene, days, seed, params, and
// for scene tree or terrain the land's fields tree, tree_years, terrain, terrain_seed})
// to its days, posting progress after every day (at most every 100 ms), then sends the stats (the
// CLI's `niwa moss grow --stats`, parsed, and its text as statsText), the resolved state and hash,
// the bounds, and buffer groups:
// the land (three vertices per soil cell with its coverage, geology and last day's irradiance,
// T_s, rh_s, theta and best-species fitness), every moss ever alive with its birth and death day
// (the page's day scrubber replays them without a new grow) and the last day's photon points;
// copied once out of the WASM heap into buffers the page gave back ('recycle') where they fit
// (web/worker/transfer.js TransferPool), then transferred, with the reply's bufferCounts.
// Table, presets and hash: the generic tableJson / presetsJson / decodeHash of the compose
// registry (core/compose/studies.cpp, its moss row); the scenes: the moss bindings' mossScenesJson.
// A dropped mesh ('mesh': bytes, Draco already decoded by the page) is read once into the lab and
// answered with 'meshLoaded' ({name, triangles}) or an error naming "mesh"; an update with
// useMesh: true grows on it (MossLab growOnMesh) instead of the state's scene; with meshOf (another
// client's name: the page's A/B view) the client's lab first takes the mesh that client's lab
// read (MossLab shareMesh: the same scene, neither read nor copied again).
// Messages: web/worker/protocol.js.
// An 'export' ({format: glb | json}) answers with the bytes of `niwa moss grow ... --out moss.glb`
// or `--out moss.json` for the last run (MossLab build), transferred, or an error naming "download".
// Does not: load the module, route messages or catch errors (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';
import { TransferPool, closeLabSession, exportLabDownload } from './transfer.js';
import { nextTask } from './next_task.js';

// ctx: {post(msg, transfer), isLatest(client, id)} from the router.
export function createHandler(Module, ctx) {
  const { post, isLatest } = ctx;
  const paramTable = JSON.parse(Module.tableJson('moss'));
  const presets = JSON.parse(Module.presetsJson('moss'));
  const scenes = JSON.parse(Module.mossScenesJson()).scenes;
  const decode = (hash) => JSON.parse(Module.decodeHash('moss', hash, ''));
  const labs = new Map();  // client -> {lab, working, lastPost}
  const returned = new TransferPool();  // the land and moss buffers each client gave back

  function labOf(client) {
    if (!labs.has(client)) {
      const entry = { lab: new Module.MossLab(), working: 0, lastPost: 0 };
      entry.lab.setProgress((stage, done, total) => {
        const now = performance.now();
        if (done !== total && now - entry.lastPost < 100) return;
        entry.lastPost = now;
        post({ type: 'progress', id: entry.working, client, stage, done, total, text: `growing: day ${done} of ${total}` });
      });
      labs.set(client, entry);
    }
    return labs.get(client);
  }

  async function update(msg, client) {
    const { id } = msg;
    const entry = labOf(client);
    await nextTask();  // a newer update that is already queued supersedes this one
    if (!isLatest(client, id)) return;
    entry.working = id;
    if (msg.useMesh === true && typeof msg.meshOf === 'string' && msg.meshOf !== client) {
      const owner = labs.get(msg.meshOf);
      if (!owner) {
        post(errorReply({ field: 'mesh', message: `mesh: no mesh is loaded for client '${msg.meshOf.slice(0, 40)}'` }, id, client));
        return;
      }
      entry.lab.shareMesh(owner.lab);
    }
    post({ type: 'progress', id, client, stage: 'grow', done: 0, total: 0, text: 'starting the run' });
    const t0 = performance.now();
    const stateJson = JSON.stringify(msg.state || {});
    const error = errorOf(msg.useMesh === true ? entry.lab.growOnMesh(stateJson) : entry.lab.grow(stateJson));
    if (error) {
      post(errorReply(error, id, client));
      return;
    }
    const growMs = performance.now() - t0;
    const statsText = entry.lab.statsJson();  // the CLI's bytes (the tests compare them as they are)
    const stats = JSON.parse(statsText);
    const transfer = [];
    const counts = { reused: 0, fresh: 0, dropped: 0 };
    const buffers = {};
    for (const group of ['land', 'mosses', 'photons']) buffers[group] = returned.take(client, group, entry.lab.buffers(group), transfer, counts);
    post({
      type: 'moss', id, client, stats, statsText, hash: entry.lab.hash(), state: JSON.parse(entry.lab.stateJson()),
      bounds: JSON.parse(entry.lab.boundsJson()), buffers, bufferCounts: counts, growMs, wallMs: performance.now() - t0,
    }, transfer);
  }

  // A dropped mesh: read into the client's lab (the lab keeps its old mesh when a read fails).
  async function mesh(msg, client) {
    const { id } = msg;
    const name = String(msg.name || 'mesh');
    const entry = labOf(client);
    post({ type: 'progress', id, client, stage: 'mesh', done: 0, total: 0, text: `reading ${name}` });
    await nextTask();
    const error = errorOf(entry.lab.loadMesh(new Uint8Array(msg.bytes || new ArrayBuffer(0)), name));
    if (error) {
      post(errorReply(error, id, client));
      return;
    }
    post({ type: 'meshLoaded', id, client, mesh: JSON.parse(entry.lab.meshJson()) });
  }

  const FORMATS = ['glb', 'json'];
  const exportMoss = (msg, client) => exportLabDownload(labOf(client).lab, FORMATS, msg, client, post);

  // The client went away (web/worker/worker.js 'close'): its lab is deleted and its returned
  // buffers are dropped. Returns what was let go.
  const close = (client) => closeLabSession(labs, returned, client);

  return {
    superseding: ['update'],
    close,
    ready: (msg) => ({ paramTable, presets, scenes, decoded: decode(String(msg.hash || '')) }),
    messages: {
      decode: (msg, client) => post({ type: 'decoded', id: msg.id, client, ...decode(String(msg.hash || '')) }),
      update,
      mesh,
      export: exportMoss,
      recycle: (msg, client) => returned.give(client, msg.buffers),
    },
  };
}
