// The terrain study's page (public/terrain.html, main thread; paper 002, Misawa, Chiba, Saito):
// opens with a mountain grown from a built-in seed, builds the panel from the terrain table, keeps
// the state in location.hash through the terrain hash codec (the same text `niwa terrain grow
// --url` reads: preset, builtin or contour=x,y;..., changed parameters), picks a built-in seed, a
// method or figure preset and the RNG seed, takes a seed contour drawn on the plan view
// (plan_view.js), shows the mountain in 3-D (terrain_renderer.js) and downloads .glb, the 16-bit
// heightmap with its sidecar, and the contours; imports a contour file; offers an embed
// (<niwa-terrain>). Growth runs in the worker (terrain_handler.js).
// Does not: parse or check states or contours (the core does; its one line is shown beside its
// field), or draw directly.
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { OrbitCamera } from '../gl/orbit_camera.js';
import { Frame } from '../gl/frame.js';
import { ProgressiveLoop } from '../gl/progressive_loop.js';
import { DEFAULT_SUNS } from '../gl/sun.js';
import { FileDrop } from '../shell/file_drop.js';
import { ParamPanel } from '../shell/param_panel.js';
import { StepScrubber } from '../shell/step_scrubber.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { Notices, copyLink, mountStudyNav, showEmbedDialog } from '../shell/study_page.js';
import { bumpHook, setHooks } from '../shell/test_hooks.js';
import { gridIndices } from './grid_indices.js';
import { PlanView } from './plan_view.js';
import { TerrainRenderer } from './terrain_renderer.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'), plan: $('plan'), stats: $('stats'), progress: $('progress'), builtin: $('builtin'),
  builtinHelp: $('builtin-help'), preset: $('preset'), presetHelp: $('preset-help'), rngSeed: $('rng-seed'),
  reset: $('reset'), showContours: $('show-contours'), showTint: $('show-tint'), resetView: $('reset-view'),
  copyLink: $('copy-link'), shareStatus: $('share-status'), params: $('params'), play: $('play'), level: $('level'),
  levelText: $('level-text'), cancel: $('cancel'),
};
mountStudyNav($('studies'), 'terrain');

// webgl: drawing problems; error: the core's line for the current state; hash: decoding notices;
// budget: the page budget's line when it stopped the growth early (docs/budgets.md).
const notices = new Notices($('notice'), ['webgl', 'error', 'hash', 'budget']);
// Errors beside the controls outside the panel (the panel's rows find their own).
const BASIC_FIELDS = { builtin: 'builtin-error', preset: 'preset-error', seed: 'rng-seed-error', contour: 'contour-error' };
// The worker, Cancel (issue 16: whatever the worker is doing, a grow or an export, ends now),
// updates, history, exports and errors (web/shell/study_controller.js).
const controller = new StudyController({
  study: 'terrain', notices, ui, fields: BASIC_FIELDS, panel: () => panel, state: () => currentState(false),
  onCancel: () => 'cancelled: back to the last finished mountain',
  // Cancel restarted the worker: init it again, then grow the last finished state (or the
  // opening mountain when none finished yet); the mountain on screen stays until then.
  onRestart: () => {
    restarting = true;
    worker.request('init', { hash: '' }, { done: ['ready'] });
  },
  onError: (msg, when) => {
    if (when === 'after') ui.rngSeed.setAttribute('aria-invalid', msg.field === 'seed' ? 'true' : 'false');
    return false;
  },
});
const { worker } = controller;
let restarting = false;  // the next 'ready' answers a restart (the panel exists already)
let lastGoodHash = null; // the hash of the last mountain shown

// The opening mountain when the link holds no seed: a result without input.
const OPENING = { preset: 'improved', builtin: 'lobes7' };
const DRAWN = '(drawn contour)';

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let frame = null;     // the view's one Frame (web/gl/frame.js): its camera, sun and the layers
let renderer = null;  // the mountain's layer of it
let terrainSerial = 0;
let installedSerial = 0;  // the mountain whose buffers are in place (a big one goes up in parts)
// Frames on demand over the renderer's progressive parts (web/gl/progressive_loop.js); the hooks
// describe a finished frame.
const loop = new ProgressiveLoop({
  renderer: () => (renderer ? frame : null),
  camera,
  onDrawn: (drawn) => {
    setHooks({
      drawnSerial: installedSerial, drawnLevel: Number.isFinite(shownLevel) ? shownLevel : 'all', drawnTriangles: drawn.triangles, drawnLines: drawn.lines,
      drawCalls: drawn.drawCalls,
    });
  },
});
const requestFrame = () => loop.request();

// The level scrubber and Play: the mountain contour by contour, from the seed (or the lowest
// `down` contour) to the top; nothing regrows. Level k shows the contours up to k and the surface
// cut flat at h0 + k·Δh; the top level shows everything (summits included).
let levels = { min: 0, max: 0, h0: 0, dh: 1 };
let shownLevel = Infinity;
const scrubber = new StepScrubber({ range: ui.level, text: ui.levelText, play: ui.play }, (step) => {
  const k = levels.min + step;
  const all = k >= levels.max;
  shownLevel = all ? Infinity : k;
  ui.levelText.textContent = `level ${k} of ${levels.max}`;
  renderer?.setLevel(shownLevel, all ? Infinity : levels.h0 + k * levels.dh);
  plan.setLevel(shownLevel);
  setHooks({ levelShown: k });
  requestFrame();
}, { interval: 250 });

async function startRenderer() {
  try {
    await loop.start(async () => {
      // One study fitted to the view (fit), the terrain's low sun, no ground (the surface is it).
      frame = new Frame(ui.canvas, { camera, sun: DEFAULT_SUNS.terrain, ground: false, fit: true, request: () => loop.request(), what: 'the mountain' });
      await frame.init();
      renderer = await frame.addLayer(new TerrainRenderer(frame));
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

// ---------------------------------------------------------------- state
let panel = null;
let presets = [];
let seeds = [];
let drawnContour = null;  // [[x, y], ...] in metres when the seed is a drawing, else null
let frameNext = true;

// The 3-D view's framing of a mountain: from higher than the tree pages' default angle, so the
// contours are seen from above, and closer (the box is flat: its bounding sphere overstates it).
function frameTerrain() {
  const b = renderer?.bounds();
  if (!b) return;
  camera.reset(b);
  camera.pitch = 0.62;
  camera.frame(b, 0.82);
}

// The state the worker grows: the seed contour (a built-in or the drawing), the preset, the RNG
// seed (a state field, kept by `reset`), and (unless `reset`, which takes the preset's and the
// seed contour's own values) every parameter of the panel.
function currentState(reset) {
  const state = { preset: ui.preset.value, seed: numberOr(ui.rngSeed) };
  if (drawnContour) state.contour = drawnContour;
  else state.builtin = ui.builtin.value;
  state.params = reset ? {} : panel.values();
  return state;
}

// A state from the worker ({preset, builtin, contour?, seed, params}) shown in the controls.
function applyState(state) {
  ui.preset.value = state.preset;
  drawnContour = state.builtin ? null : state.contour;
  if (drawnContour) {
    if (![...ui.builtin.options].some((o) => o.value === '')) ui.builtin.append(new Option(DRAWN, ''));
    ui.builtin.value = '';
  } else {
    ui.builtin.value = state.builtin;
  }
  panel.setValues(state.params);
  ui.rngSeed.value = String(state.seed);
  showHelp();
}

function showHelp() {
  const seed = seeds.find((s) => s.name === ui.builtin.value);
  ui.builtinHelp.textContent = drawnContour ? `A drawn contour of ${drawnContour.length} points.`
    : seed ? `${seed.source} (${seed.points} points)` : '';
  const preset = presets.find((p) => p.name === ui.preset.value);
  ui.presetHelp.textContent = preset ? preset.caption : 'the table\'s defaults (the improved method)';
}

// Sends the state to grow; commit: a new history entry once it has grown.
// repair: the contour is a fresh drawing (the worker makes a self-crossing one simple first).
// statsAfter: the mountain comes first and its stats at once after it ('terrainStats').
const sendUpdate = (commit, reset = false, repair = false) =>
  controller.update(commit, { state: currentState(reset), repair, statsAfter: true }, { done: ['terrainStats'] });
// An edit of a control (stage 'grow') or a panel row (its stage): one update after a quiet moment.
const scheduleUpdate = (stage = 'grow') => controller.schedule(() => sendUpdate(true), stage);

// A core error record {field, message} beside its field ('' clears); the RNG seed box is marked too.
function showFieldError(error) {
  ui.rngSeed.setAttribute('aria-invalid', error?.field === 'seed' ? 'true' : 'false');
  controller.showFieldError(error);
}

// ---------------------------------------------------------------- the drawn seed contour
// Twice the plan's shortest side over 20 device pixels at least, and 8 points at least: a click or
// a scribble is not a contour. Crossings are the core's to find (CheckSeed names "contour").
const MIN_DRAWN_PX = 20, MIN_DRAWN_POINTS = 8;
const plan = new PlanView(ui.plan, (points, pixels) => {
  bumpHook('contourDrawings');
  if (pixels.points < MIN_DRAWN_POINTS || Math.min(pixels.width, pixels.height) < MIN_DRAWN_PX) {
    showFieldError({ field: 'contour', message: `contour: the drawing is too small (${pixels.points} points, ${Math.round(pixels.width)} x ${Math.round(pixels.height)} px); must be a closed loop at least ${MIN_DRAWN_PX} px across with ${MIN_DRAWN_POINTS}+ points` });
    setHooks({ contourNotice: 'small' });
    return;
  }
  takeSeed(points);
});

// ---------------------------------------------------------------- an imported contour file
// The file's text goes to the worker (the core's ParseContourJson, as `niwa terrain grow
// --contour` reads it); its points become the seed as a drawing's do (a crossing one repaired,
// the link carrying it), and its "elevation", when given, becomes h0.
const MAX_CONTOUR_FILE_BYTES = 4 << 20;
const takeSeed = (points) => {
  setHooks({ contourNotice: '' });
  $('contour-note').textContent = '';
  drawnContour = points;
  if (![...ui.builtin.options].some((o) => o.value === '')) ui.builtin.append(new Option(DRAWN, ''));
  ui.builtin.value = '';
  showHelp();
  frameNext = true;
  sendUpdate(true, false, true);
};
async function importContourFile(file) {
  bumpHook('contourImports');
  if (file.size > MAX_CONTOUR_FILE_BYTES) {
    showFieldError({ field: 'contour', message: `contour: ${String(file.name).slice(0, 60)} is ${file.size} bytes; must be at most ${MAX_CONTOUR_FILE_BYTES} bytes` });
    setHooks({ contourNotice: 'file' });
    return;
  }
  const text = await file.text();
  const { reply } = worker.request('parseContour', { name: String(file.name).slice(0, 200), text }, { done: ['contourFile', 'error'] });
  const msg = await reply;
  if (!msg) return;  // superseded, or the worker restarted
  if (msg.ok === false || msg.type === 'error') {
    showFieldError(msg);
    setHooks({ contourNotice: 'file' });
    return;
  }
  if (msg.elevation !== undefined) panel?.setValues({ h0: msg.elevation });
  takeSeed(msg.points);
}
new FileDrop({
  target: ui.plan, input: $('contour-file'), accept: ['.json', '.geojson'], what: 'contour file',
  onFiles: (files) => importContourFile(files[0]),
  onRefuse: (line) => {
    showFieldError({ field: 'contour', message: `contour: ${line}` });
    setHooks({ contourNotice: 'file' });
  },
});

// ---------------------------------------------------------------- worker replies
worker.on('ready', (msg) => {
  if (restarting) {  // after Cancel: the last finished state again
    restarting = false;
    const hash = lastGoodHash ? `#${lastGoodHash}` : `#preset=${OPENING.preset}&builtin=${OPENING.builtin}`;
    worker.request('decode', { hash }, { done: ['decoded'] });
    return;
  }
  presets = msg.presets;
  seeds = msg.seeds;
  ui.preset.append(new Option('defaults (improved)', ''));
  for (const p of presets) ui.preset.append(new Option(p.name, p.name));
  for (const s of seeds) ui.builtin.append(new Option(s.name, s.name));
  panel = new ParamPanel(ui.params, msg.paramTable, (spec, stage) => scheduleUpdate(stage));
  const hash = location.hash.replace(/^#/, '');
  applyState(msg.decoded.state);
  notices.set('hash', msg.decoded.notices);
  if (!/(^|&)(builtin|contour|preset)=/.test(hash)) {
    ui.preset.value = OPENING.preset;
    ui.builtin.value = OPENING.builtin;
    sendUpdate(false, true);
  } else {
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

// The mountain (its stats null: they follow in 'terrainStats', web/worker/terrain_handler.js).
let shownMountain = null;  // {id, msg} of the mountain on screen until its stats arrive
let planLines = null;  // {contours, summits, uploaded}: the worker's buffers the plan draws from
worker.on('terrain', (msg) => {
  if (!controller.isLatest(msg)) return;
  notices.set('error', '');
  showFieldError('');
  lastGoodHash = msg.hash;
  applyState(msg.state);
  const r = msg.repaired, f = msg.simplified;
  const notes = [];
  if (r) notes.push(`The drawing crossed itself; repaired (${r.method === 'loops' ? `${r.loopsRemoved} loop${r.loopsRemoved === 1 ? '' : 's'} cut, §4.4 method 2` : 'its largest simple piece kept'}): ${r.points} points.`);
  // The link holds the contour: one too long for it is put on a grid and thinned first.
  if (f) notes.push(`Simplified to fit a link: ${f.to} of ${f.from} points kept, on a ${f.quantum} m grid.`);
  if (notes.length) $('contour-note').textContent = notes.join(' ');
  if (r) setHooks({ contourRepaired: `${r.method}:${r.loopsRemoved}` });
  if (f) setHooks({ contourSimplified: `${f.from}:${f.to}` });
  // The worker sends no triangles: the grid's are the same for every regrow on it.
  const surface = msg.buffers.surface;
  surface.indices = gridIndices(msg.bounds.width, msg.bounds.height);
  plan.setTerrain(msg.buffers, msg.bounds);
  levels = { min: msg.bounds.level_min, max: msg.bounds.level_max, h0: msg.bounds.h0, dh: msg.bounds.dh };
  const serial = terrainSerial + 1;
  // Once on the GPU, the surface's buffers go back to the worker for the next grow to fill; the
  // contours and summits (views the plan draws from) once a newer mountain replaced them in the
  // plan and their own upload ended (web/worker/transfer.js TransferPool).
  setHooks({ buffersReused: msg.bufferCounts?.reused ?? '', buffersFresh: msg.bufferCounts?.fresh ?? '' });
  const uploaded = renderer ? renderer.setTerrain(msg.buffers, msg.bounds) : Promise.resolve(false);
  const previous = planLines;
  planLines = { contours: msg.buffers.contours, summits: msg.buffers.summits, uploaded };
  previous?.uploaded.then(() => worker.recycle({ contours: previous.contours, summits: previous.summits }));
  uploaded.then((installed) => {
    const { positions, normals, colours } = surface;
    worker.recycle({ surface: { positions, normals, colours } });
    if (!installed || !renderer) return;
    installedSerial = serial;
    if (frameNext && renderer.bounds()) {
      frameTerrain();
      frameNext = false;
    }
    requestFrame();
  });
  controller.grown(msg.hash);
  scrubber.reset(levels.max - levels.min);
  terrainSerial += 1;
  shownMountain = { id: msg.id, msg };
  requestFrame();
});

// The stats of the mountain just shown: the line under the view and the page's hooks.
worker.on('terrainStats', (reply) => {
  if (!controller.isLatest(reply) || !shownMountain || shownMountain.id !== reply.id) return;
  const { msg } = shownMountain;
  const s = reply.stats;
  notices.set('budget', s.truncated_by || '');
  controller.showWork(false);
  ui.progress.textContent = '';
  ui.stats.textContent = `${s.method} · ${s.levels} levels · ${s.contours} contours · ${s.peaks} peak${s.peaks === 1 ? '' : 's'} · relief ${s.relief.toFixed(1)} m · HI ${s.hypsometric_integral.toFixed(3)} · ${s.res} cells across · ${msg.wallMs.toFixed(0)} ms`;
  setHooks({
    status: 'ready', error: '', terrainSerial, levels: s.levels, contours: s.contours, peaks: s.peaks,
    stats: JSON.stringify(s), hash: msg.hash, truncatedBy: s.truncated_by || '', wallMs: msg.wallMs.toFixed(1), msGrow: msg.timings.ms_grow.toFixed(1),
    msHeightfield: msg.timings.ms_heightfield.toFixed(1), msBuffers: msg.timings.ms_buffers.toFixed(1), msStatsAfter: reply.statsMs.toFixed(1),
    grows: msg.timings.grows, heightfields: msg.timings.heightfields, erosions: msg.timings.erosions, msErosion: msg.timings.ms_erosion.toFixed(1),
    regrowParts: JSON.stringify(msg.parts || {}), gridSize: JSON.stringify({ width: msg.bounds.width, height: msg.bounds.height }),
  });
});

const TYPES = { glb: 'model/gltf-binary', heightmap: 'image/png', sidecar: 'application/json', json: 'application/json', geojson: 'application/geo+json', svg: 'image/svg+xml' };

// ---------------------------------------------------------------- controls
ui.builtin.addEventListener('change', () => {
  if (ui.builtin.value === '' && drawnContour) return;
  drawnContour = null;
  $('contour-note').textContent = '';
  showHelp();
  frameNext = true;
  sendUpdate(true, true);  // the seed's own d, Δh, h0 under the chosen method
});
ui.preset.addEventListener('change', () => {
  showHelp();
  sendUpdate(true, true);
});
ui.rngSeed.addEventListener('input', () => scheduleUpdate());
ui.reset.addEventListener('click', () => sendUpdate(true, true));
ui.showContours.addEventListener('change', () => {
  renderer?.setVisible({ contours: ui.showContours.checked });
  requestFrame();
});
ui.showTint.addEventListener('change', () => {
  renderer?.setVisible({ tint: ui.showTint.checked });
  requestFrame();
});
ui.resetView.addEventListener('click', () => {
  frameTerrain();
  requestFrame();
});
ui.copyLink.addEventListener('click', () => copyLink(ui.shareStatus));
// The embed: <niwa-terrain> (public/niwa-terrain.js) or an iframe of public/embed.html?study=terrain,
// with this hash (a drawn contour included).
$('embed').addEventListener('click', () => {
  showEmbedDialog({ tag: 'niwa-terrain', title: 'Niwa terrain', heading: 'Embed this mountain', script: 'niwa-terrain.js',
    frame: 'embed.html?study=terrain' });
});
const exportAs = (format, name) => controller.exportAs(format, name, TYPES[format]);
$('download-glb').addEventListener('click', () => exportAs('glb', 'terrain.glb'));
$('download-heightmap').addEventListener('click', () => {
  exportAs('heightmap', 'terrain-heightmap.png');
  exportAs('sidecar', 'terrain-heightmap.json');
});
$('download-geojson').addEventListener('click', () => exportAs('geojson', 'terrain-contours.geojson'));
$('download-svg').addEventListener('click', () => exportAs('svg', 'terrain-contours.svg'));
$('download-json').addEventListener('click', () => exportAs('json', 'terrain-contours.json'));

// ---------------------------------------------------------------- start
setHooks({ status: 'loading' });
await startRenderer();
worker.request('init', { hash: location.hash }, { done: ['ready'] });
