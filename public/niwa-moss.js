// <niwa-moss>: mosses grown day by day on a small scene from light, water and warmth (Nomura 2010)
// for any page; the moss study's counterpart of <niwa-tree> (niwa-embed.js), <niwa-ivy> and
// <niwa-terrain>.
//
//   <script type="module" src="https://HOST/niwa-moss.js"></script>
//   <niwa-moss scene="walls" seed="2"></niwa-moss>
//   <niwa-moss state="preset=nomura2010-sky&amp;days=90&amp;photons=2048" animate></niwa-moss>
//
// Attributes: scene (a scene of `niwa moss scenes`), preset (nomura2010 or nomura2010-sky), days,
// seed (the RNG seed), or state (the moss page's share-link hash, which wins over the others);
// without state the run is the moss page's opening one (thesis, 60 days, 4096 photons a day: a
// few seconds) with the attributes over it; animate replays the days from 0 once it is grown (the
// mosses alive each day; nothing regrows). Drag, wheel or the arrow and +/- keys orbit and zoom.
// Every <niwa-moss> (and <niwa-tree>, <niwa-ivy>, <niwa-terrain>) on a page shares ONE Web Worker
// and one WASM instance, kept apart by a client id; the core checks every value and its one-line
// message is shown as text, never as markup.
// Does not: take a dropped mesh, show overlays or charts, or download (the moss page,
// public/moss.html, does). The shadow root, camera, frame loop and the shared worker are
// web/shell/embed_element.js's.
import { EmbedElement } from './web/shell/embed_element.js';
import { setHooks } from './web/shell/test_hooks.js';
import { MossRenderer } from './web/moss/moss_renderer.js';
import { DEFAULT_SUNS } from './web/gl/sun.js';

// The moss page's opening run (web/moss/moss_page.js OPENING), the attributes' base.
const OPENING = { days: 60, photons: 4096 };
const DAY_MS = 100;

class NiwaMoss extends EmbedElement {
  static get observedAttributes() { return ['scene', 'preset', 'days', 'seed', 'state']; }

  constructor() {
    super({ kind: 'moss', label: 'Niwa moss: mosses grown on a small scene day by day', study: 'moss',
      messages: ['decoded', 'moss', 'error'] });
    this.pendingMoss = null;  // a run that came before the renderer
    this.days = 0;
    this.animation = null;
  }

  // The mosses on the land as the layer of the element's Frame, fitted to the view.
  createRenderer(frame) {
    return new MossRenderer(frame);
  }

  frameOptions() {
    return { sun: DEFAULT_SUNS.ivy, ground: false, fit: true, what: 'the moss' };
  }

  onRendererReady() {
    if (this.pendingMoss) this.showMoss(this.pendingMoss);
  }

  drawFrame() {
    const drawn = this.frame.render(this.camera);
    setHooks({ drawnTriangles: drawn.triangles }, this);
  }

  disconnectedCallback() {
    this.animation = null;
    this.worker?.cancel('moss');
    this.releaseWorker();
  }

  // The attributes as a share-link hash, so state= and the attributes go through the same decoder.
  stateHash() {
    const state = this.getAttribute('state');
    if (state !== null) return state;
    const parts = [];
    for (const key of ['preset', 'scene', 'seed']) {
      const value = this.getAttribute(key);
      if (value !== null) parts.push(`${key}=${encodeURIComponent(value)}`);
    }
    parts.push(`days=${encodeURIComponent(this.getAttribute('days') ?? OPENING.days)}`);
    parts.push(`photons=${OPENING.photons}`);
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
      this.worker.request('update', { state: msg.state }, { group: 'moss', done: ['moss'] });
    } else if (msg.type === 'moss') {
      if (this.renderer) this.showMoss(msg);
      else this.pendingMoss = msg;
    } else if (this.ownError(msg, 'moss')) {
      this.showMessage(msg.message);
    }
  }

  showMoss(msg) {
    this.pendingMoss = null;
    this.renderer.setMoss(msg.buffers, msg.bounds, Number(msg.state.params.moss_size) || 0.01);
    this.worker.recycle(msg.buffers);  // used at once (copied to the GPU)
    const b = this.renderer.bounds();
    if (b) {
      this.camera.reset(b);
      this.camera.pitch = 0.55;
      this.camera.frame(b, 0.9);
    }
    this.days = msg.bounds.days;
    const s = msg.stats;
    setHooks({ status: 'ready', error: '', mosses: s.mosses.total, days: this.days, hash: msg.hash, stats: JSON.stringify(s) }, this);
    if (this.hasAttribute('animate')) this.animate();
    else this.showDay(this.days);
  }

  showDay(k) {
    this.renderer.setDay(k >= this.days ? Infinity : k);
    setHooks({ stepShown: k, mossesShown: this.renderer.aliveOn(k).total }, this);
    this.requestFrame();
  }

  // Replays the run: one day every DAY_MS from day 0 to the last.
  async animate() {
    const token = (this.animation = {});
    for (let k = 0; k <= this.days && token === this.animation; ++k) {
      this.showDay(k);
      await new Promise((resolve) => setTimeout(resolve, DAY_MS));
    }
  }
}

if (!customElements.get('niwa-moss')) customElements.define('niwa-moss', NiwaMoss);
