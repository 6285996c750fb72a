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
import { OrbitCamera } from './web/camera.js';
import { Renderer } from './web/renderer.js';

const clients = new Map();  // client id -> element
let worker = null;
let nextClient = 0;
let nextId = 0;

function sharedWorker() {
  if (!worker) {
    const url = new URL('./web/worker.js', import.meta.url);
    // A worker script must be same-origin; from another site a one-line module shim imports it
    // (the host then has to send CORS headers for web/, shaders/ and wasm/).
    worker = url.origin === location.origin
      ? new Worker(url, { type: 'module' })
      : new Worker(URL.createObjectURL(new Blob([`import ${JSON.stringify(url.href)};`], { type: 'text/javascript' })), { type: 'module' });
    worker.onmessage = (event) => clients.get(event.data.client)?.onWorkerMessage(event.data);
    worker.onerror = (e) => {
      e.preventDefault();
      for (const element of clients.values()) element.showMessage('The simulation worker failed to start.');
    };
    worker.postMessage({ type: 'init', client: 'embed', hash: '' });
  }
  return worker;
}

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
    this.frameRequested = false;
    this.latestId = 0;
    this.state = null;
    this.years = 0;
    this.animating = false;
    this.pendingTree = null;
  }

  connectedCallback() {
    clients.set(this.client, this);
    if (!this.rendererReady) this.rendererReady = this.startRenderer();
    this.load();
  }

  disconnectedCallback() {
    clients.delete(this.client);
    this.animating = false;
    worker?.postMessage({ type: 'wind', client: this.client, play: false });
  }

  attributeChangedCallback() {
    if (this.isConnected) this.load();
  }

  async startRenderer() {
    try {
      const renderer = new Renderer(this.canvas);
      await renderer.init();
      this.renderer = renderer;
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
    this.dataset.status = 'error';
  }

  requestFrame() {
    if (!this.renderer || this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      this.renderer.render(this.camera);
      if (this.poseDrawPending) {  // the worker sends the next pose once this one is on screen
        this.poseDrawPending = false;
        sharedWorker().postMessage({ type: 'poseDone', client: this.client });
      }
    });
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
    sharedWorker().postMessage({ type: 'view', client: this.client, camera: this.renderer.viewFor(this.camera) });
  }

  // Reads the attributes: state= goes through the core's hash decoder; the others are checked by the
  // core when the tree is grown (missing ones take the preset's values).
  load() {
    this.framed = false;
    this.dataset.status = 'growing';
    const hash = this.getAttribute('state');
    if (hash !== null) {
      sharedWorker().postMessage({ type: 'decode', id: ++nextId, client: this.client, hash });
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

  grow(until) {
    this.latestId = ++nextId;
    const message = { type: 'update', id: this.latestId, client: this.client, state: this.state };
    if (until !== undefined) message.until = until;
    sharedWorker().postMessage(message);
    return new Promise((resolve) => { this.resolveTree = resolve; });
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
    } else if (msg.type === 'tree' && msg.id === this.latestId) {
      this.years = msg.stats.years;
      if (this.renderer) this.showTree(msg);
      else this.pendingTree = msg;
      this.resolveTree?.(true);
    } else if (msg.type === 'drawList') {
      this.viewInFlight = false;
      if (!this.hybridOn || !this.renderer) return;
      this.renderer.setDrawList(msg);
      this.requestFrame();
      if (this.viewDirty) this.requestView();
    } else if (msg.type === 'pose') {
      if (!this.hasAttribute('wind') || !this.renderer) {
        sharedWorker().postMessage({ type: 'poseDone', client: this.client });
        return;
      }
      this.renderer.setPoses(new Float32Array(msg.poses), msg.wind, msg.time);
      this.poseDrawPending = true;
      this.dataset.swayTime = msg.time.toFixed(3);
      this.requestFrame();
    } else if (msg.type === 'error' && (msg.id === undefined || msg.id === this.latestId)) {
      this.showMessage(msg.message);
      this.resolveTree?.(false);
    }
  }

  showTree(msg) {
    this.pendingTree = null;
    this.renderer.setTree(msg.mesh, msg.stats.bounds, msg.swayNodes, msg.hybrid);
    this.hybridOn = Boolean(msg.hybrid);
    this.viewInFlight = false;
    if (this.sun) this.renderer.setSun(...this.sun);
    sharedWorker().postMessage({ type: 'wind', client: this.client, play: this.hasAttribute('wind') });
    if (!this.framed) {
      this.camera.frame(msg.stats.bounds);
      this.framed = true;
    }
    this.requestFrame();
    this.requestView();
    Object.assign(this.dataset, { status: 'ready', internodes: String(msg.stats.internodes), year: String(msg.stats.years) });
  }
}

if (!customElements.get('niwa-tree')) customElements.define('niwa-tree', NiwaTree);
