// <niwa-garden>: a garden of trees grown together on one ground, with its walls, rocks, stone
// lantern and ivy (issue 33, docs/garden-model.md) for any page; the garden's counterpart of
// <niwa-tree> (niwa-embed.js), <niwa-ivy>, <niwa-terrain> and <niwa-moss>.
//
//   <script type="module" src="https://HOST/niwa-garden.js"></script>
//   <niwa-garden></niwa-garden>
//   <niwa-garden years="5" seed="2" size="30"></niwa-garden>
//   <niwa-garden state="years=6&amp;plant_seed=3&amp;ground=flat"></niwa-garden>
//
// Attributes: years (the garden's age), seed (the planting rules' seed, plant_seed), size (the
// garden's side in metres), or state (the garden page's share-link hash, which wins over the
// others); without state the garden is the garden page's opening one (the default garden grown
// OPENING_YEARS years: a few seconds) with the attributes over it. Drag, wheel or the arrow and
// +/- keys orbit and zoom. Every <niwa-garden> (and <niwa-tree>, <niwa-ivy>, ...) on a page shares
// ONE Web Worker and one WASM instance, kept apart by a client id; the core checks every value and
// its one-line message (a link's notices, a refused garden) is shown as text, never as markup.
// Does not: place or remove plants, show the panel, replay years or download (the garden page,
// public/garden.html, does). The shadow root, camera, frame loop and the shared worker are
// web/shell/embed_element.js's; the drawing is the garden page's renderer
// (web/garden/garden_renderer.js).
import { EmbedElement } from './web/shell/embed_element.js';
import { setHooks } from './web/shell/test_hooks.js';
import { GardenRenderer } from './web/garden/garden_renderer.js';
import { DEFAULT_SUNS } from './web/gl/sun.js';

// The garden page's opening years (web/garden/garden_page.js OPENING_YEARS).
const OPENING_YEARS = 8;
// Attribute -> the garden table's key (niwa params garden).
const KEYS = { years: 'years', seed: 'plant_seed', size: 'size' };

class NiwaGarden extends EmbedElement {
  static get observedAttributes() { return [...Object.keys(KEYS), 'state']; }

  constructor() {
    super({ kind: 'garden', label: 'Niwa garden: trees grown together on one ground', study: 'garden',
      messages: ['decoded', 'garden', 'error'] });
    this.pendingGarden = null;  // a garden that came before the renderer
    this.gardens = 0;
  }

  // The ground, objects and trees as the layer of the element's Frame, in metres (not fitted).
  createRenderer(frame) {
    return new GardenRenderer(frame);
  }

  frameOptions() {
    return { sun: DEFAULT_SUNS.tree, ground: false, fit: false, what: 'the garden' };
  }

  onRendererReady() {
    if (this.pendingGarden) this.showGarden(this.pendingGarden);
  }

  drawFrame() {
    const drawn = this.frame.render(this.camera);
    setHooks({ drawnTriangles: drawn.triangles, drawnTrees: drawn.trees ?? 0, drawnSerial: this.gardens }, this);
  }

  disconnectedCallback() {
    this.worker?.cancel('garden');
    this.releaseWorker();
  }

  // The attributes as a share-link hash, so state= and the attributes go through the same decoder.
  stateHash() {
    const state = this.getAttribute('state');
    if (state !== null) return state.replace(/^#/, '');
    const parts = [];
    for (const [attribute, key] of Object.entries(KEYS)) {
      const value = this.getAttribute(attribute) ?? (attribute === 'years' ? String(OPENING_YEARS) : null);
      if (value !== null) parts.push(`${key}=${encodeURIComponent(value)}`);
    }
    return parts.join('&');
  }

  async load() {
    this.ensureWorker();
    setHooks({ status: 'growing' }, this);
    await this.ready;
    this.decode(this.stateHash());
  }

  onWorkerMessage(msg) {
    if (msg.type === 'decoded') {
      this.line.textContent = msg.notices.join('\n');
      this.worker.request('update', { state: msg.state }, { group: 'garden', done: ['garden'] });
    } else if (msg.type === 'garden') {
      if (this.renderer) this.showGarden(msg);
      else this.pendingGarden = msg;
    } else if (this.ownError(msg, 'garden')) {
      this.showMessage(msg.message);
    }
  }

  showGarden(msg) {
    this.pendingGarden = null;
    this.renderer.setGarden(msg.buffers, msg.bounds);
    this.worker.recycle(msg.buffers);  // used at once (copied to the GPU)
    // The garden seen from the south-east above, as the garden page frames it (the ground's square,
    // its relief, not the crowns), a little lower and nearer: an element is smaller than the page's
    // view, and its trees read better against the sky.
    const half = msg.bounds.size / 2;
    this.camera.yaw = 0.6;
    this.camera.pitch = 0.6;
    this.camera.frame({ min: [-half, 0, -half], max: [half, msg.bounds.relief, half] }, 0.64);
    this.gardens += 1;
    const s = msg.stats;
    setHooks({ status: 'ready', error: '', trees: s.trees.count, gardenSerial: this.gardens, hash: msg.hash, stats: JSON.stringify(s) }, this);
    this.requestFrame();
  }
}

if (!customElements.get('niwa-garden')) customElements.define('niwa-garden', NiwaGarden);
