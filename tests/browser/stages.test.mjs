// Browser test of stage-aware edits on the tree page: node tests/browser/stages.test.mjs.
// An edit of a wind or sway row (stage "sway") or a render row (stage "view") must not regrow the
// tree: the page's study controller sends 'update' with that stage and the worker re-skins or
// re-views the tree it has. A growth row regrows it once. Counts from the page's hooks:
// data-grow-requests (updates of stage 'grow'), data-restage-requests (of a later stage) and
// data-trees-grown (trees the worker grew, from each tree's `grown`).
import path from 'node:path';
import {
  ARTIFACTS, TIMEOUT, check, nativeStats, newContext, runBrowserTest, waitReady, watchPage,
} from './harness.mjs';

const problems = [];
const hooks = (page) => page.evaluate(() => {
  const d = document.documentElement.dataset;
  return { grows: Number(d.growRequests), restages: Number(d.restageRequests), grown: Number(d.treesGrown),
    serial: Number(d.treeSerial), internodes: d.internodes, renderMode: d.renderMode, views: Number(d.renderViews || 0),
    reused: Number(d.buffersReused), fresh: Number(d.buffersFresh), stages: d.restagedStages,
    poseReused: Number(d.poseBuffersReused || 0), poseFresh: Number(d.poseBuffersFresh || 0),
    viewReused: Number(d.viewBuffersReused || 0), viewFresh: Number(d.viewBuffersFresh || 0) };
});

// Fills a panel field (opening its section first) and waits for the tree that answers it.
async function edit(page, key, value) {
  const before = await hooks(page);
  await page.evaluate((k) => { document.getElementById(`param-${k}`).closest('details').open = true; }, key);
  await page.fill(`#param-${key}`, value);
  await waitReady(page, before.serial, 100);
  return { before, after: await hooks(page), hash: await page.evaluate(() => location.hash) };
}

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1100, height: 760 } });
  const page = watchPage(await context.newPage(), problems);
  await page.goto(`${server.url}#preset=keyaki-thesis&seed=1&years=6`);
  await waitReady(page, 0, 100);
  const start = await hooks(page);
  check('the first tree is one grow', start.grows === 1 && start.grown === 1 && start.restages === 0, JSON.stringify(start));

  // Group titles come from the table's group_title (the page's own fallback would say "Shape").
  const titles = await page.evaluate(() => [...document.querySelectorAll('#params summary')].map((s) => s.textContent));
  check('section titles from the table', titles.some((t) => t.startsWith('Shape and limits (')) && titles.some((t) => t.startsWith('Wind (')),
    titles.join(' | '));

  // A wind row: no grow, the same tree, the new value in the URL, and the wind blows with it.
  const wind = await edit(page, 'wind_speed', '9');
  check('a wind edit sends no grow', wind.after.grows === wind.before.grows && wind.after.grown === wind.before.grown,
    `grow requests ${wind.before.grows} -> ${wind.after.grows}, grown ${wind.before.grown} -> ${wind.after.grown}`);
  check('a wind edit is one restage', wind.after.restages === wind.before.restages + 1, `${wind.before.restages} -> ${wind.after.restages}`);
  // The stages the run re-did (core TreeRun::Update through the session's update): sway and after.
  check('a wind edit re-does the sway and view stages', wind.after.stages === 'sway,view', `stages '${wind.after.stages}'`);
  check('a wind edit keeps the tree', wind.after.internodes === start.internodes, `${start.internodes} -> ${wind.after.internodes}`);
  check('a wind edit is in the URL', wind.hash.includes('wind_speed=9'), wind.hash);
  // The first tree's buffers went into fresh ones; the page handed them back once on the GPU, and
  // the restaged tree (the same mesh sizes) was copied into them: no fresh buffer
  // (web/worker/transfer.js TransferPool).
  check('the first tree comes in fresh buffers', start.fresh >= 10 && start.reused === 0, `fresh ${start.fresh}, reused ${start.reused}`);
  check('the restaged tree reuses the returned buffers', wind.after.reused === start.fresh && wind.after.fresh === 0,
    `fresh ${wind.after.fresh}, reused ${wind.after.reused} (first tree: ${start.fresh} fresh)`);
  await page.click('#wind');
  await page.waitForFunction(() => Number(document.documentElement.dataset.swayTime || 0) > 2, null, { timeout: TIMEOUT, polling: 100 });
  const info = await page.textContent('#wind-info');
  check('the sway blows with the edited wind', /wind 9\.0 m\/s/.test(info), info);
  // Each pose is copied into the poses buffer the page handed back after uploading the last one.
  const blowing = await hooks(page);
  check('the poses reuse the returned buffer', blowing.poseFresh <= 2 && blowing.poseReused >= 5,
    `${blowing.poseFresh} fresh, ${blowing.poseReused} reused pose buffers`);
  // A sway row while it blows: re-skinned (eq. 3.15's exponent), still no grow, still blowing.
  const sway = await edit(page, 'sway_alpha', '3');
  await page.waitForFunction(() => Number(document.documentElement.dataset.swayTime || 0) > 1.5, null, { timeout: TIMEOUT, polling: 100 });
  check('a sway edit sends no grow and the sway goes on', sway.after.grows === sway.before.grows && sway.after.grown === sway.before.grown
    && (await page.getAttribute('#wind', 'aria-pressed')) === 'true', `grow requests ${sway.before.grows} -> ${sway.after.grows}`);
  await page.click('#wind');

  // A bad wind value: the core's one line naming the field, no grow; a good value recovers.
  const badBefore = await hooks(page);
  await page.fill('#param-wind_speed', '1000');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const notice = await page.textContent('#notice');
  const bad = await hooks(page);
  check('a bad wind value shows the core error and grows nothing', /^wind_speed\b.*\[0, 100\]/.test(notice.trim()) && bad.grows === badBefore.grows,
    `${notice.trim()}; grow requests ${badBefore.grows} -> ${bad.grows}`);
  await page.fill('#param-wind_speed', '9');
  await waitReady(page, bad.serial, 100);
  check('a good wind value recovers', !(await page.isVisible('#notice')) && (await hooks(page)).grows === badBefore.grows);

  // A render row: hybrid mode from the tree already grown (its atlas and draw list, no grow).
  const beforeMode = await hooks(page);
  await page.selectOption('#render-mode', '1');
  await waitReady(page, beforeMode.serial, 100);
  await page.waitForFunction((n) => Number(document.documentElement.dataset.renderViews || 0) > n, beforeMode.views, { timeout: TIMEOUT, polling: 100 });
  const hybrid = await hooks(page);
  check('render mode switches without a grow', hybrid.grows === beforeMode.grows && hybrid.grown === beforeMode.grown && hybrid.renderMode === 'hybrid',
    `grow requests ${beforeMode.grows} -> ${hybrid.grows}, mode ${hybrid.renderMode}`);
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'stages-hybrid.png') });
  const lines = await edit(page, 'line_threshold', '8');
  check('a render row edit sends no grow', lines.after.grows === lines.before.grows && lines.after.grown === lines.before.grown
    && lines.hash.includes('line_threshold=8'), `${lines.before.grows} -> ${lines.after.grows}; ${lines.hash}`);
  check('a render row edit re-does the view stage only', lines.after.stages === 'view', `stages '${lines.after.stages}'`);
  // The draw lists (cards and lines) are copied into the buffers the page handed back after the last.
  await page.waitForFunction((n) => Number(document.documentElement.dataset.renderViews || 0) > n, lines.before.views, { timeout: TIMEOUT, polling: 100 });
  const views = await hooks(page);
  check('the draw lists reuse the returned buffers', views.viewReused > 0, `${views.viewFresh} fresh, ${views.viewReused} reused draw-list buffers`);
  // A mesh row (leaf_shape): the mesh is rebuilt on the same tree, no grow.
  const shape = await edit(page, 'leaf_shape', '2');
  check('a mesh row edit re-does mesh, sway and view, not the growth', shape.after.stages === 'mesh,sway,view'
    && shape.after.grows === shape.before.grows && shape.after.grown === shape.before.grown && shape.after.internodes === shape.before.internodes,
    `stages '${shape.after.stages}', grow requests ${shape.before.grows} -> ${shape.after.grows}, internodes ${shape.before.internodes} -> ${shape.after.internodes}`);

  // A growth row: exactly one grow, and the tree equals the native CLI's.
  const growth = await edit(page, 'alpha_l', '0.6');
  check('a growth edit sends one grow', growth.after.grows === growth.before.grows + 1 && growth.after.grown === growth.before.grown + 1,
    `grow requests ${growth.before.grows} -> ${growth.after.grows}, grown ${growth.before.grown} -> ${growth.after.grown}`);
  const native = nativeStats(['--preset', 'keyaki-thesis', '--seed', '1', '--years', '6', '--set', 'alpha_l=0.6']);
  check('the regrown tree equals the native CLI', growth.after.internodes === String(native.internodes),
    `web ${growth.after.internodes} native ${native.internodes}`);

  // A wind edit and a growth edit within one debounce: one grow that carries both.
  const both = await hooks(page);
  await page.evaluate(() => {  // both inside one 250 ms debounce, whatever the machine's load
    for (const [key, value] of [['wind_speed', '4'], ['alpha_l', '0.5']]) {
      const input = document.getElementById(`param-${key}`);
      input.value = value;
      input.dispatchEvent(new Event('input', { bubbles: true }));
    }
  });
  await waitReady(page, both.serial, 100);
  const after = await hooks(page);
  const hash = await page.evaluate(() => location.hash);
  check('pending wind + growth edits make one grow', after.grows === both.grows + 1 && after.restages === both.restages
    && hash.includes('wind_speed=4') && hash.includes('alpha_l=0.5'), `${both.grows} -> ${after.grows}; ${hash}`);

  // Undo walks back through the restaged edits too (each committed edit is one history entry).
  const undoBefore = await hooks(page);
  await page.click('#undo');
  await waitReady(page, undoBefore.serial, 100);
  check('Undo restores the previous edit', (await page.inputValue('#param-alpha_l')) === '0.6'
    && (await page.inputValue('#param-wind_speed')) === '9', await page.evaluate(() => location.hash));

  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
