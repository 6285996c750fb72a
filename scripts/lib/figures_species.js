#!/usr/bin/env node
// Niwa's tree species beside ez-tree's presets, drawn by three.js in Chromium
// (scripts/lib/figures_species.mjs): `scripts/figures species`. Needs the browser tests' Chromium
// and node_modules (three, @dgreenheck/ez-tree).
'use strict';
const path = require('path');
require('child_process').execFileSync(process.execPath, [path.join(__dirname, 'figures_species.mjs')], { stdio: 'inherit' });
