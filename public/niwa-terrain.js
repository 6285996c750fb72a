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
// The shadow root, camera, frame loop and the shared worker are web/shell/embed_element.js's.
import { EmbedElement } from './web/shell/embed_element.js';
import { setHooks } from './web/shell/test_hooks.js';
import { gridIndices } from './web/terrain/grid_indices.js';
import { TerrainRenderer } from './web/terrain/terrain_renderer.js';
import { DEFAULT_SUNS } from './web/gl/sun.js';

class NiwaTerrain extends EmbedElement {
  static get observedAttributes() { return ['builtin', 'method', 'seed', 'state']; }

  constructor() {
    super({ kind: 'terrain', label: 'Niwa terrain: a mountain grown from one contour', study: 'terrain',
      messages: ['decoded', 'terrain', 'error'] });
    this.pendingTerrain = null;  // a mountain that came before the renderer
    this.levels = null;
    this.animation = null;
  }

  // The mountain as the layer of the element's Frame, fitted to the view, in the terrain's sun.
  createRenderer(frame) {
    return new TerrainRenderer(frame);
  }

  frameOptions() {
    return { sun: DEFAULT_SUNS.terrain, ground: false, fit: true, what: 'the mountain' };
  }

  onRendererReady() {
    if (this.pendingTerrain) this.showTerrain(this.pendingTerrain);
  }

  drawFrame() {
    const drawn = this.frame.render(this.camera);
    setHooks({ drawnLines: drawn.lines, drawnTriangles: drawn.triangles }, this);
  }

  disconnectedCallback() {
    this.animation = null;
    this.worker?.cancel('terrain');
    this.releaseWorker();
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
    await this.ready;
    this.decode(this.stateHash());
  }

  onWorkerMessage(msg) {
    if (msg.type === 'decoded') {
      this.line.textContent = msg.notices.join('\n');
      this.worker.request('update', { state: msg.state }, { group: 'terrain', done: ['terrain'] });
    } else if (msg.type === 'terrain') {
      if (this.renderer) this.showTerrain(msg);
      else this.pendingTerrain = msg;
    } else if (this.ownError(msg, 'terrain')) {
      this.showMessage(msg.message);
    }
  }

  showTerrain(msg) {
    this.pendingTerrain = null;
    msg.buffers.surface.indices = gridIndices(msg.bounds.width, msg.bounds.height);
    this.levels = { min: msg.bounds.level_min, max: msg.bounds.level_max, h0: msg.bounds.h0, dh: msg.bounds.dh };
    // A big surface goes up in parts (web/gl/chunked_upload.js): framed and shown once in place.
    this.renderer.setTerrain(msg.buffers, msg.bounds).then((installed) => {
      if (!installed) return;  // a newer mountain came meanwhile
      const b = this.renderer.bounds();
      if (b) {
        this.camera.reset(b);
        this.camera.pitch = 0.62;
        this.camera.frame(b, 0.82);
      }
      const s = msg.stats;
      setHooks({ status: 'ready', error: '', levels: s.levels, peaks: s.peaks, hash: msg.hash, stats: JSON.stringify(s) }, this);
      if (this.hasAttribute('animate')) this.animate();
      else this.showLevel(Infinity);
    });
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
