// The bark study's page (public/bark.html, main thread; paper 003, Hirota, Kato, Kaneko; spec
// §6 "Browser"): opens with the camphor preset grown on its 128 × 64 lattice (a 64 × 32 preview
// first, in about a second), builds the panel from the bark table, keeps the state in
// location.hash through the bark hash codec (the text `niwa bark grow --url` reads), picks the
// species, the model and the RNG seed, shows the unrolled tile animating as it cracks (frames of
// the lattice while the worker grows it), then the base-colour map on the tile and a trunk segment
// wearing the maps (bark_renderer.js); replays the cracks tenth of a cycle by tenth with the cycle
// scrubber and Play (nothing regrows: each triangle comes with the step it broke), charts the
// broken fraction of each spring family and the plates' mean width and height against time (the
// run's per-tenth-cycle samples), colours the tile by layer (S, M1, M2, inner: the 4-layer model)
// or by peel state and toggles the broken springs over it, runs the three species for a Table 3
// beside the paper's numbers, and downloads the maps, the trunk segment's .glb (the bytes of
// `niwa bark grow --url HASH --out trunk.glb`) and the CSV. Growth runs in the worker
// (web/worker/bark_handler.js).
// Does not: parse or check states (the core does; its one line is shown beside its field), or
// draw directly.
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { Frame } from '../gl/frame.js';
import { OrbitCamera } from '../gl/orbit_camera.js';
import { ProgressiveLoop } from '../gl/progressive_loop.js';
import { DEFAULT_SUNS } from '../gl/sun.js';
import { ParamPanel } from '../shell/param_panel.js';
import { StepScrubber } from '../shell/step_scrubber.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { Notices, copyLink, mountStudyNav, showEmbedDialog } from '../shell/study_page.js';
import { bumpHook, setHooks } from '../shell/test_hooks.js';
import { drawBrokenChart, drawPlateChart, parseCyclesCsv, sampleAt } from './bark_chart.js';
import { BarkRenderer } from './bark_renderer.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'), stats: $('stats'), progress: $('progress'), species: $('species'), speciesHelp: $('species-help'),
  model: $('model'), rngSeed: $('rng-seed'), reset: $('reset'), tileView: $('tile-view'), resetView: $('reset-view'),
  copyLink: $('copy-link'), shareStatus: $('share-status'), params: $('params'), play: $('play'), cycle: $('cycle'),
  cycleText: $('cycle-text'), cancel: $('cancel'), chart: $('chart'), chartCaption: $('chart-caption'),
  table3Run: $('table3-run'), table3: $('table3'), table3Error: $('table3-error'),
  showBroken: $('show-broken'), tileLegend: $('tile-legend'), plateChart: $('plate-chart'), plateChartCaption: $('plate-chart-caption'),
};
mountStudyNav($('studies'), 'bark');

const notices = new Notices($('notice'), ['webgl', 'error', 'hash']);
// Errors beside the controls outside the panel (the panel's rows find their own).
const BASIC_FIELDS = { species: 'species-error', model: 'model-error', seed: 'rng-seed-error' };
const controller = new StudyController({
  study: 'bark', notices, ui, fields: BASIC_FIELDS, panel: () => panel, state: () => currentState(false),
  onCancel: () => {
    ui.table3Run.disabled = false;
    return 'cancelled: back to the last finished bark';
  },
  onRestart: () => {
    restarting = true;
    worker.request('init', { hash: '' }, { done: ['ready'] });
  },
  onError: (msg, when) => {
    if (msg.control === 'table3') {
      ui.table3Error.textContent = msg.message;
      ui.table3Error.hidden = false;
      ui.table3Run.disabled = false;
      controller.showWork(controller.inFlight);
      return true;
    }
    if (when === 'after') ui.rngSeed.setAttribute('aria-invalid', msg.field === 'seed' ? 'true' : 'false');
    return false;
  },
});
const { worker } = controller;
let restarting = false;
let lastGoodHash = null;

// Table 3 of the paper (experiment column, cm: width around × height along; spec §4.1). null:
// "(>20)", a region the whole patch high.
const PAPER_TABLE3 = {
  camphor: { mean: [1.58, 11.6], max: [2.06, null] },
  tallow: { mean: [1.70, 3.02], max: [2.08, 3.96] },
  pine: { mean: [2.34, 4.28], max: [3.24, 6.48] },
};

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let frame = null;
let renderer = null;
let barkSerial = 0;
let installedSerial = 0;
let framesSeen = 0;
let framesInstalled = 0;  // the live frames put on the renderer (data-drawn-frame: the last one drawn)
let livePhase = '';       // the phase of the last of them (preview or full)
let liveFullDrawn = 0;    // distinct full-lattice frames drawn while a run grows (data-live-full-drawn)
let lastFullDrawn = -1;
// A live frame is drawn in full before the next replaces it: on a slow GPU (SwiftShader under load)
// a frame drawn in parts takes longer than the worker's 100 ms between frames, and installing each
// as it came restarted the frame every time, so no growing lattice was ever finished on screen
// (and a frame in parts could mix two steps). A frame arriving meanwhile waits here; a newer one
// replaces it.
let liveWaiting = null;   // the newest live frame not yet installed
let liveDrawing = false;  // the installed live frame has not been drawn in full yet
const loop = new ProgressiveLoop({
  renderer: () => (renderer ? frame : null),
  camera,
  onDrawn: (drawn) => {
    if (renderer?.live && livePhase === 'full' && framesInstalled !== lastFullDrawn) {
      lastFullDrawn = framesInstalled;
      liveFullDrawn += 1;
    }
    liveDrawing = false;
    if (liveWaiting) {
      const next = liveWaiting;
      liveWaiting = null;
      installLive(next);
    }
    setHooks({ drawnSerial: installedSerial, drawnFrame: framesInstalled, drawnPhase: renderer?.live ? livePhase : '', liveFullDrawn, drawnTriangles: drawn.triangles, drawCalls: drawn.drawCalls, tileShows: renderer?.tileShows ?? '' });
  },
});
const requestFrame = () => loop.request();

// The last finished run: bounds, samples of the CSV, the scrubber's step per position.
let shown = null;  // {bounds, samples, springs, cycles, stepsPerCycle}

// Scrubber position k (tenths of a cycle; the last position is the end, after settling) -> step.
const stepOf = (k) => (shown && k < shown.cycles * 10 ? Math.round((k * shown.stepsPerCycle) / 10) : Infinity);

const scrubber = new StepScrubber({ range: ui.cycle, text: ui.cycleText, play: ui.play }, (k) => {
  if (!shown) return;
  const step = stepOf(k);
  renderer?.setStep(step);
  const s = sampleAt(shown.samples, step);
  const all = shown.springs.axial + shown.springs.diagonal;
  const broken = s ? s.broken_axial + s.broken_diagonal : 0;
  const when = Number.isFinite(step) ? `${(k / 10).toFixed(1)} of ${shown.cycles}` : `${shown.cycles} of ${shown.cycles}, settled`;
  ui.cycleText.textContent = `${when} · ${((100 * broken) / all).toFixed(1)} % broken`;
  ui.cycleText.title = `${broken} of ${all} springs broken`;
  drawBrokenChart(ui.chart, shown.samples, shown.springs, shown.stepsPerCycle, step);
  drawPlateChart(ui.plateChart, shown.samples, shown.stepsPerCycle, step);
  setHooks({ plateShown: s ? `${s.plates}:${s.plate_mean_w}:${s.plate_mean_h}` : '' });
  setHooks({ cycleShown: k, stepShown: Number.isFinite(step) ? step : 'end', brokenShown: broken });
  requestFrame();
}, { interval: 150 });

async function startRenderer() {
  try {
    await loop.start(async () => {
      frame = new Frame(ui.canvas, { camera, sun: DEFAULT_SUNS.ivy, ground: false, fit: true, request: () => loop.request(), what: 'the bark' });
      await frame.init();
      renderer = await frame.addLayer(new BarkRenderer(frame));
      renderer.setView(ui.tileView.value);
      renderer.setShowBroken(ui.showBroken.checked);
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

// Looks straight at the tile and the trunk, filling the view's width or height.
function frameBark() {
  const b = renderer?.bounds();
  if (!b) return;
  camera.yaw = 0;
  camera.pitch = 0.04;
  camera.frame(b, 1.0);
  const aspect = ui.canvas.clientWidth / Math.max(1, ui.canvas.clientHeight) || 1;
  const t = Math.tan(camera.fov / 2);
  camera.distance = 1.1 * Math.max(b.max[1] / t, b.max[0] / (t * aspect)) + b.max[2];
}

// ---------------------------------------------------------------- state
let panel = null;
let presets = [];
let frameNext = true;

// The state the worker grows: species, model, RNG seed and (unless `reset`, which takes the
// species' values) every row of the panel.
function currentState(reset) {
  return { species: ui.species.value, model: ui.model.value, seed: numberOr(ui.rngSeed), params: reset ? {} : panel.values() };
}

function applyState(state) {
  ui.species.value = state.species;
  ui.model.value = state.model;
  ui.rngSeed.value = String(state.seed);
  panel.setValues(state.params);
  showHelp();
}

function showHelp() {
  const preset = presets.find((p) => p.name === ui.species.value);
  ui.speciesHelp.textContent = preset ? preset.source : '';
}

const sendUpdate = (commit, reset = false) => controller.update(commit, { state: currentState(reset) }, { done: ['bark'] });
const scheduleUpdate = (stage = 'grow') => controller.schedule(() => sendUpdate(true), stage);

// ---------------------------------------------------------------- worker replies
worker.on('ready', (msg) => {
  if (restarting) {
    restarting = false;
    worker.request('decode', { hash: lastGoodHash ? `#${lastGoodHash}` : '' }, { done: ['decoded'] });
    return;
  }
  presets = msg.presets;
  for (const p of presets) ui.species.append(new Option(p.title ? `${p.name} · ${p.title}` : p.name, p.name));
  panel = new ParamPanel(ui.params, msg.paramTable, (spec, stage) => scheduleUpdate(stage));
  notices.set('hash', msg.decoded.notices);
  // No state in the link: the decoded default is the opening run (camphor, 128 × 64).
  applyState(msg.decoded.state);
  sendUpdate(false);
});

worker.on('decoded', (msg) => {
  applyState(msg.state);
  notices.set('hash', msg.notices);
  frameNext = true;
  sendUpdate(false);
});

worker.on('progress', (msg) => {
  if (msg.phase === 'table3') {
    ui.table3Error.hidden = true;
    ui.progress.textContent = msg.text;
    return;
  }
  if (!controller.isLatest(msg)) return;
  ui.progress.textContent = msg.text;
});

// A frame of the lattice while it grows (the preview's or the full run's).
worker.on('frame', (msg) => {
  if (!controller.isLatest(msg) || !renderer) return;
  framesSeen += 1;
  setHooks({ framesSeen, framePhase: msg.phase });
  if (liveDrawing) {
    liveWaiting = msg;  // drawn once the frame on screen is finished (above)
    return;
  }
  installLive(msg);
});

function installLive(msg) {
  if (!controller.isLatest(msg) || !renderer) return;  // a newer run, or its result, came meanwhile
  renderer.setStep(Infinity);
  renderer.setTile(msg.tile, msg.bounds, { live: true });
  renderer.setSprings(null);  // the finished run's come with it
  framesInstalled += 1;
  livePhase = msg.phase;
  liveDrawing = true;
  if (frameNext) {
    frameBark();
    frameNext = false;
  }
  requestFrame();
}

// A preview or a finished run replaces what is on screen: no live frame waits any more.
function endLive() {
  liveWaiting = null;
  liveDrawing = false;
}

worker.on('preview', (msg) => {
  if (!controller.isLatest(msg)) return;
  endLive();
  if (renderer) {
    renderer.setStep(Infinity);
    renderer.setTile(msg.buffers.tile, msg.bounds);
    renderer.setSprings(null);
    renderer.setMaps(msg.buffers.maps, msg.bounds.map.width, msg.bounds.map.height);
    if (frameNext) {
      frameBark();
      frameNext = false;
    }
  }
  const s = msg.stats;
  ui.stats.textContent = `preview ${msg.bounds.n_r} × ${msg.bounds.n_h} · ${(100 * s.broken_fraction.all).toFixed(1)} % of springs broken · ${(msg.previewMs / 1000).toFixed(1)} s; the full lattice is growing`;
  bumpHook('previews');
  setHooks({ previewMs: msg.previewMs.toFixed(0), previewNodes: s.nodes });
  requestFrame();
});

// A length in cm; a height past the patch's (a region wrapping along the trunk) as the paper's
// "(>H)".
function fmt(x, patchHeight = Infinity) {
  if (typeof x !== 'number' || !Number.isFinite(x)) return '—';
  return x > patchHeight ? `(>${Math.round(patchHeight)})` : x.toFixed(2);
}

worker.on('bark', (msg) => {
  if (!controller.isLatest(msg)) return;
  endLive();
  notices.set('error', '');
  controller.showFieldError('');
  ui.rngSeed.setAttribute('aria-invalid', 'false');
  lastGoodHash = msg.hash;
  applyState(msg.state);
  const s = msg.stats, b = msg.bounds;
  const brokenSprings = (msg.buffers.springs?.broken.length ?? 0) / 2;  // before the buffers go back
  shown = {
    bounds: b, samples: parseCyclesCsv(msg.csv), springs: b.springs, cycles: b.cycles, stepsPerCycle: b.steps_per_cycle,
  };
  if (renderer) {
    renderer.setTile(msg.buffers.tile, b);
    renderer.setSprings(msg.buffers.springs);
    renderer.setMaps(msg.buffers.maps, b.map.width, b.map.height);
    installedSerial = barkSerial + 1;
    if (frameNext) {
      frameBark();
      frameNext = false;
    }
  }
  // The views were used at once (copied to the GPU): they go back for the next grow to fill.
  worker.recycle(msg.buffers);
  controller.grown(msg.hash);
  barkSerial += 1;
  scrubber.reset(b.cycles * 10 + 1);
  controller.showWork(false);
  ui.progress.textContent = '';
  const r = s.regions;
  ui.stats.textContent = `${s.species} · ${b.n_r} × ${b.n_h} nodes (R ${b.radius.toFixed(2)} cm, H ${b.height.toFixed(1)} cm) · `
    + `${(100 * s.broken_fraction.all).toFixed(1)} % broken, ${(100 * s.vertical_crack_share).toFixed(0)} % vertical · `
    + `plates ${fmt(r.mean_w)} × ${fmt(r.mean_h, s.H_o)} cm mean, ${fmt(r.max_w)} × ${fmt(r.max_h, s.H_o)} max · ${r.count} regions · ${(msg.growMs / 1000).toFixed(1)} s`;
  ui.chartCaption.textContent = 'Broken share of each spring family against growth cycles (axial: horizontal cracks; diagonal: vertical cracks).';
  ui.plateChartCaption.textContent = `Plate size: the surface's plates' mean width around and height along (cm) against the same cycles${s.model === '4layer' ? ' (S: after each role exchange, the former M1)' : ''}.`;
  const layerShares = s.exposed ? ` Showing at the end: S ${(100 * s.exposed.S).toFixed(0)} %, M1 ${(100 * s.exposed.M1).toFixed(0)} %, M2 ${(100 * s.exposed.M2).toFixed(0)} %, inner ${(100 * s.exposed.I).toFixed(0)} %; S ${(100 * s.peeled_fraction).toFixed(0)} % peeled.` : '';
  ui.tileLegend.textContent = `Layers: S grey-brown, M1 red-brown, M2 tan, the inner layer dark. Peel: bonded brown, peeling orange, peeled pink.${layerShares}`;
  setHooks({
    status: 'ready', error: '', barkSerial, hash: msg.hash, stats: JSON.stringify(s), species: s.species,
    brokenAll: s.broken_fraction.all, growMs: msg.growMs.toFixed(1), wallMs: msg.wallMs.toFixed(1),
    mapWidth: b.map.width, mapHeight: b.map.height, samples: shown.samples.length,
    brokenSprings, model: s.model,
    buffersReused: msg.bufferCounts?.reused ?? '', buffersFresh: msg.bufferCounts?.fresh ?? '',
  });
  requestFrame();
});

worker.on('table3', (msg) => {
  ui.table3Run.disabled = false;
  ui.progress.textContent = '';
  controller.showWork(controller.inFlight);
  const body = ui.table3.querySelector('tbody');
  body.replaceChildren();
  const out = [];
  for (const { species, stats } of msg.rows) {
    const paper = PAPER_TABLE3[species];
    // The paper's measure: crack spacing along scan lines (docs/bark-model.md choice 10a), as
    // `niwa bark table3` scores it; an open line along (no horizontal crack) is "(>H)".
    const w = stats.spacing.width, h = stats.spacing.height;
    const tr = document.createElement('tr');
    const cells = [
      species,
      paper ? `${fmt(paper.mean[0])} × ${fmt(paper.mean[1])}` : '—',
      `${fmt(w.mean)} × ${fmt(h.mean)}`,
      paper ? `${fmt(paper.max[0])} × ${paper.max[1] === null ? '(>20)' : fmt(paper.max[1])}` : '—',
      `${fmt(w.max)} × ${h.open > 0 ? `(>${Math.round(stats.H_o)})` : fmt(h.max)}`,
    ];
    for (const c of cells) {
      const td = document.createElement('td');
      td.textContent = c;
      tr.append(td);
    }
    body.append(tr);
    out.push({ species, mean_w: w.mean, mean_h: h.mean, max_w: w.max, max_h: h.max, open_h: h.open });
  }
  ui.table3.hidden = false;
  setHooks({ table3: JSON.stringify(out) });
});

// ---------------------------------------------------------------- controls
ui.species.addEventListener('change', () => {
  showHelp();
  sendUpdate(true, true);
});
ui.model.addEventListener('change', () => sendUpdate(true));
ui.rngSeed.addEventListener('input', () => scheduleUpdate());
ui.reset.addEventListener('click', () => sendUpdate(true, true));
ui.tileView.addEventListener('change', () => {
  renderer?.setView(ui.tileView.value);
  setHooks({ tileView: ui.tileView.value });
  requestFrame();
});
ui.showBroken.addEventListener('change', () => {
  renderer?.setShowBroken(ui.showBroken.checked);
  setHooks({ showBroken: String(ui.showBroken.checked) });
  requestFrame();
});
ui.resetView.addEventListener('click', () => {
  frameBark();
  requestFrame();
});
ui.copyLink.addEventListener('click', () => copyLink(ui.shareStatus));
$('embed').addEventListener('click', () => showEmbedDialog({
  tag: 'niwa-bark', title: 'Niwa bark', heading: 'Embed this bark', script: 'niwa-bark.js', frame: 'embed.html?study=bark',
}));
const MAPS = { 'download-base': 'base_colour', 'download-normal': 'normal', 'download-height': 'height', 'download-orm': 'orm' };
for (const [id, map] of Object.entries(MAPS)) {
  $(id).addEventListener('click', () => controller.exportAs('png', `bark_${ui.species.value}_${map}.png`, 'image/png', { map }));
}
$('download-glb').addEventListener('click', () => controller.exportAs('glb', `bark_${ui.species.value}_trunk.glb`, 'model/gltf-binary'));
$('download-csv').addEventListener('click', () => controller.exportAs('csv', `bark_${ui.species.value}_cycles.csv`, 'text/csv'));
ui.table3Run.addEventListener('click', () => {
  ui.table3Run.disabled = true;
  ui.table3Error.hidden = true;
  controller.showWork(true);  // Cancel ends the three runs too (the worker restarts)
  const p = panel.values();
  worker.request('table3', { seed: numberOr(ui.rngSeed), N_R: p.N_R, N_H: p.N_H }, { group: 'table3', done: ['table3'] });
});

// ---------------------------------------------------------------- start
setHooks({ status: 'loading' });
await startRenderer();
worker.request('init', { hash: location.hash }, { done: ['ready'] });
