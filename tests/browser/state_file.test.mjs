// Browser test of Save / Open (issue 17 item 6): node tests/browser/state_file.test.mjs. Save
// downloads the whole state ({preset, seed, years, changed params, prunes, camera}); the native CLI's
// 'tree grow --state' of that file prints the same --stats bytes (timings aside) as the page's link;
// Open of that file brings the tree back (its hash and counts); a bad file is a notice naming the
// field and the old tree stays.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { ARTIFACTS, NATIVE, check, newContext, runBrowserTest, waitReady, watchPage } from './harness.mjs';

const problems = [];
const hash = 'preset=keyaki-thesis&seed=3&years=5&gamma=0.3&wind_speed=12&prune=5:b3';
const cliStats = (args) => {
  const stats = JSON.parse(execFileSync(NATIVE, ['tree', 'grow', ...args, '--stats'], { encoding: 'utf8' }));
  return JSON.stringify(Object.fromEntries(Object.entries(stats).filter(([k]) => !k.startsWith('ms'))));
};
const data = (page) => page.evaluate(() => ({ ...document.documentElement.dataset }));
const noticeText = (page) => page.evaluate(() => {
  const el = document.getElementById('notice');
  return el.hidden ? '' : el.textContent;
});

await runBrowserTest(async (server, browser) => {
  const context = await newContext(browser, { viewport: { width: 900, height: 700 }, acceptDownloads: true });
  const page = await context.newPage();
  watchPage(page, problems);
  await page.goto(`${server.url}index.html#${hash}`);
  await waitReady(page, 0);
  const shown = await data(page);

  // Save: the state file, downloaded.
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 60_000 }), page.click('#save-state')]);
  const saved = path.join(ARTIFACTS, 'state_file-saved.json');
  await download.saveAs(saved);
  const file = JSON.parse(fs.readFileSync(saved, 'utf8'));
  check('Save downloads *-state.json', /^niwa-keyaki-thesis-seed3-year5-state\.json$/.test(download.suggestedFilename()),
    download.suggestedFilename());
  check('the file holds preset, seed, years, the changed params, prunes and the camera',
    file.preset === 'keyaki-thesis' && file.seed === 3 && file.years === 5 &&
    JSON.stringify(file.params) === '{"gamma":0.3,"wind_speed":12}' && JSON.stringify(file.prunes) === '["5:b3"]' &&
    /^-?[\d.]+(,-?[\d.e-]+){5}$/.test(file.camera) && Object.keys(file).length === 6, JSON.stringify(file));
  const byFile = cliStats(['--state', saved]);
  check('niwa tree grow --state <saved file> gives the same --stats bytes as --url <the page hash>',
    byFile === cliStats(['--url', hash]), byFile.slice(0, 160));
  check('... and the tree the page shows', JSON.parse(byFile).internodes === Number(shown.internodes) &&
    JSON.parse(byFile).leaves === Number(shown.leaves), `page ${shown.internodes}/${shown.leaves}`);

  // Another tree, then Open of the saved file: the saved tree again, with its camera.
  await page.goto(`${server.url}index.html#preset=binary&years=3`);
  await page.reload();
  await waitReady(page, 0);
  const before = Number((await data(page)).treeSerial);
  const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: 30_000 }), page.click('#open-state')]);
  await chooser.setFiles(saved);
  await waitReady(page, before);
  let d = await data(page);
  let pageHash = await page.evaluate(() => decodeURIComponent(location.hash));
  check('Open brings the saved tree back', d.stateFile === 'opened' && d.internodes === shown.internodes &&
    pageHash.startsWith(`#${hash}&cam=`), `${d.stateFile} ${d.internodes} ${pageHash.slice(0, 140)}`);
  check('... with the saved camera', pageHash.endsWith(`&cam=${file.camera}`), pageHash.slice(-60));
  const backHash = await page.evaluate(() => history.length);
  check('the opened state is a history entry', backHash >= 2, String(backHash));

  // Bad files: the line beside Open names the field; the old tree and hash stay; nothing goes to
  // the notices at the panel's top (out of view: issue 32).
  const cases = [
    ['{"preset": "keyaki-thesis", "colour": "red"}', /colour: unknown state key; the keys are preset, seed, years, params, prunes, camera/],
    ['{"years": 300}', /years: 300 is out of range; must be a whole number in \[0, 100\]/],
    ['not json', /state: malformed JSON/],
  ];
  for (const [text, pattern] of cases) {
    const bad = path.join(ARTIFACTS, 'state_file-bad.json');
    fs.writeFileSync(bad, text);
    const serial = (await data(page)).treeSerial;
    const hashBefore = await page.evaluate(() => location.hash);
    await page.evaluate(() => { document.documentElement.dataset.stateFile = ''; });
    await page.setInputFiles('#open-state-file', bad);
    await page.waitForFunction(() => document.documentElement.dataset.stateFile !== '', null, { timeout: 30_000 });
    await page.waitForTimeout(500);
    d = await data(page);
    const notice = await noticeText(page);
    check(`a bad file (${text}) is refused, old tree kept, no notice at the panel's top`, d.stateFile === 'open-error' &&
      !pattern.test(notice) && !notice.includes('state_file-bad.json') && d.treeSerial === serial &&
      (await page.evaluate(() => location.hash)) === hashBefore && d.status === 'ready', `${d.stateFile}: notice ${JSON.stringify(notice)}`);
    // ... and the line beside Open says so, in view (it said "Opened" of the file before).
    const line = await page.evaluate(() => {
      const el = document.getElementById('state-status');
      const r = el.getBoundingClientRect();
      const open = document.getElementById('open-state').getBoundingClientRect();
      return { text: el.textContent, inView: r.top >= 0 && r.bottom <= innerHeight, belowOpen: Math.round(r.top - open.bottom) };
    });
    check(`... and the line beside Open names the refusal, in view, right under Open`, line.text.startsWith('Open state_file-bad.json refused: ') &&
      pattern.test(line.text) && line.inView && line.belowOpen >= 0 && line.belowOpen < 80, JSON.stringify(line));
  }
  check('no console errors or page errors', problems.length === 0, problems.join(' | ').slice(0, 300));
});
