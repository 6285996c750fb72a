// <niwa-bark>: bark that cracks as the trunk grows (paper 003, Hirota, Kato, Kaneko), for any
// page; the bark study's counterpart of <niwa-tree> (niwa-embed.js) and <niwa-ivy>.
//
//   <script type="module" src="https://HOST/niwa-bark.js"></script>
//   <niwa-bark species="pine" seed="3"></niwa-bark>
//   <niwa-bark state="species=tallow&amp;model=2layer&amp;seed=2&amp;N_R=64&amp;N_H=32"></niwa-bark>
//
// Attributes: species (camphor, tallow or pine), model, seed, or state (the bark page's share-link
// hash, which wins over the others). Shows the unrolled tile as it cracks (a 64 × 32 preview
// first, then the full lattice), then the base-colour map on the tile and a trunk segment wearing
// the maps. Drag, wheel or the arrow and +/- keys orbit and zoom. Every <niwa-*> element on a page
// shares ONE Web Worker and one WASM instance, kept apart by a client id; the core checks every
// value and its one-line message is shown as text, never as markup.
// Does not: offer the panel, the scrubber, Table 3 or downloads (the bark page, public/bark.html,
// does). The shadow root, camera, frame loop and the shared worker are web/shell/embed_element.js's.
import { EmbedElement, attributeValue } from './web/shell/embed_element.js';
import { BarkRenderer } from './web/bark/bark_renderer.js';
import { DEFAULT_SUNS } from './web/gl/sun.js';
import { setHooks } from './web/shell/test_hooks.js';

// Attribute -> state key (the bark state JSON of core/bark/bark_state.h).
const KEYS = { species: 'species', model: 'model', seed: 'seed' };
const NUMERIC = new Set(['seed']);

class NiwaBark extends EmbedElement {
  static get observedAttributes() { return [...Object.keys(KEYS), 'state']; }

  constructor() {
    super({ kind: 'bark', label: 'Niwa bark', study: 'bark', messages: ['decoded', 'frame', 'preview', 'bark', 'error'] });
    this.pending = null;  // the last reply that came before the renderer
    this.framed = false;
  }

  createRenderer(frame) {
    return new BarkRenderer(frame);
  }

  frameOptions() {
    return { sun: DEFAULT_SUNS.ivy, ground: false, fit: true, what: 'the bark' };
  }

  onRendererReady() {
    if (this.pending) this.show(this.pending);
    this.pending = null;
  }

  disconnectedCallback() {
    this.worker?.cancel('bark');
    this.releaseWorker();
  }

  async load() {
    this.ensureWorker();
    setHooks({ status: 'growing' }, this);
    await this.ready;
    const hash = this.getAttribute('state');
    if (hash !== null) {
      this.decode(hash);
      return;
    }
    const state = {};
    for (const [attribute, key] of Object.entries(KEYS)) {
      const value = this.getAttribute(attribute);
      if (value !== null) state[key] = attributeValue(value, NUMERIC.has(key));
    }
    this.grow(state, []);
  }

  grow(state, notices) {
    this.line.textContent = notices.join('\n');
    this.worker.request('update', { state }, { group: 'bark', done: ['bark'] });
  }

  onWorkerMessage(msg) {
    if (msg.type === 'decoded') {
      this.grow(msg.state, msg.notices);
    } else if (msg.type === 'frame' || msg.type === 'preview' || msg.type === 'bark') {
      if (msg.id !== this.worker.latestId('bark')) return;
      if (this.renderer) this.show(msg);
      else if (msg.type !== 'frame') this.pending = msg;
    } else if (this.ownError(msg, 'bark')) {
      this.showMessage(msg.message);
    }
  }

  show(msg) {
    const r = this.renderer;
    if (msg.type === 'frame') {
      r.setTile(msg.tile, msg.bounds, { live: true });
    } else {
      r.setTile(msg.buffers.tile, msg.bounds);
      r.setMaps(msg.buffers.maps, msg.bounds.map.width, msg.bounds.map.height);
    }
    if (!this.framed && r.bounds()) {
      this.camera.yaw = 0;
      this.camera.pitch = 0.04;
      const b = r.bounds();
      this.camera.frame(b, 1.0);
      const aspect = this.canvas.clientWidth / Math.max(1, this.canvas.clientHeight) || 1;
      const t = Math.tan(this.camera.fov / 2);
      this.camera.distance = 1.1 * Math.max(b.max[1] / t, b.max[0] / (t * aspect)) + b.max[2];
      this.framed = true;
    }
    if (msg.type === 'bark') {
      this.worker.recycle(msg.buffers);
      this.line.textContent = '';
      const s = msg.stats;
      setHooks({ status: 'ready', error: '', species: s.species, hash: msg.hash, stats: JSON.stringify(s) }, this);
    }
    this.requestFrame();
  }
}

if (!customElements.get('niwa-bark')) customElements.define('niwa-bark', NiwaBark);
