#!/usr/bin/env node
// The ivy's look (issue 31 item 5): `paper` beside `artist` on the Stanford bunny
// (tests/data/meshes/bunny.obj) and on the overhang facade, each `niwa ivy grow ... --out x.glb
// --with-support --stats` drawn by three.js (tests/browser/three_page.mjs, an independent glTF
// loader in Chromium; the bunny from a seed point at its front foot, about where the page's default
// "front" seed lies) from the front-right, side by side, into docs/figures/ivy/look_*.png, with
// the numbers in docs/figures/ivy/look.md. Run by `scripts/figures ivy look` (figures_ivy.js).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchChromium } from '../../tests/browser/harness.mjs';
import { openThreePage, saveSideBySide } from '../../tests/browser/three_page.mjs';

const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const NIWA = process.env.NIWA || path.join(ROOT, 'build/native/bin/niwa');
const OUT = path.join(ROOT, 'docs/figures/ivy');
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-ivy-look-'));

const SUPPORTS = [
  { name: 'bunny', args: ['--mesh', path.join(ROOT, 'tests/data/meshes/bunny.obj'), '--seed-point', '0.6981,2.435,3.828'], steps: 150 },
  { name: 'facade', args: ['--scene', 'overhang'], steps: 150 },
];
const PRESETS = ['paper', 'artist'];

const rows = [];
const browser = await launchChromium();
try {
  const page = await openThreePage(browser, dir);
  for (const s of SUPPORTS) {
    const files = [];
    for (const preset of PRESETS) {
      const file = `${s.name}-${preset}.glb`;
      const args = ['ivy', 'grow', ...s.args, '--preset', preset, '--seed', '1', '--steps', String(s.steps),
        '--out', path.join(dir, file), '--with-support', '--stats'];
      const st = JSON.parse(execFileSync(NIWA, args, { encoding: 'utf8' }));
      rows.push({ support: s.name, preset, steps: s.steps, st, line: `niwa ${args.slice(0, -4).join(' ').replace(ROOT + '/', '')}` });
      files.push(file);
      console.log(`${s.name} ${preset}: ${st.internodes} internodes, cover ${st.leaf_cover}, overlap ${st.overlap_pairs}, bend_max ${st.bend_max}`);
    }
    // One call: one camera (framed on the first file) for both.
    const pngs = (await page.evaluate((n) => window.renderGlbs(n), files)).map((r) => r.png);
    const out = path.join(OUT, `look_${s.name}.png`);
    await saveSideBySide(page, pngs, out);
    console.log(`wrote ${path.relative(ROOT, out)}`);
  }
} finally {
  await browser.close();
  fs.rmSync(dir, { recursive: true, force: true });
}

const fmt = (x, d = 3) => (Number.isFinite(x) ? String(Number(x.toFixed(d))) : String(x));
let md = '| support | preset | steps | internodes | leaves (thinned) | leaf cover, front | overlap pairs (% of internodes) | bend_max | up_min | tendrils (hanging internodes) | rise |\n';
md += '|---|---|---|---|---|---|---|---|---|---|---|\n';
for (const { support, preset, steps, st } of rows) {
  md += `| ${support} | ${preset} | ${steps} | ${st.internodes} | ${st.leaves} (${st.leaves_thinned}) | ${fmt(st.leaf_cover)} | ${st.overlap_pairs} (${fmt(100 * st.overlap_pairs / Math.max(1, st.internodes), 1)} %) | ${fmt(st.bend_max, 1)}° | ${fmt(st.up_min, 2)} | ${st.hanging.tendrils} (${st.hanging.internodes}) | ${fmt(st.rise, 2)} |\n`;
}
md += '\nCommands (each with `--out x.glb --with-support --stats`):\n\n';
for (const r of rows) md += `- \`${r.line}\`\n`;
fs.writeFileSync(path.join(OUT, 'look.md'), md);
console.log(md);
