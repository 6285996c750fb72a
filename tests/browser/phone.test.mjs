// Browser test of the tree page on a phone (issue 32 item 4): node tests/browser/phone.test.mjs.
// On a 390 x 844 touch screen the controls used most (Preset, Age, Play, Blow, Cut) are on the first
// screen beside the view, the page never scrolled (web/tree/phone_dock.js puts them in the dock under
// the view; Play is on the view's year bar): each is used in turn and a screenshot of the screen
// (not the full page) taken after it holds both the control and its effect: the view's pixels in
// that screenshot differ from the one before. On a desktop-sized window the controls are back in
// their panel sections and the dock is hidden. Screenshots: build/artifacts/phone-*.png.
import path from 'node:path';
import { ARTIFACTS, TIMEOUT, check, nativeStats, newContext, pickAt, runBrowserTest, waitReady, watchPage } from './harness.mjs';

const problems = [];
const W = 390, H = 844;
const dataset = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));
const serialOf = async (page) => Number((await dataset(page)).treeSerial || 0);

// The controls and where they must be: inside the screen, not covered (the element, or its label,
// is what a tap at its centre reaches).
const CONTROLS = { Preset: '#preset', Age: '#simple-years', Play: '#play', Blow: '#wind', Cut: '#cut' };

async function onScreen(page, selector) {
  return page.evaluate(([sel, w, h]) => {
    const e = document.querySelector(sel);
    if (!e) return { ok: false, why: 'missing' };
    const r = e.getBoundingClientRect();
    const hit = document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2);
    const reached = hit === e || e.contains(hit) || [...(e.labels || [])].some((l) => l.contains(hit));
    return { ok: r.top >= 0 && r.bottom <= h && r.left >= 0 && r.right <= w && r.height > 0 && reached,
      box: [r.x, r.y, r.width, r.height].map(Math.round), scrollY: window.scrollY, hit: hit?.id || hit?.tagName };
  }, [selector, W, H]);
}

// A screenshot of the screen as it is (never scrolled: the screenshot is the viewport), saved as
// build/artifacts/FILE, with the view's box in it.
async function shot(page, file) {
  const png = await page.screenshot({ path: path.join(ARTIFACTS, file) });
  const view = await page.locator('#view').boundingBox();
  const scrollY = await page.evaluate(() => window.scrollY);
  return { png: png.toString('base64'), view, scrollY, file };
}

// Share of the view's pixels (its box in both screenshots) that differ by more than 30 (RGB sum)
// between two screenshots, decoded in the page.
async function viewChange(page, a, b) {
  return page.evaluate(async ([pa, pb, box]) => {
    const pixels = async (b64) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const ctx = c.getContext('2d', { willReadFrequently: true });
      ctx.drawImage(img, 0, 0);
      return ctx.getImageData(Math.round(box.x), Math.round(box.y), Math.round(box.width), Math.round(box.height)).data;
    };
    const x = await pixels(pa), y = await pixels(pb);
    let n = 0;
    for (let i = 0; i < x.length; i += 4) {
      if (Math.abs(x[i] - y[i]) + Math.abs(x[i + 1] - y[i + 1]) + Math.abs(x[i + 2] - y[i + 2]) > 30) ++n;
    }
    return n / (x.length / 4);
  }, [a.png, b.png, a.view]);
}

// Checks that `name`'s control is on the screen and that the screenshot after it shows the view changed.
async function used(page, name, before, after, minChange = 0.002) {
  const where = await onScreen(page, CONTROLS[name]);
  const change = await viewChange(page, before, after);
  check(`phone: ${name} is on the first screen with the view, and its effect shows in the same screenshot`,
    where.ok && before.scrollY === 0 && after.scrollY === 0 && change > minChange,
    `${CONTROLS[name]} at ${where.box} (reached: ${where.hit}); view changed over ${(change * 100).toFixed(2)}% of its pixels; ` +
    `scrollY ${before.scrollY}/${after.scrollY}; ${after.file}`);
}

const settled = (page) => page.waitForFunction(() => {
  const d = document.documentElement.dataset;
  return d.status === 'ready' && d.drawnTreeSerial === d.treeSerial && d.framePartial !== '1' && d.stale !== '1';
}, null, { timeout: TIMEOUT, polling: 100 });

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: W, height: H }, isMobile: true, hasTouch: true, deviceScaleFactor: 1 });
  const page = watchPage(await context.newPage(), problems);
  await page.goto(`${server.url}#preset=tsutsuji&seed=1&years=6`);
  await waitReady(page, 0, 100);
  await page.waitForFunction(() => document.querySelector('#dock [data-for-key="years"]'), null, { timeout: TIMEOUT });
  await settled(page);

  // ---- The first screen: the view and every control on it.
  const first = await shot(page, 'phone-first.png');
  const places = {};
  for (const [name, sel] of Object.entries(CONTROLS)) places[name] = await onScreen(page, sel);
  const viewBox = first.view;
  check('phone: the view and Preset, Age, Play, Blow and Cut all on the first 390 x 844 screen',
    Object.values(places).every((p) => p.ok) && viewBox.y >= 0 && viewBox.y + viewBox.height <= H && viewBox.height > 300,
    `${Object.entries(places).map(([n, p]) => `${n} ${p.box} ${p.ok ? 'ok' : `NOT (${p.why || p.hit})`}`).join('; ')}; view ${[viewBox.x, viewBox.y, viewBox.width, viewBox.height].map(Math.round)}`);
  const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
  check('phone: no horizontal scrolling', overflow <= 0, `${overflow} px`);

  // ---- Preset: another species, grown and drawn.
  let serial = await serialOf(page);
  await page.selectOption('#preset', 'maple');
  await waitReady(page, serial, 100);
  await settled(page);
  const afterPreset = await shot(page, 'phone-preset.png');
  await used(page, 'Preset', first, afterPreset);
  check('phone: Preset grew the chosen preset', (await page.evaluate(() => location.hash)).includes('preset=maple'));

  // ---- Age: typed in the dock's Age field, the tree of that age.
  serial = await serialOf(page);
  await page.tap('#simple-years');
  await page.fill('#simple-years', '6');
  await page.evaluate(() => document.activeElement?.blur());
  await waitReady(page, serial, 100);
  await settled(page);
  const afterAge = await shot(page, 'phone-age.png');
  await used(page, 'Age', afterPreset, afterAge);
  check('phone: Age set the tree\'s years (the year bar says so)', (await page.textContent('#year-text')) === '6 of 6'
    && (await page.inputValue('#years')) === '6', await page.textContent('#year-text'));

  // A bad Age: its error shows in the dock beside the field typed in, the page not scrolled away.
  await page.fill('#simple-years', '130');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT, polling: 50 });
  await page.waitForTimeout(200);
  const ageError = await page.evaluate(() => {
    const line = document.querySelector('#dock [data-for-key="years"] .field-error');
    const r = line?.getBoundingClientRect();
    return { text: line && !line.hidden ? line.textContent : '', top: r?.top, bottom: r?.bottom, scrollY: window.scrollY };
  });
  await page.screenshot({ path: path.join(ARTIFACTS, 'phone-age-error.png') });
  check('phone: a bad Age shows its error in the dock, on the first screen, the page not scrolled',
    /^years: 130 is out of range/.test(ageError.text) && ageError.bottom <= H && ageError.scrollY === 0, JSON.stringify(ageError));
  serial = await serialOf(page);
  await page.fill('#simple-years', '6');
  await page.evaluate(() => document.activeElement?.blur());
  await waitReady(page, serial, 100);
  await settled(page);

  // ---- Play: the tree grows from year 0 again; a screenshot while it plays shows a younger tree
  // and the year bar says which. Play goes on 250 ms after each year is on screen, and a screenshot
  // takes longer than that on a loaded machine (seconds on SwiftShader with the sun's shadow pass),
  // so the test pauses it the moment a young year is drawn (Pause, in the page: a round trip from
  // here is slower than a year), takes the screenshot and reads the year bar, then plays on.
  const drawnYearsBefore = await page.evaluate(() => (window.__niwaHookLog['html data-drawn-year'] || []).length);
  await page.tap('#play');
  const pausedAt = await page.evaluate(() => new Promise((resolve) => {
    const d = document.documentElement.dataset;
    const observer = new MutationObserver(() => look());
    const look = () => {
      if (!['1', '2'].includes(d.drawnYear) || d.drawnTreeSerial !== d.treeSerial) return;
      observer.disconnect();
      document.getElementById('play').click();  // Pause
      resolve({ year: d.drawnYear, button: document.getElementById('play').textContent });
    };
    observer.observe(document.documentElement, { attributes: true });
    look();
  }));
  await settled(page);
  const playing = await shot(page, 'phone-play.png');
  const playYear = await page.textContent('#year-text');
  const shownAfter = await dataset(page);
  await used(page, 'Play', afterAge, playing);
  check('phone: Play shows the young tree on the year bar', /^[12] of 6$/.test(playYear) && playYear.startsWith(`${pausedAt.year} `)
    && shownAfter.drawnYear === pausedAt.year && pausedAt.button === 'Play',
  `${playYear}; paused at drawn year ${pausedAt.year} (button then '${pausedAt.button}'), drawn year at the screenshot ${shownAfter.drawnYear}`);
  await page.tap('#play');  // Play on from the year shown
  await page.waitForFunction(() => document.getElementById('play').textContent === 'Play', null, { timeout: TIMEOUT, polling: 100 });
  await settled(page);
  const played = await shot(page, 'phone-played.png');
  // Every year of the tree was on screen in turn (the next one asked for after this one is drawn).
  const drawnYears = await page.evaluate((n) => (window.__niwaHookLog['html data-drawn-year'] || []).slice(n).map(Number), drawnYearsBefore);
  const seen = [1, 2, 3, 4, 5, 6].filter((y) => drawnYears.includes(y));
  check('phone: Play draws every year in turn, 1 to 6', seen.length === 6 && drawnYears.at(-1) === 6
    && drawnYears.every((y, i) => i === 0 || y >= drawnYears[i - 1]), `years drawn ${drawnYears.join(',')}`);

  // ---- Blow: the tree sways (a screenshot well into the gust).
  await page.tap('#wind');
  await page.waitForFunction(() => Number(document.documentElement.dataset.swayTime) >= 2, null, { timeout: TIMEOUT, polling: 50 });
  const blowing = await shot(page, 'phone-blow.png');
  await used(page, 'Blow', played, blowing, 0.001);
  check('phone: Blow says Still while it blows, with the wind line', (await page.textContent('#wind')) === 'Still');
  await page.tap('#wind');
  await page.waitForFunction(() => document.documentElement.dataset.swayTime === '' && document.documentElement.dataset.framePartial !== '1',
    null, { timeout: TIMEOUT, polling: 100 });
  await page.waitForTimeout(300);
  const still = await shot(page, 'phone-still.png');

  // ---- Cut: tap a branch in the view (not the trunk), then Cut in the dock.
  const before = await dataset(page);
  let branch = null;
  for (let fy = 0.6; fy > 0.15 && branch === null; fy -= 0.04) {
    for (const fx of [0.5, 0.45, 0.55, 0.4, 0.6, 0.35, 0.65]) {
      await pickAt(page, viewBox.x + viewBox.width * fx, viewBox.y + viewBox.height * fy, { tap: true });
      const id = (await dataset(page)).selected;
      if (id && id !== '0' && await page.isEnabled('#cut')) { branch = id; break; }
    }
  }
  check('phone: a tap in the view selects a branch, and the line in the dock says so', branch !== null
    && (await page.textContent('#selection')).startsWith(`Branch ${branch} selected`), `branch ${branch}`);
  if (branch !== null) {
    serial = await serialOf(page);
    await page.tap('#cut');
    await waitReady(page, serial, 100);
    await page.evaluate(() => document.getElementById('view').blur());
    await settled(page);
    const cutShot = await shot(page, 'phone-cut.png');
    const cut = await dataset(page);
    await used(page, 'Cut', still, cutShot);
    const native = nativeStats(['--preset', 'maple', '--seed', '1', '--years', '6', '--prune', `6:b${branch}`]);
    check('phone: Cut pruned the tapped branch (the CLI\'s tree)', Number(cut.internodes) < Number(before.internodes)
      && cut.internodes === String(native.internodes), `${before.internodes} -> ${cut.internodes} (native ${native.internodes})`);
  }
  check('phone: the page was never scrolled', (await page.evaluate(() => window.scrollY)) === 0);

  // ---- A desktop-sized window: the controls back in their panel sections, the dock hidden.
  await page.setViewportSize({ width: 1100, height: 760 });
  await page.waitForTimeout(300);
  const desk = await page.evaluate(() => ({
    dock: document.getElementById('dock').hidden,
    preset: Boolean(document.getElementById('preset').closest('.basics')),
    wind: document.getElementById('wind').closest('section')?.getAttribute('aria-label'),
    cut: document.getElementById('cut').closest('section')?.getAttribute('aria-label'),
    age: Boolean(document.getElementById('simple-years').closest('.getting-started')),
    selection: document.getElementById('selection').closest('section')?.getAttribute('aria-label'),
  }));
  check('desktop: the dock hidden, every control back in its panel section', desk.dock && desk.preset && desk.age
    && desk.wind === 'Wind' && desk.cut === 'Pruning' && desk.selection === 'Pruning', JSON.stringify(desk));
  await page.screenshot({ path: path.join(ARTIFACTS, 'phone-desktop.png') });
  await page.setViewportSize({ width: W, height: H });
  await page.waitForTimeout(300);
  check('phone again: the controls back in the dock', (await dataset(page)).docked === '1'
    && (await onScreen(page, '#wind')).ok && (await onScreen(page, '#simple-years')).ok);

  // ---- A tablet held upright (768 x 1024): one column like the phone, the view the screen's width,
  // the dock's controls on the first screen; turned (1024 x 768): view and panel side by side, the
  // studies' links on one line.
  await page.setViewportSize({ width: 768, height: 1024 });
  await page.waitForTimeout(300);
  const upright = await page.evaluate(() => {
    const v = document.getElementById('view').getBoundingClientRect();
    return { width: v.width, height: v.height, docked: document.documentElement.dataset.docked };
  });
  const reach = [];
  for (const [name, selector] of Object.entries(CONTROLS)) {
    const r = await page.evaluate(([sel]) => {
      const e = document.querySelector(sel);
      const b = e.getBoundingClientRect();
      return { ok: b.top >= 0 && b.bottom <= innerHeight && b.height > 0, box: [b.x, b.y, b.width, b.height].map(Math.round) };
    }, [selector]);
    if (!r.ok) reach.push(`${name} ${JSON.stringify(r.box)}`);
  }
  await page.screenshot({ path: path.join(ARTIFACTS, 'tablet-portrait.png') });
  check('tablet upright: one column, the view the screen\'s width, every control on the first screen', upright.width === 768
    && upright.height >= 0.5 * 1024 && upright.docked === '1' && reach.length === 0, `${JSON.stringify(upright)} ${reach.join(', ')}`);
  await page.setViewportSize({ width: 1024, height: 768 });
  await page.waitForTimeout(300);
  const turned = await page.evaluate(() => {
    const v = document.getElementById('view').getBoundingClientRect();
    const tops = [...document.querySelectorAll('.studies li')].map((li) => Math.round(li.getBoundingClientRect().top));
    return { width: v.width, height: v.height, docked: document.documentElement.dataset.docked, links: tops.length, lines: new Set(tops).size };
  });
  await page.screenshot({ path: path.join(ARTIFACTS, 'tablet-landscape.png') });
  check('tablet turned: view and panel side by side, the studies\' links on one line', turned.width >= 0.6 * 1024 && turned.height === 768
    && turned.docked !== '1' && turned.links >= 6 && turned.lines === 1, JSON.stringify(turned));

  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
