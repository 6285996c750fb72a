// A study page's core error lines ("key: ...") shown beside the field they name: a basic field's
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
  // basics: {key: id of its error element}; panel(): the page's ParamPanel or null.
  constructor(basics, panel) {
    this.basics = basics;
    this.panel = panel;
  }

  #line(key) {
    if (this.basics[key]) return document.getElementById(this.basics[key]);
    const row = document.getElementById(`param-${key}`)?.closest('.field');
    return row ? errorLineIn(row) : null;
  }

  // Shows `message` beside its field ("" clears them all); the test hooks learn the key.
  show(message) {
    for (const line of document.querySelectorAll('.field-error')) {
      line.hidden = true;
      line.textContent = '';
    }
    this.panel()?.markError(message || '');
    if (!message) return;
    const key = /^([A-Za-z_][A-Za-z_0-9]*):/.exec(message)?.[1];
    const line = key ? this.#line(key) : null;
    if (!line) return;
    line.textContent = message;
    line.hidden = false;
    setHooks({ fieldError: key });
  }
}
