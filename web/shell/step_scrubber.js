// A step scrubber with Play for pages that replay a growth already computed (each vertex carries
// its birth step, e.g. ivy's _BIRTH_STEP): a range input 0..max, a text "k of max", and a Play
// button that advances one step per `interval` ms and stops at the end. onStep(k) is called for
// every change; nothing is regrown.
// Does not: draw (the page shows what was born at or before k), or keep history.

export class StepScrubber {
  // ui: {range: <input type=range>, text: <output>, play: <button>}; onStep(k).
  constructor({ range, text, play }, onStep, { interval = 120 } = {}) {
    this.ui = { range, text, play };
    this.onStep = onStep;
    this.interval = interval;
    this.timer = 0;
    this.max = 0;
    range.addEventListener('input', () => {
      this.stop();
      this.#show(Number(range.value));
    });
    play.addEventListener('click', () => (this.timer ? this.stop() : this.play()));
  }

  // A new growth of `max` steps: the scrubber moves to its end (the full growth).
  reset(max) {
    this.stop();
    this.max = Math.max(0, Math.floor(max));
    this.ui.range.max = String(this.max);
    this.#show(this.max);
  }

  get value() {
    return Number(this.ui.range.value);
  }

  // Shows step k (clamped to [0, max]).
  set(k) {
    this.stop();
    this.#show(k);
  }

  play() {
    if (this.value >= this.max) this.#show(0);
    this.ui.play.setAttribute('aria-pressed', 'true');
    this.ui.play.textContent = 'Pause';
    this.timer = setInterval(() => {
      if (this.value >= this.max) {
        this.stop();
        return;
      }
      this.#show(this.value + 1);
    }, this.interval);
  }

  stop() {
    if (!this.timer) return;
    clearInterval(this.timer);
    this.timer = 0;
    this.ui.play.setAttribute('aria-pressed', 'false');
    this.ui.play.textContent = 'Play';
  }

  #show(k) {
    const step = Math.max(0, Math.min(this.max, Math.round(Number(k) || 0)));
    this.ui.range.value = String(step);
    this.ui.text.textContent = `step ${step} of ${this.max}`;
    this.onStep(step);
  }
}
