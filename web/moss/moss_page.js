// The moss study's page (public/moss.html, main thread; Nomura 2010): opens with a small run
// grown on the thesis scene (60 days, 4096 photons a day: a few seconds), builds the panel from
// the moss table, keeps the state in location.hash through the moss hash codec (the text `niwa
// moss grow --url` reads), picks a built-in scene or takes a dropped .glb/.gltf/.obj (read as
// `niwa moss grow --mesh` reads it; Draco decoded here by web/mesh/mesh_file.js; not part of the
// link; a bad file is one line beside the drop control) or another study's land (Land: a Niwa tree
// with its preset and years, or a Niwa terrain with its preset and seed: state fields, so the link
// regrows it, grown in the worker through core/compose), a preset, the days and the RNG seed, shows the
// land tinted by an overlay and every moss as a tuft (moss_renderer.js), and replays the run day
// by day with the day scrubber and Play (nothing regrows: every moss comes with its birth and
// death day). Growth runs in the worker (web/worker/moss_handler.js).
// Charts the population per species by day with a marker on the day shown (moss_chart.js) and
// downloads the stats (.json, as `niwa moss grow --stats`) and the days as CSV made from them;
// offers an embed (<niwa-moss>, public/niwa-moss.js, or the iframe) of the page's hash.
// The A/B view grows a second run beside the first (a second client of the worker, drawn to its
// right with the same camera, day and overlay): the same state with indirect light switched, or at
// the other of fig 4.3's temperatures (288.15 / 293.15 K), on the scene or the dropped mesh (the
// file's bytes go to the worker once, transferred; run B's lab shares the mesh run A's lab read).
// The Moss .glb and Moss .json downloads are the worker's run's own bytes (MossLab.build: the
// bytes of `niwa moss grow --url HASH --out`). Does not: parse or check states (the core does; its
// one line is shown beside its field), build the exports' bytes itself, or draw directly.
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { Frame } from '../gl/frame.js';
import { OrbitCamera } from '../gl/orbit_camera.js';
import { ProgressiveLoop } from '../gl/progressive_loop.js';
import { DEFAULT_SUNS } from '../gl/sun.js';
import { ParamPanel } from '../shell/param_panel.js';
import { StepScrubber } from '../shell/step_scrubber.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { Notices, copyLink, download, mountStudyNav, showEmbedDialog } from '../shell/study_page.js';
import { FileDrop } from '../shell/file_drop.js';
import { sendMeshFile } from '../mesh/mesh_file.js';
import { setHooks } from '../shell/test_hooks.js';
import { PopulationChart, populationCsv } from './moss_chart.js';
import { MossRenderer } from './moss_renderer.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'), stats: $('stats'), progress: $('progress'), scene: $('scene'), sceneHelp: $('scene-help'),
  preset: $('preset'), presetHelp: $('preset-help'), days: $('days'), rngSeed: $('rng-seed'), reset: $('reset'),
  overlay: $('overlay'), overlayHelp: $('overlay-help'), compare: $('compare'), compareHelp: $('compare-help'), resetView: $('reset-view'), copyLink: $('copy-link'), shareStatus: $('share-status'),
  params: $('params'), play: $('play'), day: $('day'), dayText: $('day-text'), cancel: $('cancel'),
  downloadStats: $('download-stats'), downloadCsv: $('download-csv'), meshFile: $('mesh-file'), meshError: $('mesh-error'),
  land: $('land'), landHelp: $('land-help'), landTree: $('land-tree'), landTerrain: $('land-terrain'),
  treePreset: $('tree-preset'), treeYears: $('tree-years'), terrainPreset: $('terrain-preset'), terrainSeed: $('terrain-seed'),
  landRocks: $('land-rocks'), rockTriangles: $('rock-triangles'),
};
const chart = new PopulationChart($('population-chart'), $('population-legend'), $('population-marker'));
let lastStats = null;  // the stats of the run shown (the downloads' source)
mountStudyNav($('studies'), 'moss');

const notices = new Notices($('notice'), ['webgl', 'error', 'hash', 'mesh']);
// Errors beside the controls outside the panel (the panel's rows find their own).
const BASIC_FIELDS = {
  scene: 'scene-error', mesh: 'mesh-error', preset: 'preset-error', days: 'days-error', seed: 'rng-seed-error',
  tree: 'tree-preset-error', tree_years: 'tree-years-error', terrain: 'terrain-preset-error', terrain_seed: 'terrain-seed-error',
  rock_triangles: 'rock-triangles-error',
};
const controller = new StudyController({
  study: 'moss', notices, ui, fields: BASIC_FIELDS, panel: () => panel, state: () => currentState(false),
  onCancel: () => {
    if (!useMesh) return 'cancelled: back to the last finished run';
    useMesh = false;  // the new worker has no mesh
    showHelp();
    return 'cancelled: the dropped mesh is dropped; back to the last finished run on a built-in scene';
  },
  onRestart: () => {
    restarting = true;
    worker.request('init', { hash: '' }, { done: ['ready'] });
  },
  onError: (msg, when) => {
    // A dropped file's read failed: its line beside the drop control; the run shown stays.
    if (when === 'before' && meshRequest && msg.id === meshRequest) {
      meshRequest = 0;
      showMeshError(msg.message);
      ui.progress.textContent = '';
      return true;
    }
    if (when === 'after') {
      ui.days.setAttribute('aria-invalid', msg.field === 'days' ? 'true' : 'false');
      ui.rngSeed.setAttribute('aria-invalid', msg.field === 'seed' ? 'true' : 'false');
    }
    return false;
  },
});
const { worker } = controller;
let restarting = false;
let lastGoodHash = null;
let useMesh = false;   // grow on the dropped mesh, not a built-in scene
let meshInfo = null;   // {name, triangles} of the dropped mesh
let meshRequest = 0;   // the id of the 'mesh' request in flight

// The opening run when the link holds no state: a result without input, small enough to grow in
// a few seconds in the page (the CLI's default is 300 days at 8192 photons: about 30 s).
const OPENING = { preset: 'nomura2010', scene: 'thesis', days: 60, seed: 1, params: { photons: 4096 } };
const OPENING_HASH = '#preset=nomura2010&days=60&photons=4096';
// What an overlay's ramp shows: its field's name and unit (dark blue at the minimum, pale yellow
// at the maximum over the land).
const FIELD_TEXT = {
  irradiance: ['irradiance S', ' W/m²'], T_s: ['T_s', ' K'], rh_s: ['rh_s', ''], theta: ['theta', ''], fitness: ['best-species G', ''],
};
const fmt = (x) => Number(Number(x).toPrecision(4));

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let frame = null;
let renderer = null;
let rendererB = null;  // the A/B view's right-hand run
let mossSerial = 0;
let installedSerial = 0;
let shownDay = Infinity;
let lastDay = 0;
const loop = new ProgressiveLoop({
  renderer: () => (renderer ? frame : null),
  camera,
  onDrawn: (drawn) => {
    const alive = renderer ? renderer.aliveOn(Number.isFinite(shownDay) ? shownDay : lastDay) : { total: 0 };
    const aliveB = rendererB?.mosses ? rendererB.aliveOn(Number.isFinite(shownDay) ? shownDay : lastDay).total : '';
    setHooks({ drawnSerialB: bInstalled, drawnMossesB: aliveB, drawnOverlay: renderer?.overlay ?? '' });
    setHooks({ drawnSerial: installedSerial, drawnDay: Number.isFinite(shownDay) ? shownDay : lastDay, drawnMosses: alive.total, drawnTriangles: drawn.triangles, drawCalls: drawn.drawCalls });
  },
});
const requestFrame = () => loop.request();

// The day scrubber and Play: the mosses alive on day k (born on or before it, not dead by it).
const scrubber = new StepScrubber({ range: ui.day, text: ui.dayText, play: ui.play }, (k) => {
  shownDay = k >= lastDay ? Infinity : k;
  renderer?.setDay(k);
  rendererB?.setDay(k);
  const alive = renderer ? renderer.aliveOn(k) : { total: 0, bySpecies: [0, 0, 0] };
  const [g, h, s] = alive.bySpecies;
  ui.dayText.textContent = `day ${k} of ${lastDay} · ${alive.total} mosses (${g} gingoke, ${h} haigoke, ${s} sugigoke)`;
  const marked = chart.mark(k);
  setHooks({ dayShown: k, chartDay: marked, mossesShown: alive.total, coverageShown: (renderer?.coverageShown ?? 0).toFixed(6) });
  loop.request(true);  // the picked day at the next animation frame (issue 29: the scrubber in ≤ 100 ms)
}, { interval: 120 });

async function startRenderer() {
  try {
    await loop.start(async () => {
      // No MSAA on a CPU rasteriser: it triples the frame that answers the day scrubber (issue 29
      // item 6: the scrubber in ≤ 100 ms; 140 ms a frame with it on SwiftShader).
      frame = new Frame(ui.canvas, { camera, sun: DEFAULT_SUNS.ivy, ground: false, fit: true, request: () => loop.request(), what: 'the moss' });
      await frame.init();
      renderer = await frame.addLayer(new MossRenderer(frame));
      rendererB = await frame.addLayer(new MossRenderer(frame, { beside: 1.15 }));
      showOverlay();
      return frame;
    }, {
      canvas: ui.canvas, camera,
      onLost: () => notices.set('webgl', 'The WebGL2 context was lost; reload the page to draw again.'),
    });
  } catch (e) {
    renderer = null;
    setHooks({ drawing: 'off' });
    notices.set('webgl', `Cannot draw: ${e.message}`);
  }
}

function frameLand() {
  let b = renderer?.bounds();
  if (!b) return;
  const bB = rendererB?.bounds();
  if (bB) b = { min: b.min.map((x, i) => Math.min(x, bB.min[i])), max: b.max.map((x, i) => Math.max(x, bB.max[i])) };
  camera.reset(b);
  camera.pitch = 0.55;
  camera.frame(b, useMesh || bB ? 1.1 : 0.9);  // a dropped mesh or the A/B pair whole; a scene a little closer
}

// ---------------------------------------------------------------- state
let panel = null;
let presets = [];
let scenes = [];
let frameNext = true;

// The state the worker grows: scene, preset, days, RNG seed and (unless `reset`, which takes the
// preset's values) every row of the panel.
function currentState(reset) {
  const land = ui.land.value;
  const state = {
    preset: ui.preset.value, scene: land === 'scene' ? ui.scene.value : land, days: numberOr(ui.days), seed: numberOr(ui.rngSeed),
  };
  if (land === 'tree') Object.assign(state, { tree: ui.treePreset.value.trim(), tree_years: numberOr(ui.treeYears) });
  if (land === 'terrain') Object.assign(state, { terrain: ui.terrainPreset.value.trim(), terrain_seed: numberOr(ui.terrainSeed) });
  if (land === 'scene' && ui.scene.value === 'rocks') state.rock_triangles = numberOr(ui.rockTriangles);
  state.params = reset ? {} : panel.values();
  return state;
}

// The Land control: a built-in scene (the scene select), or a Niwa tree or terrain (their fields).
function showLand() {
  const land = ui.land.value;
  ui.landTree.hidden = land !== 'tree';
  ui.landTerrain.hidden = land !== 'terrain';
  ui.landRocks.hidden = !(land === 'scene' && ui.scene.value === 'rocks');  // the rocks scene's size knob
  ui.scene.disabled = land !== 'scene';
  ui.landHelp.textContent = land === 'tree' ? 'Moss on a grown Niwa tree: its bark (sandy) and a square of humus around its foot.'
    : land === 'terrain' ? 'Moss on a grown Niwa terrain (metres, y up): a mountain of a few hundred metres, so the photons spread thin.' : '';
}

function applyState(state) {
  ui.preset.value = state.preset;
  if (state.scene === 'tree' || state.scene === 'terrain') {
    ui.land.value = state.scene;
    if (state.tree !== undefined) ui.treePreset.value = state.tree;
    if (state.tree_years !== undefined) ui.treeYears.value = String(state.tree_years);
    if (state.terrain !== undefined) ui.terrainPreset.value = state.terrain;
    if (state.terrain_seed !== undefined) ui.terrainSeed.value = String(state.terrain_seed);
  } else {
    ui.land.value = 'scene';
    ui.scene.value = state.scene;
    if (state.rock_triangles !== undefined) ui.rockTriangles.value = String(state.rock_triangles);
  }
  showLand();
  ui.days.value = String(state.days);
  ui.rngSeed.value = String(state.seed);
  panel.setValues(state.params);
  showHelp();
}

function showHelp() {
  const scene = ui.land.value === 'scene' ? scenes.find((s) => s.name === ui.scene.value) : null;
  ui.sceneHelp.textContent = useMesh && meshInfo ? `Growing on the dropped mesh ${meshInfo.name} (${meshInfo.triangles} triangles); pick a scene to go back.`
    : scene ? `${scene.description} (${scene.cells} soil cells)` : '';
  notices.set('mesh', useMesh && meshInfo ? `Growing on the dropped mesh ${meshInfo.name}; a dropped mesh is not part of the link.` : '');
  const preset = presets.find((p) => p.name === ui.preset.value);
  ui.presetHelp.textContent = preset ? preset.source : '';
}

const sendUpdate = (commit, reset = false, state = null) =>
  controller.update(commit, { state: state || currentState(reset), useMesh }, { done: ['moss'] });
const scheduleUpdate = (stage = 'grow') => controller.schedule(() => sendUpdate(true), stage);

// ---------------------------------------------------------------- worker replies
worker.on('ready', (msg) => {
  if (restarting) {
    restarting = false;
    worker.request('decode', { hash: lastGoodHash ? `#${lastGoodHash}` : OPENING_HASH }, { done: ['decoded'] });
    return;
  }
  presets = msg.presets;
  scenes = msg.scenes;
  for (const p of presets) ui.preset.append(new Option(p.name, p.name));
  for (const s of scenes) ui.scene.append(new Option(s.name, s.name));
  panel = new ParamPanel(ui.params, msg.paramTable, (spec, stage) => scheduleUpdate(stage));
  const hash = location.hash.replace(/^#/, '');
  notices.set('hash', msg.decoded.notices);
  if (!/(^|&)(preset|scene|days|seed)=/.test(hash)) {
    // No state in the link: the opening run (its rows over the preset's, as a link would set).
    applyState(msg.decoded.state);
    ui.days.value = String(OPENING.days);
    panel.setValues(OPENING.params);
    sendUpdate(false);
  } else {
    applyState(msg.decoded.state);
    sendUpdate(false);
  }
});

worker.on('decoded', (msg) => {
  applyState(msg.state);
  notices.set('hash', msg.notices);
  frameNext = true;
  sendUpdate(false);
});

worker.on('progress', (msg) => {
  ui.progress.textContent = msg.text;
});

worker.on('moss', (msg) => {
  if (!controller.isLatest(msg)) return;
  notices.set('error', '');
  controller.showFieldError('');
  ui.days.setAttribute('aria-invalid', 'false');
  ui.rngSeed.setAttribute('aria-invalid', 'false');
  lastGoodHash = msg.hash;
  applyState(msg.state);
  const s = msg.stats;
  lastStats = s;
  lastDay = msg.bounds.days;
  chart.set(s);
  if (renderer) {
    renderer.setMoss(msg.buffers, msg.bounds, Number(msg.state.params.moss_size) || 0.01);
    showOverlay();
    setHooks({ coverageReplayError: renderer.coverageReplayError });
    installedSerial = mossSerial + 1;
    if (frameNext) {
      frameLand();
      frameNext = false;
    }
  }
  // The views were used at once (copied to the GPU): they go back for the next grow to fill.
  worker.recycle(msg.buffers);
  stateA = msg.state;
  controller.grown(msg.hash);
  mossSerial += 1;
  scrubber.reset(lastDay);
  controller.showWork(false);
  ui.progress.textContent = '';
  const m = s.mosses;
  const landText = s.scene === 'mesh' ? s.mesh : s.scene === 'tree' ? `tree ${s.tree} (${s.tree_years} years)`
    : s.scene === 'terrain' ? `terrain ${s.terrain} (seed ${s.terrain_seed})` : s.scene || ui.scene.value;
  ui.stats.textContent = `${landText} · ${lastDay} days · ${m.total} mosses (${m.by_species.gingoke} gingoke, ${m.by_species.haigoke} haigoke, ${m.by_species.sugigoke} sugigoke) · ${m.on_mosses} on mosses · ${msg.bounds.mosses_ever} ever · ${(msg.growMs / 1000).toFixed(1)} s`;
  setHooks({
    status: 'ready', error: '', mossSerial, mosses: m.total, mossesEver: msg.bounds.mosses_ever, days: lastDay,
    stats: JSON.stringify(s), statsText: msg.statsText, hash: msg.hash, sceneShown: s.scene === 'mesh' ? `mesh:${s.mesh}` : s.scene === 'tree' ? `tree:${s.tree}` : s.scene === 'terrain' ? `terrain:${s.terrain}` : s.scene, wallMs: msg.wallMs.toFixed(1), growMs: msg.growMs.toFixed(1),
    buffersReused: msg.bufferCounts?.reused ?? '', buffersFresh: msg.bufferCounts?.fresh ?? '',
  });
  requestFrame();
  growB();
});

// ---------------------------------------------------------------- the A/B view
// Run B: run A's resolved state with one row switched (indirect 1 <-> 0; T 288.15 <-> 293.15, any
// other T going to 293.15), grown by a second client after each run A, on A's scene or mesh.
const clientB = controller.client('moss-b');
let stateA = null;
let bSerial = 0;
let bInstalled = 0;
let textB = '';
let frameB = false;  // frame both runs when B comes (the view was just switched on)

function stateB(a, mode) {
  const params = { ...a.params };
  if (mode === 'indirect') params.indirect = Number(params.indirect) === 1 ? 0 : 1;
  else params.T = Number(params.T) === 293.15 ? 288.15 : 293.15;
  return { ...a, params };
}

const sideText = (mode, state) => (mode === 'indirect' ? `indirect ${Number(state.params.indirect) === 1 ? 'on' : 'off'}` : `T ${state.params.T} K`);

function growB() {
  const mode = ui.compare.value;
  if (mode === 'off' || !stateA) {
    rendererB?.clear();
    showOverlay();
    textB = '';
    ui.compareHelp.textContent = '';
    setHooks({ compare: 'off', hashB: '', statsB: '' });
    requestFrame();
    return;
  }
  const b = stateB(stateA, mode);
  ui.compareHelp.textContent = `Left: ${sideText(mode, stateA)}; right: growing with ${sideText(mode, b)}…`;
  setHooks({ compare: mode, statusB: 'growing' });
  // On a dropped mesh run B grows on the mesh run A's client read (meshOf: the worker shares it).
  clientB.request('update', useMesh ? { state: b, useMesh, meshOf: worker.name } : { state: b, useMesh }, { done: ['moss'] });
}

clientB.on('moss', (msg) => {
  if (msg.id !== clientB.latestId('update')) return;
  const mode = ui.compare.value;
  if (mode === 'off') return;
  const s = msg.stats;
  if (rendererB) {
    rendererB.setMoss(msg.buffers, msg.bounds, Number(msg.state.params.moss_size) || 0.01);
    showOverlay();
    rendererB.setDay(Number.isFinite(shownDay) ? shownDay : lastDay);
    if (frameB) frameLand();
    frameB = false;
  }
  clientB.recycle(msg.buffers);
  bSerial += 1;
  bInstalled = bSerial;
  textB = `${sideText(mode, msg.state)}: ${s.mosses.total} mosses`;
  ui.compareHelp.textContent = `Left: ${sideText(mode, stateA)}, ${lastStats?.mosses.total ?? 0} mosses; right: ${textB} (day ${lastDay}).`;
  setHooks({ statusB: 'ready', serialB: bSerial, hashB: msg.hash, statsB: JSON.stringify(s), statsTextB: msg.statsText, mossesB: s.mosses.total });
  requestFrame();
});
clientB.on('error', (msg) => {
  if (msg.id !== clientB.latestId('update')) return;
  ui.compareHelp.textContent = `Right: ${msg.message}`;
  setHooks({ statusB: 'error', errorB: msg.message });
});

ui.compare.addEventListener('change', () => {
  frameB = true;
  growB();
  if (ui.compare.value === 'off') {
    frameLand();
    requestFrame();
  }
});

// ---------------------------------------------------------------- dropped meshes
// One line beside the drop control (a refused name, a file the core cannot read, a run the mesh
// cannot start); '' clears it.
function showMeshError(line) {
  ui.meshError.textContent = line;
  ui.meshError.hidden = !line;
  setHooks({ meshError: line });
}

async function loadMeshFile(file) {
  showMeshError('');
  ui.progress.textContent = `reading ${file.name}`;
  try {
    const sent = await sendMeshFile(worker, file);
    meshRequest = sent.id;
    setHooks({ meshTransferred: sent.transferred ? 'yes' : 'no' });
  } catch (e) {
    ui.progress.textContent = '';
    showMeshError(`mesh: ${String(file.name).slice(0, 60)}: ${e.message}`);
  }
}

worker.on('meshLoaded', (msg) => {
  if (!meshRequest || msg.id !== meshRequest) return;
  meshRequest = 0;
  meshInfo = msg.mesh;
  useMesh = true;
  showHelp();
  frameNext = true;
  setHooks({ meshName: meshInfo.name, meshTriangles: meshInfo.triangles });
  sendUpdate(false);
});

new FileDrop({
  target: $('stage'), input: ui.meshFile, accept: ['.glb', '.gltf', '.obj'],
  onFiles: (files) => loadMeshFile(files[0]),
  onRefuse: (line) => showMeshError(`mesh: ${line}`),
});

// ---------------------------------------------------------------- controls
ui.scene.addEventListener('change', () => {
  useMesh = false;
  showLand();
  showHelp();
  frameNext = true;
  sendUpdate(true);
});
ui.land.addEventListener('change', () => {
  useMesh = false;
  showLand();
  showHelp();
  frameNext = true;
  sendUpdate(true);
});
for (const input of [ui.treePreset, ui.treeYears, ui.terrainPreset, ui.terrainSeed, ui.rockTriangles]) {
  input.addEventListener('input', () => {
    frameNext = true;
    scheduleUpdate();
  });
}
ui.preset.addEventListener('change', () => {
  showHelp();
  sendUpdate(true, true);
});
ui.days.addEventListener('input', () => scheduleUpdate());
ui.rngSeed.addEventListener('input', () => scheduleUpdate());
ui.reset.addEventListener('click', () => sendUpdate(true, true));
// The overlay chosen, on the land, with a line saying what its colours mean.
function showOverlay() {
  rendererB?.setOverlay(ui.overlay.value);
  renderer?.setOverlay(ui.overlay.value);
  // With the A/B view both runs share the ramp's ends (the union of their ranges), so the same
  // colour is the same value on both sides.
  const ra = renderer?.fieldRange(), rb = rendererB?.fieldRange();
  const shared = ra && rb ? { min: Math.min(ra.min, rb.min), max: Math.max(ra.max, rb.max) } : null;
  if (renderer) renderer.sharedRange = shared;
  if (rendererB) rendererB.sharedRange = shared;
  const shown = renderer ? renderer.overlayShown() : { overlay: ui.overlay.value };
  let text = '';
  if (shown.field) {
    const [name, unit] = FIELD_TEXT[shown.field];
    const both = rendererB?.fieldRange() ? ' (both runs)' : '';
    text = shown.min === shown.max ? `${name} of the last day: ${fmt(shown.min)}${unit} on every cell`
      : `${name} of the last day${both}: dark blue ${fmt(shown.min)}${unit} to pale yellow ${fmt(shown.max)}${unit}`;
  } else if (shown.overlay === 'photons') {
    text = `The last day's stored photons: ${shown.direct} direct (yellow), ${shown.bounced} bounced (blue).`;
  } else if (shown.overlay === 'coverage') {
    text = 'Green where mosses cover the land on the day shown.';
  }
  ui.overlayHelp.textContent = text;
  setHooks({ overlay: shown.overlay, overlayField: shown.field || '', overlayMin: shown.min ?? '', overlayMax: shown.max ?? '',
    photonsDirect: shown.direct ?? '', photonsBounced: shown.bounced ?? '' });
}
ui.overlay.addEventListener('change', () => {
  setHooks({ drawnOverlay: '' });  // until a frame with it is drawn
  showOverlay();
  requestFrame();
});
ui.resetView.addEventListener('click', () => {
  frameLand();
  requestFrame();
});
ui.copyLink.addEventListener('click', () => copyLink(ui.shareStatus));
// The embed: <niwa-moss> (public/niwa-moss.js) or an iframe of public/embed.html?study=moss, both
// with the page's hash (a dropped mesh is not in it).
$('embed').addEventListener('click', () => {
  showEmbedDialog({ tag: 'niwa-moss', title: 'Niwa moss', heading: 'Embed this moss', script: 'niwa-moss.js', frame: 'embed.html?study=moss' });
});
// Downloads of the run shown: its stats as the CLI's --stats writes them, and its days as CSV.
const baseName = () => `moss-${lastStats?.scene || 'run'}-${lastDay}d`;
ui.downloadStats.addEventListener('click', () => {
  if (lastStats) download(new Blob([`${JSON.stringify(lastStats)}\n`], { type: 'application/json' }), `${baseName()}-stats.json`, ui.shareStatus);
});
ui.downloadCsv.addEventListener('click', () => {
  if (lastStats) download(new Blob([populationCsv(lastStats)], { type: 'text/csv' }), `${baseName()}-days.csv`, ui.shareStatus);
});
// The run's outputs from the worker's one run (the bytes `niwa moss grow --out` writes for the same
// state: the last day, whatever day the scrubber shows).
const runName = () => `moss-${lastStats?.scene || 'run'}-${lastStats?.days ?? 0}d`;
$('download-glb').addEventListener('click', () => {
  if (lastStats) controller.exportAs('glb', `${runName()}.glb`, 'model/gltf-binary');
});
$('download-json').addEventListener('click', () => {
  if (lastStats) controller.exportAs('json', `${runName()}.json`, 'application/json');
});

// ---------------------------------------------------------------- start
setHooks({ status: 'loading' });
await startRenderer();
worker.request('init', { hash: location.hash }, { done: ['ready'] });
