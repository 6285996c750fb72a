// EmbedElement: the shared start-up of Niwa's custom elements (<niwa-tree>, <niwa-ivy>, ...).
//
// It owns what every embed has: the shadow root (style, canvas, one message line), the orbit
// camera, the frame loop, this element's client of the page's ONE Web Worker (so one WASM
// instance for every embed on a page; the worker keeps the clients apart by id), one `init` per
// study for the whole page, and the view's one Frame (web/gl/frame.js: camera, sun, ground) with
// the study's renderer as its layer. A subclass says which renderer to make, the frame's options
// and which worker messages it wants, and grows its own study:
//
//   class NiwaIvy extends EmbedElement {
//     constructor() { super({ kind: 'ivy', label: 'Niwa ivy', study: 'ivy', messages: ['ivy', 'error'] }); }
//     createRenderer(frame) { return new IvyRenderer(frame); }     // a layer, with async init()
//     frameOptions() { return { sun: DEFAULT_SUNS.ivy, ground: false, fit: true }; }
//     load() { ... }                  // read the attributes, ask the worker
//     onWorkerMessage(msg) { ... }    // the messages named above
//   }
//
// Does not: know any study's attributes, state or messages, or draw anything itself; messages are
// shown as text, never as markup.
import { Frame } from '../gl/frame.js';
import { FrameLoop } from '../gl/frame_loop.js';
import { OrbitCamera } from '../gl/orbit_camera.js';
import { setHooks } from './test_hooks.js';
import { StudyController } from './study_controller.js';

const STYLE = `
:host { display: inline-block; position: relative; width: 320px; height: 320px; contain: content; }
:host([hidden]) { display: none; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; cursor: grab; border-radius: inherit; }
canvas:focus-visible { outline: 3px solid #2f6b3a; outline-offset: -3px; }
p { position: absolute; left: 0.4rem; bottom: 0.4rem; margin: 0; padding: 0.15rem 0.4rem; border-radius: 4px;
    background: rgba(255, 255, 255, 0.82); font: 12px system-ui, sans-serif; color: #1d2a1f; max-width: calc(100% - 0.8rem); }
p:empty { display: none; }
`;

const clientCount = new Map();  // kind -> elements made so far (client ids 'tree-1', 'ivy-2', ...)
const studyReady = new Map();   // study ('' for the tree) -> its init's reply, requested once a page

export class EmbedElement extends HTMLElement {
  // kind: the client id prefix; label: what the canvas is called for screen readers; study: the
  // worker's study handler ('' for the tree, the worker's default); messages: the reply types this
  // element handles in onWorkerMessage.
  constructor({ kind, label, study = '', messages }) {
    super();
    const count = (clientCount.get(kind) || 0) + 1;
    clientCount.set(kind, count);
    this.client = `${kind}-${count}`;
    this.study = study;
    this.messages = messages;
    const shadow = this.attachShadow({ mode: 'open' });
    const style = document.createElement('style');
    style.textContent = STYLE;
    this.canvas = document.createElement('canvas');
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', `${label}. Drag or use the arrow keys to orbit, wheel or plus and minus to zoom.`);
    this.line = document.createElement('p');
    this.line.setAttribute('aria-live', 'polite');
    shadow.append(style, this.canvas, this.line);
    this.camera = new OrbitCamera();
    this.frame = null;     // the view's Frame, once its layer is in
    this.renderer = null;  // the study's layer of it
    this.rendererReady = null;
    this.frames = new FrameLoop(() => this.drawFrame());
    this.worker = null;
    this.ready = null;  // this study's init reply (shared by every element of the study)
  }

  // This element's client of the page's one worker (attributes may arrive before connectedCallback):
  // the client of a study controller of its own (web/shell/study_controller.js: no history, no
  // Cancel, no edits to commit, its hooks on this element, a worker failure on the element's line); the element's
  // handlers of the messages it names (its own error replies included) are installed on it.
  ensureWorker() {
    if (this.worker && !this.worker.isClosed) return;
    this.controller = new StudyController({
      study: this.study, name: this.client, history: false, ui: {}, hooks: this, commits: null,
      notices: { set: (source, lines) => {
        const text = [lines].flat().filter(Boolean).join('\n');
        if (text) this.showMessage(text);
      } },
    });
    this.worker = this.controller.worker;
    for (const type of this.messages) this.worker.on(type, (msg) => this.onWorkerMessage(msg));
    if (!studyReady.has(this.study)) studyReady.set(this.study, this.worker.request('init', { hash: '' }, { done: ['ready'] }).reply);
    this.ready = studyReady.get(this.study);
  }

  // Taken off the page (not moved: still out of it after this task's microtasks): the element's
  // client ends, and the worker lets its sessions and returned buffers go (worker_client.js
  // close; the closed client's late calls do nothing); put back, it gets a new client and grows
  // again. Resolves to the worker's 'closed'
  // reply (null when there was nothing to close), also kept as this.closed (tests).
  releaseWorker() {
    this.closed = Promise.resolve().then(() => (this.isConnected || !this.worker ? null : this.worker.close()));
    return this.closed;
  }

  connectedCallback() {
    this.ensureWorker();
    if (!this.rendererReady) this.rendererReady = this.startRenderer();
    this.load();
  }

  attributeChangedCallback() {
    if (this.isConnected) this.load();
  }

  async startRenderer() {
    try {
      const frame = new Frame(this.canvas, { camera: this.camera, request: () => this.requestFrame(), ...this.frameOptions() });
      await frame.init();
      const renderer = await frame.addLayer(this.createRenderer(frame));
      this.frame = frame;
      this.renderer = renderer;
      this.frames.attach(frame.gl, this.canvas);  // one frame in flight (web/gl/frame_loop.js)
      this.camera.attach(this.canvas, () => this.onCameraMove());
      new ResizeObserver(() => this.requestFrame()).observe(this.canvas);
      this.onRendererReady();
    } catch (e) {
      this.showMessage(`Cannot draw: ${e.message}`);
    }
  }

  // Asks the worker to decode a share-link hash (its 'decoded' reply holds the state and notices);
  // the request's group is 'decode', which ownError below also answers for.
  decode(hash) {
    this.worker.request('decode', { hash }, { group: 'decode', done: ['decoded'] });
  }

  // True for an error reply to this element's latest request of `group` or its latest decode, or
  // one with no request id (a worker failure): the ones the element shows.
  ownError(msg, group) {
    return msg.type === 'error' &&
      (msg.id === undefined || msg.id === this.worker.latestId(group) || msg.id === this.worker.latestId('decode'));
  }

  showMessage(text) {
    this.line.textContent = text;
    setHooks({ status: 'error', error: text }, this);
  }

  requestFrame() {
    if (this.renderer) this.frames.request();
  }

  // Overridable: the Frame's options (web/gl/frame.js: sun, ground, fit, what; default: the
  // tree's sun and a ground), what a frame draws, what a camera move does, what waits for the
  // renderer.
  frameOptions() {
    return {};
  }

  drawFrame() {
    this.frame.render(this.camera);
  }

  onCameraMove() {
    this.requestFrame();
  }

  onRendererReady() {}
}

// Reads numeric attributes as numbers (the core checks every value; a non-number stays text so its
// message names it).
export function attributeValue(value, numeric) {
  return numeric && value.trim() !== '' && Number.isFinite(Number(value)) ? Number(value) : value;
}
