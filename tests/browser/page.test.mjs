// Browser test of the Niwa page: node tests/browser/page.test.mjs (exit code 0 = pass).
// Starts scripts/serve.mjs on a free port, drives Debian chromium (SwiftShader WebGL2) through
// playwright-core, and compares the page's stats with the native CLI ($NIWA_NATIVE).
import fs from 'node:fs';
import path from 'node:path';
import {
  ARTIFACTS, NATIVE, ROOT, TIMEOUT, check, nativeStats, newContext, runBrowserTest, waitReady, watchPage,
} from './harness.mjs';

function parseStats(text) {
  const number = (name) => {
    const m = text.match(new RegExp(`${name} (\\d+)`));
    return m ? Number(m[1]) : NaN;
  };
  return { internodes: number('internodes'), leaves: number('leaves'), flowers: number('flowers') };
}


// Pixel statistics of the WebGL canvas (preserveDrawingBuffer keeps the last frame readable).
async function canvasPixels(page) {
  return page.evaluate(() => {
    const image = window.__niwaCanvasImage('#view');  // see newContext in harness.mjs
    const data = image.data;
    let sum = 0, sum2 = 0, n = 0, green = 0, pink = 0, brown = 0;
    for (let i = 0; i < data.length; i += 4) {
      const r = data[i], g = data[i + 1], b = data[i + 2];
      const y = 0.299 * r + 0.587 * g + 0.114 * b;
      sum += y; sum2 += y * y; ++n;
      if (g > r + 30 && g > b + 30) ++green;  // leaf green (the ground is a greyish meadow)
      if (r > 200 && g < r - 25 && b > g + 5) ++pink;
      if (r > g + 15 && g > b + 5 && r < 150) ++brown;
    }
    const mean = sum / n;
    return { width: image.width, height: image.height, std: Math.sqrt(Math.max(0, sum2 / n - mean * mean)), green: green / n, pink: pink / n, brown: brown / n };
  });
}

const problems = [];
await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  watchPage(page, problems);
  page.on('requestfailed', (r) => problems.push(`requestfailed: ${r.url()}`));
  page.on('request', (r) => {
    if (!r.url().startsWith(server.url) && !r.url().startsWith('data:')) problems.push(`external request: ${r.url()}`);
  });

  // 1. Default page: sakura at its default years and seed, fully grown.
  const t0 = Date.now();
  await page.goto(server.url, { waitUntil: 'load' });
  check('page title is Niwa', (await page.title()) === 'Niwa');
  await waitReady(page, 0);
  const grown = await page.evaluate(() => ({ serial: Number(document.documentElement.dataset.treeSerial), drawn: document.documentElement.dataset.drawnTreeSerial, stats: document.querySelector('#stats')?.textContent || '' }));
  const internodes = Number((grown.stats.match(/internodes (\d+)/) || [])[1]);
  check('default tree grown and drawn', grown.serial > 0 && grown.drawn === String(grown.serial) && internodes > 100,
    `${internodes} internodes, ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  const preset = await page.inputValue('#preset');
  const years = Number(await page.inputValue('#years'));
  const seed = Number(await page.inputValue('#seed'));
  check('default preset is sakura', preset === 'sakura', `preset=${preset} years=${years} seed=${seed}`);
  const statsText = await page.textContent('#stats');
  console.log(`  stats: ${statsText}`);
  check('stats line format', /^internodes \d+ · leaves \d+ · flowers \d+ · height [\d.]+ cm · grown in \d+ ms$/.test(statsText), statsText);

  let native = null;
  try {
    native = nativeStats(['--preset', preset, '--years', String(years), '--seed', String(seed)]);
  } catch (e) {
    check('native CLI runs', false, `${NATIVE}: ${e.message.split('\n')[0]}`);
  }
  if (native) {
    const web = parseStats(statsText);
    check('stats equal native CLI', web.internodes === native.internodes && web.leaves === native.leaves && web.flowers === native.flowers,
      `web ${JSON.stringify(web)} native ${JSON.stringify({ internodes: native.internodes, leaves: native.leaves, flowers: native.flowers })}`);
  }

  const pixels = await canvasPixels(page);
  check('canvas is not blank', pixels.std > 8, `luma std ${pixels.std.toFixed(1)} on ${pixels.width}x${pixels.height}`);
  // The species sakura (issue 17) is framed from farther back than the thesis tree, and its 3.2 cm
  // flowers fall below a pixel there (blossom that reads from a distance is issue 17 item 3), so
  // the flower colour is checked on the thesis tree below (section 4b).
  // Its crown is drawn as dense as the species' (leaf_spray 5, docs/tree-species.md "Beside
  // ez-tree"): it hides the limbs and shades the trunk, whose lit-bark pixels fell from 0.54 % (as
  // docs/tree-species.md last measured it) to 0.05 % of the canvas (the floor was 0.05 %); the bark colour's floor of 0.05 % stays on the
  // thesis tree (section 4b), here 0.02 %.
  check('canvas shows leaves and bark colours', pixels.green > 0.01 && pixels.brown > 0.0002,
    `green ${(pixels.green * 100).toFixed(2)}% pink ${(pixels.pink * 100).toFixed(2)}% brown ${(pixels.brown * 100).toFixed(2)}%`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'niwa-sakura.png') });
  check('screenshot saved', fs.existsSync(path.join(ARTIFACTS, 'niwa-sakura.png')), 'build/artifacts/niwa-sakura.png');
  // Orbit by mouse drag and zoom by keyboard: the picture changes; save a close-up.
  const box = await page.locator('#view').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 150, box.y + box.height / 2 + 40, { steps: 5 });
  await page.mouse.up();
  await page.waitForTimeout(400);
  const orbited = await canvasPixels(page);
  check('mouse drag orbits the camera', Math.abs(orbited.green - pixels.green) > 1e-4 || Math.abs(orbited.std - pixels.std) > 0.01,
    `green ${(pixels.green * 100).toFixed(2)}% -> ${(orbited.green * 100).toFixed(2)}%`);
  await page.focus('#view');
  for (let i = 0; i < 8; ++i) await page.keyboard.press('+');
  await page.keyboard.press('ArrowUp');
  await page.waitForTimeout(400);
  await page.screenshot({ path: path.join(ARTIFACTS, 'niwa-sakura-close.png') });

  const hashBefore = await page.evaluate(() => location.hash);
  check('hash written from state', hashBefore.startsWith('#preset=sakura&seed=') && hashBefore.includes(`years=${years}`), hashBefore);

  // 2. Changing a parameter in the panel regrows and rewrites the hash.
  const serial = Number(await page.evaluate(() => document.documentElement.dataset.treeSerial));
  await page.fill('#param-alpha_l', '0.6');
  await waitReady(page, serial);
  const hashAfter = await page.evaluate(() => location.hash);
  const statsAfter = await page.textContent('#stats');
  check('parameter change rewrites the hash', hashAfter !== hashBefore && hashAfter.includes('alpha_l=0.6'), hashAfter);
  check('parameter change regrows', statsAfter !== statsText, statsAfter);
  if (native) {
    const n2 = nativeStats(['--preset', preset, '--years', String(years), '--seed', String(seed), '--set', 'alpha_l=0.6']);
    const web = parseStats(statsAfter);
    check('changed stats equal native CLI', web.internodes === n2.internodes && web.leaves === n2.leaves,
      `web ${web.internodes}/${web.leaves} native ${n2.internodes}/${n2.leaves}`);
  }

  // 3. An out-of-range value is refused by the core with a visible message, and the page keeps working.
  await page.fill('#param-alpha_l', '7');
  await page.waitForFunction(() => document.documentElement.dataset.status === 'error', null, { timeout: TIMEOUT });
  const errorText = await page.textContent('#notice');
  check('bad value shows the core error', /alpha_l/.test(errorText) && (await page.isVisible('#notice')), errorText.trim());
  const serial2 = Number(await page.evaluate(() => document.documentElement.dataset.treeSerial));
  await page.fill('#param-alpha_l', '0.4');
  await waitReady(page, serial2);
  check('recovers after a bad value', !(await page.isVisible('#notice')));

  // 4. A hostile hash: notices shown as text, never as markup; a usable tree is still grown.
  const page2 = await context.newPage();
  watchPage(page2, problems);
  await page2.goto(`${server.url}#preset=nope&years=7&alpha_t=%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E&bogus=1`);
  await waitReady(page2, 0);
  const notice = await page2.textContent('#notice');
  const markup = await page2.evaluate(() => document.querySelectorAll('#notice *').length);
  check('hash notices visible as text', (await page2.isVisible('#notice')) && notice.includes('preset') && notice.includes('bogus') && markup === 0,
    notice.replace(/\n/g, ' | '));
  check('hash years honoured', (await page2.inputValue('#years')) === '7');
  await page2.close();

  // 4b. The thesis's sakura (table 2.2) draws its flowers' colour.
  const page3 = await context.newPage();
  watchPage(page3, problems);
  await page3.setViewportSize({ width: 1280, height: 800 });
  await page3.goto(`${server.url}#preset=sakura-thesis&years=15`);
  await waitReady(page3, 0);
  const thesisPixels = await canvasPixels(page3);
  check('sakura-thesis shows leaves, flowers and bark colours', thesisPixels.green > 0.01 && thesisPixels.pink > 0.0001 && thesisPixels.brown > 0.0005,
    `green ${(thesisPixels.green * 100).toFixed(2)}% pink ${(thesisPixels.pink * 100).toFixed(2)}% brown ${(thesisPixels.brown * 100).toFixed(2)}%`);
  await page3.screenshot({ path: path.join(ARTIFACTS, 'niwa-sakura-thesis.png') });
  await page3.close();

  // 5. Narrow screen (375 px): no horizontal scrolling, controls reachable.
  await page.setViewportSize({ width: 375, height: 740 });
  await page.waitForTimeout(500);
  const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
  check('usable at 375 px wide', overflow <= 0, `horizontal overflow ${overflow}px`);
  await page.screenshot({ path: path.join(ARTIFACTS, 'niwa-375.png') });

  const unlabelled = await page.evaluate(() =>
    [...document.querySelectorAll('input:not([aria-hidden="true"]), select, button')]
      .filter((e) => !(e.labels && e.labels.length) && !e.getAttribute('aria-label') && !e.textContent.trim())
      .map((e) => e.id || e.outerHTML.slice(0, 60)));
  check('every control is labelled', unlabelled.length === 0, unlabelled.join(', '));

  check('no console errors or warnings', problems.length === 0, problems.slice(0, 5).join(' | '));
});
