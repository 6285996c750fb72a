// One lane's shared browser for scripts/test: node tests/browser/lane_browser.mjs FILE starts Debian
// chromium as a Playwright browser server (harness.mjs CHROMIUM_OPTIONS), writes its WebSocket
// endpoint to FILE, and keeps it until it is sent SIGTERM or SIGINT (harness.mjs launchChromium says
// why the tests share it). Not a test: scripts/test runs the *.test.mjs files.
import fs from 'node:fs';
import { chromium } from 'playwright-core';
import { CHROMIUM_OPTIONS } from './harness.mjs';

const file = process.argv[2];
if (!file) {
  console.error('usage: node tests/browser/lane_browser.mjs ENDPOINT_FILE');
  process.exit(2);
}
const server = await chromium.launchServer(CHROMIUM_OPTIONS);
fs.writeFileSync(`${file}.partial`, server.wsEndpoint());
fs.renameSync(`${file}.partial`, file);
const stop = async () => {
  await server.close().catch(() => {});
  process.exit(0);
};
process.on('SIGTERM', stop);
process.on('SIGINT', stop);
