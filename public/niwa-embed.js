// <niwa-tree>: a grown Niwa tree for any page.
//
//   <script type="module" src="https://HOST/niwa-embed.js"></script>
//   <niwa-tree preset="sakura" years="12" seed="3"></niwa-tree>
//   <niwa-tree state="preset=maple&amp;seed=2&amp;years=10" animate></niwa-tree>
//   <niwa-tree preset="keyaki" wind></niwa-tree>
//
// Attributes: preset, seed, years, or state (a share link's hash, which wins over the other three);
// animate grows the tree year by year once it is shown; wind sways it in the state's wind (thesis
// chapter 3, the gust schedule repeating). Drag, wheel, pinch or the arrow and +/- keys
// orbit and zoom. Every <niwa-tree> on a page shares ONE Web Worker and so one WASM instance (the
// worker keeps their requests apart by a client id). Messages are shown as text, never as markup.
import { OrbitCamera } from './web/gl/orbit_camera.js';
import { FrameLoop } from './web/gl/frame_loop.js';
import { setHooks } from './web/shell/test_hooks.js';
import { WorkerClient } from './web/shell/worker_client.js';
import { Renderer } from './web/tree/tree_renderer.js';

let nextClient = 0;
let ready = null;  // the shared worker's module, loaded once for every element (its 'ready')

const STYLE = `
:host { display: inline-block; position: relative; width: 320px; height: 320px; contain: content; }
:host([hidden]) { display: none; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; cursor: grab; border-radius: inherit; }
canvas:focus-visible { outline: 3px solid #2f6b3a; outline-offset: -3px; }
p { position: absolute; left: 0.4rem; bottom: 0.4rem; margin: 0; padding: 0.15rem 0.4rem; border-radius: 4px;
    background: rgba(255, 255, 255, 0.82); font: 12px system-ui, sans-serif; color: #1d2a1f; max-width: calc(100% - 0.8rem); }
p:empty { display: none; }
`;

class NiwaTree extends HTMLElement {
  static get observedAttributes() { return ['preset', 'seed', 'years', 'state', 'wind']; }

  constructor() {
    super();
    this.client = `tree-${++nextClient}`;
    const shadow = this.attachShadow({ mode: 'open' });
    const style = document.createElement('style');
    style.textContent = STYLE;
    this.canvas = document.createElement('canvas');
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', 'Niwa tree. Drag or use the arrow keys to orbit, wheel or plus and minus to zoom.');
    this.line = document.createElement('p');
    this.line.setAttribute('aria-live', 'polite');
    shadow.append(style, this.canvas, this.line);
    this.camera = new OrbitCamera();
    this.renderer = null;
    this.rendererReady = null;
    this.framed = false;
    this.frames = new FrameLoop(() => this.drawFrame());
    this.worker = null;
    this.state = null;
    this.years = 0;
    this.animating = false;
    this.pendingTree = null;
  }

  // This element's client of the page's one worker (attributes may arrive before connectedCallback).
  ensureWorker() {
    if (this.worker) return;
    this.worker = new WorkerClient(this.client, { onFailure: (text) => this.showMessage(text) });
    for (const type of ['decoded', 'tree', 'drawList', 'pose', 'error']) this.worker.on(type, (msg) => this.onWorkerMessage(msg));
    // One init for the page's worker (its module and tables), from the first element.
    if (!ready) ready = this.worker.request('init', { hash: '' }, { done: ['ready'] }).reply;
  }

  connectedCallback() {
    this.ensureWorker();
    if (!this.rendererReady) this.rendererReady = this.startRenderer();
    this.load();
  }

  disconnectedCallback() {
    this.animating = false;
    this.worker?.post('wind', { play: false });
    this.worker?.cancel('tree');
  }

  attributeChangedCallback() {
    if (this.isConnected) this.load();
  }

  async startRenderer() {
    try {
      const renderer = new Renderer(this.canvas);
      await renderer.init();
      this.renderer = renderer;
      this.frames.attach(renderer.gl, this.canvas);  // one frame in flight (web/gl/frame_loop.js)
      this.camera.attach(this.canvas, () => {
        this.requestFrame();
        this.requestView();
      });
      new ResizeObserver(() => this.requestFrame()).observe(this.canvas);
      if (this.pendingTree) this.showTree(this.pendingTree);
    } catch (e) {
      this.showMessage(`Cannot draw: ${e.message}`);
    }
  }

  showMessage(text) {
    this.line.textContent = text;
    setHooks({ status: 'error' }, this);
  }

  requestFrame() {
    if (this.renderer) this.frames.request();
  }

  drawFrame() {
    this.renderer.render(this.camera);
    if (this.poseDrawPending) {  // the worker sends the next pose once this one is on screen
      this.poseDrawPending = false;
      this.worker.post('poseDone');
    }
  }

  // Hybrid mode (render_mode 1 in the state): one view request at a time, the newest camera wins.
  requestView() {
    if (!this.hybridOn || !this.renderer) return;
    if (this.viewInFlight) {
      this.viewDirty = true;
      return;
    }
    this.viewInFlight = true;
    this.viewDirty = false;
    this.worker.post('view', { camera: this.renderer.viewFor(this.camera) });
  }

  // Reads the attributes: state= goes through the core's hash decoder; the others are checked by the
  // core when the tree is grown (missing ones take the preset's values).
  load() {
    this.ensureWorker();
    this.framed = false;
    setHooks({ status: 'growing' }, this);
    const hash = this.getAttribute('state');
    if (hash !== null) {
      this.worker.request('decode', { hash }, { done: ['decoded'] });
      return;
    }
    const state = {};
    for (const key of ['preset', 'seed', 'years']) {
      const value = this.getAttribute(key);
      if (value !== null) state[key] = value.trim() !== '' && Number.isFinite(Number(value)) ? Number(value) : value;
    }
    this.start(state, []);
  }

  start(state, notices) {
    this.state = state;
    this.line.textContent = notices.join('\n');
    if (this.hasAttribute('animate')) {
      this.animate();
    } else {
      this.grow();
    }
  }

  // Resolves to true with the tree, false on an error or when a newer request superseded it.
  async grow(until) {
    const message = { state: this.state };
    if (until !== undefined) message.until = until;
    const reply = await this.worker.request('update', message, { group: 'tree', done: ['tree'] }).reply;
    return Boolean(reply && reply.type === 'tree');
  }

  // Grows the tree year by year, from a seedling to its full age.
  async animate() {
    this.animating = true;
    const token = (this.animationToken = {});
    const years = Number(this.state.years);
    // The full tree first (frames the camera at its final size), then every age from the start.
    if (!(await this.grow())) return;
    const total = Number.isInteger(years) ? years : this.years;
    for (let y = 0; y <= total && this.animating && token === this.animationToken; ++y) {
      if (!(await this.grow(y))) return;
      await new Promise((resolve) => setTimeout(resolve, 300));
    }
    this.animating = false;
  }

  onWorkerMessage(msg) {
    if (msg.type === 'decoded') {
      const { camera, ...state } = msg.state;
      if (this.camera.fromHash(camera)) this.framed = true;
      this.sun = [state.params?.sun_elevation, state.params?.sun_azimuth];  // the light model's sun
      this.start(state, msg.notices);
    } else if (msg.type === 'tree') {
      this.years = msg.stats.years;
      if (this.renderer) this.showTree(msg);
      else this.pendingTree = msg;
    } else if (msg.type === 'drawList') {
      this.viewInFlight = false;
      if (!this.hybridOn || !this.renderer) return;
      this.renderer.setDrawList(msg);
      this.requestFrame();
      if (this.viewDirty) this.requestView();
    } else if (msg.type === 'pose') {
      if (!this.hasAttribute('wind') || !this.renderer) {
        this.worker.post('poseDone');
        return;
      }
      this.renderer.setPoses(new Float32Array(msg.poses), msg.wind, msg.time);
      this.poseDrawPending = true;
      setHooks({ swayTime: msg.time.toFixed(3) }, this);
      this.requestFrame();
    } else if (msg.type === 'error' && (msg.id === undefined || msg.id === this.worker.latestId('tree'))) {
      this.showMessage(msg.message);
    }
  }

  showTree(msg) {
    this.pendingTree = null;
    // A big mesh goes up in parts (tree_renderer.js): draw again once it is in place.
    this.renderer.setTree(msg.mesh, msg.stats.bounds, msg.swayNodes, msg.hybrid).then(() => this.requestFrame());
    this.hybridOn = Boolean(msg.hybrid);
    this.viewInFlight = false;
    if (this.sun) this.renderer.setSun(...this.sun);
    this.worker.post('wind', { play: this.hasAttribute('wind') });
    if (!this.framed) {
      this.camera.frame(msg.stats.bounds);
      this.framed = true;
    }
    this.requestFrame();
    this.requestView();
    setHooks({ status: 'ready', internodes: msg.stats.internodes, year: msg.stats.years }, this);
  }
}

if (!customElements.get('niwa-tree')) customElements.define('niwa-tree', NiwaTree);
