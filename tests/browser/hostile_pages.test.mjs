// The pages' half of the shared hostile-input suite (issue 34 item 5): node tests/browser/hostile_pages.test.mjs.
// Every study page (the studies of 'niwa flags', the tree's page being index.html) is opened with a
// hash that gives every row of its table ('niwa params STUDY --json') a hostile value (hex, nan,
// 1e400 or just past the row's maximum, in turn over the rows, twice; the key repeated; a hash over
// 16,384 characters); the page
// must show the notice (one line per refused row, capped at five and "... N more"), settle (ready,
// or an error line beside a field), keep its worker (a valid hash then grows again) and log no
// uncaught error. Hostile files are dropped on the pages that take files (#mesh-file, #contour-file,
// the garden's #heightmap-file and #mask-file):
// each must end in a notice or a line beside the field, and a page that still works. Like tests/cli/hostile.test.mjs it lists no
// row or value by hand: a new study page is covered by its table.
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { NATIVE, ROOT, TIMEOUT, check, newContext, runBrowserTest, watchPage } from './harness.mjs';
import { glbBytes } from '../support/glb_bytes.mjs';
import { dracoGlb } from '../support/draco_encode.mjs';
import { gray16PngBytes, pngBytes } from '../support/png_bytes.mjs';

const declared = JSON.parse(execFileSync(NATIVE, ['flags'], { encoding: 'utf8' }));
const pageOf = (study) => (study === 'tree' ? 'index.html' : `${study}.html`);
// A study's CLI can land before its page (moss: its table and soil commands first); a study without
// public/<study>.html has no page to test yet, and is named so that it is not silently left out.
// NIWA_HOSTILE_STUDY=ivy: one study's page only (while working on it).
const paged = declared.studies.filter((s) => existsSync(join(ROOT, 'public', pageOf(s.name)))
  && (!process.env.NIWA_HOSTILE_STUDY || s.name === process.env.NIWA_HOSTILE_STUDY));
for (const s of declared.studies.filter((x) => !existsSync(join(ROOT, 'public', pageOf(x.name))))) console.log(`(no page yet: ${s.name})`);

// The hostile kinds of value. Each page load gives every row one of them, in turn (row i the kind
// (i + turn) % 4), and two loads per page (turns 0 and 2) give each row two kinds and each kind to
// half of the rows: the hash codec is one parser for every row, and a page load costs seconds.
const KINDS = [
  ['hex', () => '0x10'],
  ['nan', () => 'nan'],
  ['overflow', () => '1e400'],
  ['past the maximum', (row) => String(row.max + Math.max(1, Math.abs(row.max) * 1e-6))],
];
const TURNS = [0, 2];

// Waits until the page has settled: ready or a field error shown, nothing running. With
// `orNotice`, also returns as soon as the notice shows while the page still grows what it kept of
// a hostile hash (a garden with every row at its maximum grows for half a minute on the CPU
// rasteriser): stillWorks then gives the page a valid hash mid-growth, which it must take over
// the growth it is doing, and grow to ready; a page that hangs on the hostile state fails there.
async function settled(page, orNotice = false) {
  await page.waitForFunction((early) => {
    const d = document.documentElement.dataset;
    const notice = document.getElementById('notice');
    return d.status === 'ready' || d.status === 'error' || (early && !notice.hidden && notice.textContent.trim() !== '');
  }, orNotice, { timeout: TIMEOUT, polling: 250 });
  return page.evaluate(() => ({
    status: document.documentElement.dataset.status,
    notice: document.getElementById('notice').hidden ? [] : document.getElementById('notice').textContent.split('\n'),
  }));
}

// The notice names every refused row: min(rows, 5) lines and "... N more" for the rest.
function namesRows(lines, keys) {
  const more = lines.length ? /^\.\.\. (\d+) more$/.exec(lines[lines.length - 1]) : null;
  const shown = more ? lines.slice(0, -1) : lines;
  const total = shown.length + (more ? Number(more[1]) : 0);
  return total >= keys.length && shown.every((line) => keys.some((k) => line.includes(k)));
}

// After a hostile hash, a valid one (the page's own opening state, `opening`: the hash the page wrote
// when opened with none, under another seed) must grow again in the same page. (A serial of the page,
// treeSerial, ivySerial, ..., goes up and the page is ready.) The opening state, not the table's
// defaults alone: the moss table's defaults are the thesis workload (300 days), the page opens on 60.
// The valid hash is the page's opening state made lighter (LIGHTER: any valid hash shows the page
// recovered, and each study's regrow here is five per page): the garden at 2 years instead of 8
// (its regrow took 13-17 s of the suite's CPU each time), the tree at 3 years instead of 15, the
// ivy at 15 steps, the terrain's mesh at 64², the moss over 10 days with 1,024 photons, the bark on
// a 32 x 16 lattice. The opening states themselves are grown (and drawn) by each page's own test.
const LIGHTER = {
  garden: { years: '2' }, tree: { years: '3' }, ivy: { steps: '15' }, terrain: { res: '64' },
  moss: { days: '10', photons: '1024' }, bark: { N_R: '32', N_H: '16' },
};
async function stillWorks(page, opening, lighter = {}) {
  const serials = () => Object.fromEntries(Object.entries(document.documentElement.dataset)
    .filter(([k]) => /^[a-z]+Serial$/.test(k) && !k.startsWith('drawn')).map(([k, v]) => [k, Number(v)]));
  const before = await page.evaluate(serials);
  const seed = `seed=${2 + Math.floor(Math.random() * 1000)}`;
  const fields = opening.replace(/^#/, '').split('&').filter((f) => f && !f.startsWith('seed='))
    .map((f) => { const k = f.split('=')[0]; return k in lighter ? `${k}=${lighter[k]}` : f; });
  for (const [k, v] of Object.entries(lighter)) if (!fields.some((f) => f.split('=')[0] === k)) fields.push(`${k}=${v}`);
  await page.evaluate((h) => { location.hash = h; }, `#${[...fields, seed].join('&')}`);
  const grown = (old) => page.waitForFunction((o) => {
    const d = document.documentElement.dataset;
    return d.status === 'ready' && Object.entries(d).some(([k, v]) =>
      /^[a-z]+Serial$/.test(k) && !k.startsWith('drawn') && Number(v) > (o[k] ?? -1));
  }, old, { timeout: 60000, polling: 250 });
  try {
    await grown(before);
    // The hostile hash's own growth may have ended just before the page took the valid hash (the
    // test no longer waits for it, settled's orNotice): then the page grows again; wait for that one.
    const first = await page.evaluate(serials);
    await page.waitForTimeout(400);
    if (await page.evaluate(() => document.documentElement.dataset.status) !== 'ready') await grown(first);
    return true;
  } catch {
    return false;
  }
}

const glb = (json, binLength = 0) => glbBytes(JSON.stringify(json), Buffer.alloc(binLength));
const deep = (n) => '['.repeat(n) + ']'.repeat(n);
const FILES = {
  '#mesh-file': {
    'deep extras': { name: 'deep.gltf', buffer: Buffer.from(`{"asset":{"version":"2.0","extras":${deep(30000)}}}`) },
    'a wrapping accessor': { name: 'wrap.glb', buffer: glb({
      asset: { version: '2.0' }, buffers: [{ byteLength: 36 }], bufferViews: [{ buffer: 0, byteLength: 36 }],
      accessors: [{ bufferView: 0, componentType: 5126, count: 0x15555556, type: 'VEC3' }],
      meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }], nodes: [{ mesh: 0 }], scenes: [{ nodes: [0] }] }, 36) },
    'a vertex bomb': { name: 'bomb.glb', buffer: glb({
      asset: { version: '2.0' }, buffers: [{ byteLength: 36 }], bufferViews: [{ buffer: 0, byteLength: 36 }],
      accessors: [{ bufferView: 0, componentType: 5126, count: 3, type: 'VEC3' }],
      meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }],
      nodes: [{ children: Array.from({ length: 1000 }, (_, i) => i + 1) }, ...Array.from({ length: 1000 }, () => ({ mesh: 0 }))],
      scenes: [{ nodes: [0, 0, 0, 0, 0, 0, 0, 0, 0, 0] }] }, 36) },
    garbage: { name: 'garbage.glb', buffer: Buffer.from([0, 1, 2, 255, 254, 10, 13]) },
    // A Draco header (bitstream 2.2, edgebreaker) declaring 2^28 faces: refused by the page's import before draco3d
    // decodes (web/mesh/mesh_import.js), with the native reader's line (issue 34; before, Draco's own refusal).
    'a Draco header over the cap': { name: 'capped.glb', expect: /the Draco data declares 49 vertices and 268435456 triangles; the limits are 12000000 and 4000000/,
      buffer: dracoGlb(Buffer.concat([Buffer.from('DRACO'), Buffer.from([2, 2, 1, 1, 0, 0, 0, 49, 0x80, 0x80, 0x80, 0x80, 0x01]), Buffer.alloc(35)]), 3) },
  },
  // The garden's PNGs (a heightmap ground, a density mask): decoded in the core, each refusal its line.
  '#heightmap-file': {
    'text named .png': { name: 'text.png', buffer: Buffer.from('not a PNG'), expect: /ground\.file: 'text\.png': not a PNG file/ },
    'a colour PNG': { name: 'colour.png', buffer: pngBytes(2, 2, new Uint8Array(16).fill(90)), expect: /ground\.file: 'colour\.png' is a colour \(RGBA\) PNG; must be a grey PNG/ },
    'a PNG declaring 5000 x 5000': { name: 'huge.png', buffer: pngBytes(1, 1, new Uint8Array(4), { declared: { width: 5000, height: 5000 } }), expect: /ground\.file: 'huge\.png' is 5000 x 5000 pixels; each side must be in 2\.\.4096/ },
    'a truncated 16-bit PNG': { name: 'cut.png', buffer: gray16PngBytes(8, 8, (x) => x * 8000).subarray(0, 40), expect: /ground\.file: 'cut\.png': truncated PNG/ },
  },
  '#mask-file': {
    'text named .png': { name: 'text.png', buffer: Buffer.from('not a PNG'), expect: /mask: 'text\.png': not a PNG file/ },
    'a PNG declaring 5000 x 5000': { name: 'huge.png', buffer: pngBytes(1, 1, new Uint8Array(4), { declared: { width: 5000, height: 5000 } }), expect: /mask: 'huge\.png' is 5000 x 5000 pixels; each side must be in 1\.\.4096/ },
  },
  '#contour-file': {
    'a numeric type': { name: 'n.json', buffer: Buffer.from('{"type": 7, "coordinates": [[0,0],[1,0],[1,1]]}') },
    'no coordinates': { name: 'p.json', buffer: Buffer.from('{"type": "Polygon"}') },
    'a null type': { name: 't.json', buffer: Buffer.from('{"type": null}') },
    'deep JSON': { name: 'd.json', buffer: Buffer.from(deep(30000)) },
    'a repeated key': { name: 'r.json', buffer: Buffer.from('{"points": [[0,0],[100,0],[100,100]], "points": [[0,0],[1,0],[1,1]]}') },
  },
};

await runBrowserTest(async (server, browser) => {
  for (const study of paged) {
    const table = JSON.parse(execFileSync(NATIVE, ['params', study.name, '--json'], { encoding: 'utf8' }));
    const keys = table.map((row) => row.key);
    const problems = [];
    const context = await newContext(browser, { viewport: { width: 900, height: 650 } });
    const page = watchPage(await context.newPage(), problems);
    const url = `${server.url}${pageOf(study.name)}`;
    // The page opened with no hash: its result, and the hash it writes (the state stillWorks varies).
    await page.goto(url);
    const first = await settled(page);
    const opening = await page.evaluate(() => location.hash);
    check(`${study.name} page: opens with a result and no notice`, first.status === 'ready' && first.notice.length === 0,
      `${first.status}; hash ${opening.slice(0, 120)}; ${JSON.stringify(first.notice).slice(0, 160)}`);
    for (const turn of TURNS) {
      const what = `${KINDS[turn][0]}, ${KINDS[(turn + 1) % 4][0]}, ... in turn`;
      const hash = table.map((row, i) => `${row.key}=${encodeURIComponent(KINDS[(i + turn) % 4][1](row))}`).join('&');
      await page.goto('about:blank');
      await page.goto(`${url}#${hash}`);
      const s = await settled(page, true);
      check(`${study.name} page: every row ${what} is refused with a notice naming it`, namesRows(s.notice, keys),
        `${keys.length} rows; ${JSON.stringify(s.notice).slice(0, 240)}`);
      check(`${study.name} page: after every row ${what}, a valid hash grows again`, await stillWorks(page, opening, LIGHTER[study.name]));
    }
    // Every row given twice.
    await page.goto('about:blank');
    await page.goto(`${url}#${table.map((row) => `${row.key}=${row.default}&${row.key}=${row.default}`).join('&')}`);
    let s = await settled(page, true);
    check(`${study.name} page: every row repeated is refused with a notice naming it`, namesRows(s.notice, keys),
      JSON.stringify(s.notice).slice(0, 240));
    check(`${study.name} page: after repeated keys, a valid hash grows again`, await stillWorks(page, opening, LIGHTER[study.name]));
    // Over the link's maximum: refused whole, with a notice; the page still grows.
    await page.goto('about:blank');
    await page.goto(`${url}#${keys[0]}=${table[0].default}&x=${'1'.repeat(17000)}`);
    s = await settled(page, true);
    check(`${study.name} page: a 17,000-character hash is refused with a notice`, s.notice.some((l) => /16384|16,384/.test(l)),
      JSON.stringify(s.notice).slice(0, 200));
    check(`${study.name} page: after a 17,000-character hash, a valid hash grows again`, await stillWorks(page, opening, LIGHTER[study.name]));
    // Hostile files on the page's file inputs, one after another in one page (each drop's notice
    // or line is cleared first, so a line left by the one before cannot pass for it); then a
    // valid hash grows again.
    let dropped = 0;
    for (const [input, files] of Object.entries(FILES)) {
      if (!(await page.$(input))) continue;
      for (const [what, file] of Object.entries(files)) {
        s = await settled(page);
        await page.evaluate(() => {
          const notice = document.getElementById('notice');
          notice.hidden = true;
          notice.textContent = '';
          for (const e of document.querySelectorAll('.field-error')) { e.hidden = true; e.textContent = ''; }
        });
        const { expect: want, ...payload } = file;
        await page.setInputFiles(input, { ...payload, mimeType: 'application/octet-stream' });
        // A notice, or a line beside the field (a visible .field-error).
        const shown = await page.waitForFunction(() => {
          const notice = document.getElementById('notice');
          const lines = [...document.querySelectorAll('.field-error')].filter((e) => !e.hidden && e.textContent.trim());
          if (!notice.hidden && notice.textContent.trim()) return notice.textContent;
          return lines.length ? lines[0].textContent : false;
        }, null, { timeout: 60000, polling: 250 }).then((h) => h.jsonValue()).catch(() => '');
        s = await settled(page);
        check(`${study.name} page: dropped ${what} (${file.name}) ends in a notice or a line beside the field`,
          typeof shown === 'string' && shown.length > 0 && (!want || want.test(shown)), `${JSON.stringify(shown).slice(0, 200)}; ${s.status}`);
        ++dropped;
      }
    }
    if (dropped) check(`${study.name} page: after ${dropped} hostile files, a valid hash grows again`, await stillWorks(page, opening, LIGHTER[study.name]));
    check(`${study.name} page: no uncaught error or console error`, problems.length === 0, problems.slice(0, 3).join(' | ').slice(0, 400));
    await context.close();
  }
});
