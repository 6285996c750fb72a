// The card atlas painted in parts (paintAtlasInParts: the moving tree's cheap representation) is
// the atlas paintAtlas paints at once (the hybrid mode's), texel for texel, textures included: cut-
// out leaves and blossoms, bark colour from the worker's maps. A small synthetic atlas (three parts,
// a quad each, uvs over a textured disc) in Chromium's WebGL2, painted three ways.
// Run: node tests/browser/atlas_paint.test.mjs (no build needed: it loads web/ and shaders/ only).
import { check, modulePage, runBrowserTest } from './harness.mjs';

await runBrowserTest(async (server, browser) => {
  const problems = [];
  const page = await modulePage(server, browser, problems);
  const result = await page.evaluate(async () => {
    const { Renderer, createAtlasTarget, paintAtlas, paintAtlasInParts } = await import('/web/tree/tree_renderer.js');
    const { imageTexture } = await import('/web/gl/textures.js');
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 8;
    document.body.append(canvas);
    const renderer = new Renderer(canvas);
    await renderer.init();
    const gl = renderer.gl;
    const size = 64;
    // A 16 x 16 texture: an opaque disc (a leaf, a blossom) in a transparent square, its colour
    // changing across it, so both the cut-out and the uvs show in the atlas.
    const disc = (r, g, b) => {
      const pixels = new Uint8Array(16 * 16 * 4);
      for (let y = 0; y < 16; ++y) {
        for (let x = 0; x < 16; ++x) {
          const i = 4 * (y * 16 + x), inside = (x - 7.5) ** 2 + (y - 7.5) ** 2 < 36;
          pixels.set([r + 6 * x, g + 4 * y, b, inside ? 255 : 0], i);
        }
      }
      return { texture: imageTexture(gl, { width: 16, height: 16, pixels: pixels.buffer }, gl.CLAMP_TO_EDGE) };
    };
    const textures = { bark: disc(90, 60, 30), leaf: disc(40, 120, 30), flower: disc(200, 140, 160) };
    // One quad per part in atlas clip space (x, y in [-1, 1]), facing +z, uvs over the whole texture.
    const quad = (x0, y0, x1, y1) => ({
      positions: new Float32Array([x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0]).buffer,
      normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]).buffer,
      uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]).buffer,
      indices: new Uint32Array([0, 1, 2, 0, 2, 3]).buffer,
    });
    const hybrid = { atlasSize: size, bark: quad(-1, -1, 0, 0), leaves: quad(0, -1, 1, 0.5), flowers: quad(-0.9, 0.1, 0.6, 0.9) };
    const read = ({ fb }) => {
      const out = new Uint8Array(size * size * 4);
      gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
      gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, out);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      return out;
    };
    const light = [0.3, 0.8, 0.5];
    const whole = createAtlasTarget(gl, size), parts = createAtlasTarget(gl, size), plain = createAtlasTarget(gl, size);
    paintAtlas(gl, renderer.atlasProgram, hybrid, whole.fb, whole.texture, light, textures);
    // A budget of one triangle: every part's draw is split, each resumed after the GPU finished.
    const painted = await paintAtlasInParts(gl, renderer.atlasProgram, hybrid, parts.fb, parts.texture, light, null, 1, () => false, textures);
    await paintAtlasInParts(gl, renderer.atlasProgram, hybrid, plain.fb, plain.texture, light, null, 1, () => false, null);
    const a = read(whole), b = read(parts), c = read(plain);
    let differ = 0, plainDiffer = 0, holes = 0, covered = 0;
    for (let i = 0; i < a.length; i += 4) {
      if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2] || a[i + 3] !== b[i + 3]) ++differ;
      if (a[i] !== c[i] || a[i + 1] !== c[i + 1] || a[i + 2] !== c[i + 2] || a[i + 3] !== c[i + 3]) ++plainDiffer;
      if (a[i + 3] > 0) ++covered;
      if (c[i + 3] > 0 && a[i + 3] === 0) ++holes;  // a quad's corner cut out by the disc's alpha
    }
    return { painted, texels: size * size, differ, plainDiffer, covered, holes, error: gl.getError() };
  });
  check('the atlas painted in parts equals the one painted at once (textures included)',
    result.differ === 0 && result.painted === 6 && result.covered > 0,
    `${result.differ} of ${result.texels} texels differ; ${result.painted} triangles painted in parts; ${result.covered} texels covered`);
  check('the textures show: cut-out corners and texture colours, unlike the plain-colour atlas',
    result.holes > 100 && result.plainDiffer > 1000, `${result.holes} texels cut out, ${result.plainDiffer} differ from the plain atlas`);
  check('no GL error and no page error', result.error === 0 && problems.length === 0, `gl error ${result.error}; ${problems.join(' | ')}`);
});
