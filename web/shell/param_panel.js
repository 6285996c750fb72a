// Parameter panel built FROM THE PARAMETER TABLE sent by the worker (no parameter list in JS):
// one collapsible section per `group`, titled by the table's `group_title`, each field labelled
// with key, symbol and unit, limited by the table's min/max, with the help text as title and
// aria-describedby, shown under the row while any of its controls has focus (keyboard or tap).
// Each edit reports the row's `stage` (grow | mesh | sway | view) so the page reruns only what the
// edit invalidates.
// Each slider's mapping (linear, or logarithmic over several decades) is the table row's range's
// (web/shell/slider_scale.js).
// With `later` (the tree page), the closed groups' rows are built after the first group's, one group
// a task (issue 32 item 5: the panel's rows were most of the longest main-thread task of the page's
// load); until then a row keeps its value in the panel, and opening its group, asking for its input
// (element) or marking its error builds its group at once.
// Does not: validate values (the core does and its error line is shown), or send anything.
import { sliderScale } from './slider_scale.js';

// A readable title when a table has no group_title (older WASM builds).
function groupTitle(spec) {
  if (typeof spec.group_title === 'string' && spec.group_title) return spec.group_title;
  return spec.group.replace(/_/g, ' ').replace(/^./, (c) => c.toUpperCase());
}

// The row's stage; rows without one are growth rows (an edit regrows: always correct, if slow).
export const stageOf = (spec) => (['grow', 'mesh', 'sway', 'view'].includes(spec?.stage) ? spec.stage : 'grow');

const isFlag = (spec) => spec.integer && spec.min === 0 && spec.max === 1 && !spec.unit;

function el(tag, attrs = {}, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

// A number input's value as the browser keeps it: a valid floating-point number's text, else ''
// (the HTML value sanitization of <input type=number>).
const FLOAT_TEXT = /^-?(\d+(\.\d+)?|\.\d+)([eE][-+]?\d+)?$/;
const numberText = (v) => (FLOAT_TEXT.test(String(v)) ? String(v) : '');
// A number field's value for the state: valid numbers as numbers, anything else as text (the core
// checks both and says what is wrong).
const readNumber = (text) => (text.trim() !== '' && Number.isFinite(Number(text)) ? Number(text) : text);

export class ParamPanel {
  // container: element to fill; onChange(spec, stage): called after any edit of the row `spec`;
  // later(fn): runs fn in a later task (given: the closed groups' rows are built one group a task).
  constructor(container, paramTable, onChange, { later = null } = {}) {
    this.fields = new Map();  // key -> {spec, read(), write(value), setInvalid(bool), text()}
    this.onChange = onChange;
    this.waiting = new Map(); // a closed <details> whose rows are not built yet -> its specs
    const groups = new Map();
    for (const spec of paramTable) {
      if (!groups.has(spec.group)) groups.set(spec.group, []);
      groups.get(spec.group).push(spec);
    }
    this.stages = new Map(paramTable.map((spec) => [spec.key, stageOf(spec)]));
    let first = true;
    for (const [group, specs] of groups) {
      const details = el('details', { class: 'group' });
      if (first) details.open = true;
      const summary = el('summary', {}, `${groupTitle(specs[0])} (${specs.length})`);
      details.append(summary);
      if (first || !later) {
        for (const spec of specs) details.append(this.#field(spec, onChange));
      } else {
        this.waiting.set(details, specs);
        for (const spec of specs) this.fields.set(spec.key, this.#unbuilt(spec, details));
        // A click on the summary builds the rows before the group opens (no empty frame); toggle
        // covers `open` set by a script.
        summary.addEventListener('click', () => this.#build(details));
        details.addEventListener('toggle', () => this.#build(details));
      }
      first = false;
      container.append(details);
    }
    if (later && this.waiting.size) {
      const next = () => {
        const details = this.waiting.keys().next().value;
        if (details) this.#build(details);
        if (this.waiting.size) later(next);
      };
      later(next);
    }
  }

  // A row not built yet: its value kept as its input would keep it; marking it invalid builds it.
  #unbuilt(spec, details) {
    const flag = isFlag(spec);
    const kept = { written: false, value: flag ? 0 : '' };
    return {
      spec,
      kept,
      read: () => (flag ? kept.value : readNumber(kept.value)),
      write: (v) => {
        kept.written = true;
        kept.value = flag ? (Number(v) !== 0 ? 1 : 0) : numberText(v);
      },
      setInvalid: (bad) => {
        if (bad) {
          this.#build(details);
          this.fields.get(spec.key).setInvalid(true);
        }
      },
      text: () => String(kept.value),
    };
  }

  // Builds the rows of a group that waits (its kept values written into them).
  #build(details) {
    const specs = this.waiting.get(details);
    if (!specs) return;
    this.waiting.delete(details);
    const rows = [];
    for (const spec of specs) {
      const { kept } = this.fields.get(spec.key);
      rows.push(this.#field(spec, this.onChange));
      if (kept.written) this.fields.get(spec.key).write(kept.value);
    }
    details.append(...rows);
  }

  // Builds every row still waiting.
  buildAll() {
    for (const details of [...this.waiting.keys()]) this.#build(details);
  }

  // The input of row `key` (its group built first when it waits), or null.
  element(key) {
    const field = this.fields.get(key);
    if (!field) return null;
    if (field.kept) for (const [details, specs] of this.waiting) if (specs.includes(field.spec)) this.#build(details);
    return document.getElementById(`param-${key}`);
  }

  // Whether the table has row `key`.
  has(key) {
    return this.fields.has(key);
  }

  // The text in row `key`'s input ('' for none), built or not.
  text(key) {
    return this.fields.get(key)?.text() ?? '';
  }

  #field(spec, report) {
    const onChange = () => report(spec, stageOf(spec));
    const id = `param-${spec.key}`;
    const helpId = `help-${spec.key}`;
    const row = el('div', { class: 'field', title: spec.help });
    const label = el('label', { for: id });
    label.append(el('span', { class: 'key' }, spec.key));
    const extra = [spec.symbol, spec.unit].filter(Boolean).join(', ');
    if (extra) label.append(el('span', { class: 'symbol' }, ` (${extra})`));
    const help = el('span', { id: helpId, class: 'help' }, spec.help);
    row.append(label);

    if (isFlag(spec)) {
      const box = el('input', { id, type: 'checkbox', 'aria-describedby': helpId, 'data-key': spec.key });
      box.addEventListener('change', onChange);
      row.classList.add('flag');
      row.append(box, help);
      this.fields.set(spec.key, {
        spec,
        read: () => (box.checked ? 1 : 0),
        write: (v) => { box.checked = Number(v) !== 0; },
        setInvalid: () => {},
        text: () => (box.checked ? '1' : '0'),
      });
      return row;
    }

    const scale = sliderScale(spec);
    const range = el('input', {
      type: 'range', ...scale.attrs, tabindex: '-1', 'aria-hidden': 'true', class: scale.log ? 'slider log' : 'slider',
    });
    const toRange = (v) => {
      const p = scale.position(v);
      if (p !== null) range.value = p;
    };
    const number = el('input', {
      id, type: 'number', min: spec.min, max: spec.max, step: spec.integer ? 1 : 'any',
      inputmode: spec.integer ? 'numeric' : 'decimal', 'aria-describedby': helpId, 'data-key': spec.key,
    });
    range.addEventListener('input', () => {
      number.value = scale.value(range.value);
      onChange();
    });
    number.addEventListener('input', () => {
      toRange(number.value);
      onChange();
    });
    const controls = el('div', { class: 'controls' });
    controls.append(range, number);
    row.append(controls, help);
    this.fields.set(spec.key, {
      spec,
      // Valid numbers go as numbers, anything else as text: the core checks both and says what is wrong.
      read: () => readNumber(number.value),
      write: (v) => { number.value = String(v); toRange(v); },
      setInvalid: (bad) => { number.setAttribute('aria-invalid', bad ? 'true' : 'false'); },
      text: () => number.value,
    });
    return row;
  }

  // The stage of row `key` ('grow' for unknown keys).
  stage(key) {
    return this.stages.get(key) || 'grow';
  }

  // params: {key: value}
  setValues(params) {
    for (const [key, value] of Object.entries(params)) this.fields.get(key)?.write(value);
  }

  values() {
    const out = {};
    for (const [key, field] of this.fields) out[key] = field.read();
    return out;
  }

  // Marks the row of state field `field` (a core error's field; '' clears every mark).
  markError(field) {
    for (const [key, row] of this.fields) row.setInvalid(key === field);
  }
}
