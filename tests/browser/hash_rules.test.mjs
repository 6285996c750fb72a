// Browser test of issue 16's hash rules (docs/input-rules.md): node tests/browser/hash_rules.test.mjs.
// The tree page refuses a hash over 16,384 characters with one notice (never cut) and caps its notices
// at five lines and "... N more"; a repeated key is named; the grove survives one bad wind value (one
// notice, the rest applies) and writes decoded values back encoded (no '&mode=full' injection).
import { check, newContext, runBrowserTest, waitGroveDrawn, waitReady, watchPage } from './harness.mjs';

const problems = [];
const noticeLines = (page) => page.evaluate(() => {
  const el = document.getElementById('notice');
  return el.hidden ? [] : el.textContent.split('\n');
});

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 800, height: 600 } });
  const page = await context.newPage();
  watchPage(page, problems);

  // Over the maximum: one notice, nothing read (years stays the preset's, not a cut "years=1").
  const long = `#preset=binary&years=3&x=${'1'.repeat(16400)}`;
  await page.goto(`${server.url}index.html${long}`);
  await waitReady(page, 0);
  let lines = await noticeLines(page);
  check('a hash over 16,384 characters is refused whole with one notice', lines.length === 1 &&
    /^hash: \d+ characters; the limit is 16384, nothing was read$/.test(lines[0]), JSON.stringify(lines).slice(0, 200));

  // Many bad keys: at most five lines and "... N more".
  const bad = Array.from({ length: 40 }, (_, i) => `bad${i}=1`).join('&');
  // A fresh load each time (about:blank first): a hash-only goto applies the hash in the open page,
  // which then writes back the cleaned hash, and a reload racing that write-back reads the clean one.
  await page.goto('about:blank');
  await page.goto(`${server.url}index.html#preset=binary&years=3&${bad}`);
  await waitReady(page, 0);
  lines = await noticeLines(page);
  check('notices are capped at 5 lines and "... N more"', lines.length === 6 && lines[5] === '... 35 more',
    JSON.stringify(lines).slice(0, 200));

  // A repeated key is named.
  await page.goto('about:blank');
  await page.goto(`${server.url}index.html#preset=binary&years=3&seed=1&seed=2`);
  await waitReady(page, 0);
  lines = await noticeLines(page);
  check('a repeated hash key refuses the link with a notice naming it', lines.includes('seed: given 2 times; must be given once, nothing was read'),
    JSON.stringify(lines));

  // The grove: one bad wind value, one injected value (hybrid mode: a full-mode frame of the grove takes
  // about 12 s on SwiftShader, a hybrid one about 0.4 s; the injection would switch it to full).
  const grove = await context.newPage();
  watchPage(grove, problems);
  await grove.goto(`${server.url}grove.html#mode=hybrid&wind_speed=5%26mode%3Dfull&wind_period=abc&gust_front_speed=3`);
  await waitGroveDrawn(grove, 'hybrid');
  const d = await grove.evaluate(() => ({ ...document.documentElement.dataset }));
  const message = await grove.textContent('#message');
  check('the grove grows despite bad wind values in the hash', d.status === 'ready', `${d.status}: ${message}`);
  check('each bad wind value is one notice naming it', /wind_speed: '5\\x26mode=full' dropped/.test(message) &&
    /wind_period: 'abc' dropped/.test(message), JSON.stringify(message));
  const hash = await grove.evaluate(() => location.hash);
  const params = new URLSearchParams(hash.slice(1));
  check('decoded values are written back encoded (no injected key)', params.getAll('mode').join() === 'hybrid' &&
    params.get('wind_speed') === '5&mode=full' && hash.includes('wind_speed=5%26mode%3Dfull'), hash.slice(0, 160));
  check('no console errors or page errors', problems.length === 0, problems.join(' | ').slice(0, 300));
});
