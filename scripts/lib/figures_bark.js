#!/usr/bin/env node
// Regenerates the bark paper's results (Hirota, Kato, Kaneko, paper 003: Table 3 with Fig. 5's
// tiles, Figs 6-8 of the 4-layer model; spec ../shared/specs/bark.md §4.1-4.5) through the CLI
// (build/native/bin/niwa, or $NIWA) into docs/figures/bark_* and docs/figures/bark_measures.json
// (the numbers docs/FIGURES.md quotes), and prints each check with its bar and whether it holds.
// Every run is deterministic. Does not: tune anything toward the paper's numbers, or run the
// spec's sensitivity sweep (§4.6) or note *3 (§4.3).
// Usage: scripts/figures bark [table3 fig5 fig7 fig8] (default all); BARK_SEEDS=1-2 for fewer.
'use strict';
const fs = require('fs');
const path = require('path');
const { root, start, run, esc } = require('./figures_common');

const outDir = path.join(root, 'docs/figures');
const tmpDir = start('bark-figures');
const seeds = process.env.BARK_SEEDS || '1-5';
const wanted = process.argv.slice(2);
const want = (k) => !wanted.length || wanted.includes(k);
const r2 = (v) => Math.round(v * 100) / 100;
const pm = (s) => `${r2(s.mean)} ± ${r2(s.sd)}`;
const measuresPath = path.join(outDir, 'bark_measures.json');
const measures = fs.existsSync(measuresPath) ? JSON.parse(fs.readFileSync(measuresPath, 'utf8')) : {};
const verdicts = [];
function check(what, ok, detail) {
  verdicts.push({ what, ok, detail });
  console.log(`${ok ? 'yes' : 'NO '} ${what}: ${detail}`);
}

// ------------------------------------------------------------------ Table 3 (2-layer, E1)
function table3(level, extra) {
  const t = JSON.parse(run(['bark', 'table3', '--seeds', seeds, '--max-seconds', '3600', ...extra]));
  const by = Object.fromEntries(t.rows.map((r) => [r.species, r]));
  const o = (sp, k) => by[sp].ours[k].mean;
  const rows = t.rows.map((r) => ({
    species: r.species, paper: r.paper,
    ours: { mean: [pm(r.ours.mean_w), pm(r.ours.mean_h)], max: [pm(r.ours.max_w), pm(r.ours.max_h)],
      vertical_crack_share: pm(r.ours.vertical_crack_share), closed_fraction: pm(r.ours.closed_fraction),
      strips: r.ours.strips },
  }));
  measures[`table3_${level}`] = { seeds, rows };
  console.log(`Table 3, level ${level} (seeds ${seeds}):`);
  for (const r of rows)
    console.log(`  ${r.species.padEnd(8)} paper ${r.paper.mean.join(' x ')} (max ${r.paper.max.join(' x ')})` +
      `  ours ${r.ours.mean.join(' x ')} (max ${r.ours.max.join(' x ')}), vertical ${r.ours.vertical_crack_share},` +
      ` closed ${r.ours.closed_fraction}`);
  if (level === 'A') {
    const w = (sp) => o(sp, 'mean_w'), h = (sp) => o(sp, 'mean_h');
    check('A: pine wider than tallow and camphor by 1.25x', w('pine') >= 1.25 * Math.max(w('tallow'), w('camphor')),
      `pine ${r2(w('pine'))}, tallow ${r2(w('tallow'))}, camphor ${r2(w('camphor'))} cm`);
    check('A: height camphor > pine > tallow', h('camphor') > h('pine') && h('pine') > h('tallow'),
      `${r2(h('camphor'))} > ${r2(h('pine'))} > ${r2(h('tallow'))} cm`);
    const ar = (sp) => h(sp) / w(sp);
    check('A: camphor height/width >= 1.3x tallow\'s', ar('camphor') >= 1.3 * ar('tallow'),
      `${r2(ar('camphor') / ar('tallow'))}x (paper 4.1x)`);
    const v = (sp) => o(sp, 'vertical_crack_share');
    check('A: camphor vertical-crack share >= 0.85 and the highest',
      v('camphor') >= 0.85 && v('camphor') >= v('tallow') && v('camphor') >= v('pine'),
      `camphor ${r2(v('camphor'))}, tallow ${r2(v('tallow'))}, pine ${r2(v('pine'))}`);
    check('A: tallow closed-area fraction > camphor\'s', o('tallow', 'closed_fraction') > o('camphor', 'closed_fraction'),
      `${r2(o('tallow', 'closed_fraction'))} vs ${r2(o('camphor', 'closed_fraction'))}`);
  } else {
    for (const r of t.rows) {
      const sp = r.species, p = r.paper;
      const within = (ours, paper, tol) => typeof paper !== 'number' || Math.abs(ours / paper - 1) <= tol;
      const dev = (ours, paper) => typeof paper !== 'number' ? `(${paper})` : `${Math.round((ours / paper - 1) * 100)} %`;
      check(`B: ${sp} means within ±25 %`, within(o(sp, 'mean_w'), p.mean[0], 0.25) && within(o(sp, 'mean_h'), p.mean[1], 0.25),
        `width ${dev(o(sp, 'mean_w'), p.mean[0])}, height ${dev(o(sp, 'mean_h'), p.mean[1])}`);
      check(`B: ${sp} maxima within ±40 %`, within(o(sp, 'max_w'), p.max[0], 0.4) && within(o(sp, 'max_h'), p.max[1], 0.4),
        `width ${dev(o(sp, 'max_w'), p.max[0])}, height ${dev(o(sp, 'max_h'), p.max[1])}`);
    }
    check('B: camphor max height ">H" (a plate wraps along the trunk)', by.camphor.ours.strips > 0,
      `${by.camphor.ours.strips} strips over the seeds`);
  }
}

// ------------------------------------------------------------------ Fig. 5's tiles (E2)
function fig5() {
  for (const sp of ['camphor', 'tallow', 'pine']) {
    const out = path.join(outDir, `bark_fig5_${sp}.png`);
    run(['bark', 'grow', '--species', sp, '--seed', '1', '--set', 'map_size=512', '--out', out]);
    console.log(`  ${path.relative(root, out)}`);
  }
}

// ------------------------------------------------------------------ Fig. 7 (E4)
function fig7() {
  const csv = path.join(tmpDir, 'fig7.csv');
  const j = JSON.parse(run(['bark', 'layers', '--cycles', '3', '--csv', csv]));
  const lines = fs.readFileSync(csv, 'utf8').trim().split('\n');
  const head = lines[0].split(','), rows = lines.slice(1).map((l) => l.split(',').map(Number));
  const col = (k) => head.indexOf(k);
  const W = 560, H = 320, x0 = 50, y0 = 20, pw = 480, ph = 250;
  const tMax = Math.max(...rows.map((r) => r[col('t')]));
  const rMin = j.R_o - 0.1, rMax = j.surface_end + 0.1;
  const X = (t) => x0 + pw * t / tMax, Y = (r) => y0 + ph * (1 - (r - rMin) / (rMax - rMin));
  const series = [['r_I', '#7a3b1c', 'inner layer r_I'], ['M2_out', '#c9a66b', 'M2 outer'],
    ['M1_out', '#a0522d', 'M1 outer'], ['S_out', '#5b5048', 'S outer (surface)']];
  const parts = [`<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" font-family="sans-serif" font-size="11">`,
    `<rect width="${W}" height="${H}" fill="#fff"/>`,
    `<text x="${x0}" y="14">${esc('Fig. 7: layer radii (cm) over 3 cycles of the 4-layer model (niwa bark layers)')}</text>`];
  series.forEach(([k, colour, label], n) => {
    const pts = rows.map((r) => `${X(r[col('t')]).toFixed(1)},${Y(r[col(k)]).toFixed(1)}`).join(' ');
    parts.push(`<polyline fill="none" stroke="${colour}" stroke-width="2" points="${pts}"/>`);
    parts.push(`<text x="${x0 + 8}" y="${y0 + 14 + 13 * n}" fill="${colour}">${esc(label)}</text>`);
  });
  for (let c = 0; c <= 3; ++c)
    parts.push(`<text x="${X(c * tMax / 3) - 8}" y="${y0 + ph + 16}">${r2(c * tMax / 3)} s</text>`);
  parts.push(`<text x="4" y="${Y(rMax) + 4}">${r2(rMax)}</text><text x="4" y="${Y(rMin)}">${r2(rMin)}</text></svg>`);
  fs.writeFileSync(path.join(outDir, 'bark_fig7.svg'), parts.join('\n') + '\n');
  // The checks of spec §4.4: the outer surface r_I + D·τ + 2D, and no jump at the exchanges.
  let worst = 0;
  for (const r of rows) worst = Math.max(worst, Math.abs(r[col('S_out')] - (r[col('r_I')] + j.D * r[col('tau')] + 2 * j.D)));
  check('Fig 7: outer surface = r_I + D·tau + 2D', worst < 1e-9, `max deviation ${worst.toExponential(1)} cm`);
  check('Fig 7: a layer shed a cycle', j.layers_shed === j.cycles, `${j.layers_shed} shed over ${j.cycles} cycles`);
  measures.fig7 = { ...j, max_surface_deviation_cm: worst };
}

// ------------------------------------------------------------------ Figs 6 and 8 (E5)
function fig8() {
  const frames = path.join(tmpDir, 'frames');
  fs.mkdirSync(frames, { recursive: true });
  const csv = path.join(tmpDir, 'cycles.csv');
  const cycles = 6;
  const s = JSON.parse(run(['bark', 'grow', '--species', 'pine', '--model', '4layer', '--size', '128x32',
    '--cycles', String(cycles), '--seed', '1', '--set', 'map_size=256', '--csv', csv, '--frames', frames, '--stats',
    '--max-seconds', '3600']));
  for (const f of fs.readdirSync(frames).sort())
    fs.copyFileSync(path.join(frames, f), path.join(outDir, `bark_fig8_${f.replace('bark_', '')}`));
  const lines = fs.readFileSync(csv, 'utf8').trim().split('\n');
  const head = lines[0].split(','), rows = lines.slice(1).map((l) => l.split(',').map(Number));
  const col = (k) => head.indexOf(k);
  // Per cycle, the last row before its exchange: what peeled, what shows, what was shed so far.
  const perCycle = [];
  for (let c = 0; c < cycles; ++c) {
    // The CSV's cycle is t/T (fractional); a cycle's rows are those before its exchange.
    const rs = rows.filter((r) => r[col('exchanges')] === c && r[col('cycle')] <= c + 1);
    const last = rs[rs.length - 1];
    const first = rs[0];
    perCycle.push({ cycle: c + 1, peeled_fraction: Math.round(last[col('peeled_fraction')] * 1e4) / 1e4,
      bonds_broken_in_cycle: last[col('bonds_broken')] - first[col('bonds_broken')],
      exposed: { S: r2(last[col('exposed_S')]), M1: r2(last[col('exposed_M1')]), M2: r2(last[col('exposed_M2')]), I: r2(last[col('exposed_I')]) },
      broken_S: last[col('broken_S')], shed_regions_so_far: last[col('shed_regions')], shed_area_so_far: r2(last[col('shed_area')]) });
  }
  console.log('Fig. 8 (pine, 4-layer, 128x32, seed 1), per cycle before its exchange:');
  for (const p of perCycle) console.log(`  ${JSON.stringify(p)}`);
  const peel = s.peel;
  check('Fig 8: first peel after the first crack', peel.first_step > peel.first_crack_step,
    `first crack step ${peel.first_crack_step}, first peel step ${peel.first_step}`);
  const peeledEvery = perCycle.slice(1).every((p) => p.bonds_broken_in_cycle > 0);
  check('Fig 8: every cycle >= 2 peels (S->M1 bonds break)', peeledEvery,
    perCycle.map((p) => p.bonds_broken_in_cycle).join(', ') + ' bonds a cycle');
  const shedGrows = perCycle.slice(2).every((p, k) => p.shed_area_so_far > perCycle[k + 1].shed_area_so_far);
  check('Fig 8: every exchange from the 2nd on sheds bark', shedGrows, perCycle.map((p) => p.shed_area_so_far).join(', ') + ' cm²');
  const m1Shows = perCycle.some((p) => p.exposed.M1 > 0);
  check('Fig 6/8: the intermediate layer shows where S peeled', m1Shows, perCycle.map((p) => p.exposed.M1).join(', '));
  measures.fig8 = { species: 'pine', size: '128x32', cycles, seed: 1, per_cycle: perCycle,
    peel, shed: s.shed, exchanges: s.exchanges };
}

if (want('table3')) { table3('B', []); table3('A', ['--set', 'dH=0.03']); }
if (want('fig5')) fig5();
if (want('fig7')) fig7();
if (want('fig8')) fig8();
measures.verdicts = { ...(measures.verdicts || {}), ...Object.fromEntries(verdicts.map((v) => [v.what, { holds: v.ok, measured: v.detail }])) };
fs.writeFileSync(measuresPath, JSON.stringify(measures, null, 1) + '\n');
fs.rmSync(tmpDir, { recursive: true, force: true });
console.log(`${verdicts.filter((v) => v.ok).length} of ${verdicts.length} checks hold; ${path.relative(root, measuresPath)}`);
