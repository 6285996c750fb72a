// The tree study's page (public/index.html, main thread): builds the panel from the parameter
// table, keeps the state in location.hash (one history entry per committed edit), reruns only the
// stage an edit invalidates (a growth row regrows; a wind or sway row re-skins and restarts the
// sway; a render row rebuilds the hybrid view, all on the tree already grown) and draws each tree
// with WebGL2, as the layer of the view's one Frame (web/gl/frame.js: its camera, sun and ground). Growth runs in the worker (web/worker/tree_handler.js); the worker, Cancel,
// debounced and merged edits with their stage, history (with the camera and the year shown),
// exports and errors are the study controller's (web/shell/study_controller.js).
// Does not: parse or check states (the core does), or draw directly (tree_renderer.js does).
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { OrbitCamera } from '../gl/orbit_camera.js';
import { Frame } from '../gl/frame.js';
import { FrameGovernor } from '../gl/frame_governor.js';
import { FrameLoop } from '../gl/frame_loop.js';
import { viewOf } from '../gl/buffers.js';
import { ParamPanel } from '../shell/param_panel.js';
import {
  Notices, copyLink, download, mountStudyNav, showEmbedDialog,
} from '../shell/study_page.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { bumpHook, hookValue, setHooks } from '../shell/test_hooks.js';
import { atlasGroups, treeExtras } from '../shell/worker_client.js';
import { ExportGuard, cutRefusal } from './cut_rules.js';
import { EditFeedback } from './edit_feedback.js';
import { GettingStarted } from './getting_started.js';
import { RenderTable } from './render_table.js';
import { PhoneDock } from './phone_dock.js';
import { mountStateFile } from './state_file.js';
import { exportRefusals, mountExportPanel } from './export_panel.js';
import { Renderer } from './tree_renderer.js';

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
      motionOff = true;
      motionInFlight = false;
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
  viewHash: () => `${renderer ? `&cam=${camera.toHash()}` : ''}${ui.shadows.value === 'off' ? '&shadows=off' : ''}`,
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
let freshOnDraw = false; // the next frame drawn shows the tree of the latest edit (clears "stale")
let lastGood = null;     // {hash, state} of the last tree shown

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let frame = null;     // the view's one Frame (web/gl/frame.js): camera, sun, ground and the layers
let renderer = null;  // the tree's layer of it (web/tree/tree_renderer.js)
let poseDrawPending = false;
const table = new RenderTable(ui.renderTable, ui.renderCol, ui.frameStats);
// One frame in flight on the GPU (web/gl/frame_loop.js); while the tree sways or the camera
// moves, the governor draws cheaper frames when they lag, and the full one once all is still.
const governor = new FrameGovernor({ onStill: () => requestFrame() });
// A frame bigger than the governor's budget is drawn in parts over several animation frames
// (web/gl/progressive_frame.js) and goes on until it is finished, unless the governor now wants
// another level (the view started or stopped moving, the cheap representation arrived); what
// changed meanwhile (frameDirty) is drawn by the next frame.
let frameDirty = true;
let wholeNext = false;  // the next frame is drawn whole, not in parts (requestFrame(true, true))
let freshNext = false;  // the next frame starts anew, not resuming one begun before (a new selection)
let frameLevel = -1;  // the governor's level of the frame in parts
let poseAtFrameStart = 0;  // the renderer's poseSerial when the frame on its way was started
let swayTimeAtFrameStart = 0;  // ... and the simulated time of that pose (s)
const frames = new FrameLoop(() => {
  // While a big tree goes up in parts the canvas keeps its last frame (no draw: a frame of the old
  // big tree costs seconds on a CPU GL, and every part's upload would wait for it).
  if (renderer.uploading) return false;
  if (poseDrawPending) governor.motion();  // a new pose to draw: moving, however long the last frame took
  // (a hybrid-mode tree is cheap already: its levels only shrink the drawing buffer)
  const cheapAvailable = hybridOn || renderer.motionReady() ? Infinity : 0;
  const next = governor.peek(cheapAvailable);
  if (next.wantCheap > 0 && !renderer.motionReady()) requestMotionView();
  // Swaying, the cheaper representation on its way and a full frame too big for one animation
  // frame: no full frame meanwhile (the canvas keeps the last one; the GPU paints the atlas), the
  // sway goes on.
  if (windPlaying && next.moving && next.capped && !motionOff && renderer.fullPrimitives() > governor.budget()) {
    frame.progress.abort();  // a full frame in parts would only hold the atlas back
    if (poseDrawPending) {
      poseDrawPending = false;
      worker.post('poseDone');
    }
    return false;
  }
  const resume = frame.progress.pending() && next.level === frameLevel && !wholeNext && !freshNext;
  let quality = null;
  let whole = false;
  if (!resume) {
    viewsAtFrameStart = viewsReceived;
    poseAtFrameStart = renderer.poseSerial;
    swayTimeAtFrameStart = renderer.swaying ? renderer.swayTime : 0;
    freshNext = false;
    quality = governor.quality(cheapAvailable);
    frameLevel = quality.level;
    frameDirty = false;
    whole = wholeNext;
    wholeNext = false;
  }
  // A camera drag without the cheaper representation: each frame at once (smaller), as it moves;
  // an edit that must show at once (the sun): one whole frame, however long it takes.
  const dragging = next.moving && next.capped && !windPlaying;
  const drawn = frame.render(camera, quality, { budget: dragging || whole ? Infinity : governor.budget(), resume });
  if (!drawn) return false;
  governor.drew(drawn.drawnPrimitives, !drawn.partial, drawn.primitives, drawn.shadowPrimitives);
  setHooks({ frameScale: frame.scale, frameMode: drawn.mode, framesDrawn: frames.stats.drawn,
    framesSkipped: frames.stats.skippedBusy, frameGpuMs: Math.round(frames.stats.gpuMs), framePartial: drawn.partial ? 1 : 0 });
  if (drawn.partial) {
    if (drawn.mode !== 'motion') table.showPartial(drawn);
    frames.request();  // the rest of this frame
    return true;
  }
  if (frameDirty) frames.request();  // what changed while the frame was drawn in parts
  if (poseDrawPending) {  // the worker sends the next pose once this one is on screen
    poseDrawPending = false;
    worker.post('poseDone');
  }
  if (drawn.mode !== 'motion') table.showFrame(drawn);
  // tests wait for the new tree's frame, and for the frame that shows a new selection
  treeDrawn(treeSerial);
  setHooks({ drawnTreeSerial: treeSerial, drawnYear: shownYear, drawnSelection: drawn.selected ?? -1,
    drawnMode: drawn.mode, drawnViews: viewsAtFrameStart,
    // the sun's shadow map in this frame: 'drawn' (redrawn), 'reused' or 'off'; maps drawn so far
    drawnShadow: drawn.shadow, shadowPasses: frame.shadowMap?.passes ?? 0,
    // the poses this frame was started with, and the latest (equal: the pose on screen is the latest)
    drawnPose: poseAtFrameStart, latestPose: renderer.poseSerial, drawnSwayTime: swayTimeAtFrameStart.toFixed(3) });
  bumpHook('framesShown');  // finished frames (the orbit frame time of tests/browser/no_blank_frames)
  if (freshOnDraw) {  // the tree that answers the latest edit is on screen now
    freshOnDraw = false;
    feedback.fresh();
  }
  return true;
}, { governor });
// The tree serials drawn: treeOnScreen(serial) resolves once a finished frame shows that tree or
// a newer one (at once without a renderer: nothing will be drawn).
let drawnSerial = 0;
let drawnWaiters = [];
function treeDrawn(serial) {
  drawnSerial = Math.max(drawnSerial, serial);
  const done = drawnWaiters.filter((w) => w.serial <= drawnSerial);
  drawnWaiters = drawnWaiters.filter((w) => w.serial > drawnSerial);
  for (const w of done) w.resolve();
}
function treeOnScreen(serial) {
  if (!renderer || drawnSerial >= serial) return Promise.resolve();
  return new Promise((resolve) => drawnWaiters.push({ serial, resolve }));
}
const requestFrame = (urgent = false, whole = false) => {
  if (!renderer) return;
  frameDirty = true;
  wholeNext ||= whole;
  frames.request(urgent);
};

// Hybrid mode: the worker chooses card or line per branch for each view (eq. 4.1 with hysteresis);
// one request at a time, the newest camera wins.
let hybridOn = false;
let viewInFlight = false;
let viewDirty = false;
function requestView() {
  if (!hybridOn || !renderer) return;
  if (viewInFlight) {
    viewDirty = true;
    return;
  }
  viewInFlight = true;
  viewDirty = false;
  worker.post('view', { camera: renderer.viewFor(camera) });
}

// A full-mode tree's cheaper representation while it moves (the governor's cheap levels): its
// hybrid scene from the worker ('view' with motion: true; the atlas once per tree), one request at
// a time, the newest camera wins; none when the worker cannot build it for this tree.
let motionInFlight = false;
let motionDirty = false;
let motionOff = false;
function requestMotionView() {
  if (hybridOn || !renderer || motionOff) return;
  if (motionInFlight) {
    motionDirty = true;
    return;
  }
  motionInFlight = true;
  motionDirty = false;
  worker.post('view', { camera: renderer.viewFor(camera), motion: true, atlas: !renderer.hasMotionAtlas() });
}

// The renderer's light is the light model's sun (parameters sun_elevation and sun_azimuth). Every
// panel edit comes here: only a sun that moved is drawn at once (issue 32 item 5: an urgent whole
// frame of the old tree for every edit held the new tree's first frame back until the GPU had
// drawn it, 0.9 s of a probed 1.4 s edit on SwiftShader).
// urgent: false when the renderer has just started (its first frame is asked for anyway).
let sunShown = '';  // the sun the renderer has, 'elevation,azimuth'
function showSun(urgent = true) {
  if (!panel) return;
  const v = panel.values();
  const el = Number(v.sun_elevation), az = Number(v.sun_azimuth), weight = Number(v.sun_weight);
  if (!Number.isFinite(el) || !Number.isFinite(az)) return;
  const growth = weight > 0 ? `and the growth model, weight ${weight}` : 'only; the growth model has sky light (sun_weight 0)';
  ui.sunInfo.textContent = `sun: az ${az}°, el ${el}° (lights the view ${growth})`;
  if (!renderer || sunShown === `${el},${az}`) return;
  sunShown = `${el},${az}`;
  renderer.setSun(el, az);
  if (urgent) requestFrame(true, true);  // the new light at once, before the regrown tree
}

// Camera moves rewrite the cam= field of the current history entry (no new entry), a moment later.
let cameraTimer = 0;
function cameraMoved() {
  governor.motion();
  requestFrame();
  requestView();
  if (renderer?.motionReady()) requestMotionView();  // its draw list is for the last camera
  clearTimeout(cameraTimer);
  cameraTimer = setTimeout(writeHash, 400);
}

// The hybrid draw lists installed, and how many a frame began with (tests wait for a whole frame
// drawn with the latest list: hook drawnViews).
let viewsReceived = 0;
let viewsAtFrameStart = 0;
let rendererStarting = true;  // until startRenderer has a renderer or has failed
let pendingTree = null;        // the tree that came before the renderer (installed once it is up)

async function startRenderer() {
  try {
    frame = new Frame(ui.canvas, { camera, what: 'the tree', request: () => requestFrame() });
    await frame.init();
    frame.setShadows(ui.shadows.value !== 'off');
    renderer = await frame.addLayer(new Renderer(frame));
    showSun(false);  // the state's sun when the panel came first
    frames.attach(frame.gl, ui.canvas);
    camera.attach(ui.canvas, cameraMoved);
    new ResizeObserver(() => {
      requestFrame();
      requestView();
    }).observe(ui.canvas);
    ui.canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();
      notices.set('webgl', 'The WebGL2 context was lost; reload the page to draw again.');
    });
    requestFrame();
  } catch (e) {
    renderer = null;
    setHooks({ drawing: 'off' });  // no frames will come (tests stop waiting for them)
    notices.set('webgl', `Cannot draw: ${e.message}`);
  }
  rendererStarting = false;
  // A tree that came while WebGL started goes on now; the link gains the camera (cam=).
  const waiting = pendingTree;
  pendingTree = null;
  if (waiting && renderer) installTree(waiting);
  else if (waiting) giveBackTree(waiting);
  writeHash();
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

function select(id) {
  selected = Number.isInteger(id) ? id : null;
  renderer?.select(selected);
  const refusal = selected === null ? '' : cutRefusal(selected, shownYear);
  ui.cut.disabled = selected === null || refusal !== '';
  ui.selection.textContent = selected === null
    ? 'Click or tap a branch in the view to select it.'
    : refusal || `Branch ${selected} selected: Cut (or the Delete key) removes it and everything above it after year ${shownYear}.`;
  setHooks({ selected: selected === null ? '' : selected });
  // A frame in parts begun before the click has the old selection's steps (no x-ray pass for the
  // new branch): drop it and start one with the new highlight, instead of finishing it first.
  freshNext = true;
  requestFrame();
}

// Opens the full table's row `key` (its section) and focuses it, so its help line shows.
function openTableRow(key) {
  const input = document.getElementById(`param-${key}`);
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
  });
  gettingStarted = new GettingStarted($('getting-started'), msg.paramTable, ui.years, openTableRow);
  dock.add('age', $('getting-started').querySelector('[data-for-key="years"]'));
  // The table's Bark group (bark, bark_model: view rows, re-texturing the tree grown) shown in the
  // view's settings beside the Bark notice, not among the model's rows.
  const barkGroup = ui.params.querySelector('[data-key="bark"]')?.closest('details');
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

// Once on the GPU (or dropped), the mesh's buffers, its textures' pixels and the hybrid atlas
// (painted at install) go back for the worker's next tree to fill; nothing on the page reads
// them after (the renderer keeps copies of what it keeps).
function giveBackTree(msg) {
  const { bark, leaves, flowers } = msg.mesh;
  worker.recycle({ bark, leaves, flowers, ...treeExtras(msg) });
}

// Puts a grown tree on the renderer (framing the camera on it when asked).
function installTree(msg) {
  const installed = renderer.setTree(msg.mesh, msg.stats.bounds, msg.swayNodes, msg.hybrid);
  // A big mesh is installed a few tasks later (uploaded in parts): a draw list that arrives
  // before then finds no hybrid tree and is dropped, so the view is asked for again once the
  // tree is in place.
  const later = renderer.uploading;
  installed.then((done) => {
    giveBackTree(msg);
    if (done) governor.reset();  // another tree: its frames cost what they cost
    if (done && later) requestView();
    requestFrame();
  });
  renderer.leafLength = Number(panel.values().leaf_size) / 100 || 0.05;
  lastBounds = msg.stats.bounds;
  if (frameNext) {
    camera.frame(msg.stats.bounds, 1.12);  // room for the year bar over the view
    frameNext = false;
    writeHash();
  }
  requestFrame();
}

worker.on('tree', (msg) => {
  if (!controller.isLatest(msg)) return;
  controller.showWork(false);
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
  if (renderer) installTree(msg);
  else if (rendererStarting) {
    // WebGL still starting (a slow first shader compile): the tree waits for it, the last one only.
    if (pendingTree) giveBackTree(pendingTree);
    pendingTree = msg;
  } else {
    giveBackTree(msg);
  }
  hybridOn = Boolean(msg.hybrid);
  viewInFlight = false;
  motionInFlight = false;
  motionOff = false;
  table.showHybridCounts(null);
  setHooks({ renderMode: hybridOn ? 'hybrid' : 'full' });
  requestView();
  // A new tree clears the selection; another age of it, or a later stage of it, keeps it.
  const sameTree = latestRequest.kind === 'scrub' || !msg.grown;
  select(sameTree ? selected : null);
  treeSerial += 1;
  // (the stages a restage re-did, core TreeRun::Update, go to the hooks from the controller)
  if (msg.grown) bumpHook('treesGrown');
  setHooks({
    status: 'ready', treeSerial, internodes: msg.stats.internodes, leaves: msg.stats.leaves,
    flowers: msg.stats.flowers, year: msg.stats.years,
    // bench/edit_latency.mjs: the worker's time for this tree and when it reached the page
    treeWorkerMs: msg.workerMs == null ? '' : msg.workerMs.toFixed(1), treeArrivedMs: performance.now().toFixed(1),
  });
  if (windPlaying) worker.post('wind', { play: true });  // sway the new tree (or new wind) too
  else showWind(null);
  // "stale" stays while a newer edit waits (the controller sends it now if it was queued behind
  // this tree); else it goes with the first frame of this tree.
  if (!controller.editWaiting()) {
    if (renderer) freshOnDraw = true; else feedback.fresh();
  }
});

worker.on('motionAtlas', (msg) => {
  countReuse('motion', msg.buffers);
  // Painted (or dropped): its buffers go back for the worker's next atlas to fill.
  const giveBack = () => worker.recycle(atlasGroups(msg.hybrid));
  if (!renderer) return giveBack();
  renderer.setMotionHybrid(msg.hybrid, governor.budget()).then((painted) => {
    giveBack();
    if (painted) setHooks({ motionTextured: renderer.motion.hybrid.textured.join(',') });  // tests
    if (governor.moving()) requestFrame();
  });
});

worker.on('drawList', (msg) => {
  if (msg.motion) {
    motionInFlight = false;
    renderer?.setMotionDrawList(msg);
    if (governor.moving()) requestFrame();
    if (motionDirty) requestMotionView();
    return;
  }
  viewInFlight = false;
  if (!hybridOn || !renderer) return;
  renderer.setDrawList(msg);
  viewsReceived += 1;
  // Uploaded: the list's buffers go back for the worker's next draw list to fill.
  worker.recycle({ cards: msg.cards, lines: msg.lines });
  countReuse('view', msg.buffers);
  table.showHybridCounts(msg.stats);
  requestFrame(true);  // a hybrid frame is cheap: the new list at once, not after the frame in flight
  if (viewDirty) requestView();
});

// The worker's buffers reused and fresh (web/worker/transfer.js), per kind of reply, for the hooks
// data-<kind>-buffers-reused and -fresh.
const reuse = {};
function countReuse(kind, buffers) {
  const r = (reuse[kind] ||= { reused: 0, fresh: 0 });
  r.reused += buffers?.reused || 0;
  r.fresh += buffers?.fresh || 0;
  setHooks({ [`${kind}BuffersReused`]: r.reused, [`${kind}BuffersFresh`]: r.fresh });
}

worker.on('pose', (msg) => {
  if (!windPlaying || !renderer || renderer.uploading) {  // no poses for a tree not yet in place
    worker.post('poseDone');
    return;
  }
  renderer.setPoses(viewOf(Float32Array, msg.poses), msg.wind, msg.time);
  // Uploaded: the poses buffer goes back for the worker's next pose to fill.
  worker.recycle({ sway: { poses: msg.poses } });
  countReuse('pose', msg.buffers);
  governor.motion();
  poseDrawPending = true;
  showWind(msg);
  requestFrame();
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
  if (!down || !renderer) return;
  const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
  const quick = performance.now() - down.t < 600;
  down = null;
  if (moved > 5 || !quick) return;
  const rect = ui.canvas.getBoundingClientRect();
  select(renderer.pick(camera, e.clientX - rect.left, e.clientY - rect.top));
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
  // The still frames were slow: the sway will want the cheaper representation, asked for first.
  if (play && governor.motionCheap() > 0 && !renderer?.motionReady()) requestMotionView();
  worker.post('wind', { play });
  if (!play) {
    governor.stop();  // the rest shape at full quality, at once
    renderer?.setRestPoses(renderer.poseNodes);
    requestFrame(true);
  }
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
    ui.timeFrames.textContent = 'Cancelling…';
    return;
  }
  if (!renderer) return;
  const label = ui.timeFrames.textContent;
  const run = { cancelled: false };
  timing = run;
  ui.timeFrames.textContent = 'Cancel timing';
  setHooks({ timing: 'running' });
  try {
    const timed = await frame.timeFrames(10, { cancelled: () => run.cancelled });
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
    requestFrame();
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
  frame?.setShadows(ui.shadows.value !== 'off');
  setHooks({ shadows: ui.shadows.value });
  requestFrame(true, true);
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
  if (!renderer) return;
  frame.render(camera);
  ui.canvas.toBlob((blob) => {
    if (blob) download(blob, `${fileStem()}.png`, ui.shareStatus);
    else ui.shareStatus.textContent = 'The picture could not be saved.';
  }, 'image/png');
});

// Save / Open: the whole state as a file (the CLI's --state); an opened state is a new history
// entry, drawn from its own camera when it has one.
mountStateFile({ save: $('save-state'), open: $('open-state'), input: $('open-state-file'), status: $('state-status') }, {
  worker,
  state: () => ({ ...currentState(), camera: renderer ? camera.toHash() : '' }),
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
startRenderer();
worker.request('init', { hash: location.hash }, { done: ['ready'] });
