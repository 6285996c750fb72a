// The one mapping between a table row's value and its slider's position, taken from the row's range
// (min, max, integer) alone: every slider built from a parameter table (the panel's rows,
// web/shell/param_panel.js; the tree's Getting started controls, web/tree/getting_started.js) uses it,
// so no page decides a row's slider for itself.
// The decades rule: a row of real numbers whose range spans three decades or more (max/min >= 1000 with
// min > 0: Shoot length 0.01-100 cm, dt 0.0001-0.1 s) gets a logarithmic slider, positions 0..LOG_STEPS
// for min·(max/min)^(p/LOG_STEPS) at three significant digits (a linear one put all of 0.01-1 cm in its
// first pixel, issue 32); any other row a linear one, step 1 for whole numbers, else a power of ten
// about a thousandth of the range. The number field beside a slider stays exact either way.
// Does not: check values (the core does), or build any element.

export const LOG_STEPS = 1000;

// Slider step of a linear row: 1 for whole numbers, else a power of ten about a thousandth of the range.
export function stepOf(spec) {
  if (spec.integer) return 1;
  const range = spec.max - spec.min;
  return range > 0 ? 10 ** (Math.floor(Math.log10(range)) - 3) : 'any';
}

export const isLogRow = (spec) => !spec.integer && spec.min > 0 && spec.max / spec.min >= 1000;

export function logSliderValue(spec, position) {
  const v = spec.min * (spec.max / spec.min) ** (Number(position) / LOG_STEPS);
  return Math.min(spec.max, Math.max(spec.min, Number(v.toPrecision(3))));
}

export function logSliderPosition(spec, value) {
  const v = Number(value);
  if (!(v > 0)) return 0;
  const p = Math.round((LOG_STEPS * Math.log(v / spec.min)) / Math.log(spec.max / spec.min));
  return Math.min(LOG_STEPS, Math.max(0, p));
}

// spec: {min, max, integer} (a table row, or a field shaped like one). Returns the slider's
// attributes {min, max, step}, whether it is logarithmic, position(value) -> the slider's value
// (a string, or null for a value that is not a finite number: the slider stays) and value(position) ->
// the row's value as the number field's text.
export function sliderScale(spec) {
  const log = isLogRow(spec);
  const finite = (v) => v !== '' && v !== null && Number.isFinite(Number(v));
  return {
    log,
    attrs: log ? { min: 0, max: LOG_STEPS, step: 1 } : { min: spec.min, max: spec.max, step: stepOf(spec) },
    position: (v) => (finite(v) ? String(log ? logSliderPosition(spec, v) : v) : null),
    value: (p) => String(log ? logSliderValue(spec, p) : p),
  };
}
