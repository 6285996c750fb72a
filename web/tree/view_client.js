// The tree page's side of its view (tree_view.js): the canvas handed to the render worker
// (render_worker.js) with transferControlToOffscreen when that worker can make a WebGL2 context on
// an OffscreenCanvas, else the same TreeView on the main thread (one renderer either way). Messages
// go both ways as in tree_view.js; with the worker, buffers in `transfer` move (never copied), on
// the main thread they are handed over as they are. Each direction keeps its order, and a message
// is delivered in a later task or microtask, never inside send(). tree_view.js (the renderer and
// the GL toolkit) is loaded on the main thread only for the fallback.
// Does not: know the view's messages, or start the growth worker.
const WORKER_URL = new URL('./render_worker.js', import.meta.url);

export class ViewClient {
  // canvas: the page's view; onMessage(msg): the view's messages; init: the 'init' message's
  // fields ({css, dpr, shadows}). mode: 'starting', then 'worker' or 'main' ('off': the fallback's
  // module did not load).
  constructor(canvas, onMessage, init) {
    this.canvas = canvas;
    this.onMessage = onMessage;
    this.mode = 'starting';
    this.waiting = [];  // [msg, transfer] sent before the mode was known
    this.local = null;
    this.worker = null;
    let worker = null;
    if (typeof OffscreenCanvas !== 'undefined' && typeof canvas.transferControlToOffscreen === 'function') {
      try {
        worker = new Worker(WORKER_URL, { type: 'module' });
      } catch {
        worker = null;
      }
    }
    if (!worker) {
      this.#onMain(init);
      return;
    }
    worker.onerror = (e) => {  // the module failed to load: draw on the main thread
      e.preventDefault();
      if (this.mode === 'starting') {
        worker.terminate();
        this.#onMain(init);
      }
    };
    worker.onmessage = (event) => {
      const msg = event.data || {};
      if (msg.type !== 'probe') {
        this.onMessage(msg);
        return;
      }
      if (!msg.webgl2) {
        worker.terminate();
        this.#onMain(init);
        return;
      }
      const offscreen = canvas.transferControlToOffscreen();
      worker.postMessage({ ...init, type: 'init', canvas: offscreen }, [offscreen]);
      this.worker = worker;
      this.mode = 'worker';
      this.#flush();
    };
    worker.postMessage({ type: 'probe' });
  }

  // The view on the main thread (no OffscreenCanvas WebGL2 in a worker here); messages wait while
  // its module loads.
  async #onMain(init) {
    let TreeView;
    try {
      ({ TreeView } = await import('./tree_view.js'));
    } catch (e) {
      this.onMessage({ type: 'failed', message: `the view's module did not load (${e.message})` });
      this.mode = 'off';
      this.waiting = [];
      return;
    }
    this.local = new TreeView(this.canvas, (type, fields = {}) => {
      const msg = { ...fields, type };
      queueMicrotask(() => this.onMessage(msg));
    });
    this.mode = 'main';
    this.local.handle({ ...init, type: 'init' });
    this.#flush();
  }

  #flush() {
    const waiting = this.waiting;
    this.waiting = [];
    for (const [msg, transfer] of waiting) this.#deliver(msg, transfer);
  }

  #deliver(msg, transfer) {
    if (this.worker) this.worker.postMessage(msg, transfer);
    else queueMicrotask(() => this.local.handle(msg));
  }

  // Sends {type, ...fields} to the view; transfer: ArrayBuffers of fields that move with it (the
  // caller must not read them after).
  send(type, fields = {}, transfer = []) {
    const msg = { ...fields, type };
    if (this.mode === 'starting') this.waiting.push([msg, transfer]);
    else if (this.mode !== 'off') this.#deliver(msg, transfer);
  }
}
