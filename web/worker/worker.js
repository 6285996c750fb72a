// Niwa's Web Worker (ES module worker): a small router over the WASM core. It loads the one
// module (niwa_web), keeps the clients apart (a newer update of a client supersedes its older one),
// dispatches each message to its study's handler (msg.study, default 'tree') and answers any
// failure with one error envelope. One worker and one WASM instance serve every client on a page.
// Protocol (init, then update messages; buffers transferred, never copied twice): ./protocol.js.
// Does not: know any study's messages (web/worker/<study>_handler.js do).
const MODULE_URL = new URL('../../wasm/niwa_web.js', import.meta.url).href;

// A study's handler is the module ./<study>_handler.js, loaded on its first message: its
// createHandler(Module, ctx) returns {superseding, ready(msg), messages: {type: fn(msg, client)},
// close(client)}. Adding a study adds that file; nothing here changes.
// A client's end ('close', web/shell/worker_client.js close(): an embed taken off its page) goes to
// every study's handler loaded so far: each lets the client's sessions and returned buffers go
// (close(client) -> {sessions, buffers}), and the router answers {type: 'closed', released:
// {study: what its handler let go}}.
const STUDY_NAME = /^[a-z][a-z_]{0,31}$/;

let modulePromise = null;
const handlers = new Map();  // study -> promise of its handler (created once the module is loaded)
const latest = new Map();    // client -> id of its newest superseding request

function loadModule() {
  if (!modulePromise) {
    modulePromise = import(MODULE_URL).then((factory) =>
      factory.default({
        locateFile: (file) => new URL(file, MODULE_URL).href,
        print: () => {},
        printErr: () => {},
      }));
  }
  return modulePromise;
}

// The module is fetched and compiled as soon as the worker starts (streaming, while the page still
// loads its own modules and sends init), not on the first message (issue 17 item 7). A failure is
// answered to the first message that needs the module.
loadModule().catch(() => {});

// Options from the worker's URL: ?warmup=0 turns the tree handler's warm-up grow off, ?warmup=N
// grows N years (bench/worker_first_grow.mjs compares them).
const options = Object.fromEntries(new URL(self.location.href).searchParams);

const ctx = {
  post: (msg, transfer = []) => postMessage(msg, transfer),
  isLatest: (client, id) => latest.get(client) === id,
  options,
};

async function handlerFor(study) {
  if (!handlers.has(study)) {
    if (!STUDY_NAME.test(study)) throw new Error(`unknown study '${study.slice(0, 40)}': must be a lower-case name`);
    const loaded = import(`./${study}_handler.js`).then(
      async (module) => module.createHandler(await loadModule(), ctx),
      () => { throw new Error(`unknown study '${study}': no web/worker/${study}_handler.js`); });
    handlers.set(study, loaded);
    loaded.catch(() => handlers.delete(study));
  }
  return handlers.get(study);
}

const messageOf = (e) => String(e && e.message ? e.message : e);

self.onmessage = async (event) => {
  const msg = event.data || {};
  const client = typeof msg.client === 'string' ? msg.client : 'app';
  const study = typeof msg.study === 'string' ? msg.study : 'tree';
  try {
    if (typeof msg.type !== 'string' || !msg.type) throw new Error(`unknown message type '${String(msg.type).slice(0, 40)}'`);
    if (msg.type === 'close') {
      const released = {};
      for (const [name, loaded] of handlers) {
        const handler = await loaded.catch(() => null);
        if (handler?.close) released[name] = handler.close(client);
      }
      latest.delete(client);
      postMessage({ type: 'closed', id: msg.id, client, released });
      return;
    }
    const handler = await handlerFor(study);
    if (msg.type === 'init') {
      postMessage({ type: 'ready', id: msg.id, client, study, ...handler.ready(msg) });
      return;
    }
    const run = Object.hasOwn(handler.messages, msg.type) ? handler.messages[msg.type] : null;
    if (!run) throw new Error(`study '${study}' has no message '${msg.type.slice(0, 40)}'`);
    if (handler.superseding.includes(msg.type)) latest.set(client, msg.id);
    await run(msg, client);
  } catch (e) {
    postMessage({ type: 'error', id: msg.id, client, message: `worker: ${messageOf(e)}` });
  }
};
