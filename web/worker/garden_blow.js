// The garden's Blow in the worker (web/worker/garden_handler.js; GardenLab's blow* calls in
// web/bindings/garden_bindings.cpp over core/compose/garden_wind): a 'wind' {play: true, wind?}
// starts one sway simulator per planted tree of the client's last garden (wind: the wind rows
// over the garden's defaults) and answers {type: 'blowing', skin: {joints, weights, blocks}, blocks,
// dt, speed, stepsPerTick, run} (the trees' sway skin, copied once and transferred), or an error
// with control: 'wind'; then, by the wall clock, at most stepsPerTick steps a tick (the page sway's
// rules: a tick within the page's tick estimate), and one {type: 'pose', time, wind (m/s at the
// garden's centre), stepMs, poses} at a time, the latest step's: the next is sent after the page's
// 'poseDone' (this one is drawn), into the poses buffer the page handed back ('recycle' {wind:
// {poses}}) when it fits. At the wind's duration it starts again from rest. {play: false}, a grow or a year picked
// stops it (the lab's blowStop).
// Does not: grow, mesh or draw anything, or catch errors (web/worker/worker.js does).
import { errorOf, errorReply } from './errors.js';

export function createBlow({ post, returned, labOf }) {
  const blows = new Map();  // client -> {lab, start, steps, waiting, timer}

  function stop(client) {
    const blow = blows.get(client);
    if (!blow) return;
    clearTimeout(blow.timer);
    blows.delete(client);
    blow.lab.blowStop();
  }

  function start(msg, client) {
    stop(client);
    const { lab } = labOf(client);
    const wind = JSON.stringify(msg.wind && typeof msg.wind === 'object' ? msg.wind : {});
    const error = errorOf(lab.blowStart(wind));
    if (error) {  // control: the page shows it beside Blow
      post(errorReply(error, msg.id, client, { control: 'wind' }));
      return;
    }
    const transfer = [], buffers = { reused: 0, fresh: 0, dropped: 0 };
    const skin = returned.take(client, 'skin', lab.buffers('skin'), transfer, buffers);
    post({ type: 'blowing', id: msg.id, client, run: lab.runGrows(), skin, blocks: lab.blowBlocks(), dt: lab.blowDt(),
      speed: lab.blowSpeed(), stepsPerTick: lab.blowStepsPerTick(), buffers }, transfer);
    const blow = { lab, wind, start: performance.now(), steps: 0, time: 0, stepMs: 0, fresh: false, waiting: false, timer: 0 };
    blows.set(client, blow);
    tick(client, blow);
  }

  // The wind follows the wall clock whether or not the page has drawn the last pose: at most
  // stepsPerTick steps a tick (the clock slips when the worker cannot keep up), and the poses of
  // the latest step are sent when the page is ready for them (a slow frame skips poses, not time).
  function tick(client, blow) {
    if (blows.get(client) !== blow) return;
    const { lab } = blow;
    if (lab.blowBlocks() === 0) {  // the lab stopped it (a grow finished: its trees are gone)
      stop(client);
      return;
    }
    const dt = lab.blowDt();
    const due = Math.floor((performance.now() - blow.start) / (1000 * dt)) - blow.steps;
    if (due > 0 || blow.steps === 0) {
      const most = lab.blowStepsPerTick();
      const n = Math.max(1, Math.min(due, most));
      const started = performance.now();
      blow.time = lab.blowStep(n);
      blow.stepMs = (performance.now() - started) / n;  // per step, every tree
      blow.steps += n;
      blow.fresh = true;
      if (due > most) blow.start += (due - most) * 1000 * dt;  // too slow: the clock slips, no pile-up
      if (blow.time >= lab.blowDuration()) {  // the wind's schedule is over: again from rest
        lab.blowStart(blow.wind);
        blow.start = performance.now();
        blow.steps = 0;
        blow.time = 0;
      }
    }
    if (!blow.waiting && blow.fresh) {
      const transfer = [], buffers = { reused: 0, fresh: 0 };
      const { poses } = returned.take(client, 'wind', lab.buffers('wind'), transfer, buffers);
      blow.waiting = true;
      blow.fresh = false;
      post({ type: 'pose', client, time: blow.time, wind: lab.blowWindSpeed(), stepMs: blow.stepMs, speed: lab.blowSpeed(), poses, buffers }, transfer);
    }
    blow.timer = setTimeout(() => tick(client, blow), 8);
  }

  function poseDone(client) {
    const blow = blows.get(client);
    if (blow) blow.waiting = false;
  }

  return { start, stop, poseDone };
}
