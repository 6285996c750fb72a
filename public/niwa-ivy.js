// <niwa-ivy>: climbing ivy (paper 004, Shindo & Sakamoto) grown over a built-in scene or a Niwa
// tree, for any page; the ivy study's counterpart of <niwa-tree> (niwa-embed.js).
//
//   <script type="module" src="https://HOST/niwa-ivy.js"></script>
//   <niwa-ivy scene="cubes4" seed="3" steps="50"></niwa-ivy>
//   <niwa-ivy scene="tree" tree="sakura" tree-years="8" preset="metric" animate></niwa-ivy>
//   <niwa-ivy state="preset=improved&amp;seed=2&amp;steps=60&amp;scene=wall"></niwa-ivy>
//
// Attributes: scene (a built-in scene of `niwa ivy scenes`, or tree), seed, steps, preset, tree and
// tree-years (on scene="tree"), or state (the ivy page's share-link hash, which wins over the
// others); animate replays the growth step by step once it is grown (from the vertices' birth
// steps: nothing regrows). Drag, wheel or the arrow and +/- keys orbit and zoom. Every <niwa-ivy>
// (and <niwa-tree>) on a page shares ONE Web Worker and one WASM instance, kept apart by a client
// id; the core checks every value and its one-line message is shown as text, never as markup.
// Does not: take dropped meshes or clicks for seed points (the ivy page, public/ivy.html, does).
// The shadow root, camera, frame loop and the shared worker are web/shell/embed_element.js's.
import { EmbedElement, attributeValue } from './web/shell/embed_element.js';
import { IvyRenderer } from './web/ivy/ivy_renderer.js';
import { DEFAULT_SUNS } from './web/gl/sun.js';
import { setHooks } from './web/shell/test_hooks.js';

// Attribute -> state key (the ivy state JSON of core/ivy/ivy_state.h).
const KEYS = { scene: 'scene', seed: 'seed', steps: 'steps', preset: 'preset', tree: 'tree', 'tree-years': 'tree_years' };
const NUMERIC = new Set(['seed', 'steps', 'tree_years']);

class NiwaIvy extends EmbedElement {
  static get observedAttributes() { return [...Object.keys(KEYS), 'state']; }

  constructor() {
    super({ kind: 'ivy', label: 'Niwa ivy', study: 'ivy', messages: ['decoded', 'support', 'ivy', 'error'] });
    this.pending = { support: null, ivy: null, leafTexture: null };  // replies that came before the renderer
    this.framed = false;
    this.steps = 0;
    this.animation = null;
  }

  // The ivy as the layer of the element's Frame, fitted to the view, in the ivy's sun.
  createRenderer(frame) {
    return new IvyRenderer(frame);
  }

  frameOptions() {
    return { sun: DEFAULT_SUNS.ivy, ground: false, fit: true, what: 'the ivy' };
  }

  onRendererReady() {
    this.renderer.setVisible({ seeds: false });
    if (this.pending.leafTexture) this.showLeafTexture(this.pending.leafTexture);
    this.pending.leafTexture = null;
    if (this.pending.support) this.showSupport(this.pending.support);
    if (this.pending.ivy) this.showIvy(this.pending.ivy);
  }

  disconnectedCallback() {
    this.animation = null;
    this.worker?.cancel('ivy');
    this.releaseWorker();
  }

  // state= goes through the core's hash decoder; the other attributes are checked by the core when
  // the ivy is grown (missing ones take the defaults: cubes4, paper, seed 1, 50 steps).
  async load() {
    this.ensureWorker();
    this.animation = null;
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
      if (value === null) continue;
      state[key] = attributeValue(value, NUMERIC.has(key));
    }
    // A tree is in metres: its ivy preset is metric unless one is given (as the CLI's --tree-preset).
    if (state.scene === 'tree' && state.preset === undefined) state.preset = 'metric';
    this.grow(state, []);
  }

  grow(state, notices) {
    this.line.textContent = notices.join('\n');
    this.worker.request('update', { state }, { group: 'ivy', done: ['ivy'] });
  }

  onWorkerMessage(msg) {
    if (msg.type === 'decoded') {
      this.grow(msg.state, msg.notices);
    } else if (msg.type === 'support') {
      if (this.renderer) this.showSupport(msg);
      else this.pending.support = msg;
    } else if (msg.type === 'ivy') {
      // The leaf texture (the .glb's pixels) comes with the client's first ivy only: keep it.
      if (msg.leafTexture) {
        if (this.renderer) this.showLeafTexture(msg.leafTexture);
        else this.pending.leafTexture = msg.leafTexture;
      }
      if (this.renderer) this.showIvy(msg);
      else this.pending.ivy = msg;
    } else if (this.ownError(msg, 'ivy')) {
      this.showMessage(msg.message);
    }
  }

  // Uploads the leaf texture and hands its pixels back (the next client's copy goes into them).
  showLeafTexture(texture) {
    this.renderer.setLeafTexture(texture);
    this.worker.recycle({ leafTexture: { pixels: texture.pixels } });
  }

  showSupport(msg) {
    this.pending.support = null;
    this.renderer.clearIvy();
    this.renderer.setSupport(msg.buffers, msg.support.bounds);
    this.framed = false;
    setHooks({ supportName: msg.support.name, supportTriangles: msg.support.triangles }, this);
  }

  showIvy(msg) {
    this.pending.ivy = null;
    this.renderer.setIvy(msg.mesh).then((installed) => {  // a big ivy goes up in parts
      this.worker.recycle(msg.mesh);  // back to the worker for the next ivy to fill
      if (!installed) return;
      if (!this.framed && this.renderer.bounds()) {
        this.camera.reset(this.renderer.bounds());
        this.framed = true;
      }
      this.requestFrame();
    });
    this.steps = msg.steps;
    this.line.textContent = '';
    const s = msg.stats;
    setHooks({ status: 'ready', error: '', internodes: s.internodes, leaves: s.leaves, steps: msg.steps, hash: msg.hash,
      stats: JSON.stringify(s) }, this);
    if (this.hasAttribute('animate')) this.animate();
    else this.showStep(msg.steps);
  }

  showStep(k) {
    this.renderer.setStep(k);
    setHooks({ stepShown: k }, this);
    this.requestFrame();
  }

  // Replays the growth: one step every 60 ms from step 0 to the last (nothing regrows).
  async animate() {
    const token = (this.animation = {});
    for (let k = 0; k <= this.steps && token === this.animation; ++k) {
      this.showStep(k);
      await new Promise((resolve) => setTimeout(resolve, 60));
    }
  }
}

if (!customElements.get('niwa-ivy')) customElements.define('niwa-ivy', NiwaIvy);
