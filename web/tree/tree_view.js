// The tree page's drawing, wherever it runs: the WebGL2 context (a Frame, web/gl/frame.js), the tree
// renderer (tree_renderer.js) as its layer, the frame loop and governor (one frame in flight; cheaper
// frames while the view moves; big frames in parts that never replace the last finished frame with
// nothing), the hybrid and motion draw lists asked of the growth worker, the sway's poses, picking
// and the frame timing. It runs in the render worker (render_worker.js, on the canvas the page
// transferred with transferControlToOffscreen: WebGL's start, shader links and draw calls off the
// main thread, issue 32 item 5) or, where a browser cannot draw WebGL2 in a worker, on the main
// thread (view_client.js): one module, one renderer, the same messages either way.
// Messages in (handle): init {css: [w, h], dpr, shadows}, resize {css, dpr}, camera {state},
// frame {urgent, whole}, tree, pose, drawList, motionAtlas (the growth worker's replies, forwarded
// by the page with their buffers transferred), select {id}, pick {x, y}, sun {elevation, azimuth,
// urgent}, shadows {on}, wind {play}, motionOff, time {frames}, cancelTiming, png, finish.
// Messages out (post(type, fields, transfer)): ready, failed {message}, lost, hooks {fields},
// bump {key}, table {method, arg}, worker {message, fields} (to the growth worker), recycle {groups}
// (buffers back to the growth worker), drawn {serial} (a finished frame of that tree), picked {id},
// timed {result}, png {blob}, finished.
// Does not: touch the DOM, keep the page's state (history, panel, selection's meaning), handle
// input (the page's orbit camera posts its state), or talk to the growth worker but through post.
import { OrbitCamera } from '../gl/orbit_camera.js';
import { Frame } from '../gl/frame.js';
import { FrameGovernor } from '../gl/frame_governor.js';
import { FrameLoop } from '../gl/frame_loop.js';
import { finishGpu } from '../gl/context.js';
import { viewOf } from '../gl/buffers.js';
import { atlasGroups, buffersOf, treeGroups } from '../shell/worker_client.js';
import { LatestRequest } from '../shell/latest_request.js';
import { Renderer } from './tree_renderer.js';

export class TreeView {
  // canvas: an HTMLCanvasElement (main thread) or an OffscreenCanvas (the render worker; its CSS size
  // and the device pixel ratio come in init and resize); post(type, fields, transfer): to the page.
  constructor(canvas, post) {
    this.canvas = canvas;
    this.post = post;
    this.camera = new OrbitCamera();
    this.frame = null;
    this.renderer = null;
    this.starting = true;     // until start() has a renderer or has failed
    this.failed = false;
    this.queue = [];          // messages that came while the renderer started
    this.sun = null;          // [elevation, azimuth] asked for
    this.shadows = true;
    this.windPlaying = false;
    this.treeSerial = 0;
    this.poseDrawPending = false;
    this.frameDirty = true;
    this.wholeNext = false;   // the next frame is drawn whole, not in parts
    this.freshNext = false;   // the next frame starts anew (a new selection)
    this.frameLevel = -1;     // the governor's level of the frame in parts
    this.poseAtFrameStart = 0;
    this.swayTimeAtFrameStart = 0;
    this.viewsReceived = 0;   // hybrid draw lists installed
    this.viewsAtFrameStart = 0;
    this.hybridOn = false;
    // The hybrid and motion draw lists: one request each in flight, the newest camera wins.
    this.viewRequest = new LatestRequest(() => this.toWorker('view', { camera: this.renderer.viewFor(this.camera) }));
    this.motionRequest = new LatestRequest(() => this.toWorker('view',
      { camera: this.renderer.viewFor(this.camera), motion: true, atlas: !this.renderer.hasMotionAtlas() }));
    this.motionOff = false;
    this.timing = null;       // {cancelled} while a timing runs
    this.reuse = {};
    // One frame in flight on the GPU (web/gl/frame_loop.js); while the tree sways or the camera
    // moves, the governor draws cheaper frames when they lag, and the full one once all is still.
    this.governor = new FrameGovernor({ onStill: () => this.requestFrame() });
    this.frames = new FrameLoop(() => this.#draw(), { governor: this.governor });
  }

  hooks(fields) {
    this.post('hooks', { fields });
  }

  toWorker(type, fields = {}, transfer = []) {
    this.post('worker', { message: type, fields }, transfer);
  }

  // Buffers back to the growth worker (through the page's worker client) for its next reply.
  recycle(groups) {
    const transfer = buffersOf(groups);
    if (transfer.length) this.post('recycle', { groups }, transfer);
  }

  requestFrame(urgent = false, whole = false) {
    if (!this.renderer) return;
    this.frameDirty = true;
    this.wholeNext ||= whole;
    this.frames.request(urgent);
  }

  // One message from the page.
  handle(msg) {
    if (msg.type === 'init') {
      this.#size(msg);
      this.shadows = msg.shadows !== false;
      this.#start();
      return;
    }
    if (msg.type === 'resize') {
      this.#size(msg);
      this.requestFrame();
      this.requestView();
      return;
    }
    if (msg.type === 'camera') {  // the page's orbit camera moved (or was framed on a tree)
      Object.assign(this.camera, msg.state);
      // withTree: the tree that follows asks for the frame (a frame of the old tree with the new
      // camera, drawn between the two messages, held the new tree's frame back and came after it
      // in the drawn years: phone.test's Play saw 6, 0, 1, ...).
      if (msg.withTree) return;
      if (!msg.moved) return this.requestFrame();
      this.governor.motion();
      this.requestFrame();
      this.requestView();
      if (this.renderer?.motionReady()) this.requestMotionView();  // its draw list is for the last camera
      return;
    }
    if (this.failed) return this.#drop(msg);
    if (this.starting) {
      // While WebGL starts (a slow first shader compile) the messages wait; of the trees only the
      // last (the others' buffers go back at once), and poses are answered at once.
      if (msg.type === 'tree') {
        this.queue = this.queue.filter((m) => (m.type === 'tree' ? (this.#drop(m), false) : true));
      } else if (msg.type === 'pose' || msg.type === 'drawList' || msg.type === 'motionAtlas') {
        return this.#drop(msg);
      }
      this.queue.push(msg);
      return;
    }
    const on = this[`on_${msg.type}`];
    if (on) on.call(this, msg);
  }

  // A message that will not be drawn: its buffers go back, a pose is answered.
  #drop(msg) {
    if (msg.type === 'tree') this.recycle(treeGroups(msg));
    else if (msg.type === 'pose') {
      this.recycle({ sway: { poses: msg.poses } });
      this.toWorker('poseDone');
    } else if (msg.type === 'motionAtlas') {
      this.recycle(atlasGroups(msg.hybrid));
    } else if (msg.type === 'drawList') {
      if (msg.motion) this.motionRequest.done();
      else this.viewRequest.done();
    } else if (msg.type === 'pick') {
      this.post('picked', { id: null });
    } else if (msg.type === 'png') {
      this.post('png', { blob: null });
    } else if (msg.type === 'time') {
      this.post('timed', { result: null });
    } else if (msg.type === 'finish') {
      this.post('finished');
    }
  }

  // The canvas's CSS size and the device pixel ratio (drawingBufferSize reads them): an
  // OffscreenCanvas has neither, so the page sends them.
  #size({ css, dpr }) {
    if (!css || typeof HTMLCanvasElement !== 'undefined' && this.canvas instanceof HTMLCanvasElement) return;
    this.canvas.clientWidth = css[0];
    this.canvas.clientHeight = css[1];
    globalThis.devicePixelRatio = dpr;
  }

  async #start() {
    try {
      this.frame = new Frame(this.canvas, { camera: this.camera, what: 'the tree', request: () => this.requestFrame() });
      await this.frame.init();
      this.frame.setShadows(this.shadows);
      this.renderer = await this.frame.addLayer(new Renderer(this.frame));
      this.frames.attach(this.frame.gl);
      this.canvas.addEventListener?.('webglcontextlost', (e) => {
        e.preventDefault();
        this.post('lost');
      });
      this.post('ready');
    } catch (e) {
      this.renderer = null;
      this.failed = true;
      this.post('failed', { message: e.message });
    }
    this.starting = false;
    const queued = this.queue;
    this.queue = [];
    for (const msg of queued) this.handle(msg);
    this.requestFrame();
  }

  // ---- the frame (the page's FrameLoop callback before the render worker)
  #draw() {
    const { renderer, frame, governor } = this;
    // While a big tree goes up in parts the canvas keeps its last frame (no draw: a frame of the old
    // big tree costs seconds on a CPU GL, and every part's upload would wait for it).
    if (renderer.uploading) return false;
    if (this.poseDrawPending) governor.motion();  // a new pose to draw: moving, however long the last frame took
    // (a hybrid-mode tree is cheap already: its levels only shrink the drawing buffer)
    const cheapAvailable = this.hybridOn || renderer.motionReady() ? Infinity : 0;
    const next = governor.peek(cheapAvailable);
    if (next.wantCheap > 0 && !renderer.motionReady()) this.requestMotionView();
    // Swaying, the cheaper representation on its way and a full frame too big for one animation
    // frame: no full frame meanwhile (the canvas keeps the last one; the GPU paints the atlas), the
    // sway goes on.
    if (this.windPlaying && next.moving && next.capped && !this.motionOff && renderer.fullPrimitives() > governor.budget()) {
      frame.progress.abort();  // a full frame in parts would only hold the atlas back
      this.#poseShown();
      return false;
    }
    const resume = frame.progress.pending() && next.level === this.frameLevel && !this.wholeNext && !this.freshNext;
    let quality = null;
    let whole = false;
    if (!resume) {
      this.viewsAtFrameStart = this.viewsReceived;
      this.poseAtFrameStart = renderer.poseSerial;
      this.swayTimeAtFrameStart = renderer.swaying ? renderer.swayTime : 0;
      this.freshNext = false;
      quality = governor.quality(cheapAvailable);
      this.frameLevel = quality.level;
      this.frameDirty = false;
      whole = this.wholeNext;
      this.wholeNext = false;
    }
    // A camera drag without the cheaper representation: each frame at once (smaller), as it moves;
    // an edit that must show at once (the sun): one whole frame, however long it takes.
    const dragging = next.moving && next.capped && !this.windPlaying;
    const drawn = frame.render(this.camera, quality, { budget: dragging || whole ? Infinity : governor.budget(), resume });
    if (!drawn) return false;
    governor.drew(drawn.drawnPrimitives, !drawn.partial, drawn.primitives, drawn.shadowPrimitives);
    const stats = this.frames.stats;
    this.hooks({ frameScale: frame.scale, frameMode: drawn.mode, framesDrawn: stats.drawn,
      framesSkipped: stats.skippedBusy, frameGpuMs: Math.round(stats.gpuMs), framePartial: drawn.partial ? 1 : 0 });
    if (drawn.partial) {
      if (drawn.mode !== 'motion') this.post('table', { method: 'showPartial', arg: drawn });
      this.frames.request();  // the rest of this frame
      return true;
    }
    if (this.frameDirty) this.frames.request();  // what changed while the frame was drawn in parts
    this.#poseShown();
    if (drawn.mode !== 'motion') this.post('table', { method: 'showFrame', arg: drawn });
    // tests wait for the new tree's frame, and for the frame that shows a new selection
    this.post('drawn', { serial: this.treeSerial });
    this.hooks({ drawnTreeSerial: this.treeSerial, drawnYear: this.shownYear, drawnSelection: drawn.selected ?? -1,
      drawnMode: drawn.mode, drawnViews: this.viewsAtFrameStart,
      // the sun's shadow map in this frame: 'drawn' (redrawn), 'reused' or 'off'; maps drawn so far
      drawnShadow: drawn.shadow, shadowPasses: frame.shadowMap?.passes ?? 0,
      // the poses this frame was started with, and the latest (equal: the pose on screen is the latest)
      drawnPose: this.poseAtFrameStart, latestPose: renderer.poseSerial, drawnSwayTime: this.swayTimeAtFrameStart.toFixed(3) });
    this.post('bump', { key: 'framesShown' });  // finished frames (the orbit frame time of tests/browser/no_blank_frames)
    return true;
  }

  // The worker sends the next pose once this one is on screen.
  #poseShown() {
    if (!this.poseDrawPending) return;
    this.poseDrawPending = false;
    this.toWorker('poseDone');
  }

  // Hybrid mode: the worker chooses card or line per branch for each view (eq. 4.1 with
  // hysteresis); one request at a time, the newest camera wins.
  requestView() {
    if (!this.hybridOn || !this.renderer) return;
    this.viewRequest.request();
  }

  // A full-mode tree's cheaper representation while it moves (the governor's cheap levels): its
  // hybrid scene from the worker ('view' with motion: true; the atlas once per tree), one request
  // at a time, the newest camera wins; none when the worker cannot build it for this tree.
  requestMotionView() {
    if (this.hybridOn || !this.renderer || this.motionOff) return;
    this.motionRequest.request();
  }

  #countReuse(kind, buffers) {
    const r = (this.reuse[kind] ||= { reused: 0, fresh: 0 });
    r.reused += buffers?.reused || 0;
    r.fresh += buffers?.fresh || 0;
    this.hooks({ [`${kind}BuffersReused`]: r.reused, [`${kind}BuffersFresh`]: r.fresh });
  }

  // ---- messages (after the renderer is up)
  on_frame(msg) {
    this.requestFrame(Boolean(msg.urgent), Boolean(msg.whole));
  }

  // A grown tree: {mesh, bounds, swayNodes, hybrid (its atlas or null), hybridOn, leafLength,
  // serial, selected (kept, or null), year}. Once on the GPU (or dropped), its buffers go back.
  on_tree(msg) {
    const renderer = this.renderer;
    const installed = renderer.setTree(msg.mesh, msg.bounds, msg.swayNodes, msg.hybrid);
    // A big mesh is installed a few tasks later (uploaded in parts): a draw list that arrives
    // before then finds no hybrid tree and is dropped, so the view is asked for again once the
    // tree is in place.
    const later = renderer.uploading;
    installed.then((done) => {
      this.recycle(treeGroups(msg));
      if (done) this.governor.reset();  // another tree: its frames cost what they cost
      if (done && later) this.requestView();
      this.requestFrame();
    });
    renderer.leafLength = msg.leafLength;
    this.hybridOn = Boolean(msg.hybridOn);
    this.viewRequest.done();
    this.motionRequest.done();
    this.motionOff = false;
    this.post('table', { method: 'showHybridCounts', arg: null });
    this.requestView();
    this.treeSerial = msg.serial;
    this.shownYear = msg.year;
    this.on_select({ id: msg.selected });
    this.requestFrame();
  }

  on_motionAtlas(msg) {
    this.#countReuse('motion', msg.buffers);
    // Painted (or dropped): its buffers go back for the worker's next atlas to fill.
    const giveBack = () => this.recycle(atlasGroups(msg.hybrid));
    this.renderer.setMotionHybrid(msg.hybrid, this.governor.budget()).then((painted) => {
      giveBack();
      if (painted) this.hooks({ motionTextured: this.renderer.motion.hybrid.textured.join(',') });  // tests
      if (this.governor.moving()) this.requestFrame();
    });
  }

  on_drawList(msg) {
    if (msg.motion) {
      this.motionRequest.done();
      this.renderer.setMotionDrawList(msg);
      if (this.governor.moving()) this.requestFrame();
      if (this.motionRequest.wanted) this.requestMotionView();
      return;
    }
    this.viewRequest.done();
    if (!this.hybridOn) return;
    this.renderer.setDrawList(msg);
    this.viewsReceived += 1;
    // Uploaded: the list's buffers go back for the worker's next draw list to fill.
    this.recycle({ cards: msg.cards, lines: msg.lines });
    this.#countReuse('view', msg.buffers);
    this.post('table', { method: 'showHybridCounts', arg: msg.stats });
    this.requestFrame(true);  // a hybrid frame is cheap: the new list at once, not after the frame in flight
    if (this.viewRequest.wanted) this.requestView();
  }

  on_pose(msg) {
    const renderer = this.renderer;
    if (!this.windPlaying || renderer.uploading) return this.#drop(msg);  // no poses for a tree not yet in place
    renderer.setPoses(viewOf(Float32Array, msg.poses), msg.wind, msg.time);
    // Uploaded: the poses buffer goes back for the worker's next pose to fill.
    this.recycle({ sway: { poses: msg.poses } });
    this.#countReuse('pose', msg.buffers);
    this.governor.motion();
    this.poseDrawPending = true;
    this.requestFrame();
  }

  on_select(msg) {
    this.renderer.select(Number.isInteger(msg.id) ? msg.id : null);
    // A frame in parts begun before the click has the old selection's steps (no x-ray pass for the
    // new branch): drop it and start one with the new highlight, instead of finishing it first.
    this.freshNext = true;
    this.requestFrame();
  }

  on_pick(msg) {
    this.post('picked', { id: this.renderer.pick(this.camera, msg.x, msg.y) });
  }

  on_sun(msg) {
    this.renderer.setSun(msg.elevation, msg.azimuth);
    if (msg.urgent) this.requestFrame(true, true);  // the new light at once, before the regrown tree
  }

  // A changed Sun shadows choice: one whole frame at once. The same choice again (the page sends
  // the link's value once the growth worker has decoded it, usually while the view starts, and the
  // tree arrives then too) draws nothing: a whole frame asked for then became the first tree's
  // frame, drawn on the canvas at once instead of in parts in the offscreen target, whose
  // multisampling the canvas lacks on a CPU rasteriser (render.test's SSIM 0.846 against 0.854).
  on_shadows(msg) {
    if (Boolean(msg.on) === this.frame.shadows) return;
    this.frame.setShadows(msg.on);
    this.requestFrame(true, true);
  }

  on_wind(msg) {
    this.windPlaying = Boolean(msg.play);
    // The still frames were slow: the sway will want the cheaper representation, asked for first.
    if (this.windPlaying && this.governor.motionCheap() > 0 && !this.renderer.motionReady()) this.requestMotionView();
    if (!this.windPlaying) {
      this.governor.stop();  // the rest shape at full quality, at once
      this.renderer.setRestPoses(this.renderer.poseNodes);
      this.requestFrame(true);
    }
  }

  // The worker cannot build a cheaper representation for this tree: full frames only.
  on_motionOff() {
    this.motionOff = true;
    this.motionRequest.done();
  }

  // Frame time with the GPU's work included (web/gl/frame.js timeFrames); cancelTiming stops it.
  async on_time(msg) {
    const run = { cancelled: false };
    this.timing = run;
    try {
      const result = await this.frame.timeFrames(msg.frames || 10, { cancelled: () => run.cancelled });
      this.post('timed', { result: { ...result } });
    } finally {
      if (this.timing === run) this.timing = null;
      this.requestFrame();
    }
  }

  on_cancelTiming() {
    if (this.timing) this.timing.cancelled = true;
  }

  // The view as a PNG: a whole frame drawn now, then the canvas's pixels (the drawing buffer is
  // preserved) as a Blob.
  async on_png() {
    this.frame.render(this.camera);
    let blob = null;
    try {
      if (this.canvas.convertToBlob) blob = await this.canvas.convertToBlob({ type: 'image/png' });
      else blob = await new Promise((resolve) => this.canvas.toBlob(resolve, 'image/png'));
    } catch {
      blob = null;
    }
    this.post('png', { blob });
  }

  // Answers once the GPU has finished everything drawn so far (tests wait on it).
  on_finish() {
    finishGpu(this.frame.gl);
    this.post('finished');
  }
}
