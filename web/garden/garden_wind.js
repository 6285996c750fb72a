// The garden page's Blow (issue 33 item 6; docs/garden-model.md "The page"): the Blow / Still
// button, the wind line, and the poses streamed from the worker (web/worker/garden_blow.js over
// core/compose/garden_wind: one sway simulator per planted tree at its place and turn, a gust front
// entering at the garden's upwind edge). The worker's 'blowing' reply brings the trees' sway skin
// (garden_renderer.js setSkin); each 'pose' is uploaded (setPoses), its buffer handed back, and
// 'poseDone' is sent once a frame with it is on screen (drawn()), so the worker sends the next one
// then. Still, a regrow (stop()) or a year picked stop the wind and draw the grown shape again.
// In hybrid mode (garden_hybrid.js) each pose also goes to the far copies' cards and lines
// (hybrid().setPoses); the near copies are the renderer's. The wind is the state's (wind(): its
// rows by key, the View's Wind rows); changed() starts a Blow under way again in a new one.
// Test hooks: data-wind (on/off), data-sway-time, data-poses-drawn, data-wind-error, and
// window.__niwaGardenSway() (per planted tree: its foot, the sum of its node points' tip offsets
// |M_j| in the last pose drawn, and whether it is drawn full).
// Does not: grow or sway anything (the worker does) or draw (the renderer does).
import { viewOf } from '../gl/buffers.js';
import { setHooks } from '../shell/test_hooks.js';

const STILL_MS = 600;  // after the governor's still time (frame_governor.js stillMs, 500 ms)
// The compass word of a wind blowing towards azimuth `deg` (0: +x, east; 90: +z, south).
const FROM = ['the west', 'the north-west', 'the north', 'the north-east', 'the east', 'the south-east', 'the south', 'the south-west'];
const fromOf = (deg) => FROM[((Math.round(Number(deg) / 45) % 8) + 8) % 8];
const stillText = (w) => (w?.wind_dir === undefined ? 'Still air.' : `Still air. Blow: a gust front crosses the garden from ${fromOf(w.wind_dir)} (towards ${w.wind_dir}°) at ${w.gust_front_speed} m/s, ${w.wind_speed} m/s behind it; each tree sways with the wind at its place.`);

export class GardenWind {
  // worker: the page's garden WorkerClient; button, info: the Blow button and the wind line;
  // renderer(): the GardenRenderer or null; moved(): a frame of a moving view (the pose changed);
  // request(): a frame (of a still view once the governor's motion is over);
  // canBlow(): '' or why not now (a past year shown: the caller shows the last); trees(): the
  // planted trees of the garden on screen (the worker's bounds.trees); hybrid(): the GardenHybrid
  // or null; wind(): the state's wind rows by key (wind_speed, wind_dir, gust_front_speed, ...).
  constructor({ worker, button, info, renderer, moved, request, canBlow, trees, hybrid, wind }) {
    Object.assign(this, { worker, button, info, renderer, moved, request, canBlow, trees, hybrid, wind });
    this.playing = false;
    this.skinned = false;   // the trees on screen carry the 'blowing' skin
    this.blocks = null;     // Float32Array: each copy's first pose block (instances' order)
    this.totalBlocks = 0;
    this.offsets = null;    // per copy: sum |M_j| of the last pose drawn
    this.waiting = false;   // a pose is uploaded, its frame not yet drawn
    this.last = null;       // {time, wind, stepMs, speed} of the last pose
    this.drawnPoses = 0;
    this.probe = null;      // offsets and time of the last pose on screen
    this.stillDue = 0;      // Still: the time after which a frame is the still view's (its shadow redrawn)
    this.stillTimer = 0;
    this.stills = 0;
    worker.on('blowing', (msg) => this.#blowing(msg));
    worker.on('pose', (msg) => this.#pose(msg));
    button.addEventListener('click', () => (this.playing ? this.stop() : this.start()));
    window.__niwaGardenSway = () => this.#probe();
    this.#show();
  }

  start() {
    const why = this.canBlow();
    if (why) {
      this.info.textContent = why;
      return;
    }
    this.playing = true;
    this.skinned = false;
    this.probe = null;
    this.last = null;
    this.stillDue = 0;
    clearTimeout(this.stillTimer);
    this.worker.post('wind', { play: true });
    this.#show();
  }

  // The state's wind changed (the View's Wind rows, set in the worker): a Blow under way starts
  // again from rest in it (the worker's Blow reads the state's wind); still air says it.
  changed() {
    if (!this.playing) {
      this.#show();
      return;
    }
    this.skinned = false;
    this.waiting = false;
    this.probe = null;
    this.last = null;
    this.worker.post('wind', { play: true });
    this.#show();
  }

  // Still (and a regrow, a year picked, a failure): the grown shape again. tell: false when the
  // worker stopped it already.
  stop(tell = true) {
    const was = this.playing;
    this.playing = false;
    this.skinned = false;
    this.waiting = false;
    if (tell && was) this.worker.post('wind', { play: false });
    this.renderer()?.still();
    this.hybrid?.()?.still();
    this.#show();
    if (!was) return;
    // The grown shape at once, and once the motion is over a still frame (the sun's shadow map is
    // redrawn only in a still frame: moving frames reuse the swaying pose's).
    this.request();
    clearTimeout(this.stillTimer);
    this.stillDue = performance.now() + STILL_MS;
    this.stillTimer = setTimeout(() => this.request(), STILL_MS);
  }

  // The worker's refusal (control: 'wind'): its line beside Blow.
  failed(msg) {
    this.stop(false);
    this.info.textContent = msg.message;
    setHooks({ windError: msg.message });
  }

  // After every finished frame: a pose drawn is acknowledged, the worker sends the next.
  drawn() {
    if (this.stillDue && !this.playing && performance.now() >= this.stillDue) {
      this.stillDue = 0;
      this.stills += 1;
      setHooks({ windStills: this.stills });  // a still frame of the grown shape after Still
    }
    if (!this.waiting) return;
    this.waiting = false;
    this.drawnPoses += 1;
    this.probe = { time: this.last.time, offsets: this.offsets };
    setHooks({ swayTime: this.last.time.toFixed(3), posesDrawn: this.drawnPoses });
    this.info.textContent = `t = ${this.last.time.toFixed(1)} s · wind ${this.last.wind.toFixed(1)} m/s at the centre · sway ${this.last.stepMs.toFixed(1)} ms/step`;
    this.worker.post('poseDone');
  }

  #blowing(msg) {
    const r = this.renderer();
    if (!this.playing || !r || !r.setSkin(msg.skin)) {
      this.worker.recycle({ skin: msg.skin });
      if (this.playing) this.stop();
      return;
    }
    this.blocks = viewOf(Float32Array, msg.skin.blocks).slice();
    this.totalBlocks = msg.blocks;
    this.skinned = true;
    this.worker.recycle({ skin: msg.skin });
    setHooks({ windError: '', windSpeed: msg.speed.toFixed(3), windStepsPerTick: msg.stepsPerTick });
  }

  #pose(msg) {
    const r = this.renderer();
    if (!this.playing || !this.skinned || !r) {  // a pose of a wind stopped here: stopped there too
      this.worker.recycle({ wind: { poses: msg.poses } });
      this.worker.post(this.playing ? 'poseDone' : 'wind', this.playing ? {} : { play: false });
      return;
    }
    const poses = viewOf(Float32Array, msg.poses);
    r.setPoses(poses, this.totalBlocks);
    this.hybrid?.()?.setPoses(poses, this.blocks, this.totalBlocks);  // the far copies' cards
    this.offsets = this.#offsets(poses);
    this.worker.recycle({ wind: { poses: msg.poses } });  // uploaded: the worker fills it again
    this.last = { time: msg.time, wind: msg.wind, stepMs: msg.stepMs, speed: msg.speed };
    this.waiting = true;
    this.moved();
  }

  // Per copy, the sum over its node points of |M_j| (the eq. 3.15 tip offsets, m).
  #offsets(poses) {
    const b = this.blocks, out = new Float64Array(b.length);
    for (let k = 0; k < b.length; ++k) {
      const end = k + 1 < b.length ? b[k + 1] : this.totalBlocks;
      let sum = 0;
      for (let j = b[k]; j < end; ++j) sum += Math.hypot(poses[j * 16 + 3], poses[j * 16 + 7], poses[j * 16 + 11]);
      out[k] = sum;
    }
    return out;
  }

  // Per planted tree (the instances' order: group by group, each group's trees in planting order):
  // its foot, its offset in the last pose on screen and whether it is drawn full (false: hybrid
  // mode's cards and lines); null before one.
  #probe() {
    if (!this.probe) return null;
    const trees = this.trees() || [];
    const order = trees.map((t, i) => ({ t, i })).sort((a, b) => a.t.group - b.t.group || a.i - b.i);
    const h = this.hybrid?.();
    const mask = h?.mode === 'hybrid' ? h.mask : null;
    return {
      time: this.probe.time,
      trees: order.map(({ t }, k) => ({ x: t.pos[0], z: t.pos[2], offset: this.probe.offsets[k] ?? null, full: mask ? Boolean(mask[k]) : true })),
    };
  }

  #show() {
    this.button.textContent = this.playing ? 'Still' : 'Blow';
    this.button.setAttribute('aria-pressed', String(this.playing));
    if (!this.playing) this.info.textContent = stillText(this.wind());
    else if (!this.last) this.info.textContent = 'starting the wind…';
    setHooks({ wind: this.playing ? 'on' : 'off', ...(this.playing ? {} : { swayTime: '' }) });
  }
}
