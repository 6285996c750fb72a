// The garden page's hybrid trees (issue 33 items 6-7; docs/garden-model.md "The page"): the View's
// "Trees: full | hybrid". In hybrid, every copy farther than NEAR_M from the eye is drawn as the
// grove page draws its trees (thesis ch. 4: eq. 4.1 cards and lines, one draw list per (distinct
// tree, distance band), web/tree/grove_renderer.js as a second layer of the garden's frame, its
// shaders and card atlases), the near copies stay full meshes (garden_renderer.js setFull). The
// worker builds each distinct tree's hybrid scene ('hybrid' -> 'gardenAtlas') and a round of draw
// lists ('hybridViews' -> 'gardenDrawLists') whenever a copy moves to another band (checked after
// every frame); until a round is in, the last one (or every copy in full) stays on screen, so no
// frame is blank. A band's draw list is chosen for its nearest copy's view of the tree; its other
// copies are turned so that the camera sees them from the same side as that copy (their own turn
// is not kept: at a band's distance a tree's turn does not show, a card seen edge-on would).
// Blow sways both: the near copies are the full meshes skinned to their own pose blocks
// (garden_renderer.js setFull keeps them), the far copies' cards and lines are skinned to their
// copy's pose block (the draw lists' skin numbers the node points as Blow's poses; setPoses
// uploads each distinct tree's copies' poses into its pose texture of the grove layer). A band's
// other copies are drawn turned to its nearest copy's view, so their sway turns with them (by
// the difference between that turn and their own; docs/garden-model.md).
// A distinct tree in simulated bark (bark 1) has its atlas's bark painted from its bark map (the
// full trees' texture), so its far copies wear the simulated bark too.
// Test hooks: data-trees-mode, data-hybrid-serial (rounds on screen), data-hybrid-pending,
// data-hybrid-bark-trees (distinct trees whose atlas was painted from their simulated bark),
// data-hybrid-trees, data-full-trees, data-hybrid-ms (a round's time, request to lists),
// data-hybrid-atlas-triangles and data-hybrid-atlas-ms (the atlases' triangles and the page's time to queue their painting),
// data-drawn-hybrid-serial (the round of the last frame drawn); window.__niwaGardenFrameMs(n): the
// median ms of n whole frames of the view on screen (Frame.timeFrames), with {trees: false} of the
// view without its trees; data-hybrid-atlas-sides (side:count of the atlases on screen).
// Does not: grow, step the wind or pick anything, or keep the mode in the link (a view, like the
// camera).
import { drawingBufferSize } from '../gl/context.js';
import { setHooks } from '../shell/test_hooks.js';
import { GroveRenderer, MEMBER_FLOATS } from '../tree/grove_renderer.js';

const NEAR_M = 12;         // copies nearer than this (to the crown's middle) stay full meshes
const BAND_RATIO = 1.4;    // distance bands [d, 1.4 d), as the grove page's
const SLOTS = 256;         // the worker's hysteresis slots per group (bands 0..255)

// The worker's buffers of a 'gardenAtlas' or 'gardenDrawLists' reply as recycle's groups.
const atlasGroups = (atlases) => Object.fromEntries((atlases || []).flatMap((a, g) => ['bark', 'leaves', 'flowers'].map((p) => [`atlas${g}.${p}`, a[p]])));
const listGroups = (lists) => Object.fromEntries((lists || []).flatMap((l, i) => [[`cards${i}`, l.cards], [`lines${i}`, l.lines]]));

// The angle of the horizontal vector (x, z) in turn()'s sense (shaders/common/turn.glsl).
const angleOf = (x, z) => Math.atan2(-z, x);

export class GardenHybrid {
  // worker: the page's WorkerClient; frame: its Frame; full(): its GardenRenderer; camera: its
  // OrbitCamera; select, info: the Trees select and its line; request(): a frame.
  constructor({ worker, frame, full, camera, select, info, request }) {
    Object.assign(this, { worker, frame, full, camera, select, info, request });
    this.mode = select.value === 'hybrid' ? 'hybrid' : 'full';
    this.layer = null;      // the GroveRenderer layer (its mode 'hybrid')
    this.groups = null;     // bounds.groups of the garden on screen
    this.year = 0;
    this.run = 0;           // the worker's runGrows of the garden on screen
    this.atlases = false;   // the atlases of this garden and year are painted
    this.keys = '';         // the band of every copy of the lists on screen (or asked)
    this.pending = null;    // {tag, start, lists, mask}
    this.dirty = false;
    this.tag = 0;
    this.serial = 0;
    this.barkShown = true;  // false: the atlases in the plain bark brown (a test's A/B, showBark)
    worker.on('gardenAtlas', (msg) => this.#atlas(msg));
    worker.on('gardenDrawLists', (msg) => this.#lists(msg));
    select.addEventListener('change', () => this.setMode(select.value));
    this.#hooks({ hybridSerial: 0, hybridPending: 0 });
    // trees: false times the frame without any tree (the ground, objects and ivy: its fixed cost).
    window.__niwaGardenFrameMs = async (n, { trees = true } = {}) => {
      if (trees) return (await this.frame.timeFrames(n)).ms;  // web/gl/frame.js
      const full = this.full(), kept = full?.trees, only = this.layer?.only;
      if (full) full.trees = null;
      if (this.layer) this.layer.only = -1;
      try {
        return (await this.frame.timeFrames(n)).ms;
      } finally {
        if (full) full.trees = kept;
        if (this.layer) this.layer.only = only;
        this.request();
      }
    };
  }

  async init() {
    this.layer = await this.frame.addLayer(new GroveRenderer(this.frame));
    this.layer.mode = 'hybrid';
  }

  setMode(mode) {
    this.mode = mode === 'hybrid' ? 'hybrid' : 'full';
    this.select.value = this.mode;
    this.#reset();
    if (this.mode === 'hybrid') this.#ask();
    this.request();
  }

  // A garden (or another year of it) on screen: bounds (the worker's boundsJson), its year and
  // the worker's runGrows. Its trees are drawn full until its hybrid lists are in.
  garden(bounds, year, run) {
    this.groups = bounds?.groups || null;
    this.year = year;
    this.run = run;
    this.#reset();
    if (this.mode === 'hybrid') this.#ask();
  }

  // The simulated bark on the atlases (true) or the plain brown (a test's A/B of one view): in
  // hybrid mode a change repaints them (a new round).
  showBark(on) {
    if (this.barkShown === Boolean(on)) return;
    this.barkShown = Boolean(on);
    if (this.mode !== 'hybrid') return;
    this.#reset();
    this.#ask();
  }

  // Blow's poses (Float32Array, 16 floats a node point of every copy, the worker's 'pose') and each
  // copy's first pose block in the instances' order (the 'blowing' skin's blocks): each distinct
  // tree's copies' poses into its cards' pose texture. A tree whose node points are not the
  // wind's (another year's hybrid scene) stays at rest. The near copies sway in the full renderer.
  setPoses(poses, firstBlocks, totalBlocks) {
    const trees = this.full()?.trees;
    if (this.mode !== 'hybrid' || !this.atlases || !trees || !this.layer) return;
    let swayed = 0;
    trees.groups.forEach((g, k) => {
      const t = this.layer.trees[k];
      if (!t || g.instances === 0) return;
      const first = firstBlocks[g.firstInstance];
      const next = k + 1 < trees.groups.length ? firstBlocks[trees.groups[k + 1].firstInstance] : totalBlocks;
      if (t.instances !== g.instances || (next - first) !== t.instances * t.nodes) return;
      this.layer.setPoses(k, poses.subarray(first * 16, next * 16));
      swayed += 1;
    });
    this.swaying = swayed > 0;
    this.#hooks({ hybridSwayed: swayed });
  }

  // Blow stopped: every card at rest again.
  still() {
    if (!this.swaying || !this.layer) return;
    this.swaying = false;
    this.layer.trees.forEach((t, k) => this.layer.setRestPoses(k));
    this.#hooks({ hybridSwayed: 0 });
  }

  // The worker could not build the hybrid scenes (its error record): full again, with its line.
  failed(msg) {
    this.setMode('full');
    this.info.textContent = `Hybrid trees: ${msg.message}`;
  }

  // After every frame drawn: a copy in another band asks for a new round.
  drawn() {
    setHooks({ drawnHybridSerial: this.mode === 'hybrid' ? this.serial : 0 });
    if (this.mode !== 'hybrid' || !this.atlases) return;
    if (this.pending) {
      this.dirty = true;
      return;
    }
    const plan = this.#plan();
    if (plan && plan.keys !== this.keys) this.#round(plan);
  }

  #hooks(extra = {}) {
    setHooks({ treesMode: this.mode, ...extra });
  }

  #reset() {
    this.atlases = false;
    this.keys = '';
    this.pending = null;
    this.dirty = false;
    this.mask = null;
    this.layer?.clearTrees();
    this.full()?.setFull(null);
    this.info.textContent = this.mode === 'hybrid' ? `Copies farther than ${NEAR_M} m: the cards and lines of the thesis's hybrid rendering (ch. 4, as the grove page), one draw list per distinct tree and distance band; nearer ones full. Blow sways both.` : '';
    this.#hooks({ hybridTrees: 0, fullTrees: '' });
  }

  #ask() {
    if (!this.groups || !this.groups.length || !this.layer) return;
    this.#hooks({ hybridPending: 1 });
    this.worker.post('hybrid', { year: this.year, grows: this.run });
  }

  #atlas(msg) {
    if (this.mode !== 'hybrid' || msg.run !== this.run || msg.year !== this.year || !this.layer) {
      this.worker.recycle(atlasGroups(msg.atlases));
      return;
    }
    this.layer.clearTrees();
    // A distinct tree in simulated bark (bark 1): its cards' bark painted from its base colour map
    // (the full trees' texture, GardenRenderer.barks; the worker's atlas uvs wrap its tile).
    const barks = this.barkShown ? this.full()?.barks || [] : [];
    let barkTrees = 0, atlasTriangles = 0;
    const sides = new Map();
    const groups = this.full()?.trees?.groups || [];
    const paintStart = performance.now();
    msg.atlases.forEach((hybrid, g) => {
      for (const part of ['bark', 'leaves', 'flowers']) atlasTriangles += (hybrid[part]?.indices?.byteLength || 0) / 12;
      sides.set(hybrid.atlasSize, (sides.get(hybrid.atlasSize) || 0) + 1);
      const bark = barks[g] ? { bark: { texture: barks[g].colour } } : null;
      if (bark) barkTrees += 1;
      // Its copies' pose blocks (at rest until Blow's poses come: setPoses).
      this.layer.addCards(g, hybrid, bark, groups[g]?.instances || 1, hybrid.nodes || 1);
    });
    this.swaying = false;
    this.worker.recycle(atlasGroups(msg.atlases));
    this.atlases = true;
    // the atlases' triangles painted (each distinct tree's whole geometry, once) and the page's time
    // to queue them (the GPU's own time follows in the next frame)
    this.#hooks({ hybridBarkTrees: barkTrees, hybridAtlasTriangles: atlasTriangles, hybridAtlasMs: (performance.now() - paintStart).toFixed(0),
      hybridAtlasSides: [...sides].map(([side, n]) => `${side}:${n}`).join(',') });
    const plan = this.#plan();
    if (plan) this.#round(plan);
  }

  // Every copy's band (null: drawn full) and the (group, band) lists with their members.
  #plan() {
    const trees = this.full()?.trees;
    if (!trees || !this.groups) return null;
    const eye = this.camera.position();
    const lists = new Map();
    const mask = new Uint8Array(trees.instanceData.length / 4);
    const keys = [];
    trees.groups.forEach((g, group) => {
      const lift = this.groups[group]?.crown ?? 2;  // the crown's middle, about a crown radius up
      for (let k = g.firstInstance; k < g.firstInstance + g.instances; ++k) {
        const [x, y, z, turn] = trees.instanceData.subarray(k * 4, k * 4 + 4);
        const d = Math.hypot(eye[0] - x, eye[1] - (y + lift), eye[2] - z);
        if (d < NEAR_M) {
          mask[k] = 1;
          keys.push('f');
          continue;
        }
        const band = Math.max(0, Math.min(SLOTS - 1, Math.floor(Math.log(d) / Math.log(BAND_RATIO)) + 3));
        const key = `${group}:${band}`;
        keys.push(key);
        if (!lists.has(key)) lists.set(key, { tree: group, band, members: [] });
        lists.get(key).members.push({ x, y, z, turn, d, copy: k - g.firstInstance });
      }
    });
    return { keys: keys.join(','), lists: [...lists.values()], mask };
  }

  #round(plan) {
    const [width, height] = drawingBufferSize(this.frame.canvas, this.layer.scale || 1);
    const eye = this.camera.position(), target = this.camera.target;
    const views = [];
    for (const list of plan.lists) {
      list.members.sort((a, b) => a.d - b.d);
      const rep = list.members[0];
      // The camera in the representative copy's own frame: moved to its foot, turned back.
      const local = (p) => {
        const v = [p[0] - rep.x, p[1] - rep.y, p[2] - rep.z];
        const c = Math.cos(-rep.turn), s = Math.sin(-rep.turn);
        return [c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2]];
      };
      const seen = angleOf(eye[0] - rep.x, eye[2] - rep.z);
      const members = new Float32Array(list.members.length * MEMBER_FLOATS);
      list.members.forEach((m, i) => {
        const turn = rep.turn + angleOf(eye[0] - m.x, eye[2] - m.z) - seen;
        members.set([m.x, m.y, m.z, 1, rep.d / m.d, m.copy, turn], i * MEMBER_FLOATS);
      });
      list.members = members;
      views.push({ group: list.tree, slot: list.band, camera: { eye: local(eye), target: local(target), fovY: this.camera.fov, width, height } });
    }
    this.pending = { tag: ++this.tag, start: performance.now(), lists: plan.lists, mask: plan.mask, keys: plan.keys };
    this.keys = plan.keys;
    this.#hooks({ hybridPending: 1 });
    this.worker.post('hybridViews', { tag: this.tag, light: [...this.frame.light], bark: this.barkShown, views });
  }

  #lists(msg) {
    const pending = this.pending;
    if (!pending || msg.tag !== pending.tag || msg.run !== this.run || this.mode !== 'hybrid') {
      this.worker.recycle(listGroups(msg.lists));
      return;
    }
    msg.lists.forEach((l, i) => Object.assign(pending.lists[i], { cards: l.cards, lines: l.lines }));
    this.layer.setBands(pending.lists);
    this.full().setFull(pending.mask);
    this.mask = pending.mask;  // the copies drawn full now (1) or as cards and lines (0)
    this.worker.recycle(listGroups(msg.lists));
    this.pending = null;
    this.serial += 1;
    let full = 0;
    for (const m of pending.mask) full += m;
    this.#hooks({ hybridSerial: this.serial, hybridPending: 0, hybridMs: (performance.now() - pending.start).toFixed(0), fullTrees: full, hybridTrees: pending.mask.length - full });
    this.request();
    if (this.dirty) {
      this.dirty = false;
      this.drawn();
    }
  }
}
