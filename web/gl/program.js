// GLSL programs: fetches shader files and resolves `#include "file"` lines (relative to the file
// that includes them, each file inserted once per shader, cycles refused), then compiles and links.
// loadPrograms compiles and links every program of a renderer at once and waits for them without
// blocking (KHR_parallel_shader_compile, else a fence; issue 16: on SwiftShader a status
// query right after compiling held the main thread 100-350 ms a shader, and the compile held the
// GPU process, so the page's first clicks waited up to 1.8 s for a frame).
// Does not: know any study's shaders, cache programs across contexts, or preprocess anything but
// `#include` (no #define injection; GLSL ES keeps its own preprocessor).

export async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`cannot load ${url} (${response.status})`);
  return response.text();
}

const INCLUDE = /^[ \t]*#include[ \t]+"([^"]+)"[ \t]*$/;

// The source of `url` with every `#include "file"` line replaced by that file's resolved source.
// `read(url)` returns a promise of the text (default fetchText; cached per call of loadShader so a
// file shared by several includes is fetched once). A file already inserted into this shader is
// not inserted again (so two includes of one helper do not redefine it); a file that includes
// itself through any chain is an error naming the chain.
export async function resolveIncludes(url, read = fetchText) {
  const seen = new Set();
  const expand = async (fileUrl, chain) => {
    if (chain.includes(fileUrl)) {
      throw new Error(`shader include cycle: ${[...chain, fileUrl].map((u) => new URL(u).pathname).join(' -> ')}`);
    }
    seen.add(fileUrl);
    const lines = (await read(fileUrl)).split('\n');
    const out = [];
    for (const line of lines) {
      const m = INCLUDE.exec(line);
      if (!m) {
        out.push(line);
        continue;
      }
      const target = new URL(m[1], fileUrl).href;
      if (chain.includes(target) || target === fileUrl) {
        throw new Error(`shader include cycle: ${[...chain, fileUrl, target].map((u) => new URL(u).pathname).join(' -> ')}`);
      }
      if (seen.has(target)) continue;  // already in this shader
      out.push(await expand(target, [...chain, fileUrl]));
    }
    return out.join('\n');
  };
  return expand(new URL(url).href, []);
}

// A reader that fetches each URL once (shared by the shaders of one renderer).
export function cachedReader(read = fetchText) {
  const cache = new Map();
  return (url) => {
    if (!cache.has(url)) cache.set(url, read(url));
    return cache.get(url);
  };
}

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  return shader;
}

// Starts compiling and linking two sources (no status is read: that would wait for the compile).
function startLink(gl, vertexSource, fragmentSource, name) {
  const program = gl.createProgram();
  const vs = compile(gl, gl.VERTEX_SHADER, vertexSource);
  const fs = compile(gl, gl.FRAGMENT_SHADER, fragmentSource);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  return { program, vs, fs, name };
}

// The linked program's {program, uniforms}, or the compile or link log as an error.
function finishLink(gl, { program, vs, fs, name }) {
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    for (const [shader, suffix] of [[vs, 'vert'], [fs, 'frag']]) {
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
        const log = gl.getShaderInfoLog(shader);
        throw new Error(`shader ${name}.${suffix}: ${log}`);
      }
    }
    throw new Error(`program ${name}: ${gl.getProgramInfoLog(program)}`);
  }
  gl.detachShader(program, vs);
  gl.detachShader(program, fs);
  gl.deleteShader(vs);
  gl.deleteShader(fs);
  const uniforms = {};
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; ++i) {
    const info = gl.getActiveUniform(program, i);
    uniforms[info.name] = gl.getUniformLocation(program, info.name);
  }
  return { program, uniforms };
}

// Compiles and links two sources; returns {program, uniforms: {name: location}} (blocking).
export function link(gl, vertexSource, fragmentSource, name) {
  return finishLink(gl, startLink(gl, vertexSource, fragmentSource, name));
}

// Resolves once every program of `started` has finished linking: polled every `ms` through
// KHR_parallel_shader_compile's COMPLETION_STATUS_KHR (which never blocks). Without the extension
// (SwiftShader has none) a fence after the links is polled instead (gl.getSyncParameter never
// blocks either): the GPU process compiles and links the programs while the page goes on, and the
// status queries that follow wait only for what is left of a link (ANGLE may finish one after the
// fence: in two instrumented loads of the tree page the ground's query then took 2 ms once, 1.3 s
// after a 1.1 s fence the other time, on a machine loaded 24 on 2 cores). Reading LINK_STATUS at
// once waited for every compile in one main-thread task (93% of a 609 ms task during the tree
// page's load, issue 32).
export function whenLinked(gl, started, ms = 16) {
  const ext = gl.getExtension('KHR_parallel_shader_compile');
  const fence = ext ? null : gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (fence) gl.flush();
  const done = () => gl.isContextLost() || (ext
    ? started.every((s) => gl.getProgramParameter(s.program, ext.COMPLETION_STATUS_KHR))
    : gl.getSyncParameter(fence, gl.SYNC_STATUS) === gl.SIGNALED);
  return new Promise((resolve) => {
    const poll = () => {
      if (!done()) {
        setTimeout(poll, ms);
        return;
      }
      if (fence) gl.deleteSync(fence);
      resolve();
    };
    setTimeout(poll, ms);  // (a fence's status changes only between tasks)
  });
}

// Loads several programs at once. specs: {name: [vertexPath, fragmentPath]}, paths relative to
// `base` (a URL ending in '/'); returns {name: {program, uniforms}}. Every program is compiled and
// linked before any status is read, and the renderer's first frame waits until they are all done
// without blocking the page (whenLinked).
export async function loadPrograms(gl, base, specs) {
  const read = cachedReader();
  const entries = Object.entries(specs);
  const sources = await Promise.all(entries.map(([, [vert, frag]]) => Promise.all([
    resolveIncludes(new URL(vert, base).href, read), resolveIncludes(new URL(frag, base).href, read)])));
  const started = entries.map(([name], i) => startLink(gl, sources[i][0], sources[i][1], name));
  await whenLinked(gl, started);
  // One program's status a task: a link still under way (the fence does not always cover it) holds
  // the page for that program alone, not for all of them in one task.
  const out = {};
  for (const [i, [name]] of entries.entries()) {
    if (i > 0) await new Promise((resolve) => setTimeout(resolve, 0));
    out[name] = finishLink(gl, started[i]);
  }
  return out;
}
