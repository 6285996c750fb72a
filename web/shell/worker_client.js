// The pages' side of the worker protocol (web/worker/protocol.js): one shared module worker per
// page, and per client (the tree page, each grove tree, each <niwa-tree>) request ids, supersede
// and promise replies. Every page and the embed talk to the worker through this file only.
// Does not: know any study's messages beyond their envelope {type, id, client}, retry, or time out.

const WORKER_URL = new URL('../worker/worker.js', import.meta.url);

let shared = null;  // {worker, clients: Map(name -> WorkerClient)}
const closing = new Map();  // id of a 'close' -> its resolve (the client is gone from `clients`)
let shared0 = null;  // the clients kept across restartWorker until the next worker is made

// The page's one worker (created on first use). From another origin (the embed on a foreign page)
// a one-line module shim imports it, since a worker script must be same-origin.
function sharedWorker() {
  if (shared) return shared;
  const url = WORKER_URL;
  const worker = url.origin === location.origin
    ? new Worker(url, { type: 'module' })
    : new Worker(URL.createObjectURL(new Blob([`import ${JSON.stringify(url.href)};`], { type: 'text/javascript' })), { type: 'module' });
  shared = { worker, clients: shared0?.clients || new Map() };
  shared0 = null;
  worker.onmessage = (event) => {
    const msg = event.data || {};
    if (msg.type === 'closed' && closing.has(msg.id)) {
      closing.get(msg.id)(msg);
      closing.delete(msg.id);
      return;
    }
    shared.clients.get(typeof msg.client === 'string' ? msg.client : 'app')?.deliver(msg);
  };
  worker.onerror = (e) => {
    e.preventDefault();
    const text = `The simulation worker failed to start${e.message ? `: ${e.message}` : ''}.`;
    for (const client of shared.clients.values()) client.failed(text);
  };
  return shared;
}

// Cancel (issue 16): ends the page's worker at once, whatever it is computing, and starts a fresh
// one. Every pending request of every client resolves to null and its late replies are dropped;
// each client gets onRestart() and must send its init (and its last good state) again.
export function restartWorker() {
  if (!shared) return;
  shared.worker.terminate();
  for (const resolve of closing.values()) resolve(null);  // the worker and all it kept are gone
  closing.clear();
  shared0 = { clients: shared.clients };
  shared = null;
  sharedWorker();
  for (const client of shared.clients.values()) client.restarted();
}

let nextId = 0;  // ids are unique across the page's clients

export class WorkerClient {
  // name: the protocol's client string (unique on the page); study: the worker handler its
  // messages go to (omitted: the worker's default, 'tree'); onFailure(text): the worker failed.
  constructor(name, { study, onFailure, onRestart } = {}) {
    this.name = name;
    this.study = study;
    this.onRestart = onRestart || (() => {});
    this.handlers = new Map();  // type -> handler(msg)
    this.pending = new Map();   // id -> {group, done: Set of reply types, resolve}
    this.latest = new Map();    // group -> newest id
    this.onFailure = onFailure || (() => {});
    this.isClosed = false;
    const { clients } = sharedWorker();
    if (clients.has(name)) throw new Error(`worker client '${name}' exists already`);
    clients.set(name, this);
  }

  // Calls handler(msg) for every current message of `type` (superseded replies never arrive).
  on(type, handler) {
    this.handlers.set(type, handler);
    return this;
  }

  // Sends {type, client, ...fields} without expecting a reply (transfer: ArrayBuffers to move).
  post(type, fields = {}, transfer = []) {
    if (this.isClosed) return;  // closed: the worker has let this client go
    const envelope = this.study ? { type, client: this.name, study: this.study } : { type, client: this.name };
    sharedWorker().worker.postMessage({ ...fields, ...envelope }, transfer);
  }

  // Hands a reply's buffers back to the worker once they are on the GPU (the protocol's "buffers
  // transferred and reused"): groups {group: {name: view or ArrayBuffer}} go as {"group.name":
  // ArrayBuffer} in a message of `type` (default 'recycle'), transferred; the worker's next reply
  // copies into them (web/worker/transfer.js TransferPool). The caller must not read them after.
  // Returns the number of buffers sent.
  recycle(groups, type = 'recycle') {
    const buffers = {}, transfer = [];
    eachBuffer(groups, (key, buffer) => {
      buffers[key] = buffer;
      transfer.push(buffer);
    });
    if (transfer.length > 0) this.post(type, { buffers }, transfer);
    return transfer.length;
  }

  // Sends a request with a fresh id; a newer request of the same `group` supersedes it (its later
  // replies are dropped and its promise resolves to null). Resolves to the first reply whose type
  // is in `done` (or an 'error' with this id). transfer: ArrayBuffers of `fields` moved to the
  // worker, not copied (the caller must not read them after). Returns {id, reply}.
  request(type, fields = {}, { group = type, done = [], transfer = [] } = {}) {
    if (this.isClosed) return { id: 0, reply: Promise.resolve(null) };
    const id = ++nextId;
    const superseded = this.latest.get(group);
    if (superseded !== undefined) this.#settle(superseded, null);
    this.latest.set(group, id);
    let resolve;
    const reply = new Promise((r) => { resolve = r; });
    this.pending.set(id, { group, done: new Set([...done, 'error']), resolve });
    this.post(type, { ...fields, id }, transfer);
    return { id, reply };
  }

  // The newest id of `group` (0 before any request).
  latestId(group) {
    return this.latest.get(group) || 0;
  }

  // Drops every pending request of `group` (their replies are ignored from now on).
  cancel(group) {
    const id = this.latest.get(group);
    if (id !== undefined) this.#settle(id, null);
    this.latest.delete(group);
  }

  // Unregisters the client (its replies are dropped; its name is free again at once; later posts
  // and requests do nothing, a request resolving to null) and tells the worker, whose handlers let
  // the client's sessions and returned buffers go. Resolves to the worker's {type: 'closed',
  // released: {study: {sessions, buffers}}} (null if the worker restarted or it was closed already).
  close() {
    if (this.isClosed) return Promise.resolve(null);
    this.isClosed = true;
    for (const id of [...this.pending.keys()]) this.#settle(id, null);
    const { worker, clients } = sharedWorker();
    clients.delete(this.name);
    const id = ++nextId;
    const reply = new Promise((resolve) => closing.set(id, resolve));
    worker.postMessage({ type: 'close', id, client: this.name });
    return reply;
  }

  deliver(msg) {
    const entry = msg.id === undefined ? null : this.pending.get(msg.id);
    // A reply with an id this client no longer waits for: superseded or cancelled.
    if (msg.id !== undefined && !entry && this.#wasRequested(msg.id)) return;
    this.handlers.get(msg.type)?.(msg);
    if (entry && entry.done.has(msg.type)) this.#settle(msg.id, msg);
  }

  failed(text) {
    this.onFailure(text);
  }

  // After restartWorker: every pending request resolves to null, then onRestart().
  restarted() {
    for (const id of [...this.pending.keys()]) this.#settle(id, null);
    this.latest.clear();
    this.onRestart();
  }

  // Ids come from this page's counter: any id at most nextId that is not pending was settled.
  #wasRequested(id) {
    return Number.isInteger(id) && id > 0 && id <= nextId;
  }

  #settle(id, value) {
    const entry = this.pending.get(id);
    if (!entry) return;
    this.pending.delete(id);
    entry.resolve(value);
  }
}

// Calls fn("group.name", ArrayBuffer) for each buffer of recycle-style groups ({group: {name: view
// or ArrayBuffer}}), skipping empty and detached buffers and a buffer named twice (one transfer each).
function eachBuffer(groups, fn) {
  const seen = new Set();
  for (const [group, parts] of Object.entries(groups || {})) {
    for (const [name, value] of Object.entries(parts || {})) {
      const buffer = ArrayBuffer.isView(value) ? value.buffer : value;
      if (!(buffer instanceof ArrayBuffer) || buffer.byteLength === 0 || seen.has(buffer)) continue;
      seen.add(buffer);
      fn(`${group}.${name}`, buffer);
    }
  }
}

// The ArrayBuffers of recycle-style groups, each once: a postMessage transfer list (the tree page
// hands the worker's replies on to its render worker with it, web/tree/tree_view.js).
export function buffersOf(groups) {
  const out = [];
  eachBuffer(groups, (key, buffer) => out.push(buffer));
  return out;
}

// Every buffer of a tree reply (its mesh parts, and treeExtras) as recycle's groups.
export function treeGroups(msg) {
  const { bark, leaves, flowers } = msg?.mesh || {};
  return { bark, leaves, flowers, ...treeExtras(msg) };
}

// A tree reply's ('tree': web/worker/tree_handler.js) buffers beside its mesh parts, as recycle's
// groups: the textures' pixels ("textures.bark", ...) and the hybrid atlas ("atlas.bark.*", ...).
export function treeExtras(msg) {
  const t = msg?.mesh?.textures || {};
  const textures = Object.fromEntries(['bark', 'barkNormal', 'leaf', 'flower'].map((kind) => [kind, t[kind]?.pixels]));
  return { textures, ...atlasGroups(msg?.hybrid) };
}

// A hybrid card atlas's buffers (a tree reply's `hybrid`, or a 'motionAtlas' reply's) as recycle's
// groups ("atlas.bark", ...), for the worker's next atlas to fill; {} for none.
export function atlasGroups(hybrid) {
  return hybrid ? { 'atlas.bark': hybrid.bark, 'atlas.leaves': hybrid.leaves, 'atlas.flowers': hybrid.flowers } : {};
}
