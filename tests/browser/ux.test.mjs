// Browser test of the tree page's rough edges and Getting started panel (issue 17 items 6 and 8):
// node tests/browser/ux.test.mjs (exit 0 = pass). Getting started controls generated from the
// table's simple rows; help on focus and on tap; an error beside its field and the "stale" label;
// the trunk cut refused and no .glb of an empty tree; a slider drag grows only the latest value;
// typing waits for its quiet moment and a committed value (change) goes at once;
// long tasks of a 30 -> 15 year change (numbers to build/artifacts/ux-longtasks.json; only under
// scripts/bench, NIWA_TIMED=1); Blow moves
// at once; touch targets >= 44 px and tap-to-cut at a phone viewport. Screenshots:
// build/artifacts/ux-*.png.
// Its answer times are speed goals (harness.mjs timedCheck): checked by scripts/bench with NIWA_TIMED=1,
// guarded only against a hang here.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, TIMED, TIMEOUT, check, nativeStats, newContext, pickAt, runBrowserTest, snapshotCanvas, snapshotDifference, timedCheck,
  waitReady, watchPage,
} from './harness.mjs';

const problems = [];
const dataset = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));
const serialOf = async (page) => Number((await dataset(page)).treeSerial || 0);
const BASE = ['--preset', 'sakura-thesis', '--seed', '1', '--years', '8'];
const HASH = '#preset=sakura-thesis&seed=1&years=8';

async function andWait(page, action) {
  const serial = await serialOf(page);
  await action();
  await waitReady(page, serial, 100);
}

// Box of a selector's element in CSS px: {x, y, width, height, visible}.
const box = (page, selector) => page.evaluate((sel) => {
  const e = document.querySelector(sel);
  if (!e) return null;
  const r = e.getBoundingClientRect();
  const style = getComputedStyle(e);
  return { x: r.x, y: r.y, width: r.width, height: r.height, visible: !e.closest('[hidden]') && style.display !== 'none' && r.height > 2 && r.width > 2 };
}, selector);

// Bark pixels low in the middle of the view: the trunk (as features.test.mjs finds it).
function findTrunk(page) {
  return page.evaluate(() => {
    const src = document.getElementById('view');
    const c = window.__niwaCanvasImage('#view');
    const scale = src.width / src.clientWidth;
    for (let y = c.height - 1; y > c.height * 0.3; --y) {
      const row = [];
      for (let x = Math.floor(c.width * 0.3); x < c.width * 0.7; ++x) {
        const i = (y * c.width + x) * 4;
        const r = c.data[i], g = c.data[i + 1], b = c.data[i + 2];
        if (r > g + 10 && g > b && r < 130) row.push(x);
      }
      if (row.length >= 3) return { x: row[Math.floor(row.length / 2)] / scale, y: (y - 6 * scale) / scale };
    }
    return null;
  });
}

// Long tasks (PerformanceObserver 'longtask') on the main thread from a 30 -> 15 year edit until the
// 15-year tree is drawn; numbers to build/artifacts/ux-longtasks.json (docs/BENCHMARKS.md).
async function longTasks(context, server) {
  const big = watchPage(await context.newPage(), problems);
  await big.goto(`${server.url}#preset=sakura-thesis&seed=1&years=30`);
  await waitReady(big, 0, 250);
  const bigStats = await dataset(big);
  // The 30-year tree's frame may still be drawing in the GPU process (seconds on SwiftShader; the
  // page's JS is done with it long before): a finished pixel read waits for it, so the window below
  // measures the 30 -> 15 change, not the tail of the first frame.
  // (the view's context is the render worker's: the page asks it, web/tree/tree_page.js 'niwa-gpu-finish')
  await big.evaluate(() => new Promise((resolve) => {
    const answers = () => Number(document.documentElement.dataset.gpuFinished || 0);
    const before = answers();
    document.dispatchEvent(new Event('niwa-gpu-finish'));
    const poll = () => (answers() > before ? resolve() : setTimeout(poll, 20));
    poll();
  }));
  await big.waitForTimeout(1000);
  const t0 = await big.evaluate(() => performance.now());
  const serial = await serialOf(big);
  await big.fill('#years', '15');
  await waitReady(big, serial, 50);
  const t1 = await big.evaluate(() => performance.now());
  const tasks = await big.evaluate((t) => window.__longtasks.filter((e) => e.start >= t), t0);
  const supported = await big.evaluate(() => PerformanceObserver.supportedEntryTypes.includes('longtask'));
  const longest = tasks.reduce((m, e) => Math.max(m, e.duration), 0);
  const total = tasks.reduce((s, e) => s + e.duration, 0);
  const result = { from: { years: 30, internodes: Number(bigStats.internodes) }, to: { years: 15, internodes: Number((await dataset(big)).internodes) },
    windowMs: Math.round(t1 - t0), longTasks: tasks.length, longestMs: Math.round(longest), totalMs: Math.round(total), tasks };
  fs.writeFileSync(path.join(ARTIFACTS, process.env.UX_LONGTASKS_OUT || 'ux-longtasks.json'), `${JSON.stringify(result, null, 2)}\n`);
  check('long tasks are observed in this Chromium', supported);
  timedCheck('30 -> 15 years: the longest main-thread task', longest, 200,
    `${tasks.length} long tasks, longest ${longest.toFixed(0)} ms, total ${total.toFixed(0)} ms in ${(t1 - t0).toFixed(0)} ms (${bigStats.internodes} -> ${result.to.internodes} internodes)`);
  await big.close();

}

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1200, height: 800 } });
  await context.addInitScript(() => {
    window.__longtasks = [];
    try {
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) window.__longtasks.push({ start: e.startTime, duration: e.duration });
      }).observe({ type: 'longtask', buffered: true });
    } catch { /* no longtask support: the check below says so */ }
  });
  if (process.env.UX_ONLY === 'longtasks') {  // the before/after numbers of docs/BENCHMARKS.md
    await longTasks(context, server);
    return;
  }
  const page = watchPage(await context.newPage(), problems);
  await page.goto(`${server.url}${HASH}`);
  await waitReady(page, 0, 100);

  // ---- 1. Getting started: the table's simple rows (and Age), above the full table.
  const table = JSON.parse(execFileSync(NATIVE, ['params', 'tree', '--json'], { encoding: 'utf8' }));
  const group = await page.evaluate(() => [...document.querySelectorAll('.getting-started .simple')].map((e) => ({
    key: e.dataset.forKey, name: e.querySelector('.simple-name').textContent,
    help: e.querySelector('.simple-help').textContent,
  })));
  const rows = group.slice(1).map((g) => table.findIndex((r) => r.key === g.key));
  check('Getting started: Age, then 4 to 8 rows of the table in table order, named for what they do',
    group[0]?.key === 'years' && group[0]?.name === 'Age' && rows.length >= 4 && rows.length <= 8
    && rows.every((i, n) => i >= 0 && (n === 0 || i > rows[n - 1])) && group.slice(1).every((g) => g.name !== g.key),
    group.map((g) => `${g.name}=${g.key}`).join(', '));
  // The panel builds its closed groups' rows in later tasks (issue 32 item 5): by 'ready' every row
  // of the table is there, a closed group's rows are not rendered until it opens, and each Getting
  // started control shows its row's value.
  const panelRows = await page.evaluate(() => {
    const closed = [...document.querySelectorAll('#params details.group:not([open]) > .field')];
    const simple = [...document.querySelectorAll('.getting-started .simple')].slice(1)
      .map((e) => [e.querySelector('input[type=number]').value, document.getElementById(`param-${e.dataset.forKey}`)?.value]);
    const summary = document.querySelector('#params details.group:not([open]) > summary');
    summary.click();  // opened: its rows show (then closed again)
    const shown = [...summary.parentElement.querySelectorAll(':scope > .field')].every((f) => f.getBoundingClientRect().height > 0);
    summary.click();
    return { rows: document.querySelectorAll('.panel .field[title] input[data-key]').length, closed: closed.length,
      hidden: closed.every((f) => getComputedStyle(f).display === 'none'), simple, shown };
  });
  check('every row of the table is in the panel by ready, a closed group\'s rows not rendered until it opens',
    panelRows.rows === table.length && panelRows.closed > 0 && panelRows.hidden && panelRows.shown
    && panelRows.simple.every(([a, b]) => a !== '' && a === b), JSON.stringify(panelRows));
  const simpleRows = group.slice(1).map((g) => ({ ...table.find((r) => r.key === g.key), simple: g.name }));
  check('each control says in plain words what it does', group.every((g) => g.help.length > 20), group.map((g) => g.help.length).join(','));
  const gsBox = await box(page, '.getting-started');
  const tableBox = await box(page, '#params');
  check('Getting started is above the full table', gsBox.visible && gsBox.y + gsBox.height <= tableBox.y, `${gsBox.y + gsBox.height} <= ${tableBox.y}`);
  const intro = await page.textContent('.getting-started .intro');
  check('the intro says what the tree is and what to try first', /grown year by year/.test(intro) && /Try first/.test(intro), intro.slice(0, 80));
  await page.locator('.getting-started').screenshot({ path: path.join(ARTIFACTS, 'ux-getting-started.png') });

  // A simple control is an edit of its table row: same field, same hash, same tree as the CLI.
  const branchy = simpleRows.find((r) => r.key === 'P_l_old') || simpleRows.find((r) => r.stage === 'grow');
  let before = await dataset(page);
  await andWait(page, () => page.fill(`#simple-${branchy.key}`, '0.3'));
  let after = await dataset(page);
  const native = nativeStats([...BASE, '--set', `${branchy.key}=0.3`]);
  check(`${branchy.simple} writes the table row ${branchy.key}`, (await page.inputValue(`#param-${branchy.key}`)) === '0.3'
    && (await page.evaluate(() => location.hash)).includes(`${branchy.key}=0.3`), await page.evaluate(() => location.hash));
  check(`${branchy.simple} grows once, the CLI's tree`, Number(after.growRequests) === Number(before.growRequests) + 1
    && after.internodes === String(native.internodes), `grows ${before.growRequests} -> ${after.growRequests}; web ${after.internodes} native ${native.internodes}`);
  await andWait(page, () => page.fill('#simple-years', '6'));
  check('Age is the Years field', (await page.inputValue('#years')) === '6' && (await dataset(page)).year === '6');
  await andWait(page, () => page.fill('#simple-years', '8'));
  await andWait(page, () => page.fill(`#simple-${branchy.key}`, String(branchy.default)));

  // ---- 2. Help on focus (keyboard), not only on hover.
  await page.evaluate(() => { document.getElementById('param-gamma').closest('details').open = true; });
  const helpBefore = await box(page, '#help-gamma');
  await page.focus('#param-gamma');
  const helpFocused = await box(page, '#help-gamma');
  await page.keyboard.press('Tab');
  const helpAfter = await box(page, '#help-gamma');
  const next = await page.evaluate(() => document.activeElement?.id);
  const nextHelp = await box(page, `#${next.replace('param-', 'help-')}`);
  check('a row\'s help shows on focus and goes with it', helpBefore.height <= 1 && helpFocused.height > 8 && helpFocused.width > 100
    && helpAfter.height <= 1 && nextHelp?.height > 8, `gamma help ${helpBefore.height} -> ${helpFocused.height} -> ${helpAfter.height}; ${next} ${nextHelp?.height}`);

  // ---- 3. An error beside its field, scrolled into view; the tree on screen marked stale.
  await page.evaluate(() => { document.getElementById('param-alpha_t').closest('details').open = true; });
  await page.fill('#param-alpha_t', '2');
  const staleAtOnce = await box(page, '#stale');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const row = await page.evaluate(() => {
    const line = document.getElementById('param-alpha_t').closest('.field').querySelector('.field-error');
    const r = line?.getBoundingClientRect();
    const panel = document.querySelector('.panel').getBoundingClientRect();
    return line ? { text: line.textContent, hidden: line.hidden, top: r.top, bottom: r.bottom, panelTop: panel.top, panelBottom: panel.bottom } : null;
  });
  check('the stale label shows as soon as a field is edited', staleAtOnce.visible);
  check('the error is shown in the row of its field', row && !row.hidden && /^alpha_t: 2 is out of range.*\[0, 1\]/.test(row.text), JSON.stringify(row));
  check('the error line is in view', row && row.top >= row.panelTop && row.bottom <= row.panelBottom && row.bottom <= 800, JSON.stringify(row));
  const staleText = await page.textContent('#stale');
  check('the old tree stays marked stale after the error', (await box(page, '#stale')).visible && /stale/.test(staleText), staleText);
  await page.locator('.layout').screenshot({ path: path.join(ARTIFACTS, 'ux-error-stale.png') });
  // A valid Years typed while alpha_t is still bad is refused too: the year bar goes back to the
  // tree on screen (it kept the refused age: "50 of 50" over a 15-year tree).
  const barBefore = await page.textContent('#year-text');
  const yearsBefore = await page.inputValue('#years');
  const errorsBefore = await page.evaluate(() => document.documentElement.dataset.errors || '');
  await page.fill('#years', String(Number(yearsBefore) + 3));
  const barBack = await page.waitForFunction((before) => document.getElementById('year-text').textContent === before,
    barBefore, { timeout: 15_000, polling: 50 }).then(() => true, () => false);
  check('a refused edit leaves the year bar on the tree shown', barBack,
    `"${await page.textContent('#year-text')}" (was "${barBefore}"; errors hook ${errorsBefore})`);
  await page.fill('#years', yearsBefore);
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  let serial = await serialOf(page);
  await page.fill('#param-alpha_t', '0.7');
  await waitReady(page, serial, 100);
  check('a good value clears the error and the stale label', !(await box(page, '#stale')).visible
    && (await page.evaluate(() => document.getElementById('param-alpha_t').closest('.field').querySelector('.field-error')?.hidden ?? true)));
  await page.fill('#years', '130');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const yearsError = await page.evaluate(() => {
    const line = document.getElementById('years').nextElementSibling;
    return line?.classList.contains('field-error') && !line.hidden ? line.textContent : '';
  });
  check('a Years error is shown beside Years (and beside Age)', /^years: 130 is out of range/.test(yearsError)
    && (await page.evaluate(() => !document.querySelector('[data-for-key="years"] .field-error')?.hidden)), yearsError);
  // The year bar stays on the tree shown (8 years), not on the refused Years.
  const barAfterBad = await page.textContent('#year-text');
  const barMax = await page.evaluate(() => document.getElementById('year').max);
  check('a refused Years leaves the year bar on the tree shown', barAfterBad === `${yearsBefore} of ${yearsBefore}` && barMax === yearsBefore,
    `"${barAfterBad}", max ${barMax}; the tree shown is ${yearsBefore} years`);
  await andWait(page, () => page.fill('#years', '8'));
  // A bad Shoot length typed in Getting started: its error shows beside that field and the panel
  // stays on it (issue 32: it scrolled to the full table's copy of the row, away from the field).
  await page.evaluate(() => document.querySelector('.panel').scrollTo(0, 0));
  const shoot = page.locator('.getting-started [data-for-key="D_high"] input[type=number]');
  await shoot.fill('500');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  await page.waitForTimeout(200);
  const typed = await page.evaluate(() => {
    const host = document.querySelector('.getting-started [data-for-key="D_high"]');
    const input = host.querySelector('input[type=number]').getBoundingClientRect();
    const line = host.querySelector('.field-error');
    const panel = document.querySelector('.panel').getBoundingClientRect();
    const lr = line?.getBoundingClientRect();
    return { inputTop: input.top, inputBottom: input.bottom, lineText: line && !line.hidden ? line.textContent : '',
      lineBottom: lr?.bottom, panelTop: panel.top, panelBottom: Math.min(panel.bottom, window.innerHeight) };
  });
  check('a bad Shoot length typed in Getting started: its error beside it, the field still in view',
    /^D_high: 500 is out of range/.test(typed.lineText) && typed.inputTop >= typed.panelTop && typed.inputBottom <= typed.panelBottom
    && typed.lineBottom <= typed.panelBottom, JSON.stringify(typed));
  await andWait(page, () => shoot.fill('3'));

  // ---- 4. The trunk: selected, but Cut and Delete refuse, with the reason.
  const trunk = await findTrunk(page);
  const view = await box(page, '#view');
  let trunkId = null;
  for (let dy = 0; trunk && dy < 60 && trunkId !== '0'; dy += 6) {
    await pickAt(page, view.x + trunk.x, view.y + trunk.y - dy);
    trunkId = (await dataset(page)).selected;
  }
  const selectionText = await page.textContent('#selection');
  check('the trunk (branch 0) can be selected', trunkId === '0', `selected ${trunkId}`);
  check('Cut is off for the trunk, and says why', await page.isDisabled('#cut') && /trunk cannot be cut/.test(selectionText), selectionText);
  before = await dataset(page);
  const hashBefore = await page.evaluate(() => location.hash);
  await page.focus('#view');
  await page.keyboard.press('Delete');
  await page.waitForTimeout(600);
  after = await dataset(page);
  check('Delete on the trunk is refused: no grow, no prune', Number(after.cutsRefused) === Number(before.cutsRefused || 0) + 1
    && after.growRequests === before.growRequests && (await page.evaluate(() => location.hash)) === hashBefore && !hashBefore.includes('prune'),
    `refused ${before.cutsRefused} -> ${after.cutsRefused}; grows ${before.growRequests} -> ${after.growRequests}`);
  await page.keyboard.press('Escape');
  check('a tree with branches offers its .glb', await page.isEnabled('#download-glb') && (await dataset(page)).glbOffered === '1');

  // A link whose prune removes the whole tree: grown (the core accepts it) but no .glb offered.
  const emptyPage = watchPage(await context.newPage(), problems);
  await emptyPage.goto(`${server.url}${HASH}&prune=1:b0`);
  await waitReady(emptyPage, 0, 100);
  const emptyStats = await dataset(emptyPage);
  const reason = await emptyPage.textContent('#glb-reason');
  check('an empty tree: Download .glb is disabled with the reason shown', await emptyPage.isDisabled('#download-glb')
    && (await box(emptyPage, '#glb-reason')).visible && /empty/.test(reason), `internodes ${emptyStats.internodes}; ${reason}`);
  await emptyPage.close();

  // ---- 5. A one-second slider drag grows only the latest value.
  await page.evaluate(() => {
    const field = document.getElementById('param-D_high').closest('.field');
    field.closest('details').open = true;
    field.scrollIntoView({ block: 'center' });
  });
  const slider2 = await page.evaluate(() => {
    const r = document.getElementById('param-D_high').closest('.field').querySelector('.slider').getBoundingClientRect();
    return { x: r.x, y: r.y + r.height / 2, width: r.width };
  });
  before = await dataset(page);
  // A drag as the browser reports it: 30 input events on the slider over one second (sent in the
  // page, so a busy CPU GL cannot stretch the drag as mouse moves through the test driver did).
  const dragStart = Date.now();
  await page.evaluate(() => new Promise((resolve) => {
    const range = document.getElementById('param-D_high').closest('.field').querySelector('.slider');
    let i = 0;
    const step = () => {
      i += 1;
      range.value = String(600 + 5 * i);  // a log slider (0.01-100 cm): positions 605..750 of 1000
      range.dispatchEvent(new Event('input', { bubbles: true }));
      if (i < 30) setTimeout(step, 33); else resolve();
    };
    step();
  }));
  const dragMs = Date.now() - dragStart;
  await page.waitForFunction((n) => {
    const d = document.documentElement.dataset;
    return d.status === 'ready' && Number(d.treeSerial) > n && d.drawnTreeSerial === d.treeSerial && d.stale === '0';
  }, Number(before.treeSerial), { timeout: TIMEOUT, polling: 100 });
  await page.waitForTimeout(800);
  after = await dataset(page);
  const dragged = await page.inputValue('#param-D_high');
  // Shoot length spans four decades: its slider is logarithmic (issue 32: a linear one put
  // 0.01-1 cm in its first pixel). Position 750 of 1000 is 0.01·10^3 = 10 cm; the field's value
  // puts the slider back where it belongs (1 cm: the middle).
  check('a four-decade row has a log slider: position 750 is 10 cm', dragged === '10', `D_high ${dragged}`);
  const draggedNative = nativeStats([...BASE, '--set', `D_high=${dragged}`]);
  check('a slider drag sends at most 2 grows', Number(after.growRequests) - Number(before.growRequests) <= 2 && Number(after.growRequests) > Number(before.growRequests),
    `${Number(after.growRequests) - Number(before.growRequests)} grow requests for a ${dragMs} ms drag to D_high ${dragged} (${slider2.width.toFixed(0)} px slider); coalesced ${after.editsCoalesced || 0}`);
  check('the drag\'s last value is the tree shown', (await page.evaluate(() => location.hash)).includes(`D_high=${dragged}`)
    && after.internodes === String(draggedNative.internodes), `web ${after.internodes} native ${draggedNative.internodes} at D_high=${dragged}`);

  // ---- 5b. Typing waits for its quiet moment (one update for a burst of `input` events); a
  // committed value (the `change` of Enter or blur) goes to the worker at once, without the 250 ms
  // debounce (issue 32 item 5: the debounce alone was over an edit's budget). Read in the page:
  // data-grow-requests is bumped, and data-update-sent-ms stamped, as the update is posted.
  const burst = await page.evaluate(() => new Promise((resolve) => {
    const d = document.documentElement.dataset;
    const number = document.getElementById('param-D_high');
    const grows = () => Number(d.growRequests);
    const out = { before: grows(), commits: Number(d.editsCommitted || 0) };
    for (const v of ['2', '2.5', '2.52', '2.5', '2.6']) {
      number.value = v;
      number.dispatchEvent(new Event('input', { bubbles: true }));
    }
    out.burst = grows();  // the burst is waiting
    setTimeout(() => {
      out.mid = grows();  // 100 ms on: still waiting (its debounce is 250 ms)
      setTimeout(() => {
        out.quiet = grows();  // the burst's one update
        number.value = '2.75';
        number.dispatchEvent(new Event('input', { bubbles: true }));
        const t0 = performance.now();
        number.dispatchEvent(new Event('change', { bubbles: true }));  // Enter
        out.change = grows();
        out.sentAfterMs = Number(d.updateSentMs) - t0;
        out.commitsAfter = Number(d.editsCommitted || 0);
        resolve(out);
      }, 450);
    }, 100);
  }));
  check('typing waits: a burst of 5 input events sends nothing for 100 ms, then one grow', burst.burst === burst.before
    && burst.mid === burst.before && burst.quiet === burst.before + 1, JSON.stringify(burst));
  check('a committed value (change) goes to the worker at once, not after the debounce', burst.change === burst.quiet + 1
    && burst.sentAfterMs > -1 && burst.sentAfterMs < 50 && burst.commitsAfter === burst.commits + 1, JSON.stringify(burst));
  await page.waitForFunction(() => {
    const d = document.documentElement.dataset;
    return d.status === 'ready' && d.drawnTreeSerial === d.treeSerial && d.stale === '0' && location.hash.includes('D_high=2.75');
  }, null, { timeout: TIMEOUT, polling: 100 });

  // ---- 6. Blow moves at once: the first pose is already in the gust (not in the still air before it).
  await andWait(page, () => page.fill('#param-D_high', '1'));
  const middle = await page.evaluate(() => document.getElementById('param-D_high').closest('.field').querySelector('.slider').value);
  check('... and a typed 1 cm puts that slider in its middle', middle === '500', `position ${middle}`);
  // Getting started's Shoot length is the same row: its slider takes the row's mapping too
  // (web/shell/slider_scale.js; it was linear, issue 32), both ways.
  const simpleShoot = await page.evaluate(() => {
    const range = document.querySelector('.getting-started [data-for-key="D_high"] .slider');
    const number = document.querySelector('.getting-started [data-for-key="D_high"] input[type=number]');
    const at1cm = { min: range.min, max: range.max, position: range.value, number: number.value };
    range.value = '750';
    range.dispatchEvent(new Event('input', { bubbles: true }));
    return { at1cm, number: number.value, row: document.getElementById('param-D_high').value,
      rowSlider: document.getElementById('param-D_high').closest('.field').querySelector('.slider').value };
  });
  check('Getting started\'s Shoot length slider is logarithmic as the table\'s: 1 cm in its middle, position 750 is 10 cm in both',
    simpleShoot.at1cm.min === '0' && simpleShoot.at1cm.max === '1000' && simpleShoot.at1cm.position === '500' && simpleShoot.at1cm.number === '1'
    && simpleShoot.number === '10' && simpleShoot.row === '10' && simpleShoot.rowSlider === '750', JSON.stringify(simpleShoot));
  await andWait(page, () => page.fill('#param-D_high', '3'));
  await snapshotCanvas(page, 'rest');
  await page.click('#wind');
  await page.waitForFunction(() => document.documentElement.dataset.swayTime !== '' && document.documentElement.dataset.swayTime !== undefined,
    null, { timeout: TIMEOUT, polling: 20 });
  const first = await dataset(page);
  await page.waitForFunction(() => Number(document.documentElement.dataset.swayTime) >= 1.2, null, { timeout: TIMEOUT, polling: 20 });
  await snapshotCanvas(page, 'early');
  const early = await dataset(page);
  const movedEarly = await snapshotDifference(page, 'rest', 'early', 30);
  check('Blow: the first pose is in the gust (wind on)', Number(first.swayWind) > 0 && Number(first.swayTime) >= 1 && Number(first.swayTime) < 1.5,
    `first pose t = ${first.swayTime} s, wind ${first.swayWind} m/s (gust_on 1 s)`);
  check('Blow: the tree has moved within the first 0.2 s of the gust', movedEarly > 0.0005,
    `${(movedEarly * 100).toFixed(3)}% of pixels changed at t = ${early.swayTime} s`);
  await page.locator('#view').screenshot({ path: path.join(ARTIFACTS, 'ux-blow-early.png') });
  await page.click('#wind');

  // ---- 7. Long tasks while a 30-year tree becomes a 15-year one: a speed goal, so its 30-year grow
  // (23 s of the suite's CPU) runs only under scripts/bench (NIWA_TIMED=1); here the observer the
  // measurement reads is checked on this page (the Blow above made tasks to see).
  if (TIMED) {
    await longTasks(context, server);
  } else {
    check('long tasks are observed in this Chromium',
      await page.evaluate(() => PerformanceObserver.supportedEntryTypes.includes('longtask') && Array.isArray(window.__longtasks)));
  }

  // ---- 8. A phone: touch targets, help on tap, tap a branch and Cut.
  const phone = await newContext(browser, { viewport: { width: 390, height: 760 }, isMobile: true, hasTouch: true, deviceScaleFactor: 1 });
  const mobile = watchPage(await phone.newPage(), problems);
  await mobile.goto(`${server.url}${HASH}`);
  await waitReady(mobile, 0, 100);
  await mobile.screenshot({ path: path.join(ARTIFACTS, 'ux-phone.png') });
  const small = await mobile.evaluate(() => {
    const out = [];
    let n = 0;
    for (const e of document.querySelectorAll('button, input, select, summary, a[href], textarea')) {
      if (e.closest('dialog') || e.getClientRects().length === 0) continue;
      const style = getComputedStyle(e);
      if (style.visibility === 'hidden' || style.display === 'none') continue;
      // A control's target includes its labels (a tap on a label acts on it).
      let w = e.getBoundingClientRect().width, h = e.getBoundingClientRect().height;
      for (const label of e.labels || []) {
        const r = label.getBoundingClientRect();
        w = Math.max(w, r.width);
        h = Math.max(h, r.height);
      }
      ++n;
      if (w < 44 || h < 44) out.push(`${e.tagName.toLowerCase()}#${e.id || e.className || e.textContent.trim().slice(0, 20)} ${w.toFixed(0)}x${h.toFixed(0)}`);
    }
    return { n, out };
  });
  check('phone: every visible control is at least 44 x 44 px', small.n > 20 && small.out.length === 0, `${small.n} controls; too small: ${small.out.join(', ')}`);
  await mobile.evaluate(() => { document.getElementById('param-gamma').closest('details').open = true; });
  await mobile.tap('#param-gamma');
  const tapped = await box(mobile, '#help-gamma');
  check('phone: a tap on a field shows its help', tapped.height > 8, `help ${tapped.width.toFixed(0)}x${tapped.height.toFixed(0)}`);
  await mobile.evaluate(() => document.activeElement?.blur());
  await mobile.evaluate(() => window.scrollTo(0, 0));
  const phoneView = await box(mobile, '#view');
  const phoneBefore = await dataset(mobile);
  let branch = null;
  for (let fy = 0.55; fy > 0.2 && branch === null; fy -= 0.04) {
    for (const fx of [0.5, 0.45, 0.55, 0.4, 0.6]) {
      await pickAt(mobile, phoneView.x + phoneView.width * fx, phoneView.y + phoneView.height * fy, { tap: true });
      const id = (await dataset(mobile)).selected;
      if (id && id !== '0') { branch = id; break; }
    }
  }
  check('phone: a tap selects a branch', branch !== null && await mobile.isEnabled('#cut'), `branch ${branch}`);
  if (branch !== null) {
    await andWait(mobile, () => mobile.tap('#cut'));
    const cut = await dataset(mobile);
    const cutNative = nativeStats([...BASE, '--prune', `8:b${branch}`]);
    check('phone: Cut prunes the tapped branch (the CLI\'s tree)', (await mobile.evaluate(() => location.hash)).includes(`prune=8:b${branch}`)
      && cut.internodes === String(cutNative.internodes) && Number(cut.internodes) < Number(phoneBefore.internodes),
    `${phoneBefore.internodes} -> ${cut.internodes} (native ${cutNative.internodes})`);
  }
  await mobile.screenshot({ path: path.join(ARTIFACTS, 'ux-phone-cut.png') });
  await mobile.evaluate(() => document.querySelector('.panel').scrollIntoView());
  await mobile.screenshot({ path: path.join(ARTIFACTS, 'ux-phone-panel.png') });

  check('no console errors or warnings', problems.length === 0, problems.join(' | '));
});
