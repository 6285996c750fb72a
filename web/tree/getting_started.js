// The tree page's "Getting started" panel (issue 17 item 8): what the tree is and what to try
// first, in plain words, and a small group of the most effective controls named for what they do.
// The group is generated FROM THE TABLE the worker sends: its rows with a `simple` name (the core
// adds them from core/tree/tree_simple.cpp), plus Age, which is the state's Years field.
// Each control writes its table row's field (or Years) and fires that field's own input event, so
// an edit here is exactly an edit of the row; the full table below keeps the thesis's names.
// Each slider maps its row's range as the full table's slider of the row does (web/shell/slider_scale.js:
// Shoot length, 0.01-100 cm, is logarithmic in both).
// Does not: hold a list of parameters, check values, or send anything itself.
import { sliderScale } from '../shell/slider_scale.js';

function el(tag, attrs = {}, text) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

// The rows of `paramTable` in the group, in table order.
export const simpleRows = (paramTable) => paramTable.filter((spec) => typeof spec.simple === 'string' && spec.simple);

export class GettingStarted {
  // container: an element to fill; paramTable: the worker's table; years: the Years input;
  // openRow(key): shows a row of the full table (opens its section, focuses it); rows: the full
  // table's rows ({has(key), text(key), element(key)}: the ParamPanel, whose closed groups may not be built
  // yet: a control reads its row's value through text() and asks for the row's input only to write it).
  constructor(container, paramTable, years, openRow, rows) {
    this.controls = [];
    const box = el('details', { class: 'getting-started', open: '' });
    box.append(el('summary', {}, 'Getting started'));
    const intro = el('div', { class: 'intro' });
    intro.append(
      el('p', {}, 'This is a tree grown year by year from a seedling: each spring its buds open into '
        + 'shoots, the shoots that get more light grow longer, and shaded ones die back, as in '
        + 'Kanayama\'s growth model.'),
      el('p', {}, 'Try first: pick a Preset, drag Age to watch it grow, press Blow for wind, and '
        + 'click or tap a branch, then Cut, to prune it. Undo takes any step back.'));
    box.append(intro);
    const group = el('div', { class: 'simple-controls', role: 'group', 'aria-label': 'Main controls' });
    group.append(this.#control({
      key: 'years', label: 'Age', unit: 'years', range: { min: Number(years.min), max: Number(years.max), integer: true },
      help: 'How many years the tree has grown.', target: { text: () => years.value, element: () => years }, row: 'Years',
    }));
    for (const spec of simpleRows(paramTable)) {
      if (!rows.has(spec.key)) continue;
      group.append(this.#control({
        key: spec.key, label: spec.simple, unit: spec.unit, range: spec,
        help: spec.simple_help || spec.help, target: { text: () => rows.text(spec.key), element: () => rows.element(spec.key) },
        row: [spec.key, spec.symbol].filter(Boolean).join(', '), openRow: () => openRow(spec.key),
      }));
    }
    box.append(group);
    box.append(el('p', { class: 'help-text' }, 'Every setting, under the names of the thesis, is in the '
      + 'full table below.'));
    container.append(box);
    this.root = box;
  }

  #control({ key, label, unit, range: spec, help, target, row, openRow }) {
    const scale = sliderScale(spec);
    const id = `simple-${key}`;
    const wrap = el('div', { class: 'simple', 'data-for-key': key });
    const head = el('label', { for: id });
    head.append(el('span', { class: 'simple-name' }, label));
    if (unit) head.append(el('span', { class: 'symbol' }, ` (${unit})`));
    const helpId = `simple-help-${key}`;
    const range = el('input', { type: 'range', ...scale.attrs, tabindex: '-1', 'aria-hidden': 'true', class: scale.log ? 'slider log' : 'slider' });
    const number = el('input', { id, type: 'number', min: spec.min, max: spec.max, step: 'any', 'aria-describedby': helpId,
      inputmode: spec.integer ? 'numeric' : 'decimal' });
    const toRange = (v) => {
      const p = scale.position(v);
      if (p !== null) range.value = p;
    };
    const write = (value) => {
      const input = target.element();
      input.value = value;
      input.dispatchEvent(new Event('input', { bubbles: true }));
    };
    range.addEventListener('input', () => {
      number.value = scale.value(range.value);
      write(number.value);
    });
    number.addEventListener('input', () => {
      toRange(number.value);
      write(number.value);
    });
    const controls = el('div', { class: 'controls' });
    controls.append(range, number);
    const text = el('p', { id: helpId, class: 'simple-help' }, help);
    if (openRow) {
      const link = el('button', { type: 'button', class: 'row-link', title: `Show ${key} in the full table` }, `table: ${row}`);
      link.addEventListener('click', openRow);
      text.append(' ', link);
    } else {
      text.append(` (the ${row} field below)`);
    }
    wrap.append(head, controls, text);
    this.controls.push({ key, target, range, number, toRange });
    return wrap;
  }

  // Shows the values of the fields the controls are bound to (after a state is applied or any edit).
  sync() {
    for (const c of this.controls) {
      if (document.activeElement === c.number) continue;  // the user is typing here
      c.number.value = c.target.text();
      c.toRange(c.target.text());
    }
  }
}
