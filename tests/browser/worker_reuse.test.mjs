// Browser test of the worker protocol's "buffers transferred and reused, never copied twice"
// (web/worker/transfer.js TransferPool, web/shell/worker_client.js): the buffers the page hands back
// are the ones the worker's next reply fills, observed by the counts and byte lengths the worker
// reports. The tree's moving-representation atlas ('motionAtlas') handed back as the tree page does
// (atlasGroups) is refilled by the next one; the ivy's leaf texture handed back by one client is the
// buffer the next client's texture comes in; a client's end ('close', and an <niwa-ivy> taken off the
// page) makes the worker let its sessions and returned buffers go, and its name works again after.
// Run: node tests/browser/worker_reuse.test.mjs (needs build/wasm's niwa_web).
import { TIMEOUT, check, modulePage, runBrowserTest } from './harness.mjs';

const problems = [];

await runBrowserTest(async (server, browser) => {
  const page = await modulePage(server, browser, problems);

  // ---- The tree's motion atlas: asked twice (two trees of one state), handed back between.
  const tree = await page.evaluate(async () => {
    const { WorkerClient, atlasGroups } = await import('/web/shell/worker_client.js');
    const client = new WorkerClient('reuse-tree');
    const atlases = [];
    client.on('motionAtlas', (msg) => atlases.push(msg));
    const waitAtlas = (n) => new Promise((resolve) => {
      const poll = () => (atlases.length >= n ? resolve(atlases[n - 1]) : setTimeout(poll, 20));
      poll();
    });
    const camera = { eye: [0, 3, 12], target: [0, 3, 0], fovY: Math.PI / 4, width: 640, height: 480 };
    const state = { preset: 'sakura', years: 6 };
    const bytes = (hybrid) => Object.fromEntries(['bark', 'leaves', 'flowers'].flatMap((part) =>
      Object.entries(hybrid[part] || {}).filter(([, v]) => v.byteLength > 0).map(([name, v]) => [`${part}.${name}`, v.buffer.byteLength])));
    const grown = [];
    for (let k = 1; k <= 2; ++k) {
      const reply = await client.request('update', { state }, { done: ['tree'] }).reply;
      grown.push(reply?.type);
      client.post('view', { camera, motion: true, atlas: true });
      const atlas = await waitAtlas(k);
      atlases[k - 1] = { buffers: atlas.buffers, bytes: bytes(atlas.hybrid) };
      client.recycle(atlasGroups(atlas.hybrid));  // as web/tree/tree_page.js once painted
    }
    const closed = await client.close();
    // The name is free again, and the worker grows a fresh tree for it.
    const again = new WorkerClient('reuse-tree');
    const regrown = await again.request('update', { state }, { done: ['tree'] }).reply;
    const closedAgain = await again.close();
    return { grown, first: atlases[0], second: atlases[1], closed: closed?.released, regrown: regrown?.type, closedAgain: closedAgain?.released };
  });
  const given = Object.keys(tree.first.bytes).length;
  check('two trees grown, a motion atlas for each', tree.grown.join() === 'tree,tree' && given > 3,
    `${tree.grown.join()}; ${given} atlas buffers, counts ${JSON.stringify(tree.first.buffers)}`);
  check('the first motion atlas comes in fresh buffers (the reply counts them)', tree.first.buffers?.fresh === given && tree.first.buffers?.reused === 0,
    JSON.stringify(tree.first.buffers));
  const sameBytes = Object.entries(tree.first.bytes).every(([key, n]) => tree.second.bytes[key] === n);
  check('the motion atlas handed back is refilled by the next one', tree.second.buffers?.reused === given && tree.second.buffers?.fresh === 0 && sameBytes,
    `${JSON.stringify(tree.second.buffers)}; byte lengths ${JSON.stringify(tree.first.bytes)} -> ${JSON.stringify(tree.second.bytes)}`);
  check('close lets the client\'s tree session go (and its returned buffers)', tree.closed?.tree?.sessions === 1 && tree.closed.tree.buffers === given
    && tree.regrown === 'tree' && tree.closedAgain?.tree?.sessions === 1, JSON.stringify({ closed: tree.closed, regrown: tree.regrown }));

  // ---- The ivy's leaf texture: one client hands it back, the next client's comes in it.
  const ivy = await page.evaluate(async () => {
    const { WorkerClient } = await import('/web/shell/worker_client.js');
    const state = { preset: 'paper', seed: 1, steps: 10, scene: 'cubes4' };
    const sum = (view) => view.reduce((a, b) => (a + b) % 1000003, 0);
    const out = [];
    for (const name of ['reuse-ivy-1', 'reuse-ivy-2']) {
      const client = new WorkerClient(name, { study: 'ivy' });
      client.on('support', (msg) => client.recycle({ support: msg.buffers }));
      const reply = await client.request('update', { state }, { done: ['ivy'] }).reply;
      const t = reply?.leafTexture;
      const pixels = t ? new Uint8Array(t.pixels.buffer, t.pixels.byteOffset, t.pixels.byteLength) : new Uint8Array(0);
      out.push({ type: reply?.type, counts: reply?.leafTextureBuffers, bytes: pixels.buffer.byteLength, size: t ? [t.width, t.height] : null, sum: sum(pixels) });
      client.recycle(reply.mesh);
      client.recycle({ leafTexture: { pixels: t.pixels } });  // as web/ivy/ivy_page.js once uploaded
      out.at(-1).handedBack = pixels.buffer.byteLength === 0;  // transferred: detached here
      out.at(-1).released = (await client.close())?.released;
    }
    return out;
  });
  const [a, b] = ivy;
  check('each ivy client gets the leaf texture with its first ivy', a.type === 'ivy' && b.type === 'ivy' && a.size?.[0] > 0 && a.sum === b.sum,
    `${a.size?.join('x')} RGBA, checksums ${a.sum} and ${b.sum}`);
  check('the first client\'s leaf texture is a fresh buffer, handed back after', a.counts?.fresh === 1 && a.counts?.reused === 0 && a.handedBack,
    JSON.stringify(a.counts));
  check('the next client\'s leaf texture comes in the buffer handed back (no fresh one)', b.counts?.reused === 1 && b.counts?.fresh === 0 && b.bytes === a.bytes,
    `${JSON.stringify(b.counts)}, ${a.bytes} -> ${b.bytes} bytes`);
  check('close lets an ivy client\'s lab and returned buffers go', a.released?.ivy?.sessions === 1 && a.released.ivy.buffers > 0
    && b.released?.ivy?.sessions === 1, JSON.stringify(a.released));

  // ---- An <niwa-ivy> taken off the page ends its client; put back, it grows again.
  const embed = await page.evaluate(async (timeout) => {
    await import('/niwa-ivy.js');
    const element = document.createElement('niwa-ivy');
    element.setAttribute('steps', '10');
    element.style.cssText = 'width: 200px; height: 150px; display: block';
    const ready = (since) => new Promise((resolve, reject) => {
      const start = performance.now();
      const poll = () => {
        const d = element.dataset;
        if (d.status === 'ready' && d.stats && d.stats !== since) resolve(d.stats);
        else if (d.status === 'error' || performance.now() - start > timeout) reject(new Error(`status ${d.status} ${d.error || ''}`));
        else setTimeout(poll, 50);
      };
      poll();
    });
    document.body.append(element);
    const first = await ready('');
    // Moved (out and back in one task): the same client.
    const client = element.worker;
    document.body.prepend(element);
    const moved = await element.closed;
    const kept = element.worker === client && !client.isClosed;
    element.remove();
    const released = (await element.closed)?.released;
    document.body.append(element);
    element.dataset.stats = '';
    await ready('');
    return { first: Boolean(first), moved, kept, released, renewed: element.worker !== client && !element.worker.isClosed };
  }, TIMEOUT);
  check('a moved <niwa-ivy> keeps its client', embed.first && embed.moved === null && embed.kept, JSON.stringify(embed));
  check('a <niwa-ivy> taken off the page ends its client in the worker', embed.released?.ivy?.sessions === 1, JSON.stringify(embed.released));
  check('put back, it grows again with a new client', embed.renewed, JSON.stringify(embed));
  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
