// The study pages' one controller (ivy, terrain; moss, bark and the garden next): the study's
// worker and its restart on Cancel, the progress line with Cancel, debounced updates that carry
// the earliest stage their edits touched, the grown state's history entry (a commit or a
// replace), export routing to downloads, and the error reply routed to the export that failed or
// beside the field it names.
// Does not: know a study's state, panel or replies other than 'update' / 'export' / 'error'
// (the page installs its own handlers on `worker`), draw, or decide what a stage re-does (the
// core run does: core/<study>/<study>_run.h Update).
import { FieldErrors } from './field_errors.js';
import { HashHistory } from './hash_history.js';
import { download } from './study_page.js';
import { bumpHook, setHooks } from './test_hooks.js';
import { WorkerClient, restartWorker } from './worker_client.js';

const STAGES = ['grow', 'mesh', 'sway', 'view'];
const earlier = (a, b) => (STAGES.indexOf(a) <= STAGES.indexOf(b) ? a : b);

// A number when the input holds one, else its text (the core then names the field).
export const numberOr = (input) => (input.value.trim() !== '' && Number.isFinite(Number(input.value)) ? Number(input.value) : input.value);

export class StudyController {
  // study: the worker handler's name; notices: the page's Notices (with an 'error' kind);
  // ui: {progress, cancel, shareStatus, progressBar?}; fields: {stateKey: errorElementId} of the
  // controls outside the panel; panel: () => the ParamPanel (for errors beside its rows);
  // state(): the state to grow; onCancel(): the page's own part of a Cancel (its text);
  // onRestart(): after Cancel the worker is new: the page sends init again; onError(msg): the
  // page's part of an error of the latest update (hooks), after the controller showed it.
  constructor({ study, notices, ui, fields = {}, panel, state, onCancel, onRestart, onError, debounceMs = 250 }) {
    this.study = study;
    this.notices = notices;
    this.ui = ui;
    this.state = state;
    this.onError = onError || (() => {});
    this.debounceMs = debounceMs;
    this.latestId = 0;
    this.commitNext = false;  // the next grown state is a new history entry
    this.pendingStage = null; // the earliest stage the edits since the last update touched
    this.debounceTimer = 0;
    this.exports = new Map(); // request id -> {name, type}
    this.fieldErrors = new FieldErrors(fields, panel, (message) => notices.set('field', message));
    this.worker = new WorkerClient(study, {
      study,
      onFailure: (text) => {
        notices.set('error', text);
        setHooks({ status: 'error' });
      },
      onRestart: () => onRestart(),
    });
    this.history = new HashHistory({
      onRestore: () => this.worker.request('decode', { hash: location.hash }, { done: ['decoded'] }),
    });
    ui.cancel.addEventListener('click', () => this.cancel(onCancel));
    this.worker.on('export', (msg) => this.#exported(msg));
    this.worker.on('error', (msg) => this.#failed(msg));
  }

  // Shows or hides Cancel (and with it off, the progress bar).
  showWork(on) {
    this.ui.cancel.hidden = !on;
    if (!on && this.ui.progressBar) this.ui.progressBar.hidden = true;
  }

  // Ends the work in the worker at once: the worker is restarted (web/shell/worker_client.js).
  cancel(onCancel) {
    this.showWork(false);
    clearTimeout(this.debounceTimer);
    this.pendingStage = null;
    this.ui.progress.textContent = onCancel ? onCancel() : 'cancelled';
    bumpHook('cancels');
    setHooks({ status: 'cancelled' });
    restartWorker();
  }

  // Sends the state to grow now (`fields` beside it); commit: a new history entry once grown.
  // The message's `stage` is the earliest stage the edits since the last update touched ('grow'
  // when none is known).
  update(commit, fields = {}, { done }) {
    clearTimeout(this.debounceTimer);
    this.commitNext = this.commitNext || commit;
    const stage = this.pendingStage || 'grow';
    this.pendingStage = null;
    setHooks({ status: 'growing', updateStage: stage });
    const request = this.worker.request('update', { state: this.state(), stage, ...fields }, { group: this.study, done });
    this.latestId = request.id;
    this.showWork(true);
    bumpHook('growRequests');
    return request;
  }

  // An edit: the update goes after a quiet moment (one update for a burst of edits); `stage`: the
  // edited row's (param_panel.js stageOf), 'grow' for the controls outside the panel.
  schedule(send, stage = 'grow') {
    this.notices.set('hash', []);
    this.pendingStage = this.pendingStage ? earlier(this.pendingStage, stage) : stage;
    clearTimeout(this.debounceTimer);
    setHooks({ status: 'pending' });
    this.debounceTimer = setTimeout(send, this.debounceMs);
  }

  isLatest(msg) {
    return msg.id === this.latestId;
  }

  // The grown state's link: a new history entry after an edit, else the current one replaced.
  grown(hash) {
    if (this.commitNext) this.history.commit(hash, `#${hash}`);
    else {
      this.history.base = hash;
      this.history.replace(`#${hash}`);
    }
    this.commitNext = false;
  }

  // A core error (a {field, message} record or its line) beside its field; '' clears them.
  showFieldError(error) {
    this.fieldErrors.show(error);
  }

  // Asks the worker for `format` of the last result and downloads it as `name` (`type`: its MIME type).
  exportAs(format, name, type, fields = {}) {
    const { id } = this.worker.request('export', { format, ...fields }, { group: `export-${format}`, done: ['export'] });
    this.exports.set(id, { name, type });
  }

  #exported(msg) {
    const file = this.exports.get(msg.id);
    if (!file) return;
    this.exports.delete(msg.id);
    download(new Blob([msg.bytes], { type: file.type }), file.name, this.ui.shareStatus);
    setHooks({ exported: `${msg.format}:${msg.bytes.byteLength}` });
  }

  // An error reply: an export's goes to the share line; the latest update's (or one with no id)
  // beside its field and in the notices; a superseded one is dropped. The page's onError runs for
  // any error not an export's (it may handle its own requests first and return true to stop).
  #failed(msg) {
    if (this.exports.delete(msg.id)) {
      this.ui.shareStatus.textContent = `Export failed: ${msg.message}`;
      return;
    }
    if (this.onError(msg, 'before') === true) return;
    if (msg.id !== undefined && msg.id !== this.latestId) return;
    this.showWork(false);
    this.notices.set('error', msg.message);
    this.showFieldError(msg);
    this.ui.progress.textContent = '';
    setHooks({ status: 'error', error: msg.message });
    this.onError(msg, 'after');
  }
}
