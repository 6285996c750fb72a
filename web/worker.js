// Niwa Web Worker (ES module worker): runs the WASM core off the main thread.
//
// Protocol: init, then update messages; buffers transferred, never copied twice.
//   in  {type:'init', hash}           -> out {type:'ready', paramTable, presets, decoded:{state, notices}}
//   in  {type:'decode', id, hash}     -> out {type:'decoded', id, state, notices}
//   in  {type:'update', id, state}    -> out {type:'hash', id, hash}            (state accepted by the core)
//                                        out {type:'progress', id, year, years} (after each year)
//                                        out {type:'tree', id, stats, mesh}     (ArrayBuffers transferred)
//   any failure                        -> out {type:'error', id, message}
// A newer update supersedes an older one: the grow loop yields between years and drops itself when
// a newer id has arrived.

const MODULE_URL = new URL('../wasm/niwa_web.js', import.meta.url).href;

let modulePromise = null;
let latestId = 0;

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
  return { bark: part('bark'), leaves: part('leaves'), flowers: part('flowers') };
}

async function grow(id, state) {
  const Module = await loadModule();
  if (id !== latestId) return;
  let session;
  try {
    session = new Module.GrowSession(JSON.stringify(state));
  } catch (e) {
    postMessage({ type: 'error', id, message: String(e && e.message ? e.message : e) });
    return;
  }
  try {
    const error = session.error();
    if (error) {
      postMessage({ type: 'error', id, message: error });
      return;
    }
    postMessage({ type: 'hash', id, hash: session.hash() });
    const years = session.years();
    postMessage({ type: 'progress', id, year: 0, years });
    while (!session.done()) {
      await yieldToEvents();
      if (id !== latestId) return; // superseded by a newer update: drop this one
      session.growYear();
      postMessage({ type: 'progress', id, year: session.year(), years });
    }
    await yieldToEvents();
    if (id !== latestId) return;
    session.buildMesh();
    const stats = JSON.parse(session.statsJson());
    const transfer = [];
    const mesh = takeMesh(session, transfer);
    postMessage({ type: 'tree', id, stats, mesh }, transfer);
  } finally {
    session.delete();
  }
}

function decode(Module, hash) {
  return JSON.parse(Module.decodeHash(String(hash ?? '')));
}

self.onmessage = async (event) => {
  const msg = event.data || {};
  try {
    if (msg.type === 'init') {
      const Module = await loadModule();
      postMessage({
        type: 'ready',
        paramTable: JSON.parse(Module.paramTableJson()),
        presets: JSON.parse(Module.presetsJson()),
        decoded: decode(Module, msg.hash),
      });
    } else if (msg.type === 'decode') {
      const Module = await loadModule();
      const { state, notices } = decode(Module, msg.hash);
      postMessage({ type: 'decoded', id: msg.id, state, notices });
    } else if (msg.type === 'update') {
      latestId = msg.id;
      await grow(msg.id, msg.state);
    } else {
      postMessage({ type: 'error', id: msg.id, message: `worker: unknown message type '${String(msg.type)}'` });
    }
  } catch (e) {
    postMessage({ type: 'error', id: msg.id, message: `worker: ${e && e.message ? e.message : String(e)}` });
  }
};
