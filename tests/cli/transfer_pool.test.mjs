// web/worker/transfer.js TransferPool under node (no module, no browser): a reply's views are
// copied into the buffers the client handed back when they fit (the same ArrayBuffer object comes
// back, views of the exact length), else into fresh ones with headroom; another client's buffers,
// a too-small one and a far too big one are not used (and dropped, counted); empty views take
// nothing; a pooled buffer its group's replies have not reused for MAX_IDLE_REPLIES is dropped (the
// pool does not only grow), a buffer of a group never asked for again is dropped MAX_IDLE_MS after it
// came back (whoever asks next), and forget() drops a client's.
// Run: node tests/cli/transfer_pool.test.mjs
import { check, finish } from '../support/cli_pair.mjs';
import { HEADROOM, MAX_IDLE_MS, MAX_IDLE_REPLIES, SHRINK, TransferPool, takeBuffers } from '../../web/worker/transfer.js';

const pool = new TransferPool();
const views = (n) => ({ positions: Float32Array.from({ length: 3 * n }, (_, i) => i / 7), indices: Uint32Array.from({ length: n }, (_, i) => i) });

// First reply: nothing returned yet, every buffer fresh, HEADROOM bigger, views of the exact length.
let transfer = [], counts = { reused: 0, fresh: 0 };
const first = pool.take('a', 'bark', views(100), transfer, counts);
check('the first reply is fresh', counts.fresh === 2 && counts.reused === 0 && transfer.length === 2, JSON.stringify(counts));
check('fresh views have the exact length over a buffer with headroom',
  first.positions.length === 300 && first.positions.buffer.byteLength >= Math.floor(1200 * HEADROOM) && first.positions instanceof Float32Array,
  `${first.positions.length} floats in ${first.positions.buffer.byteLength} bytes`);
check('the values are copied', first.positions[7] === Float32Array.of(1)[0] && first.indices[99] === 99);

// The page hands them back; a slightly bigger reply goes into the same buffers.
const returned = { 'bark.positions': first.positions.buffer, 'bark.indices': first.indices };
pool.give('a', returned);
transfer = [];
counts = { reused: 0, fresh: 0 };
const second = pool.take('a', 'bark', views(105), transfer, counts);
check('a reply that fits reuses the returned buffers', counts.reused === 2 && counts.fresh === 0
  && second.positions.buffer === returned['bark.positions'] && second.indices.buffer === returned['bark.indices'].buffer,
  JSON.stringify(counts));
check('reused views have the new exact length', second.positions.length === 315 && second.indices[104] === 104);
check('each buffer is taken once', transfer.length === 2 && new Set(transfer).size === 2);

// Given back again, then asked by another client or another group: not used.
pool.give('a', { 'bark.positions': second.positions.buffer });
counts = { reused: 0, fresh: 0 };
pool.take('b', 'bark', views(10), [], counts);
pool.take('a', 'leaves', views(10), [], counts);
check('another client or group does not take them', counts.reused === 0 && counts.fresh === 4, JSON.stringify(counts));

// Too small: fresh; far too big (over SHRINK times and 1 MB): dropped, fresh.
pool.give('a', { 'bark.positions': new ArrayBuffer(16) });
counts = { reused: 0, fresh: 0 };
pool.take('a', 'bark', { positions: new Float32Array(100) }, [], counts);
pool.give('a', { 'bark.positions': new ArrayBuffer(SHRINK * 4 * (1 << 20)) });
pool.take('a', 'bark', { positions: new Float32Array(1 << 18) }, [], counts);
check('a too small or far too big buffer is not used, and dropped', counts.reused === 0 && counts.fresh === 2 && counts.dropped === 2, JSON.stringify(counts));

// Empty views move nothing and keep a returned buffer for later.
const kept = new ArrayBuffer(64);
pool.give('a', { 'flowers.positions': kept });
transfer = [];
counts = { reused: 0, fresh: 0 };
const empty = pool.take('a', 'flowers', { positions: new Float32Array(0) }, transfer, counts);
const later = pool.take('a', 'flowers', { positions: new Float32Array(4) }, transfer, counts);
check('an empty view takes nothing and the buffer waits', empty.positions.length === 0 && later.positions.buffer === kept
  && counts.reused === 1 && counts.fresh === 0 && transfer.length === 1, JSON.stringify(counts));

// Aging: a part that stays empty leaves its returned buffer in the pool for MAX_IDLE_REPLIES replies
// of its group, then it is dropped; another group's replies do not age it, and a buffer given back
// again starts afresh.
const aging = new TransferPool();
const big = new ArrayBuffer(1 << 20);
aging.give('c', { 'flowers.positions': big, 'bark.positions': new ArrayBuffer(4096) });
check('the pool holds what was given', aging.held('c').buffers === 2 && aging.held('c').bytes === (1 << 20) + 4096, JSON.stringify(aging.held('c')));
counts = { reused: 0, fresh: 0, dropped: 0 };
for (let k = 0; k < 10; ++k) aging.take('c', 'leaves', { positions: new Float32Array(0) }, [], counts);
check('replies of another group do not age a buffer', aging.held('c').buffers === 2 && counts.dropped === 0, JSON.stringify(aging.held('c')));
for (let k = 1; k < MAX_IDLE_REPLIES; ++k) aging.take('c', 'flowers', { positions: new Float32Array(0) }, [], counts);
check(`kept through ${MAX_IDLE_REPLIES - 1} replies that did not reuse it`, aging.held('c').buffers === 2 && counts.dropped === 0, JSON.stringify(counts));
aging.take('c', 'flowers', { positions: new Float32Array(0) }, [], counts);
check(`dropped at the ${MAX_IDLE_REPLIES}th`, aging.held('c').buffers === 1 && aging.held('c').bytes === 4096 && counts.dropped === 1, JSON.stringify(counts));
// A name the reply no longer sends ages the same way; a buffer reused is taken out, so it never ages.
aging.give('c', { 'bark.uvs': new ArrayBuffer(64) });
for (let k = 0; k < MAX_IDLE_REPLIES; ++k) {
  const t = aging.take('c', 'bark', { positions: new Float32Array(8) }, [], counts);
  aging.give('c', { 'bark.positions': t.positions.buffer });
}
check('a name no longer sent is dropped; the reused one stays', aging.held('c').buffers === 1 && counts.dropped === 2 && counts.reused === MAX_IDLE_REPLIES,
  JSON.stringify({ held: aging.held('c'), counts }));
// Nested groups ("atlas.bark") are their own: "atlas" replies do not age them.
aging.give('c', { 'atlas.bark.positions': new ArrayBuffer(64) });
for (let k = 0; k < MAX_IDLE_REPLIES; ++k) aging.take('c', 'atlas', { x: new Float32Array(0) }, [], counts);
check('a nested group is not aged by its parent\'s replies', aging.held('c').buffers === 2, JSON.stringify(aging.held('c')));
check('forget drops a client\'s buffers', aging.forget('c') === 2 && aging.held('c').buffers === 0);

// Time: a group never asked for again (the atlas once the page left hybrid mode) ages out on the
// clock, at the next give or take of any client or group; one given back since is kept.
let clock = 0;
const timed = new TransferPool({ now: () => clock });
check('the pool\'s idle time is a minute by default', MAX_IDLE_MS === 60_000 && new TransferPool().maxIdleMs === MAX_IDLE_MS);
timed.give('d', { 'atlas.bark.positions': new ArrayBuffer(256), 'atlas.leaves.positions': new ArrayBuffer(128) });
timed.give('e', { 'support.positions': new ArrayBuffer(64) });
clock = MAX_IDLE_MS / 2;
timed.give('d', { 'atlas.leaves.positions': new ArrayBuffer(128) });  // given back again: its time starts afresh
counts = { reused: 0, fresh: 0, dropped: 0 };
clock = MAX_IDLE_MS;
timed.take('d', 'bark', views(4), [], counts);
check('kept up to MAX_IDLE_MS', timed.held('d').buffers === 2 && timed.held('e').buffers === 1 && counts.dropped === 0, JSON.stringify({ d: timed.held('d'), counts }));
clock = MAX_IDLE_MS + 1;
timed.take('d', 'bark', views(4), [], counts);
check('a group never asked for again is dropped after MAX_IDLE_MS, any client\'s', timed.held('d').buffers === 1
  && timed.held('d').bytes === 128 && timed.held('e').buffers === 0 && counts.dropped === 2, JSON.stringify({ d: timed.held('d'), e: timed.held('e'), counts }));
clock = 2 * MAX_IDLE_MS;
timed.give('f', {});
check('a give ages them too (nothing left)', timed.held('d').buffers === 0 && !timed.clients.has('d'), JSON.stringify(timed.held('d')));

// takeBuffers (the replies that are not pooled): one fresh buffer each, exactly the view's bytes.
transfer = [];
const plain = takeBuffers({ bytes: Uint8Array.of(1, 2, 3) }, transfer);
check('takeBuffers copies into a fresh buffer of the exact size', plain.bytes.byteLength === 3 && transfer[0] === plain.bytes);
finish();
