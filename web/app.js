// Niwa page (main thread): starts the worker, builds the panel from the parameter table, keeps the
// state in location.hash (one history entry per committed edit) and draws each new tree with WebGL2.
// All growth runs in web/worker.js.
import { OrbitCamera } from './camera.js';
import { ParamPanel } from './panel.js';
import { Renderer } from './renderer.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'),
  notice: $('notice'),
  stats: $('stats'),
  frameStats: $('frame-stats'),
  sunInfo: $('sun-info'),
  progress: $('progress'),
  progressBar: $('grow-progress'),
  preset: $('preset'),
  presetSource: $('preset-source'),
  seed: $('seed'),
  years: $('years'),
  params: $('params'),
  reset: $('reset'),
  play: $('play'),
  year: $('year'),
  yearText: $('year-text'),
  selection: $('selection'),
  cut: $('cut'),
  undo: $('undo'),
  redo: $('redo'),
  prunes: $('prunes'),
  copyLink: $('copy-link'),
  resetView: $('reset-view'),
  embed: $('embed'),
  downloadGlb: $('download-glb'),
  downloadJson: $('download-json'),
  downloadPng: $('download-png'),
  shareStatus: $('share-status'),
  embedDialog: $('embed-dialog'),
  embedElement: $('embed-element'),
  embedIframe: $('embed-iframe'),
  wind: $('wind'),
  windInfo: $('wind-info'),
  renderMode: $('render-mode'),
  renderTable: $('render-table'),
  renderCol: $('render-col'),
  timeFrames: $('time-frames'),
};
const root = document.documentElement;

let hashNotices = [];   // from decoding the URL hash at start (or after navigation)
let pruneNotices = [];  // prunes of the current state that cut nothing (from the grown tree)
let errorMessage = '';  // from the core, for the current state
let webglMessage = '';

// Notices are shown as text only (textContent), never as markup: they may echo the URL.
function showNotices() {
  const lines = [webglMessage, errorMessage, ...hashNotices, ...pruneNotices].filter(Boolean);
  ui.notice.textContent = lines.join('\n');
  ui.notice.hidden = lines.length === 0;
}

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let renderer = null;
let frameRequested = false;
let poseDrawPending = false;
function requestFrame() {
  if (!renderer || frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(() => {
    frameRequested = false;
    const drawn = renderer.render(camera);
    if (drawn) showFrameStats(drawn);
    root.dataset.drawnTreeSerial = String(treeSerial);  // tests wait for the new tree's frame
    if (poseDrawPending) {  // the worker sends the next pose once this one is on screen
      poseDrawPending = false;
      worker.postMessage({ type: 'poseDone' });
    }
  });
}

// Draw primitives and frame cost: triangles and draw calls of the last frame (from the index counts
// drawn), and the CPU time of the render call averaged over the last 30 frames drawn (frames are
// drawn on demand, so there is no steady frame rate to report; GPU time is not measurable here).
const frameTimes = [];
function showFrameStats(drawn) {
  frameTimes.push(drawn.cpuMs);
  if (frameTimes.length > 30) frameTimes.shift();
  const avg = frameTimes.reduce((a, b) => a + b, 0) / frameTimes.length;
  ui.frameStats.textContent = `tris ${Math.round(drawn.triangles).toLocaleString('en-US')} · draw calls ${drawn.drawCalls}`
    + ` · frame ${avg.toFixed(1)} ms CPU`;
  ui.frameStats.title = `CPU time of the render call, mean of the last ${frameTimes.length} frames drawn (GPU time is not measured)`;
  const column = drawn.mode === 'hybrid' ? 'row' : 'full';
  setCell(column, 'draw_calls', drawn.drawCalls);
  setCell(column, 'frame_ms', `${avg.toFixed(1)} ms`);
  if (drawn.mode !== 'hybrid') for (const key of ['draw_calls', 'frame_ms']) setCell('row', key, '');
}

// ---------------------------------------------------------------- render table (thesis table 4.1)
function setCell(column, key, value) {
  const cell = ui.renderTable.querySelector(`[data-${column}="${key}"]`);
  if (cell) cell.textContent = typeof value === 'number' ? value.toLocaleString('en-US') : String(value);
}
function showFullCounts(mesh) {
  const tris = (part) => (part ? part.indices.byteLength / 12 : 0);
  const bark = tris(mesh.bark), leaves = tris(mesh.leaves) + tris(mesh.flowers);
  setCell('full', 'branch_polygons', bark);
  setCell('full', 'leaf_polygons', leaves);
  setCell('full', 'total_polygons', bark + leaves);
}
function showHybridCounts(stats) {
  ui.renderCol.textContent = stats ? 'hybrid' : 'this view';
  for (const key of ['lines', 'branch_polygons', 'leaf_polygons', 'total_polygons', 'textures']) {
    setCell('row', key, stats ? stats[key] : '');
  }
  if (!stats) return;
  Object.assign(root.dataset, {
    renderLines: String(stats.lines),
    renderPolygons: String(stats.total_polygons),
    renderTextures: String(stats.textures),
    renderFull: String(stats.full_polygons),
    // Every alive branch is a line or a card in every view (none vanishes while switching).
    renderUnassigned: String(stats.alive_branches - stats.line_branches - stats.card_branches),
    renderViews: String(Number(root.dataset.renderViews || 0) + 1),
  });
}

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
  worker.postMessage({ type: 'view', camera: renderer.viewFor(camera) });
}

// The renderer's light is the light model's sun (parameters sun_elevation and sun_azimuth).
function showSun() {
  if (!panel) return;
  const v = panel.values();
  const el = Number(v.sun_elevation), az = Number(v.sun_azimuth), weight = Number(v.sun_weight);
  if (!Number.isFinite(el) || !Number.isFinite(az)) return;
  const growth = weight > 0 ? `and the growth model, weight ${weight}` : 'only; the growth model has sky light (sun_weight 0)';
  ui.sunInfo.textContent = `sun: az ${az}°, el ${el}° (lights the view ${growth})`;
  renderer?.setSun(el, az);
  requestFrame();
}

// Camera moves rewrite the cam= field of the current history entry (no new entry), a moment later.
let cameraTimer = 0;
function cameraMoved() {
  requestFrame();
  requestView();
  clearTimeout(cameraTimer);
  cameraTimer = setTimeout(writeHash, 400);
}

async function startRenderer() {
  try {
    renderer = new Renderer(ui.canvas);
    await renderer.init();
    camera.attach(ui.canvas, cameraMoved);
    new ResizeObserver(() => {
      requestFrame();
      requestView();
    }).observe(ui.canvas);
    ui.canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();
      webglMessage = 'The WebGL2 context was lost; reload the page to draw again.';
      showNotices();
    });
    requestFrame();
  } catch (e) {
    renderer = null;
    root.dataset.drawing = 'off';  // no frames will come (tests stop waiting for them)
    webglMessage = `Cannot draw: ${e.message}`;
    showNotices();
  }
}

// ---------------------------------------------------------------- state and worker
const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
let panel = null;
let presets = [];
let nextId = 0;
let latestId = 0;
let latestRequest = null;  // {id, kind, showYear, state}
let treeSerial = 0;
let debounceTimer = 0;
let currentPrunes = [];
let showYear = null;       // the scrubber's year, or null for the state's full age
let shownYear = 0;         // the age of the tree on screen
let baseHash = '';         // the core's hash of the current state (without cam=)
let frameNext = true;      // frame the camera on the next tree
let lastBounds = null;    // bounds of the tree on screen (Reset view)
let selected = null;       // selected branch id
let historyIndex = 0;      // position of this page's entry among the edits (undo/redo)
let historyMax = 0;

function currentState() {
  const text = (input) => (input.value.trim() !== '' && Number.isFinite(Number(input.value)) ? Number(input.value) : input.value);
  // The camera is appended by the page (writeHash), so the core hashes the tree state only.
  return { preset: ui.preset.value, seed: text(ui.seed), years: text(ui.years), params: panel.values(), prunes: [...currentPrunes] };
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
  ui.year.max = String(n);
  if (showYear !== null && showYear >= n) showYear = null;
  ui.year.value = String(showYear ?? n);
  ui.yearText.textContent = `${showYear ?? n} of ${n}`;
}

// kind: 'edit' (a committed change: new history entry, camera framed), 'prune' (committed, camera
// kept), 'scrub' (another age of the same state), 'restore' (undo/redo/back/forward).
function sendUpdate(kind = 'edit') {
  clearTimeout(debounceTimer);
  latestId = ++nextId;
  syncScrubber();
  const state = currentState();
  // An edit still waiting for its debounce is committed by whichever request carries it.
  const commit = kind === 'edit' || kind === 'prune' || editPending;
  editPending = false;
  latestRequest = { id: latestId, kind, state, commit };
  if (kind === 'edit') frameNext = true;
  root.dataset.status = 'growing';
  const message = { type: 'update', id: latestId, state };
  if (showYear !== null) message.until = showYear;
  worker.postMessage(message);
}

let editPending = false;
function scheduleUpdate() {
  editPending = true;
  hashNotices = [];
  clearTimeout(debounceTimer);
  root.dataset.status = 'pending';
  debounceTimer = setTimeout(() => sendUpdate('edit'), 250);
}

function fullHash() {
  return `#${baseHash}${baseHash && renderer ? `&cam=${camera.toHash()}` : ''}`;
}

function entryState() {
  return { niwa: { index: historyIndex, max: historyMax, showYear } };
}

// Rewrites the current history entry (camera moves, scrubbing: no new entry).
function writeHash() {
  if (!baseHash) return;
  const hash = fullHash();
  if (location.hash !== hash) history.replaceState(entryState(), '', hash);
}

// A committed edit: a new history entry (so back/forward and undo/redo walk through edits).
function commitHash(hash) {
  if (hash === baseHash) return writeHash();
  const first = baseHash === '';
  baseHash = hash;
  if (first) return writeHash();
  historyIndex += 1;
  historyMax = historyIndex;
  history.pushState(entryState(), '', fullHash());
  updateUndoButtons();
}

function updateUndoButtons() {
  ui.undo.disabled = historyIndex <= 0;
  ui.redo.disabled = historyIndex >= historyMax;
}

function formatStats(s) {
  const height = s.height >= 100 ? s.height.toFixed(0) : s.height.toFixed(1);
  return `internodes ${s.internodes} · leaves ${s.leaves} · flowers ${s.flowers} · height ${height} cm · grown in ${s.ms.toFixed(0)} ms`;
}

function select(id) {
  selected = Number.isInteger(id) ? id : null;
  renderer?.select(selected);
  ui.cut.disabled = selected === null || shownYear < 1;
  ui.selection.textContent = selected === null
    ? 'Click a branch in the view to select it.'
    : `Branch ${selected} selected: Cut (or the Delete key) removes it and everything above it after year ${shownYear}.`;
  root.dataset.selected = selected === null ? '' : String(selected);
  requestFrame();
}

const waiters = [];  // resolved with each tree (the play loop waits on them)

worker.onmessage = (event) => {
  const msg = event.data;
  switch (msg.type) {
    case 'ready': {
      presets = msg.presets;
      for (const p of presets) ui.preset.append(new Option(`${p.title} (${p.name})`, p.name));
      panel = new ParamPanel(ui.params, msg.paramTable, () => {
        showSun();
        ui.renderMode.value = String(Number(panel.values().render_mode) === 1 ? 1 : 0);
        scheduleUpdate();
      });
      applyState(msg.decoded.state);
      hashNotices = msg.decoded.notices;
      if (camera.fromHash(msg.decoded.state.camera)) frameNext = false;
      const saved = history.state?.niwa;
      if (saved && Number.isInteger(saved.index)) {
        historyIndex = saved.index;
        // After a reload the forward entries are still there: redo stays available.
        historyMax = Math.max(saved.index, Number.isInteger(saved.max) ? saved.max : 0);
      }
      showNotices();
      updateUndoButtons();
      sendUpdate('restore');
      break;
    }
    case 'decoded':
      applyState(msg.state);
      hashNotices = msg.notices;
      if (camera.fromHash(msg.state.camera)) frameNext = false;
      showNotices();
      sendUpdate('restore');
      break;
    case 'hash':
      if (msg.id !== latestId) break;
      if (latestRequest.commit) commitHash(msg.hash);
      else {
        baseHash = msg.hash;
        writeHash();
      }
      break;
    case 'progress':
      if (msg.id !== latestId) break;
      ui.progressBar.hidden = false;
      ui.progressBar.max = Math.max(1, msg.years);
      ui.progressBar.value = msg.year;
      ui.progress.textContent = msg.year < msg.years ? `growing: year ${msg.year} of ${msg.years}` : 'building mesh';
      break;
    case 'tree': {
      if (msg.id !== latestId) break;
      errorMessage = '';
      pruneNotices = msg.stats.idle_prunes || [];
      panel.markError('');
      showNotices();
      ui.stats.textContent = formatStats(msg.stats);
      ui.progress.textContent = msg.stats.truncated ? 'stopped at max_internodes' : '';
      ui.progressBar.hidden = true;
      shownYear = msg.stats.years;
      if (renderer) {
        renderer.setTree(msg.mesh, msg.stats.bounds, msg.swayNodes, msg.hybrid);
        renderer.leafLength = Number(panel.values().leaf_size) / 100 || 0.05;
        lastBounds = msg.stats.bounds;
        if (frameNext) {
          camera.frame(msg.stats.bounds, 1.12);  // room for the year bar over the view
          frameNext = false;
          writeHash();
        }
        requestFrame();
      }
      showFullCounts(msg.mesh);
      hybridOn = Boolean(msg.hybrid);
      viewInFlight = false;
      showHybridCounts(null);
      root.dataset.renderMode = hybridOn ? 'hybrid' : 'full';
      requestView();
      if (latestRequest.kind !== 'scrub') select(null); else select(selected);
      Object.assign(root.dataset, {
        status: 'ready',
        treeSerial: String(++treeSerial),
        internodes: String(msg.stats.internodes),
        leaves: String(msg.stats.leaves),
        flowers: String(msg.stats.flowers),
        year: String(msg.stats.years),
      });
      waiters.splice(0).forEach((resolve) => resolve(true));
      if (windPlaying) worker.postMessage({ type: 'wind', play: true });  // sway the new tree too
      else showWind(null);
      break;
    }
    case 'drawList':
      viewInFlight = false;
      if (!hybridOn || !renderer) break;
      renderer.setDrawList(msg);
      showHybridCounts(msg.stats);
      requestFrame();
      if (viewDirty) requestView();
      break;
    case 'pose':
      if (!windPlaying || !renderer) {
        worker.postMessage({ type: 'poseDone' });
        break;
      }
      renderer.setPoses(new Float32Array(msg.poses), msg.wind, msg.time);
      poseDrawPending = true;
      showWind(msg);
      requestFrame();
      break;
    case 'export':
      exportIds.delete(msg.id);
      download(new Blob([msg.bytes], { type: msg.format === 'glb' ? 'model/gltf-binary' : 'application/json' }),
        `${fileStem()}${msg.format === 'json' ? '-params' : ''}.${msg.format}`);
      break;
    case 'error':
      if (exportIds.delete(msg.id)) {
        ui.shareStatus.textContent = `Export failed: ${msg.message}`;
        break;
      }
      if (msg.id !== undefined && msg.id !== latestId) break;
      errorMessage = msg.message;
      panel?.markError(msg.message);
      ui.progress.textContent = '';
      ui.progressBar.hidden = true;
      showNotices();
      root.dataset.status = 'error';
      waiters.splice(0).forEach((resolve) => resolve(false));
      break;
    default:
      break;
  }
};
worker.onerror = (e) => {
  e.preventDefault();
  errorMessage = `The simulation worker failed to start${e.message ? `: ${e.message}` : ''}.`;
  showNotices();
  root.dataset.status = 'error';
};

// ---------------------------------------------------------------- controls
ui.preset.addEventListener('change', () => {
  const preset = presets.find((p) => p.name === ui.preset.value);
  if (preset) applyState({ preset: preset.name, seed: preset.seed, years: preset.years, params: preset.params, prunes: [] });
  showYear = null;
  scheduleUpdate();
});
ui.seed.addEventListener('input', scheduleUpdate);
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

let playing = false;
function stopPlaying() {
  playing = false;
  ui.play.textContent = 'Play';
  ui.play.setAttribute('aria-pressed', 'false');
}
ui.play.addEventListener('click', async () => {
  if (playing) return stopPlaying();
  const n = fullYears();
  if (n === null || panel === null) return;
  playing = true;
  ui.play.textContent = 'Pause';
  ui.play.setAttribute('aria-pressed', 'true');
  let y = showYear === null || showYear >= n ? 0 : showYear;
  while (playing && y <= n) {
    showYear = y >= n ? null : y;
    const done = new Promise((resolve) => waiters.push(resolve));
    sendUpdate('scrub');
    if (!(await done) || !playing) break;
    await new Promise((resolve) => setTimeout(resolve, 250));
    y += 1;
  }
  stopPlaying();
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
  if (selected === null || shownYear < 1) return;
  const prune = `${shownYear}:b${selected}`;
  if (!currentPrunes.includes(prune)) currentPrunes.push(prune);
  showPrunes();
  select(null);
  sendUpdate('prune');
}
ui.cut.addEventListener('click', cutSelected);
ui.undo.addEventListener('click', () => { if (historyIndex > 0) history.back(); });
ui.redo.addEventListener('click', () => { if (historyIndex < historyMax) history.forward(); });

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

// Back/forward (and undo/redo, which use them) restore the entry's state; a hash typed by the user
// arrives here too and becomes a new entry.
window.addEventListener('popstate', (event) => {
  stopPlaying();
  const saved = event.state?.niwa;
  if (saved && Number.isInteger(saved.index)) {
    historyIndex = saved.index;
    showYear = Number.isInteger(saved.showYear) ? saved.showYear : null;
  } else {
    historyIndex = historyMax = historyIndex + 1;
    showYear = null;
  }
  updateUndoButtons();
  history.replaceState(entryState(), '', location.href);  // remembers historyMax for a reload
  baseHash = '';
  worker.postMessage({ type: 'decode', id: ++nextId, hash: location.hash });
});

// ---------------------------------------------------------------- wind (thesis chapter 3)
// Blow runs the node-point sway of the tree on screen in the worker; each pose (16 floats per node
// point) skins the mesh in the vertex shader. The wind is the state's wind parameters.
let windPlaying = false;
function showWind(pose) {
  if (!pose) {
    ui.windInfo.textContent = windPlaying ? 'starting the wind…' : 'Still air. Blow sways the tree with the wind settings (speed, direction, gusts).';
    root.dataset.swayTime = '';
    return;
  }
  const speed = pose.wind > 0 ? `${pose.wind.toFixed(1)} m/s` : 'calm';
  ui.windInfo.textContent = `t = ${pose.time.toFixed(1)} s · wind ${speed}`;
  root.dataset.swayTime = pose.time.toFixed(3);
}
function setWind(play) {
  windPlaying = play;
  ui.wind.textContent = play ? 'Still' : 'Blow';
  ui.wind.setAttribute('aria-pressed', String(play));
  worker.postMessage({ type: 'wind', play });
  if (!play) {
    renderer?.setRestPoses(renderer.poseNodes);
    requestFrame();
  }
  showWind(null);
}
ui.wind.addEventListener('click', () => setWind(!windPlaying));

// Frame time of this view with the GPU's work included (the "frame (CPU)" row is only the CPU time
// of issuing the draw calls), into the column of the mode shown.
ui.timeFrames.addEventListener('click', async () => {
  if (!renderer || ui.timeFrames.disabled) return;
  ui.timeFrames.disabled = true;
  try {
    const timed = await renderer.timeFrames(camera, 10);
    setCell(timed.mode === 'hybrid' ? 'row' : 'full', 'timed_ms', `${timed.ms.toFixed(1)} ms`);
    root.dataset[timed.mode === 'hybrid' ? 'timedHybrid' : 'timedFull'] =
      JSON.stringify({ ms: timed.ms, triangles: timed.triangles, lines: timed.lines, drawCalls: timed.drawCalls });
  } finally {
    ui.timeFrames.disabled = false;
  }
});

ui.renderMode.addEventListener('change', () => {
  if (!panel) return;
  panel.setValues({ render_mode: Number(ui.renderMode.value) });
  scheduleUpdate();
});

// ---------------------------------------------------------------- share and export
function fileStem() {
  return `niwa-${ui.preset.value}-seed${ui.seed.value}-year${shownYear}`;
}

function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
  ui.shareStatus.textContent = `Saved ${name}`;
}

const exportIds = new Set();
function requestExport(format) {
  const id = ++nextId;
  exportIds.add(id);
  worker.postMessage({ type: 'export', id, format });
}
ui.downloadGlb.addEventListener('click', () => requestExport('glb'));
ui.downloadJson.addEventListener('click', () => requestExport('json'));
ui.downloadPng.addEventListener('click', () => {
  if (!renderer) return;
  renderer.render(camera);
  ui.canvas.toBlob((blob) => {
    if (blob) download(blob, `${fileStem()}.png`);
    else ui.shareStatus.textContent = 'The picture could not be saved.';
  }, 'image/png');
});

ui.resetView.addEventListener('click', () => {
  camera.reset(lastBounds);
  cameraMoved();
});

ui.copyLink.addEventListener('click', async () => {
  writeHash();
  try {
    await navigator.clipboard.writeText(location.href);
    ui.shareStatus.textContent = 'Link copied.';
  } catch {
    ui.shareStatus.textContent = `Copy this link: ${location.href}`;
  }
});

ui.embed.addEventListener('click', () => {
  writeHash();
  const base = new URL('.', location.href).href;
  const state = location.hash.slice(1).replace(/&/g, '&amp;').replace(/"/g, '&quot;');
  ui.embedElement.value = `<script type="module" src="${base}niwa-embed.js"></script>\n`
    + `<niwa-tree state="${state}" style="width:480px;height:360px"></niwa-tree>`;
  ui.embedIframe.value = `<iframe src="${base}embed.html#${state}" width="480" height="360" title="Niwa tree" loading="lazy"></iframe>`;
  ui.embedDialog.showModal();
  ui.embedElement.select();
});

root.dataset.status = 'loading';
startRenderer();
worker.postMessage({ type: 'init', hash: location.hash });
