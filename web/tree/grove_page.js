// Grove page (public/grove.html): 100 trees made of 10 unique trees (5 presets × 2 seeds), each grown
// once in the shared worker and drawn instanced, in full mode or hybrid mode (thesis ch. 4) with one
// eq. 4.1 draw list per (unique tree, distance band). Hash: #mode=full|hybrid&cam=yaw,pitch,dist,tx,ty,tz
// &wind=1 (blowing) and any of the wind rows of the parameter table (WIND below), read at load.
// Wind (issue 6, beyond the thesis): Blow sways every instance with the wind at ITS position: the
// worker runs one SwaySimulator per instance (origin = the instance's base) for each unique tree and
// sends all instances' poses of that tree in one 'pose'; the shaders skin each instance with its block.
// The worker's clients (one per unique tree, 'grove-0' ..., and 'grove' for the module's ready
// message), a worker failure and the notices are the study controller's
// (web/shell/study_controller.js, without history: the hash is the grove's view, not a state).
// The view is one Frame (web/gl/frame.js: the page's camera, the tree's sun, the ground) with the
// grove's renderer as its layer, as the other study pages draw.
// Does not: grow or sway trees (the worker does) or draw directly (grove_renderer.js does).
import { OrbitCamera } from '../gl/orbit_camera.js';
import { drawingBufferSize, finishGpu } from '../gl/context.js';
import { Frame } from '../gl/frame.js';
import { FrameLoop, nextFrame } from '../gl/frame_loop.js';
import { viewOf } from '../gl/buffers.js';
import { DEFAULT_SUNS } from '../gl/sun.js';
import { StudyController } from '../shell/study_controller.js';
import { Notices, mountStudyNav } from '../shell/study_page.js';
import { bumpHook, hookValue, setHooks } from '../shell/test_hooks.js';
import { treeExtras } from '../shell/worker_client.js';
import { GroveRenderer, MEMBER_FLOATS } from './grove_renderer.js';

// The unique trees: a few seconds of growing in total.
export const UNIQUE = [
  { preset: 'sakura', seed: 1, years: 9 }, { preset: 'sakura', seed: 2, years: 9 },
  { preset: 'keyaki', seed: 1, years: 12 }, { preset: 'keyaki', seed: 2, years: 12 },
  { preset: 'maple', seed: 1, years: 10 }, { preset: 'maple', seed: 2, years: 10 },
  { preset: 'ginkgo', seed: 1, years: 10 }, { preset: 'ginkgo', seed: 2, years: 10 },
  { preset: 'pine', seed: 1, years: 10 }, { preset: 'pine', seed: 2, years: 10 },
];
const ROWS = 10, SPACING = 4.2;  // 10 × 10 trees, metres apart (jittered)
const BAND_RATIO = 1.4;  // distance bands: [d, 1.4 d) share one draw list per unique tree
// The grove's wind (rows of the parameter table, group "wind"): 8 m/s towards +x with a gust front
// travelling downwind at 4 m/s that enters the grove's upwind edge (x ≈ −20 m) as Blow is pressed
// (gust_on 5 s at x = 0) and crosses it in about 10 s, and a ±40 % wave 25 m long every 5 s; the wind
// then blows for the 10 minutes of the run. A hash key of the same name overrides a value.
export const WIND = {
  wind_speed: 8, wind_dir: 0, gust_on: 5, gust_off: 600, duration: 600,
  gust_front_speed: 4, wind_variation: 0.4, wind_wavelength: 25, wind_period: 5,
};

const ui = {
  canvas: document.getElementById('view'),
  mode: document.getElementById('mode'),
  stats: document.getElementById('stats'),
  time: document.getElementById('time'),
  frames: document.getElementById('frames'),
  timing: document.getElementById('timing'),
  message: document.getElementById('message'),
  reset: document.getElementById('reset-view'),
  wind: document.getElementById('wind'),
  windInfo: document.getElementById('wind-info'),
};

// The grove: instance -> unique tree, base position and scale (a fixed pseudo-random layout).
function layout() {
  let state = 20240531;
  const random = () => {  // mulberry32
    state = (state + 0x6d2b79f5) | 0;
    let t = Math.imul(state ^ (state >>> 15), 1 | state);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const out = [];
  const blocks = new Array(UNIQUE.length).fill(0);
  for (let r = 0; r < ROWS; ++r) {
    for (let c = 0; c < ROWS; ++c) {
      const tree = (r * 3 + c) % UNIQUE.length;
      out.push({
        tree,
        block: blocks[tree]++,  // its index among the tree's instances: its pose block
        position: [(c - (ROWS - 1) / 2 + (random() - 0.5) * 0.5) * SPACING, 0,
          (r - (ROWS - 1) / 2 + (random() - 0.5) * 0.5) * SPACING],
        scale: 0.8 + 0.4 * random(),
      });
    }
  }
  return out;
}
const INSTANCES = layout();

let frame = null;     // the page's one Frame (camera, sun, ground)
let renderer = null;  // the grove's layer of it (GroveRenderer)
const camera = new OrbitCamera();
const trees = [];  // unique tree index -> {bounds, stats} once grown
let mode = 'hybrid';
let timing = null;  // last "Time N frames" result
let viewRound = 0, viewPending = null, viewDirty = false, viewMs = 0;
let wind = { ...WIND };   // the wind of every unique tree's state (WIND with the hash's overrides)
let windPlaying = false, windRound = 0;
const sway = [];          // unique tree -> {time, wind, stepMs, poses} of the last pose drawn
const poseDone = new Set();  // clients whose pose is waiting for the next frame
// The notices line: the wind keys of the hash the core dropped, then a failure.
const notices = new Notices(ui.message, ['hash', 'error']);
// The study controller's client 'grove' (the module's ready message; an error reply of its own is
// a failure) plus one client per unique tree ('grove-0' ...), all of the tree study.
const controller = new StudyController({
  study: 'tree', name: 'grove', history: false, notices, ui: {},
  onError: (msg, when) => {
    if (when === 'before') fail(`${msg.client || 'worker'}: ${msg.message}`);
    return true;
  },
});
const groveClient = controller.worker;
const treeClients = UNIQUE.map((_, index) => controller.client(`grove-${index}`));
mountStudyNav(document.getElementById('studies'), 'grove');

function readHash() {
  const params = new URLSearchParams(location.hash.slice(1));
  mode = params.get('mode') === 'full' ? 'full' : 'hybrid';
  ui.mode.value = mode;
  setHooks({ mode });
  return { cam: params.get('cam'), wind: params.get('wind') === '1' };
}

function writeHash() {
  const params = new URLSearchParams(location.hash.slice(1));
  // Decoded values are encoded again when written back: "5&mode=full" stays one value.
  const extra = Object.keys(WIND).filter((k) => params.has(k))
    .map((k) => `&${k}=${encodeURIComponent(params.get(k))}`).join('');
  const hash = `#mode=${mode}&cam=${camera.toHash()}${windPlaying ? '&wind=1' : ''}${extra}`;
  if (location.hash !== hash) history.replaceState(null, '', hash);
}

function resetCamera() {
  camera.yaw = 0.6;
  camera.pitch = 0.34;
  const half = (ROWS / 2) * SPACING;
  camera.frame({ min: [-half, 0, -half], max: [half, 5, half] }, 0.58);
  camera.target[1] = 1;
}

function fail(text) {
  setHooks({ status: 'error' });
  notices.set('error', text);
}

const n = (x) => Math.round(x).toLocaleString('en-US');
function updateStats(drawn) {
  const grown = trees.filter(Boolean).length;
  const parts = [`${drawn.instances} trees (${drawn.uniqueDrawn} unique of ${UNIQUE.length})`, mode,
    `${n(drawn.triangles)} triangles`, `${n(drawn.lines)} lines`, `${drawn.drawCalls} draw calls`];
  if (mode === 'hybrid' && viewMs) parts.push(`draw lists ${viewMs.toFixed(0)} ms`);
  if (windPlaying && sway.length) {
    const cost = sway.reduce((sum, s) => sum + (s?.stepMs || 0), 0);
    parts.push(`sway ${cost.toFixed(1)} ms/step (${INSTANCES.length} trees)`);
  }
  if (timing) parts.push(`${timing.median.toFixed(1)} ms/frame (${timing.mode}, median of ${timing.frames})`);
  ui.stats.textContent = grown < UNIQUE.length ? `growing ${grown}/${UNIQUE.length} unique trees…` : parts.join(' · ');
  setHooks({
    instances: drawn.instances, uniqueDrawn: drawn.uniqueDrawn, unique: UNIQUE.length,
    triangles: drawn.triangles, lines: drawn.lines, drawCalls: drawn.drawCalls, drawnMode: drawn.mode,
  });
}

const frameLoop = new FrameLoop(() => {
  const pending = [...poseDone];
  poseDone.clear();
  updateStats(drawGrove());
  bumpHook('frameSerial');
  // The round of draw lists this frame drew (hybrid): a test waits for it, not just for the lists.
  setHooks({ drawnViewSerial: mode === 'hybrid' ? hookValue('viewSerial') || '0' : '0' });
  if (windPlaying) showWind();
  // The worker sends a tree's next pose once this one is on screen.
  for (const client of pending) treeClients[Number(client.slice('grove-'.length))].post('poseDone');
  // Ready once a frame with every unique tree is on screen (hybrid: see data-view-pending too).
  if (trees.filter(Boolean).length === UNIQUE.length && hookValue('status') === 'loading') setHooks({ status: 'ready' });
});
function requestFrame() {
  if (renderer) frameLoop.request();
}

// Draws the frame with the grove in `mode`, every unique tree or `only`'s alone (-1: none, the
// ground alone); returns what it drew (the ground's triangles and draw call included).
function drawGrove(only = undefined) {
  renderer.mode = mode;
  renderer.only = only;
  return frame.render();
}

// Hybrid mode: one 'view' per (unique tree, distance band) with that band's nearest instance's
// camera in the tree's own frame; the worker keeps the hysteresis per (tree, band) slot. One round
// at a time; the last round's draw lists stay on screen until the next is complete.
function requestViews() {
  if (mode !== 'hybrid' || !renderer || trees.filter(Boolean).length < UNIQUE.length) return;
  if (viewPending) {
    viewDirty = true;
    return;
  }
  viewDirty = false;
  // The drawing buffer's size (the canvas is resized only by a frame drawn: resizing blanks it).
  const [width, height] = drawingBufferSize(ui.canvas, renderer.scale);
  const eye = camera.position();
  const groups = new Map();
  for (const instance of INSTANCES) {
    const b = trees[instance.tree].bounds;
    const s = instance.scale, p = instance.position;
    const centre = [0, 1, 2].map((k) => p[k] + s * (b.min[k] + b.max[k]) / 2);
    const distance = Math.hypot(eye[0] - centre[0], eye[1] - centre[1], eye[2] - centre[2]);
    const band = Math.max(0, Math.min(255, Math.floor(Math.log(Math.max(distance, 0.5)) / Math.log(BAND_RATIO)) + 3));
    const key = `${instance.tree}:${band}`;
    if (!groups.has(key)) groups.set(key, { tree: instance.tree, band, members: [] });
    groups.get(key).members.push({ instance, distance });
  }
  const round = ++viewRound;
  viewPending = { round, start: performance.now(), waiting: groups.size, lists: [] };
  setHooks({ viewPending: 1 });
  for (const group of groups.values()) {
    group.members.sort((a, b) => a.distance - b.distance);
    const rep = group.members[0];
    const s = rep.instance.scale, p = rep.instance.position;
    const local = (v) => v.map((x, k) => (x - p[k]) / s);
    const members = new Float32Array(group.members.length * MEMBER_FLOATS);
    group.members.forEach((m, i) => {
      members.set([...m.instance.position, m.instance.scale, (m.instance.scale / s) * (rep.distance / m.distance),
        m.instance.block, 0], i * MEMBER_FLOATS);
    });
    viewPending.lists.push({ tree: group.tree, band: group.band, members });
    treeClients[group.tree].post('view', {
      slot: group.band, tag: round,
      camera: { eye: local(eye), target: local(camera.target), fovY: camera.fov, width, height },
    });
  }
}

function onDrawList(msg) {
  if (!viewPending || msg.tag !== viewPending.round) return;
  const tree = Number(msg.client.slice('grove-'.length));
  const list = viewPending.lists.find((l) => l.tree === tree && l.band === msg.slot);
  if (!list) return;
  Object.assign(list, { cards: msg.cards, lines: msg.lines });
  if (--viewPending.waiting > 0) return;
  renderer.setBands(viewPending.lists);
  viewMs = performance.now() - viewPending.start;
  viewPending = null;
  bumpHook('viewSerial');
  setHooks({ viewMs: viewMs.toFixed(1) });
  if (viewDirty) requestViews();
  else setHooks({ viewPending: 0 });
  requestFrame();
}

function onTree(msg) {
  const index = Number(msg.client.slice('grove-'.length));
  const mine = INSTANCES.filter((i) => i.tree === index);
  const instances = new Float32Array(mine.length * 4);
  mine.forEach((i, k) => instances.set([...i.position, i.scale], k * 4));
  renderer.addTree(index, msg.mesh, instances, msg.hybrid, msg.swayNodes, msg.stats.bounds);
  // Uploaded at once: the buffers go back for the worker's next tree of this client to fill.
  const { bark, leaves, flowers } = msg.mesh;
  treeClients[index].recycle({ bark, leaves, flowers, ...treeExtras(msg) });
  trees[index] = { bounds: msg.stats.bounds, stats: msg.stats, nodes: msg.swayNodes };
  if (trees.filter(Boolean).length === UNIQUE.length) {
    requestViews();
    if (windPlaying) startWind();
  }
  requestFrame();
}

// ---- Wind: every unique tree's instances swayed in the worker, all on one shared clock ----
function startWind() {
  if (trees.filter(Boolean).length < UNIQUE.length) return;  // starts once every tree is grown
  const clock = `grove-wind-${++windRound}`;
  UNIQUE.forEach((_, index) => {
    const origins = INSTANCES.filter((i) => i.tree === index).flatMap((i) => i.position);  // metres, block order
    treeClients[index].post('wind', { play: true, origins, clock });
  });
}

function setWind(play) {
  windPlaying = play;
  ui.wind.textContent = play ? 'Still' : 'Blow';
  ui.wind.setAttribute('aria-pressed', String(play));
  setHooks({ wind: play ? 'on' : 'off' });
  writeHash();
  sway.length = 0;
  if (play) {
    startWind();
  } else {
    UNIQUE.forEach((_, index) => {
      treeClients[index].post('wind', { play: false });
      renderer?.setRestPoses(index);
    });
  }
  showWind();
  requestFrame();
}

function onPose(msg) {
  const index = Number(msg.client.slice('grove-'.length));
  if (!windPlaying || !renderer || !trees[index]) {
    treeClients[index].post('poseDone');
    return;
  }
  const poses = viewOf(Float32Array, msg.poses);  // kept: this page hands no pose buffer back
  renderer.setPoses(index, poses);
  sway[index] = { time: msg.time, wind: msg.wind, stepMs: msg.stepMs, poses };
  poseDone.add(msg.client);
  requestFrame();
}

// The wind line and data-sway-time (the earliest simulated time among the unique trees on screen).
function showWind() {
  if (!windPlaying) {
    ui.windInfo.textContent = 'Still air. Blow: a gust front crosses the grove from the left (−x), each tree sways with the wind at its place.';
    setHooks({ swayTime: '' });
    return;
  }
  const shown = sway.filter(Boolean);
  if (shown.length < UNIQUE.length) {
    ui.windInfo.textContent = 'starting the wind…';
    return;
  }
  const time = Math.min(...shown.map((s) => s.time));
  const cost = shown.reduce((sum, s) => sum + s.stepMs, 0);
  ui.windInfo.textContent = `t = ${time.toFixed(1)} s · wind ${shown[0].wind.toFixed(1)} m/s at the centre · front ${wind.gust_front_speed} m/s`;
  setHooks({ swayTime: time.toFixed(3), swayStepMs: cost.toFixed(2) });
}

// For the tests: per instance of unique tree `tree`, its position and a measure of its sway in the
// last pose drawn: the sum over node points of |M_j| (eq. 3.15 tip offsets, metres) and the mean
// M_j.x (along the default wind); null while no pose was drawn.
function swayProbe(tree) {
  const s = sway[tree];
  if (!s || !trees[tree]) return null;
  const nodes = trees[tree].nodes;
  const out = INSTANCES.filter((i) => i.tree === tree).map((instance, k) => {
    let sum = 0, x = 0;
    for (let j = 0; j < nodes; ++j) {
      const o = (k * nodes + j) * 16;
      sum += Math.hypot(s.poses[o + 3], s.poses[o + 7], s.poses[o + 11]);
      x += s.poses[o + 3];
    }
    return { position: instance.position, block: instance.block, tipOffsetSum: sum, meanOffsetX: x / nodes };
  });
  return { time: s.time, nodes, instances: out };
}

// Largest difference between two instances' pose blocks of unique tree `tree` (0: identical).
function poseBlockDifference(tree, a, b) {
  const s = sway[tree];
  if (!s) return null;
  const n = trees[tree].nodes * 16;
  let most = 0;
  for (let i = 0; i < n; ++i) most = Math.max(most, Math.abs(s.poses[a * n + i] - s.poses[b * n + i]));
  return most;
}

// The wind keys as a tree-state hash for the core's decoder: each WIND key with the page's value
// or the hash's (re-encoded), so a bad value is named and dropped by the core (one notice each)
// and the others still apply; the gust order is checked against the grove's own values.
let windHash = '';
function windStateHash(params) {
  return Object.keys(WIND).map((k) => `${k}=${encodeURIComponent(params.has(k) ? params.get(k) : String(WIND[k]))}`).join('&');
}

// The decoded wind: a value the core dropped keeps the grove's default; clamped ones are used.
function applyDecodedWind(decoded) {
  const lines = decoded?.notices ?? [];
  const hashParams = new URLSearchParams(location.hash.slice(1));
  for (const key of Object.keys(WIND)) {
    if (!hashParams.has(key)) continue;
    const dropped = lines.some((line) => line.startsWith(`${key}:`) && line.includes('dropped'));
    const value = decoded?.state?.params?.[key];
    if (!dropped && Number.isFinite(value)) wind[key] = value;
  }
  if (lines.length) notices.set('hash', lines);
  setHooks({ notices: lines.length });
}

// The module is ready: every unique tree is grown once (each client's own request).
groveClient.on('ready', (msg) => {
  applyDecodedWind(msg.decoded);
  UNIQUE.forEach((u, index) => treeClients[index].request('update', {
    state: { preset: u.preset, seed: u.seed, years: u.years, params: { render_mode: 1, ...wind } },
  }, { done: ['tree'] }));
});
for (const client of treeClients) {
  client.on('tree', onTree).on('pose', onPose).on('drawList', onDrawList)
    .on('progress', () => requestFrame())
    .on('error', (msg) => fail(`${msg.client || 'worker'}: ${msg.message}`));
}

// Times `frames` frames of the current view (after one untimed frame): each is drawn and then
// waited for (gl.readPixels of one pixel blocks until the GPU is done); the median is shown.
// only = -1 times the ground alone (the frame's fixed cost), as drawGrove().
// warmUp: draw one untimed frame first (false when the mode has just been drawn: a full-mode frame of
// the grove is about 12 s on SwiftShader, so the grove test times one, right after the full-mode draws).
// While it runs the button is its Cancel (a full-mode frame of the grove takes seconds on a CPU GL:
// 20 of them ran 228 s with no way out, issue 32); a cancelled timing shows the frames it timed.
let timingCancelled = false;
async function timeFrames(frames = 20, only = undefined, warmUp = true) {
  if (!renderer || hookValue('status') !== 'ready' || hookValue('timing') === 'running') return null;
  setHooks({ timing: 'running' });
  timingCancelled = false;
  const label = ui.time.textContent;
  ui.time.textContent = 'Cancel timing';
  const times = [];
  let drawn = null;
  for (let i = warmUp ? -1 : 0; i < frames; ++i) {
    await nextFrame();
    if (timingCancelled) break;
    const start = performance.now();
    drawn = drawGrove(only);
    finishGpu(renderer.gl);
    if (i >= 0) times.push(performance.now() - start);
  }
  ui.time.textContent = label;
  if (timingCancelled && times.length === 0) {
    ui.timing.textContent = 'timing cancelled before its first frame';
    setHooks({ timing: 'cancelled', timedFrames: 0 });
    requestFrame();
    return null;
  }
  const cancelled = timingCancelled;
  frames = times.length;
  times.sort((a, b) => a - b);
  const median = times.length % 2 ? times[(times.length - 1) / 2] : (times[times.length / 2 - 1] + times[times.length / 2]) / 2;
  timing = { mode: only === undefined ? mode : 'ground only', frames, median, min: times[0], max: times[times.length - 1], ...drawn };
  ui.timing.textContent = `${timing.mode}: ${median.toFixed(1)} ms per frame (median of ${frames}${cancelled ? ', cancelled' : ''}; ` +
    `${times[0].toFixed(1)}–${times[times.length - 1].toFixed(1)} ms), ${renderer.canvas.width}×${renderer.canvas.height} px`;
  setHooks({ timing: cancelled ? 'cancelled' : 'done', frameMs: median.toFixed(2), timedMode: timing.mode, timedFrames: frames });
  if (only !== undefined) requestFrame();  // the whole grove back on screen
  else updateStats(drawn);
  window.grove.lastTiming = { ...timing, width: renderer.canvas.width, height: renderer.canvas.height, viewMs };
  return window.grove.lastTiming;
}

// Share of canvas pixels each unique tree covers when its instances are drawn alone (differs from
// the bare ground by more than a faint amount): every unique tree must show in both modes.
function coverage() {
  if (!renderer) return [];
  drawGrove(-1);
  const empty = renderer.readCanvas();
  const shares = UNIQUE.map((_, index) => {
    drawGrove(index);
    const pixels = renderer.readCanvas();
    let count = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      if (Math.abs(pixels[i] - empty[i]) + Math.abs(pixels[i + 1] - empty[i + 1]) + Math.abs(pixels[i + 2] - empty[i + 2]) > 24) ++count;
    }
    return count / (pixels.length / 4);
  });
  updateStats(drawGrove());
  return shares;
}

function setMode(next) {
  mode = next === 'full' ? 'full' : 'hybrid';
  ui.mode.value = mode;
  setHooks({ mode });
  writeHash();
  requestViews();
  requestFrame();
}

async function start() {
  setHooks({ status: 'loading', viewPending: 0 });
  const { cam, wind: blowing } = readHash();
  // The wind settings are part of every unique tree's state: read once, before the trees are grown.
  const params = new URLSearchParams(location.hash.slice(1));
  windHash = windStateHash(params);
  resetCamera();
  if (cam) camera.fromHash(cam);
  try {
    frame = new Frame(ui.canvas, { camera, sun: DEFAULT_SUNS.tree, what: 'the grove', request: () => requestFrame() });
    await frame.init();
    renderer = await frame.addLayer(new GroveRenderer(frame));
    frameLoop.attach(frame.gl, ui.canvas);  // one frame in flight (web/gl/frame_loop.js)
  } catch (e) {
    fail(`Cannot draw: ${e.message}`);
    return;
  }
  camera.attach(ui.canvas, () => {
    writeHash();
    requestViews();
    requestFrame();
  });
  new ResizeObserver(() => {
    requestViews();
    requestFrame();
  }).observe(ui.canvas);
  ui.mode.addEventListener('change', () => setMode(ui.mode.value));
  ui.wind.addEventListener('click', () => setWind(!windPlaying));
  setWind(blowing);
  ui.reset.addEventListener('click', () => {
    resetCamera();
    writeHash();
    requestViews();
    requestFrame();
  });
  ui.frames.addEventListener('input', () => {
    ui.time.textContent = `Time ${Math.max(1, Math.min(200, Number(ui.frames.value) || 20))} frames`;
  });
  ui.time.addEventListener('click', () => {
    if (hookValue('timing') === 'running') {
      timingCancelled = true;
      ui.time.textContent = 'Cancelling…';
      return;
    }
    timeFrames(Math.max(1, Math.min(200, Number(ui.frames.value) || 20)));
  });
  window.addEventListener('hashchange', () => {
    const { cam, wind: blowing } = readHash();
    if (cam) camera.fromHash(cam);
    if (blowing !== windPlaying) setWind(blowing);
    requestViews();
    requestFrame();
  });
  writeHash();
  groveClient.request('init', { hash: windHash }, { done: ['ready'] });
  requestFrame();
}

// For tests and bench/grove.mjs; lastTiming is the last "Time N frames" result.
window.grove = {
  timeFrames, coverage, swayProbe, poseBlockDifference, requestFrame, instances: INSTANCES.length, unique: UNIQUE.length,
  get frame() { return frame; },  // the page's Frame and its grove layer (tests)
  get renderer() { return renderer; },
  layout: INSTANCES, lastTiming: null,
};
start();
