// What the tree page shows while an edit is on its way (issue 17 item 6): the core's error
// beside the field it names (the panel row, a basic field or a Getting started control), opened and
// scrolled into view, and a "stale" label over the view from the first edit until the tree that
// answers it is drawn (or, after an error, until a good value is drawn).
// Does not: check values (the core does), send requests, or decide which tree is current.
import { errorLineIn, newErrorLine } from '../shell/field_errors.js';

export class EditFeedback {
  // stage: the element the label covers (the view's section); basics: {key: input} of the fields
  // outside the panel (seed, years, preset); the panel rows are found by their input id param-KEY.
  constructor(stage, basics) {
    this.basics = basics;
    this.label = document.createElement('p');
    this.label.id = 'stale';
    this.label.className = 'stale';
    this.label.setAttribute('role', 'status');
    this.label.hidden = true;
    stage.append(this.label);
    this.shown = [];
  }

  // Marks the tree on screen as stale: `why` says what it is waiting for.
  stale(why = 'stale: growing the new tree…') {
    this.label.textContent = why;
    this.label.hidden = false;
    document.documentElement.dataset.stale = '1';
  }

  // The tree on screen answers the latest edit.
  fresh() {
    this.label.hidden = true;
    document.documentElement.dataset.stale = '0';
  }

  // The hosts an error of `key` is shown in: the panel row, the basic field's parent, and every
  // Getting started control bound to the key (elements with data-for-key=KEY).
  #hosts(key) {
    const hosts = [];
    const input = this.basics[key] || document.getElementById(`param-${key}`);
    const row = input?.closest('.field') || (this.basics[key] ? input.parentElement : null);
    if (row) hosts.push({ host: row, input });
    for (const control of document.querySelectorAll(`[data-for-key="${CSS.escape(key)}"]`)) {
      hosts.push({ host: control, input: null });
    }
    return hosts;
  }

  // Shows an error (the worker's error reply or record {field, message}: field the state key,
  // message its one line) beside its field(s) and clears the others; a falsy error clears all.
  // Returns true when a field was found for it.
  showError(error) {
    const message = error ? String(error.message || '') : '';
    const key = error ? error.field || null : null;
    for (const line of this.shown) {
      line.hidden = true;
      line.textContent = '';
    }
    this.shown = [];
    for (const input of Object.values(this.basics)) input.removeAttribute('aria-invalid');
    if (!key) {
      if (message) this.stale('stale: this is the last good tree (see the notice in the panel)');
      return false;
    }
    const hosts = this.#hosts(key);
    let first = null;
    let firstTyped = false;
    for (const { host, input } of hosts) {
      // A basic field's line goes after the field (its parent is the grid of the basics).
      const line = this.basics[key] && input ? this.#lineAfter(input) : errorLineIn(host);
      line.textContent = message;
      line.hidden = false;
      this.shown.push(line);
      if (input && this.basics[key]) input.setAttribute('aria-invalid', 'true');
      const details = host.closest('details');
      if (details && !details.open && !host.closest('.getting-started')) details.open = true;
      if (host.offsetParent === null) continue;
      // The field being typed in keeps the view: its own line, not another copy of the row's.
      const typedIn = host.contains(document.activeElement) || input === document.activeElement;
      if (!first || (typedIn && !firstTyped)) first = line;
      firstTyped ||= typedIn;
    }
    first?.scrollIntoView({ block: 'nearest' });
    this.stale(hosts.length > 0 ? 'stale: this is the last good tree; fix the field marked in red'
      : 'stale: this is the last good tree (see the notice in the panel)');
    return hosts.length > 0;
  }

  #lineAfter(input) {
    const next = input.nextElementSibling;
    if (next?.classList.contains('field-error')) return next;
    const line = newErrorLine();
    input.after(line);
    return line;
  }
}
