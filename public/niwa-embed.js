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
// The shadow root, camera, frame loop and the shared worker are web/shell/embed_element.js's.
import { EmbedElement, attributeValue } from './web/shell/embed_element.js';
import { LatestRequest } from './web/shell/latest_request.js';
import { setHooks } from './web/shell/test_hooks.js';
import { Renderer } from './web/tree/tree_renderer.js';
import { viewOf } from './web/gl/buffers.js';

class NiwaTree extends EmbedElement {
  static get observedAttributes() { return ['preset', 'seed', 'years', 'state', 'wind']; }

  constructor() {
    super({ kind: 'tree', label: 'Niwa tree', messages: ['decoded', 'tree', 'drawList', 'pose', 'error'] });
    this.framed = false;
    this.state = null;
    this.years = 0;
    this.animating = false;
    this.pendingTree = null;
    // Hybrid mode's draw lists: one request in flight, the newest camera wins.
    this.viewRequest = new LatestRequest(() => this.worker.post('view', { camera: this.renderer.viewFor(this.camera) }));
  }

  // The tree as the layer of the element's Frame (the tree's sun, a ground).
  createRenderer(frame) {
    return new Renderer(frame);
  }

  onRendererReady() {
    if (this.pendingTree) this.showTree(this.pendingTree);
  }

  onCameraMove() {
    this.requestFrame();
    this.requestView();
  }

  disconnectedCallback() {
    this.animating = false;
    this.worker?.post('wind', { play: false });
    this.worker?.cancel('tree');
    this.releaseWorker();
  }

  drawFrame() {
    this.frame.render(this.camera);
    if (this.poseDrawPending) {  // the worker sends the next pose once this one is on screen
      this.poseDrawPending = false;
      this.worker.post('poseDone');
    }
  }

  // Hybrid mode (render_mode 1 in the state): one view request at a time, the newest camera wins.
  requestView() {
    if (!this.hybridOn || !this.renderer) return;
    this.viewRequest.request();
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
      if (value !== null) state[key] = attributeValue(value, true);
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
      this.viewRequest.done();
      if (!this.hybridOn || !this.renderer) return;
      this.renderer.setDrawList(msg);
      this.worker.recycle({ cards: msg.cards, lines: msg.lines });  // uploaded: back to the worker
      this.requestFrame();
      if (this.viewRequest.wanted) this.requestView();
    } else if (msg.type === 'pose') {
      if (!this.hasAttribute('wind') || !this.renderer) {
        this.worker.post('poseDone');
        return;
      }
      this.renderer.setPoses(viewOf(Float32Array, msg.poses), msg.wind, msg.time);
      this.worker.recycle({ sway: { poses: msg.poses } });  // uploaded: back to the worker
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
    // Once in place, the mesh's buffers go back to the worker for the next tree to fill.
    const { bark, leaves, flowers } = msg.mesh;
    this.renderer.setTree(msg.mesh, msg.stats.bounds, msg.swayNodes, msg.hybrid).then(() => {
      this.worker.recycle({ bark, leaves, flowers });
      this.requestFrame();
    });
    this.hybridOn = Boolean(msg.hybrid);
    this.viewRequest.done();
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
