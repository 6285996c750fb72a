// Moving WASM buffers to the main thread: each typed view into WASM memory is copied ONCE into an
// ArrayBuffer, which is then transferred (never copied a second time). A TransferPool keeps the
// buffers a page hands back once they are on the GPU ('recycle'), per client, and the next reply
// copies into them instead of fresh ones (the protocol's "buffers transferred and reused").
// Does not: keep views (they are only valid until the next call into WASM that may allocate), or
// decide when a page is done with a buffer (the page returns it: web/shell/worker_client.js).

import { errorOf, errorReply } from './errors.js';

// Copies one WASM-memory view into a fresh typed array of its own type; returns its buffer.
export function copyView(view) {
  const out = new view.constructor(view.length);
  out.set(view);
  return out.buffer;
}

// A session's named views ({name: typed view}, as the bindings' buffers(group) returns them) as
// {name: ArrayBuffer}; every buffer is pushed onto `transfer`. Copy before any other WASM call.
export function takeBuffers(views, transfer) {
  if (!views) throw new Error('no such buffer group');
  const out = {};
  for (const [name, view] of Object.entries(views)) {
    out[name] = copyView(view);
    transfer.push(out[name]);
  }
  return out;
}

// A fresh buffer is this much bigger than its first view, so a slightly bigger mesh next time (a
// tree a year older, an ivy a few steps longer) still fits it.
export const HEADROOM = 1.125;
// A returned buffer more than SHRINK times (and 1 MB) bigger than what it would hold is dropped,
// so one huge mesh does not stay in every later reply.
export const SHRINK = 4;

// A pooled buffer that the replies of its group have not reused this many times (a part that
// stayed empty, a name no longer sent) is dropped, so the pool holds only what the next replies
// may fill, never every buffer a client once had.
export const MAX_IDLE_REPLIES = 4;
// A pooled buffer of a group that is never asked for again (the hybrid atlas after the page went
// back to full mode, the draw lists of a tree no longer in hybrid mode, a client that went silent
// without closing) is dropped this long after it was given back, at the pool's next give or take
// (of any client and group).
export const MAX_IDLE_MS = 60_000;

// Per client, the buffers its page returned, by key ("<group>.<name>", e.g. "bark.positions"),
// each with the number of its group's replies that have not reused it and the time it came back.
// A client may be any Map key (a handler's buffers shared by every client use a Symbol of its own).
export class TransferPool {
  // now(): the clock in ms (tests pass their own); maxIdleMs: see MAX_IDLE_MS.
  constructor({ now = () => performance.now(), maxIdleMs = MAX_IDLE_MS } = {}) {
    this.clients = new Map();  // client -> Map(key -> {buffer: ArrayBuffer, idle, at})
    this.now = now;
    this.maxIdleMs = maxIdleMs;
  }

  // The page's buffers back: {key: ArrayBuffer or view} (the newest one per key is kept).
  give(client, buffers) {
    const at = this.now();
    this.#expire(at);
    if (!buffers || typeof buffers !== 'object') return;
    let pool = this.clients.get(client);
    if (!pool) this.clients.set(client, (pool = new Map()));
    for (const [key, value] of Object.entries(buffers)) {
      const buffer = ArrayBuffer.isView(value) ? value.buffer : value;
      if (buffer instanceof ArrayBuffer && buffer.byteLength > 0) pool.set(String(key), { buffer, idle: 0, at });
    }
  }

  // Drops every pooled buffer (of any client) given back more than maxIdleMs before `at`; returns
  // how many.
  #expire(at) {
    let dropped = 0;
    for (const [client, pool] of this.clients) {
      for (const [key, entry] of pool) {
        if (at - entry.at <= this.maxIdleMs) continue;
        pool.delete(key);
        dropped += 1;
      }
      if (pool.size === 0) this.clients.delete(client);
    }
    return dropped;
  }

  // Like takeBuffers, but each view is copied into the client's returned buffer of key
  // "<group>.<name>" when it fits, else into a fresh one (HEADROOM bigger); the reply holds views of
  // the exact length (byteLength, not their buffer's, is the data's size), every buffer is pushed
  // onto `transfer`, and `counts` ({reused, fresh, dropped}) counts them. A returned buffer of the
  // wrong size class (too small, or over SHRINK times and 1 MB too big) is dropped; one of the group
  // that this reply did not reuse (its view empty, or its name not sent) ages by one reply and is
  // dropped after MAX_IDLE_REPLIES; any buffer given back over maxIdleMs ago is dropped first
  // (counted too). `room(view)`: the bytes of a fresh buffer for the view (at least its own;
  // default HEADROOM more).
  take(client, group, views, transfer, counts = { reused: 0, fresh: 0, dropped: 0 }, room = (view) => view.byteLength * HEADROOM) {
    if (!views) throw new Error('no such buffer group');
    const drop = () => { counts.dropped = (counts.dropped ?? 0) + 1; };
    for (let n = this.#expire(this.now()); n > 0; --n) drop();
    const pool = this.clients.get(client);
    const out = {};
    for (const [name, view] of Object.entries(views)) {
      const key = `${group}.${name}`;
      const need = view.byteLength;
      if (need === 0) {  // nothing to move (an empty part leaves its returned buffer to age)
        out[name] = new view.constructor(0);
        continue;
      }
      let buffer = pool?.get(key)?.buffer;
      pool?.delete(key);
      const fits = buffer && buffer.byteLength >= need && !(buffer.byteLength > SHRINK * need && buffer.byteLength > 1 << 20);
      if (fits) {
        counts.reused += 1;
      } else {
        if (buffer) drop();  // its size class changed: left to the garbage collector
        const size = Math.ceil(Math.max(need, room(view)) / 8) * 8;
        buffer = new ArrayBuffer(size);
        counts.fresh += 1;
      }
      const into = new view.constructor(buffer, 0, view.length);
      into.set(view);
      out[name] = into;
      transfer.push(buffer);
    }
    // The group's buffers this reply did not reuse age.
    const prefix = `${group}.`;
    for (const [key, entry] of pool ?? []) {
      if (!key.startsWith(prefix) || key.indexOf('.', prefix.length) >= 0) continue;  // another group
      entry.idle += 1;
      if (entry.idle >= MAX_IDLE_REPLIES) {
        pool.delete(key);
        drop();
      }
    }
    return out;
  }

  // Drops every buffer a client returned (it went away); returns how many.
  forget(client) {
    const n = this.clients.get(client)?.size ?? 0;
    this.clients.delete(client);
    return n;
  }

  // What the pool holds for a client: {buffers, bytes}.
  held(client) {
    let buffers = 0, bytes = 0;
    for (const { buffer } of this.clients.get(client)?.values() ?? []) {
      buffers += 1;
      bytes += buffer.byteLength;
    }
    return { buffers, bytes };
  }
}

// A handler's 'close' for one client whose session is {lab} in `labs` (a Map): the lab's progress
// callback dropped and the lab deleted, its returned buffers in `pool` forgotten. Returns what was
// let go ({sessions, buffers}) for web/worker/worker.js.
export function closeLabSession(labs, pool, client) {
  const entry = labs.get(client);
  if (entry) {
    entry.lab.setProgress(null);
    entry.lab.delete();
  }
  labs.delete(client);
  return { sessions: entry ? 1 : 0, buffers: pool.forget(client) };
}

// A handler's 'export' for a lab that builds its bytes by format (`lab.build(format)`, "" or an
// error record) into its 'download' buffer group (the moss and garden labs): a format outside
// `formats` throws (the router's error envelope), a build error is the reply, else the bytes are
// copied once and transferred as {type: 'export', id, client, format, bytes}.
export function exportLabDownload(lab, formats, msg, client, post) {
  const format = String(msg.format);
  if (!formats.includes(format)) throw new Error(`export: format '${format.slice(0, 20)}' is unknown; must be ${formats.join(', ')}`);
  const error = errorOf(lab.build(format));
  if (error) {
    post(errorReply(error, msg.id, client));
    return;
  }
  const transfer = [];
  const { bytes } = takeBuffers(lab.buffers('download'), transfer);
  post({ type: 'export', id: msg.id, client, format, bytes }, transfer);
}
