// The tree study's worker handler: grows trees year by year (superseded between years), sends
// their meshes, re-skins or re-views the tree already grown for updates of a later stage (restage),
// runs the wind, the hybrid views and the exports. One TreeSession (web/bindings/tree_bindings.cpp)
// per client keeps the client's last finished tree. The mesh parts, their textures, the card
// atlas, the sway poses and the hybrid draw lists go as views into the buffers the client handed
// back ('recycle', once they are on its GPU) when they fit, else into fresh ones
// (web/worker/transfer.js TransferPool). Messages: web/worker/protocol.js.
// Does not: load the module, route messages or catch errors (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';
import { nextTask as yieldToEvents } from './next_task.js';
import { TransferPool, copyView } from './transfer.js';

// The warm-up grow's years (sakura-thesis; ?warmup=N on the worker's URL sets N, 0 turns it off).
const WARM_UP_YEARS = 8;

// ctx: {post(msg, transfer), isLatest(client, id), options} from the router.
export function createHandler(Module, ctx) {
  const { post, isLatest } = ctx;
  scheduleWarmUp(Module, ctx.options || {});
  const paramTable = JSON.parse(Module.tableJson('tree'));
  // Rows whose edits change the grown tree (stage grow; rows without a stage too). Mesh, sway and
  // view rows restage the tree already grown (the session's update: core TreeRun::Update re-does
  // only the earliest stage whose rows changed, and clears the hybrid scene).
  const treeKeys = paramTable.filter((row) => !['mesh', 'sway', 'view'].includes(row.stage)).map((row) => row.key);
  const finished = new Map();  // client -> {session, state, until} of its last tree sent
  const returned = new TransferPool();  // the mesh, pose and draw-list buffers each client handed back

  // True when states a and b (as the pages send them) grow the same tree.
  function sameTree(a, b) {
    const text = (v) => (v === undefined || v === null ? '' : String(v));
    if (text(a.state.preset) !== text(b.state.preset) || text(a.state.seed) !== text(b.state.seed)) return false;
    if (text(a.state.years) !== text(b.state.years) || text(a.until) !== text(b.until)) return false;
    if ((a.state.prunes || []).join(',') !== (b.state.prunes || []).join(',')) return false;
    const pa = a.state.params || {}, pb = b.state.params || {};
    return treeKeys.every((key) => text(pa[key]) === text(pb[key]));
  }

  // The procedural textures of a look (core/tree/tree_textures.h: the .glb's own pixels), painted
  // once per look and kept: kind -> {width, height, pixels: Uint8Array, digest}.
  const textureCache = new Map();  // "bark" | "barkNormal" | "leaf:shape,season,autumn,spray" | "flower:colour,form"
  function texture(kind, look) {
    const flowerColour = look.flower_colour ?? 0, flowerForm = look.flower_form ?? 0, spray = look.leaf_spray ?? 1;
    const key = kind === 'leaf' ? `leaf:${look.leaf_shape},${look.season},${look.autumn_colour},${spray}`
      : kind === 'flower' ? `flower:${flowerColour},${flowerForm}` : kind;
    if (!textureCache.has(key)) {
      textureCache.set(key, Module.treeTexture(kind, look.leaf_shape, look.season, look.autumn_colour, flowerColour, flowerForm, spray));
    }
    return textureCache.get(key);
  }

  // The textures of the session's mesh, copied into the client's returned 'textures.<kind>'
  // buffers where they fit (transferred); the renderer uploads a texture only when its digest
  // changes.
  function takeTextures(session, client, transfer, counts) {
    const look = JSON.parse(session.lookJson());
    const kinds = ['bark', 'barkNormal', 'leaf', 'flower'];
    // A dressed session's bark is the bark study's maps (TreeSession.dressBark), not the look's.
    const dressed = session.barkDressed();
    const painted = Object.fromEntries(kinds.map((kind) => [kind,
      dressed && (kind === 'bark' || kind === 'barkNormal') ? session.barkTexture(kind) : texture(kind, look)]));
    const pixels = returned.take(client, 'textures', Object.fromEntries(kinds.map((kind) => [kind, painted[kind].pixels])), transfer, counts);
    const out = { look };
    for (const kind of kinds) {
      const t = painted[kind];
      out[kind] = { width: t.width, height: t.height, digest: t.digest, pixels: pixels[kind] };
    }
    return out;
  }

  // The mesh parts copied once out of the heap, into the client's returned buffers where they fit;
  // counts: {reused, fresh} buffers.
  function takeMesh(session, client, transfer, counts) {
    const part = (name) => returned.take(client, name, session.buffers(name), transfer, counts);
    return { bark: part('bark'), leaves: part('leaves'), flowers: part('flowers'), textures: takeTextures(session, client, transfer, counts) };
  }

  // The card-atlas geometry of a hybrid-mode tree (copied once into the client's returned
  // 'atlas.<part>.*' buffers where they fit, transferred).
  function takeAtlas(session, client, transfer, counts = { reused: 0, fresh: 0, dropped: 0 }) {
    const part = (name) => returned.take(client, `atlas.${name}`, session.buffers(`atlas.${name}`), transfer, counts);
    return { atlasSize: session.atlasSize(), bark: part('bark'), leaves: part('leaves'), flowers: part('flowers') };
  }

  // The 'tree' message of a session whose mesh is built; false (after an error message) when the
  // hybrid scene cannot be built.
  // stages: the stages a restage re-did (a grow: null).
  // started: the worker's clock when a grow's request began (performance.now()), or null; the
  // message's workerMs is its wall time from then to this message, the stats, the mesh's copies out
  // of the heap and the hybrid view included (they were left out: bench/edit_latency.mjs counted
  // them against the page's messages instead of the grow); builtMs: from then to the mesh built
  // (the copies not included: the workerMs of before).
  function sendTree(id, client, session, grown, stages = null, started = null, builtMs = null) {
    const stats = JSON.parse(session.statsJson());
    if (session.barkDressed()) stats.bark = JSON.parse(session.barkJson());
    const transfer = [];
    const buffers = { reused: 0, fresh: 0 };
    const mesh = takeMesh(session, client, transfer, buffers);
    let hybrid = null;
    if (session.renderMode() === 1) {
      const error = errorOf(session.buildHybrid());
      if (error) {
        post(errorReply(error, id, client));
        return false;
      }
      hybrid = takeAtlas(session, client, transfer, buffers);
    }
    const swayNodes = session.swayNodes();
    const workerMs = started === null ? null : performance.now() - started;
    post({ type: 'tree', id, client, stats, mesh, hybrid, swayNodes, grown, stages, buffers, workerMs, builtMs }, transfer);
    return true;
  }

  async function grow(msg, client) {
    const { id, state, until } = msg;
    const started = performance.now();  // the worker's time for this grow, sent with the tree
    let session;
    try {
      session = new Module.TreeSession(JSON.stringify(state));
    } catch (e) {
      post({ type: 'error', id, client, message: String(e && e.message ? e.message : e) });
      return;
    }
    let keep = false;
    try {
      const error = errorOf(session.error());
      if (error) {
        post(errorReply(error, id, client));
        return;
      }
      post({ type: 'hash', id, client, hash: session.hash() });
      const full = session.years();
      const years = Number.isInteger(until) ? Math.max(0, Math.min(until, full)) : full;
      post({ type: 'progress', id, client, year: 0, years });
      while (session.year() < years && !session.done()) {
        await yieldToEvents();
        if (!isLatest(client, id)) return;  // superseded by a newer request: drop this one
        session.growYear();
        post({ type: 'progress', id, client, year: session.year(), years });
      }
      await yieldToEvents();
      if (!isLatest(client, id)) return;
      const meshError = errorOf(session.buildMesh());  // null or the page budget it would cross
      if (meshError) {
        post(errorReply(meshError, id, client));
        return;
      }
      dressBark(session, client);
      if (!sendTree(id, client, session, true, null, started, performance.now() - started)) return;
      stopWind(client);  // the client restarts the wind on the new tree if it is playing
      finished.get(client)?.session.delete();
      finished.set(client, { session, state, until });
      keep = true;
    } finally {
      if (!keep) session.delete();
    }
  }

  // The bark the state's rows `bark` and `bark_model` ask for on the session's tree
  // (TreeSession.dressBark: the bark study when bark is 1, the same run as the CLI's --bark sim);
  // a refusal (a tree of one year, bark_model 3, the page budget) goes beside the Bark choice
  // (control 'bark') and the tree keeps its procedural bark.
  function dressBark(session, client) {
    const error = errorOf(session.dressBark());
    if (error) post(errorReply(error, undefined, client, { control: 'bark' }));
  }

  // An update of stage mesh, sway or view: the client's last tree with the new state, not grown
  // again (or a grow when the state grows another tree). The reply's `stages` are the ones the run
  // re-did.
  async function restage(msg, client) {
    const last = finished.get(client);
    if (!last || !sameTree(last, msg)) return grow(msg, client);
    const answer = JSON.parse(last.session.update(JSON.stringify(msg.state)));
    if (answer.ok === false) {
      post(errorReply(answer, msg.id, client));
      return;
    }
    if (answer.stages.includes('grow')) {  // the run says another tree after all: grown anew
      finished.delete(client);
      stopWind(client);
      last.session.delete();
      return grow(msg, client);
    }
    post({ type: 'hash', id: msg.id, client, hash: last.session.hash() });
    stopWind(client);  // the sway restarts in the new wind (the client asks when it is playing)
    last.state = msg.state;
    dressBark(last.session, client);  // the bark rows re-texture the tree grown, not regrow it
    if (answer.stages.length > 0) last.motionHybrid = false;  // the update cleared the hybrid scene
    sendTree(msg.id, client, last.session, false, answer.stages);
  }

  // ---- Wind: one sway loop per client, following the wall clock ----
  const sways = new Map();   // client -> {session, origins, clock, clockName, base, steps, waiting, timer}
  const clocks = new Map();  // name -> {start}: wall-clock origin shared by the sways started with it

  // The thesis's gust (3.5) starts suddenly from still air at gust_on (1 s by default), and the
  // simulator starts at rest at t = 0: run live from t = 0, Blow showed nothing for that second.
  // The still air is stepped through before the first pose instead (the same simulation, the same
  // bits as a run from 0), so the first pose on screen is the first step of the gust: at most
  // `most` steps a worker tick (swayStepsPerTick: within the page's tick estimate, so a slow tree
  // does not hold the worker over it; core/sway/sway_budget), at most MAX_STILL_AIR_STEPS in all,
  // none in calm air. Returns {steps, done}. docs/sway-model.md, "In the page".
  const MAX_STILL_AIR_STEPS = 600;
  function skipStillAir(session, state, most) {
    const speed = Number(state?.params?.wind_speed);
    if (Number.isFinite(speed) && speed <= 0) return { steps: 0, done: true };  // calm: no gust to wait for
    let steps = 0;
    while (steps < most && session.swayWindSpeed() === 0) {
      session.swayStep(1);
      steps += 1;
    }
    return { steps, done: session.swayWindSpeed() !== 0 };
  }

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
    const last = finished.get(client);
    const session = last?.session;
    if (!session) return;
    const at = origins ? Array.from(origins, Number) : null;
    const error = errorOf(at ? session.swayStartAt(at) : session.swayStart());
    if (error) {  // control: the page shows it beside Blow (e.g. the page memory budget's line)
      post(errorReply(error, undefined, client, { control: 'wind' }));
      return;
    }
    let clock = typeof clockName === 'string' ? clocks.get(clockName) : null;
    if (!clock) {
      clock = { start: performance.now() };
      if (typeof clockName === 'string') clocks.set(clockName, clock);
    }
    // Simulated time 0 is at the clock's start: a sway joining a running clock catches up, and when
    // it is more than 8 steps behind, the shared clock slips back to it (the others wait).
    const sway = { session, state: last.state, origins: at, clock, clockName, base: 0, steps: 0, skipped: 0, stillAir: true, waiting: false, timer: 0 };
    sways.set(client, sway);
    windTick(client, sway);
  }

  function windTick(client, sway) {
    if (sways.get(client) !== sway) return;
    const session = sway.session;
    const dt = session.swayDt();
    if (sway.stillAir) {  // the still air before the gust, a tick's steps at a time, no pose
      const part = skipStillAir(session, sway.state, Math.min(session.swayStepsPerTick(), MAX_STILL_AIR_STEPS - sway.skipped));
      sway.skipped += part.steps;
      if (part.done || sway.skipped >= MAX_STILL_AIR_STEPS) {
        sway.stillAir = false;
        // Its own clock starts now (the first pose is the gust's first step); a shared clock
        // (the grove) is caught up as a sway joining it late.
        if (typeof sway.clockName !== 'string') sway.clock.start = performance.now() - (sway.base + sway.steps) * 1000 * dt;
      }
      sway.timer = setTimeout(() => windTick(client, sway), part.done ? 8 : 0);
      return;
    }
    if (!sway.waiting) {
      const now = Math.floor((performance.now() - sway.clock.start) / (1000 * dt));
      const due = now - sway.base - sway.steps;
      if (due > 0) {
        // At most the steps one tick may take (swayStepsPerTick: 8, fewer for a tree whose 8 steps
        // would hold the worker over the page's tick estimate; core/sway/sway_budget).
        const most = session.swayStepsPerTick();
        const started = performance.now();
        let time = session.swayStep(Math.min(due, most));
        const stepMs = (performance.now() - started) / Math.min(due, most);  // per step, all instances
        sway.steps += Math.min(due, most);
        if (due > most) sway.clock.start += (due - most) * 1000 * dt;  // too slow: let the clock slip, not pile up
        if (time >= session.swayDuration()) {  // the gust schedule is over: again from rest
          if (sway.origins) session.swayStartAt(sway.origins); else session.swayStart();
          sway.skipped = 0;
          sway.stillAir = true;  // stepped through in the next ticks, as at Blow
          sway.base += sway.steps;
          sway.steps = 0;
          time = 0;
        }
        // Into the poses buffer the client handed back with the last pose, when it did.
        const transfer = [], buffers = { reused: 0, fresh: 0 };
        const { poses } = returned.take(client, 'sway', session.buffers('sway'), transfer, buffers);
        sway.waiting = true;
        post({ type: 'pose', client, time, wind: session.swayWindSpeed(), instances: session.swayInstances(),
          stepMs, stepsPerTick: most, speed: session.swaySpeed(), poses, buffers }, transfer);
      }
    }
    sway.timer = setTimeout(() => windTick(client, sway), 8);
  }

  // One view of a hybrid-mode tree: selection, draw list and its sway skin. With motion: true, the
  // same for a full-mode tree, its cheaper representation while it moves (issue 16; the page's
  // FrameGovernor): the hybrid scene is built once per tree, its atlas sent ('motionAtlas') when
  // the page asks for it (atlas: true), and the draw list comes back with motion: true.
  function hybridView(msg, client) {
    const last = finished.get(client);
    const session = last?.session;
    const motion = msg.motion === true;
    if (!session || (session.renderMode() === 1) === motion) return;
    if (motion && (!last.motionHybrid || msg.atlas === true)) {
      if (!last.motionHybrid) {
        const error = errorOf(session.buildHybrid());
        if (error) {  // no cheaper representation: the page keeps drawing the full one
          post(errorReply(error, undefined, client, { control: 'motion' }));
          return;
        }
        last.motionHybrid = true;
      }
      // Into the 'atlas.*' buffers the client handed back (the page recycles them once painted).
      const transfer = [], buffers = { reused: 0, fresh: 0, dropped: 0 };
      post({ type: 'motionAtlas', client, hybrid: takeAtlas(session, client, transfer, buffers), buffers }, transfer);
    }
    const { camera, slot, tag } = msg;
    const n = (x, d) => (Number.isFinite(Number(x)) ? Number(x) : d);
    const eye = camera?.eye || [0, 0, 10], target = camera?.target || [0, 0, 0];
    const view = [n(eye[0], 0), n(eye[1], 0), n(eye[2], 10), n(target[0], 0),
      n(target[1], 0), n(target[2], 0), n(camera?.fovY, Math.PI / 4), Math.round(n(camera?.width, 512)),
      Math.round(n(camera?.height, 512))];
    const slotted = slot !== undefined && slot !== null;
    const stats = JSON.parse(slotted ? session.hybridViewSlot(Number.isInteger(slot) ? slot : -1, ...view)
      : session.hybridView(...view));
    if (stats.ok === false) throw new Error(stats.message);
    const transfer = [], buffers = { reused: 0, fresh: 0 };
    const cards = returned.take(client, 'cards', session.buffers('cards'), transfer, buffers);
    const lines = returned.take(client, 'lines', session.buffers('lines'), transfer, buffers);
    const extra = slotted ? { slot, tag } : motion ? { motion: true } : {};
    post({ type: 'drawList', client, stats, cards, lines, buffers, ...extra }, transfer);
  }

  function exportTree(msg, client) {
    const session = finished.get(client)?.session;
    if (!session) throw new Error('no tree has been grown yet');
    let bytes;
    if (msg.format === 'glb') {
      // A triangle budget, LOD levels (core/render/tree_lod) or the sway clip (core/sway/sway_gltf):
      // web/tree/export_panel.js; none of them: the full mesh as before.
      const error = errorOf(msg.variant === 'sway' ? session.buildSwayGlb(Number(msg.fps ?? 30))
        : (msg.variant === 'lod' || msg.variant === 'budget')
          ? session.buildLodGlb(Number(msg.maxTriangles ?? -1), msg.variant === 'lod')
          : session.buildGlb());
      if (error) {  // refused by the page budget's estimate before it started (or a bad value): the line itself
        post(errorReply(error, msg.id, client, { control: 'export' }));
        return;
      }
      bytes = copyView(session.buffers('glb').bytes);
    } else if (msg.format === 'json') {
      bytes = new TextEncoder().encode(session.paramsJson()).buffer;
    } else {
      throw new Error(`unknown export format '${String(msg.format)}'`);
    }
    post({ type: 'export', id: msg.id, client, format: msg.format, variant: msg.variant, bytes }, [bytes]);
  }

  // The link's page fields are the page's choices, not rows of the tree's table (the tree and its
  // exports are the same either way): taken out before the core decodes the rest, and returned
  // beside the state, each at its first value unless the link names another (a bad value is
  // dropped with a notice, as the core drops a bad value of its own keys): shadows=on|off (Sun
  // shadows). The page writes only values off the first. The Bark choice is the table's row
  // `bark` now (bark=1); an older link's bark=sim or bark=procedural is read as bark=1 or 0.
  const PAGE_FIELDS = { shadows: ['on', 'off'] };
  const OLD_BARK = { 'bark=sim': 'bark=1', 'bark=procedural': 'bark=0' };
  const decode = (hash) => {
    const page = Object.fromEntries(Object.entries(PAGE_FIELDS).map(([key, values]) => [key, values[0]]));
    const pageNotices = [];
    const rest = String(hash ?? '').replace(/^#/, '').split('&').map((pair) => OLD_BARK[pair] ?? pair).filter((pair) => {
      const eq = pair.indexOf('=');
      const key = eq < 0 ? pair : pair.slice(0, eq);
      const values = Object.hasOwn(PAGE_FIELDS, key) ? PAGE_FIELDS[key] : null;
      if (!values) return true;
      const value = eq < 0 ? '' : pair.slice(eq + 1);
      if (values.includes(value)) page[key] = value;
      else pageNotices.push(`${key}: '${value.slice(0, 64).replace(/[^\x20-\x7e]/g, '?')}' dropped, must be ${values.join(' or ')}`);
      return false;
    }).join('&');
    const decoded = JSON.parse(Module.decodeHash('tree', rest, ''));
    return { ...decoded, notices: [...(decoded.notices || []), ...pageNotices], ...page };
  };

  // The client went away (web/worker/worker.js 'close'): its sway stops, its tree session is
  // deleted and its returned buffers are dropped. Returns what was let go.
  function close(client) {
    stopWind(client);
    const last = finished.get(client);
    last?.session.delete();
    finished.delete(client);
    return { sessions: last ? 1 : 0, buffers: returned.forget(client) };
  }

  return {
    // Requests of these types supersede the client's older ones.
    superseding: ['update'],
    close,
    ready: (msg) => ({ paramTable, presets: JSON.parse(Module.presetsJson('tree')), decoded: decode(msg.hash) }),
    messages: {
      decode: (msg, client) => {
        const { state, notices, shadows } = decode(msg.hash);
        post({ type: 'decoded', id: msg.id, client, state, notices, shadows });
      },
      // An update of a later stage than 'grow' (the page's controller sends the earliest stage its
      // edits touched) restages the tree grown; the others grow.
      update: (msg, client) => (['mesh', 'sway', 'view'].includes(msg.stage) ? restage(msg, client) : grow(msg, client)),
      wind: (msg, client) => (msg.play ? startWind(client, msg.origins, msg.clock) : stopWind(client)),
      poseDone: (msg, client) => {
        const sway = sways.get(client);
        if (sway) sway.waiting = false;
      },
      view: hybridView,
      export: exportTree,
      recycle: (msg, client) => returned.give(client, msg.buffers),
      // Save / Open (web/tree/state_file.js): {save: page state} -> {json}; {open: file text} ->
      // {state}; a bad state or file is an 'error' with its field.
      stateFile: (msg, client) => {
        const answer = JSON.parse(msg.open !== undefined ? Module.openStateFile(String(msg.open))
          : Module.stateFile(JSON.stringify(msg.save ?? {})));
        if (answer.ok === false) post({ type: 'error', id: msg.id, client, field: answer.field, message: answer.message });
        else post({ type: 'stateFile', id: msg.id, client, json: answer.json, state: answer.state });
      },
    },
  };
}

// Warm-up (issue 17 item 7): V8 compiles each WASM function on its first call with its baseline
// compiler (Liftoff) and recompiles it with TurboFan in the background only once it has run a
// while; a call already running keeps its Liftoff code (no on-stack replacement for WASM), so the
// page's first 15-year grow ran mostly in baseline code while TurboFan competed for the cores. A
// small grow and mesh in the task after the worker's 'ready' (while the page builds its panel)
// makes the hot growth and mesh functions tier up before the first tree is asked for.
function scheduleWarmUp(Module, options) {
  const years = options.warmup === undefined ? WARM_UP_YEARS : Number(options.warmup);
  if (!Number.isInteger(years) || years <= 0) return;
  setTimeout(() => {
    const session = new Module.TreeSession(JSON.stringify({ preset: 'sakura-thesis', seed: 1, years }));
    try {
      while (session.year() < years && !session.done()) session.growYear();
      session.buildMesh();
    } finally {
      session.delete();
    }
  }, 0);
}
