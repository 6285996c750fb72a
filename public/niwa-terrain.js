// <niwa-terrain>: a mountain grown from one seed contour (paper 002, Misawa, Chiba, Saito) for any
// page; the terrain study's counterpart of <niwa-tree> (niwa-embed.js) and <niwa-ivy>.
//
//   <script type="module" src="https://HOST/niwa-terrain.js"></script>
//   <niwa-terrain builtin="valleys" method="improved" seed="3"></niwa-terrain>
//   <niwa-terrain state="preset=improved&amp;builtin=lobes7&amp;d=25"></niwa-terrain>
//   <niwa-terrain state="contour=0,0;300,0;300,200;0,200" animate></niwa-terrain>
//
// Attributes: builtin (a seed of `niwa terrain seeds`), method (simple, midpoint, fourier, improved
// or a figure preset), seed (the RNG seed), or state (the terrain page's share-link hash, drawn
// contours included, which wins over the others); animate replays the mountain level by level once
// it is grown (the surface cut at each level; nothing regrows). Drag, wheel or the arrow and +/-
// keys orbit and zoom. Every <niwa-terrain> (and <niwa-tree>, <niwa-ivy>) on a page shares ONE Web
// Worker and one WASM instance, kept apart by a client id; the core checks every value and its
// one-line message is shown as text, never as markup.
// Does not: draw seeds, import files or download (the terrain page, public/terrain.html, does).
import { OrbitCamera } from './web/gl/orbit_camera.js';
import { FrameLoop } from './web/gl/frame_loop.js';
import { setHooks } from './web/shell/test_hooks.js';
import { WorkerClient } from './web/shell/worker_client.js';
import { gridIndices } from './web/terrain/grid_indices.js';
import { TerrainRenderer } from './web/terrain/terrain_renderer.js';

let nextClient = 0;
let ready = null;  // the terrain handler's tables, loaded once for every element (its 'ready')

const STYLE = `
:host { display: inline-block; position: relative; width: 320px; height: 320px; contain: content; }
:host([hidden]) { display: none; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; cursor: grab; border-radius: inherit; }
canvas:focus-visible { outline: 3px solid #2f6b3a; outline-offset: -3px; }
p { position: absolute; left: 0.4rem; bottom: 0.4rem; margin: 0; padding: 0.15rem 0.4rem; border-radius: 4px;
    background: rgba(255, 255, 255, 0.82); font: 12px system-ui, sans-serif; color: #1d2a1f; max-width: calc(100% - 0.8rem); }
p:empty { display: none; }
`;

class NiwaTerrain extends HTMLElement {
  static get observedAttributes() { return ['builtin', 'method', 'seed', 'state']; }

  constructor() {
    super();
    this.client = `terrain-${++nextClient}`;
    const shadow = this.attachShadow({ mode: 'open' });
    const style = document.createElement('style');
    style.textContent = STYLE;
    this.canvas = document.createElement('canvas');
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', 'Niwa terrain: a mountain grown from one contour. Drag or use the arrow keys to orbit, wheel or plus and minus to zoom.');
    this.line = document.createElement('p');
    this.line.setAttribute('aria-live', 'polite');
    shadow.append(style, this.canvas, this.line);
    this.camera = new OrbitCamera();
    this.renderer = null;
    this.rendererReady = null;
    this.frames = new FrameLoop(() => {
      const drawn = this.renderer.render(this.camera);
      setHooks({ drawnLines: drawn.lines, drawnTriangles: drawn.triangles }, this);
    });
    this.worker = null;
    this.pendingTerrain = null;  // a mountain that came before the renderer
    this.levels = null;
    this.animation = null;
  }

  ensureWorker() {
    if (this.worker) return;
    this.worker = new WorkerClient(this.client, { study: 'terrain', onFailure: (text) => this.showMessage(text) });
    for (const type of ['decoded', 'terrain', 'error']) this.worker.on(type, (msg) => this.onWorkerMessage(msg));
    if (!ready) ready = this.worker.request('init', { hash: '' }, { done: ['ready'] }).reply;
  }

  connectedCallback() {
    this.ensureWorker();
    if (!this.rendererReady) this.rendererReady = this.startRenderer();
    this.load();
  }

  disconnectedCallback() {
    this.animation = null;
    this.worker?.cancel('terrain');
  }

  attributeChangedCallback() {
    if (this.isConnected) this.load();
  }

  async startRenderer() {
    try {
      const renderer = new TerrainRenderer(this.canvas);
      await renderer.init();
      this.renderer = renderer;
      this.camera.attach(this.canvas, () => this.requestFrame());
      new ResizeObserver(() => this.requestFrame()).observe(this.canvas);
      if (this.pendingTerrain) this.showTerrain(this.pendingTerrain);
    } catch (e) {
      this.showMessage(`Cannot draw: ${e.message}`);
    }
  }

  showMessage(text) {
    this.line.textContent = text;
    setHooks({ status: 'error', error: text }, this);
  }

  requestFrame() {
    if (this.renderer) this.frames.request();
  }

  // The attributes as a share-link hash (builtin, preset, seed), so state= and the attributes go
  // through the same decoder; a missing builtin is the terrain page's opening seed, lobes7.
  stateHash() {
    const state = this.getAttribute('state');
    if (state !== null) return state;
    const parts = [];
    const method = this.getAttribute('method');
    if (method !== null) parts.push(`preset=${encodeURIComponent(method)}`);
    parts.push(`builtin=${encodeURIComponent(this.getAttribute('builtin') ?? 'lobes7')}`);
    const seed = this.getAttribute('seed');
    if (seed !== null) parts.push(`seed=${encodeURIComponent(seed)}`);
    return parts.join('&');
  }

  async load() {
    this.ensureWorker();
    this.animation = null;
    setHooks({ status: 'growing' }, this);
    await ready;
    this.worker.request('decode', { hash: this.stateHash() }, { group: 'decode', done: ['decoded'] });
  }

  onWorkerMessage(msg) {
    if (msg.type === 'decoded') {
      this.line.textContent = msg.notices.join('\n');
      this.worker.request('update', { state: msg.state }, { group: 'terrain', done: ['terrain'] });
    } else if (msg.type === 'terrain') {
      if (this.renderer) this.showTerrain(msg);
      else this.pendingTerrain = msg;
    } else if (msg.type === 'error' && (msg.id === undefined || msg.id === this.worker.latestId('terrain') || msg.id === this.worker.latestId('decode'))) {
      this.showMessage(msg.message);
    }
  }

  showTerrain(msg) {
    this.pendingTerrain = null;
    msg.buffers.surface.indices = gridIndices(msg.bounds.width, msg.bounds.height);
    this.renderer.setTerrain(msg.buffers, msg.bounds);
    const b = this.renderer.bounds();
    if (b) {
      this.camera.reset(b);
      this.camera.pitch = 0.62;
      this.camera.frame(b, 0.82);
    }
    this.levels = { min: msg.bounds.level_min, max: msg.bounds.level_max, h0: msg.bounds.h0, dh: msg.bounds.dh };
    const s = msg.stats;
    setHooks({ status: 'ready', error: '', levels: s.levels, peaks: s.peaks, hash: msg.hash, stats: JSON.stringify(s) }, this);
    if (this.hasAttribute('animate')) this.animate();
    else this.showLevel(Infinity);
  }

  showLevel(k) {
    const all = !Number.isFinite(k) || k >= this.levels.max;
    this.renderer.setLevel(all ? Infinity : k, all ? Infinity : this.levels.h0 + k * this.levels.dh);
    setHooks({ levelShown: all ? 'all' : k }, this);
    this.requestFrame();
  }

  // Replays the mountain: one level every 120 ms from the lowest contour to the top.
  async animate() {
    const token = (this.animation = {});
    for (let k = this.levels.min; k <= this.levels.max && token === this.animation; ++k) {
      this.showLevel(k);
      await new Promise((resolve) => setTimeout(resolve, 120));
    }
  }
}

if (!customElements.get('niwa-terrain')) customElements.define('niwa-terrain', NiwaTerrain);
