// Niwa page (main thread): starts the worker, builds the panel from the parameter table, keeps the
// state in location.hash and draws each new tree with WebGL2. All growth runs in web/worker.js.
import { OrbitCamera } from './camera.js';
import { ParamPanel } from './panel.js';
import { Renderer } from './renderer.js';

const $ = (id) => document.getElementById(id);
const ui = {
  canvas: $('view'),
  notice: $('notice'),
  stats: $('stats'),
  progress: $('progress'),
  preset: $('preset'),
  presetSource: $('preset-source'),
  seed: $('seed'),
  years: $('years'),
  params: $('params'),
  reset: $('reset'),
};
const root = document.documentElement;

let hashNotices = [];   // from decoding the URL hash at start (or after the user edits it)
let errorMessage = '';  // from the core, for the current state
let webglMessage = '';

// Notices are shown as text only (textContent), never as markup: they may echo the URL.
function showNotices() {
  const lines = [webglMessage, errorMessage, ...hashNotices].filter(Boolean);
  ui.notice.textContent = lines.join('\n');
  ui.notice.hidden = lines.length === 0;
}

// ---------------------------------------------------------------- rendering
const camera = new OrbitCamera();
let renderer = null;
let frameRequested = false;
function requestFrame() {
  if (!renderer || frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(() => {
    frameRequested = false;
    renderer.render(camera);
  });
}

async function startRenderer() {
  try {
    renderer = new Renderer(ui.canvas);
    await renderer.init();
    camera.attach(ui.canvas, requestFrame);
    new ResizeObserver(requestFrame).observe(ui.canvas);
    ui.canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();
      webglMessage = 'The WebGL2 context was lost; reload the page to draw again.';
      showNotices();
    });
    requestFrame();
  } catch (e) {
    renderer = null;
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
let treeSerial = 0;
let debounceTimer = 0;

function currentState() {
  const text = (input) => (input.value.trim() !== '' && Number.isFinite(Number(input.value)) ? Number(input.value) : input.value);
  return { preset: ui.preset.value, seed: text(ui.seed), years: text(ui.years), params: panel.values(), prunes: currentPrunes };
}
let currentPrunes = [];

function applyState(state) {
  ui.preset.value = state.preset;
  ui.seed.value = String(state.seed);
  ui.years.value = String(state.years);
  panel.setValues(state.params);
  currentPrunes = state.prunes || [];
  showPresetSource();
}

function showPresetSource() {
  const preset = presets.find((p) => p.name === ui.preset.value);
  ui.presetSource.textContent = preset ? preset.source : '';
}

function sendUpdate() {
  clearTimeout(debounceTimer);
  latestId = ++nextId;
  root.dataset.status = 'growing';
  worker.postMessage({ type: 'update', id: latestId, state: currentState() });
}

function scheduleUpdate() {
  hashNotices = [];
  clearTimeout(debounceTimer);
  root.dataset.status = 'pending';
  debounceTimer = setTimeout(sendUpdate, 250);
}

function formatStats(s) {
  const height = s.height >= 100 ? s.height.toFixed(0) : s.height.toFixed(1);
  return `internodes ${s.internodes} · leaves ${s.leaves} · flowers ${s.flowers} · height ${height} cm · grown in ${s.ms.toFixed(0)} ms`;
}

worker.onmessage = (event) => {
  const msg = event.data;
  switch (msg.type) {
    case 'ready': {
      presets = msg.presets;
      for (const p of presets) ui.preset.append(new Option(`${p.title} (${p.name})`, p.name));
      panel = new ParamPanel(ui.params, msg.paramTable, scheduleUpdate);
      applyState(msg.decoded.state);
      hashNotices = msg.decoded.notices;
      showNotices();
      sendUpdate();
      break;
    }
    case 'decoded':
      applyState(msg.state);
      hashNotices = msg.notices;
      showNotices();
      sendUpdate();
      break;
    case 'hash':
      if (msg.id !== latestId) break;
      if (location.hash.slice(1) !== msg.hash) history.replaceState(null, '', `#${msg.hash}`);
      lastHash = location.hash;
      break;
    case 'progress':
      if (msg.id !== latestId) break;
      ui.progress.textContent = msg.year < msg.years ? `growing: year ${msg.year} of ${msg.years}` : 'building mesh';
      break;
    case 'tree': {
      if (msg.id !== latestId) break;
      errorMessage = '';
      panel.markError('');
      showNotices();
      ui.stats.textContent = formatStats(msg.stats);
      ui.progress.textContent = msg.stats.truncated ? 'stopped at max_internodes' : '';
      if (renderer) {
        renderer.setTree(msg.mesh, msg.stats.bounds);
        camera.frame(msg.stats.bounds);
        requestFrame();
      }
      Object.assign(root.dataset, {
        status: 'ready',
        treeSerial: String(++treeSerial),
        internodes: String(msg.stats.internodes),
        leaves: String(msg.stats.leaves),
        flowers: String(msg.stats.flowers),
      });
      break;
    }
    case 'error':
      if (msg.id !== undefined && msg.id !== latestId) break;
      errorMessage = msg.message;
      panel?.markError(msg.message);
      ui.progress.textContent = '';
      showNotices();
      root.dataset.status = 'error';
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
  scheduleUpdate();
});
ui.seed.addEventListener('input', scheduleUpdate);
ui.years.addEventListener('input', scheduleUpdate);
ui.reset.addEventListener('click', () => {
  ui.preset.dispatchEvent(new Event('change'));
});

// A hash typed or pasted by the user (our own writes use replaceState and fire no event).
let lastHash = location.hash;
window.addEventListener('hashchange', () => {
  if (location.hash === lastHash) return;
  lastHash = location.hash;
  worker.postMessage({ type: 'decode', id: ++nextId, hash: location.hash });
});

root.dataset.status = 'loading';
startRenderer();
worker.postMessage({ type: 'init', hash: location.hash });
