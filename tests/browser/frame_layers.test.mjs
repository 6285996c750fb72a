// Browser test of web/gl/frame.js: two studies' renderers as layers of ONE frame (one canvas, one
// orbit camera, one sun, one ground), as the garden (issue 33) will draw them. A sakura tree of 6
// years (the tree handler) and ivy grown on that same tree's bark (the ivy handler's scene 'tree',
// metres) are drawn together; each layer alone and both at once are compared, the ivy must lie
// where the tree is (one world frame), and the frame's sun must light both.
// The grove's renderer (the grove page's layer) joins the same frame beside the ivy: both drawn
// under the one camera and sun (read back from both layers) on the one ground.
// Run: node tests/browser/frame_layers.test.mjs (needs build/wasm's niwa_web). Screenshots:
// build/artifacts/frame-tree.png, frame-tree-ivy.png, frame-tree-ivy-low-sun.png, frame-tree-ivy-close.png,
// frame-grove-ivy.png, frame-grove-ivy-close.png and frame-bare-*.png (without the ground).
import { check, modulePage, runBrowserTest, saveCanvasPng, snapshotCanvas, snapshotDifference } from './harness.mjs';

const problems = [];

// The pixels of a snapshot drawn over the background (a frame without its ground): their share
// and box (x, y in [0, 1]), and the share of them that is drawn in snapshot `within` too.
const drawn = (page, name, within = null) => page.evaluate(([key, other]) => {
  const bg = [219, 230, 240];  // web/gl/context.js BACKGROUND
  const image = window.__snapshots[key], o = other ? window.__snapshots[other].data : null;
  const d = image.data, w = image.width, h = image.height;
  const isDrawn = (a, i) => Math.abs(a[i] - bg[0]) + Math.abs(a[i + 1] - bg[1]) + Math.abs(a[i + 2] - bg[2]) > 12;
  let n = 0, shared = 0, x0 = 1, x1 = 0, y0 = 1, y1 = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (!isDrawn(d, i)) continue;
    const x = ((i / 4) % w) / w, y = Math.floor(i / 4 / w) / h;
    ++n;
    if (o && isDrawn(o, i)) ++shared;
    x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  return { share: n / (w * h), within: n ? shared / n : 0, x0, x1, y0, y1 };
}, [name, within]);

await runBrowserTest(async (server, browser) => {
  const page = await modulePage(server, browser, problems);
  const setup = await page.evaluate(async () => {
    const { Frame } = await import('/web/gl/frame.js');
    const { Renderer } = await import('/web/tree/tree_renderer.js');
    const { IvyRenderer } = await import('/web/ivy/ivy_renderer.js');
    const { WorkerClient } = await import('/web/shell/worker_client.js');
    const canvas = document.createElement('canvas');
    canvas.id = 'frame-view';
    canvas.style.cssText = 'width: 640px; height: 480px; display: block';
    document.body.append(canvas);
    const frame = new Frame(canvas);
    await frame.init();
    const tree = await frame.addLayer(new Renderer(frame));
    const ivy = await frame.addLayer(new IvyRenderer(frame));
    // The two studies' worker handlers, one client each (one worker, one WASM instance).
    const treeClient = new WorkerClient('frame-tree');
    const ivyClient = new WorkerClient('frame-ivy', { study: 'ivy' });
    let support = null;
    ivyClient.on('support', (msg) => { support = msg; });
    const treeReply = await treeClient.request('update', { state: { preset: 'sakura', years: 6 } }, { done: ['tree'] }).reply;
    const ivyReply = await ivyClient.request('update', {
      state: { preset: 'metric', seed: 1, steps: 50, scene: 'tree', tree: 'sakura', tree_years: 6 },
    }, { done: ['ivy'] }).reply;
    if (treeReply?.type !== 'tree' || ivyReply?.type !== 'ivy' || !support) {
      return { error: `tree ${treeReply?.type} ${treeReply?.message || ''}, ivy ${ivyReply?.type} ${ivyReply?.message || ''}, support ${Boolean(support)}` };
    }
    await tree.setTree(treeReply.mesh, treeReply.stats.bounds, treeReply.swayNodes, treeReply.hybrid);
    ivy.setSupport(support.buffers, support.support.bounds);
    ivy.setVisible({ support: false, seeds: false });  // the tree layer draws the bark
    if (ivyReply.leafTexture) ivy.setLeafTexture(ivyReply.leafTexture);
    await ivy.setIvy(ivyReply.mesh);
    frame.frameAll();
    window.__frame = { frame, tree, ivy };
    return {
      layers: frame.layers.length, treeBounds: tree.worldBounds(), ivyBounds: ivy.worldBounds(),
      internodes: treeReply.stats.internodes, ivyInternodes: ivyReply.stats.internodes, supportName: support.support.name,
    };
  });
  check('tree and ivy grown for one frame', !setup.error && setup.layers === 2 && setup.internodes > 0 && setup.ivyInternodes > 10,
    setup.error || `${setup.internodes} tree internodes, ${setup.ivyInternodes} ivy internodes on ${setup.supportName}`);
  if (setup.error) return;
  // One world frame: the ivy's support (the tree's bark, metres) lies inside the tree's box.
  const inside = [0, 1, 2].every((i) => setup.ivyBounds.min[i] >= setup.treeBounds.min[i] - 0.05
    && setup.ivyBounds.max[i] <= setup.treeBounds.max[i] + 0.05);
  check('the ivy layer is in the tree layer\'s metres', inside, `ivy ${JSON.stringify(setup.ivyBounds)} tree ${JSON.stringify(setup.treeBounds)}`);

  // Draws the frame with `layers` (names), with or without its ground, in the sun [elevation,
  // azimuth], and keeps its pixels under `name` (and as build/artifacts/frame-NAME.png).
  const draw = async (name, layers, { ground = true, sun = [60, 0] } = {}) => {
    await page.evaluate(([names, g, s]) => {
      const { frame, tree, ivy } = window.__frame;
      frame.layers = names.map((n) => ({ tree, ivy })[n]);
      frame.showGround = g;
      frame.setSun(...s);
      frame.render();
    }, [layers, ground, sun]);
    await snapshotCanvas(page, name, '#frame-view');
    await saveCanvasPng(page, `frame-${name}.png`, '#frame-view');
  };
  // Without the ground: each layer's own pixels over the background.
  await draw('bare-tree', ['tree'], { ground: false });
  await draw('bare-ivy', ['ivy'], { ground: false });
  await draw('bare-tree-ivy', ['tree', 'ivy'], { ground: false });
  const tree = await drawn(page, 'bare-tree'), ivy = await drawn(page, 'bare-ivy', 'bare-tree');
  const both = await drawn(page, 'bare-tree-ivy');
  check('each layer alone draws something', tree.share > 0.01 && ivy.share > 0.0005, `tree ${(tree.share * 100).toFixed(2)}%, ivy ${(ivy.share * 100).toFixed(2)}% of the canvas`);
  const ivyOverTree = await snapshotDifference(page, 'bare-tree-ivy', 'bare-tree', 30);
  check('both layers show in the one canvas', ivyOverTree > 0.0002 && both.share >= tree.share,
    `${(ivyOverTree * 100).toFixed(3)}% of pixels change when the ivy layer joins the tree; drawn ${(tree.share * 100).toFixed(2)}% -> ${(both.share * 100).toFixed(2)}%`);
  // One camera, one world: the ivy lies on the tree (it climbs that tree's trunk; its leaves stand
  // out of the thin trunk, so most, not all, of its pixels are the tree's too).
  check('one camera: the ivy is drawn on the tree', ivy.within > 0.4 && ivy.x0 >= tree.x0 && ivy.x1 <= tree.x1 && ivy.y1 <= tree.y1 + 0.01,
    `${(ivy.within * 100).toFixed(1)}% of the ivy's pixels are tree pixels alone; ivy box x ${ivy.x0.toFixed(2)}-${ivy.x1.toFixed(2)} y ${ivy.y0.toFixed(2)}-${ivy.y1.toFixed(2)}, tree x ${tree.x0.toFixed(2)}-${tree.x1.toFixed(2)} y ${tree.y0.toFixed(2)}-${tree.y1.toFixed(2)}`);

  // With the one ground, under the one sun, high and low.
  await draw('tree', ['tree']);
  await draw('tree-ivy', ['tree', 'ivy']);
  await draw('tree-ivy-low-sun', ['tree', 'ivy'], { sun: [10, 0] });
  const groundShare = (await drawn(page, 'tree')).share;
  check('the frame draws one ground under the layers', groundShare > tree.share + 0.2, `drawn ${(tree.share * 100).toFixed(1)}% without the ground, ${(groundShare * 100).toFixed(1)}% with it`);
  // One sun: a low sun moves the shading and the shadow of the frame (every layer reads its light).
  await draw('bare-tree-ivy-low-sun', ['tree', 'ivy'], { ground: false, sun: [10, 0] });
  const sunOnLayers = await snapshotDifference(page, 'bare-tree-ivy', 'bare-tree-ivy-low-sun', 30);
  const sunOnGround = await snapshotDifference(page, 'tree-ivy', 'tree-ivy-low-sun', 30);
  check('the frame\'s sun lights the layers and the ground', sunOnLayers > 0.005 && sunOnGround > sunOnLayers,
    `${(sunOnLayers * 100).toFixed(2)}% of the layers' pixels, ${(sunOnGround * 100).toFixed(2)}% with the ground, change with the sun`);

  // Close up on the trunk's foot, where the ivy climbs (the trunk stands at the origin): for the eye.
  await page.evaluate(() => {
    const { frame, tree, ivy } = window.__frame;
    frame.layers = [tree, ivy];
    frame.showGround = true;
    frame.setSun(60, 0);
    frame.camera.frame({ min: [-0.3, 0, -0.3], max: [0.3, 1.2, 0.3] }, 1);
    frame.render();
  });
  await saveCanvasPng(page, 'frame-tree-ivy-close.png', '#frame-view');

  // The grove's renderer (web/tree/grove_renderer.js, the grove page's layer) and the ivy's in one
  // frame: one camera, one sun, one ground. The grove: a sakura of 6 years grown for it (its own
  // client of the tree handler, as the grove page's) drawn instanced in full mode at three places,
  // one of them the origin at scale 1, where the ivy climbs that same tree's bark.
  const grove = await page.evaluate(async () => {
    const { GroveRenderer } = await import('/web/tree/grove_renderer.js');
    const { WorkerClient } = await import('/web/shell/worker_client.js');
    const { frame } = window.__frame;
    const client = new WorkerClient('frame-grove');
    const reply = await client.request('update', { state: { preset: 'sakura', years: 6 } }, { done: ['tree'] }).reply;
    if (reply?.type !== 'tree') return { error: `grove tree ${reply?.type} ${reply?.message || ''}` };
    const layer = await frame.addLayer(new GroveRenderer(frame));
    layer.mode = 'full';
    const instances = new Float32Array([0, 0, 0, 1, -4.5, 0, 1.5, 0.8, 4, 0, -2, 1.2]);
    layer.addTree(0, reply.mesh, instances, null, reply.swayNodes, reply.stats.bounds);
    window.__frame.grove = layer;
    return { layers: frame.layers.length, bounds: layer.worldBounds(), instances: instances.length / 4 };
  });
  check('a grove layer is added to the same frame', !grove.error && grove.bounds && grove.bounds.max[0] - grove.bounds.min[0] > 8,
    grove.error || `${grove.layers} layers, grove box ${JSON.stringify(grove.bounds)}`);
  if (!grove.error) {
    // Draws the grove and/or the ivy under the one camera framed on them both, and reads back the
    // sun each layer was given and the frame's totals.
    const drawGroveIvy = async (name, layers, { ground = true, sun = [60, 0] } = {}) => {
      const out = await page.evaluate(([names, g, s]) => {
        const { frame, grove, ivy } = window.__frame;
        frame.layers = [grove, ivy];
        frame.frameAll();
        frame.layers = names.map((n) => ({ grove, ivy })[n]);
        frame.showGround = g;
        frame.setSun(...s);
        const drawn = frame.render();
        return {
          drawn: { triangles: drawn.triangles, drawCalls: drawn.drawCalls, instances: drawn.instances, layers: drawn.layers },
          frameLight: [...frame.light], groveLight: [...grove.light], ivyLight: [...ivy.light],
          sameCamera: grove.frame.camera === frame.camera && ivy.frame.camera === frame.camera,
        };
      }, [layers, ground, sun]);
      await snapshotCanvas(page, name, '#frame-view');
      await saveCanvasPng(page, `frame-${name}.png`, '#frame-view');
      return out;
    };
    const g = await drawGroveIvy('bare-grove', ['grove'], { ground: false });
    const i = await drawGroveIvy('bare-grove-ivy-only', ['ivy'], { ground: false });
    const gi = await drawGroveIvy('bare-grove-ivy', ['grove', 'ivy'], { ground: false });
    const groveShare = await drawn(page, 'bare-grove'), ivyShare = await drawn(page, 'bare-grove-ivy-only', 'bare-grove');
    const ivyOverGrove = await snapshotDifference(page, 'bare-grove-ivy', 'bare-grove', 30);
    // The 6-year ivy on the middle trunk is a few dozen pixels (about 30 without MSAA, which a CPU
    // rasteriser goes without: web/gl/context.js): more than 15 pixels of it, alone and over the grove.
    check('grove + ivy: both layers draw in the one canvas', groveShare.share > 0.01 && ivyShare.share > 0.00005 && ivyOverGrove > 0.00005,
      `grove ${(groveShare.share * 100).toFixed(2)}%, ivy ${(ivyShare.share * 100).toFixed(3)}% of the canvas; ${(ivyOverGrove * 100).toFixed(3)}% of pixels change when the ivy joins the grove`);
    check('grove + ivy: the frame counts both layers (triangles and draw calls add up)',
      gi.drawn.layers === 2 && g.drawn.instances === 3 && gi.drawn.triangles === g.drawn.triangles + i.drawn.triangles &&
      gi.drawn.drawCalls === g.drawn.drawCalls + i.drawn.drawCalls,
      `grove ${g.drawn.triangles} + ivy ${i.drawn.triangles} = ${gi.drawn.triangles} triangles, ${g.drawn.drawCalls} + ${i.drawn.drawCalls} = ${gi.drawn.drawCalls} draw calls, ${g.drawn.instances} grove instances`);
    check('grove + ivy: one camera (the ivy climbs the grove\'s tree at the origin)',
      gi.sameCamera && ivyShare.within > 0.4,
      `${(ivyShare.within * 100).toFixed(1)}% of the ivy's pixels are grove pixels alone`);
    // One sun: the frame's one direction, read back from both layers at two elevations; the low
    // sun changes the frame's pixels.
    const low = await drawGroveIvy('bare-grove-ivy-low-sun', ['grove', 'ivy'], { ground: false, sun: [10, 0] });
    const same = (a, b) => a.length === 3 && a.every((x, k) => x === b[k]);
    const lowLight = await page.evaluate(async () => {
      const { sunDirection } = await import('/web/gl/sun.js');
      return [...sunDirection(10, 0)];
    });
    const sunMoves = await snapshotDifference(page, 'bare-grove-ivy', 'bare-grove-ivy-low-sun', 30);
    check('grove + ivy: one sun, read back from both layers, lights them both',
      same(gi.groveLight, gi.frameLight) && same(gi.ivyLight, gi.frameLight) && same(low.groveLight, lowLight) && same(low.ivyLight, lowLight) &&
      !same(gi.frameLight, lowLight) && sunMoves > 0.005,
      `sun at 60°: grove ${gi.groveLight.map((x) => x.toFixed(3))}, ivy ${gi.ivyLight.map((x) => x.toFixed(3))}; at 10°: grove ${low.groveLight.map((x) => x.toFixed(3))}, ivy ${low.ivyLight.map((x) => x.toFixed(3))}; ${(sunMoves * 100).toFixed(2)}% of pixels change`);
    // With the frame's one ground under both (the grove's footprint: its 60 m square).
    await drawGroveIvy('grove-ivy', ['grove', 'ivy']);
    const withGround = (await drawn(page, 'grove-ivy')).share;
    check('grove + ivy: the frame draws one ground under both', withGround > groveShare.share + 0.2,
      `drawn ${(groveShare.share * 100).toFixed(1)}% without the ground, ${(withGround * 100).toFixed(1)}% with it`);
    // Close up on the foot of the grove's tree at the origin, where the ivy climbs: for the eye.
    await page.evaluate(() => {
      const { frame } = window.__frame;
      frame.camera.frame({ min: [-0.3, 0, -0.3], max: [0.3, 1.2, 0.3] }, 1);
      frame.render();
    });
    await saveCanvasPng(page, 'frame-grove-ivy-close.png', '#frame-view');
    await page.evaluate(() => {
      const { frame, grove } = window.__frame;
      frame.layers = [grove];
      frame.removeLayer(grove);  // disposed of: its programs and buffers freed
    });
  }

  // A layer removed is disposed of and no longer drawn: the tree alone again, pixel for pixel.
  const removed = await page.evaluate(() => {
    const { frame, tree, ivy } = window.__frame;
    frame.layers = [tree, ivy];
    frame.showGround = true;
    frame.setSun(60, 0);
    frame.frameAll();
    frame.removeLayer(ivy);
    frame.render();
    return { layers: frame.layers.length, programs: ivy.programs };
  });
  await snapshotCanvas(page, 'removed', '#frame-view');
  const sameAsTree = await snapshotDifference(page, 'removed', 'tree', 0);
  check('a removed layer is disposed of and not drawn', removed.layers === 1 && removed.programs === null && sameAsTree === 0,
    `${removed.layers} layers, ${(sameAsTree * 100).toFixed(3)}% of pixels differ from the tree alone`);
  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
