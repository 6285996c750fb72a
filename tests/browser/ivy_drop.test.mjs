// Browser test of the ivy page as a new user meets it with a mesh of their own (issue 31 items 4 and
// 7): node tests/browser/ivy_drop.test.mjs (exit 0 = pass). The Stanford bunny (tests/data/meshes/
// bunny.obj, 9.9 units across) dropped on the view grows at the scale read from its bounds with
// the default preset, and its page --stats equal the native CLI's for the same file; the Scene
// select shows the dropped file; Copy link says plainly that the mesh is not in the link, and the
// link opens on cubes4 without an error; Undo/Redo step through the committed edits; on the tree
// scene the progress line moves through the tree's years and says when the ivy is measured.
// Screenshots: build/artifacts/ivy-bunny.png (support shown) and ivy-bunny-close.png.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {
  NATIVE, ROOT, TIMEOUT, check, newContext, runBrowserTest, saveCanvasPng, waitStudyRun, watchPage,
} from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));

const waitIvy = (page, serialAbove) => waitStudyRun(page, 'ivySerial', serialAbove);

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 760 } });
  const page = await context.newPage();
  watchPage(page, problems);
  await page.goto(`${server.url}ivy.html`, { waitUntil: 'load' });
  let data = await waitIvy(page, 0);
  check('opens with cubes4 grown', data.status === 'ready' && data.supportName === 'cubes4', `${data.status} ${data.supportName}`);
  check('Undo and Redo start disabled', data.canUndo === 'false' && data.canRedo === 'false', `${data.canUndo} ${data.canRedo}`);

  // 1. Undo/Redo over committed edits: steps 50 -> 30 -> Undo (50) -> Redo (30).
  let serial = Number(data.ivySerial);
  await page.fill('#steps', '30');
  data = await waitIvy(page, serial);
  await page.waitForFunction(() => document.documentElement.dataset.canUndo === 'true', null, { timeout: TIMEOUT }).catch(() => {});
  const undoEnabled = await page.evaluate(() => !document.getElementById('undo').disabled);
  check('an edit enables Undo', undoEnabled && data.steps === '30', `undo enabled ${undoEnabled}, steps ${data.steps}`);
  serial = Number(data.ivySerial);
  await page.click('#undo');
  data = await waitIvy(page, serial);
  const afterUndo = await page.inputValue('#steps');
  check('Undo goes back to the state before the edit', afterUndo === '50' && data.steps === '50' && /steps=50/.test(data.hash), `field ${afterUndo}, grown ${data.steps}, ${data.hash}`);
  await page.waitForFunction(() => !document.getElementById('redo').disabled, null, { timeout: TIMEOUT }).catch(() => {});
  serial = Number(data.ivySerial);
  await page.click('#redo');
  data = await waitIvy(page, serial);
  const afterRedo = await page.inputValue('#steps');
  check('Redo brings the edit back', afterRedo === '30' && data.steps === '30', `field ${afterRedo}, grown ${data.steps}`);

  // 2. The bunny dropped: grown at the scale of its bounds, the Scene select names it, stats == CLI.
  serial = Number(data.ivySerial);
  const file = path.join(ROOT, 'tests/data/meshes/bunny.obj');
  await page.setInputFiles('#mesh-file', file);
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    return d.supportName === 'bunny.obj' && Number(d.ivySerial) > n;
  }, serial, { timeout: TIMEOUT, polling: 200 }).catch(() => {});
  data = await waitIvy(page, serial);
  check('the bunny grows ivy with the default preset (scale from its bounds)', data.status === 'ready' && data.supportName === 'bunny.obj' && Number(data.internodes) > 10,
    `${data.supportName}: ${data.internodes} internodes ${data.error || data.meshError || ''}`);
  const selected = await page.evaluate(() => { const s = document.getElementById('scene'); return s.options[s.selectedIndex]?.textContent || ''; });
  check('the Scene select shows the dropped file', selected.startsWith('bunny.obj (dropped'), selected);
  const notice = await page.textContent('#notice');
  check('the notice gives the scale read from its size', /px per unit from its size/.test(notice) && notice.includes('not part of the link'), notice);
  if (data.status === 'ready') {
    const native = JSON.parse(execFileSync(NATIVE, ['ivy', 'grow', '--mesh', file, '--url', data.hash, '--stats'], { encoding: 'utf8' }).trim());
    const web = withoutMs(JSON.parse(data.stats));
    const same = JSON.stringify(web) === JSON.stringify(withoutMs(native));
    check('bunny: page --stats == native CLI --mesh --url', same, same ? `${web.internodes} internodes` : `${JSON.stringify(web).slice(0, 200)} vs ${JSON.stringify(withoutMs(native)).slice(0, 200)}`);
  }
  await page.waitForTimeout(300);
  await saveCanvasPng(page, 'ivy-bunny.png');
  const box = await page.locator('#view').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let i = 0; i < 3; ++i) await page.mouse.wheel(0, -240);
  await page.waitForTimeout(800);
  await saveCanvasPng(page, 'ivy-bunny-close.png');

  // 3. Copy link on the dropped mesh: plain words, and a link that opens without an error.
  await page.click('#copy-link');
  await page.waitForFunction(() => document.getElementById('share-status').textContent.includes('not in the link'), null, { timeout: 10_000 }).catch(() => {});
  const status = await page.textContent('#share-status');
  check('Copy link says the dropped mesh is not in the link', status.includes('The dropped mesh bunny.obj is not in the link') && status.includes('cubes4'), status);
  const link = await page.evaluate(() => location.href);
  check('the link holds no seed point of the mesh', !/[#&]at=/.test(link), link);
  const opened = await context.newPage();
  const openedProblems = [];
  watchPage(opened, openedProblems);
  await opened.goto(link, { waitUntil: 'load' });
  const o = await waitIvy(opened, 0);
  const openedNotice = await opened.textContent('#notice');
  check('the link opens on cubes4 without an error', o.status === 'ready' && o.supportName === 'cubes4' && !o.error && !/seed/.test(openedNotice),
    `${o.status} ${o.supportName} error '${o.error || ''}' notice '${openedNotice}'`);
  await opened.close();
  problems.push(...openedProblems);

  // 4. The tree scene: the progress line moves through the tree's years, then the measuring.
  const texts = [];
  await page.exposeFunction('__ivyProgressText', (t) => texts.push(t));
  await page.evaluate(() => {
    new MutationObserver(() => window.__ivyProgressText(document.getElementById('progress').textContent))
      .observe(document.getElementById('progress'), { childList: true, characterData: true, subtree: true });
  });
  serial = Number((await page.evaluate(() => ({ ...document.documentElement.dataset }))).ivySerial);
  await page.selectOption('#scene', 'tree');
  data = await waitIvy(page, serial);
  const shown = texts.filter(Boolean);
  check('the tree scene grows ivy', data.status === 'ready' && data.supportName.startsWith('tree:'), `${data.status} ${data.supportName} ${data.error || ''}`);
  check('the progress line goes through the tree, its bark, the growth and the measuring',
    shown.some((t) => /year \d+ of \d+/.test(t)) && shown.some((t) => t.startsWith("building the tree's bark")) && shown.some((t) => /step \d+ of/.test(t)) && shown.includes('measuring the ivy (statistics)'),
    [...new Set(shown)].slice(0, 14).join(' | '));
  const dropped = await page.evaluate(() => [...document.getElementById('scene').options].some((o) => o.value === '(dropped)'));
  check('picking a scene takes the dropped file off the select', !dropped, String(dropped));

  check('no console errors, page errors or external requests', problems.length === 0, problems.join(' | '));
});
