// The ivy study's page (public/ivy.html, main thread; paper 004, Shindo & Sakamoto): opens with
// cubes4 grown, builds the panel from the ivy table, keeps the state in location.hash through the
// ivy hash codec (the same text `niwa ivy grow --url` reads: preset, seed, steps, scene, at=
// seed points, changed parameters), picks a built-in scene or takes a dropped .glb/.gltf/.obj
// (Draco decoded here by web/mesh/mesh_file.js; a glTF drawn with its own base colour textures,
// WebP included, web/mesh/mesh_images.js, and factors and vertex colours), adds a seed point where the surface is clicked,
// replays the growth with the step scrubber (the vertices' birth steps; nothing regrows), and
// downloads .glb, .json and .lsys. Growth runs in the worker (web/worker/ivy_handler.js).
// Does not: parse or check states (the core does; its one line is shown beside its field), draw
// directly (ivy_renderer.js), or grow the tree it climbs (scene 'tree': the worker grows the
// tree preset's bark, core/compose/ivy_on_tree, as the CLI's --tree-preset does).
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { OrbitCamera } from '../gl/orbit_camera.js';
import { Frame } from '../gl/frame.js';
import { ProgressiveLoop } from '../gl/progressive_loop.js';
import { DEFAULT_SUNS } from '../gl/sun.js';
import { meshFileBytes } from '../mesh/mesh_file.js';
import { baseColorImages } from '../mesh/mesh_images.js';
import { FileDrop } from '../shell/file_drop.js';
import { ParamPanel } from '../shell/param_panel.js';
import { StepScrubber } from '../shell/step_scrubber.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { Notices, copyLink, mountStudyNav, showEmbedDialog } from '../shell/study_page.js';
import { bumpHook, setHooks } from '../shell/test_hooks.js';
import { IvyRenderer } from './ivy_renderer.js';

const $ = (id) => document.getElementById(id);
const ui = {
  stage: $('stage'), canvas: $('view'), stats: $('stats'), progress: $('progress'), scene: $('scene'),
  sceneHelp: $('scene-help'), tree: $('tree'), treeYears: $('tree-years'), meshFile: $('mesh-file'), preset: $('preset'), seed: $('seed'), steps: $('steps'),
  reset: $('reset'), undo: $('undo'), redo: $('redo'), seeds: $('seeds'), clickSeeds: $('click-seeds'), clearSeeds: $('clear-seeds'),
  showLeaves: $('show-leaves'), showLeafTexture: $('show-leaf-texture'), showSupportTexture: $('show-support-texture'), showSuckers: $('show-suckers'), showSupport: $('show-support'), showSeeds: $('show-seeds'), showBuds: $('show-buds'),
  resetView: $('reset-view'), copyLink: $('copy-link'), downloadGlb: $('download-glb'), glbSupport: $('glb-support'),
  downloadJson: $('download-json'), downloadLsys: $('download-lsys'), shareStatus: $('share-status'), params: $('params'),
  embed: $('embed'),
  play: $('play'), step: $('step'), stepText: $('step-text'), progressBar: $('ivy-progress'), cancel: $('cancel'),
};
mountStudyNav($('studies'), 'ivy');

// webgl: drawing problems; error: the core's line for the current state; hash: decoding notices;
// mesh: the dropped mesh (not part of the link); drop: refused files; budget: the page budget's
// line when it stopped the growth early (docs/budgets.md); look: a dropped glTF's base colour image
// the browser could not decode (its material drawn with its colour).
const notices = new Notices($('notice'), ['webgl', 'error', 'hash', 'mesh', 'look', 'drop', 'budget']);
// Errors beside the controls outside the panel (the panel's rows find their own).
const BASIC_FIELDS = {
  seed: 'seed-error', steps: 'steps-error', at: 'at-error', seed_points: 'at-error', tree: 'tree-error', tree_years: 'tree-error',
};
// The worker, Cancel, updates, history, exports and errors (web/shell/study_controller.js).
// Progress of the work in the worker (a dropped mesh's read and BVH, the tree, every growth
// step) shows beside Cancel: the worker is ended at once.
const controller = new StudyController({
  study: 'ivy', notices, ui, fields: BASIC_FIELDS, panel: () => panel, state: () => currentState(),
  onCancel: () => {
    const text = useMesh ? 'cancelled: the dropped mesh is dropped; back to the last finished ivy' : 'cancelled: back to the last finished ivy';
    useMesh = false;
    meshRequest = 0;
    showDropped('');
    return text;
  },
  // Cancel restarted the worker: init it again from the last ivy shown (a dropped mesh is gone
  // with the old worker; the last built-in scene or tree comes back). The ivy on screen stays.
  onRestart: () => {
    restarting = true;
    worker.request('init', { hash: lastBuiltIn ? `#${lastBuiltIn}` : OPENING_HASH }, { done: ['ready'] });
  },
  // Undo/Redo are back/forward over the committed states (web/shell/hash_history.js).
  onHistoryChange: () => updateUndoButtons(),
  // A dropped mesh's error is the mesh's notice, not the state's.
  onError: (msg, when) => {
    if (when === 'before' && msg.id === meshRequest) {
      notices.set('mesh', msg.message);
      if (meshBefore) ({ useMesh, meshName } = meshBefore);  // the next edit grows on what was there
      showDropped(useMesh ? meshName : '');
      showScene();
      ui.progress.textContent = '';
      controller.showWork(false);
      setHooks({ status: 'error', meshError: msg.message });
      return true;
    }
    return false;
  },
});
const { worker, history: history_ } = controller;
function updateUndoButtons() {
  ui.undo.disabled = !history_.canUndo();
  ui.redo.disabled = !history_.canRedo();
  setHooks({ canUndo: history_.canUndo(), canRedo: history_.canRedo() });
}
let restarting = false;  // the next 'ready' answers a restart (the panel exists already)
let lastBuiltIn = '';    // the hash of the last ivy grown on a built-in scene or tree
const progressSeen = [];

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let frame = null;     // the view's one Frame (web/gl/frame.js): its camera, sun and the layers
let renderer = null;  // the ivy's layer of it
let leafTexture = null;  // the worker's leaf texture ({width, height, pixels}) until a renderer has it
// Uploads the leaf texture kept for the renderer, then hands its pixels back to the worker (the
// next client's copy goes into them: web/worker/ivy_handler.js).
function installLeafTexture() {
  if (!renderer || !leafTexture) return;
  renderer.setLeafTexture(leafTexture);
  worker.recycle({ leafTexture: { pixels: leafTexture.pixels } });
  leafTexture = null;
}
let ivySerial = 0;
let installedSerial = 0;  // the ivy whose buffers are in place (a big one goes up in parts)
// Frames on demand over the renderer's progressive parts (web/gl/progressive_loop.js); the hooks
// describe a finished frame.
const loop = new ProgressiveLoop({
  renderer: () => (renderer ? frame : null),
  camera,
  onDrawn: (drawn) => {
    const counts = renderer.drawnCounts();
    setHooks({
      drawnSerial: installedSerial, drawnStep: scrubber.value, drawnTriangles: drawn.triangles, drawCalls: drawn.drawCalls,
      drawnStems: counts.stems, drawnLeaves: counts.leaves, drawnSuckers: counts.suckers,
      leafTexture: drawn.leavesTextured ? 'on' : 'off', supportTexture: drawn.supportTextured ? 'on' : 'off',
    });
  },
});
const requestFrame = () => loop.request();

const scrubber = new StepScrubber({ range: ui.step, text: ui.stepText, play: ui.play }, (k) => {
  renderer?.setStep(k);
  setHooks({ stepShown: k });
  requestFrame();
});

async function startRenderer() {
  try {
    await loop.start(async () => {
      // One study fitted to the view (fit), the ivy's sun, no ground (the support is the ground).
      frame = new Frame(ui.canvas, { camera, sun: DEFAULT_SUNS.ivy, ground: false, fit: true, request: () => loop.request(), what: 'the ivy' });
      await frame.init();
      renderer = await frame.addLayer(new IvyRenderer(frame));
      installLeafTexture();
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
let scenes = [];
let trees = [];            // the tree presets ivy can climb (scene 'tree')
let support = null;       // the worker's description of the current support
let seedPoints = [];      // [[x, y, z], ...] in scene units; [] = the scene's first named seed
let useMesh = false;      // grow on the dropped mesh, not a built-in scene
let meshName = '';
let frameNext = true;

const formatPoint = (p) => p.map((x) => String(Number(x.toPrecision(7)))).join(',');

function currentState() {
  const state = {
    preset: ui.preset.value, seed: numberOr(ui.seed), steps: numberOr(ui.steps),
    seed_points: seedPoints.map(formatPoint).join(';'), params: panel.values(),
  };
  if (!useMesh) state.scene = ui.scene.value;
  if (state.scene === 'tree') {
    state.tree = ui.tree.value;
    state.tree_years = numberOr(ui.treeYears);
  }
  return state;
}

function applyState(state) {
  ui.preset.value = state.preset;
  ui.seed.value = String(state.seed);
  ui.steps.value = String(state.steps);
  panel.setValues(state.params);
  if (state.scene) {
    ui.scene.value = state.scene;
    builtInScene = state.scene;
    useMesh = false;
    showDropped('');
  }
  if (state.tree) ui.tree.value = state.tree;
  if (state.tree_years !== undefined) ui.treeYears.value = String(state.tree_years);
  seedPoints = String(state.seed_points || '').split(';').filter(Boolean).map((p) => p.split(',').map(Number));
  showScene();
  showSeeds();
}

function showScene() {
  const scene = scenes.find((s) => s.name === ui.scene.value);
  const onTree = !useMesh && ui.scene.value === 'tree';
  for (const el of document.querySelectorAll('.tree-field')) el.hidden = !onTree;
  ui.sceneHelp.textContent = useMesh ? `Growing on the dropped mesh ${meshName}.`
    : onTree ? `The bark of Niwa's ${ui.tree.value} tree at ${ui.treeYears.value} years (metres), seeded at the trunk foot.`
      : scene ? scene.description : '';
}

// The Scene select shows the dropped file as its choice (the option goes when another scene is
// picked: the worker holds one support, so the file would have to be dropped again).
const DROPPED = '(dropped)';
let builtInScene = 'cubes4';  // the select's last built-in choice
function showDropped(name) {
  let option = [...ui.scene.options].find((o) => o.value === DROPPED);
  if (!name) {
    if (option) option.remove();
    if (ui.scene.value === DROPPED || !ui.scene.value) ui.scene.value = builtInScene;
    return;
  }
  if (ui.scene.value !== DROPPED && ui.scene.value) builtInScene = ui.scene.value;
  if (!option) {
    option = new Option('', DROPPED);
    ui.scene.prepend(option);
  }
  option.textContent = `${name} (dropped${support?.dropped && support.name === name ? `, ${support.triangles} tris` : ''})`;
  ui.scene.value = DROPPED;
}

function showSeeds() {
  const named = support?.seeds?.[0];
  ui.seeds.textContent = seedPoints.length
    ? `${seedPoints.length} seed point${seedPoints.length > 1 ? 's' : ''}: ${seedPoints.map((p) => `(${formatPoint(p)})`).join(' ')}`
    : named ? `The scene's seed '${named.name}' (${formatPoint(named.pos)}). Click the surface to place your own.`
      : 'Click the surface to place a seed point.';
  renderer?.setSeeds(seedPoints.length ? seedPoints : named ? [named.pos] : []);
  requestFrame();
}

// Sends the state to grow; commit: a new history entry once it has grown.
const sendUpdate = (commit) => controller.update(commit, { useMesh }, { done: ['ivy'] });
// An edit of a control (stage 'grow') or a panel row (its stage): one update after a quiet moment.
const scheduleUpdate = (stage = 'grow') => controller.schedule(() => sendUpdate(true), stage);

// A hash without the points and scene of a dropped mesh (they mean nothing elsewhere).
const linkWithoutMesh = (hash) => hash.split('&').filter((kv) => !/^(at|scene)=/.test(kv)).join('&');

// ---------------------------------------------------------------- worker replies
worker.on('ready', (msg) => {
  if (restarting) {  // after Cancel: the panel exists; regrow the last good state (or the hash's)
    restarting = false;
    support = null;
    notices.set('mesh', '');
    applyState(msg.decoded.state);
    if (!msg.decoded.state.scene) ui.scene.value = 'cubes4';
    sendUpdate(false);
    return;
  }
  presets = msg.presets;
  scenes = msg.scenes;
  trees = msg.trees;
  for (const p of presets) ui.preset.append(new Option(p.name, p.name));
  for (const s of scenes) ui.scene.append(new Option(`${s.name} (${s.triangles} tris)`, s.name));
  ui.scene.append(new Option('tree (a Niwa tree)', 'tree'));
  for (const t of trees) ui.tree.append(new Option(t.title ? `${t.name} (${t.title})` : t.name, t.name));
  panel = new ParamPanel(ui.params, msg.paramTable, (spec, stage) => scheduleUpdate(stage));
  applyState(msg.decoded.state);
  if (!msg.decoded.state.scene) ui.scene.value = 'cubes4';
  notices.set('hash', msg.decoded.notices);
  sendUpdate(false);
});

worker.on('decoded', (msg) => {
  applyState(msg.state);
  notices.set('hash', msg.notices);
  sendUpdate(false);
});

worker.on('progress', (msg) => {
  ui.progress.textContent = msg.text;
  const fraction = msg.stage === 'grow' && msg.total > 0 ? msg.done / msg.total : null;
  ui.progressBar.hidden = fraction === null;
  if (fraction !== null) ui.progressBar.value = fraction;
  controller.showWork(true);
  if (progressSeen.at(-1) !== msg.stage) progressSeen.push(msg.stage);
  setHooks({ progressStages: progressSeen.slice(-12).join(','), progressText: msg.text });
  bumpHook('progressMessages');
});

worker.on('support', (msg) => {
  support = msg.support;
  if (renderer) {
    renderer.clearIvy();
    renderer.setSupport(msg.buffers, support.bounds);  // uploaded at once
    frameNext = true;
  }
  worker.recycle({ support: msg.buffers });  // for the worker's next support to fill
  // A glTF is in metres (its spec): its leaves and tubes keep their size in metres whatever its size, while
  // the growth's lengths are read from its bounds (core/ivy/ivy_params.h IvyLookPxPerUnit).
  const leavesInMetres = support.dropped && support.look_px_per_unit === 1000 && support.look_px_per_unit !== support.px_per_unit;
  notices.set('mesh', support.dropped
    ? `Growing on the dropped mesh ${support.name} (${support.triangles} triangles${support.obstacles ? `, ${support.obstacles} obstacle-only` : ''}, ${Number(support.px_per_unit.toPrecision(3))} px per unit from its size unless Scale is set${leavesInMetres ? '; its leaves and tubes in metres, as glTF is: 1 px of their sizes = 1 mm' : ''}); a dropped mesh is not part of the link.`
    : '');
  setHooks({ supportPxPerUnit: support.px_per_unit, supportLookPxPerUnit: support.look_px_per_unit ?? '' });
  setHooks({ supportName: support.name, supportTriangles: support.triangles, supportDropped: support.dropped,
    supportLoadMs: msg.loadMs === null ? '' : Math.round(msg.loadMs) });
  if (support.dropped) showDropped(support.name);
  // A dropped glTF's own look: its base colour images (kept from the file) decoded and uploaded.
  if (renderer && support.dropped && meshImages.id === msg.id && support.materials?.length) {
    const look = support.materials.map((m) => m.image);
    setHooks({ supportLook: 'decoding' });
    renderer.setSupportMaterials(support.materials, meshImages.images, requestFrame).then((r) => {
      if (!r) return;
      notices.set('look', r.failed.length ? `${support.name}: ${r.failed.join('; ')}; those materials are drawn with their colour.` : '');
      setHooks({ supportLook: 'ready', supportTextures: r.textures, supportMaterials: look.length, supportTextureFailures: r.failed.join(' | ') });
    });
  } else {
    notices.set('look', '');
    setHooks({ supportLook: support.dropped ? 'ready' : '', supportTextures: 0, supportMaterials: support.materials?.length || 0, supportTextureFailures: '' });
  }
  showSeeds();
  if (msg.id === meshRequest) {  // a dropped mesh: grow on it once it is loaded
    ui.progress.textContent = '';
    // Its default seed goes into the state, so the link (with the mesh file) regrows this ivy.
    if (!seedPoints.length && support.seeds?.length) seedPoints = [support.seeds[0].pos];
    showSeeds();
    sendUpdate(true);
  }
});

// The support's paper pixels per unit: the row "scale", else the support's own (a dropped mesh's
// from its bounds: core/ivy/ivy_params.h IvyPxPerUnit), so the px rows are in scene units / k.
function pxPerUnit() {
  const k = Number(panel.values().scale);
  return k > 0 ? k : (support?.px_per_unit || 1);
}

worker.on('ivy', (msg) => {
  // The leaf texture comes once per worker, with its first ivy: kept even from a superseded one.
  if (msg.leafTexture) {
    leafTexture = msg.leafTexture;
    installLeafTexture();
  }
  if (!controller.isLatest(msg)) return;
  const s = msg.stats;
  notices.set('error', '');
  // The tree support's own stop (scene=tree grown within the page budget), then the ivy's.
  // And the statistics' overlap sweep left out when its exact estimate does not fit (ivy_bindings).
  notices.set('budget', [s.tree_truncated_by, s.truncated_by, s.overlap_skipped_by].filter(Boolean).join(' '));
  controller.showFieldError('');
  controller.showWork(false);
  ui.progress.textContent = '';
  ui.stats.textContent = `internodes ${s.internodes} · leaves ${s.leaves} · laterals ${s.laterals} · buds A ${s.buds.A} D ${s.buds.D} Z ${s.buds.Z} · grown in ${s.ms.toFixed(1)} ms`;
  const serial = ivySerial + 1;
  // The worker's buffers reused (web/worker/transfer.js): what this reply's copy went into.
  setHooks({ buffersReused: msg.buffers?.reused ?? '', buffersFresh: msg.buffers?.fresh ?? '' });
  if (renderer) {
    renderer.setIvy(msg.mesh).then((installed) => {
      // On the GPU (or dropped): the buffers go back for the worker's next ivy to fill.
      worker.recycle(msg.mesh);
      if (!installed) return;
      installedSerial = serial;
      if (frameNext && renderer.bounds()) {
        camera.reset(renderer.bounds());
        frameNext = false;
      }
      requestFrame();
    });
    renderer.setBuds(msg.mesh.buds);  // uploaded at once (the buffers go back after setIvy's)
  } else {
    worker.recycle(msg.mesh);
  }
  scrubber.reset(msg.steps);
  if (!support?.dropped) lastBuiltIn = msg.hash;
  // On a dropped mesh the page's link leaves out its seed points (at=): the mesh is not in the
  // link, which opens on the default scene with these settings, without an error.
  controller.grown(support?.dropped ? linkWithoutMesh(msg.hash) : msg.hash);
  ivySerial += 1;
  setHooks({
    status: 'ready', error: '', meshError: '', ivySerial, internodes: s.internodes, leaves: s.leaves, laterals: s.laterals,
    steps: msg.steps, stats: JSON.stringify(s), hash: msg.hash, truncatedBy: s.truncated_by || '',
    overlapSkippedBy: s.overlap_skipped_by || '',
  });
  requestFrame();
});

worker.on('picked', (msg) => {
  if (!msg.hit.hit) {
    ui.shareStatus.textContent = 'That click missed the support.';
    return;
  }
  // Half the sucker length off the face along its normal (the seed must be within d of a face;
  // d is in paper pixels, pxPerUnit() of them a scene unit), on the side the click came from: a
  // face wound inward (a scan's) would otherwise put the seed, and the ivy, inside the mesh.
  const d = Number(panel.values().d) / pxPerUnit();
  const lift = Number.isFinite(d) && d > 0 ? d / 2 : 0;
  const n = msg.hit.normal;
  const facing = pickRay && n[0] * pickRay.direction[0] + n[1] * pickRay.direction[1] + n[2] * pickRay.direction[2] > 0 ? -1 : 1;
  seedPoints.push(msg.hit.point.map((x, i) => x + facing * lift * n[i]));
  showSeeds();
  bumpHook('seedClicks');
  scheduleUpdate();
});

let pickRay = null;  // the ray of the last click on the view
let meshRequest = 0;
let meshImages = { id: 0, images: new Map() };  // the base colour images of the mesh request `id`
let meshBefore = null;  // what the page grew on before the last drop: a refused file goes back to it

// ---------------------------------------------------------------- dropped meshes
async function loadMeshFile(file) {
  // A new file's answer replaces the last one's: its error leaves the notice and the field now.
  notices.set('drop', '');
  notices.set('error', '');
  notices.set('mesh', '');
  controller.showFieldError('');
  ui.progress.textContent = `reading ${file.name}`;
  try {
    const bytes = await meshFileBytes(file);  // Draco decoded here (web/mesh/mesh_file.js)
    meshBefore = { useMesh, meshName };
    meshName = file.name;
    useMesh = true;
    seedPoints = [];
    showDropped(file.name);
    showScene();
    const images = baseColorImages(bytes, file.name);  // copied: the bytes go to the worker
    const request = worker.request('mesh', { name: file.name, bytes: bytes.buffer }, { group: 'mesh', done: ['support'] });
    meshRequest = request.id;
    meshImages = { id: request.id, images };
    bumpHook('meshDrops');
  } catch (e) {
    ui.progress.textContent = '';
    notices.set('drop', `${file.name}: ${e.message}`);
    setHooks({ status: 'error', meshError: e.message });
  }
}

new FileDrop({
  target: ui.stage, input: ui.meshFile, accept: ['.glb', '.gltf', '.obj'],
  onFiles: (files) => loadMeshFile(files[0]),
  onRefuse: (line) => notices.set('drop', line),
});

// ---------------------------------------------------------------- controls
// A click (not a drag) on the view adds a seed point where the ray meets the support.
let down = null;
ui.canvas.addEventListener('pointerdown', (e) => { down = { x: e.clientX, y: e.clientY, button: e.button, shift: e.shiftKey }; });
ui.canvas.addEventListener('pointerup', (e) => {
  if (!down || !renderer || !ui.clickSeeds.checked) return;
  const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
  const plain = down.button === 0 && !down.shift;
  down = null;
  if (moved > 4 || !plain) return;
  const rect = ui.canvas.getBoundingClientRect();
  const ray = renderer.rayAt(camera, e.clientX - rect.left, e.clientY - rect.top);
  pickRay = ray;
  worker.request('pick', ray, { done: ['picked'] });
});

ui.scene.addEventListener('change', () => {
  if (ui.scene.value === DROPPED) return;  // the dropped file is shown already
  useMesh = false;
  seedPoints = [];
  builtInScene = ui.scene.value;
  showDropped('');
  // A tree is in metres: its ivy preset is metric (the CLI's --tree-preset default).
  if (ui.scene.value === 'tree' && ui.preset.value !== 'metric') {
    ui.preset.value = 'metric';
    const metric = presets.find((p) => p.name === 'metric');
    if (metric) panel.setValues(metric.params);
  }
  showScene();
  frameNext = true;
  scheduleUpdate();
});
for (const input of [ui.tree, ui.treeYears]) {
  input.addEventListener(input === ui.tree ? 'change' : 'input', () => {
    seedPoints = [];
    showScene();
    frameNext = true;
    scheduleUpdate();
  });
}
ui.preset.addEventListener('change', () => {
  const preset = presets.find((p) => p.name === ui.preset.value);
  if (preset) panel.setValues(preset.params);
  scheduleUpdate();
});
ui.seed.addEventListener('input', () => scheduleUpdate());
ui.steps.addEventListener('input', () => scheduleUpdate());
ui.reset.addEventListener('click', () => ui.preset.dispatchEvent(new Event('change')));
ui.clearSeeds.addEventListener('click', () => {
  seedPoints = [];
  showSeeds();
  scheduleUpdate();
});
for (const [input, part] of [[ui.showLeaves, 'leaves'], [ui.showLeafTexture, 'leafTexture'], [ui.showSupportTexture, 'supportTexture'], [ui.showSuckers, 'suckers'], [ui.showSupport, 'support'], [ui.showSeeds, 'seeds'], [ui.showBuds, 'buds']]) {
  input.addEventListener('change', () => {
    renderer?.setVisible({ [part]: input.checked });
    requestFrame();
  });
}
ui.resetView.addEventListener('click', () => {
  if (renderer?.bounds()) camera.reset(renderer.bounds());
  requestFrame();
});
// On a dropped mesh the link says so plainly: the mesh is not in it (the page's hash holds no
// seed points or scene then, so the link opens on the default scene without an error).
ui.copyLink.addEventListener('click', async () => {
  await copyLink(ui.shareStatus);
  if (useMesh) {
    ui.shareStatus.textContent += ` The dropped mesh ${meshName} is not in the link: it opens on ${builtInScene} with these settings; drop the file there to grow on it again.`;
  }
});
ui.undo.addEventListener('click', () => history_.undo());
ui.redo.addEventListener('click', () => history_.redo());
const editable = (t) => t instanceof HTMLElement && (t.isContentEditable || ['INPUT', 'TEXTAREA', 'SELECT'].includes(t.tagName));
document.addEventListener('keydown', (e) => {
  if (editable(e.target)) return;  // the fields keep their own undo
  const key = e.key.toLowerCase();
  if ((e.ctrlKey || e.metaKey) && (key === 'z' || key === 'y')) {
    e.preventDefault();
    (key === 'y' || e.shiftKey ? ui.redo : ui.undo).click();
  }
});
// The embed: <niwa-ivy> (public/niwa-ivy.js) or an iframe of public/embed.html?study=ivy, with this hash.
ui.embed.addEventListener('click', () => {
  showEmbedDialog({ tag: 'niwa-ivy', title: 'Niwa ivy', heading: 'Embed this ivy', script: 'niwa-ivy.js', frame: 'embed.html?study=ivy' });
});
const TYPES = { glb: 'model/gltf-binary', json: 'application/json', lsys: 'text/plain' };
const exportAs = (format) => controller.exportAs(format, `ivy.${format}`, TYPES[format], { withSupport: ui.glbSupport.checked });
ui.downloadGlb.addEventListener('click', () => exportAs('glb'));
ui.downloadJson.addEventListener('click', () => exportAs('json'));
ui.downloadLsys.addEventListener('click', () => exportAs('lsys'));

// ---------------------------------------------------------------- start
setHooks({ status: 'loading' });
updateUndoButtons();
await startRenderer();
// Opened with no hash: the artist preset (issue 31 item 5: the page's default covers a support as
// artists expect; the CLI's default stays the paper's rules).
const OPENING_HASH = '#preset=artist';
worker.request('init', { hash: location.hash || OPENING_HASH }, { done: ['ready'] });
