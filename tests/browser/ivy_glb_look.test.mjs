// Issue 18 item 3: the ivy .glb's leaves are textured. `niwa ivy grow --scene cubes4 --steps 50
// --out ivy.glb --with-support` drawn by three.js (an independent glTF loader) in Chromium, once
// as written and once with the colour maps dropped: the leaves' pixels must differ (the texture
// reaches the screen) and show the veins (a spread of greens, not one flat shade); the pair goes
// to build/artifacts/ivy-glb-textured.png (left: as written, right: maps dropped).
// Run: NIWA_NATIVE=$PWD/build/native/bin/niwa node tests/browser/ivy_glb_look.test.mjs
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ARTIFACTS, NATIVE, ROOT, check, finish, launchChromium } from './harness.mjs';
import { openThreePage, saveSideBySide } from './three_page.mjs';

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-ivy-glb-'));
const browser = await launchChromium();
try {
  execFileSync(NATIVE, ['ivy', 'grow', '--scene', 'cubes4', '--steps', '50', '--out', path.join(dir, 'ivy.glb')]);
  const page = await openThreePage(browser, dir);
  const [textured] = await page.evaluate(() => window.renderGlbs(['ivy.glb'], { rgba: true }));
  const [plain] = await page.evaluate(() => window.renderGlbs(['ivy.glb'], { plain: true, rgba: true }));
  // Leaf pixels: drawn in both, green dominant in the plain render (the leaf factor is white, so
  // plain leaves are light grey: greener than it only where the texture is).
  let leaves = 0, changed = 0;
  const shades = new Set();
  for (let i = 0; i < textured.rgba.length; i += 4) {
    if (textured.rgba[i + 3] === 0 || plain.rgba[i + 3] === 0) continue;
    const [r, g, b] = textured.rgba.slice(i, i + 3);
    if (!(g > r + 20 && g > b + 20)) continue;  // a green pixel of the textured render
    ++leaves;
    const d = Math.abs(r - plain.rgba[i]) + Math.abs(g - plain.rgba[i + 1]) + Math.abs(b - plain.rgba[i + 2]);
    if (d > 30) ++changed;
    shades.add(`${r >> 3},${g >> 3},${b >> 3}`);
  }
  check('the textured ivy shows green leaf pixels', leaves > 500, `${leaves} green pixels`);
  check('the leaves take their colour from the texture (maps dropped: different pixels)', changed > 0.9 * leaves,
    `${changed} of ${leaves} green pixels change without the maps`);
  check('the leaves show more than one shade (veins, rim, the lighter base)', shades.size >= 20, `${shades.size} shades (5 bits a channel)`);
  const file = path.join(ARTIFACTS, 'ivy-glb-textured.png');
  await saveSideBySide(page, [textured.png, plain.png], file);
  console.log(`wrote ${path.relative(ROOT, file)} (left: as written, right: colour maps dropped)`);
} catch (e) {
  check('test ran to the end', false, e.stack || String(e));
} finally {
  await browser.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
finish();
