// Browser test of a dropped glTF's own look and its leaves' size on the ivy page (issue 31 item 7,
// item 4 where it touches it): node tests/browser/ivy_mesh_look.test.mjs (exit 0 = pass).
// 1. ez-tree's rock (tests/data/meshes/rock1.glb: Draco, its base colour a WebP) is drawn with its
//    texture: the support's pixels vary from pixel to pixel and take many shades, against the same
//    view with "Support texture" off (its colour only: flat). Screenshots build/artifacts/
//    ivy-rock-textured.png and ivy-rock-flat.png.
// 2. A glTF of two meshes under node transforms, one with COLOR_0 (red) and one with a
//    baseColorFactor (blue), no texture: both colours reach the screen (ivy-colours.png); and
//    ez-tree's flower (three PNG textures, a blue factor, seven primitives) decodes its textures.
// 3. The rock scaled by its node to 0.3 m and to 20 m across: the page's .glb leaves, measured
//    (blade width = |dp| / |duv| along a blade edge), are 4-12 cm on both (glTF is in metres),
//    while the growth's scale still comes from the bounds (ivy-rock-0.3m.png, ivy-rock-20m.png and
//    its close-up on the seed, ivy-rock-20m-close.png).
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, ROOT, TIMEOUT, check, newContext, panToColourAndZoom, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';
import { glbBytes, readGlb } from '../support/glb_bytes.mjs';

const MESHES = path.join(ROOT, 'tests/data/meshes');
const waitIvy = (page, serialAbove) => waitStudyRun(page, 'ivySerial', serialAbove);
const hooks = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));

// Drops `file` ({name, buffer}) on the page and waits for its ivy and its look.
async function drop(page, file) {
  const serial = Number((await hooks(page)).ivySerial);
  await page.setInputFiles('#mesh-file', { name: file.name, mimeType: 'model/gltf-binary', buffer: file.buffer });
  await page.waitForFunction(([name, n]) => {
    const d = document.documentElement.dataset;
    return d.supportName === name && Number(d.ivySerial) > n && d.supportLook === 'ready';
  }, [file.name, serial], { timeout: TIMEOUT, polling: 200 }).catch(() => {});
  return hooks(page);
}

// Waits for a frame drawn with the support texture hook at `state` ('on' or 'off').
async function drawnWith(page, state) {
  await page.waitForFunction((s) => document.documentElement.dataset.supportTexture === s, state, { timeout: TIMEOUT }).catch(() => {});
  await page.waitForTimeout(400);
}

// The canvas's pixels (kept in the page as window.__look[key]).
const grab = (page, key) => page.evaluate((k) => {
  (window.__look ||= {})[k] = window.__niwaCanvasImage('#view');
  return true;
}, key);

// Over the pixels that are not background in image a (the same view in b): per image, the share with
// detail (the pixel differs by more than 16, summed RGB, from the mean of the four pixels 3 away
// left, right, up and down, all inside: smooth lighting, linear across a few pixels, gives about
// 0; a texture's grain does not), the mean chroma (largest minus smallest channel), the distinct
// 5-bit shades, the share of red and of blue pixels, and the share at full white (every channel
// ≥ 250: lighting clipped).
const compare = (page, a, b) => page.evaluate(([ka, kb]) => {
  const bg = [219, 230, 240];
  const A = window.__look[ka], B = window.__look[kb];
  const w = A.width, h = A.height;
  const fore = (d, i) => Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30;
  // The support's pixels are image a's foreground: both images are the same view of the same mesh,
  // and a pale support in image b (the flat white rock, its lit side near the sky's colour) would
  // otherwise drop out of the comparison.
  const inside = (i) => fore(A.data, i);
  const measure = (d) => {
    let n = 0, probed = 0, detail = 0, chroma = 0, red = 0, blue = 0, white = 0;
    const shades = new Set();
    const at = (x, y) => 4 * (y * w + x);
    for (let y = 0; y < h; ++y) {
      for (let x = 0; x < w; ++x) {
        const i = at(x, y);
        if (!inside(i)) continue;
        ++n;
        shades.add(`${d[i] >> 3},${d[i + 1] >> 3},${d[i + 2] >> 3}`);
        chroma += Math.max(d[i], d[i + 1], d[i + 2]) - Math.min(d[i], d[i + 1], d[i + 2]);
        if (d[i] > d[i + 1] + 60 && d[i] > d[i + 2] + 60) ++red;
        if (d[i + 2] > d[i] + 60 && d[i + 2] > d[i + 1] + 40) ++blue;
        if (d[i] >= 250 && d[i + 1] >= 250 && d[i + 2] >= 250) ++white;
        if (x < 3 || y < 3 || x + 3 >= w || y + 3 >= h) continue;
        const around = [at(x - 3, y), at(x + 3, y), at(x, y - 3), at(x, y + 3)];
        if (!around.every(inside)) continue;
        ++probed;
        let off = 0;
        for (let c = 0; c < 3; ++c) off += Math.abs(d[i + c] - around.reduce((s, j) => s + d[j + c], 0) / 4);
        if (off > 16) ++detail;
      }
    }
    return {
      share: n / (w * h), detail: detail / Math.max(1, probed), chroma: chroma / Math.max(1, n), shades: shades.size,
      red: red / Math.max(1, n), blue: blue / Math.max(1, n), white: white / Math.max(1, n),
    };
  };
  return { a: measure(A.data), b: measure(B.data) };
}, [a, b]);

// The rock with its node scaled so that it is about `metres` across (the node's rotation aside).
function scaledRock(metres) {
  const { json, bin } = readGlb(fs.readFileSync(path.join(MESHES, 'rock1.glb')));
  const position = json.accessors[json.meshes[0].primitives[0].attributes.POSITION];
  const node = json.nodes[0];
  const extent = Math.max(...[0, 1, 2].map((i) => (position.max[i] - position.min[i]) * node.scale[i]));
  node.scale = node.scale.map((s) => (s * metres) / extent);
  node.translation = [0, 0, 0];
  return { name: `rock-${metres}m.glb`, buffer: glbBytes(JSON.stringify(json), Buffer.from(bin)), extent: metres };
}

// Two meshes under node transforms, no texture: a quad with COLOR_0 red (material without a
// factor), and a quad with baseColorFactor blue, side by side in the x-y plane facing +z.
function colouredQuads() {
  const quad = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0];
  const bin = Buffer.alloc(48 + 48 + 64 + 12);
  quad.forEach((v, i) => bin.writeFloatLE(v, 4 * i));
  quad.forEach((_, i) => bin.writeFloatLE([0, 0, 1][i % 3], 48 + 4 * i));  // normals
  for (let v = 0; v < 4; ++v) [0.9, 0.05, 0.05, 1].forEach((c, k) => bin.writeFloatLE(c, 96 + 16 * v + 4 * k));
  [0, 1, 2, 0, 2, 3].forEach((k, i) => bin.writeUInt16LE(k, 160 + 2 * i));
  const json = {
    asset: { version: '2.0' },
    buffers: [{ byteLength: bin.length }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: 48 }, { buffer: 0, byteOffset: 48, byteLength: 48 },
      { buffer: 0, byteOffset: 96, byteLength: 64 }, { buffer: 0, byteOffset: 160, byteLength: 12 },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 4, type: 'VEC3', min: [0, 0, 0], max: [1, 1, 0] },
      { bufferView: 1, componentType: 5126, count: 4, type: 'VEC3' },
      { bufferView: 2, componentType: 5126, count: 4, type: 'VEC4' },
      { bufferView: 3, componentType: 5123, count: 6, type: 'SCALAR' },
    ],
    materials: [{ name: 'painted' }, { name: 'blue', pbrMetallicRoughness: { baseColorFactor: [0.05, 0.1, 0.9, 1] } }],
    meshes: [
      { name: 'red', primitives: [{ attributes: { POSITION: 0, NORMAL: 1, COLOR_0: 2 }, indices: 3, material: 0 }] },
      { name: 'blue', primitives: [{ attributes: { POSITION: 0, NORMAL: 1 }, indices: 3, material: 1 }] },
    ],
    nodes: [
      { children: [1, 2], translation: [5, 0, 0] },
      { mesh: 0, scale: [1.5, 2, 1] },
      { mesh: 1, translation: [1.6, 0, 0], scale: [1.5, 2, 1] },
    ],
    scenes: [{ nodes: [0] }],
    scene: 0,
  };
  return { name: 'quads.glb', buffer: glbBytes(JSON.stringify(json), bin) };
}

// Blade widths (scene units) of the leaves in a .glb: along each blade triangle's longest uv edge,
// |dp| / |duv| (the blade is the outline's unit coordinates times its width; core/ivy/ivy_mesh.cpp).
function bladeWidths(bytes) {
  const glb = readGlb(bytes);
  const mesh = glb.json.meshes.find((m) => m.name === 'ivy_leaves');
  if (!mesh) return [];
  const prim = mesh.primitives[0];
  const p = glb.floats(prim.attributes.POSITION), uv = glb.floats(prim.attributes.TEXCOORD_0), ix = glb.indices(prim.indices);
  const widths = [];
  for (let t = 0; t + 2 < ix.length; t += 3) {
    let best = 0, width = 0;
    for (let e = 0; e < 3; ++e) {
      const a = ix[t + e], b = ix[t + ((e + 1) % 3)];
      const duv = Math.hypot(uv[2 * a] - uv[2 * b], uv[2 * a + 1] - uv[2 * b + 1]);
      if (duv > best) {
        best = duv;
        width = Math.hypot(p[3 * a] - p[3 * b], p[3 * a + 1] - p[3 * b + 1], p[3 * a + 2] - p[3 * b + 2]) / duv;
      }
    }
    if (best > 0.1) widths.push(width);
  }
  return widths.sort((x, y) => x - y);
}
const quantile = (sorted, q) => (sorted.length ? sorted[Math.floor(q * (sorted.length - 1))] : NaN);

// Pans the seed marker (orange) to the view's centre, zooms in and saves the canvas as `file`:
// the leaves of a big mesh, a few pixels in the whole view.
async function closeUpOnSeed(page, file) {
  // The seed marker's orange.
  await panToColourAndZoom(page, '(r, g, b) => r > 200 && g > 80 && g < 170 && b < 90');
  await page.waitForTimeout(1200);
  await saveCanvasPng(page, file);
  await page.click('#reset-view');
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 760 }, acceptDownloads: true });
  const page = await context.newPage();
  watchPage(page, problems);
  await page.goto(`${server.url}ivy.html`, { waitUntil: 'load' });
  const opened = await waitIvy(page, 0);
  // No ivy while the supports' looks are compared (its stems would be pixels of both images).
  const steps = await page.inputValue('#steps');
  await page.fill('#steps', '0');
  await waitIvy(page, Number(opened.ivySerial));

  // 1. The rock: its WebP base colour reaches the screen.
  let data = await drop(page, { name: 'rock1.glb', buffer: fs.readFileSync(path.join(MESHES, 'rock1.glb')) });
  check('the rock is dropped and grown', data.supportName === 'rock1.glb' && data.status === 'ready', `${data.supportName} ${data.status} ${data.meshError || ''}`);
  check('its base colour WebP is decoded and uploaded', data.supportTextures === '1' && data.supportTextureFailures === '',
    `textures ${data.supportTextures}, materials ${data.supportMaterials}, failures '${data.supportTextureFailures}'`);
  for (const id of ['#show-leaves', '#show-suckers', '#show-seeds']) await page.uncheck(id);
  await drawnWith(page, 'on');
  await grab(page, 'rock-textured');
  await saveCanvasPng(page, 'ivy-rock-textured.png');
  await page.uncheck('#show-support-texture');
  await drawnWith(page, 'off');
  await grab(page, 'rock-flat');
  await saveCanvasPng(page, 'ivy-rock-flat.png');
  const rock = await compare(page, 'rock-textured', 'rock-flat');
  check('the rock fills a good part of the view', rock.a.share > 0.1, `${(rock.a.share * 100).toFixed(1)}% of the canvas`);
  check('textured, the rock has grain (pixels off their neighbours\' mean); flat, it has not',
    rock.a.detail > 0.03 && rock.a.detail > 3 * rock.b.detail,
    `${(rock.a.detail * 100).toFixed(1)}% of its pixels with detail textured, ${(rock.b.detail * 100).toFixed(1)}% flat`);
  check('textured, the rock takes its colours (moss green, grey stone); flat, its colour only (white)', rock.a.chroma > 20 && rock.a.chroma > 3 * rock.b.chroma,
    `mean chroma ${rock.a.chroma.toFixed(1)} textured, ${rock.b.chroma.toFixed(1)} flat; ${rock.a.shades} and ${rock.b.shades} shades`);
  check('flat, the white rock keeps its shading where the sun is (at most 2 % of it at full white)', rock.b.white <= 0.02,
    `${(rock.b.white * 100).toFixed(1)}% of the flat rock's pixels at full white`);
  await page.check('#show-support-texture');

  // 2. Vertex colours and a factor, no texture, under node transforms; then the flower's PNGs.
  data = await drop(page, colouredQuads());
  check('the two-mesh glTF is dropped and grown', data.supportName === 'quads.glb' && data.status === 'ready', `${data.supportName} ${data.status} ${data.meshError || ''}`);
  await page.waitForTimeout(600);
  await grab(page, 'quads');
  await saveCanvasPng(page, 'ivy-colours.png');
  const quads = await compare(page, 'quads', 'quads');
  check('its COLOR_0 (red) and its baseColorFactor (blue) reach the screen', quads.a.red > 0.2 && quads.a.blue > 0.2,
    `red ${(quads.a.red * 100).toFixed(1)}%, blue ${(quads.a.blue * 100).toFixed(1)}% of the support's pixels`);
  data = await drop(page, { name: 'flower_blue.glb', buffer: fs.readFileSync(path.join(MESHES, 'flower_blue.glb')) });
  check("ez-tree's flower decodes its three PNG base colours", data.supportTextures === '3' && data.supportMaterials === '7' && data.supportTextureFailures === '',
    `textures ${data.supportTextures}, materials ${data.supportMaterials}, failures '${data.supportTextureFailures}'`);
  await page.waitForTimeout(600);
  await saveCanvasPng(page, 'ivy-flower.png');

  // 3. Leaves in metres on the rock at 0.3 m and at 20 m.
  for (const id of ['#show-leaves', '#show-suckers', '#show-seeds']) await page.check(id);
  await page.fill('#steps', steps);
  const leaves = {};
  for (const metres of [0.3, 20]) {
    const file = scaledRock(metres);
    data = await drop(page, file);
    // (artist's leaf_spacing: about one leaf in 5 cm of stem, so the small rock's 1.25 cm
    // internodes share a leaf between about four buds; docs/ivy-model.md "Leaves a real length apart")
    const ok = data.supportName === file.name && data.status === 'ready' && Number(data.leaves) >= 10;
    check(`the rock at ${metres} m grows leaves`, ok, `${data.supportName} ${data.status} ${data.leaves} leaves ${data.meshError || data.error || ''}`);
    const k = Number(data.supportPxPerUnit);
    check(`at ${metres} m the growth's scale is read from its bounds and the leaves' is the glTF's metres`,
      Math.abs(k * metres / 1200 - 1) < 0.35 && data.supportLookPxPerUnit === '1000', `px per unit ${k}, leaves ${data.supportLookPxPerUnit}`);
    await page.waitForTimeout(600);
    await saveCanvasPng(page, `ivy-rock-${metres}m.png`);
    if (metres === 20) await closeUpOnSeed(page, 'ivy-rock-20m-close.png');
    const [d] = await Promise.all([page.waitForEvent('download', { timeout: TIMEOUT }), page.click('#download-glb')]);
    const out = path.join(ARTIFACTS, `ivy-rock-${metres}m.glb`);
    await d.saveAs(out);
    const widths = bladeWidths(fs.readFileSync(out));
    leaves[metres] = { n: widths.length, p50: quantile(widths, 0.5), p90: quantile(widths, 0.9) };
  }
  const says = (l) => `${l.n} blade triangles, median ${(l.p50 * 100).toFixed(1)} cm, 90th percentile ${(l.p90 * 100).toFixed(1)} cm`;
  for (const metres of [0.3, 20]) {
    const l = leaves[metres];
    check(`the leaves on the ${metres} m rock are 4-12 cm (90th percentile of the blade widths)`, l.n > 100 && l.p90 >= 0.04 && l.p90 <= 0.12, says(l));
  }
  check('the same leaves on a rock 67 times bigger (within a factor 2)', Math.max(leaves[0.3].p90, leaves[20].p90) / Math.min(leaves[0.3].p90, leaves[20].p90) < 2,
    `${says(leaves[0.3])} | ${says(leaves[20])}`);

  check('no console errors, page errors or external requests', problems.length === 0, problems.join(' | '));
});
