// What every `scripts/figures <study>` script shares: the CLI it runs (build/native/bin/niwa, or
// $NIWA), a scratch folder, running it, and escaping text for SVG. Does not: draw any figure.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const { execFileSync } = require('child_process');

const root = path.resolve(__dirname, '..', '..');
const niwa = process.env.NIWA ? path.resolve(process.env.NIWA) : path.join(root, 'build/native/bin/niwa');

// Exits with one line when the CLI has not been built; returns a fresh scratch folder.
function start(name) {
  if (!fs.existsSync(niwa)) {
    console.error(`figures: ${path.relative(root, niwa)} is missing; run scripts/build native first`);
    process.exit(1);
  }
  return fs.mkdtempSync(path.join(os.tmpdir(), `niwa-${name}-`));
}

// The CLI's stdout for `args` (throws with its stderr on a non-zero exit).
const run = (args) => execFileSync(niwa, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
const esc = (s) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

module.exports = { root, niwa, start, run, esc };
