// Node test (no Chromium) of the pages' frame pacing (issue 16): web/gl/frame_loop.js keeps one
// frame in flight (a fence per frame; no draw until it signals, unless the request is urgent);
// web/gl/frame_governor.js lowers and restores the quality from frame
// latencies and measures the budget of web/gl/progressive_frame.js (a frame drawn in parts);
// web/ivy/ivy_renderer.js's birthCounter against its brute-force twin (a sort).
// Also a fence whose status is cached as Chromium caches it (read between animation frames).
// node tests/browser/frame_pacing.test.mjs
import { check, finish } from './harness.mjs';

// A fake animation-frame clock and WebGL2 fences the test signals by hand.
const frameQueue = [];
globalThis.requestAnimationFrame = (f) => frameQueue.push(f);
const tick = () => frameQueue.splice(0).forEach((f) => f(performance.now()));
const fences = [];
const gl = {
  SYNC_GPU_COMMANDS_COMPLETE: 1, SYNC_STATUS: 2, SIGNALED: 3, UNSIGNALED: 4,
  fenceSync() { const f = { signaled: false }; fences.push(f); return f; },
  getSyncParameter(f) { return f.signaled ? this.SIGNALED : this.UNSIGNALED; },
  deleteSync() {}, flush() {}, isContextLost: () => false,
};

const { FrameLoop } = await import('../../web/gl/frame_loop.js');
const { FrameGovernor, LEVELS } = await import('../../web/gl/frame_governor.js');
const { ProgressiveFrame } = await import('../../web/gl/progressive_frame.js');
const { birthCounter } = await import('../../web/ivy/ivy_renderer.js');

// ---- One frame in flight.
{
  let draws = 0;
  const governed = [];
  const loop = new FrameLoop(() => { draws += 1; }, { gl, governor: { frameDone: (ms) => governed.push(ms) } });
  loop.request();
  tick();
  check('a requested frame is drawn at the next animation frame', draws === 1 && fences.length === 1, `${draws} draws`);
  loop.request();
  tick();
  tick();
  check('no new frame while the last one has not finished on the GPU', draws === 1 && loop.stats.skippedBusy === 2 && loop.busy(),
    `${draws} draws, ${loop.stats.skippedBusy} skipped`);
  fences[0].signaled = true;
  tick();
  check('the wanted frame is drawn once the fence signals, and its latency goes to the governor',
    draws === 2 && governed.length === 1 && governed[0] >= 0, `${draws} draws, latencies ${governed.join(',')}`);
  fences[1].signaled = true;
  tick();
  check('an unrequested frame is not drawn (frames on demand)', draws === 2 && !loop.busy() && frameQueue.length === 0, `${draws} draws`);

  // An urgent request (Still) is drawn at the next animation frame, the last fence or not.
  loop.request();
  tick();
  check('(a frame in flight)', draws === 3 && loop.busy());
  loop.request(true);
  tick();
  check('an urgent request does not wait for the frame in flight', draws === 4, `${draws} draws`);
  fences.at(-1).signaled = true;
  tick();
}

// ---- A fence's status as Chromium reports it: a read returns the cached status and, at most once
// per return to the event loop, asks for the real one, which lands in the cache a task later. The
// loop reads a busy fence between animation frames while a frame is wanted, so the first animation
// frame after the GPU finished draws it (before, that frame read the stale status and the wanted
// frame waited one more animation frame: 100-150 ms on SwiftShader).
{
  const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
  const cachedGl = {
    ...gl,
    fenceSync() { const f = { done: false, cached: false, asking: false }; fences.push(f); return f; },
    getSyncParameter(f) {
      if (!f.asking) {
        f.asking = true;
        const real = f.done;
        setTimeout(() => { f.cached = real; f.asking = false; }, 0);
      }
      return f.cached ? this.SIGNALED : this.UNSIGNALED;
    },
  };
  let draws = 0;
  const loop = new FrameLoop(() => { draws += 1; }, { gl: cachedGl });
  loop.request();
  tick();
  await sleep(10);
  tick();  // the fence read once in an animation frame: still on the GPU
  loop.request();
  fences.at(-1).done = true;  // the GPU finishes between animation frames
  // Until the loop's own read between frames has brought the real status into the cache (a loop
  // that reads only in animation frames never does: the check below then fails after 2 s). Not a
  // fixed sleep: at load 11 a 30 ms one ended before the loop's read came round (1 draw).
  for (const t0 = Date.now(); !fences.at(-1).cached && Date.now() - t0 < 2000;) await sleep(5);
  tick();
  check('with a cached fence status, the wanted frame is drawn at the first animation frame after the GPU finished',
    draws === 2, `${draws} draws, ${loop.stats.skippedBusy} skipped`);
  fences.at(-1).done = true;
  await sleep(10);
  tick();
  await sleep(10);
  tick();
}

// ---- The governor: slow moving frames get cheaper, fast ones better, still ones full.
{
  let stills = 0;
  const g = new FrameGovernor({ targetMs: 100, stillMs: 80, onStill: () => { stills += 1; } });
  check('still: full quality', g.quality().level === 0 && g.quality().scale === 1);
  g.frameDone(500);
  check('a slow still frame does not lower the quality', g.quality().level === 0);
  g.motion();
  check('but the motion after it starts 1 + floor(log2 5) = 3 levels down', g.quality().level === 3 && g.motionCheap() === LEVELS[3].cheap,
    `level ${g.quality().level}`);
  g.reset();
  const levels = [];
  for (let i = 0; i < LEVELS.length + 1; ++i) {
    levels.push(g.quality().level);
    g.frameDone(150);
  }
  const last = LEVELS.length - 1;
  check('moving frames 1.5 x too slow lower the level one step at a time, to the last',
    levels.join(',') === [...Array(LEVELS.length).keys(), last].join(','), levels.join(','));
  g.reset();
  g.quality();
  g.frameDone(1700);
  check('a moving frame 17 x too slow skips 1 + floor(log2 17) = 5 levels', g.quality().level === 5, `level ${g.quality().level}`);
  const up = [];
  for (let i = 0; i < 5; ++i) {
    g.frameDone(10);
    up.push(g.quality().level);
  }
  check('fast moving frames step back up one level each, never to a level measured slow (0)', up.join(',') === '4,3,2,1,1',
    up.join(','));
  g.frameDone(60);
  check('a frame between a third of the target and the target keeps its level', g.quality().level === 1);

  // Cheap levels need the renderer's cheaper representation: without it, the last level without.
  g.reset();
  g.quality();
  g.frameDone(1700);  // wants level 5 (cheap)
  const capped = g.quality(0);
  check('a cheap level without the cheap representation is drawn as the last level without it',
    capped.cheap === 0 && capped.level === 2 && capped.wantCheap > 0, JSON.stringify(capped));
  g.frameDone(1700);
  check('and its slow frame does not move the level (it waits for the representation)', g.quality(Infinity).level === 5,
    `level ${g.quality(Infinity).level}`);

  await new Promise((resolve) => setTimeout(resolve, 150));
  check('once still, onStill asks for the full frame and it is level 0', stills === 1 && g.quality().level === 0 && g.quality().scale === 1,
    `${stills} onStill calls, level ${g.quality().level}`);
  g.motion();
  check('the next motion starts at the level learned', g.quality().level === 5);
  g.stop();
  check('stop(): full quality at once', g.quality().level === 0);
}

// ---- A frame in parts: the same draws, in the same order, within the budget per call.
{
  const log = [];
  const step = (name, primitives) => ({
    primitives,
    setup: () => log.push(`setup ${name}`),
    draw: (first, n) => log.push(`${name} ${first}+${n}`),
  });
  const frame = new ProgressiveFrame();
  frame.start([step('ground', 0), step('bark', 250), step('leaves', 100), step('marks', 0)]);
  const calls = [];
  while (frame.pending()) calls.push(frame.run(120));
  const ranges = log.filter((l) => !l.startsWith('setup')).join(', ');
  check('a frame in parts draws every primitive once, in order, at most the budget per call',
    ranges === 'ground 0+0, bark 0+120, bark 120+120, bark 240+10, leaves 0+100, marks 0+0' &&
      calls.map((c) => c.primitives).join(',') === '120,120,110' && calls.at(-1).done && !calls[0].done,
    `${ranges}; per call ${calls.map((c) => c.primitives).join(',')}`);
  check('each resumed step is set up again', log.filter((l) => l === 'setup bark').length === 3, log.join('; '));
  log.length = 0;
  frame.start([step('bark', 250)]);
  const whole = frame.run();
  check('without a budget the frame is drawn at once', whole.done && log.join(',') === 'setup bark,bark 0+250', log.join(','));
  frame.start([step('bark', 250)]);
  frame.run(1);
  frame.abort();
  check('abort drops a frame in parts', !frame.pending() && frame.run(10).primitives === 0);
  // retire: a layer's old objects are deleted only once no frame in progress can bind them.
  const released = [];
  frame.retire(() => released.push('idle'));
  frame.start([step('bark', 250)]);
  frame.run(100);
  frame.retire(() => released.push('finished'));
  const held = released.join(',');
  frame.run(100);
  const beforeEnd = released.join(',');
  frame.run(100);
  frame.start([step('bark', 250)]);
  frame.run(100);
  frame.retire(() => released.push('aborted'));
  frame.abort();
  frame.start([step('bark', 250)]);
  frame.run(100);
  frame.retire(() => released.push('replaced'));
  frame.start([step('bark', 250)]);
  check('retire deletes at once when idle, and otherwise when the frame in parts finishes, is aborted or replaced',
    held === 'idle' && beforeEnd === 'idle' && released.join(',') === 'idle,finished,aborted,replaced', `${held}; ${beforeEnd}; ${released.join(',')}`);
}

// ---- The governor's budget: the measured rate times the target.
{
  const g = new FrameGovernor({ targetMs: 100, firstBudget: 5000 });
  check('the first budget before any measurement', g.budget() === 5000);
  g.quality();
  g.drew(50_000, true);
  g.frameDone(200);
  check('after a draw of 50,000 primitives in 200 ms: 250 per ms, 25,000 per 100 ms', Math.abs(g.budget() - 25_000) < 1, `${g.budget()}`);
  g.motion();
  g.quality();
  g.drew(25_000, false, 400_000);
  g.frameDone(100);
  check('a moving frame 16 budgets big is judged slow at its first part (1 + log2 16 = 5 levels)',
    g.quality().level === 5, `level ${g.quality().level}`);
  g.stop();
}

// ---- The sun's shadow map is redrawn by still frames only (moving ones reuse it): a still frame
// is judged for the motion level without its shadow pass (drew's `once`).
{
  const g = new FrameGovernor({ targetMs: 100, firstBudget: 50_000 });
  g.quality();
  g.drew(50_000, false, 180_000, 90_000);  // 90 k of the tree + 90 k into the shadow map, in parts
  g.frameDone(100);
  g.motion();
  check('a still frame of 90 k primitives plus a 90 k shadow pass, in parts: the motion starts at full quality (90 k is not governed)',
    g.quality().level === 0, `level ${g.quality().level}`);
  g.stop();
  g.reset();
  g.quality();  // the same frame without the shadow pass counted apart
  g.drew(50_000, false, 180_000);
  g.frameDone(100);
  g.motion();
  check('... counted whole it would be judged slow (180 k over a 50 k budget: 1 + floor(log2 3.6) = 2 levels)',
    g.quality().level === 2, `level ${g.quality().level}`);
  g.stop();
  g.reset();
  // The frames' times on a clock the test moves (the governor reads performance.now()): a busy
  // wait of 240 ms took over 400 ms when the suite's other lane held the cores (one failure in a
  // full run, 2026-12-07), which judged the frame by the machine's load instead of the rule.
  const realNow = performance.now.bind(performance);
  let fakeMs = realNow();
  let judged, judgedSlow;
  performance.now = () => fakeMs;
  try {
    g.quality();
    fakeMs += 60;  // a whole still frame of 60 ms
    g.drew(400_000, true, 400_000, 300_000);  // a quarter of it moves
    g.frameDone(60);
    g.motion();
    judged = g.quality().level;
    g.stop();
    g.reset();
    g.quality();
    fakeMs += 240;  // four times as long, the same primitives
    g.drew(400_000, true, 400_000, 300_000);
    g.frameDone(240);
    g.motion();
    judgedSlow = g.quality().level;
    g.stop();
  } finally {
    performance.now = realNow;
  }
  check('a whole still frame is judged by its time times the share moving frames draw again (60 ms x 1/4 fast, 240 ms x 1/4 = 60 ms fast, not 240 ms slow)',
    judged === 0 && judgedSlow === 0, `levels ${judged}, ${judgedSlow}`);
}

// ---- birthCounter against the sort it replaces (whole steps and fractional ones).
{
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) >>> 0) / 2 ** 32);
  for (const fractional of [false, true]) {
    const vertices = 3000, triangles = 5000;
    const birth = new Float32Array(vertices).map(() => (fractional ? random() * 40 : Math.floor(random() * 40)));
    const indices = new Uint32Array(3 * triangles).map(() => Math.floor(random() * vertices));
    const count = birthCounter(indices, birth);
    const sorted = Array.from({ length: triangles }, (_, t) => birth[indices[3 * t]]).sort((a, b) => a - b);
    let bad = 0;
    for (const k of [-1, -0.3, 0, 0.4, 1, 7, 17.5, 39, 40, 100, Infinity]) {
      if (count(k) !== sorted.filter((b) => b <= k + 0.5).length) bad += 1;
    }
    check(`birthCounter matches the brute-force count (${fractional ? 'fractional' : 'whole'} birth steps)`, bad === 0, `${bad} of 11 steps differ`);
  }
}
finish();
