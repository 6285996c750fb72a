#!/usr/bin/env node
// Regenerates the side views and plots of thesis section 2.5 (figs. 2.10-2.23) and the sway examples
// of section 3.5 (table 3.1, figs. 3.13-3.17) through the CLI (build/native/bin/niwa, from
// `scripts/build native`, or $NIWA) into docs/figures/figN_NN.svg; docs/FIGURES.md shows them.
// Deterministic except fig. 2.21 (run times of this machine). Usage: scripts/figures [tree] [FIG...]
// e.g. `scripts/figures 2.16 2.17` to redo only those.
'use strict';
const fs = require('fs');
const path = require('path');
const { root, start, run, esc } = require('./figures_common');

const outDir = path.join(root, 'docs/figures');
const tmpDir = start('figures');


// ---------------------------------------------------------------------------------------------
// Running the CLI

function niwaArgs(p) {
  const args = ['tree', 'grow', '--preset', p.preset];
  if (p.years !== undefined) args.push('--years', String(p.years));
  if (p.seed !== undefined) args.push('--seed', String(p.seed));
  const sets = Object.entries(p.set || {}).map(([k, v]) => `${k}=${v}`);
  if (sets.length) args.push('--set', ...sets);
  if (p.prune && p.prune.length) args.push('--prune', ...p.prune);
  return args;
}

function stats(p) {
  return JSON.parse(run([...niwaArgs(p), '--stats']));
}

function treeJson(p) {
  const file = path.join(tmpDir, 'tree.json');
  run([...niwaArgs(p), '--out', file]);
  return JSON.parse(fs.readFileSync(file, 'utf8'));
}

// ---------------------------------------------------------------------------------------------
// Panels: one CLI side view each, nested side by side in one SVG per figure

const W = 420, H = 460, GROUND = H - 20;  // panel size; the CLI draws the ground at H - 20

const r1 = (v) => String(Math.round(v * 10) / 10);

// Keeps the points of a polyline that are at least 2 px from the last kept one (and the last).
function thin(xy) {
  const kept = [xy[0]];
  for (let i = 1; i < xy.length; ++i) {
    const [lx, ly] = kept[kept.length - 1];
    const far = Math.hypot(xy[i][0] - lx, xy[i][1] - ly) >= 2;
    if (far) kept.push(xy[i]);
    else if (i === xy.length - 1) kept[kept.length === 1 ? 1 : kept.length - 1] = xy[i];
  }
  return kept;
}

const pt = ([x, y]) => `${r1(x)},${r1(y)}`;

// Grows one panel through the CLI (--out panel.svg --stats): its SVG, scale (px per cm) and stats.
function growPanel(p) {
  const file = path.join(tmpDir, 'panel.svg');
  const args = [...niwaArgs(p), '--out', file, '--stats', '--svg-width', String(W),
    '--svg-height', String(H), '--svg-leaves', p.leaves === false ? '0' : '1',
    '--svg-flowers', p.flowers === false ? '0' : '1'];
  if (p.label) args.push('--caption', p.label);
  const st = JSON.parse(run(args));
  const svg = fs.readFileSync(file, 'utf8');
  // The CLI fits the tree: its top is at GROUND - height * scale.
  let top = GROUND;
  for (const m of svg.matchAll(/points="([^"]*)"/g)) {
    for (const q of m[1].trim().split(/\s+/)) top = Math.min(top, Number(q.split(',')[1]));
  }
  const scale = st.height > 0 && top < GROUND ? (GROUND - top) / st.height : 1;
  return { svg, scale, stats: st, p };
}

// Re-draws a panel's SVG scaled by f about the foot of the tree (W/2, GROUND), with rounded
// coordinates: branches become one path per stroke width, leaves one path, flowers stay circles.
function scalePanel(svg, f) {
  const X = (x) => W / 2 + (Number(x) - W / 2) * f, Y = (y) => GROUND + (Number(y) - GROUND) * f;
  const widths = new Map();
  for (const m of svg.matchAll(/<polyline stroke-width="([0-9.]+)" points="([^"]*)"\/>/g)) {
    const w = Math.max(0.4, Number(m[1]) * f).toFixed(1);
    const xy = thin(m[2].trim().split(/\s+/).map((q) => q.split(',')).map(([x, y]) => [X(x), Y(y)]));
    if (!widths.has(w)) widths.set(w, []);
    widths.get(w).push('M' + xy.map(pt).join(' '));
  }
  let out = '<g fill="none" stroke="#4a3520" stroke-linecap="round" stroke-linejoin="round">\n';
  for (const w of [...widths.keys()].sort((a, b) => b - a)) {
    out += `<path stroke-width="${w}" d="${widths.get(w).join('')}"/>\n`;
  }
  out += '</g>\n';
  const leaves = [...svg.matchAll(/<line x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)"\/>/g)]
    .map((m) => `M${pt([X(m[1]), Y(m[2])])} ${pt([X(m[3]), Y(m[4])])}`);
  if (leaves.length) {
    out += `<path fill="none" stroke="#3f8f3a" stroke-width="1" stroke-opacity="0.7" ` +
      `d="${leaves.join('')}"/>\n`;
  }
  const flowers = [...svg.matchAll(/<circle cx="([-0-9.]+)" cy="([-0-9.]+)" r="[0-9.]+"\/>/g)];
  if (flowers.length) {
    out += '<g fill="#f4a6c0" stroke="#d0708f" stroke-width="0.5">' + flowers.map((m) =>
      `<circle cx="${r1(X(m[1]))}" cy="${r1(Y(m[2]))}" r="2"/>`).join('') + '</g>\n';
  }
  const ground = (svg.match(/<line x1="0"[^>]*stroke="#aaa"\/>/) || [''])[0];
  const caption = (svg.match(/<text[\s\S]*?<\/text>/) || [''])[0];
  return `${ground}\n${out}${caption}\n`;
}

function niceLength(cm) {
  const steps = [1, 2, 5];
  let best = 1;
  for (let e = -1; e < 5; ++e) {
    for (const s of steps) {
      const v = s * 10 ** e;
      if (v <= cm) best = v;
    }
  }
  return best;
}

// Writes one figure: panels side by side; with common scale (default) every panel has the same px/cm.
function figure(name, title, panels, options = {}) {
  const grown = panels.map(growPanel);
  const common = Math.min(...grown.map((g) => g.scale));
  const cols = options.cols || grown.length;
  const rows = Math.ceil(grown.length / cols);
  const top = 28;
  const width = cols * W, height = top + rows * H;
  let out = `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" ` +
    `viewBox="0 0 ${width} ${height}">\n<rect width="100%" height="100%" fill="white"/>\n` +
    `<text x="10" y="19" font-family="sans-serif" font-size="16" font-weight="bold">` +
    `${esc(title)}</text>\n`;
  grown.forEach((g, i) => {
    const s = options.ownScale ? g.scale : common;
    const f = s / g.scale;
    const x = (i % cols) * W, y = top + Math.floor(i / cols) * H;
    out += `<svg x="${x}" y="${y}" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}">\n`;
    out += scalePanel(g.svg, f);
    const bar = niceLength((W * 0.25) / s);
    const bx = W - 12 - bar * s;
    out += `<g font-family="sans-serif" font-size="11" fill="#555"><line x1="${r1(bx)}" ` +
      `y1="${GROUND + 8}" x2="${W - 12}" y2="${GROUND + 8}" stroke="#555" stroke-width="2"/>` +
      `<text x="${r1(bx)}" y="${GROUND + 19}">${bar} cm</text></g>\n</svg>\n`;
  });
  out += '</svg>\n';
  writeFigure(name, out);
  for (const g of grown) {
    const st = g.stats;
    console.log(`  ${g.p.label || ''}: height ${st.height.toFixed(1)} cm, ${st.internodes} ` +
      `internodes, ${st.branches} branches, ${st.leaves} leaves, ${st.flowers} flowers`);
  }
  return grown;
}

function writeFigure(name, svg) {
  const file = path.join(outDir, `${name}.svg`);
  fs.writeFileSync(file, svg);
  console.log(`wrote ${path.relative(root, file)} (${Math.round(svg.length / 1024)} KB)`);
}

// ---------------------------------------------------------------------------------------------
// Line plots (figs. 2.20, 2.21)

function linePlot(title, xLabel, yLabel, series, options = {}) {
  const w = options.width || 560, h = options.height || 400;
  const left = 64, right = 130, topM = 36, bottom = 48;
  const xs = series.flatMap((s) => s.points.map((p) => p[0]));
  const ys = series.flatMap((s) => s.points.map((p) => p[1]));
  const xMax = options.xMax ?? Math.max(...xs), xMin = options.xMin ?? Math.min(...xs);
  const yMax = niceCeil(Math.max(...ys));
  const px = (x) => left + ((x - xMin) / (xMax - xMin)) * (w - left - right);
  const py = (y) => h - bottom - (y / yMax) * (h - topM - bottom);
  let out = `<g font-family="sans-serif" font-size="12">\n` +
    `<text x="10" y="20" font-size="14" font-weight="bold">${esc(title)}</text>\n` +
    `<line x1="${left}" y1="${py(0)}" x2="${w - right}" y2="${py(0)}" stroke="#000"/>\n` +
    `<line x1="${left}" y1="${py(0)}" x2="${left}" y2="${topM}" stroke="#000"/>\n`;
  for (const x of options.xTicks || []) {
    out += `<line x1="${r1(px(x))}" y1="${py(0)}" x2="${r1(px(x))}" y2="${py(0) + 4}" ` +
      `stroke="#000"/><text x="${r1(px(x))}" y="${py(0) + 17}" text-anchor="middle">${x}</text>\n`;
  }
  for (let k = 0; k <= 5; ++k) {
    const y = (yMax * k) / 5;
    out += `<line x1="${left - 4}" y1="${r1(py(y))}" x2="${w - right}" y2="${r1(py(y))}" ` +
      `stroke="${k ? '#ddd' : '#000'}"/><text x="${left - 7}" y="${r1(py(y) + 4)}" ` +
      `text-anchor="end">${+y.toPrecision(3)}</text>\n`;
  }
  out += `<text x="${(left + w - right) / 2}" y="${h - 10}" text-anchor="middle">${esc(xLabel)}</text>\n` +
    `<text transform="translate(16,${(topM + h - bottom) / 2}) rotate(-90)" text-anchor="middle">` +
    `${esc(yLabel)}</text>\n`;
  series.forEach((s, i) => {
    const pts = s.points.map(([x, y]) => `${r1(px(x))},${r1(py(y))}`).join(' ');
    out += `<polyline fill="none" stroke="${s.color}" stroke-width="2" points="${pts}"/>\n`;
    for (const [x, y] of s.points) {
      out += `<circle cx="${r1(px(x))}" cy="${r1(py(y))}" r="2.5" fill="${s.color}"/>`;
    }
    const ly = topM + 10 + i * 20;
    out += `\n<line x1="${w - right + 12}" y1="${ly}" x2="${w - right + 36}" y2="${ly}" ` +
      `stroke="${s.color}" stroke-width="2"/><text x="${w - right + 42}" y="${ly + 4}">` +
      `${esc(s.name)}</text>\n`;
  });
  return { svg: out + '</g>\n', width: w, height: h };
}

function niceCeil(v) {
  if (v <= 0) return 1;
  const e = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) if (m * e >= v) return m * e;
  return 10 * e;
}

function plotsFigure(name, plots) {
  const width = plots.reduce((a, p) => a + p.width, 0), height = Math.max(...plots.map((p) => p.height));
  let out = `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" ` +
    `viewBox="0 0 ${width} ${height}">\n<rect width="100%" height="100%" fill="white"/>\n`;
  let x = 0;
  for (const p of plots) {
    out += `<svg x="${x}" y="0" width="${p.width}" height="${p.height}">\n${p.svg}</svg>\n`;
    x += p.width;
  }
  writeFigure(name, out + '</svg>\n');
}

// ---------------------------------------------------------------------------------------------
// Sway (thesis 3.5): the tree at rest (side view, wind from the left) next to the CLI's plot of the
// traced tips' displacement along the wind against time (`niwa tree sway ... --svg`).

function swayFigure(name, title, p, sway) {
  const panel = growPanel({ ...p, label: p.label || '' });
  const plotFile = path.join(tmpDir, 'sway.svg');
  const sets = Object.entries(sway.set || {}).map(([k, v]) => `${k}=${v}`);
  const args = ['tree', 'sway', ...niwaArgs(p).slice(2), '--wind', String(sway.wind),
    '--gust', sway.gust, '--duration', String(sway.duration), '--tips', String(sway.tips || 3),
    '--svg', plotFile, '--stats'];
  if (sets.length) args.push('--set', ...sets);
  const st = JSON.parse(run(args));
  const plot = fs.readFileSync(plotFile, 'utf8').replace(/^<svg[^>]*>\n/, '').replace(/<\/svg>\n$/, '');
  const top = 28, PW = 800, PH = 400;
  const width = W + PW, height = top + Math.max(H, PH);
  let out = `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" ` +
    `viewBox="0 0 ${width} ${height}">\n<rect width="100%" height="100%" fill="white"/>\n` +
    `<text x="10" y="19" font-family="sans-serif" font-size="16" font-weight="bold">` +
    `${esc(title)}</text>\n`;
  out += `<svg x="0" y="${top}" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}">\n` +
    scalePanel(panel.svg, 1);
  const bar = niceLength((W * 0.25) / panel.scale);
  const bx = W - 12 - bar * panel.scale;
  out += `<g font-family="sans-serif" font-size="11" fill="#555"><line x1="${r1(bx)}" ` +
    `y1="${GROUND + 8}" x2="${W - 12}" y2="${GROUND + 8}" stroke="#555" stroke-width="2"/>` +
    `<text x="${r1(bx)}" y="${GROUND + 19}">${bar} cm</text><text x="12" y="20">` +
    `wind →</text></g>\n</svg>\n`;
  out += `<svg x="${W}" y="${top}" width="${PW}" height="${PH}" viewBox="0 0 ${PW} ${PH}">\n${plot}</svg>\n`;
  writeFigure(name, out + '</svg>\n');
  console.log(`  ${p.preset} ${p.years} years: ${st.internodes} internodes, ${st.node_points} node ` +
    `points (${st.moving} moving, ${st.followers} following, ${st.fixed} fixed), wind ${st.wind} m/s, ` +
    `largest tip displacement ${st.max_tip_displacement.toFixed(1)} cm, ${st.ns_per_internode.toFixed(1)} ` +
    `ns/internode/step`);
  return st;
}

// Table 3.1. Examples 2-4 share the spreading tree (sakura) and examples 2-3 have no leaf mass or area.
const oneBranch = { N_low: 5, N_high: 5, D_low: 10, D_high: 10, use_light: 0, pipe_area: 0.16 };
// Eq. 3.16's own bound (omit_limit 3) in every example; Niwa's default is 1 (docs/sway-model.md).
const ex1 = { K_dir_trunk: 50000, K_dir_tip: 50000, K_rev: 0, K_vdel: 0.9, m_leaf: 0, s_leaf: 0,
  omit_limit: 3 };
const ex24 = { K_dir_trunk: 150000, K_dir_tip: 50000, K_rev: 0.8, K_vdel: 1, omit_limit: 3 };
const bare = { m_leaf: 0, s_leaf: 0 };
const ex5 = { K_dir_trunk: 700000, K_dir_tip: 90000, K_rev: 0.7, K_vdel: 1, m_leaf: 5, s_leaf: 20,
  omit_limit: 3 };
const spreading = { preset: 'sakura-thesis', years: 5 };
const upright = { preset: 'keyaki-thesis', years: 6 };

// ---------------------------------------------------------------------------------------------
// The figures of thesis section 2.5

const noBend = { b_L_low: 0, b_L_high: 0, b_g_low: 0, b_g_high: 0 };
// 2.5.1: the branching model alone: no light, no hormone, no bending.
const branchingOnly = { use_light: 0, use_hormone: 0, ...noBend };
// 2.5.3 (figs. 2.16, 2.17): light on, apical dominance and dwarf shoots (D_s/D_l 0.5); the sun low on
// the -x side (left in the side view).
const lightOn = { use_light: 1, D_s_ratio: 0.5, sun_azimuth: 180, sun_elevation: 20, sun_weight: 0.8 };

const FIGURES = {
  '3.13': () => swayFigure('fig3_13', 'Fig. 3.13 / example 1: one branch, 5 m/s (table 3.1)',
    { preset: 'binary', years: 1, set: oneBranch, label: 'one shoot, 5 internodes' },
    { wind: 5, gust: '0.5:4', duration: 8, set: ex1, tips: 1 }),
  '3.14': () => swayFigure('fig3_14', 'Fig. 3.14 / example 2: spreading tree, no leaves, 5 m/s',
    { ...spreading, leaves: false, label: 'sakura, 5 years' }, { wind: 5, gust: '0.5:5', duration: 10, set: { ...ex24, ...bare } }),
  '3.15': () => swayFigure('fig3_15', 'Fig. 3.15 / example 3: spreading tree, no leaves, 20 m/s',
    { ...spreading, leaves: false, label: 'sakura, 5 years' }, { wind: 20, gust: '0.5:5', duration: 10, set: { ...ex24, ...bare } }),
  '3.16': () => swayFigure('fig3_16', 'Fig. 3.16 / example 4: spreading tree with leaves (3 g, 30 cm²), 5 m/s',
    { ...spreading, label: 'sakura, 5 years' }, { wind: 5, gust: '0.5:5', duration: 10, set: ex24 }),
  '3.17': () => swayFigure('fig3_17', 'Fig. 3.17 / example 5: upright tree with leaves (5 g, 20 cm²), 10 m/s',
    { ...upright, label: 'keyaki, 6 years' }, { wind: 10, gust: '0.5:5', duration: 10, set: ex5 }),
  '2.10': () => {
    const shoots = { ...branchingOnly, N_low: 4, N_high: 4, D_low: 2, D_high: 2, B_l: 1, psi_t: 0,
      psi_l: 45 };
    figure('fig2_10', 'Fig. 2.10: branching patterns (branching model alone: no light, no hormone, ' +
      'no bending; own scales)', [
      { preset: 'binary', years: 8, set: branchingOnly, label: '(a) binary, 8 years' },
      { preset: 'binary', years: 6, set: { ...shoots, phi: 0.4, B_tl: 0, P_l_young: 0.5,
        P_l_old: 0.5 }, label: '(b) monopodial, 2/5' },
      { preset: 'binary', years: 6, set: { ...shoots, phi: 0.5, B_tl: 0, P_l_young: 0.5,
        P_l_old: 0.5, sympodial: 1, theta_N: 15 }, label: '(c) sympodial, 1/2, θ_N 15°' },
      { preset: 'binary', years: 5, set: { ...shoots, phi: 1 / 3, B_tl: 3, P_l_young: 0,
        P_l_old: 0 }, label: '(d) monopodial 1/3, B_tl 3, P_l 0' },
    ], { ownScale: true });
  },
  '2.11': () => figure('fig2_11', 'Fig. 2.11: apical dominance, P_tl^s varied (binary, no light)',
    [0.1, 0.3, 0.6].map((v, i) => ({ preset: 'binary', set: { ...noBend, P_tl_s: v },
      label: `(${'abc'[i]}) P_tl^s = ${v}` }))),
  '2.12': () => figure('fig2_12', 'Fig. 2.12: apical dominance, α_tl varied (binary, no light)',
    [0.3, 0.4, 0.5].map((v, i) => ({ preset: 'binary', set: { ...noBend, alpha_tl: v },
      label: `(${'abc'[i]}) α_tl = ${v}` }))),
  '2.13': () => figure('fig2_13',
    'Fig. 2.13: apical dominance and dwarf shoots, D_s/D_l varied (binary, no light)',
    [0.4, 0.5].flatMap((a, j) => [1, 0.5, 0.25].map((d, i) => ({ preset: 'binary',
      set: { ...noBend, alpha_tl: a, D_s_ratio: d },
      label: `(${'abcdef'[3 * j + i]}) α_tl ${a}, D_s/D_l ${d}` }))), { cols: 3 }),
  '2.14': () => {
    const base = { ...noBend, D_s_ratio: 0.5 };
    figure('fig2_14', 'Fig. 2.14: dormancy break (binary, dwarf shoots D_s/D_l 0.5, no light)', [
      { preset: 'binary', set: { ...base, H_b_l: 0, h_b_d: 0 }, label: '(a) no dormancy break' },
      { preset: 'binary', set: { ...base, H_b_l: 0 }, label: '(b) sudden drop only' },
      { preset: 'binary', set: { ...base, h_b_d: 0 }, label: '(c) threshold only' },
      { preset: 'binary', set: base, label: '(d) both' },
    ]);
  },
  '2.15': () => figure('fig2_15',
    'Fig. 2.15: dormancy break after pruning (binary; at year 10 every shoot since year 7 cut)',
    [10, 12, 14, 16].map((y, i) => ({ preset: 'binary', years: y, set: { ...noBend, D_s_ratio: 0.5 },
      prune: ['10:since7'], label: `(${'abcd'[i]}) year ${y}` }))),
  '2.16': () => {
    const base = { ...lightOn, b_g_low: 0, b_g_high: 0 };
    figure('fig2_16', 'Fig. 2.16: phototropism (binary + light, D_s/D_l 0.5, no geotropism; ' +
      'sun low on the LEFT)', [
      { preset: 'binary', set: { ...base, b_L_low: 0, b_L_high: 0 }, label: '(a) no bending' },
      { preset: 'binary', set: { ...base, b_L_low: 0.3, b_L_high: 0.3 },
        label: '(b) constant b_L 0.3' },
      { preset: 'binary', set: { ...base, b_L_by_light: 1 }, label: '(c) b_L by light L' },
      { preset: 'binary', set: base, label: '(d) b_L by hormone' },
    ]);
  },
  '2.17': () => figure('fig2_17', 'Fig. 2.17: phototropism and geotropism (binary + light, ' +
    'D_s/D_l 0.5; sun low on the LEFT)', [
    { preset: 'binary', set: { ...lightOn, ...noBend }, label: '(a) no bending' },
    { preset: 'binary', set: { ...lightOn, b_g_low: 0, b_g_high: 0 }, label: '(b) phototropism only' },
    { preset: 'binary', set: { ...lightOn, b_L_low: 0, b_L_high: 0 }, label: '(c) geotropism only' },
    { preset: 'binary', set: lightOn, label: '(d) both' },
  ]),
  '2.18': () => {
    // Light on under the growth model's own sky (no low sun): 2.18 is about regrowth, and a sun low
    // on one side made the whole tree lean 30-40°, so the cut tree's regrowth was read against
    // phototropism. tests/tree/fig218_test.cpp checks this setup over seeds 1-5.
    const base = { use_light: 1, D_s_ratio: 0.25, N_low: 2, N_high: 2, B_l: 1, psi_l: 45, P_l_young: 0,
      P_l_old: 0 };
    const p10 = { preset: 'binary', years: 10, set: base };
    const trunk = trunkToCut(treeJson(p10), 3);
    figure('fig2_18', `Fig. 2.18: trunk regeneration (binary + light, D_s/D_l 0.25, 2 internodes ` +
      `per shoot, middle buds dormant; main axis cut at its year-3 shoot b${trunk})`, [
      { ...p10, label: '(a) year 10' },
      { ...p10, prune: [`10:b${trunk}`], label: `(b) year 10, trunk cut (b${trunk})` },
      { ...p10, years: 15, label: '(c) year 15, uncut' },
      { ...p10, years: 15, prune: [`10:b${trunk}`], label: '(d) year 15, cut at 10' },
    ]);
    for (let seed = 1; seed <= 5; ++seed) regrowthReport({ ...p10, seed });
  },
  '2.19': () => figure('fig2_19', 'Fig. 2.19: the three species at 15 years (own scales)', [
    { preset: 'sakura-thesis', years: 15, leaves: false, label: '(a) sakura (no leaves drawn)' },
    { preset: 'keyaki-thesis', years: 15, label: '(b) keyaki' },
    { preset: 'tsutsuji-thesis', years: 15, label: '(c) tsutsuji' },
  ], { ownScale: true }).forEach((g) => shootReport(g.p)),
  '2.20': () => {
    const rows = growthRows();
    plotsFigure('fig2_20', [linePlot('Fig. 2.20: tree height', 'year', 'height (cm)',
      rows.map((r) => ({ name: r.preset, color: r.color, points: r.years.map((y) => [y.year, y.height]) })),
      { xMin: 0, xTicks: [0, 3, 6, 9, 12, 15] })]);
  },
  '2.21': () => {
    const rows = growthRows(true);
    plotsFigure('fig2_21', [
      linePlot('Fig. 2.21 (a): growth time vs year', 'year', 'time (ms, best of 5)',
        rows.map((r) => ({ name: r.preset, color: r.color, points: r.years.map((y) => [y.year, y.ms]) })),
        { xMin: 0, xTicks: [0, 3, 6, 9, 12, 15] }),
      linePlot('(b) growth time vs internodes', 'internodes', 'time (ms, best of 5)',
        rows.map((r) => ({ name: r.preset, color: r.color,
          points: r.years.map((y) => [y.internodes, y.ms]) })),
        { xMin: 0, xTicks: xTicksFor(rows), xMax: xTicksFor(rows)[5] }),
    ]);
  },
  '2.22': () => figure('fig2_22', 'Fig. 2.22: sakura growing (years 3 to 15, one scale; leaves not drawn)',
    [3, 6, 9, 12, 15].map((y, i) => ({ preset: 'sakura-thesis', years: y, leaves: false,
      label: `(${'abcde'[i]}) year ${y}` }))),
  mappings: () => {
    // Hormone- and age-dependent ranges of table 2.2 as the model computes them (docs/growth-model.md).
    const mappings = (preset, sets = []) => {
      const args = ['tree', 'mappings', '--preset', preset];
      if (sets.length) args.push('--set', ...sets);
      const [hormoneBlock, ageBlock] = run(args).trim().split('\n\n');
      const table = (block) => {
        const [head, ...rows] = block.trim().split('\n');
        const keys = head.split(',');
        return rows.map((r) => Object.fromEntries(r.split(',').map((v, i) => [keys[i], Number(v)])));
      };
      const h = table(hormoneBlock);
      const series = (key, name, color) => ({ name, color, points: h.map((r) => [r.hormone, r[key]]) });
      return { h, age: table(ageBlock), series };
    };
    const ticks = [0, 0.25, 0.5, 0.75, 1, 1.25, 1.5];
    const longDwarf = (m, key, title, unit) => linePlot(title, 'initial hormone H0', unit,
      [m.series(`${key}_long${unit === 'cm' ? '_cm' : ''}`, 'long shoot', '#8a5a2b'),
        m.series(`${key}_dwarf${unit === 'cm' ? '_cm' : ''}`, 'dwarf shoot', '#c9a36b')],
      { xMin: 0, xTicks: ticks, width: 420 });
    const sakura = mappings('sakura-thesis');
    plotsFigure('mappings_sakura', [
      longDwarf(sakura, 'N', 'N vs hormone (sakura)', 'nodes'),
      longDwarf(sakura, 'D', 'D vs hormone', 'cm'),
      linePlot('bending rates', 'hormone H', 'rate',
        [sakura.series('b_L', 'b_L', '#e0a000'), sakura.series('b_g', 'b_g', '#3060c0')],
        { xMin: 0, xTicks: ticks, width: 420 }),
      linePlot('break chances (fig. 2.8)', 'hormone H', 'probability',
        [sakura.series('P_terminal', 'terminal', '#333'), sakura.series('P_tl', 'term.-lateral', '#c04040'),
          sakura.series('P_lateral_at_age_P_l_years', 'lateral', '#40a040')], { xMin: 0, xTicks: ticks, width: 420 }),
      linePlot('P_l vs tree age (fig. 2.9)', 'year', 'P_l', [{ name: 'P_l', color: '#40a040',
        points: sakura.age.map((r) => [r.year, r.P_l_max]) }], { xMin: 1, xTicks: [1, 5, 10, 15], width: 420 }),
    ]);
    // Fig. 2.5's shape: keyaki's D as the preset has it (length_step 0) and with length_step 0.5.
    const keyaki = mappings('keyaki-thesis'), stepped = mappings('keyaki-thesis', ['length_step=0.5']);
    plotsFigure('mappings_keyaki_length_step', [
      longDwarf(keyaki, 'D', 'keyaki D, length_step 0 (preset)', 'cm'),
      longDwarf(stepped, 'D', 'keyaki D, length_step 0.5', 'cm'),
      longDwarf(stepped, 'N', 'keyaki N, length_step 0.5', 'nodes'),
    ]);
  },
  '2.23': () => figure('fig2_23', 'Fig. 2.23: keyaki, same conditions, seeds 1 to 4 (15 years)',
    [1, 2, 3, 4].map((s, i) => ({ preset: 'keyaki-thesis', years: 15, seed: s,
      label: `(${'abcd'[i]}) seed ${s}` }))).forEach((g) => shootReport(g.p)),
};

// True when shoot b broke by dormancy break: two or more years after its parent grew (a bud breaks
// normally the year after). byId maps branch ids of b's tree to branches.
const brokeDormant = (byId, b) => b.parent >= 0 && b.year - byId.get(b.parent).year >= 2;

// Fig. 2.18's regrowth on one seed, as FIGURES.md quotes it: height gained in years 10-15 with the
// main axis cut at its year-3 shoot and without, the share of the top fifth's nodes that grow on a
// dormancy-break lineage (a shoot that broke two or more years after its parent grew, or a
// descendant), and the share of the years 11-15 shoots in lineages that broke after year 10.
function regrowthReport(p10) {
  const trunk = trunkToCut(treeJson(p10), 3);
  const cut = (years) => ({ ...p10, years, prune: [`10:b${trunk}`] });
  const measure = (tree) => {
    const byId = new Map(tree.branches.map((b) => [b.id, b]));
    const broke = (b) => brokeDormant(byId, b);
    const lineage = (b) => { const out = []; for (let x = b; x; x = byId.get(x.parent)) out.push(x); return out; };
    const height = Math.max(...tree.branches.flatMap((b) => b.nodes.map((n) => n[1])));
    let top = 0, topOnBreak = 0, late = 0, lateOnLateBreak = 0;
    for (const b of tree.branches) {
      const line = lineage(b);
      const onBreak = line.some(broke), onLateBreak = line.some((x) => broke(x) && x.year > 10);
      const high = b.nodes.filter((n) => n[1] >= 0.8 * height).length;
      top += high;
      if (onBreak) topOnBreak += high;
      if (b.year > 10) { ++late; if (onLateBreak) ++lateOnLateBreak; }
    }
    return { height, top: topOnBreak / top, late: late ? lateOnLateBreak / late : 0 };
  };
  const pct = (v) => `${Math.round(100 * v)} %`;
  const at10 = measure(treeJson(p10)), cut10 = measure(treeJson(cut(10)));
  const cut15 = measure(treeJson(cut(15))), uncut15 = measure(treeJson({ ...p10, years: 15 }));
  console.log(`  seed ${p10.seed} (cut b${trunk}): cut ${r1(cut10.height)} -> ${r1(cut15.height)} cm ` +
    `(+${r1(cut15.height - cut10.height)}), uncut ${r1(at10.height)} -> ${r1(uncut15.height)} cm ` +
    `(+${r1(uncut15.height - at10.height)}); top fifth on dormancy-break lineages: cut ${pct(cut15.top)}, ` +
    `uncut ${pct(uncut15.top)}; years 11-15 shoots in lineages broken after year 10: cut ` +
    `${pct(cut15.late)}, uncut ${pct(uncut15.late)}`);
}

// Shoot statistics of one tree, as FIGURES.md quotes them for figs. 2.19 and 2.23 (lengths in cm
// along the nodes; a shoot that broke two or more years after its parent grew came from dormancy
// break; the trunk line is the seedling and its chain of terminal shoots).
function shootReport(p) {
  const tree = treeJson(p);
  const byId = new Map(tree.branches.map((b) => [b.id, b]));
  const length = (b) => b.nodes.slice(1).reduce((sum, n, i) => sum + Math.hypot(
    n[0] - b.nodes[i][0], n[1] - b.nodes[i][1], n[2] - b.nodes[i][2]), 0);
  const median = (v) => { const s = [...v].sort((a, b) => a - b); return s.length ? s[s.length >> 1] : 0; };
  const shoots = tree.branches.filter((b) => b.parent >= 0);
  const long = shoots.filter((b) => !b.dwarf).map(length);
  const dwarf = shoots.filter((b) => b.dwarf).map(length);
  const terminals = shoots.filter((b) => b.kind === 'terminal' && !byId.get(b.parent).dwarf);
  const laterals = shoots.filter((b) => b.kind === 'lateral');
  const broken = shoots.filter((b) => brokeDormant(byId, b));
  let trunk = tree.branches[0], trunkLong = 0;
  while (trunk && !trunk.dwarf) {
    ++trunkLong;
    trunk = tree.branches.find((b) => b.parent === trunk.id && b.kind === 'terminal');
  }
  const ys = tree.branches.flatMap((b) => b.nodes.map((n) => n[1]));
  const xs = tree.branches.flatMap((b) => b.nodes.map((n) => n[0]));
  const zs = tree.branches.flatMap((b) => b.nodes.map((n) => n[2]));
  const height = Math.max(...ys);
  const width = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...zs) - Math.min(...zs));
  const leafYs = tree.branches.flatMap((b) => b.leaves.map((l) => b.nodes[l.node][1]));
  const f1 = (v) => v.toFixed(1), f2 = (v) => v.toFixed(2);
  console.log(`  ${p.label || p.preset}: ${shoots.length + 1} shoots; long ${long.length} (median ` +
    `${f1(median(long))}, max ${f1(Math.max(0, ...long))} cm); dwarf ${dwarf.length} (median ` +
    `${f2(median(dwarf))}, max ${f2(Math.max(0, ...dwarf))} cm, ` +
    `${Math.round((100 * dwarf.filter((l) => l < 1).length) / Math.max(1, dwarf.length))} % under 1 cm)`);
  const terminalLong = terminals.filter((b) => !b.dwarf).map(length);
  console.log(`    terminal shoots of long shoots ${terminals.length}, dwarf ${terminals.filter((b) => b.dwarf).length} ` +
    `(the long ones: median ${f1(median(terminalLong))}, max ${f1(Math.max(0, ...terminalLong))} cm); ` +
    `lateral shoots ${laterals.length}, dwarf ${laterals.filter((b) => b.dwarf).length}; from dormancy break ` +
    `${broken.length} (parents' median radius ${f2(median(broken.map((b) => byId.get(b.parent).radius)))} cm, ` +
    `all shoots' ${f2(median(shoots.map((b) => b.radius)))} cm); trunk line long for its first ${trunkLong} years; ` +
    `width/height ${f2(width / height)}; lowest leaf at ${f2(Math.min(...leafYs) / height)} of the height`);
}

// The main-axis shoot of `year`: follow terminal shoots up from the seedling.
function trunkToCut(tree, year) {
  let id = 0;
  for (;;) {
    const next = tree.branches.find((b) => b.parent === id && b.kind === 'terminal');
    if (!next || next.year > year) return id;
    id = next.id;
    if (next.year === year) return id;
  }
}

const SPECIES = [['sakura-thesis', '#d0407a'], ['keyaki-thesis', '#2a7a2a'], ['tsutsuji-thesis', '#c08000']];
let growthCache = null;
function growthRows(timed = false) {
  if (!growthCache || (timed && !growthCache.timed)) {
    growthCache = SPECIES.map(([preset, color]) => ({ preset, color, years: [] }));
    growthCache.timed = timed;
    for (const row of growthCache) {
      for (let year = 1; year <= 15; ++year) {
        let best = null;
        for (let k = 0; k < (timed ? 5 : 1); ++k) {
          const st = stats({ preset: row.preset, years: year });
          if (!best || st.ms < best.ms) best = st;
        }
        row.years.push({ year, height: best.height, ms: best.ms, internodes: best.internodes });
      }
      console.log(`  ${row.preset}: height ` + row.years.map((y) => y.height.toFixed(0)).join(' ') +
        (timed ? `; ms ` + row.years.map((y) => y.ms.toFixed(1)).join(' ') : ''));
    }
  }
  return growthCache;
}

function xTicksFor(rows) {
  const max = niceCeil(Math.max(...rows.flatMap((r) => r.years.map((y) => y.internodes))));
  return [0, 1, 2, 3, 4, 5].map((k) => Math.round((max * k) / 5));
}

// ---------------------------------------------------------------------------------------------

const wanted = process.argv.slice(2);
for (const w of wanted) {
  if (!FIGURES[w]) {
    console.error(`figures: unknown figure '${w}', must be one of ${Object.keys(FIGURES).join(', ')}`);
    process.exit(2);
  }
}
fs.mkdirSync(outDir, { recursive: true });
try {
  for (const [name, make] of Object.entries(FIGURES)) {
    if (wanted.length && !wanted.includes(name)) continue;
    make();
  }
} finally {
  fs.rmSync(tmpDir, { recursive: true, force: true });
}
const total = fs.readdirSync(outDir).reduce((a, f) => a + fs.statSync(path.join(outDir, f)).size, 0);
console.log(`docs/figures: ${(total / 1048576).toFixed(2)} MB`);
