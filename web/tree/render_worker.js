// The tree page's render worker (module worker): owns the view's WebGL2 context on the canvas the
// page transferred (transferControlToOffscreen) and draws the tree there (tree_view.js), so
// WebGL's start, the shader links and every draw call leave the main thread (issue 32 item 5: the
// context's start was a 1.7 s main-thread task on SwiftShader). First message 'probe': answers
// {type: 'probe', webgl2} (whether an OffscreenCanvas in a worker can make a WebGL2 context; the
// page falls back to drawing on the main thread when not); then 'init' with the canvas, then the
// view's messages (tree_view.js). Replies are the view's messages.
// Does not: grow trees (the growth worker, web/worker/worker.js, does), or touch the DOM.
import { webgl2Available } from '../gl/context.js';
import { TreeView } from './tree_view.js';

// The view's messages of one task go as one 'batch' (the page applies them in one task, as when it
// drew itself: a test's observer of data-frame-partial sees the stats line of the same frame); a
// message with buffers to transfer goes at once, after those before it.
let batch = [];
function post(type, fields = {}, transfer = []) {
  const msg = { ...fields, type };
  if (transfer.length === 0) {
    if (batch.length === 0) queueMicrotask(flush);
    batch.push(msg);
    return;
  }
  flush();
  self.postMessage(msg, transfer);
}
function flush() {
  if (batch.length === 0) return;
  self.postMessage({ type: 'batch', messages: batch });
  batch = [];
}

let view = null;
self.onmessage = (event) => {
  const msg = event.data || {};
  if (msg.type === 'probe') {
    self.postMessage({ type: 'probe', webgl2: webgl2Available() });
    return;
  }
  if (msg.type === 'init') {
    view = new TreeView(msg.canvas, post);
  }
  view?.handle(msg);
};
