// The tree study's page (public/index.html, main thread): builds the panel from the parameter
// table, keeps the state in location.hash (one history entry per committed edit), reruns only the
// stage an edit invalidates (a growth row regrows; a wind or sway row re-skins and restarts the
// sway; a render row rebuilds the hybrid view, all on the tree already grown) and shows each tree
// in its view, drawn with WebGL2 by tree_view.js in the render worker (render_worker.js, the canvas
// transferred to it) or, without OffscreenCanvas WebGL2 in workers, on this thread (view_client.js).
// Growth runs in the growth worker (web/worker/tree_handler.js); the worker, Cancel,
// debounced and merged edits with their stage, history (with the camera and the year shown),
// exports and errors are the study controller's (web/shell/study_controller.js).
// Does not: parse or check states (the core does), or draw (tree_view.js and tree_renderer.js do).
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { OrbitCamera } from '../gl/orbit_camera.js';
import { ParamPanel } from '../shell/param_panel.js';
import {
  Notices, copyLink, download, mountStudyNav, showEmbedDialog,
} from '../shell/study_page.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { bumpHook, hookValue, setHooks } from '../shell/test_hooks.js';
import { atlasGroups, buffersOf, treeGroups } from '../shell/worker_client.js';
import { ExportGuard, cutRefusal } from './cut_rules.js';
import { EditFeedback } from './edit_feedback.js';
import { GettingStarted } from './getting_started.js';
import { RenderTable } from './render_table.js';
import { PhoneDock } from './phone_dock.js';
import { mountStateFile } from './state_file.js';
import { exportRefusals, mountExportPanel } from './export_panel.js';
import { ViewClient } from './view_client.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'), stats: $('stats'), frameStats: $('frame-stats'), sunInfo: $('sun-info'),
  progress: $('progress'), progressBar: $('grow-progress'), preset: $('preset'), presetSource: $('preset-source'),
  seed: $('seed'), years: $('years'), params: $('params'), reset: $('reset'), play: $('play'), year: $('year'),
  yearText: $('year-text'), selection: $('selection'), cut: $('cut'), undo: $('undo'), redo: $('redo'),
  prunes: $('prunes'), copyLink: $('copy-link'), resetView: $('reset-view'), embed: $('embed'),
  downloadGlb: $('download-glb'), downloadJson: $('download-json'), downloadPng: $('download-png'),
  shareStatus: $('share-status'), wind: $('wind'), windInfo: $('wind-info'), renderMode: $('render-mode'), shadows: $('shadows'),
  barkFields: $('bark-fields'), barkInfo: $('bark-info'),
  renderTable: $('render-table'), renderCol: $('render-col'), timeFrames: $('time-frames'), cancel: $('cancel'),
};
mountStudyNav($('studies'), 'tree');
// Errors beside their fields and the "stale" label over the view; the .glb button's guard.
const feedback = new EditFeedback(ui.canvas.closest('.stage'), { seed: ui.seed, years: ui.years, preset: ui.preset });
const exportGuard = new ExportGuard(ui.downloadGlb);
let gettingStarted = null;  // the Getting started controls (built with the panel)
// On a phone the controls used most sit under the view (Age joins once Getting started is built).
const dock = new PhoneDock($('dock'))
  .add('preset', document.querySelector('label[for="preset"]'), ui.preset)
  .add('buttons', ui.wind, ui.cut, ui.undo, ui.redo)
  .add('selection', ui.selection);

// webgl: drawing problems; error: the core's line for the current state; hash: from decoding the
// URL hash; prunes: prunes of the current state that cut nothing (from the grown tree).
const notices = new Notices($('notice'), ['webgl', 'error', 'hash', 'prunes']);
// The worker, Cancel (issue 16: whatever the worker is doing, growing, meshing or exporting, ends
// now), debounced edits merged while a tree is on its way, their stage (a mesh, sway or view row
// restages the tree grown), history, exports and errors (web/shell/study_controller.js).
const controller = new StudyController({
  study: 'tree', notices, ui, state: () => currentState(),
  // The core's error beside its field (panel row, basic field, Getting started control) and the
  // "stale" label over the view (edit_feedback.js).
  errors: {
    show: (error) => {
      panel?.markError(error?.field || '');
      feedback.showError(error || '');
    },
  },
  onCancel: () => {
    if (windPlaying) setWind(false);
    return 'cancelled: back to the last finished tree';
  },
  // Cancel restarted the worker: init it again and grow the last finished state (or the hash's
  // preset defaults when nothing finished yet); the tree on screen stays until then.
  onRestart: () => {
    restarting = true;
    worker.request('init', { hash: lastGood ? `#${lastGood.hash}` : '' }, { done: ['ready'] });
  },
  onError: (msg, when) => {
    if (when === 'after') {
      if (treeSerial === 0) feedback.fresh();  // no tree on screen to call stale
      // The year bar goes back to the tree on screen (it followed the refused Years: "50 of 50"
      // over a 15-year tree); the field keeps what was typed, with its notice.
      if (lastGood) showScrubber(Number(lastGood.state.years), shownYear);
      return false;
    }
    if (msg.control === 'motion') {  // no cheaper representation for this tree: full frames only
      view.send('motionOff');
      return true;
    }
    if (msg.control === 'bark') {  // the simulated bark was refused: the line beside the choice
      ui.barkInfo.textContent = msg.message;
      setHooks({ barkError: msg.message });
      return true;
    }
    if (msg.control === 'wind') {  // the sway was refused (docs/budgets.md): the line beside Blow
      if (windPlaying) setWind(false);
      ui.windInfo.textContent = msg.message;
      setHooks({ windError: msg.message });
      return true;
    }
    return false;
  },
  // The hash carries the camera after the state; each history entry keeps the year shown.
  // and the page's fields off their first value (the worker takes them out before the core
  // decodes): Sun shadows when off (shadows=off). The Bark choice is the table's rows (bark=1).
  viewHash: () => `${drawing === 'on' ? `&cam=${camera.toHash()}` : ''}${ui.shadows.value === 'off' ? '&shadows=off' : ''}`,
  historyExtra: () => showYear,
  // Back/forward (and undo/redo, which use them) restore the entry's state; a hash typed by the
  // user arrives here too and becomes a new entry.
  onRestore: (extra) => {
    stopPlaying();
    showYear = Number.isInteger(extra) ? extra : null;
  },
  onHistoryChange: () => updateUndoButtons(),
});
const { worker, history: history_ } = controller;
let restarting = false;  // the next 'ready' answers a restart (the panel exists already)
let lastGood = null;     // {hash, state} of the last tree shown

// ---------------------------------------------------------------- rendering
// The view draws in the render worker (web/tree/render_worker.js: the canvas transferred with
// transferControlToOffscreen, WebGL2, the tree renderer, the frame loop and governor, the sway's
// poses, picking), or on the main thread where a browser cannot draw WebGL2 in a worker; either
// way through web/tree/tree_view.js's messages (view_client.js). The page keeps the DOM, the orbit
// camera's input (its state goes to the view), the panel and the growth worker, whose replies it
// hands on with their buffers transferred; the view hands them back for the growth worker's next
// reply.
const camera = new OrbitCamera();
let drawing = 'starting';  // 'on' once the view can draw, 'off' when it cannot
const table = new RenderTable(ui.renderTable, ui.renderCol, ui.frameStats);
let freshSerial = 0;       // the tree whose first frame clears "stale" (0: none waiting)
const viewReplies = { picked: [], timed: [], png: [], finished: [] };  // waiting for the view's answer
const viewCss = () => ({ css: [ui.canvas.clientWidth, ui.canvas.clientHeight], dpr: globalThis.devicePixelRatio || 1 });
const view = new ViewClient(ui.canvas, (msg) => onView(msg), { ...viewCss(), shadows: ui.shadows.value !== 'off' });
setHooks({ viewThread: view.mode });  // 'starting' until the view is up
new ResizeObserver(() => view.send('resize', viewCss())).observe(ui.canvas);

// Asks the view for one answer of `type` (picked, timed, png, finished); resolves to its message.
function askView(type, reply, fields = {}) {
  return new Promise((resolve) => {
    viewReplies[reply].push(resolve);
    view.send(type, fields);
  });
}

// The view's messages (web/tree/tree_view.js).
function onView(msg) {
  switch (msg.type) {
    case 'batch':  // the render worker's messages of one task
      for (const m of msg.messages) onView(m);
      return;
    case 'ready':
      drawing = 'on';
      setHooks({ viewThread: view.mode });
      camera.attach(ui.canvas, cameraMoved);
      view.send('camera', { state: cameraState() });
      writeHash();  // the link gains the camera (cam=)
      return;
    case 'failed':
      drawing = 'off';
      setHooks({ drawing: 'off' });  // no frames will come (tests stop waiting for them)
      notices.set('webgl', `Cannot draw: ${msg.message}`);
      treeDrawn(Infinity);
      if (freshSerial) feedback.fresh();
      return;
    case 'lost':
      notices.set('webgl', 'The WebGL2 context was lost; reload the page to draw again.');
      return;
    case 'hooks': return setHooks(msg.fields);
    case 'bump': return void bumpHook(msg.key);
    case 'table': return table[msg.method](msg.arg);
    case 'worker': return worker.post(msg.message, msg.fields);
    case 'recycle': return void worker.recycle(msg.groups);
    case 'drawn':
      treeDrawn(msg.serial);
      if (freshSerial && msg.serial >= freshSerial) {  // the tree that answers the latest edit is on screen now
        freshSerial = 0;
        feedback.fresh();
      }
      return;
    default:
      if (viewReplies[msg.type]?.length) viewReplies[msg.type].shift()(msg);
  }
}

// Tests: a 'niwa-gpu-finish' event on the document asks the view to wait for the GPU's work drawn
// so far (the page's canvas has no context of its own to read a pixel from once transferred);
// data-gpu-finished counts the answers.
document.addEventListener('niwa-gpu-finish', () => askView('finish', 'finished').then(() => bumpHook('gpuFinished')));

// The orbit camera's state for the view (its input stays here).
function cameraState() {
  const { yaw, pitch, distance, fov, near, far } = camera;
  return { yaw, pitch, distance, target: [...camera.target], fov, near, far };
}

// The tree serials drawn: treeOnScreen(serial) resolves once a finished frame shows that tree or
// a newer one (at once when the view cannot draw: nothing will be drawn).
let drawnSerial = 0;
let drawnWaiters = [];
function treeDrawn(serial) {
  drawnSerial = Math.max(drawnSerial, serial);
  const done = drawnWaiters.filter((w) => w.serial <= drawnSerial);
  drawnWaiters = drawnWaiters.filter((w) => w.serial > drawnSerial);
  for (const w of done) w.resolve();
}
function treeOnScreen(serial) {
  if (drawing === 'off' || drawnSerial >= serial) return Promise.resolve();
  return new Promise((resolve) => drawnWaiters.push({ serial, resolve }));
}
const requestFrame = (urgent = false, whole = false) => view.send('frame', { urgent, whole });

// The renderer's light is the light model's sun (parameters sun_elevation and sun_azimuth). Every
// panel edit comes here: only a sun that moved is drawn at once (issue 32 item 5: an urgent whole
// frame of the old tree for every edit held the new tree's first frame back until the GPU had
// drawn it, 0.9 s of a probed 1.4 s edit on SwiftShader).
let sunShown = '';  // the sun the view has, 'elevation,azimuth'
function showSun() {
  if (!panel) return;
  const v = panel.values();
  const el = Number(v.sun_elevation), az = Number(v.sun_azimuth), weight = Number(v.sun_weight);
  if (!Number.isFinite(el) || !Number.isFinite(az)) return;
  const growth = weight > 0 ? `and the growth model, weight ${weight}` : 'only; the growth model has sky light (sun_weight 0)';
  ui.sunInfo.textContent = `sun: az ${az}°, el ${el}° (lights the view ${growth})`;
  if (sunShown === `${el},${az}`) return;
  // The first sun goes with the first tree (no frame of its own); a moved one at once.
  view.send('sun', { elevation: el, azimuth: az, urgent: sunShown !== '' });
  sunShown = `${el},${az}`;
}

// Camera moves rewrite the cam= field of the current history entry (no new entry), a moment later.
let cameraTimer = 0;
function cameraMoved() {
  view.send('camera', { state: cameraState(), moved: true });
  clearTimeout(cameraTimer);
  cameraTimer = setTimeout(writeHash, 400);
}

// ---------------------------------------------------------------- state
let panel = null;
let presets = [];
let latestRequest = null;  // {id, kind, state}
let treeSerial = 0;
let currentPrunes = [];
let showYear = null;       // the scrubber's year, or null for the state's full age
let shownYear = 0;         // the age of the tree on screen
let frameNext = true;      // frame the camera on the next tree
let lastBounds = null;     // bounds of the tree on screen (Reset view)
let selected = null;       // selected branch id

function currentState() {
  // The camera is appended by the controller (viewHash), so the core hashes the tree state only.
  return { preset: ui.preset.value, seed: numberOr(ui.seed), years: numberOr(ui.years), params: panel.values(), prunes: [...currentPrunes] };
}

function applyState(state) {
  ui.preset.value = state.preset;
  ui.seed.value = String(state.seed);
  ui.years.value = String(state.years);
  panel.setValues(state.params);
  currentPrunes = [...(state.prunes || [])];
  showPresetSource();
  showPrunes();
  showSun();
  ui.renderMode.value = String(Number(state.params.render_mode) === 1 ? 1 : 0);
  gettingStarted?.sync();
}

function showPresetSource() {
  const preset = presets.find((p) => p.name === ui.preset.value);
  ui.presetSource.textContent = preset ? preset.source : '';
}

function showPrunes() {
  ui.prunes.textContent = currentPrunes.length ? `Cuts (year:branch): ${currentPrunes.join(', ')}` : '';
}

function fullYears() {
  const n = Number(ui.years.value);
  return Number.isInteger(n) && n >= 0 && n <= 100 ? n : null;
}

// Scrubber range follows the Years field; at its end it shows the full-grown tree.
function syncScrubber() {
  const n = fullYears();
  if (n === null) return;
  if (showYear !== null && showYear >= n) showYear = null;
  showScrubber(n, showYear ?? n);
}

// The year bar at `year` of a tree of `full` years.
function showScrubber(full, year) {
  ui.year.max = String(full);
  ui.year.value = String(year);
  ui.yearText.textContent = `${year} of ${full}`;
}

// kind: 'edit' (a committed change: new history entry; its stage is the earliest the edits since
// the last update touched: grow regrows, mesh, sway and view restage the tree grown), 'prune'
// (committed, camera kept), 'scrub' (another age of the same state), 'restore' (undo/redo/back/
// forward). A growth edit also frames the camera on the new tree; edits of later stages keep the
// tree and the camera.
function sendUpdate(kind = 'edit') {
  syncScrubber();
  const state = currentState();
  if (kind !== 'scrub' && treeSerial > 0) feedback.stale();
  const fields = { state };
  if (showYear !== null) fields.until = showYear;
  const request = controller.update(kind === 'edit' || kind === 'prune', fields,
    { done: ['tree'], stage: kind === 'edit' ? undefined : 'grow' });
  if (kind === 'edit' && request.stage === 'grow') frameNext = true;
  latestRequest = { id: request.id, kind, state };
  return request;
}

// An edit of a control ('grow') or a panel row (its stage): one update after a quiet moment.
function scheduleUpdate(stage = 'grow') {
  if (treeSerial > 0) feedback.stale();
  controller.schedule(() => sendUpdate('edit'), stage);
}

// Rewrites the current history entry (camera moves, scrubbing: no new entry).
const writeHash = () => controller.writeHash();

function updateUndoButtons() {
  ui.undo.disabled = !history_.canUndo();
  ui.redo.disabled = !history_.canRedo();
}

function formatStats(s) {
  const height = s.height >= 100 ? s.height.toFixed(0) : s.height.toFixed(1);
  return `internodes ${s.internodes} · leaves ${s.leaves} · flowers ${s.flowers} · height ${height} cm · grown in ${s.ms.toFixed(0)} ms`;
}

// The selection (and its highlight in the view, unless `send` is false: a new tree carries it).
function select(id, send = true) {
  selected = Number.isInteger(id) ? id : null;
  const refusal = selected === null ? '' : cutRefusal(selected, shownYear);
  ui.cut.disabled = selected === null || refusal !== '';
  ui.selection.textContent = selected === null
    ? 'Click or tap a branch in the view to select it.'
    : refusal || `Branch ${selected} selected: Cut (or the Delete key) removes it and everything above it after year ${shownYear}.`;
  setHooks({ selected: selected === null ? '' : selected });
  if (send) view.send('select', { id: selected });
}

// Opens the full table's row `key` (its section) and focuses it, so its help line shows.
function openTableRow(key) {
  const input = panel?.element(key);  // (its group built first if it waits)
  if (!input) return;
  const details = input.closest('details');
  if (details) details.open = true;
  input.focus();
  input.scrollIntoView({ block: 'center' });
}

// ---------------------------------------------------------------- worker replies
worker.on('ready', (msg) => {
  if (restarting) {  // after Cancel: the panel and presets exist; restore the last good state
    restarting = false;
    applyState(lastGood ? lastGood.state : msg.decoded.state);
    sendUpdate('restore');
    return;
  }
  presets = msg.presets;
  for (const p of presets) ui.preset.append(new Option(`${p.title} (${p.name})`, p.name));
  panel = new ParamPanel(ui.params, msg.paramTable, (spec, stage) => {
    if (spec.group === 'bark') {  // a new Bark choice: its last refusal goes
      ui.barkInfo.textContent = '';
      setHooks({ barkError: '' });
    }
    showSun();
    ui.renderMode.value = String(Number(panel.values().render_mode) === 1 ? 1 : 0);
    gettingStarted?.sync();
    scheduleUpdate(stage);
  }, { later: (build) => setTimeout(build, 0) });  // the closed groups' rows in later tasks (issue 32 item 5)
  gettingStarted = new GettingStarted($('getting-started'), msg.paramTable, ui.years, openTableRow, panel);
  dock.add('age', $('getting-started').querySelector('[data-for-key="years"]'));
  // The table's Bark group (bark, bark_model: view rows, re-texturing the tree grown) shown in the
  // view's settings beside the Bark notice, not among the model's rows.
  const barkGroup = panel.element('bark')?.closest('details');
  if (barkGroup) {
    barkGroup.open = true;
    ui.barkFields.append(barkGroup);
  }
  applyState(msg.decoded.state);
  showShadows(msg.decoded.shadows);
  notices.set('hash', msg.decoded.notices);
  if (camera.fromHash(msg.decoded.state.camera)) frameNext = false;
  updateUndoButtons();
  sendUpdate('restore');
});

worker.on('decoded', (msg) => {
  applyState(msg.state);
  showShadows(msg.shadows);
  notices.set('hash', msg.notices);
  if (camera.fromHash(msg.state.camera)) frameNext = false;
  sendUpdate('restore');
});

worker.on('hash', (msg) => {
  if (controller.isLatest(msg)) controller.grown(msg.hash);
});

worker.on('progress', (msg) => {
  controller.showWork(true);
  ui.progressBar.hidden = false;
  ui.progressBar.max = Math.max(1, msg.years);
  ui.progressBar.value = msg.year;
  ui.progress.textContent = msg.year < msg.years ? `growing: year ${msg.year} of ${msg.years}` : 'building mesh';
});

// Buffers the view will not draw go back for the worker's next tree to fill (the view hands back
// those it drew once they are on the GPU).
function giveBackTree(msg) {
  worker.recycle(treeGroups(msg));
}

worker.on('tree', (msg) => {
  if (!controller.isLatest(msg)) return;
  controller.showWork(false);
  panel.buildAll();  // (done by now in later tasks: a page that says 'ready' has every row)
  if (history_.base) lastGood = { hash: history_.base, state: latestRequest.state };
  // The bark texture the tree wears (a simulated one's digest starts 'bark-sim-') and its summary;
  // the leaf texture's digest (a leaf_spray card's too: tests/browser/textures.test.mjs).
  setHooks({ barkDigest: msg.mesh.textures?.bark?.digest || '', barkStats: msg.stats.bark ? JSON.stringify(msg.stats.bark) : '',
    leafDigest: msg.mesh.textures?.leaf?.digest || '' });
  notices.set('error', '');
  controller.showFieldError('');
  exportGuard.update(msg.stats, msg.mesh);
  notices.set('prunes', msg.stats.idle_prunes || []);
  ui.stats.textContent = formatStats(msg.stats);
  // The limit that stopped the growth, named (max_internodes or the page's budget).
  ui.progress.textContent = msg.stats.truncated ? msg.stats.truncated_by || 'stopped at max_internodes' : '';
  shownYear = msg.stats.years;
  // A tree stopped by a budget before its full age: the year bar ends at the year it reached
  // (it read "50 of 50" over a tree stopped in year 28).
  const full = fullYears();
  if (showYear === null && full !== null && shownYear < full) {
    showScrubber(shownYear, shownYear);
    ui.yearText.textContent = `${shownYear} of ${full} (stopped)`;
  }
  table.showFullCounts(msg.mesh);
  // The worker's buffers reused (web/worker/transfer.js): what this reply's copy went into.
  setHooks({ buffersReused: msg.buffers?.reused ?? '', buffersFresh: msg.buffers?.fresh ?? '' });
  setHooks({ renderMode: msg.hybrid ? 'hybrid' : 'full' });
  // A new tree clears the selection; another age of it, or a later stage of it, keeps it.
  const sameTree = latestRequest.kind === 'scrub' || !msg.grown;
  select(sameTree ? selected : null, false);
  treeSerial += 1;
  lastBounds = msg.stats.bounds;
  if (frameNext) {
    camera.frame(msg.stats.bounds, 1.12);  // room for the year bar over the view
    frameNext = false;
    writeHash();
  }
  if (drawing === 'off') {
    giveBackTree(msg);
  } else {
    // To the view (while WebGL starts it keeps the last tree only), its buffers moved, not copied;
    // they come back once on the GPU ('recycle').
    view.send('camera', { state: cameraState(), withTree: true });  // drawn with the tree, no frame of its own
    const tree = { mesh: msg.mesh, bounds: msg.stats.bounds, swayNodes: msg.swayNodes, hybrid: msg.hybrid,
      hybridOn: Boolean(msg.hybrid), leafLength: Number(panel.values().leaf_size) / 100 || 0.05,
      serial: treeSerial, year: shownYear, selected };
    view.send('tree', tree, buffersOf(treeGroups(tree)));
  }
  // (the stages a restage re-did, core TreeRun::Update, go to the hooks from the controller)
  if (msg.grown) bumpHook('treesGrown');
  setHooks({
    status: 'ready', treeSerial, internodes: msg.stats.internodes, leaves: msg.stats.leaves,
    flowers: msg.stats.flowers, year: msg.stats.years,
    // bench/edit_latency.mjs: the worker's time for this tree and when it reached the page
    treeWorkerMs: msg.workerMs == null ? '' : msg.workerMs.toFixed(1), treeBuiltMs: msg.builtMs == null ? '' : msg.builtMs.toFixed(1),
    treeArrivedMs: performance.now().toFixed(1),
  });
  if (windPlaying) worker.post('wind', { play: true });  // sway the new tree (or new wind) too
  else showWind(null);
  // "stale" stays while a newer edit waits (the controller sends it now if it was queued behind
  // this tree); else it goes with the first frame of this tree.
  if (!controller.editWaiting()) {
    if (drawing !== 'off') freshSerial = treeSerial; else feedback.fresh();
  }
});

// The view's cheaper representation and hybrid draw lists (it asked for them), and the sway's
// poses: to the view, their buffers moved; it hands them back once uploaded.
worker.on('motionAtlas', (msg) => {
  if (drawing === 'off') return void worker.recycle(atlasGroups(msg.hybrid));
  view.send('motionAtlas', { hybrid: msg.hybrid, buffers: msg.buffers }, buffersOf(atlasGroups(msg.hybrid)));
});

worker.on('drawList', (msg) => {
  if (drawing === 'off') return;
  const { type, ...list } = msg;
  view.send('drawList', list, buffersOf({ cards: msg.cards, lines: msg.lines }));
});

worker.on('pose', (msg) => {
  if (!windPlaying || drawing !== 'on') {  // no poses for a tree not drawn
    worker.post('poseDone');
    return;
  }
  showWind(msg);
  view.send('pose', { poses: msg.poses, wind: msg.wind, time: msg.time, buffers: msg.buffers }, buffersOf({ sway: { poses: msg.poses } }));
});

// ---------------------------------------------------------------- controls
ui.preset.addEventListener('change', () => {
  const preset = presets.find((p) => p.name === ui.preset.value);
  if (preset) applyState({ preset: preset.name, seed: preset.seed, years: preset.years, params: preset.params, prunes: [] });
  showYear = null;
  scheduleUpdate();
});
ui.seed.addEventListener('input', () => scheduleUpdate());
ui.years.addEventListener('input', () => {
  syncScrubber();
  scheduleUpdate();
});
ui.reset.addEventListener('click', () => {
  ui.preset.dispatchEvent(new Event('change'));
});

// Year scrubber and play: each age is a regrow in the worker; a newer request supersedes older ones.
ui.year.addEventListener('input', () => {
  stopPlaying();
  const y = Number(ui.year.value);
  showYear = y >= Number(ui.year.max) ? null : y;
  sendUpdate('scrub');
});

// Play shows every year: the next year is asked for 250 ms after this year's tree is on screen
// (not after its reply: with a frame slower than that, drawn in parts or with the sun's shadow map
// redrawn for each new tree, the year bar ran ahead of the view and years were never seen). Pause
// holds the year shown. playRun: a Pause and a new Play do not leave the old loop running.
let playing = false;
let playRun = 0;
function stopPlaying() {
  playing = false;
  playRun += 1;
  ui.play.textContent = 'Play';
  ui.play.setAttribute('aria-pressed', 'false');
}
ui.play.addEventListener('click', async () => {
  if (playing) return stopPlaying();
  const n = fullYears();
  if (n === null || panel === null) return;
  playing = true;
  const run = ++playRun;
  ui.play.textContent = 'Pause';
  ui.play.setAttribute('aria-pressed', 'true');
  let y = showYear === null || showYear >= n ? 0 : showYear;
  while (run === playRun && y <= n) {
    showYear = y >= n ? null : y;
    const reply = await sendUpdate('scrub').reply;  // null when superseded
    if (!reply || reply.type !== 'tree' || run !== playRun) break;
    await treeOnScreen(treeSerial);
    if (run !== playRun) break;
    await new Promise((resolve) => setTimeout(resolve, 250));
    y += 1;
  }
  if (run === playRun) stopPlaying();
});

// Picking: a click (not a drag) on the view selects the branch under the pointer.
let down = null;
ui.canvas.addEventListener('pointerdown', (e) => {
  down = { x: e.clientX, y: e.clientY, t: performance.now() };
});
ui.canvas.addEventListener('pointerup', (e) => {
  if (!down || drawing !== 'on') return;
  const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
  const quick = performance.now() - down.t < 600;
  down = null;
  if (moved > 5 || !quick) return;
  const rect = ui.canvas.getBoundingClientRect();
  // The view picks (its readPixels waits for the frame on the GPU); data-picks-answered counts the answers.
  askView('pick', 'picked', { x: e.clientX - rect.left, y: e.clientY - rect.top }).then((msg) => {
    select(msg.id);
    bumpHook('picksAnswered');
  });
});

function cutSelected() {
  if (selected === null) return;
  const refusal = cutRefusal(selected, shownYear);
  if (refusal) {
    ui.selection.textContent = refusal;
    bumpHook('cutsRefused');
    return;
  }
  const prune = `${shownYear}:b${selected}`;
  if (!currentPrunes.includes(prune)) currentPrunes.push(prune);
  showPrunes();
  select(null);
  sendUpdate('prune');
}
ui.cut.addEventListener('click', cutSelected);
ui.undo.addEventListener('click', () => history_.undo());
ui.redo.addEventListener('click', () => history_.redo());

const editable = (t) => t instanceof HTMLElement && (t.isContentEditable || ['INPUT', 'TEXTAREA', 'SELECT'].includes(t.tagName));
document.addEventListener('keydown', (e) => {
  if (editable(e.target)) return;  // the fields keep their own undo and Delete
  const key = e.key.toLowerCase();
  if ((e.ctrlKey || e.metaKey) && (key === 'z' || key === 'y')) {
    e.preventDefault();
    (key === 'y' || e.shiftKey ? ui.redo : ui.undo).click();
  } else if ((e.key === 'Delete' || e.key === 'Backspace') && selected !== null) {
    e.preventDefault();
    cutSelected();
  } else if (e.key === 'Escape' && selected !== null) {
    select(null);
  }
});

// ---------------------------------------------------------------- wind (thesis chapter 3)
// Blow runs the node-point sway of the tree on screen in the worker; each pose (16 floats per node
// point) skins the mesh in the vertex shader. The wind is the state's wind parameters.
let windPlaying = false;
function showWind(pose) {
  if (!pose) {
    ui.windInfo.textContent = windPlaying ? 'starting the wind…' : 'Still air. Blow sways the tree with the wind settings (speed, direction, gusts).';
    setHooks({ swayTime: '' });
    return;
  }
  const speed = pose.wind > 0 ? `${pose.wind.toFixed(1)} m/s` : 'calm';
  // A tree whose steps cost more than dt by estimate sways slower than real time (core/sway/sway_budget).
  const slow = pose.speed < 1 ? ` · slow motion (about ${pose.speed.toFixed(2)}× real time; lower years or raise dt)` : '';
  ui.windInfo.textContent = `t = ${pose.time.toFixed(1)} s · wind ${speed}${slow}`;
  setHooks({ swayTime: pose.time.toFixed(3), swayWind: pose.wind.toFixed(2), swayStepsPerTick: String(pose.stepsPerTick),
    swaySpeed: pose.speed.toFixed(3), swayStepMs: Number(pose.stepMs).toFixed(2) });
}
function setWind(play) {
  windPlaying = play;
  ui.wind.textContent = play ? 'Still' : 'Blow';
  ui.wind.setAttribute('aria-pressed', String(play));
  // The view asks for the cheaper representation first when its still frames were slow, and on
  // Still draws the rest shape at full quality at once.
  view.send('wind', { play });
  worker.post('wind', { play });
  showWind(null);
}
ui.wind.addEventListener('click', () => setWind(!windPlaying));

// Frame time of this view with the GPU's work included (the "frame (CPU)" row is only the CPU time
// of issuing the draw calls), into the column of the mode shown. While it runs the button is its
// Cancel (a full frame of a big tree takes seconds on a CPU GL; issue 32: every long button has
// Cancel); a cancelled timing shows the median of the frames it timed.
let timing = null;  // {cancelled} while a timing runs
ui.timeFrames.addEventListener('click', async () => {
  if (timing) {
    timing.cancelled = true;
    view.send('cancelTiming');
    ui.timeFrames.textContent = 'Cancelling…';
    return;
  }
  if (drawing !== 'on') return;
  const label = ui.timeFrames.textContent;
  const run = { cancelled: false };
  timing = run;
  ui.timeFrames.textContent = 'Cancel timing';
  setHooks({ timing: 'running' });
  try {
    const timed = (await askView('time', 'timed', { frames: 10 })).result || { ms: null, frames: 0, cancelled: true, mode: 'full' };
    const column = timed.mode === 'hybrid' ? 'row' : 'full';
    if (timed.ms === null) {
      table.set(column, 'timed_ms', 'cancelled');
    } else {
      table.set(column, 'timed_ms', `${timed.ms.toFixed(1)} ms${timed.cancelled ? ` (${timed.frames} of 10)` : ''}`);
      setHooks({ [timed.mode === 'hybrid' ? 'timedHybrid' : 'timedFull']:
        JSON.stringify({ ms: timed.ms, triangles: timed.triangles, lines: timed.lines, drawCalls: timed.drawCalls, frames: timed.frames }) });
    }
    setHooks({ timing: timed.cancelled ? 'cancelled' : 'done', timedFrames: timed.frames });
  } finally {
    timing = null;
    ui.timeFrames.textContent = label;
  }
});

// The mode select mirrors the render_mode row (a view-stage edit: the tree is not regrown).
ui.renderMode.addEventListener('change', () => {
  if (!panel) return;
  panel.setValues({ render_mode: Number(ui.renderMode.value) });
  scheduleUpdate(panel.stage('render_mode'));
});

// Sun shadows on or off (the frame's shadow map and the ground's stand-in shadow; a page view
// setting, not a row of the tree's table: the tree and its exports are the same either way). The
// link carries shadows=off as it carries the camera: the current history entry is rewritten.
function showShadows(value) {
  ui.shadows.value = value === 'off' ? 'off' : 'on';
  view.send('shadows', { on: ui.shadows.value !== 'off' });
  setHooks({ shadows: ui.shadows.value });
}
ui.shadows.addEventListener('change', () => {
  showShadows(ui.shadows.value);
  writeHash();
});

// ---------------------------------------------------------------- share and export
function fileStem() {
  return `niwa-${ui.preset.value}-seed${ui.seed.value}-year${shownYear}`;
}

// An export of the tree on screen (the plain .glb and .json, or a .glb variant of the export
// panel: budget, LOD, sway); the worker's refusal (the page budget's estimate, docs/budgets.md)
// goes beside the button that asked for it.
function requestExport(format, fields = {}) {
  refusals.clear();
  setHooks({ exportError: '', exportErrorButton: '' });
  const name = `${fileStem()}${format === 'json' ? '-params' : ''}${fields.variant ? `-${fields.variant}` : ''}.${format}`;
  controller.exportAs(format, name, format === 'glb' ? 'model/gltf-binary' : 'application/json', fields, {
    onRefused: (msg) => {
      const button = refusals.show(fields.variant, msg.message);
      setHooks({ exportError: msg.message, exportErrorButton: button });
    },
  });
}
ui.downloadGlb.addEventListener('click', () => requestExport('glb'));
const refusals = exportRefusals(mountExportPanel(ui.downloadGlb.parentElement, requestExport), ui.downloadGlb);
ui.downloadJson.addEventListener('click', () => requestExport('json'));
ui.downloadPng.addEventListener('click', () => {
  if (drawing !== 'on') return;
  askView('png', 'png').then(({ blob }) => {
    if (blob) download(blob, `${fileStem()}.png`, ui.shareStatus);
    else ui.shareStatus.textContent = 'The picture could not be saved.';
  });
});

// Save / Open: the whole state as a file (the CLI's --state); an opened state is a new history
// entry, drawn from its own camera when it has one.
mountStateFile({ save: $('save-state'), open: $('open-state'), input: $('open-state-file'), status: $('state-status') }, {
  worker,
  state: () => ({ ...currentState(), camera: drawing === 'on' ? camera.toHash() : '' }),
  stem: fileStem,
  onOpen: (state) => {
    stopPlaying();
    showYear = null;
    applyState(state);
    notices.set('hash', []);
    notices.set('error', '');
    sendUpdate('edit');
    frameNext = !camera.fromHash(state.camera);
  },
});

ui.resetView.addEventListener('click', () => {
  camera.reset(lastBounds);
  cameraMoved();
});

ui.copyLink.addEventListener('click', () => {
  writeHash();
  copyLink(ui.shareStatus);
});

ui.embed.addEventListener('click', () => {
  writeHash();
  showEmbedDialog({ tag: 'niwa-tree', title: 'Niwa tree', heading: 'Embed this tree' });
});

setHooks({ status: 'loading' });
if (hookValue('treesGrown') === undefined) setHooks({ treesGrown: 0 });
worker.request('init', { hash: location.hash }, { done: ['ready'] });
