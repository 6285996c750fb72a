// The bark page's charts, from the run's per-tenth-cycle samples (BarkRun::CyclesCsv, the CLI's
// `--csv`), as SVG line charts with a marker at the step the cycle scrubber shows: the broken
// share of each spring family (axial: horizontal cracks; diagonal: vertical cracks) against growth
// cycles, and the surface's plates' mean width around and height along (cm, the CSV's
// plate_mean_w and plate_mean_h: an uncracked surface is one strip of the whole patch) against
// the same cycles. Also the CSV's reading and the sample at a step.
// Does not: compute anything the run did not sample, or talk to the worker.

const SVG = 'http://www.w3.org/2000/svg';
const W = 280, H = 150, PAD = { l: 36, r: 16, t: 8, b: 26 };

// [{cycle, step, strain_theta, strain_z, broken_axial, broken_diagonal, plates, plate_mean_w,
// plate_mean_h, ...}] of the CSV text; the 4-layer model's S columns (broken_S_axial,
// broken_S_diagonal) are also its broken_axial and broken_diagonal.
export function parseCyclesCsv(text) {
  const lines = String(text || '').trim().split('\n');
  if (lines.length < 2) return [];
  const keys = lines[0].split(',');
  return lines.slice(1).map((line) => {
    const values = line.split(',').map(Number);
    const row = Object.fromEntries(keys.map((k, i) => [k, values[i]]));
    if ('broken_S_axial' in row) {
      row.broken_axial = row.broken_S_axial;
      row.broken_diagonal = row.broken_S_diagonal;
    }
    return row;
  });
}

// The last sample at or before `step` (Infinity: the last one).
export function sampleAt(samples, step) {
  let found = null;
  for (const s of samples) {
    if (s.step <= step) found = s;
    else break;
  }
  return found;
}

function el(name, attrs, text) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

// Draws the chart into `container` (replacing it): x the step in cycles (the settling after the
// last cycle drawn past it), y the broken share 0..max; springs {axial, diagonal}; `step` the
// marker (Infinity: the end).
export function drawBrokenChart(container, samples, springs, stepsPerCycle, step) {
  if (!container || samples.length === 0) return;
  const lastStep = samples[samples.length - 1].step;
  const xMax = Math.max(lastStep / stepsPerCycle, 1e-9);
  const share = (s, k) => s[`broken_${k}`] / Math.max(1, springs[k]);
  let yMax = 0;
  for (const s of samples) yMax = Math.max(yMax, share(s, 'axial'), share(s, 'diagonal'));
  yMax = yMax > 0 ? Math.ceil(yMax * 20) / 20 : 0.05;
  const x = (c) => PAD.l + ((W - PAD.l - PAD.r) * c) / xMax;
  const y = (v) => H - PAD.b - ((H - PAD.t - PAD.b) * v) / yMax;
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, width: '100%', role: 'img', 'aria-label': 'Broken share of the axial and diagonal springs against growth cycles' });
  svg.append(el('rect', { x: PAD.l, y: PAD.t, width: W - PAD.l - PAD.r, height: H - PAD.t - PAD.b, fill: '#fbfaf7', stroke: '#c9c3b8' }));
  for (const v of [0, yMax / 2, yMax]) {
    svg.append(el('text', { x: PAD.l - 4, y: y(v) + 3, 'text-anchor': 'end', 'font-size': 9, fill: '#555' }, `${Number((v * 100).toFixed(1))}%`));
  }
  for (const c of [0, xMax / 2, xMax]) {
    svg.append(el('text', { x: x(c), y: H - PAD.b + 12, 'text-anchor': 'middle', 'font-size': 9, fill: '#555' }, c.toFixed(2)));
  }
  svg.append(el('text', { x: (PAD.l + W - PAD.r) / 2, y: H - 3, 'text-anchor': 'middle', 'font-size': 9, fill: '#333' }, 'cycles (growth, then settling)'));
  const colours = { axial: '#2d6fb5', diagonal: '#b5532d' };
  for (const k of ['axial', 'diagonal']) {
    const d = samples.map((s, i) => `${i ? 'L' : 'M'}${x(s.step / stepsPerCycle).toFixed(1)},${y(share(s, k)).toFixed(1)}`).join(' ');
    svg.append(el('path', { d, fill: 'none', stroke: colours[k], 'stroke-width': 1.6 }));
  }
  svg.append(el('text', { x: PAD.l + 6, y: PAD.t + 12, 'font-size': 9, fill: colours.diagonal }, 'diagonal (vertical cracks)'));
  svg.append(el('text', { x: PAD.l + 6, y: PAD.t + 23, 'font-size': 9, fill: colours.axial }, 'axial (horizontal cracks)'));
  const at = Number.isFinite(step) ? step : lastStep;
  svg.append(el('line', { x1: x(at / stepsPerCycle), x2: x(at / stepsPerCycle), y1: PAD.t, y2: H - PAD.b, stroke: '#333', 'stroke-dasharray': '3 2' }));
  container.replaceChildren(svg);
}

// Draws the plate-size chart into `container` (replacing it): x the step in cycles as the broken
// chart's, y the mean plate width and height (cm, 0..the largest sampled, at most the patch's
// height), with the plate count of the step shown in the corner; `step` the marker.
export function drawPlateChart(container, samples, stepsPerCycle, step) {
  if (!container || samples.length === 0 || !('plate_mean_w' in samples[0])) return;
  const lastStep = samples[samples.length - 1].step;
  const xMax = Math.max(lastStep / stepsPerCycle, 1e-9);
  let yMax = 0;
  for (const s of samples) yMax = Math.max(yMax, s.plate_mean_w, s.plate_mean_h);
  yMax = yMax > 0 ? Math.ceil(yMax) : 1;
  const x = (c) => PAD.l + ((W - PAD.l - PAD.r) * c) / xMax;
  const y = (v) => H - PAD.b - ((H - PAD.t - PAD.b) * v) / yMax;
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, width: '100%', role: 'img', 'aria-label': 'Mean plate width and height against growth cycles' });
  svg.append(el('rect', { x: PAD.l, y: PAD.t, width: W - PAD.l - PAD.r, height: H - PAD.t - PAD.b, fill: '#fbfaf7', stroke: '#c9c3b8' }));
  for (const v of [0, yMax / 2, yMax]) {
    svg.append(el('text', { x: PAD.l - 4, y: y(v) + 3, 'text-anchor': 'end', 'font-size': 9, fill: '#555' }, `${Number(v.toFixed(1))} cm`));
  }
  for (const c of [0, xMax / 2, xMax]) {
    svg.append(el('text', { x: x(c), y: H - PAD.b + 12, 'text-anchor': 'middle', 'font-size': 9, fill: '#555' }, c.toFixed(2)));
  }
  svg.append(el('text', { x: (PAD.l + W - PAD.r) / 2, y: H - 3, 'text-anchor': 'middle', 'font-size': 9, fill: '#333' }, 'cycles (growth, then settling)'));
  const colours = { plate_mean_h: '#3d7a3a', plate_mean_w: '#8a4fb0' };
  for (const k of ['plate_mean_h', 'plate_mean_w']) {
    const d = samples.map((s, i) => `${i ? 'L' : 'M'}${x(s.step / stepsPerCycle).toFixed(1)},${y(s[k]).toFixed(1)}`).join(' ');
    svg.append(el('path', { d, fill: 'none', stroke: colours[k], 'stroke-width': 1.6 }));
  }
  svg.append(el('text', { x: W - PAD.r - 6, y: PAD.t + 12, 'text-anchor': 'end', 'font-size': 9, fill: colours.plate_mean_h }, 'mean height along'));
  svg.append(el('text', { x: W - PAD.r - 6, y: PAD.t + 23, 'text-anchor': 'end', 'font-size': 9, fill: colours.plate_mean_w }, 'mean width around'));
  const at = Number.isFinite(step) ? step : lastStep;
  const shownSample = sampleAt(samples, at);
  if (shownSample) {
    svg.append(el('text', { x: W - PAD.r - 6, y: PAD.t + 34, 'text-anchor': 'end', 'font-size': 9, fill: '#333' }, `${shownSample.plates} plates`));
  }
  svg.append(el('line', { x1: x(at / stepsPerCycle), x2: x(at / stepsPerCycle), y1: PAD.t, y2: H - PAD.b, stroke: '#333', 'stroke-dasharray': '3 2' }));
  container.replaceChildren(svg);
}
