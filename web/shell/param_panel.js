// Parameter panel built FROM THE PARAMETER TABLE sent by the worker (no parameter list in JS):
// one collapsible section per `group`, titled by the table's `group_title`, each field labelled
// with key, symbol and unit, limited by the table's min/max, with the help text as title and
// aria-describedby, shown under the row while any of its controls has focus (keyboard or tap).
// Each edit reports the row's `stage` (grow | mesh | sway | view) so the page reruns only what the
// edit invalidates.
// Each slider's mapping (linear, or logarithmic over several decades) is the table row's range's
// (web/shell/slider_scale.js).
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

export class ParamPanel {
  // container: element to fill; onChange(spec, stage): called after any edit of the row `spec`.
  constructor(container, paramTable, onChange) {
    this.fields = new Map();  // key -> {spec, read(), write(value), setInvalid(bool)}
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
      first = false;
      details.append(el('summary', {}, `${groupTitle(specs[0])} (${specs.length})`));
      for (const spec of specs) details.append(this.#field(spec, onChange));
      container.append(details);
    }
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
      read: () => (number.value.trim() !== '' && Number.isFinite(Number(number.value)) ? Number(number.value) : number.value),
      write: (v) => { number.value = String(v); toRange(v); },
      setInvalid: (bad) => { number.setAttribute('aria-invalid', bad ? 'true' : 'false'); },
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
