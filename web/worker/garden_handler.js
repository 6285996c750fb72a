// The garden's worker handler (issue 33; web/bindings/garden_bindings.cpp): one GardenLab per
// client holds the last run. An 'update' grows the state (the garden state JSON, GardenStateJson's
// shape: {params, ground, objects, plants, mix}) to its years, a year a step with the worker's
// messages taken between steps (a newer update supersedes it there), posting progress after every year
// (at most every 100 ms), then sends the stats (the run's StatsJson, parsed, and its text), the
// resolved state and hash, the bounds (the ground's size and grid, each distinct tree's group and
// every planted tree) and the buffer groups ground, objects and trees (each distinct tree's mesh
// once with its placements; with bark 1 its bark's uvs), `barks` (each distinct tree's simulated
// bark maps, or null: the garden .glb's textures), copied once out of the WASM heap into buffers the page gave back
// ('recycle') where they fit (web/worker/transfer.js TransferPool), then transferred.
// The reply also carries `phases` (the lab's phasesJson: where the grow's time went, ms), `years` (the lab's yearsJson: the years recorded as the clock ran, their
// bytes, why the recording stopped) and `grows` (how many grows this client's lab started).
// A 'year' ({year}) draws another garden year WITHOUT growing (the year scrubber and Play): the
// lab's showYear(y) builds each distinct tree's mesh of that year from the run's record and the
// reply {type: 'gardenYear', year, grows, run, buffers: {year: {positions, normals, indices, part,
// ranges, instances, moss_S}}, ms} sends them as the trees' buffers are sent (copied once,
// transferred, reused when the page gave them back); a newer 'year' of the client drops an older
// one still queued (no reply: the page's request of that group was superseded too), and a 'year'
// whose `grows` is not the lab's runGrows() (asked of a garden since regrown) is answered {stale:
// true}; `run` is runGrows() (the grow of the garden the year is of).
// Table: the garden bindings' gardenTableJson; presets: the tree study's (the species picker);
// decode: gardenDecodeJson (the default garden with the link's keys).
// An 'export' ({format: glb | svg | json | heightmap}) answers with the run's bytes (the bytes of
// `niwa garden grow --url HASH --out g.glb`), transferred, or an error naming "download".
// Blow: 'wind' ({play, wind?}) and 'poseDone' run the wind over the last garden's trees
// (web/worker/garden_blow.js) in the state's wind rows; an update or a 'year' stops it. 'windRows'
// ({wind: {wind_speed, ...}}) sets the state's wind on the last run without regrowing
// ('gardenWindRows' {hash, state}, or an error naming "wind.<key>" with control: 'windRows').
// An 'image' ({role: heightmap | mask, name, bytes}) is an opened PNG for the heightmap ground or
// the density mask, decoded in the core and kept by name ('imageLoaded' or an error naming
// "ground.file" or "mask"); a 'mesh' a dropped mesh ('meshLoaded' or an error naming "mesh").
// Hybrid trees (thesis ch. 4, the grove's; web/garden/garden_hybrid.js): 'hybrid' ({year, grows})
// builds each distinct tree's hybrid scene of that year and answers {type: 'gardenAtlas', year,
// run, atlases: [per group {atlasSize, nodes, bark, leaves, flowers}]} (the card atlas's geometry, as the
// tree handler's 'tree' hybrid; nodes: the tree's sway node points, its pose block's length); 'hybridViews' ({tag, light, bark, views: [{group, slot, camera: {eye,
// target, fovY, width, height}}]}) answers {type: 'gardenDrawLists', tag, run, lists: [per view
// {group, slot, cards: {positions, uvs, indices, joints, weights}, lines: {positions, colors,
// widths}}]}, each view's eq. 4.1 choice with its (group, slot)'s hysteresis.
// Messages: web/worker/protocol.js. Does not: load the module, route messages or catch errors
// (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';
import { TransferPool, closeLabSession, exportLabDownload } from './transfer.js';
import { nextTask } from './next_task.js';
import { createBlow } from './garden_blow.js';

export function createHandler(Module, ctx) {
  const { post, isLatest } = ctx;
  const paramTable = JSON.parse(Module.gardenTableJson());
  const windTable = JSON.parse(Module.gardenWindTableJson());
  const species = JSON.parse(Module.presetsJson('tree')).map((p) => p.name);
  const decode = (hash) => JSON.parse(Module.gardenDecodeJson(hash));
  const labs = new Map();  // client -> {lab, working, lastPost}
  const returned = new TransferPool();

  function labOf(client) {
    if (!labs.has(client)) {
      const entry = { lab: new Module.GardenLab(), working: 0, lastPost: 0, wantYear: 0 };
      entry.lab.setProgress((stage, done, total) => {
        const now = performance.now();
        if (done !== total && now - entry.lastPost < 100) return;
        entry.lastPost = now;
        post({ type: 'progress', id: entry.working, client, stage, done, total, text: `growing: year ${done} of ${total}` });
      });
      labs.set(client, entry);
    }
    return labs.get(client);
  }

  const blow = createBlow({ post, returned, labOf });

  async function update(msg, client) {
    const { id } = msg;
    const entry = labOf(client);
    blow.stop(client);  // the wind swayed the garden before this one
    await nextTask();  // a newer update already queued supersedes this one
    if (!isLatest(client, id)) return;
    entry.working = id;
    post({ type: 'progress', id, client, stage: 'grow', done: 0, total: 0, text: 'laying out the garden' });
    const t0 = performance.now();
    let error = errorOf(entry.lab.start(JSON.stringify(msg.state || {})));
    // A garden year a step; between them the worker takes its messages, and a newer update
    // supersedes this one there (within a year, not after the whole growth). The lab's last run
    // stays the one before until the last step.
    let grownMs = 0;
    while (!error) {
      const s0 = performance.now();
      const step = entry.lab.step();
      grownMs += performance.now() - s0;
      if (step === 'grown') break;
      if (step !== 'more') { error = errorOf(step); break; }
      await nextTask();
      if (!isLatest(client, id)) return;
    }
    if (error) {
      post(errorReply(error, id, client));
      return;
    }
    const growMs = grownMs;
    const statsText = entry.lab.statsJson();
    const transfer = [];
    const counts = { reused: 0, fresh: 0, dropped: 0 };
    const buffers = {};
    for (const group of ['ground', 'objects', 'trees']) buffers[group] = returned.take(client, group, entry.lab.buffers(group), transfer, counts);
    const stats = JSON.parse(statsText);
    post({
      type: 'garden', id, client, stats, statsText, hash: entry.lab.hash(), barks: barkTextures(entry.lab, stats, transfer),
      state: JSON.parse(entry.lab.stateJson()), bounds: JSON.parse(entry.lab.boundsJson()),
      years: JSON.parse(entry.lab.yearsJson()), grows: entry.lab.grows(),
      phases: JSON.parse(entry.lab.phasesJson()),
      buffers, bufferCounts: counts, growMs, wallMs: performance.now() - t0,
    }, transfer);
  }

  // Each distinct tree's simulated bark maps ({bark, barkNormal}: {width, height, pixels, digest},
  // the garden .glb's; GardenLab.barkTexture), or null where it wears the procedural bark; the
  // pixels transferred. Empty with bark 0 (the default garden: nothing more to send).
  function barkTextures(lab, stats, transfer) {
    if (!stats.bark) return [];
    const barks = [];
    for (let g = 0; g < Number(stats.trees?.distinct || 0); ++g) {
      const bark = lab.barkTexture(g, 'bark'), barkNormal = lab.barkTexture(g, 'barkNormal');
      if (bark && barkNormal) transfer.push(bark.pixels.buffer, barkNormal.pixels.buffer);
      barks.push(bark && barkNormal ? { bark, barkNormal } : null);
    }
    return barks;
  }

  // Another year of the garden grown: its trees' meshes from the run's record (nothing grows).
  async function year(msg, client) {
    const entry = labOf(client);
    blow.stop(client);  // a recorded year is drawn still
    entry.wantYear = msg.id;
    await nextTask();  // a newer 'year' already queued supersedes this one
    if (entry.wantYear !== msg.id) return;
    // Asked of a garden since regrown (the pick waited behind a grow): answered stale, not shown.
    if (msg.grows !== undefined && msg.grows !== entry.lab.runGrows()) {
      post({ type: 'gardenYear', id: msg.id, client, year: Number(msg.year), grows: entry.lab.grows(), run: entry.lab.runGrows(), stale: true, buffers: {}, ms: 0 });
      return;
    }
    const t0 = performance.now();
    const error = errorOf(entry.lab.showYear(Number(msg.year)));
    if (error) {
      post(errorReply(error, msg.id, client));
      return;
    }
    const transfer = [];
    const counts = { reused: 0, fresh: 0, dropped: 0 };
    const buffers = { year: returned.take(client, 'year', entry.lab.buffers('year'), transfer, counts) };
    post({ type: 'gardenYear', id: msg.id, client, year: Number(msg.year), grows: entry.lab.grows(), run: entry.lab.runGrows(), buffers, bufferCounts: counts, ms: performance.now() - t0 }, transfer);
  }

  // A dropped mesh ('mesh': bytes, Draco already decoded by the page), read into the client's lab
  // and kept by its name for the state's mesh objects; answered 'meshLoaded' ({name, triangles}) or
  // an error naming "mesh".
  function mesh(msg, client) {
    const entry = labOf(client);
    const name = String(msg.name || 'mesh');
    const error = errorOf(entry.lab.loadMesh(new Uint8Array(msg.bytes || new ArrayBuffer(0)), name));
    if (error) {
      post(errorReply(error, msg.id, client));
      return;
    }
    post({ type: 'meshLoaded', id: msg.id, client, mesh: { name, triangles: entry.lab.meshTriangles() } });
  }

  // An opened PNG ('image': {role: 'heightmap' | 'mask', name, bytes}), decoded in the core as the
  // garden reads it (16-bit samples kept) and kept by the client's lab by its name for the state's
  // heightmap ground or mask; answered 'imageLoaded' ({image: {role, name, width, height,
  // bit_depth, colour_type}}) or an error naming "ground.file" or "mask".
  function image(msg, client) {
    const entry = labOf(client);
    const role = msg.role === 'mask' ? 'mask' : 'heightmap';
    const name = String(msg.name || `${role}.png`);
    const error = errorOf(entry.lab.loadImage(role, new Uint8Array(msg.bytes || new ArrayBuffer(0)), name));
    if (error) {
      post(errorReply(error, msg.id, client));
      return;
    }
    post({ type: 'imageLoaded', id: msg.id, client, image: JSON.parse(entry.lab.imageJson()) });
  }

  // Hybrid trees: the atlases of every distinct tree of garden year `year`.
  function hybrid(msg, client) {
    const entry = labOf(client);
    if (msg.grows !== undefined && msg.grows !== entry.lab.runGrows()) return;  // a garden since regrown
    const error = errorOf(entry.lab.hybridBuild(Number(msg.year)));
    if (error) {
      post(errorReply(error, msg.id, client, { control: 'trees' }));
      return;
    }
    const transfer = [], counts = { reused: 0, fresh: 0, dropped: 0 };
    const atlases = [];
    for (let g = 0; g < entry.lab.hybridGroups(); ++g) {
      const atlasSize = entry.lab.hybridAtlas(g);
      const part = (name) => returned.take(client, `atlas${g}.${name}`, entry.lab.buffers(`atlas.${name}`), transfer, counts);
      atlases.push({ atlasSize, nodes: entry.lab.hybridNodes(g), bark: part('bark'), leaves: part('leaves'), flowers: part('flowers') });
    }
    post({ type: 'gardenAtlas', id: msg.id, client, year: Number(msg.year), run: entry.lab.runGrows(), atlases }, transfer);
  }

  // One round of hybrid views: each (group, slot)'s draw list for its camera in the tree's frame.
  function hybridViews(msg, client) {
    const entry = labOf(client);
    const n = (x, d) => (Number.isFinite(Number(x)) ? Number(x) : d);
    const light = msg.light || [0.3, 0.8, 0.5];
    const transfer = [], counts = { reused: 0, fresh: 0, dropped: 0 };
    const lists = [];
    (msg.views || []).forEach((v, i) => {
      const c = v.camera || {};
      const eye = c.eye || [0, 0, 10], target = c.target || [0, 0, 0];
      const error = errorOf(entry.lab.hybridView(Number(v.group), Number(v.slot), n(eye[0], 0), n(eye[1], 0), n(eye[2], 10),
        n(target[0], 0), n(target[1], 0), n(target[2], 0), n(c.fovY, Math.PI / 4), Math.round(n(c.width, 512)),
        Math.round(n(c.height, 512)), n(light[0], 0.3), n(light[1], 0.8), n(light[2], 0.5), msg.bark !== false));
      if (error) throw new Error(error.message);
      lists.push({
        group: v.group, slot: v.slot,
        cards: returned.take(client, `cards${i}`, entry.lab.buffers('cards'), transfer, counts),
        lines: returned.take(client, `lines${i}`, entry.lab.buffers('lines'), transfer, counts),
      });
    });
    post({ type: 'gardenDrawLists', id: msg.id, client, tag: msg.tag, run: entry.lab.runGrows(), lists }, transfer);
  }

  // The state's wind rows changed (the wind panel): set on the last run, nothing regrown; the reply
  // brings the run's link and state with them, or an error naming "wind.<key>" (control: 'windRows').
  function windRows(msg, client) {
    const { lab } = labOf(client);
    const error = errorOf(lab.setWind(JSON.stringify(msg.wind && typeof msg.wind === 'object' ? msg.wind : {})));
    if (error) {
      post(errorReply(error, msg.id, client, { control: 'windRows' }));
      return;
    }
    post({ type: 'gardenWindRows', id: msg.id, client, hash: lab.hash(), state: JSON.parse(lab.stateJson()) });
  }

  const FORMATS = ['glb', 'svg', 'json', 'heightmap'];
  const exportGarden = (msg, client) => exportLabDownload(labOf(client).lab, FORMATS, msg, client, post);

  const close = (client) => {
    blow.stop(client);
    return closeLabSession(labs, returned, client);
  };

  return {
    superseding: ['update'],
    close,
    ready: (msg) => ({ paramTable, windTable, species, decoded: decode(String(msg.hash || '')) }),
    messages: {
      decode: (msg, client) => post({ type: 'decoded', id: msg.id, client, ...decode(String(msg.hash || '')) }),
      update,
      year,
      mesh,
      image,
      export: exportGarden,
      wind: (msg, client) => (msg.play ? blow.start(msg, client) : blow.stop(client)),
      poseDone: (msg, client) => blow.poseDone(client),
      windRows,
      recycle: (msg, client) => returned.give(client, msg.buffers),
      hybrid,
      hybridViews,
    },
  };
}
