// The ivy study's worker handler (paper 004): one IvyLab (web/bindings/ivy_bindings.cpp) per
// client holds its support (a built-in scene, or a dropped mesh sent once with 'mesh') and the last
// ivy grown on it. An 'update' loads the state's scene when it changed, grows, and sends the stats
// and the stems, leaves and suckers (with their birth steps, so the page replays the growth
// without regrowing; the leaves with their uvs, and the client's first 'ivy' message with the
// leaf texture's pixels, so the page draws the leaves as the .glb holds them), as views into the
// buffers the client handed back ('recycle', once they are on its GPU) when they fit, else into
// fresh ones (web/worker/transfer.js TransferPool; the support's triangles too); 'pick' casts a ray on the support (a click
// places a seed point); 'export' builds .glb, .json or .lsys. Messages: web/worker/protocol.js.
// Does not: load the module, route messages or catch errors (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';
import { TransferPool, takeBuffers, closeLabSession } from './transfer.js';
import { nextTask } from './next_task.js';

// A new task of the worker's loop (not setTimeout(0), which is clamped to 4 ms when nested).
const yieldToEvents = nextTask;

// ctx: {post(msg, transfer), isLatest(client, id)} from the router.
export function createHandler(Module, ctx) {
  const { post, isLatest } = ctx;
  const paramTable = JSON.parse(Module.tableJson('ivy'));
  const presets = JSON.parse(Module.presetsJson('ivy'));
  const scenes = JSON.parse(Module.ivyScenesJson());
  // The trees ivy can climb (scene 'tree'): the tree study's presets.
  const trees = JSON.parse(Module.presetsJson('tree')).map((p) => ({ name: p.name, title: p.title, years: p.years }));
  const labs = new Map();  // client -> {lab, support: 'scene:<name>' | 'mesh:<name>' | null}
  const returned = new TransferPool();  // the ivy buffers each client handed back
  let leafTextureOnce = null;  // {width, height, pixels}: the .glb's leaf texture, painted once, kept
  // The leaf texture's buffers handed back by any client ('leafTexture.pixels'): the pixels are the
  // same for every client, so the next client's copy goes into one of them (TransferPool client
  // SHARED) instead of a fresh one.
  const SHARED = Symbol('every client');

  // Progress from inside a long call (a big mesh's read and BVH, every growth step): at most one
  // message per 100 ms, for the request the lab is working on (entry.working).
  const STAGE_TEXT = {
    read: (done, total) => `reading the mesh (${(total / 1048576).toFixed(1)} MB)`,
    bvh: (done, total) => `building the BVH of ${total.toLocaleString('en-US')} triangles`,
    tree: (done, total) => `growing the tree: year ${done} of ${total}`,
    bark: (done, total) => `building the tree's bark (${total.toLocaleString('en-US')} internodes)`,
    grow: (done, total) => `growing: step ${done} of ${total}`,
    meshing: (done, total) => `building tubes and leaves for ${total.toLocaleString('en-US')} buds`,
  };
  function labOf(client) {
    if (!labs.has(client)) {
      const entry = { lab: new Module.IvyLab(), support: null, working: 0, lastPost: 0, leafTextureSent: false };
      entry.lab.setProgress((stage, done, total) => {
        const now = performance.now();
        // Every stage's first and last message goes; steps and years in between at most every 100 ms.
        const edge = (stage !== 'grow' && stage !== 'tree') || done <= 1 || done === total;
        if (!edge && now - entry.lastPost < 100) return;
        entry.lastPost = now;
        post({ type: 'progress', id: entry.working, client, stage, done, total, text: STAGE_TEXT[stage]?.(done, total) ?? stage });
      });
      labs.set(client, entry);
    }
    return labs.get(client);
  }

  // Sends the support's description and triangles (once per support change).
  // id: the 'mesh' request it answers; an update's support goes without an id (request: its id), so
  // it reaches the page even when a newer update supersedes that one (the lab keeps the support,
  // and the newer update sends none).
  function sendSupport(id, client, entry, { asReply = true } = {}) {
    const transfer = [];
    const support = JSON.parse(entry.lab.supportJson());
    const bufferCounts = { reused: 0, fresh: 0, dropped: 0 };
    // Into the client's returned 'support.*' buffers where they fit (a scene change reuses them).
    const buffers = returned.take(client, 'support', entry.lab.buffers('support'), transfer, bufferCounts);
    const envelope = asReply ? { id } : { request: id };
    post({ type: 'support', ...envelope, client, support, buffers, bufferCounts, loadMs: entry.loadMs ?? null }, transfer);
  }

  async function update(msg, client) {
    const { id, state } = msg;
    const entry = labOf(client);
    entry.working = id;
    const scene = typeof state?.scene === 'string' && state.scene ? state.scene : 'cubes4';
    // A dropped mesh stays the support until the page asks for a built-in scene (state.scene set
    // and msg.useMesh false).
    const wantMesh = msg.useMesh === true && entry.support?.startsWith('mesh:');
    // scene 'tree': a Niwa tree's bark (tree preset and years of the state), as the CLI's
    // --tree-preset; the same key regrows nothing.
    const tree = scene === 'tree' ? { name: String(state.tree ?? ''), years: Number(state.tree_years) } : null;
    const supportKey = tree ? `tree:${tree.name}:${tree.years}` : `scene:${scene}`;
    if (!wantMesh && entry.support !== supportKey) {
      post({ type: 'progress', id, client, stage: 'scene',
        text: tree ? `growing the ${tree.name} tree (${tree.years} years) to climb` : `loading scene ${scene}` });
      if (tree) await yieldToEvents();
      const t0 = performance.now();
      const error = errorOf(tree ? entry.lab.loadTree(tree.name, tree.years) : entry.lab.loadScene(scene));
      entry.loadMs = performance.now() - t0;
      if (error) {
        post(errorReply(error, id, client));
        return;
      }
      entry.support = supportKey;
      sendSupport(id, client, entry, { asReply: false });
    }
    const grown = { ...state };
    if (wantMesh) delete grown.scene;  // the dropped mesh is not a built-in scene
    await yieldToEvents();
    if (!isLatest(client, id)) return;
    post({ type: 'progress', id, client, stage: 'grow', text: 'growing' });
    const t0 = performance.now();
    const error = errorOf(entry.lab.grow(JSON.stringify(grown)));
    if (error) {
      post(errorReply(error, id, client));
      return;
    }
    // The statistics re-measure the ivy against the support (brute force): seconds on a big one,
    // so the progress line says so instead of keeping the last growth step.
    post({ type: 'progress', id, client, stage: 'measure', text: 'measuring the ivy (statistics)' });
    const stats = JSON.parse(entry.lab.statsJson());
    const transfer = [];
    const mesh = {};
    const buffers = { reused: 0, fresh: 0 };
    for (const part of ['stems', 'leaves', 'suckers', 'buds']) mesh[part] = returned.take(client, part, entry.lab.buffers(part), transfer, buffers);
    // The leaf texture (the .glb's pixels), once per client: painted and copied out of the heap
    // by the binding once per worker, then copied into a buffer a client handed back once it
    // uploaded its texture (any client's: the pixels are the same), else a fresh one, and
    // transferred. leafTextureBuffers: {reused, fresh} of that copy.
    let leafTexture, leafTextureBuffers;
    if (!entry.leafTextureSent) {
      leafTextureOnce ??= Module.ivyLeafTexture();  // painted once per worker (about 30-50 ms)
      leafTextureBuffers = { reused: 0, fresh: 0, dropped: 0 };
      const { pixels } = returned.take(SHARED, 'leafTexture', { pixels: leafTextureOnce.pixels }, transfer, leafTextureBuffers,
        (view) => view.byteLength);
      leafTexture = { width: leafTextureOnce.width, height: leafTextureOnce.height, pixels };
      entry.leafTextureSent = true;
    }
    post({ type: 'ivy', id, client, stats, mesh, leafTexture, leafTextureBuffers, steps: entry.lab.steps(), hash: entry.lab.hash(),
      wallMs: performance.now() - t0, buffers }, transfer);
  }

  // A dropped mesh (bytes, Draco already decoded by the page): becomes the client's support.
  async function mesh(msg, client) {
    const { id, name } = msg;
    const entry = labOf(client);
    entry.working = id;
    post({ type: 'progress', id, client, stage: 'mesh', text: `reading ${name} and building its BVH` });
    await yieldToEvents();
    const t0 = performance.now();
    const error = errorOf(entry.lab.loadMesh(new Uint8Array(msg.bytes), String(name)));
    entry.loadMs = performance.now() - t0;
    if (error) {  // the lab keeps its old support when a read fails
      post(errorReply(error, id, client));
      return;
    }
    entry.support = `mesh:${name}`;
    sendSupport(id, client, entry);
  }

  function pick(msg, client) {
    const [ox, oy, oz] = msg.origin, [dx, dy, dz] = msg.direction;
    const hit = JSON.parse(labOf(client).lab.rayCast(ox, oy, oz, dx, dy, dz));
    post({ type: 'picked', id: msg.id, client, hit });
  }

  function exportIvy(msg, client) {
    const { lab } = labOf(client);
    const refused = errorOf(lab.exportCheck(String(msg.format), Boolean(msg.withSupport)));  // the page budget
    if (refused) {
      post(errorReply(refused, msg.id, client));
      return;
    }
    const text = (s) => new TextEncoder().encode(s).buffer;
    let bytes;
    if (msg.format === 'glb') {
      const error = errorOf(lab.buildGlb(Boolean(msg.withSupport)));
      if (error) {
        post(errorReply(error, msg.id, client));
        return;
      }
      const transfer = [];
      bytes = takeBuffers(lab.buffers('glb'), transfer).bytes;
    } else if (msg.format === 'json') {
      bytes = text(lab.modelJson());
    } else if (msg.format === 'lsys') {
      bytes = text(lab.lstring());
    } else {
      throw new Error(`export: format '${String(msg.format).slice(0, 20)}' is unknown; must be glb, json or lsys`);
    }
    if (bytes.byteLength === 0) throw new Error('export: nothing grown yet');
    post({ type: 'export', id: msg.id, client, format: msg.format, bytes }, [bytes]);
  }

  // The client went away (web/worker/worker.js 'close'): its lab is deleted and its returned
  // buffers are dropped (not the shared leaf-texture buffer). Returns what was let go.
  const close = (client) => closeLabSession(labs, returned, client);

  return {
    superseding: ['update'],
    close,
    ready: (msg) => ({ paramTable, presets, scenes, trees, decoded: JSON.parse(Module.decodeHash('ivy', String(msg.hash || ''), '')) }),
    messages: {
      decode: (msg, client) => post({ type: 'decoded', id: msg.id, client, ...JSON.parse(Module.decodeHash('ivy', String(msg.hash || ''), '')) }),
      encode: (msg, client) => post({ type: 'encoded', id: msg.id, client, ...JSON.parse(Module.encodeHash('ivy', JSON.stringify(msg.state || {}), '')) }),
      update,
      mesh,
      pick,
      export: exportIvy,
      // The leaf texture's pixels go to the buffers every client shares; the rest are the client's.
      recycle: (msg, client) => {
        const { 'leafTexture.pixels': texture, ...own } = msg.buffers || {};
        returned.give(client, own);
        if (texture) returned.give(SHARED, { 'leafTexture.pixels': texture });
      },
    },
  };
}
