// Test of web/gl/program.js's #include resolver in node (no browser): node tests/browser/shader_include.test.mjs.
// Includes resolve relative to the including file, a file is inserted once per shader, cycles are
// refused with the chain named; and every shader in shaders/ resolves from the real files with no
// #include left over (compared with a brute-force twin: repeated textual expansion).
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { ROOT, check, finish } from './harness.mjs';
import { resolveIncludes } from '../../web/gl/program.js';

const files = (map) => async (url) => {
  const p = new URL(url).pathname;
  if (!(p in map)) throw new Error(`cannot load ${p} (404)`);
  return map[p];
};
const base = 'http://x';

try {
  const fake = files({
    '/s/tree/a.vert': '#version 300 es\n#include "../common/skin.glsl"\n#include "../common/light.glsl"\nvoid main() {}',
    '/s/common/skin.glsl': '// skin\n#include "math.glsl"\nvec3 skin() { return v(); }',
    '/s/common/light.glsl': '#include "./math.glsl"\nfloat light() { return 1.0; }',
    '/s/common/math.glsl': 'vec3 v() { return vec3(0); }',
    '/s/loop/x.glsl': '#include "y.glsl"\nx',
    '/s/loop/y.glsl': '#include "../loop/x.glsl"\ny',
    '/s/self.glsl': '#include "self.glsl"',
    '/s/missing.vert': '#include "nope.glsl"',
  });
  const out = await resolveIncludes(`${base}/s/tree/a.vert`, fake);
  check('includes resolve relative to the including file', out.includes('vec3 skin()') && out.includes('float light()'), out.replace(/\n/g, ' | '));
  check('a file included twice is inserted once', out.split('vec3 v()').length === 2 && !/^[ \t]*#include/m.test(out), out.replace(/\n/g, ' | '));
  check('the order is kept (math before skin, #version first)', out.startsWith('#version 300 es\n// skin\nvec3 v()'), out.slice(0, 40));
  const error = async (url) => resolveIncludes(`${base}${url}`, fake).then(() => '', (e) => e.message);
  const loop = await error('/s/loop/x.glsl');
  check('a cycle is refused, naming the chain', loop.includes('cycle') && loop.includes('/s/loop/x.glsl -> /s/loop/y.glsl -> /s/loop/x.glsl'), loop);
  const self = await error('/s/self.glsl');
  check('a file including itself is refused', self.includes('cycle'), self);
  const missing = await error('/s/missing.vert');
  check('a missing include names the file', missing.includes('/s/nope.glsl'), missing);

  // The real shaders, read from disk, against a brute-force twin (expand until no #include is left).
  const disk = async (url) => fs.readFileSync(new URL(url), 'utf8');
  const brute = (file, seen = new Set()) => fs.readFileSync(file, 'utf8').split('\n').map((line) => {
    const m = /^[ \t]*#include[ \t]+"([^"]+)"[ \t]*$/.exec(line);
    if (!m) return line;
    const target = path.resolve(path.dirname(file), m[1]);
    if (seen.has(target)) return null;
    seen.add(target);
    return brute(target, seen);
  }).filter((l) => l !== null).join('\n');
  const shaders = fs.readdirSync(path.join(ROOT, 'shaders'), { recursive: true })
    .filter((f) => /\.(vert|frag)$/.test(f)).map((f) => path.join(ROOT, 'shaders', f));
  let same = 0;
  const bad = [];
  for (const file of shaders) {
    const resolved = await resolveIncludes(pathToFileURL(file).href, disk);
    if (resolved === brute(file) && !/^[ \t]*#include/m.test(resolved) && resolved.startsWith('#version 300 es')) ++same;
    else bad.push(path.relative(ROOT, file));
  }
  check('every shader resolves like the brute-force twin', shaders.length >= 15 && same === shaders.length,
    `${same}/${shaders.length}${bad.length ? `; differ: ${bad.join(', ')}` : ''}`);
} catch (e) {
  check('test ran to the end', false, e.stack || String(e));
}
finish();
