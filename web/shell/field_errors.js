// A study page's core errors ({field, message} records) shown beside the field they name: a basic field's
// own error element (by id), or a line added to the parameter panel's row of input `param-KEY`;
// showing one clears every other, and the panel marks the row. Used by the ivy and terrain pages;
// the tree page's edit feedback shares its error lines.
// Does not: check values (the core does), or decide which message is current.
import { setHooks } from './test_hooks.js';

// A new, hidden error line (<p class="field-error" role="alert">).
export function newErrorLine() {
  const line = document.createElement('p');
  line.className = 'field-error';
  line.setAttribute('role', 'alert');
  line.hidden = true;
  return line;
}

// The error line among host's children, added at its end the first time.
export function errorLineIn(host) {
  let line = [...host.children].find((c) => c.classList.contains('field-error'));
  if (!line) {
    line = newErrorLine();
    host.append(line);
  }
  return line;
}

export class FieldErrors {
  // basics: {key: id of its error element}; panel(): the page's ParamPanel or null; orphan(message):
  // shows an error whose field has no line on this page (e.g. a file's inner key), so that no
  // error is ever dropped unseen (issue 34: a contour file's repeated key vanished).
  constructor(basics, panel, orphan = () => {}) {
    this.basics = basics;
    this.panel = panel;
    this.orphan = orphan;
  }

  #line(key) {
    if (this.basics[key]) return document.getElementById(this.basics[key]);
    const row = document.getElementById(`param-${key}`)?.closest('.field');
    return row ? errorLineIn(row) : null;
  }

  // Shows an error beside its field (a falsy one clears them all); the test hooks learn the key.
  // `error`: the worker's error reply or an error record {field, message} (the core's Status at
  // the boundary: field is a state key, maybe prefixed on a composed page; message its one line).
  show(error) {
    for (const line of document.querySelectorAll('.field-error')) {
      line.hidden = true;
      line.textContent = '';
    }
    const key = error && typeof error === 'object' ? error.field || '' : '';
    const message = error && typeof error === 'object' ? String(error.message || '') : '';
    this.panel()?.markError(key);
    this.orphan('');
    if (!key && !message) return;
    const line = key ? this.#line(key) : null;
    if (!line) {
      this.orphan(message);
      return;
    }
    line.textContent = message;
    line.hidden = false;
    setHooks({ fieldError: key });
  }
}
