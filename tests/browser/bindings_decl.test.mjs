// The typed declaration of the web module (web/bindings/niwa_web.d.ts) against what it declares:
// the same functions, classes and methods as the EMSCRIPTEN_BINDINGS blocks of web/bindings/*.cpp,
// and as the module built from them, loaded in a module worker of Chromium (the module's
// environment is a worker). A binding added, renamed or removed without its declaration fails here.
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, check, modulePage, runBrowserTest } from './harness.mjs';

// What embind gives every class itself (declared for the handlers' use, not bound in C++).
const EMBIND_OWN = new Set(['constructor', 'delete', 'clone', 'isDeleted', 'deleteLater', 'isAliasOf']);

// {functions: Set, classes: Map name -> Set of methods} of the declaration file.
function declared(text) {
  const functions = new Set();
  const classes = new Map();
  let current = null;
  for (const line of text.split('\n')) {
    let m;
    if ((m = /^export function (\w+)\s*\(/.exec(line))) functions.add(m[1]);
    else if ((m = /^export class (\w+)/.exec(line))) classes.set((current = m[1]), new Set());
    else if (current && (m = /^ {2}(\w+)\s*\(/.exec(line)) && !EMBIND_OWN.has(m[1])) classes.get(current).add(m[1]);
    else if (/^}/.test(line)) current = null;
  }
  return { functions, classes };
}

// The same from the C++ bindings (function("x", ...), class_<T>("X") with its .function("m", ...)).
function bound(dir) {
  const functions = new Set();
  const classes = new Map();
  for (const file of fs.readdirSync(dir).filter((f) => f.endsWith('.cpp'))) {
    const text = fs.readFileSync(path.join(dir, file), 'utf8');
    const block = text.slice(text.indexOf('EMSCRIPTEN_BINDINGS('));
    let current = null;
    for (const m of block.matchAll(/(class_<[^>]*>\("(\w+)"\))|(\.function\("(\w+)")|((?<![.\w])function\("(\w+)")/g)) {
      if (m[2]) classes.set((current = m[2]), new Set());
      else if (m[4]) classes.get(current).add(m[4]);
      else if (m[6]) functions.add(m[6]);
    }
  }
  return { functions, classes };
}

const diff = (a, b) => [...a].filter((x) => !b.has(x));
const names = (s) => [...s].sort().join(', ');

function compare(what, a, b, aName, bName) {
  const onlyA = diff(a.functions, b.functions), onlyB = diff(b.functions, a.functions);
  check(`${what}: the same functions`, onlyA.length === 0 && onlyB.length === 0 && a.functions.size > 3,
    `${a.functions.size} functions; only in ${aName}: [${onlyA}], only in ${bName}: [${onlyB}]`);
  const classNames = new Set([...a.classes.keys(), ...b.classes.keys()]);
  for (const c of classNames) {
    const ma = a.classes.get(c), mb = b.classes.get(c);
    const ok = ma && mb && diff(ma, mb).length === 0 && diff(mb, ma).length === 0;
    check(`${what}: class ${c} has the same methods`, ok,
      !ma ? `missing in ${aName}` : !mb ? `missing in ${bName}` : `only in ${aName}: [${diff(ma, mb)}], only in ${bName}: [${diff(mb, ma)}]`);
  }
  check(`${what}: the study sessions are declared`, ['TreeSession', 'IvyLab', 'TerrainLab'].every((c) => a.classes.has(c)), names(new Set(a.classes.keys())));
}

const decl = declared(fs.readFileSync(path.join(ROOT, 'web/bindings/niwa_web.d.ts'), 'utf8'));
const cpp = bound(path.join(ROOT, 'web/bindings'));
compare('niwa_web.d.ts vs web/bindings/*.cpp', decl, cpp, 'the .d.ts', 'the C++');

const problems = [];
await runBrowserTest(async (server, browser) => {
  const page = await modulePage(server, browser, problems);
  // The module's own view of itself, from a module worker (its environment).
  const runtime = await page.evaluate(async (classes) => {
    const code = `
      const factory = (await import('${location.origin}/wasm/niwa_web.js')).default;
      const Module = await factory({ locateFile: (f) => '${location.origin}/wasm/' + f, print: () => {}, printErr: () => {} });
      const functions = Object.keys(Module).filter((k) => typeof Module[k] === 'function' && !/^[A-Z_]/.test(k));
      const classes = {};
      for (const c of ${JSON.stringify(classes)}) {
        if (typeof Module[c] === 'function' && Module[c].prototype) {
          classes[c] = Object.getOwnPropertyNames(Module[c].prototype).filter((m) => m !== 'constructor' && typeof Module[c].prototype[m] === 'function');
        }
      }
      postMessage({ functions, classes });`;
    const worker = new Worker(URL.createObjectURL(new Blob([code], { type: 'text/javascript' })), { type: 'module' });
    return new Promise((resolve, reject) => {
      worker.onmessage = (e) => resolve(e.data);
      worker.onerror = (e) => reject(new Error(e.message || 'worker failed'));
    });
  }, [...decl.classes.keys()]);
  const rt = { functions: new Set(runtime.functions), classes: new Map(Object.entries(runtime.classes).map(([c, ms]) => [c, new Set(ms)])) };
  // The runtime also has Emscripten's own functions: only the declared ones are compared there.
  const missing = diff(decl.functions, rt.functions);
  check('every declared function is in the built module', missing.length === 0, `missing: [${missing}]`);
  for (const [c, methods] of decl.classes) {
    const have = rt.classes.get(c);
    // embind puts its own helpers (delete, clone, isDeleted, ...) on every class: declared methods only.
    const absent = have ? diff(methods, have) : [...methods];
    check(`class ${c} and its declared methods are in the built module`, Boolean(have) && absent.length === 0, have ? `missing: [${absent}]` : 'class missing');
  }
  check('no page errors', problems.length === 0, problems.join(' | '));
});
