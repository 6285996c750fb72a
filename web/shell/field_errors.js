// A study page's core error lines ("key: ...") shown beside the field they name: a basic field's
// own error element (by id), or a line added to the parameter panel's row of input `param-KEY`;
// showing one clears every other, and the panel marks the row. Used by the ivy and terrain pages.
// Does not: check values (the core does), or decide which message is current.
import { setHooks } from './test_hooks.js';

export class FieldErrors {
  // basics: {key: id of its error element}; panel(): the page's ParamPanel or null.
  constructor(basics, panel) {
    this.basics = basics;
    this.panel = panel;
  }

  #line(key) {
    if (this.basics[key]) return document.getElementById(this.basics[key]);
    const row = document.getElementById(`param-${key}`)?.closest('.field');
    if (!row) return null;
    let line = row.querySelector('.field-error');
    if (!line) {
      line = document.createElement('p');
      line.className = 'field-error';
      line.setAttribute('role', 'alert');
      line.hidden = true;
      row.append(line);
    }
    return line;
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
