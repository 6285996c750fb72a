// Issue 17 item 4 (d): a 15-year sakura (`sakura` and `sakura-thesis`) within 20 k triangles still
// looks like the same tree. Both .glb files (the full `niwa tree grow --out` and the
// `--max-triangles 20000` one) are drawn the same way by three.js (an independent glTF loader) in
// Chromium: same camera framed on the full tree, same lights, transparent background. Checks the
// silhouette IoU (pixels with alpha > 0) >= IOU_FLOOR and the height and width of the silhouettes'
// boxes within 5 %; writes the pair side by side to build/artifacts/lod-<preset>.png.
// Run: NIWA_NATIVE=$PWD/build/native/bin/niwa node tests/browser/lod_look.test.mjs
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ARTIFACTS, NATIVE, ROOT, check, finish, launchChromium } from './harness.mjs';
import { openThreePage, saveSideBySide } from './three_page.mjs';

// Pixel IoU punishes one-pixel twigs (a 0.3 px twig of the full tree covers a pixel as a line);
// the block IoU compares the silhouettes at 1/4 resolution (a 4 x 4 block is set when any pixel
// is): the crown's outline and holes, which is what "looks like the same tree" means at a distance.
const IOU_FLOOR = 0.6;
const BLOCK_IOU_FLOOR = 0.8;
const BUDGET = 20000;
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'niwa-lod-look-'));

function iouOf(a, b) {
  let both = 0, either = 0;
  for (let i = 0; i < a.length; ++i) { both += a[i] & b[i]; either += a[i] | b[i]; }
  return either ? both / either : 0;
}

function blocks(mask, k = 4) {
  const n = 512 / k, out = new Array(n * n).fill(0);
  mask.forEach((m, i) => { if (m) out[Math.floor(Math.floor(i / 512) / k) * n + Math.floor((i % 512) / k)] = 1; });
  return out;
}

function box(mask) {
  let x0 = 512, x1 = -1, y0 = 512, y1 = -1;
  mask.forEach((m, i) => {
    if (!m) return;
    const x = i % 512, y = Math.floor(i / 512);
    x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  });
  return { w: x1 - x0 + 1, h: y1 - y0 + 1 };
}

const browser = await launchChromium();
try {
  const page = await openThreePage(browser, dir);

  for (const preset of ['sakura', 'sakura-thesis']) {
    const grow = ['tree', 'grow', '--preset', preset, '--years', '15'];
    execFileSync(NATIVE, [...grow, '--out', path.join(dir, `${preset}-full.glb`)]);
    execFileSync(NATIVE, [...grow, '--max-triangles', String(BUDGET), '--out', path.join(dir, `${preset}-lod.glb`)]);
    const [full, lod] = await page.evaluate((names) => window.renderGlbs(names),
      [`${preset}-full.glb`, `${preset}-lod.glb`]);
    const iou = iouOf(full.mask, lod.mask);
    const blockIou = iouOf(blocks(full.mask), blocks(lod.mask));
    const a = box(full.mask), b = box(lod.mask);
    check(`${preset} 15 years: silhouette IoU of the ${BUDGET}-triangle .glb against the full one >= ${IOU_FLOOR}`,
      iou >= IOU_FLOOR, `IoU ${iou.toFixed(3)} (full ${full.mask.reduce((s, m) => s + m, 0)} px, budget ${lod.mask.reduce((s, m) => s + m, 0)} px)`);
    check(`${preset}: silhouette IoU in 4 x 4 blocks >= ${BLOCK_IOU_FLOOR}`, blockIou >= BLOCK_IOU_FLOOR,
      `block IoU ${blockIou.toFixed(3)}`);
    check(`${preset}: silhouette height and width within 5 %`,
      Math.abs(b.h - a.h) <= 0.05 * a.h && Math.abs(b.w - a.w) <= 0.05 * a.w, `full ${a.w}x${a.h}, budget ${b.w}x${b.h}`);
    const file = path.join(ARTIFACTS, `lod-${preset}.png`);
    await saveSideBySide(page, [full.png, lod.png], file);  // full on the left
    console.log(`wrote ${path.relative(ROOT, file)} (left: full, right: ${BUDGET} triangles)`);
  }
} catch (e) {
  check('test ran to the end', false, e.stack || String(e));
} finally {
  await browser.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
finish();
