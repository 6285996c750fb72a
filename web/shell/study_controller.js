// The study pages' one controller (tree, ivy, terrain and the grove; moss, bark and the garden
// next): the study's worker (and a page's further clients of it: the grove's one per unique tree)
// and its restart on Cancel, a worker failure in the notices, the progress line with Cancel (shown while an update
// or an export runs), debounced updates that carry the earliest stage their edits touched (only
// while typing or dragging: a committed value, a `change` event, sends the waiting edit at once),
// edits that arrive while an update is in flight merged into one update sent when it is answered, the
// restage counters and the stages a restage re-did, the grown state's history entry (a commit or
// a replace, with the page's view fields and extras), export routing to downloads (any number of
// kinds and variants, a refusal beside the button that asked), and the error reply routed to the
// export that failed or beside the field it names.
// Does not: know a study's state, panel or replies other than 'update' / 'export' / 'error'
// (the page installs its own handlers on `worker`), draw, play a timeline, or decide what a stage
// re-does (the core run does: core/<study>/<study>_run.h Update; the worker answers with `stages`).
import { FieldErrors } from './field_errors.js';
import { HashHistory } from './hash_history.js';
import { download } from './study_page.js';
import { bumpHook, hookValue, setHooks } from './test_hooks.js';
import { WorkerClient, restartWorker } from './worker_client.js';

const STAGES = ['grow', 'mesh', 'sway', 'view'];
const earlier = (a, b) => (STAGES.indexOf(a) <= STAGES.indexOf(b) ? a : b);

// A number when the input holds one, else its text (the core then names the field).
export const numberOr = (input) => (input.value.trim() !== '' && Number.isFinite(Number(input.value)) ? Number(input.value) : input.value);

export class StudyController {
  // study: the worker handler's name (and the client's); notices: the page's Notices (with an
  // 'error' kind); ui: {progress, cancel, shareStatus, progressBar?}; fields: {stateKey:
  // errorElementId} of the controls outside the panel; panel: () => the ParamPanel (for errors
  // beside its rows); errors: {show(error)} in place of those two (the page's own error lines);
  // state(): the state to grow; onCancel(): the page's own part of a Cancel (its text);
  // onRestart(): after Cancel the worker is new: the page sends init again; onError(msg, when):
  // the page's part of an error of the latest update, 'before' the controller shows it (return
  // true to stop: a reply of the page's own requests) and 'after'; viewHash(): view fields the
  // page appends to the state's hash (the tree's camera, '&cam=...'); historyExtra(): what each
  // history entry keeps beside its hash (the tree's year shown); onRestore(extra): back/forward
  // landed on an entry, before its state is decoded; onHistoryChange(): Undo/Redo availability
  // changed. debounceMs: the quiet moment before an edit of `input` events goes (typing, a slider
  // dragged); commits: the node whose bubbling `change` events (Enter or blur in a field, a select,
  // a checkbox, a slider let go) send the waiting edit at once (issue 32 item 5: the debounce alone
  // was over an edit's budget; default the document, null for none: an embed); coalesceMs: an
  // edit waits this long at most for the update in flight to be answered (issue 17: a one-second
  // slider drag regrew 17 trees) before it supersedes it (a long grow never holds the newest edit
  // back). name: the controller's client (default: the study's name); history: false for a page
  // whose hash is its own view, not a state (the grove, an embed: no history entries, back/forward
  // decode nothing); a page without Cancel omits ui.cancel (and ui.progress); hooks: the element
  // whose data-* the tests read (an embed's own; default the document's).
  constructor({
    study, name = study, notices, ui, fields = {}, panel, errors, state, onCancel, onRestart, onError,
    viewHash, historyExtra, onRestore, onHistoryChange, debounceMs = 250, coalesceMs = 400, history = true,
    hooks = document.documentElement, commits = document,
  }) {
    this.study = study;
    this.hooks = hooks;
    this.notices = notices;
    this.ui = ui;
    this.state = state;
    this.onError = onError || (() => {});
    this.viewHash = viewHash || (() => '');
    this.historyExtra = historyExtra || (() => undefined);
    this.debounceMs = debounceMs;
    this.coalesceMs = coalesceMs;
    this.latestId = 0;
    this.commitNext = false;  // the next grown state is a new history entry
    this.pendingStage = null; // the earliest stage the edits since the last update touched
    this.editPending = false; // an edit waits (for its debounce or for the update in flight)
    this.editQueued = false;  // ... and its debounce is over: it goes when the update is answered
    this.pendingSend = null;  // the page's sender of that edit
    this.inFlight = false;    // the latest update is not answered yet
    this.inFlightSince = 0;
    this.working = false;     // the page shows work in progress (an update)
    this.debounceTimer = 0;
    this.queueTimer = 0;
    this.exportCount = 0;
    this.exports = new Map(); // request id -> {name, type, onRefused}
    this.fieldErrors = errors || new FieldErrors(fields, panel, (message) => notices.set('field', message));
    this.onFailure = (text) => {
      this.inFlight = false;
      notices.set('error', text);
      setHooks({ status: 'error' }, this.hooks);
    };
    this.worker = new WorkerClient(name, { study, onFailure: this.onFailure, onRestart: () => onRestart?.() });
    this.history = history ? new HashHistory({
      onChange: onHistoryChange,
      onRestore: ({ extra }) => {
        onRestore?.(extra);
        this.worker.request('decode', { hash: location.hash }, { done: ['decoded'] });
      },
    }) : null;
    ui.cancel?.addEventListener('click', () => this.cancel(onCancel));
    this.worker.on('export', (msg) => this.#exported(msg));
    this.worker.on('error', (msg) => this.#failed(msg));
    // Bubbling: the control's own handlers (which schedule the edit) have run by then.
    commits?.addEventListener('change', () => this.commitWaiting());
    if (hookValue('growRequests', this.hooks) === undefined) setHooks({ growRequests: 0, restageRequests: 0 }, this.hooks);
  }

  // Another client of the page's worker for this study (the grove's one per unique tree): a worker
  // failure shows as the controller's own; onRestart: its part after Cancel restarted the worker.
  // The page installs its handlers on it.
  client(name, { onRestart } = {}) {
    return new WorkerClient(name, { study: this.study, onFailure: this.onFailure, onRestart });
  }

  // Shows or hides the work of an update (Cancel and, with it off, the progress bar); Cancel stays
  // while an export runs.
  showWork(on) {
    this.working = on;
    if (this.ui.cancel) this.ui.cancel.hidden = !(on || this.exports.size > 0);
    if (!on && this.ui.progressBar) this.ui.progressBar.hidden = true;
  }

  // Ends the work in the worker at once: the worker is restarted (web/shell/worker_client.js);
  // waiting edits and exports are dropped.
  cancel(onCancel) {
    clearTimeout(this.debounceTimer);
    clearTimeout(this.queueTimer);
    this.pendingStage = null;
    this.editPending = false;
    this.editQueued = false;
    this.inFlight = false;
    this.exports.clear();
    this.showWork(false);
    if (this.ui.progress) this.ui.progress.textContent = onCancel ? onCancel() : 'cancelled';
    bumpHook('cancels', this.hooks);
    setHooks({ status: 'cancelled' }, this.hooks);
    restartWorker();
  }

  // Sends the state to grow now (`fields` beside it: a `state` there replaces state()); commit: a
  // new history entry once grown (an edit still waiting is carried, and committed, by it too).
  // The message's `stage`: `stage` when given (an update that is no edit: 'grow'), else the
  // earliest stage the edits since the last update touched ('grow' when none is known); a later
  // stage than 'grow' is a restage (data-restage-requests; data-grow-requests counts the others).
  // Returns the request {id, reply} with its `stage`.
  update(commit, fields = {}, { done, stage } = {}) {
    clearTimeout(this.debounceTimer);
    clearTimeout(this.queueTimer);
    this.commitNext = this.commitNext || commit || this.editPending;
    const sent = stage || this.pendingStage || 'grow';
    this.pendingStage = null;
    this.editPending = false;
    this.editQueued = false;
    setHooks({ status: 'growing', updateStage: sent }, this.hooks);
    const request = this.worker.request('update', { state: this.state(), stage: sent, ...fields }, { group: this.study, done });
    this.latestId = request.id;
    this.inFlight = true;
    this.inFlightSince = performance.now();
    this.showWork(true);
    bumpHook(sent === 'grow' ? 'growRequests' : 'restageRequests', this.hooks);
    setHooks({ updateSentMs: this.inFlightSince.toFixed(1) }, this.hooks);  // tests: when it went (page clock)
    request.reply.then((reply) => this.#answered(request.id, reply));
    return { ...request, stage: sent };
  }

  // An edit: the update goes after a quiet moment (one update for a burst of edits), by
  // send(), or at the `change` that commits it (commitWaiting); `stage`: the edited row's
  // (param_panel.js stageOf), 'grow' for the controls outside the panel. While a young update is in flight the edit waits for its answer (merged: one update
  // carries every edit since).
  schedule(send, stage = 'grow') {
    this.notices.set('hash', []);
    this.editPending = true;
    this.pendingSend = send;
    this.pendingStage = this.pendingStage ? earlier(this.pendingStage, stage) : stage;
    clearTimeout(this.debounceTimer);
    setHooks({ status: 'pending' }, this.hooks);
    this.debounceTimer = setTimeout(() => this.#flush(), this.debounceMs);
  }

  // A committed value (a `change` event): the edit waiting for its quiet moment, or queued behind
  // the update in flight, goes now (it supersedes that update); nothing when none waits (its
  // debounce sent it already).
  commitWaiting() {
    if (!this.editPending) return;
    bumpHook('editsCommitted', this.hooks);
    this.pendingSend();
  }

  // An edit waits to be sent (the page keeps its "stale" look meanwhile).
  editWaiting() {
    return this.editPending;
  }

  // Sends the waiting edit, or queues it while a young update is in flight (its answer, or the
  // update's coalesceMs age, sends it).
  #flush() {
    if (!this.editPending) return;
    const age = performance.now() - this.inFlightSince;
    if (this.inFlight && age < this.coalesceMs) {
      if (!this.editQueued) bumpHook('editsCoalesced', this.hooks);
      this.editQueued = true;
      clearTimeout(this.queueTimer);
      this.queueTimer = setTimeout(() => this.#flush(), this.coalesceMs - age);
      return;
    }
    this.pendingSend();
  }

  // The update `id` was answered (its done reply or an error; null: the worker restarted). The
  // stages a restage re-did go to data-restaged-stages; a queued edit goes now.
  #answered(id, reply) {
    if (id !== this.latestId) return;  // superseded: a newer update is in flight
    this.inFlight = false;
    clearTimeout(this.queueTimer);
    if (reply && Array.isArray(reply.stages)) setHooks({ restagedStages: reply.stages.join(',') }, this.hooks);
    if (this.editQueued && this.editPending) {
      this.editQueued = false;
      this.pendingSend();
    }
  }

  isLatest(msg) {
    return msg.id === this.latestId;
  }

  // The hash of the state `base` (the core's text) with the page's view fields appended.
  fullHash(base = this.history?.base ?? '') {
    return `#${base}${base ? this.viewHash() : ''}`;
  }

  // The grown state's link: a new history entry after an edit, else the current one replaced;
  // either keeps the page's extras.
  grown(hash) {
    if (!this.history) return;
    if (this.commitNext) this.history.commit(hash, this.fullHash(hash), this.historyExtra());
    else {
      this.history.base = hash;
      this.writeHash();
    }
    this.commitNext = false;
  }

  // Rewrites the current history entry (a camera move, scrubbing: no new entry).
  writeHash() {
    if (!this.history?.base) return;
    this.history.replace(this.fullHash(), this.historyExtra());
  }

  // A core error (a {field, message} record or its line) beside its field; '' clears them.
  showFieldError(error) {
    this.fieldErrors.show(error);
  }

  // Asks the worker for `format` of the last result (`fields` beside it: a variant and its
  // values) and downloads it as `name` (`type`: its MIME type). Each export is its own request
  // (none supersedes another); Cancel ends it. onRefused(msg): the page shows a refusal (the
  // worker's error) beside the button that asked, and the share line points there.
  exportAs(format, name, type, fields = {}, { onRefused } = {}) {
    const { id } = this.worker.request('export', { format, ...fields },
      { group: `export-${++this.exportCount}`, done: ['export'] });
    this.exports.set(id, { name, type, onRefused });
    this.showWork(this.working);
  }

  #exported(msg) {
    const file = this.exports.get(msg.id);
    if (!file) return;
    this.exports.delete(msg.id);
    this.showWork(this.working);
    download(new Blob([msg.bytes], { type: file.type }), file.name, this.ui.shareStatus);
    setHooks({ exported: `${msg.format}:${msg.bytes.byteLength}` }, this.hooks);
  }

  // An error reply: an export's goes to the share line (or beside its button); the latest
  // update's (or one with no id) beside its field and in the notices; a superseded one is
  // dropped. The page's onError runs for any error not an export's (it may handle its own
  // requests first and return true to stop).
  #failed(msg) {
    const file = this.exports.get(msg.id);
    if (file) {
      this.exports.delete(msg.id);
      this.showWork(this.working);
      if (file.onRefused) {
        this.ui.shareStatus.textContent = 'Export failed (the reason is beside its button).';
        file.onRefused(msg);
      } else {
        this.ui.shareStatus.textContent = `Export failed: ${msg.message}`;
      }
      return;
    }
    if (this.onError(msg, 'before') === true) return;
    if (msg.id !== undefined && msg.id !== this.latestId) return;
    this.commitNext = false;
    this.showWork(false);
    this.notices.set('error', msg.message);
    this.showFieldError(msg);
    if (this.ui.progress) this.ui.progress.textContent = '';
    setHooks({ status: 'error', error: msg.message }, this.hooks);
    this.onError(msg, 'after');
  }
}
