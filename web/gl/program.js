// GLSL programs: fetches shader files and resolves `#include "file"` lines (relative to the file
// that includes them, each file inserted once per shader, cycles refused), then compiles and links.
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

function compile(gl, type, source, name) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(shader);
    gl.deleteShader(shader);
    throw new Error(`shader ${name}: ${log}`);
  }
  return shader;
}

// Compiles and links two sources; returns {program, uniforms: {name: location}}.
export function link(gl, vertexSource, fragmentSource, name) {
  const program = gl.createProgram();
  const vs = compile(gl, gl.VERTEX_SHADER, vertexSource, `${name}.vert`);
  const fs = compile(gl, gl.FRAGMENT_SHADER, fragmentSource, `${name}.frag`);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  gl.deleteShader(vs);
  gl.deleteShader(fs);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`program ${name}: ${gl.getProgramInfoLog(program)}`);
  const uniforms = {};
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; ++i) {
    const info = gl.getActiveUniform(program, i);
    uniforms[info.name] = gl.getUniformLocation(program, info.name);
  }
  return { program, uniforms };
}

// Loads several programs at once. specs: {name: [vertexPath, fragmentPath]}, paths relative to
// `base` (a URL ending in '/'); returns {name: {program, uniforms}}.
export async function loadPrograms(gl, base, specs) {
  const read = cachedReader();
  const entries = Object.entries(specs);
  const sources = await Promise.all(entries.map(([, [vert, frag]]) => Promise.all([
    resolveIncludes(new URL(vert, base).href, read), resolveIncludes(new URL(frag, base).href, read)])));
  return Object.fromEntries(entries.map(([name], i) => [name, link(gl, sources[i][0], sources[i][1], name)]));
}
