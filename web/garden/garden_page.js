// The garden's page (public/garden.html, main thread; issue 33 item 6, docs/garden-model.md "The
// page"): opens with the default garden (DefaultGardenState: a 40 m terrain ground, a wall, two
// rocks, a stone lantern, a keyaki placed by hand and the rules' keyaki, sakura and maple) grown
// OPENING_YEARS years, builds the panel from the garden table, keeps the state in location.hash
// through the garden's hash codec (the text `niwa garden grow --url` reads), and draws the ground,
// the objects and every planted tree (each distinct tree's mesh once, instanced at its
// placements: garden_renderer.js) under the frame's orbit camera and sun with its shadow map.
// A click on the ground (not a drag) places the tree preset or object (wall, rock, lantern) picked
// (its foot where the click's ray meets the ground's heights), a click within a metre of a
// hand-placed tree's foot removes it, and the lists of hand-placed trees and of objects have Move
// (the next click on the ground moves it there) and Remove buttons: every one edits the state's
// plants or objects (the ivy's seeds by index follow) and regrows in the worker (web/worker/garden_handler.js) with progress and Cancel. Copy link, Embed
// (<niwa-garden>, public/niwa-garden.js, or the iframe public/embed.html?study=garden, of the
// page's hash), the .glb download (the worker's run's Export("glb"): the bytes of `niwa garden
// grow --url HASH --out g.glb`), the plan .svg, the stats line (trees by species, the ivy, the
// moss), and the ground's overlay (the moss's light, slope, altitude bands) with its legend.
// Files: a grey PNG opened (Ground: Heightmap…, or dropped on the view) is the ground, and a PNG
// opened as the planting rules' density mask (with a Clear); their bytes go to the worker once,
// decoded in the core (16-bit samples kept: not the browser's canvas), kept there by name, and the
// garden regrows; a bad file is the core's line beside its control. The rules' species mix is a
// list of rows (species, weight, Remove; Add species) checked by the core (a bad weight: its line
// beside the row). A link cannot carry the files: the Share section says so while one is in use
// (the link reads back flat and without the mask, with a notice, as `niwa garden grow --url` does).
// The year scrubber and Play replay the garden's years WITHOUT regrowing: every grow records each
// year's picture as the clock runs (core GardenRun's record_years), a picked year's trees are meshed
// from that record in the worker ('year' -> 'gardenYear') and swapped in with the moss's light of
// that year; the ivy (grown on the same clock, ivy_steps steps a year) is shown to the part of it
// born by that year, which is the ivy of that year. The link
// does not change when scrubbing (a view, like the camera); the downloads are the last year's.
// Blow / Still (garden_wind.js): the wind over the last year's trees, a simulator per planted tree
// in the worker, its poses skinned by the renderer (in hybrid mode the far copies' cards and lines
// too); a regrow or a year picked stops it. The View's Wind rows (the tree table's "wind" group but
// gust_on, the ready message's windTable: a second ParamPanel) are the state's wind: an edit is
// set on the worker's garden without regrowing ('windRows'), written into the link (wind.KEY=...),
// a bad value the core's line beside its row; a Blow under way starts again in the new wind.
// Trees: full | hybrid (garden_hybrid.js): far copies as the grove's cards and lines.
// Does not (yet): dragging things (a Move, then a click), regrowing a year the record left out
// (over its memory share: the scrubber says so), or several workers growing at once.
import '../shell/study_skeleton.js';  // first: the page's parts exist before this module's body runs
import { Frame } from '../gl/frame.js';
import { FileDrop, extensionOf } from '../shell/file_drop.js';
import { sendMeshFile } from '../mesh/mesh_file.js';
import { OrbitCamera } from '../gl/orbit_camera.js';
import { ProgressiveLoop } from '../gl/progressive_loop.js';
import { DEFAULT_SUNS } from '../gl/sun.js';
import { ParamPanel } from '../shell/param_panel.js';
import { StudyController, numberOr } from '../shell/study_controller.js';
import { Notices, copyLink, mountStudyNav, showEmbedDialog } from '../shell/study_page.js';
import { setHooks } from '../shell/test_hooks.js';
import { GardenRenderer } from './garden_renderer.js';
import { GardenWind } from './garden_wind.js';
import { GardenHybrid } from './garden_hybrid.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'), stats: $('stats'), progress: $('progress'), cancel: $('cancel'), params: $('params'),
  species: $('species'), plants: $('plants'), objects: $('objects'), meshFile: $('mesh-file'), meshError: $('mesh-error'), groundKind: $('ground-kind'), groundError: $('ground-error'), copyLink: $('copy-link'), shareStatus: $('share-status'),
  resetView: $('reset-view'), clickHelp: $('click-help'), overlay: $('overlay'), overlayHelp: $('overlay-help'),
  year: $('year'), yearText: $('year-text'), play: $('play'),
  heightmapFile: $('heightmap-file'), maskFile: $('mask-file'), maskName: $('mask-name'), maskClear: $('mask-clear'), maskError: $('mask-error'),
  mix: $('mix'), mixAdd: $('mix-add'), mixError: $('mix-error'), linkFiles: $('link-files'), rulesFiles: $('rules-files'),
};
mountStudyNav($('studies'), 'garden');

const notices = new Notices($('notice'), ['webgl', 'error', 'hash']);
// The opening garden's years: a result in a few seconds in the page with trees that read as trees
// (8 years: ~64 k internodes; the table's default, 10 years, gives ~130 k: a heavy first frame on a
// CPU rasteriser).
const OPENING_YEARS = 8;
const OPENING_HASH = `#years=${OPENING_YEARS}`;
const HAND_REACH = 1.0;  // metres: a click this near a hand-placed tree's foot removes it

// The error lines of the controls outside the panel, by the core's field: the heightmap's, the
// mask's, the mix's, and one per mix row ('mix.<species>', filled as the rows are drawn).
const errorFields = { 'ground.file': 'ground-error', mask: 'mask-error', mix: 'mix-error' };
const controller = new StudyController({
  study: 'garden', notices, ui, fields: errorFields, panel: () => panel, state: () => currentState(),
  onCancel: () => 'cancelled: back to the last finished garden',
  onRestart: () => {
    restarting = true;
    worker.request('init', { hash: '' }, { done: ['ready'] });
  },
  onError: (msg, when) => {
    if (restoring.delete(msg.id)) return true;  // a file sent again after Cancel and refused
    if (msg.control === 'wind') {  // Blow refused: its line beside the button
      gardenWind.failed(msg);
      return true;
    }
    if (msg.control === 'windRows') {  // a wind row refused: its line beside the row, the row marked
      controller.showFieldError(msg);
      windPanel?.markError(String(msg.field || '').replace(/^wind\./, ''));
      setHooks({ windRowsError: msg.message });
      return true;
    }
    if (msg.control === 'trees') {  // hybrid trees refused: its line beside the Trees select
      hybrid?.failed(msg);
      return true;
    }
    // A dropped file's read failed: its line beside the file control; the garden shown stays.
    if (when === 'before' && meshRequest && msg.id === meshRequest) {
      meshRequest = 0;
      showMeshError(msg.message);
      ui.progress.textContent = '';
      return true;
    }
    // An opened PNG the core refused: its line beside its control; the garden shown stays.
    if (when === 'before' && imageRequest && msg.id === imageRequest.id) {
      const { role } = imageRequest;
      imageRequest = null;
      showImageError(role, msg.message);
      ui.progress.textContent = '';
      return true;
    }
    if (when === 'after') {
      showPlantError(/^(plants|objects)/.test(msg.field || '') ? msg.message : '');
      ui.groundError.textContent = /^ground/.test(msg.field || '') ? msg.message : '';
      ui.groundError.hidden = !/^ground/.test(msg.field || '');
    }
    return false;
  },
});
const { worker } = controller;
let restarting = false;
let lastGoodState = null;  // the last finished garden's state (with its files' names)
let lastGoodHash = null;
let panel = null;
let windPanel = null;    // the View's Wind rows (the ready message's windTable)
let windDefaults = {};   // the garden's wind defaults by key (the windTable's)
let windTimer = 0;
let state = null;       // the resolved garden state (GardenStateJson) of the last grow or decode
let bounds = null;
let gardenSerial = 0;
let frameNext = true;
let lookSerial = 0;  // window.__niwaGardenLook's calls (the frame drawn after one: data-drawn-look)

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let frame = null;
let renderer = null;
let hybrid = null;  // the Trees: full | hybrid control (garden_hybrid.js)
const loop = new ProgressiveLoop({
  renderer: () => (renderer ? frame : null),
  camera,
  onDrawn: (drawn) => {
    setHooks({ drawnSerial: gardenSerial, drawnTrees: drawn.trees ?? 0, drawnTriangles: drawn.triangles, drawnLines: drawn.lines ?? 0, drawCalls: drawn.drawCalls, drawnGround: drawn.groundTriangles ?? 0, groundStrides: drawn.groundStrides ?? '', shadow: drawn.shadow ?? '', drawnOverlay: renderer?.overlay ?? 'none', drawnLook: lookSerial });
    yearDrawn();
    gardenWind.drawn();
    hybrid?.drawn();
  },
});
const requestFrame = () => loop.request();

async function startRenderer() {
  try {
    await loop.start(async () => {
      frame = new Frame(ui.canvas, { camera, sun: DEFAULT_SUNS.tree, ground: false, fit: false, request: () => loop.request(), what: 'the garden' });
      await frame.init();
      renderer = await frame.addLayer(new GardenRenderer(frame));
      hybrid = new GardenHybrid({ worker, frame, full: () => renderer, camera, select: $('trees-mode'), info: $('trees-help'), request: () => loop.request() });
      await hybrid.init();
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

// The whole garden in view, seen from the south-east above: the ground's square (its relief, not the
// crowns) filling the view.
function frameGarden() {
  if (!bounds) return;
  camera.yaw = 0.6;
  camera.pitch = 0.75;
  const half = bounds.size / 2;
  camera.frame({ min: [-half, 0, -half], max: [half, bounds.relief, half] }, 0.62);
  requestFrame();
}

// ---------------------------------------------------------------- state
function currentState() {
  const s = state ? { ...state } : {};
  if (panel) s.params = panel.values();
  return s;
}

const sendUpdate = (commit) => controller.update(commit, {}, { done: ['garden'] });
const scheduleUpdate = (stage = 'grow') => controller.schedule(() => sendUpdate(true), stage);

function applyState(next) {
  state = next;
  panel.setValues(next.params || {});
  windPanel?.setValues({ ...windDefaults, ...(next.wind || {}) });
  showPlants();
  showGround();
  showMix();
  showMask();
  showLinkFiles();
}

// The Ground select: terrain, flat, a dropped mesh (mesh:<name>) or an opened heightmap
// (heightmap:<name>); "Heightmap…" opens the file picker. The terrain's own state is kept while
// another ground is shown, so going back to terrain regrows the same hill.
let lastTerrain = null;
const groundValue = (g) => (g.kind === 'mesh' || g.kind === 'heightmap' ? `${g.kind}:${g.file}` : g.kind);
function addGroundOption(value, text) {
  if ([...ui.groundKind.options].some((o) => o.value === value)) return;
  // Before "Heightmap…", which stays last.
  ui.groundKind.insertBefore(new Option(text, value), ui.groundKind.querySelector('option[value="open-heightmap"]'));
}
function showGround() {
  const g = state?.ground || { kind: 'terrain' };
  if (g.kind === 'terrain') lastTerrain = g;
  const value = groundValue(g);
  addGroundOption(value, g.kind === 'mesh' ? `mesh ${g.file}` : g.kind === 'heightmap' ? `heightmap ${g.file}` : g.kind);
  ui.groundKind.value = value;
  setHooks({ groundKind: value });
}
function setGround(v) {
  const ground = v.startsWith('mesh:') ? { kind: 'mesh', file: v.slice('mesh:'.length) }
    : v.startsWith('heightmap:') ? { kind: 'heightmap', file: v.slice('heightmap:'.length) }
      : v === 'terrain' ? (lastTerrain || { kind: 'terrain' }) : { kind: v };
  state = { ...currentState(), ground };
  frameNext = true;
  showLinkFiles();
  sendUpdate(true);
}
ui.groundKind.addEventListener('change', () => {
  const v = ui.groundKind.value;
  if (v === 'open-heightmap') {
    ui.groundKind.value = groundValue(state?.ground || { kind: 'terrain' });
    ui.heightmapFile.click();
    return;
  }
  setGround(v);
});

function showPlantError(line) {
  const el = $('plants-error');
  el.textContent = line;
  el.hidden = !line;
}

// The hand-placed trees and the objects, each with Move and Remove buttons.
const OBJECT_KINDS = ['wall', 'rock', 'lantern'];
let moving = null;  // {list: 'plants' | 'objects', index}: the next click on the ground moves it there

function showPlants() {
  ui.plants.replaceChildren();
  const item = (list, k, text) => {
    const li = document.createElement('li');
    li.append(`${text} `);
    for (const [label, act] of [['Move', () => startMove(list, k)], ['Remove', () => removeItem(list, k)]]) {
      const button = document.createElement('button');
      button.type = 'button';
      button.textContent = label;
      button.dataset[list === 'plants' ? 'plant' : 'object'] = String(k);
      button.dataset.action = label.toLowerCase();
      if (moving && moving.list === list && moving.index === k && label === 'Move') button.setAttribute('aria-pressed', 'true');
      button.addEventListener('click', act);
      li.append(button);
    }
    return li;
  };
  (state?.plants || []).forEach((p, k) => {
    const [x, z] = p.pos || [0, 0];
    ui.plants.append(item('plants', k, `${p.species} (seed ${p.seed}, age ${p.age}) at ${x.toFixed(1)}, ${z.toFixed(1)} m`));
  });
  ui.objects.replaceChildren();
  (state?.objects || []).forEach((o, k) => {
    const [x, z] = o.pos || [0, 0];
    ui.objects.append(item('objects', k, `${o.kind === 'mesh' ? o.file : o.kind} at ${x.toFixed(1)}, ${z.toFixed(1)} m`));
  });
  setHooks({ handPlants: (state?.plants || []).length, objects: (state?.objects || []).length, moving: moving ? `${moving.list}[${moving.index}]` : '' });
}

// The state with `list` replaced; the ivy's seeds named by index ("objects[2]", "plants[0]") follow
// their thing when one before it is removed, and go with it when it is.
function editList(list, items, removed = -1) {
  const next = { ...currentState(), [list]: items };
  if (removed >= 0 && next.ivy?.on) {
    const re = new RegExp(`^${list}\\[(\\d+)\\]$`);
    const on = [];
    for (const seed of next.ivy.on) {
      const m = re.exec(seed);
      if (!m) { on.push(seed); continue; }
      const i = Number(m[1]);
      if (i !== removed) on.push(`${list}[${i > removed ? i - 1 : i}]`);
    }
    next.ivy = { ...next.ivy, on };
  }
  state = next;
  showPlants();
  sendUpdate(true);
}

function removeItem(list, k) {
  moving = null;
  editList(list, (state[list] || []).filter((_, i) => i !== k), k);
}

function startMove(list, k) {
  moving = moving && moving.list === list && moving.index === k ? null : { list, index: k };
  ui.clickHelp.textContent = moving ? `Click the ground where the ${list === 'plants' ? state.plants[k].species : state.objects[k].kind} goes.` : '';
  showPlants();
}

// A click on the ground at (x, z): moves the thing picked by a Move button there; else removes the
// hand-placed tree whose foot is within HAND_REACH; else places the picked tree preset (seed 1,
// age 0) or object (turned 0, scale 1) there.
function clickGround(x, z) {
  const round = (v) => Math.round(v * 100) / 100;
  const plants = state?.plants || [];
  if (moving) {
    const { list, index } = moving;
    moving = null;
    ui.clickHelp.textContent = '';
    setHooks({ lastClick: `move:${list}[${index}]:${round(x)},${round(z)}` });
    editList(list, (state[list] || []).map((it, i) => (i === index ? { ...it, pos: [round(x), round(z)] } : it)));
    return;
  }
  const near = plants.findIndex((p) => Math.hypot(p.pos[0] - x, p.pos[1] - z) <= HAND_REACH);
  if (near >= 0) {
    setHooks({ lastClick: `remove:${near}` });
    removeItem('plants', near);
    return;
  }
  const picked = ui.species.value;
  if (picked.startsWith('mesh:')) {
    const file = picked.slice('mesh:'.length);
    setHooks({ lastClick: `mesh:${file}:${round(x)},${round(z)}` });
    editList('objects', [...(state?.objects || []), { kind: 'mesh', file, pos: [round(x), round(z)], rot: 0, scale: 1 }]);
    return;
  }
  if (picked.startsWith('object:')) {
    const kind = picked.slice('object:'.length);
    setHooks({ lastClick: `object:${kind}:${round(x)},${round(z)}` });
    editList('objects', [...(state?.objects || []), { kind, pos: [round(x), round(z)], rot: 0, scale: 1 }]);
    return;
  }
  setHooks({ lastClick: `plant:${round(x)},${round(z)}` });
  editList('plants', [...plants, { species: picked, seed: 1, age: 0, pos: [round(x), round(z)], rot: 0 }]);
}

// ---------------------------------------------------------------- dropped meshes
// A mesh file dropped on the view or picked: its bytes (Draco decoded here) go to the worker once
// (transferred), which keeps it by name; it then joins the Place list as `mesh:<name>`.
let meshRequest = 0;  // the id of the 'mesh' request in flight
const meshGroup = document.createElement('optgroup');
meshGroup.label = 'Meshes (dropped)';

function showMeshError(line) {
  ui.meshError.textContent = line;
  ui.meshError.hidden = !line;
  setHooks({ meshError: line });
}

// The files the worker holds, by kind and name ({kind: 'mesh' | 'image', role, file}: the File
// handles, not their bytes): after Cancel restarts the worker they are sent to the new one before
// the last garden is decoded again, so a garden on a heightmap, a mask or mesh objects regrows
// without asking for its files. `restoring`: the ids of those requests (their replies change
// nothing on the page; a refusal leaves the decode to name the missing file, as before).
const openedFiles = new Map();
const restoring = new Set();
let meshFile = null;  // the File of the 'mesh' request in flight
async function restoreFiles() {
  const sends = [...openedFiles.values()].map(async (f, k) => {
    const group = `restore-${k}`;
    if (f.kind === 'mesh') {
      restoring.add((await sendMeshFile(worker, f.file, { group })).id);
      return;
    }
    const buffer = await f.file.arrayBuffer();
    restoring.add(worker.request('image', { role: f.role, name: f.file.name, bytes: buffer },
      { group, done: ['imageLoaded'], transfer: [buffer] }).id);
  });
  await Promise.allSettled(sends);
  setHooks({ restoredFiles: openedFiles.size });
}

async function loadMeshFile(file) {
  showMeshError('');
  ui.progress.textContent = `reading ${file.name}`;
  try {
    meshFile = file;
    const sent = await sendMeshFile(worker, file);
    meshRequest = sent.id;
  } catch (e) {
    ui.progress.textContent = '';
    showMeshError(`mesh: ${String(file.name).slice(0, 60)}: ${e.message}`);
  }
}

worker.on('meshLoaded', (msg) => {
  if (restoring.delete(msg.id)) return;
  if (!meshRequest || msg.id !== meshRequest) return;
  meshRequest = 0;
  if (meshFile) openedFiles.set(`mesh:${msg.mesh.name}`, { kind: 'mesh', file: meshFile });
  ui.progress.textContent = '';
  const value = `mesh:${msg.mesh.name}`;
  if (![...meshGroup.children].some((o) => o.value === value)) meshGroup.append(new Option(`${msg.mesh.name} (${msg.mesh.triangles} triangles)`, value));
  if (!meshGroup.parentElement) ui.species.append(meshGroup);
  if (![...ui.groundKind.options].some((o) => o.value === value)) ui.groundKind.append(new Option(`mesh ${msg.mesh.name}`, value));
  ui.species.value = value;
  ui.clickHelp.textContent = `Click the ground to stand ${msg.mesh.name} there.`;
  setHooks({ meshName: msg.mesh.name, meshTriangles: msg.mesh.triangles });
});

new FileDrop({
  target: ui.meshFile, input: ui.meshFile, accept: ['.glb', '.gltf', '.obj'],
  onFiles: (files) => loadMeshFile(files[0]),
  onRefuse: (line) => showMeshError(`mesh: ${line}`),
});
// Dropped on the view: a mesh (to place, or as the ground) or a grey PNG (the ground's heightmap).
new FileDrop({
  target: $('stage'), accept: ['.glb', '.gltf', '.obj', '.png'], what: 'mesh or PNG heightmap',
  onFiles: (files) => (extensionOf(files[0].name) === '.png' ? loadImageFile('heightmap', files[0]) : loadMeshFile(files[0])),
  onRefuse: (line) => showMeshError(`mesh: ${line}`),
});

// ---------------------------------------------------------------- opened images and the mix
// A PNG opened for the ground (role 'heightmap') or the rules' density mask (role 'mask'): its
// bytes go to the worker once (transferred), where the core decodes it (16-bit samples kept) and
// keeps it by name; the state then names it and the garden regrows. A refusal (not a PNG, a colour
// heightmap, a side over the cap) is the core's line beside the control.
let imageRequest = null;  // {id, role} of the 'image' request in flight
const imageError = (role) => (role === 'mask' ? ui.maskError : ui.groundError);
function showImageError(role, line) {
  const el = imageError(role);
  el.textContent = line;
  el.hidden = !line;
  setHooks({ [role === 'mask' ? 'maskError' : 'heightmapError']: line });
}

async function loadImageFile(role, file) {
  showImageError(role, '');
  ui.progress.textContent = `reading ${file.name}`;
  const buffer = await file.arrayBuffer();
  const request = worker.request('image', { role, name: file.name, bytes: buffer }, { group: 'image', done: ['imageLoaded'], transfer: [buffer] });
  imageRequest = { id: request.id, role, file };
}

worker.on('imageLoaded', (msg) => {
  if (restoring.delete(msg.id)) return;
  if (!imageRequest || msg.id !== imageRequest.id) return;
  openedFiles.set(`image:${msg.image.role}:${msg.image.name}`, { kind: 'image', role: msg.image.role, file: imageRequest.file });
  imageRequest = null;
  ui.progress.textContent = '';
  const im = msg.image;
  const about = `${im.name} (${im.width} x ${im.height}, ${im.bit_depth}-bit)`;
  setHooks({ [im.role === 'mask' ? 'maskLoaded' : 'heightmapLoaded']: `${im.name}:${im.width}x${im.height}:${im.bit_depth}` });
  if (im.role === 'mask') {
    maskAbout = about;
    state = { ...currentState(), mask: im.name };
    showMask();
    showLinkFiles();
    sendUpdate(true);
  } else {
    addGroundOption(`heightmap:${im.name}`, `heightmap ${about}`);
    setGround(`heightmap:${im.name}`);
    showGround();
  }
});

const pngDrop = (role, input) => new FileDrop({
  target: input, input, accept: ['.png'], what: 'PNG',
  onFiles: (files) => loadImageFile(role, files[0]),
  onRefuse: (line) => showImageError(role, `${role === 'mask' ? 'mask' : 'ground.file'}: ${line}`),
});
pngDrop('heightmap', ui.heightmapFile);
pngDrop('mask', ui.maskFile);

// The mask in use (its name, and its size when opened in this page) and Clear.
let maskAbout = '';
function showMask() {
  const name = state?.mask || '';
  if (!name) maskAbout = '';
  ui.maskName.textContent = name ? `Mask: ${maskAbout.startsWith(`${name} (`) ? maskAbout : name}` : 'No mask: every dart has its chance.';
  ui.maskClear.hidden = !name;
  setHooks({ mask: name });
}
ui.maskClear.addEventListener('click', () => {
  const next = { ...currentState() };
  delete next.mask;
  state = next;
  showMask();
  showLinkFiles();
  showImageError('mask', '');
  sendUpdate(true);
});

// The species mix: a row per species (its preset, its weight, Remove) and Add species; an edit
// regrows after a quiet moment (a burst of edits is one grow). The core checks the weights: a bad
// one is its line ('mix.<species>: ...') beside the row.
let speciesNames = [];
function mixRows() {
  return [...ui.mix.querySelectorAll('li')].map((li) => {
    const weight = li.querySelector('input');
    return [li.querySelector('select').value, numberOr(weight)];
  });
}
function mixOf(rows) {
  const mix = {};
  for (const [species, weight] of rows) mix[species] = weight;
  return mix;
}
// An edit of the rows: the state's mix from them, regrown after a quiet moment; `redraw` when a
// row's species changed or a row went (the other rows' species lists change), not while a weight
// is typed (its input keeps the focus).
function mixEdited(redraw) {
  state = { ...currentState(), mix: mixOf(mixRows()) };
  if (redraw) showMix(true);
  scheduleUpdate();
}
// Redraws the rows from state.mix (unless they show it already: a grow's reply does not take the
// focus away from a weight being typed); `force` after an edit of the rows themselves.
function showMix(force = false) {
  const entries = Object.entries(state?.mix || {});
  if (!force && JSON.stringify(mixRows()) === JSON.stringify(entries)) return;
  for (const key of Object.keys(errorFields)) if (key.startsWith('mix.')) delete errorFields[key];
  const used = new Set(entries.map(([name]) => name));
  const rows = entries.map(([species, weight], k) => {
    const li = document.createElement('li');
    const pick = document.createElement('select');
    pick.setAttribute('aria-label', `Species of mix row ${k + 1}`);
    pick.dataset.mix = String(k);
    for (const name of [species, ...speciesNames.filter((n) => n !== species && !used.has(n))]) pick.append(new Option(name, name));
    pick.value = species;
    pick.addEventListener('change', () => mixEdited(true));
    const w = document.createElement('input');
    w.type = 'number';
    w.min = '0';
    w.max = '1000';
    w.step = 'any';
    w.inputMode = 'decimal';
    w.value = String(weight);
    w.setAttribute('aria-label', `Weight of ${species}`);
    w.dataset.mixWeight = String(k);
    w.addEventListener('input', () => mixEdited(false));
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.textContent = 'Remove';
    remove.dataset.mixRemove = String(k);
    remove.addEventListener('click', () => {
      li.remove();
      mixEdited(true);
    });
    const line = document.createElement('p');
    line.className = 'field-error';
    line.id = `mix-error-${k}`;
    line.setAttribute('role', 'alert');
    line.hidden = true;
    errorFields[`mix.${species}`] = line.id;
    li.append(pick, ' weight ', w, ' ', remove, line);
    return li;
  });
  ui.mix.replaceChildren(...rows);
  ui.mixAdd.disabled = speciesNames.every((n) => used.has(n));
  setHooks({ mix: entries.map(([n, w]) => `${n}:${w}`).join(',') });
}
ui.mixAdd.addEventListener('click', () => {
  const rows = mixRows();
  const free = speciesNames.find((n) => !rows.some(([name]) => name === n));
  if (!free) return;
  state = { ...currentState(), mix: mixOf([...rows, [free, 1]]) };
  showMix(true);
  scheduleUpdate();
});

// The files a link cannot carry (the heightmap or mesh ground, the mask, mesh objects): named
// beside Copy link while in use. The link reads back flat, without the mask or mesh objects, with a
// notice (the core's ApplyGardenHash: the page and `niwa garden grow --url` the same).
function showLinkFiles() {
  const files = [];
  const g = state?.ground;
  if (g && (g.kind === 'heightmap' || g.kind === 'mesh')) files.push(`the ${g.kind} ground ${g.file}`);
  if (state?.mask) files.push(`the mask ${state.mask}`);
  const meshes = (state?.objects || []).filter((o) => o.kind === 'mesh').map((o) => o.file);
  if (meshes.length) files.push(`the mesh object${meshes.length > 1 ? 's' : ''} ${[...new Set(meshes)].join(', ')}`);
  const text = files.length ? `A link cannot carry files: ${files.join(', ')} ${files.length > 1 ? 'are' : 'is'} not in it (it opens ${g && g.kind !== 'terrain' && g.kind !== 'flat' ? 'on a flat ground' : 'this garden'}${state?.mask ? ' without the mask' : ''}${meshes.length ? ' without the mesh objects' : ''}, with a notice); open the files there again.` : '';
  ui.linkFiles.textContent = text;
  ui.linkFiles.hidden = !text;
  setHooks({ linkFiles: text });
}

// The View's Wind rows: the tree table's wind rows a garden carries (ParamPanel from the worker's
// windTable: key, symbol, unit, range and help from the one table). An edit is checked and set in
// the worker after a quiet moment ('windRows': nothing regrows), its link written; a refusal is the
// core's line ('wind.wind_speed: ...') beside the row. The grow's state carries the last wind set.
function makeWindPanel(table) {
  const box = $('wind-params');
  if (!box || !table.length) return;
  windDefaults = Object.fromEntries(table.map((spec) => [spec.key, spec.default]));
  windPanel = new ParamPanel(box, table, () => {
    clearTimeout(windTimer);
    windTimer = setTimeout(sendWind, 250);
  });
  for (const spec of table) {
    const row = $(`param-${spec.key}`)?.closest('.field');
    if (!row) continue;
    const line = document.createElement('p');
    line.className = 'field-error';
    line.id = `wind-error-${spec.key}`;
    line.setAttribute('role', 'alert');
    line.hidden = true;
    row.append(line);
    errorFields[`wind.${spec.key}`] = line.id;
  }
  box.querySelector('details')?.removeAttribute('open');  // folded under Blow until asked for
  gardenWind.changed();  // the still line in the defaults' words
}
// Before the first garden there is none to set the wind on: the rows are kept in the state, and
// the first garden's reply sets them (its wind differs from the state's: 'garden' below).
function sendWind(wind = windPanel?.values()) {
  if (!windPanel) return;
  if (!bounds) {
    state = { ...(state || {}), wind };
    return;
  }
  worker.request('windRows', { wind }, { done: ['gardenWindRows'] });
}
worker.on('gardenWindRows', (msg) => {
  controller.showFieldError('');
  windPanel?.markError('');
  state = { ...(state || {}), wind: msg.state.wind || {} };
  controller.grown(msg.hash);
  lastGoodHash = msg.hash;
  if (lastGoodState) lastGoodState = { ...lastGoodState, wind: msg.state.wind || {} };
  setHooks({ windRows: JSON.stringify(state.wind), windRowsError: '' });
  gardenWind.changed();
});

// ---------------------------------------------------------------- worker replies
worker.on('ready', (msg) => {
  if (restarting) {
    restarting = false;
    // The last finished garden's state, not its link: a link cannot carry the files.
    restoreFiles().then(() => {
      if (!lastGoodState) {
        worker.request('decode', { hash: lastGoodHash ? `#${lastGoodHash}` : OPENING_HASH }, { done: ['decoded'] });
        return;
      }
      applyState(lastGoodState);
      frameNext = true;
      sendUpdate(false);
    });
    return;
  }
  const trees = document.createElement('optgroup');
  trees.label = 'Trees';
  for (const name of msg.species) trees.append(new Option(name, name));
  const objects = document.createElement('optgroup');
  objects.label = 'Objects';
  for (const kind of OBJECT_KINDS) objects.append(new Option(kind, `object:${kind}`));
  ui.species.append(trees, objects);
  if (msg.species.includes('sakura')) ui.species.value = 'sakura';
  panel = new ParamPanel(ui.params, msg.paramTable, (spec, stage) => scheduleUpdate(stage));
  makeWindPanel(msg.windTable || []);
  speciesNames = msg.species;
  // The species mix and the mask join the panel's planting rules.
  $('param-density')?.closest('details')?.append(ui.rulesFiles);
  notices.set('hash', msg.decoded.notices);
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
  ui.progress.textContent = msg.text;
});

worker.on('garden', (msg) => {
  if (!controller.isLatest(msg)) return;
  notices.set('error', '');
  controller.showFieldError('');
  showPlantError('');
  ui.groundError.hidden = true;
  lastGoodHash = msg.hash;
  lastGoodState = msg.state;
  bounds = msg.bounds;
  // A wind set while this garden grew was set on the garden before it: set it on this one too.
  const wind = state?.wind || {};
  const windLost = JSON.stringify(wind) !== JSON.stringify(msg.state.wind || {});
  applyState(msg.state);
  if (windLost) {
    state.wind = wind;
    windPanel?.setValues({ ...windDefaults, ...wind });
    sendWind({ ...windDefaults, ...wind });
  }
  // The ivy's vertices among the objects' (kinds 3 and 4: its stems and leaves), read before the
  // buffers go back to the worker.
  let ivyVertices = 0;
  for (const k of msg.buffers.objects?.kind || []) ivyVertices += k > 2.5 ? 1 : 0;
  gardenWind.stop();  // (the worker stopped it at the update)
  if (renderer) {
    renderer.setGarden(msg.buffers, msg.bounds, msg.barks);
    showOverlay();
    if (frameNext) {
      frameGarden();
      frameNext = false;
    }
  }
  worker.recycle(msg.buffers);
  controller.grown(msg.hash);
  gardenSerial += 1;
  resetYears(msg.stats.years, msg.years, msg.grows);
  hybrid?.garden(bounds, lastYear, msg.grows);
  controller.showWork(false);
  ui.progress.textContent = '';
  const s = msg.stats;
  const species = Object.entries(s.trees.by_species).map(([name, n]) => `${n} ${name}`).join(', ');
  const ivy = s.ivy ? ` · ivy ${s.ivy.internodes.toLocaleString('en')} internodes` : '';
  const m = s.moss;
  const moss = m ? ` · moss ${m.mosses.toLocaleString('en')} (${m.ground_in_crown_shade.mosses_per_m2.toFixed(2)}/m² in crown shade, ${m.ground_open.mosses_per_m2.toFixed(2)}/m² open)` : '';
  ui.stats.textContent = `${s.size} m garden · ${s.years} years · ${s.trees.count} trees (${species}; ${s.trees.distinct} distinct, ${s.planting.by_hand} by hand) · ${s.objects} objects${ivy}${moss} · ${(msg.growMs / 1000).toFixed(1)} s`;
  // Where the grow's time went in the worker (docs/garden-model.md "Where the garden's time goes").
  const phases = msg.phases || {};
  ui.stats.title = `in the worker: ${Object.entries(phases).filter(([, ms]) => ms >= 0.5).map(([k, ms]) => `${k} ${(ms / 1000).toFixed(2)} s`).join(', ')}`;
  setHooks({
    status: 'ready', error: '', gardenSerial, trees: s.trees.count, byHand: s.planting.by_hand, distinct: s.trees.distinct, ivyVertices,
    stats: JSON.stringify(s), statsText: msg.statsText, hash: msg.hash, growMs: msg.growMs.toFixed(1), stateJson: JSON.stringify(msg.state),
    growPhases: JSON.stringify(phases),
    // the distinct trees wearing simulated bark (garden bark 1) and their maps' digests
    barkTrees: renderer ? renderer.barkTrees() : 0,
    barkDigests: (msg.barks || []).map((b) => (b ? b.bark.digest : '')).join(','),
  });
  requestFrame();
});

// ---------------------------------------------------------------- the year scrubber and Play
// Each grow records every year's picture (the worker's 'garden' reply: `years`, the recorded years
// and their bytes); the scrubber asks the worker for a year's trees ('year'; a newer pick
// supersedes an older one), which builds them from that record: no year is grown again
// (data-worker-grows, the worker's count of grows, stays put while scrubbing). The year asked and
// the time from the pick to that year on screen are hooks (yearShown, yearAnswerMs).
let lastYear = 0;        // the garden's years (the last grown)
let years = null;        // the worker's yearsJson of the garden on screen
let gardenGrows = 0;     // the worker's grows count of the garden on screen
let shownYear = 0;       // the year on screen
let askedYear = null;    // {year, at: performance.now()} of the pick not yet drawn
let yearSerial = 0;
let yearWaiters = [];    // Play: resolved once the year asked is on screen

// The recorded ivy's internodes of year y (the ivy grows on the garden's clock), or NaN.
function yearIvy(y) {
  return Number(years?.ivy?.[years.recorded.indexOf(y)]);
}

function yearText(y) {
  const mosses = years?.mosses?.[years.recorded.indexOf(y)];
  const ivy = yearIvy(y);
  return `year ${y} of ${lastYear}${Number.isFinite(ivy) && ivy > 0 ? ` · ivy ${ivy.toLocaleString('en')} internodes` : ''}${Number.isFinite(mosses) && mosses > 0 ? ` · ${mosses.toLocaleString('en')} mosses` : ''}`;
}

function resetYears(total, record, grows) {
  stopPlaying();
  lastYear = Number(total) || 0;
  years = record || null;
  gardenGrows = grows;
  shownYear = lastYear;
  askedYear = null;
  ui.year.max = String(lastYear);
  ui.year.value = String(lastYear);
  ui.year.disabled = lastYear === 0;
  ui.yearText.textContent = yearText(lastYear) + (years?.stopped_by ? ` · years after ${years.recorded.at(-1) ?? 0} not recorded` : '');
  const kb = (years?.record_bytes ?? 0) / 1024;
  setHooks({ yearShown: lastYear, yearsRecorded: years?.recorded?.length ?? 0, recordKb: kb.toFixed(0), workerGrows: grows, yearAnswerMs: '' });
}

// Shows garden year y (0..lastYear) from the record; a year the record left out says so.
function pickYear(y) {
  gardenWind.stop();  // a recorded year is drawn still
  y = Math.max(0, Math.min(lastYear, Math.round(y)));
  ui.year.value = String(y);
  if (!years || !renderer) return;
  if (y !== lastYear && !years.recorded.includes(y)) {
    ui.yearText.textContent = `year ${y} of ${lastYear} was not recorded (${years.stopped_by}): set Years to ${y} to grow it`;
    return;
  }
  ui.yearText.textContent = yearText(y);
  askedYear = { year: y, at: performance.now(), frames: 0 };
  setHooks({ yearAsked: y, yearAnswerMs: '' });
  worker.request('year', { year: y, grows: gardenGrows }, { done: ['gardenYear'] });
}

worker.on('gardenYear', (msg) => {
  // A reply for a garden no longer on screen (a grow came between): its buffers go back.
  if (msg.stale || msg.run !== gardenGrows || !renderer || !askedYear || msg.year !== askedYear.year) {
    worker.recycle(msg.buffers);
    return;
  }
  renderer.setYear(msg.buffers.year, msg.year, msg.year === lastYear);
  worker.recycle(msg.buffers);
  shownYear = msg.year;
  hybrid?.garden(bounds, shownYear, gardenGrows);
  yearSerial += 1;
  setHooks({ yearSerial, workerGrows: msg.grows, yearBuildMs: msg.ms.toFixed(1), yearIvy: String(yearIvy(msg.year)) });
  loop.request(true);  // the picked year at the next animation frame
});

// Called after every finished frame: a year picked is on screen.
function yearDrawn() {
  if (!askedYear || !renderer) return;
  askedYear.frames += 1;  // frames finished since the pick, this one included
  if (shownYear !== askedYear.year) return;
  const ms = performance.now() - askedYear.at;
  setHooks({ yearShown: shownYear, yearAnswerMs: ms.toFixed(0), yearFrames: askedYear.frames, drawnYearSerial: yearSerial });
  askedYear = null;
  const waiting = yearWaiters;
  yearWaiters = [];
  for (const resolve of waiting) resolve(true);
}

ui.year.addEventListener('input', () => {
  stopPlaying();
  pickYear(Number(ui.year.value));
});

// Play shows every year from the one on screen (or 0 at the end) to the last: the next year is
// picked 200 ms after this one is on screen, so no year is skipped on a slow frame.
let playRun = 0;
function stopPlaying() {
  playRun += 1;
  ui.play.textContent = 'Play';
  ui.play.setAttribute('aria-pressed', 'false');
}
ui.play.addEventListener('click', async () => {
  if (ui.play.getAttribute('aria-pressed') === 'true') return stopPlaying();
  if (!years || lastYear === 0) return;
  const run = ++playRun;
  ui.play.textContent = 'Pause';
  ui.play.setAttribute('aria-pressed', 'true');
  let y = shownYear >= lastYear ? 0 : shownYear;
  const played = [];
  while (run === playRun && y <= lastYear) {
    const onScreen = new Promise((resolve) => yearWaiters.push(resolve));
    pickYear(y);
    if (!(await Promise.race([onScreen, new Promise((r) => setTimeout(() => r(false), 10000))]))) break;
    if (run !== playRun) break;
    played.push(y);
    setHooks({ yearsPlayed: played.join(',') });
    await new Promise((resolve) => setTimeout(resolve, 200));
    y += 1;
  }
  if (run === playRun) stopPlaying();
});

// ---------------------------------------------------------------- overlays
// The ground's overlay (garden_renderer.js OVERLAYS) and its legend; the moss's light needs a moss
// (moss_days > 0), else the ground keeps its height tint and the legend says why.
const OVERLAY_LEGEND = {
  none: '',
  moss: 'The moss\'s light S of its last day (W/m², the photon map gathered, 10-day mean): dark blue 0, teal 50 (the thesis\'s mosses grow below about 50), yellow 300 and over; grey where the moss has no cell.',
  slope: 'Slope of the ground: green 0°, yellow 20°, red 45° and over (slope_max refuses the rules\' trees above it).',
  altitude: 'Altitude bands: one band a metre (or a tenth of the relief, if that is more), a dark line at each band\'s foot.',
};
function showOverlay() {
  const name = ui.overlay.value;
  const noMoss = name === 'moss' && renderer && !renderer.hasMoss;
  if (renderer) renderer.overlay = name;
  ui.overlayHelp.textContent = noMoss ? 'No moss in this garden (moss_days is 0, or years is 0): the ground keeps its height tint.' : OVERLAY_LEGEND[name];
  setHooks({ overlay: noMoss ? 'none' : name });
  requestFrame();
}
ui.overlay.addEventListener('change', showOverlay);

// ---------------------------------------------------------------- controls
let down = null;
ui.canvas.addEventListener('pointerdown', (e) => { down = { x: e.clientX, y: e.clientY, button: e.button, shift: e.shiftKey }; });
ui.canvas.addEventListener('pointerup', (e) => {
  if (!down || !renderer || !state) return;
  const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
  const plain = down.button === 0 && !down.shift;
  down = null;
  if (moved > 4 || !plain) return;
  const rect = ui.canvas.getBoundingClientRect();
  const hit = renderer.groundHit(renderer.rayAt(camera, e.clientX - rect.left, e.clientY - rect.top));
  if (!hit) {
    ui.clickHelp.textContent = 'That click missed the ground.';
    return;
  }
  ui.clickHelp.textContent = '';
  clickGround(hit[0], hit[2]);
});

ui.resetView.addEventListener('click', frameGarden);
ui.copyLink.addEventListener('click', async () => {
  await copyLink(ui.shareStatus);
  if (ui.linkFiles.textContent) ui.shareStatus.textContent += ' It does not carry the files (below).';
});
// The embed: <niwa-garden> (public/niwa-garden.js) or an iframe of public/embed.html?study=garden,
// both of the page's hash.
$('embed').addEventListener('click', () => {
  showEmbedDialog({ tag: 'niwa-garden', title: 'Niwa garden', heading: 'Embed this garden', script: 'niwa-garden.js', frame: 'embed.html?study=garden' });
});
const baseName = () => `garden-${state?.params?.years ?? 0}y`;
$('download-glb').addEventListener('click', () => controller.exportAs('glb', `${baseName()}.glb`, 'model/gltf-binary'));
$('download-svg').addEventListener('click', () => controller.exportAs('svg', `${baseName()}-plan.svg`, 'image/svg+xml'));

// The canvas point (CSS pixels) where the point `up` metres above ground point (x, z) is drawn: for
// a test's real click (up 0) or a tree's crown on screen.
window.__niwaGardenScreenOf = (x, z, up = 0) => {
  if (!renderer) return null;
  const y = renderer.heightAt(x, z) + up;
  const w = ui.canvas.clientWidth, h = ui.canvas.clientHeight;
  const m = camera.viewProjection(w / h);
  const c = [0, 1, 2, 3].map((r) => m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
  return [((c[0] / c[3] + 1) / 2) * w, ((1 - c[1] / c[3]) / 2) * h];
};

// For a test: the last garden's bounds (boundsJson: every planted tree's species, pos and group).
window.__niwaGardenBounds = () => bounds;

// For a test: the camera aimed at ground point (x, z), `up` metres above it, from `distance`
// metres (a trunk close-up), or put back to `view` (what an earlier call returned), and the
// simulated bark shown or left off (an A/B of the same frame): `bark` on the full trees,
// `hybridBark` (default: bark) on the hybrid trees' card atlases (repainted when it changes in
// hybrid mode: a new round, data-hybrid-serial). Returns {serial, view}: the frame drawn after it
// sets data-drawn-look to serial; view, the camera as it was.
window.__niwaGardenLook = ({ x = 0, z = 0, up = 0.8, distance = 3, bark = true, hybridBark = bark, view = null } = {}) => {
  if (!renderer) return null;
  const before = { target: [...camera.target], distance: camera.distance, yaw: camera.yaw, pitch: camera.pitch };
  if (view) Object.assign(camera, { target: [...view.target], distance: view.distance, yaw: view.yaw, pitch: view.pitch });
  else Object.assign(camera, { target: [x, renderer.heightAt(x, z) + up, z], distance });
  renderer.barkShown = bark;
  hybrid?.showBark(hybridBark);
  lookSerial += 1;
  requestFrame();
  return { serial: lookSerial, view: before };
};

// For a test's A/B of one view: the ground's level of detail (web/garden/ground_lod.js) at its most
// `px` pixels a drawn cell, 0 the full grid, undefined the page's own; the next frame drawn with it.
window.__niwaGardenGroundLod = (px) => {
  if (!renderer) return;
  renderer.lodPx = px;
  lookSerial += 1;
  requestFrame();
  return lookSerial;
};

// Blow / Still: the last year's trees swayed by a gust front crossing the garden.
const gardenWind = new GardenWind({
  worker, button: $('wind'), info: $('wind-info'), renderer: () => renderer,
  moved: () => loop.moved(), request: () => loop.request(), trees: () => bounds?.trees,
  hybrid: () => hybrid, wind: () => ({ ...windDefaults, ...(state?.wind || {}) }),
  canBlow: () => (!bounds || !renderer ? 'Nothing grown yet.' : !bounds.trees?.length ? 'No trees to sway.'
    : shownYear !== lastYear ? `Blow sways the last year's trees: show year ${lastYear} first.` : ''),
});

// ---------------------------------------------------------------- start
setHooks({ status: 'loading' });
await startRenderer();
worker.request('init', { hash: location.hash && location.hash !== '#' ? location.hash : OPENING_HASH }, { done: ['ready'] });
