// Shared parts of the browser tests: paths, PASS/FAIL counting, the native CLI, waiting for a tree, Chromium.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const NATIVE = process.env.NIWA_NATIVE || path.join(ROOT, 'build/native/bin/niwa');
export const ARTIFACTS = path.join(ROOT, 'build/artifacts');
export const TIMEOUT = 180_000;  // SwiftShader and a first WASM compile are slow
fs.mkdirSync(ARTIFACTS, { recursive: true });

const counts = { passed: 0, failed: 0 };
export function check(name, ok, detail = '') {
  if (ok) ++counts.passed; else ++counts.failed;
  console.log(`${ok ? 'PASS' : 'FAIL'} ${name}${detail ? ` — ${detail}` : ''}`);
}

// Prints the closing "N passed, N failed" line and exits 0 only when nothing failed.
export function finish() {
  console.log(`${counts.passed} passed, ${counts.failed} failed`);
  process.exit(counts.failed === 0 ? 0 : 1);
}

// The native CLI's --stats for the same tree options.
export function nativeStats(args) {
  const out = execFileSync(NATIVE, ['tree', 'grow', ...args, '--stats'], { encoding: 'utf8' });
  return JSON.parse(out.trim().split('\n').pop());
}

// Waits until the page has drawn a tree newer than serialAbove (the page's data-tree-serial).
export async function waitReady(page, serialAbove, polling = 250) {
  await page.waitForFunction(
    (n) => document.documentElement.dataset.status === 'ready' && Number(document.documentElement.dataset.treeSerial) > n,
    serialAbove, { timeout: TIMEOUT, polling });
  await page.waitForTimeout(300);  // let the frame for the new tree be drawn
}

// Debian chromium with a real WebGL2 context on SwiftShader (see ../shared/TOOLCHAIN.md).
export function launchChromium() {
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-sandbox',
      '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update',
      '--disable-sync'],
  });
}
