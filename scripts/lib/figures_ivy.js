#!/usr/bin/env node
// Regenerates paper 004's Fig. 3 (Shindo & Sakamoto: the ivy on four 400 px cubes at steps 10-50,
// and the last step with leaves) and measures the claims of its §4 through the CLI
// (build/native/bin/niwa, from `scripts/build native`, or $NIWA) into docs/figures/ivy/: fig3_steps.svg,
// fig3_leaves.svg, problems.svg (the paper's two problems in `paper` and `improved`), scenes.svg
// (convex and concave supports), tree.svg (ivy on Niwa's sakura), dormancy.svg/.md (§2.2's second
// trigger on cubes4 with the search of §3.2 alone), look_*.png/look.md (paper beside artist, drawn
// by three.js: figures_ivy_look.mjs), luft_*.png/luft.md (artist beside a Luft-style reference,
// tests/ivy/luft_reference_test.cpp) and claims.md (the numbers, seeds 1-5). docs/FIGURES.md shows them. Deterministic. Usage: scripts/figures ivy [NAME...]
// e.g. `scripts/figures ivy claims` to redo only the numbers.
'use strict';
const fs = require('fs');
const path = require('path');
const { root, start, run, esc } = require('./figures_common');

const outDir = path.join(root, 'docs/figures/ivy');
const tmpDir = start('ivy-figures');

fs.mkdirSync(outDir, { recursive: true });

const PANEL = 480;  // the CLI's .svg: two square views of 480 px (front x-y, side z-y)

function growArgs(p) {
  const args = ['ivy', 'grow'];
  if (p.tree) args.push('--tree-preset', p.tree, '--tree-years', String(p.treeYears || 10));
  else args.push('--scene', p.scene || 'cubes4');
  args.push('--preset', p.preset || 'paper', '--seed', String(p.seed ?? 1), '--steps', String(p.steps ?? 50));
  for (const s of p.seedPoints || []) args.push('--seed-point', s);
  for (const s of p.set || []) args.push('--set', s);
  return args;
}

function stats(p) {
  return JSON.parse(run([...growArgs(p), '--stats']));
}

// One CLI drawing (both views) and its stats.
function panel(p) {
  const file = path.join(tmpDir, 'panel.svg');
  const st = JSON.parse(run([...growArgs(p), '--out', file, '--stats', '--svg-leaves', p.leaves === false ? '0' : '1']));
  return { svg: fs.readFileSync(file, 'utf8'), stats: st };
}

// The markup of one view of a CLI drawing (0 front, 1 side: its <g id="front"> or <g id="side">
// group, without the <svg> element, the white background or the caption).
function inner(svg, view) {
  const body = svg.replace(/^<svg[^>]*>\n/, '').replace(/<\/svg>\n?$/, '').replace(/<rect width="100%"[^>]*\/>\n/, '');
  const at = body.indexOf('<g id="side">');
  const end = body.lastIndexOf('<text x="8" y="');  // the caption, if any, follows the side group
  return view === 0 ? body.slice(0, at) : body.slice(at, end > at && !body.slice(end).includes('<g') ? end : undefined);
}

// Writes a figure: cells of `views` (0 front, 1 side) of the panels, side by side, labelled.
function figure(name, title, cells, cols = cells.length) {
  const rows = Math.ceil(cells.length / cols);
  const top = 30, label = 36;
  const w = cols * PANEL, h = top + rows * (PANEL + label);
  let out = `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}">\n`;
  out += '<rect width="100%" height="100%" fill="#fff"/>\n';
  out += `<text x="8" y="20" font-family="sans-serif" font-size="15" font-weight="bold">${esc(title)}</text>\n`;
  cells.forEach((c, i) => {
    const x = (i % cols) * PANEL, y = top + Math.floor(i / cols) * (PANEL + label);
    // The CLI draws the front view at x 0..480 and the side view at 480..960.
    out += `<svg x="${x}" y="${y}" width="${PANEL}" height="${PANEL}" viewBox="${c.view * PANEL} 0 ${PANEL} ${PANEL}">\n`;
    out += inner(c.svg, c.view) + '</svg>\n';
    c.label.forEach((line, k) => {
      out += `<text x="${x + 8}" y="${y + PANEL + 14 + 15 * k}" font-family="sans-serif" font-size="12">${esc(line)}</text>\n`;
    });
  });
  out += '</svg>\n';
  const file = path.join(outDir, `${name}.svg`);
  fs.writeFileSync(file, out);
  console.log(`wrote ${path.relative(root, file)}`);
}

const fmt = (x, d = 2) => (Number.isFinite(x) ? String(Number(x.toFixed(d))) : String(x));
// rho is null when no lateral had a window with parent growth (the main apex died first).
const rhoText = (s) => (s.rho === null ? '—' : `${fmt(s.rho, 2)} (${s.rho_laterals})`);

const FIGURES = {
  // Fig. 3: steps 10, 20, 30, 40, 50 (front views, no leaves), as the paper's "step ごとの推移".
  fig3_steps() {
    const cells = [10, 20, 30, 40, 50].map((steps) => {
      const { svg, stats: s } = panel({ steps, leaves: false });
      console.log(`  step ${steps}: ${s.internodes} internodes, ${s.laterals} laterals, buds A ${s.buds.A} D ${s.buds.D} Z ${s.buds.Z}`);
      return { svg, view: 0, label: [`step ${steps}`, `${s.internodes} internodes, ${s.laterals} laterals`] };
    });
    figure('fig3_steps', 'Fig. 3 (paper 004): cubes4, preset paper, seed 1, steps 10-50 (front view)', cells, 5);
  },
  // Fig. 3's last panel: step 50 with leaves, front and side.
  fig3_leaves() {
    const { svg, stats: s } = panel({ steps: 50 });
    const line = `step 50 with leaves: ${s.leaves} leaves, ${s.internodes} internodes`;
    figure('fig3_leaves', 'Fig. 3, last step with leaves (cubes4, paper, seed 1)', [
      { svg, view: 0, label: ['front (x-y)', line] }, { svg, view: 1, label: ['side (z-y)', ''] }]);
  },
  // §4's two problems: extreme bends and overlapping branches, in paper and in improved.
  problems() {
    const cells = [];
    for (const preset of ['paper', 'improved']) {
      for (const seed of [1, 3]) {
        const { svg, stats: s } = panel({ preset, seed, leaves: false });
        console.log(`  ${preset} seed ${seed}: bend_max ${fmt(s.bend_max, 1)}°, overlap_pairs ${s.overlap_pairs}`);
        cells.push({ svg, view: 0, label: [`${preset}, seed ${seed}`, `bend_max ${fmt(s.bend_max, 1)}°, overlap_pairs ${s.overlap_pairs}, ${s.internodes} internodes`] });
      }
    }
    figure('problems', '§4 problems: extreme bends and overlapping branches (paper) against improved (max_bend 60°, avoid 10 px)', cells, 4);
  },
  // Convex and concave supports: every built-in scene but free.
  scenes() {
    const cells = ['wall', 'overhang', 'stairs', 'pillar', 'sphere'].map((scene) => {
      const { svg, stats: s } = panel({ scene, leaves: true });
      console.log(`  ${scene}: within d ${s.frac_nodes_within_d}, hits ${s.internode_hits}, convex ${s.convex_crossings}, concave ${s.concave_crossings}`);
      return { svg, view: scene === 'stairs' ? 1 : 0, label: [`${scene}${scene === 'stairs' ? ' (side)' : ''}`,
        `within d ${fmt(s.frac_nodes_within_d, 3)}, hits ${s.internode_hits}, convex ${s.convex_crossings}, concave ${s.concave_crossings}`] };
    });
    figure('scenes', 'The other built-in scenes (preset paper, seed 1, 50 steps)', cells, 5);
  },
  // Ivy on a Niwa tree (metric preset, --tree-preset sakura --tree-years 10).
  tree() {
    const cells = [];
    for (const steps of [50, 150]) {
      const { svg, stats: s } = panel({ tree: 'sakura', treeYears: 10, preset: 'metric', steps });
      console.log(`  sakura, ${steps} steps: ${s.internodes} internodes, rise ${fmt(s.rise)} m, tri_count ${s.tri_count}`);
      cells.push({ svg, view: 0, label: [`sakura 10 years, ${steps} steps`, `${s.internodes} internodes, rise ${fmt(s.rise)} m, within d ${fmt(s.frac_nodes_within_d, 3)}, hits ${s.internode_hits}`] });
    }
    figure('tree', 'Ivy on Niwa\'s sakura (metric preset: L = 5 cm, d = 2 cm)', cells, 2);
  },
  // §2.2's second trigger on the paper's own scene (issue 31 item 6): cubes4, paper, 50 steps, with
  // the search the paper describes (E6-E10 alone: --set tangent_retry=0, R_max 3, n_c 16, φ 30°,
  // Δφ 15°) beside the default search with the tangent fan. An apex whose search fails ends (p3)
  // and wakes the nearest dormant bud below it (released break), which grows a lateral after its
  // parent's apex died (a reiteration).
  dormancy() {
    const cells = [];
    const rows = [];
    for (const [seed, where] of [[1, 'side'], [3, 'side'], [5, 'side']]) {
      for (const fan of [1, 0]) {
        const p = { seed, seedPoints: [where], set: [`tangent_retry=${fan}`], leaves: false };
        const { svg, stats: s } = panel(p);
        rows.push({ seed, where, fan, s });
        console.log(`  seed ${seed} ${where} tangent_retry=${fan}: p3 A ${s.p3.A}, released ${s.released_breaks}, reiterations ${s.reiterations}`);
        cells.push({ svg, view: 0, label: [`seed ${seed}, ${where}, tangent_retry=${fan}${fan ? ' (default)' : ' (E6-E10 alone)'}`,
          `p3 on apices ${s.p3.A}, released breaks ${s.released_breaks}, reiterations ${s.reiterations}, ${s.internodes} internodes`] });
      }
    }
    figure('dormancy', '§2.2 second trigger on cubes4 (paper, 50 steps): the search of §3.2 alone (tangent_retry=0: R_max 3, n_c 16, φ 30°, Δφ 15°) against the default with the tangent fan', cells, 6);
    let md = '| seed | seed point | tangent_retry | p3 on apices | released breaks | reiterations | internodes | rejected (gravitropism / far / near / collision) |\n|---|---|---|---|---|---|---|---|\n';
    for (const { seed, where, fan, s } of rows) {
      const r = s.search.rejected;
      md += `| ${seed} | ${where} | ${fan} | ${s.p3.A} | ${s.released_breaks} | ${s.reiterations} | ${s.internodes} | ${r.gravitropism} / ${r.far} / ${r.near} / ${r.collision} |\n`;
    }
    fs.writeFileSync(path.join(outDir, 'dormancy.md'), md);
    console.log(md);
  },
  // The look (issue 31 item 5): paper beside artist on the bunny and the overhang facade, drawn by
  // three.js in Chromium (scripts/lib/figures_ivy_look.mjs; needs the browser tests' Chromium).
  look() {
    require('child_process').execFileSync(process.execPath, [path.join(__dirname, 'figures_ivy_look.mjs')], { stdio: 'inherit' });
  },
  // The artist preset against a Luft-style reference (issue 31 item 5): tests/ivy/luft_reference_test.cpp
  // run from build/native (scripts/build native) draws both front views and prints the leaf covers.
  luft() {
    const bin = path.join(root, 'build/native/bin/ivy_tests');
    const out = require('child_process').execFileSync(bin, ['--gtest_filter=IvyLuftReference.*'], {
      encoding: 'utf8', env: { ...process.env, NIWA_LUFT_FIGURES: outDir },
    });
    const lines = out.split('\n').filter((l) => l.startsWith('[ luft'));
    if (!/\[  PASSED  \] 1 test/.test(out)) throw new Error(`figures ivy luft: the test failed\n${out}`);
    let md = 'Printed by `build/native/bin/ivy_tests --gtest_filter=IvyLuftReference.*` (`scripts/figures ivy luft`):\n\n';
    md += lines.map((l) => `    ${l}`).join('\n') + '\n';
    fs.writeFileSync(path.join(outDir, 'luft.md'), md);
    console.log(md);
  },
  // §4's claims as numbers, seeds 1-5, cubes4, 50 steps.
  claims() {
    const rows = [];
    for (const preset of ['paper', 'literal', 'improved']) {
      for (let seed = 1; seed <= 5; ++seed) {
        const s = stats({ preset, seed });
        rows.push({ preset, seed, s });
      }
    }
    let md = '| preset | seed | within d | hits | convex / concave | up_min | first break | laterals at 20 → 30 | rho (laterals compared) | bend_max | overlap pairs |\n';
    md += '|---|---|---|---|---|---|---|---|---|---|---|\n';
    for (const { preset, seed, s } of rows) {
      md += `| ${preset} | ${seed} | ${fmt(s.frac_nodes_within_d, 3)} | ${s.internode_hits} | ${s.convex_crossings} / ${s.concave_crossings} | ${fmt(s.up_min, 3)} | ${s.first_break_step} | ${s.laterals_at['20']} → ${s.laterals_at['30']} | ${rhoText(s)} | ${fmt(s.bend_max, 1)}° | ${s.overlap_pairs} |\n`;
    }
    // C4 over more seeds (cheap: 50 steps each): rho for both seed points of cubes4, per preset.
    md += '\nC4 over seeds 1-20 (`rho`: the laterals\' p0 internodes over their parent\'s in the steps both apices were alive; — when the main apex died before any lateral had such a window):\n\n';
    md += '| preset | seed point | rho defined | rho < 1 | rho min / median / max | laterals compared | reiterations |\n|---|---|---|---|---|---|---|\n';
    for (const preset of ['paper', 'literal', 'improved']) {
      for (const where of ['side', 'column']) {
        const all = [];
        for (let seed = 1; seed <= 20; ++seed) all.push(stats({ preset, seed, seedPoints: [where] }));
        const rhos = all.filter((s) => s.rho !== null).map((s) => s.rho).sort((a, b) => a - b);
        const sum = (k) => all.reduce((t, s) => t + s[k], 0);
        const mid = rhos.length ? rhos[Math.floor((rhos.length - 1) / 2)] : null;
        md += `| ${preset} | ${where} | ${rhos.length} / 20 | ${rhos.filter((r) => r < 1).length} / ${rhos.length} | ${rhos.length ? `${fmt(rhos[0], 2)} / ${fmt(mid, 2)} / ${fmt(rhos[rhos.length - 1], 2)}` : '—'} | ${sum('rho_laterals')} | ${sum('reiterations')} |\n`;
      }
    }
    const file = path.join(outDir, 'claims.md');
    fs.writeFileSync(file, md);
    console.log(md);
    console.log(`wrote ${path.relative(root, file)}`);
  },
};

const wanted = process.argv.slice(2);
for (const name of wanted) {
  if (!FIGURES[name]) {
    console.error(`figures ivy: '${name}' is unknown; must be one of ${Object.keys(FIGURES).join(', ')}`);
    process.exit(2);
  }
}
for (const [name, make] of Object.entries(FIGURES)) {
  if (wanted.length && !wanted.includes(name)) continue;
  console.log(`${name}:`);
  make();
}
fs.rmSync(tmpDir, { recursive: true, force: true });
