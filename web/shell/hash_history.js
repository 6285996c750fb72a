// The page's state in location.hash with one history entry per committed edit: commit() pushes an
// entry, replace() rewrites the current one (camera moves, scrubbing), and back/forward (which
// undo/redo use) arrive as onRestore(). Each entry remembers its position among the edits (index)
// and the furthest edit (max), so Undo/Redo know when to stop, across reloads too.
// Does not: encode or decode the hash text (the core does, through the worker), or debounce.

export class HashHistory {
  // onRestore({extra, typed}): back/forward landed on an entry (typed: a hash the user typed, no
  // saved position), after index/max are updated; extra is what commit/replace saved with it.
  // onChange(): index or max changed (update the Undo/Redo buttons).
  constructor({ onRestore, onChange = () => {} }) {
    this.index = 0;
    this.max = 0;
    this.base = '';  // the committed state's hash text (without view fields the page appends)
    this.onRestore = onRestore;
    this.onChange = onChange;
    const saved = history.state?.niwa;
    if (saved && Number.isInteger(saved.index)) {
      this.index = saved.index;
      // After a reload the forward entries are still there: redo stays available.
      this.max = Math.max(saved.index, Number.isInteger(saved.max) ? saved.max : 0);
    }
    window.addEventListener('popstate', (event) => this.#popped(event));
  }

  // What was saved with the current entry (after a reload: the entry's extra), or undefined.
  savedExtra() {
    return history.state?.niwa?.extra;
  }

  canUndo() { return this.index > 0; }
  canRedo() { return this.index < this.max; }
  undo() { if (this.canUndo()) history.back(); }
  redo() { if (this.canRedo()) history.forward(); }

  // Rewrites the current entry with `hash` (no new entry) when the hash differs; extra: saved with it.
  replace(hash, extra) {
    if (location.hash !== hash) history.replaceState(this.#entry(extra), '', hash);
  }

  // A committed edit with base text `base` and full hash `hash`: a new entry, unless the base is
  // unchanged (then the current entry is rewritten) or nothing was committed yet (the first state
  // of the page rewrites the entry it was opened with).
  commit(base, hash, extra) {
    if (base === this.base || this.base === '') {
      this.base = base;
      this.replace(hash, extra);
      return false;
    }
    this.base = base;
    this.index += 1;
    this.max = this.index;
    history.pushState(this.#entry(extra), '', hash);
    this.onChange();
    return true;
  }

  #entry(extra) {
    return { niwa: { index: this.index, max: this.max, extra } };
  }

  #popped(event) {
    const saved = event.state?.niwa;
    const typed = !(saved && Number.isInteger(saved.index));
    if (typed) {
      this.index = this.max = this.index + 1;  // a typed hash becomes a new edit
    } else {
      this.index = saved.index;
    }
    history.replaceState(this.#entry(typed ? undefined : saved.extra), '', location.href);  // keeps max for a reload
    this.base = '';
    this.onChange();
    this.onRestore({ extra: typed ? undefined : saved.extra, typed });
  }
}
