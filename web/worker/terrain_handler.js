// The terrain study's worker handler (paper 002, Misawa, Chiba, Saito): one TerrainLab
// (web/bindings/terrain_bindings.cpp) per client holds the last mountain, in a core TerrainRun
// that re-does only the stage of the rows an 'update' changed (tint: nothing; res: the heightfield
// from the kept contours; an erosion row: the erosion of the kept heightfield; a grow row or the
// seed: the grow). An 'update' grows the
// state (a built-in seed or a drawn contour, as JSON through core/terrain/terrain_state) and sends
// the stats (the CLI's --stats minus its timings), the resolved state and hash, and the surface
// (without its triangles: the page builds the grid's, web/terrain/grid_indices.js), contour and
// summit buffers (copied once out of the WASM heap, then transferred), with the worker's time per
// step (parts). With `statsAfter` (the page) the mountain goes first, stats null, and the stats
// follow at once in a 'terrainStats' message (computed from the same grow before anything else
// runs), so the surface is not kept waiting for them. 'recycle' hands the page's buffers back
// (the surface once on the GPU, the contours and summits once a newer mountain replaced them):
// the next grow copies into them (pages already touched) instead of fresh ones
// (web/worker/transfer.js TransferPool: per client, dropped when their size class changes or they
// go unused); every group arrives as views of the exact length, with the reply's bufferCounts
// {reused, fresh, dropped}. 'export'
// builds one download (.glb, heightmap .png, its sidecar .json, contours .json/.geojson/.svg);
// 'parseContour' reads an imported contour file's text into points.
// Messages: web/worker/protocol.js.
// Does not: load the module, route messages or catch errors (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';
import { TransferPool, takeBuffers } from './transfer.js';
import { nextTask } from './next_task.js';

// A new task of the worker's loop (not setTimeout(0), which is clamped to 4 ms when nested).
const yieldToEvents = nextTask;
const FORMATS = ['glb', 'heightmap', 'sidecar', 'json', 'geojson', 'svg'];

// ctx: {post(msg, transfer), isLatest(client, id)} from the router.
export function createHandler(Module, ctx) {
  const { post, isLatest } = ctx;
  const paramTable = JSON.parse(Module.tableJson('terrain'));
  const presets = JSON.parse(Module.presetsJson('terrain'));
  const seeds = JSON.parse(Module.terrainSeedsJson());
  const labs = new Map();  // client -> TerrainLab
  const returned = new TransferPool();  // the surface, contour and summit buffers each client returned

  function labOf(client) {
    if (!labs.has(client)) labs.set(client, new Module.TerrainLab());
    return labs.get(client);
  }

  // The surface group's views copied out of the WASM heap into the client's returned buffers where
  // they fit, else into fresh ones sized for the square grid of the longer side (each drawing has
  // its own grid, so sizes differ: any later grid at this res fits).
  function takeSurface(views, bounds, client, transfer, counts) {
    const cells = bounds.width * bounds.height, square = Math.max(bounds.width, bounds.height) ** 2;
    const room = (view) => (cells > 0 ? (view.byteLength / cells) * square : view.byteLength);
    return returned.take(client, 'surface', views, transfer, counts, room);
  }

  async function update(msg, client) {
    const { id } = msg;
    const lab = labOf(client);
    await yieldToEvents();  // a newer update that is already queued supersedes this one
    if (!isLatest(client, id)) return;
    post({ type: 'progress', id, client, stage: 'grow', text: 'growing the contours and the surface' });
    const t0 = performance.now();
    const parts = {};  // the worker's wall time per step (ms): what the page's regrow costs
    const state = { ...(msg.state || {}) };
    let repaired = null;
    let simplified = null;
    if (msg.repair && Array.isArray(state.contour)) {
      const r = JSON.parse(Module.terrainRepairContour(JSON.stringify(state.contour)));
      if (r.ok === false) {
        post(errorReply(r, id, client));
        return;
      }
      if (r.repaired || r.simplified) state.contour = r.points;
      if (r.repaired) repaired = { loopsRemoved: r.loops_removed, method: r.method, reason: r.reason, points: r.points.length };
      // Too long for a link: on a grid and with fewer points (the link must read back).
      if (r.simplified) simplified = { from: r.simplified.from, to: r.simplified.to, quantum: r.simplified.quantum };
    }
    let t = performance.now();
    const lap = (name) => {
      const now = performance.now();
      parts[name] = now - t;
      t = now;
    };
    lap('repair');
    const error = errorOf(lab.grow(JSON.stringify(state)));
    if (error) {
      post(errorReply(error, id, client));
      return;
    }
    lap('grow');
    const statsAfter = Boolean(msg.statsAfter);
    const stats = statsAfter ? null : JSON.parse(lab.statsJson());
    const timings = JSON.parse(lab.timingsJson());
    lap('stats');
    const transfer = [];
    const bounds = JSON.parse(lab.boundsJson());
    const counts = { reused: 0, fresh: 0, dropped: 0 };
    const buffers = { surface: takeSurface(lab.buffers('surface'), bounds, client, transfer, counts) };
    for (const group of ['contours', 'summits']) buffers[group] = returned.take(client, group, lab.buffers(group), transfer, counts);
    lap('copy');
    const reply = {
      type: 'terrain', id, client, stats, timings, buffers, hash: lab.hash(), state: JSON.parse(lab.stateJson()),
      bounds, repaired, simplified, bufferCounts: counts,
    };
    lap('state');
    reply.parts = parts;
    reply.wallMs = performance.now() - t0;
    post(reply, transfer);
    if (!statsAfter) return;
    // The same grow's stats, before this task ends (no other message can regrow the lab).
    const s0 = performance.now();
    const followed = JSON.parse(lab.statsJson());
    post({ type: 'terrainStats', id, client, stats: followed, statsMs: performance.now() - s0 });
  }

  function exportTerrain(msg, client) {
    const format = String(msg.format);
    if (!FORMATS.includes(format)) throw new Error(`export: format '${format.slice(0, 20)}' is unknown; must be ${FORMATS.join(', ')}`);
    const error = errorOf(labOf(client).build(format));
    if (error) {
      post(errorReply(error, msg.id, client));
      return;
    }
    const transfer = [];
    const { bytes } = takeBuffers(labOf(client).buffers('download'), transfer);
    post({ type: 'export', id: msg.id, client, format, bytes }, transfer);
  }

  // The client went away (web/worker/worker.js 'close'): its lab is deleted and its returned
  // buffers are dropped. Returns what was let go.
  function close(client) {
    const lab = labs.get(client);
    lab?.delete();
    labs.delete(client);
    return { sessions: lab ? 1 : 0, buffers: returned.forget(client) };
  }

  return {
    superseding: ['update'],
    close,
    ready: (msg) => ({ paramTable, presets, seeds, decoded: JSON.parse(Module.decodeHash('terrain', String(msg.hash || ''), '')) }),
    messages: {
      decode: (msg, client) => post({ type: 'decoded', id: msg.id, client, ...JSON.parse(Module.decodeHash('terrain', String(msg.hash || ''), '')) }),
      // An imported contour file's text -> {points, elevation?} or {ok: false, field, message}.
      parseContour: (msg, client) => post({ type: 'contourFile', id: msg.id, client, name: String(msg.name || ''), ...JSON.parse(Module.terrainParseContour(String(msg.text || ''))) }),
      update,
      recycle: (msg, client) => returned.give(client, msg.buffers),
      export: exportTerrain,
    },
  };
}
