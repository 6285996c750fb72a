// Niwa Web Worker (ES module worker): runs the WASM core off the main thread. One worker and one
// WASM instance serve every client on a page (the app, or several <niwa-tree> elements).
//
// Protocol: init, then update messages; buffers transferred, never copied twice.
//   in  {type:'init', hash}                  -> out {type:'ready', paramTable, presets, decoded:{state, notices}}
//   in  {type:'decode', id, hash}            -> out {type:'decoded', id, state, notices}
//   in  {type:'update', id, client, state, until}
//         grows state.years years, or only `until` years when given (the year scrubber)
//                                            -> out {type:'hash', id, client, hash}            (state accepted)
//                                               out {type:'progress', id, client, year, years} (after each year)
//                                               out {type:'tree', id, client, stats, mesh}     (ArrayBuffers transferred;
//                                                   mesh.bark also has branchIds per vertex and branchParents per branch)
//         every part also has joints (Uint32) and weights (Float32) per vertex: the sway skin of
//         core/sway/skin.h; leaves have uvs; the message has swayNodes (node points)
//   in  {type:'wind', client, play, origins, clock}
//                                            starts (play: true, from rest) or stops the sway of the
//                                            client's last tree, with the wind of its state
//                                            -> out {type:'pose', client, time, wind, instances, stepMs,
//                                               poses}  (Float32 ArrayBuffer transferred: 16 floats per
//                                               node point and instance), one at a time: the next is sent after
//   in  {type:'poseDone', client}            the client has drawn the last pose.
//                                               The simulation follows the wall clock (steps of dt,
//                                               at most 8 per tick) and loops at the wind's duration.
//         optional origins (the grove page): array of 3 numbers per instance, each instance's base
//         in the world in metres; the tree is then swayed once per instance (one SwaySimulator each,
//         swayStartAt), each in the wind field at its own place (travelling gust front and wave),
//         and poses holds instances × swayNodes × 16 floats (instance k's node point j at
//         (k · swayNodes + j) · 16); without origins one instance at the world origin.
//         optional clock (a name): sways started with the same name share one wall clock and its
//         slips, so several clients (a grove's unique trees) stay at the same simulated time.
//         stepMs: wall time of one step of all the client's instances (and writing their poses).
//         with render_mode 1 the tree message also has hybrid: {atlasSize, bark|leaves|flowers:
//         {positions, normals, indices}}: clip-space triangles that paint the card atlas (thesis 4.2.1)
//   in  {type:'view', client, camera:{eye, target, fovY, width, height}}   (hybrid mode, after a tree)
//                                            -> out {type:'drawList', client, stats, cards:{positions,
//                                               uvs, indices, joints, weights}, lines:{positions,
//                                               colors, widths, joints, weights}} (transferred): eq. 4.1
//                                               selection with hysteresis against the client's last view
//         optional slot (whole number 0..255): the hysteresis is kept per (client, slot) instead,
//         so one tree can keep several draw lists (the grove page: one per distance band); the
//         answer then carries slot and the message's tag (any value, echoed back)
//   in  {type:'export', id, client, format:'glb'|'json'}   (the client's last finished tree)
//                                            -> out {type:'export', id, client, format, bytes} (ArrayBuffer transferred)
//   any failure                              -> out {type:'error', id, client, message}
// `client` (any string, default 'app') keeps clients apart: a newer update supersedes an older one
// OF THE SAME CLIENT: the grow loop yields between years and drops itself when a newer id arrived.

const MODULE_URL = new URL('../wasm/niwa_web.js', import.meta.url).href;

let modulePromise = null;
const latest = new Map();    // client -> id of its newest update
const finished = new Map();  // client -> GrowSession of its last tree sent (for exports)

function loadModule() {
  if (!modulePromise) {
    modulePromise = import(MODULE_URL).then((factory) =>
      factory.default({
        locateFile: (file) => new URL(file, MODULE_URL).href,
        print: () => {},
        printErr: () => {},
      }));
  }
  return modulePromise;
}

const yieldToEvents = () => new Promise((resolve) => setTimeout(resolve, 0));
const messageOf = (e) => String(e && e.message ? e.message : e);

// Copies one WASM-memory view ONCE into a fresh typed array whose buffer is then transferred.
function copyView(view, Type) {
  const out = new Type(view.length);
  out.set(view);
  return out.buffer;
}

function takeMesh(session, transfer) {
  const part = (name) => {
    // Each view is copied right after it is obtained, before any other call into WASM.
    const positions = copyView(session[`${name}Positions`](), Float32Array);
    const normals = copyView(session[`${name}Normals`](), Float32Array);
    const indices = copyView(session[`${name}Indices`](), Uint32Array);
    const joints = copyView(session[`${name}Joints`](), Uint32Array);
    const weights = copyView(session[`${name}Weights`](), Float32Array);
    transfer.push(positions, normals, indices, joints, weights);
    return { positions, normals, indices, joints, weights };
  };
  const leaves = part('leaves');
  leaves.uvs = copyView(session.leavesUvs(), Float32Array);
  transfer.push(leaves.uvs);
  const bark = part('bark');
  bark.branchIds = copyView(session.barkBranchIds(), Uint32Array);
  bark.branchParents = copyView(session.branchParents(), Int32Array);
  transfer.push(bark.branchIds, bark.branchParents);
  return { bark, leaves, flowers: part('flowers') };
}

// ---- Wind: one sway loop per client, following the wall clock ----
const sways = new Map();   // client -> {session, origins, clock, clockName, base, steps, waiting, timer}
const clocks = new Map();  // name -> {start}: wall-clock origin shared by the sways started with it

function stopWind(client) {
  const sway = sways.get(client);
  if (!sway) return;
  clearTimeout(sway.timer);
  sways.delete(client);
  if (typeof sway.clockName === 'string' && ![...sways.values()].some((s) => s.clock === sway.clock)) {
    clocks.delete(sway.clockName);
  }
}

// origins: optional, metres, 3 per instance (the grove): one simulator per instance, each in the
// wind at its own place; clock: optional name; sways started with the same name share one wall
// clock (and its slips), so the unique trees of a grove stay at the same simulated time.
function startWind(client, origins, clockName) {
  stopWind(client);
  const session = finished.get(client);
  if (!session) return;
  const at = origins ? Array.from(origins, Number) : null;
  const error = at ? session.swayStartAt(at) : session.swayStart();
  if (error) {
    postMessage({ type: 'error', client, message: error });
    return;
  }
  let clock = typeof clockName === 'string' ? clocks.get(clockName) : null;
  if (!clock) {
    clock = { start: performance.now() };
    if (typeof clockName === 'string') clocks.set(clockName, clock);
  }
  // Simulated time 0 is at the clock's start: a sway joining a running clock catches up, and when
  // it is more than 8 steps behind, the shared clock slips back to it (the others wait).
  const sway = { session, origins: at, clock, clockName, base: 0, steps: 0, waiting: false, timer: 0 };
  sways.set(client, sway);
  windTick(client, sway);
}

function windTick(client, sway) {
  if (sways.get(client) !== sway) return;
  const session = sway.session;
  const dt = session.swayDt();
  if (!sway.waiting) {
    const now = Math.floor((performance.now() - sway.clock.start) / (1000 * dt));
    const due = now - sway.base - sway.steps;
    if (due > 0) {
      const started = performance.now();
      let time = session.swayStep(Math.min(due, 8));
      const stepMs = (performance.now() - started) / Math.min(due, 8);  // per step, all instances
      sway.steps += Math.min(due, 8);
      if (due > 8) sway.clock.start += (due - 8) * 1000 * dt;  // too slow: let the clock slip, not pile up
      if (time >= session.swayDuration()) {  // the gust schedule is over: again from rest
        if (sway.origins) session.swayStartAt(sway.origins); else session.swayStart();
        sway.base += sway.steps;
        sway.steps = 0;
        time = 0;
      }
      const poses = copyView(session.swayPoses(), Float32Array);
      sway.waiting = true;
      postMessage({ type: 'pose', client, time, wind: session.swayWindSpeed(), instances: session.swayInstances(),
        stepMs, poses }, [poses]);
    }
  }
  sway.timer = setTimeout(() => windTick(client, sway), 8);
}

// The card-atlas geometry of a hybrid-mode tree (copied once, transferred).
function takeAtlas(session, transfer) {
  const part = (name) => {
    const positions = copyView(session[`atlas${name}Positions`](), Float32Array);
    const normals = copyView(session[`atlas${name}Normals`](), Float32Array);
    const indices = copyView(session[`atlas${name}Indices`](), Uint32Array);
    transfer.push(positions, normals, indices);
    return { positions, normals, indices };
  };
  return { atlasSize: session.atlasSize(), bark: part('Bark'), leaves: part('Leaves'), flowers: part('Flowers') };
}

// One view of a hybrid-mode tree: selection, draw list and its sway skin.
function hybridView(client, camera, slot, tag) {
  const session = finished.get(client);
  if (!session || session.renderMode() !== 1) return;
  const n = (x, d) => (Number.isFinite(Number(x)) ? Number(x) : d);
  const eye = camera?.eye || [0, 0, 10], target = camera?.target || [0, 0, 0];
  const view = [n(eye[0], 0), n(eye[1], 0), n(eye[2], 10), n(target[0], 0),
    n(target[1], 0), n(target[2], 0), n(camera?.fovY, Math.PI / 4), Math.round(n(camera?.width, 512)),
    Math.round(n(camera?.height, 512))];
  const slotted = slot !== undefined && slot !== null;
  const stats = JSON.parse(slotted ? session.hybridViewSlot(Number.isInteger(slot) ? slot : -1, ...view)
    : session.hybridView(...view));
  if (stats.error) throw new Error(stats.error);
  const transfer = [];
  const take = (name, Type) => {
    const buffer = copyView(session[name](), Type);
    transfer.push(buffer);
    return buffer;
  };
  const cards = {
    positions: take('cardPositions', Float32Array), uvs: take('cardUvs', Float32Array),
    indices: take('cardIndices', Uint32Array), joints: take('cardJoints', Uint32Array),
    weights: take('cardWeights', Float32Array),
  };
  const lines = {
    positions: take('linePositions', Float32Array), colors: take('lineColors', Float32Array),
    widths: take('lineWidths', Float32Array), joints: take('lineJoints', Uint32Array),
    weights: take('lineWeights', Float32Array),
  };
  const extra = slotted ? { slot, tag } : {};
  postMessage({ type: 'drawList', client, stats, cards, lines, ...extra }, transfer);
}

async function grow(id, client, state, until) {
  const Module = await loadModule();
  if (id !== latest.get(client)) return;
  let session;
  try {
    session = new Module.GrowSession(JSON.stringify(state));
  } catch (e) {
    postMessage({ type: 'error', id, client, message: messageOf(e) });
    return;
  }
  let keep = false;
  try {
    const error = session.error();
    if (error) {
      postMessage({ type: 'error', id, client, message: error });
      return;
    }
    postMessage({ type: 'hash', id, client, hash: session.hash() });
    const full = session.years();
    const years = Number.isInteger(until) ? Math.max(0, Math.min(until, full)) : full;
    postMessage({ type: 'progress', id, client, year: 0, years });
    while (session.year() < years && !session.done()) {
      await yieldToEvents();
      if (id !== latest.get(client)) return; // superseded by a newer update: drop this one
      session.growYear();
      postMessage({ type: 'progress', id, client, year: session.year(), years });
    }
    await yieldToEvents();
    if (id !== latest.get(client)) return;
    session.buildMesh();
    const stats = JSON.parse(session.statsJson());
    const transfer = [];
    const mesh = takeMesh(session, transfer);
    let hybrid = null;
    if (session.renderMode() === 1) {
      const error = session.buildHybrid();
      if (error) {
        postMessage({ type: 'error', id, client, message: error });
        return;
      }
      hybrid = takeAtlas(session, transfer);
    }
    postMessage({ type: 'tree', id, client, stats, mesh, hybrid, swayNodes: session.swayNodes() }, transfer);
    stopWind(client);  // the client restarts the wind on the new tree if it is playing
    finished.get(client)?.delete();
    finished.set(client, session);
    keep = true;
  } finally {
    if (!keep) session.delete();
  }
}

function exportTree(id, client, format) {
  const session = finished.get(client);
  if (!session) throw new Error('no tree has been grown yet');
  let bytes;
  if (format === 'glb') {
    const error = session.buildGlb();
    if (error) throw new Error(error);
    bytes = copyView(session.glbBytes(), Uint8Array);
  } else if (format === 'json') {
    bytes = new TextEncoder().encode(session.paramsJson()).buffer;
  } else {
    throw new Error(`unknown export format '${String(format)}'`);
  }
  postMessage({ type: 'export', id, client, format, bytes }, [bytes]);
}

function decode(Module, hash) {
  return JSON.parse(Module.decodeHash(String(hash ?? '')));
}

self.onmessage = async (event) => {
  const msg = event.data || {};
  const client = typeof msg.client === 'string' ? msg.client : 'app';
  try {
    if (msg.type === 'init') {
      const Module = await loadModule();
      postMessage({
        type: 'ready',
        client,
        paramTable: JSON.parse(Module.paramTableJson()),
        presets: JSON.parse(Module.presetsJson()),
        decoded: decode(Module, msg.hash),
      });
    } else if (msg.type === 'decode') {
      const Module = await loadModule();
      const { state, notices } = decode(Module, msg.hash);
      postMessage({ type: 'decoded', id: msg.id, client, state, notices });
    } else if (msg.type === 'update') {
      latest.set(client, msg.id);
      await grow(msg.id, client, msg.state, msg.until);
    } else if (msg.type === 'wind') {
      if (msg.play) startWind(client, msg.origins, msg.clock); else stopWind(client);
    } else if (msg.type === 'view') {
      await loadModule();
      hybridView(client, msg.camera, msg.slot, msg.tag);
    } else if (msg.type === 'poseDone') {
      const sway = sways.get(client);
      if (sway) sway.waiting = false;
    } else if (msg.type === 'export') {
      await loadModule();
      exportTree(msg.id, client, msg.format);
    } else {
      postMessage({ type: 'error', id: msg.id, client, message: `worker: unknown message type '${String(msg.type)}'` });
    }
  } catch (e) {
    postMessage({ type: 'error', id: msg.id, client, message: `worker: ${messageOf(e)}` });
  }
};
