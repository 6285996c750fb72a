// Niwa Web Worker (ES module worker): runs the WASM core off the main thread. One worker and one
// WASM instance serve every client on a page (the app, or several <niwa-tree> elements).
//
// Protocol: init, then update messages; buffers transferred, never copied twice.
//   in  {type:'init', hash}                  -> out {type:'ready', paramTable, presets, decoded:{state, notices}}
//   in  {type:'decode', id, hash}            -> out {type:'decoded', id, state, notices}
//   in  {type:'update', id, client, state, until}
//         grows state.years years, or only `until` years when given (the year scrubber)
//                                            -> out {type:'hash', id, client, hash}            (state accepted)
//                                               out {type:'progress', id, client, year, years} (after each year)
//                                               out {type:'tree', id, client, stats, mesh}     (ArrayBuffers transferred;
//                                                   mesh.bark also has branchIds per vertex and branchParents per branch)
//   in  {type:'export', id, client, format:'glb'|'json'}   (the client's last finished tree)
//                                            -> out {type:'export', id, client, format, bytes} (ArrayBuffer transferred)
//   any failure                              -> out {type:'error', id, client, message}
// `client` (any string, default 'app') keeps clients apart: a newer update supersedes an older one
// OF THE SAME CLIENT: the grow loop yields between years and drops itself when a newer id arrived.

const MODULE_URL = new URL('../wasm/niwa_web.js', import.meta.url).href;

let modulePromise = null;
const latest = new Map();    // client -> id of its newest update
const finished = new Map();  // client -> GrowSession of its last tree sent (for exports)

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

const yieldToEvents = () => new Promise((resolve) => setTimeout(resolve, 0));
const messageOf = (e) => String(e && e.message ? e.message : e);

// Copies one WASM-memory view ONCE into a fresh typed array whose buffer is then transferred.
function copyView(view, Type) {
  const out = new Type(view.length);
  out.set(view);
  return out.buffer;
}

function takeMesh(session, transfer) {
  const part = (name) => {
    // Each view is copied right after it is obtained, before any other call into WASM.
    const positions = copyView(session[`${name}Positions`](), Float32Array);
    const normals = copyView(session[`${name}Normals`](), Float32Array);
    const indices = copyView(session[`${name}Indices`](), Uint32Array);
    transfer.push(positions, normals, indices);
    return { positions, normals, indices };
  };
  const bark = part('bark');
  bark.branchIds = copyView(session.barkBranchIds(), Uint32Array);
  bark.branchParents = copyView(session.branchParents(), Int32Array);
  transfer.push(bark.branchIds, bark.branchParents);
  return { bark, leaves: part('leaves'), flowers: part('flowers') };
}

async function grow(id, client, state, until) {
  const Module = await loadModule();
  if (id !== latest.get(client)) return;
  let session;
  try {
    session = new Module.GrowSession(JSON.stringify(state));
  } catch (e) {
    postMessage({ type: 'error', id, client, message: messageOf(e) });
    return;
  }
  let keep = false;
  try {
    const error = session.error();
    if (error) {
      postMessage({ type: 'error', id, client, message: error });
      return;
    }
    postMessage({ type: 'hash', id, client, hash: session.hash() });
    const full = session.years();
    const years = Number.isInteger(until) ? Math.max(0, Math.min(until, full)) : full;
    postMessage({ type: 'progress', id, client, year: 0, years });
    while (session.year() < years && !session.done()) {
      await yieldToEvents();
      if (id !== latest.get(client)) return; // superseded by a newer update: drop this one
      session.growYear();
      postMessage({ type: 'progress', id, client, year: session.year(), years });
    }
    await yieldToEvents();
    if (id !== latest.get(client)) return;
    session.buildMesh();
    const stats = JSON.parse(session.statsJson());
    const transfer = [];
    const mesh = takeMesh(session, transfer);
    postMessage({ type: 'tree', id, client, stats, mesh }, transfer);
    finished.get(client)?.delete();
    finished.set(client, session);
    keep = true;
  } finally {
    if (!keep) session.delete();
  }
}

function exportTree(id, client, format) {
  const session = finished.get(client);
  if (!session) throw new Error('no tree has been grown yet');
  let bytes;
  if (format === 'glb') {
    const error = session.buildGlb();
    if (error) throw new Error(error);
    bytes = copyView(session.glbBytes(), Uint8Array);
  } else if (format === 'json') {
    bytes = new TextEncoder().encode(session.paramsJson()).buffer;
  } else {
    throw new Error(`unknown export format '${String(format)}'`);
  }
  postMessage({ type: 'export', id, client, format, bytes }, [bytes]);
}

function decode(Module, hash) {
  return JSON.parse(Module.decodeHash(String(hash ?? '')));
}

self.onmessage = async (event) => {
  const msg = event.data || {};
  const client = typeof msg.client === 'string' ? msg.client : 'app';
  try {
    if (msg.type === 'init') {
      const Module = await loadModule();
      postMessage({
        type: 'ready',
        client,
        paramTable: JSON.parse(Module.paramTableJson()),
        presets: JSON.parse(Module.presetsJson()),
        decoded: decode(Module, msg.hash),
      });
    } else if (msg.type === 'decode') {
      const Module = await loadModule();
      const { state, notices } = decode(Module, msg.hash);
      postMessage({ type: 'decoded', id: msg.id, client, state, notices });
    } else if (msg.type === 'update') {
      latest.set(client, msg.id);
      await grow(msg.id, client, msg.state, msg.until);
    } else if (msg.type === 'export') {
      await loadModule();
      exportTree(msg.id, client, msg.format);
    } else {
      postMessage({ type: 'error', id: msg.id, client, message: `worker: unknown message type '${String(msg.type)}'` });
    }
  } catch (e) {
    postMessage({ type: 'error', id: msg.id, client, message: `worker: ${messageOf(e)}` });
  }
};
