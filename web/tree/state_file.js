// Save and Open of the tree page (issue 17 item 6): Save downloads the whole state as the core's
// state file ({preset, seed, years, params: changed values, prunes, camera}; the file 'niwa tree
// grow --state' reads), Open reads one through a file input. Both go through the worker
// (web/worker/tree_handler.js 'stateFile', core/tree/tree_state), so page and CLI read one format.
// Does not: check a state itself (the core does), or change the tree on a bad file (the old tree
// stays and the error is the line beside Open).
import { download } from '../shell/study_page.js';
import { setHooks } from '../shell/test_hooks.js';

// Largest file Open reads: the CLI's cap for --state (kMaxParamsFileBytes, docs/input-rules.md).
const MAX_STATE_BYTES = 1 << 20;

// ui: {save, open, input (a hidden <input type=file>), status (the line under Save and Open)}; worker: the page's
// WorkerClient; state(): the page state to save (camera included); stem(): the file name stem;
// onOpen(state): apply an opened state (every value, as the hash decoder gives it).
export function mountStateFile(ui, { worker, state, stem, onOpen }) {
  let requests = 0;
  const ask = (fields) => worker.request('stateFile', fields, { group: `state-file-${++requests}`, done: ['stateFile'] }).reply;

  ui.save.addEventListener('click', async () => {
    const reply = await ask({ save: state() });
    if (!reply) return;  // the worker restarted (Cancel)
    if (reply.type === 'error') {
      ui.status.textContent = `Save failed: ${reply.message}`;
      setHooks({ stateFile: 'save-error' });
      return;
    }
    ui.status.classList.remove('field-error');
    download(new Blob([reply.json], { type: 'application/json' }), `${stem()}-state.json`, ui.status);
    setHooks({ stateFile: 'saved' });
  });

  ui.open.addEventListener('click', () => ui.input.click());
  ui.input.addEventListener('change', async () => {
    const file = ui.input.files?.[0];
    ui.input.value = '';  // the same file can be opened again
    if (!file) return;
    // The refusal is the line beside Open, scrolled into view (issue 32: it went to the notices at
    // the panel's top, out of view, while this line still said "Opened" of an earlier file).
    const fail = (line) => {
      ui.status.textContent = `Open ${file.name} refused: ${line}`;
      ui.status.classList.add('field-error');
      ui.status.scrollIntoView?.({ block: 'nearest' });
      setHooks({ stateFile: 'open-error' });
    };
    if (file.size > MAX_STATE_BYTES) {
      fail(`${file.size} bytes; the limit is 1 MiB`);
      return;
    }
    let text;
    try {
      text = await file.text();
    } catch (e) {
      fail(`cannot read the file (${e?.message || e})`);
      return;
    }
    const reply = await ask({ open: text });
    if (!reply) return;
    if (reply.type === 'error') {
      fail(reply.message);
      return;
    }
    onOpen(reply.state);
    ui.status.classList.remove('field-error');
    ui.status.textContent = `Opened ${file.name}`;
    setHooks({ stateFile: 'opened' });
  });
}
