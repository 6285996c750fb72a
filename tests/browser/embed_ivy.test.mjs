// Browser test of <niwa-ivy> (public/niwa-ivy.js) on public/embed-ivy.html and the iframe form
// public/embed.html?study=ivy: node tests/browser/embed_ivy.test.mjs (exit 0 = pass). Three elements
// (cubes4 by attributes, a Niwa tree with animate, a wall by state=) share one worker and each
// grows what `niwa ivy grow` grows for the same input (--stats equal but the timings); animate
// replays the steps without regrowing; a bad attribute is one line in the element and a good one
// recovers; the iframe form grows the ivy page's hash. Screenshots: build/artifacts/embed-ivy*.png.
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { ARTIFACTS, NATIVE, TIMEOUT, check, hookLog, isConsecutiveRun, newContext, runBrowserTest, watchPage } from './harness.mjs';

const withoutMs = (stats) => Object.fromEntries(Object.entries(stats).filter(([k]) => k !== 'ms' && !k.startsWith('ms_')));
const nativeIvy = (args) => withoutMs(JSON.parse(execFileSync(NATIVE, ['ivy', 'grow', ...args, '--stats'], { encoding: 'utf8' }).trim()));

function waitElement(page, selector, hashAbove = '') {
  return page.waitForFunction(([sel, before]) => {
    const d = document.querySelector(sel)?.dataset;
    return d && (d.status === 'error' || (d.status === 'ready' && d.stats && d.stats !== before));
  }, [selector, hashAbove], { timeout: TIMEOUT, polling: 200 }).then(() => page.evaluate((sel) => ({ ...document.querySelector(sel).dataset }), selector));
}

function same(name, data, args) {
  const web = JSON.stringify(withoutMs(JSON.parse(data.stats || '{}')));
  const native = JSON.stringify(nativeIvy(args));
  check(name, web === native, web === native ? `${data.internodes} internodes, ${data.leaves} leaves` : `web ${web.slice(0, 200)} | native ${native.slice(0, 200)}`);
}

// Share of leaf-green pixels of an element's canvas.
const green = (page, selector) => page.evaluate((sel) => {
  const d = window.__niwaCanvasImage(`${sel} >>> canvas`).data;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i + 1] > d[i] + 25 && d[i + 1] > d[i + 2] + 25) ++n;
  return n / (d.length / 4);
}, selector);

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1500, height: 900 } });
  const page = await context.newPage();
  watchPage(page, problems);
  const workers = [];
  page.on('worker', (w) => workers.push(w.url()));
  await page.goto(`${server.url}embed-ivy.html`, { waitUntil: 'load' });

  const cubes = await waitElement(page, '#cubes');
  check('<niwa-ivy scene="cubes4" seed="3" steps="50"> grows', cubes.status === 'ready' && cubes.supportName === 'cubes4', `${cubes.status} ${cubes.supportName} ${cubes.error || ''}`);
  same('cubes4 element == niwa ivy grow --scene cubes4 --seed 3 --steps 50', cubes, ['--scene', 'cubes4', '--seed', '3', '--steps', '50']);
  const tree = await waitElement(page, '#tree');
  check('<niwa-ivy scene="tree" tree="sakura" tree-years="8"> climbs the tree', tree.status === 'ready' && tree.supportName === 'tree:sakura', `${tree.status} ${tree.supportName} ${tree.error || ''}`);
  same('tree element == niwa ivy grow --tree-preset sakura --tree-years 8 --steps 150', tree, ['--tree-preset', 'sakura', '--tree-years', '8', '--steps', '150']);
  const wall = await waitElement(page, '#wall');
  check('<niwa-ivy state="..scene=wall"> grows the hash', wall.status === 'ready' && wall.supportName === 'wall', `${wall.status} ${wall.supportName}`);
  same('wall element == niwa ivy grow --url', wall, ['--url', 'preset=improved&seed=2&steps=60&scene=wall']);
  check('the three share one worker', workers.length === 1, workers.join(', '));

  // animate: the tree element steps through its growth to the last step without regrowing.
  await page.waitForFunction(() => document.querySelector('#tree').dataset.stepShown === '150', null, { timeout: TIMEOUT });
  const shown = await hookLog(page, '#tree', 'data-step-shown');
  const treeGrows = (await hookLog(page, '#tree', 'data-hash')).length;  // set once per grown ivy
  check('animate replays the steps to the last', isConsecutiveRun(shown, 0, 150) && treeGrows === 1,
    `${shown.length} steps shown (${shown.slice(0, 3).join(', ')} ... ${shown.slice(-2).join(', ')}), ${treeGrows} grow(s)`);
  const cubesShown = await hookLog(page, '#cubes', 'data-step-shown');
  check('without animate the last step is shown at once', cubesShown.length === 1 && cubesShown[0] === '50', cubesShown.join(', '));
  // The tree's ivy is small beside the whole tree (metres, framed on the tree): a lower share.
  for (const [id, least] of [['cubes', 0.005], ['tree', 0.001], ['wall', 0.004]]) {
    const g = await green(page, `#${id}`);
    check(`#${id} draws leaves`, g > least, `green ${(g * 100).toFixed(2)}% (> ${least * 100}%)`);
  }
  // cubes4's grey cubes are drawn (the support reaches an element whose first request was
  // superseded by its attributes).
  const grey = await page.evaluate(() => {
    const d = window.__niwaCanvasImage('#cubes >>> canvas').data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[i + 1]) < 12 && Math.abs(d[i + 1] - d[i + 2]) < 12 && d[i] < 200 && d[i] > 60) ++n;
    return n / (d.length / 4);
  });
  check('#cubes draws its support', grey > 0.03, `grey ${(grey * 100).toFixed(1)}%`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'embed-ivy.png') });

  // A bad attribute is one line in the element; a good one recovers.
  await page.evaluate(() => document.querySelector('#cubes').setAttribute('steps', '-3'));
  const bad = await waitElement(page, '#cubes', cubes.stats);
  const line = await page.evaluate(() => document.querySelector('#cubes').shadowRoot.querySelector('p').textContent);
  check('steps="-3" is one line naming steps', bad.status === 'error' && /^steps: .*\[0, 10000\]/.test(line) && !line.includes('\n'), line);
  await page.evaluate(() => document.querySelector('#cubes').setAttribute('steps', '20'));
  const good = await waitElement(page, '#cubes', cubes.stats);
  check('steps="20" recovers', good.status === 'ready' && good.steps === '20', `${good.status} ${good.steps}`);
  same('cubes4 20 steps == CLI', good, ['--scene', 'cubes4', '--seed', '3', '--steps', '20']);

  // The iframe form grows the ivy page's hash.
  const frame = await context.newPage();
  watchPage(frame, problems);
  const hash = 'preset=metric&seed=4&steps=40&scene=tree&tree=maple&tree_years=6';
  await frame.goto(`${server.url}embed.html?study=ivy#${hash}`, { waitUntil: 'load' });
  const framed = await waitElement(frame, 'niwa-ivy');
  check('embed.html?study=ivy grows its hash', framed.status === 'ready' && framed.supportName === 'tree:maple', `${framed.status} ${framed.supportName} ${framed.error || ''}`);
  same('iframe == niwa ivy grow --url', framed, ['--url', hash]);
  await frame.screenshot({ path: path.join(ARTIFACTS, 'embed-ivy-frame.png') });

  // The same page without ?study is the tree's iframe form (README's snippet); an unknown study
  // is one line on the page.
  await frame.goto(`${server.url}embed.html#preset=maple&seed=2&years=5`, { waitUntil: 'load' });
  const treeFrame = await frame.waitForFunction(() => {
    const d = document.querySelector('niwa-tree')?.dataset;
    return d && (d.status === 'ready' || d.status === 'error') && { ...d };
  }, null, { timeout: TIMEOUT, polling: 200 }).then((h) => h.jsonValue());
  check('embed.html#HASH is a <niwa-tree>', treeFrame.status === 'ready' && Number(treeFrame.year) === 5, `${treeFrame.status} year ${treeFrame.year}`);
  const other = await context.newPage();  // not watched: the missing niwa-fern.js is a 404 on its console
  await other.goto(`${server.url}embed.html?study=fern#x=1`, { waitUntil: 'load' });
  const unknown = await other.waitForFunction(() => document.body.textContent.includes('Unknown'), null, { timeout: TIMEOUT })
    .then(() => other.evaluate(() => document.body.textContent));
  check('embed.html?study=fern (no such study) is one line naming it', unknown.includes('Unknown study "fern"'), unknown);

  check('no console errors or page errors', problems.length === 0, problems.join(' | '));
});
