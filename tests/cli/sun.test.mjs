// web/gl/sun.js (the pages' one light direction) against core/light through the web module
// (web/bindings/light_bindings.cpp): the same directions within float rounding for the page
// defaults and a grid of angles, and sunAt's known equinox noon. The module is built for a Web
// Worker; node stands in for one (self, location, importScripts) with the .wasm given as bytes.
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { check, finish, root } from '../support/cli_pair.mjs';
import { DEFAULT_SUNS, defaultSunDirection, sunDirection } from '../../web/gl/sun.js';
import { sunDirection as contextSunDirection } from '../../web/gl/context.js';

const web = join(root, 'build/wasm/web');
if (!existsSync(join(web, 'niwa_web.js'))) {
  console.log(`FAIL web module missing at ${web}: build niwa_web in the wasm-release preset first`);
  process.exit(1);
}
globalThis.self = globalThis;
globalThis.location = { href: pathToFileURL(web + '/').href };
globalThis.importScripts = () => {};
const { default: createNiwaModule } = await import(pathToFileURL(join(web, 'niwa_web.js')).href);
const core = await createNiwaModule({ wasmBinary: readFileSync(join(web, 'niwa_web.wasm')) });

const far = (a, b) => Math.max(...a.map((x, i) => Math.abs(x - b[i])));
for (const [page, sun] of Object.entries(DEFAULT_SUNS)) {
  const js = defaultSunDirection(page), c = core.sunDirection(sun.elevation, sun.azimuth);
  check(`${page} default sun (${sun.elevation}°, ${sun.azimuth}°): sun.js ${js.map((x) => x.toFixed(6))} = core ${c.map((x) => x.toFixed(6))}`, far(js, c) < 1e-6);
}
let worst = 0;
for (let el = -10; el <= 90; el += 5) {
  for (let az = -180; az <= 360; az += 15) worst = Math.max(worst, far(sunDirection(el, az), core.sunDirection(el, az)));
}
check(`sun.js and core agree over a grid of 21 × 37 angles (largest difference ${worst.toExponential(2)})`, worst < 1e-6);
check('gl/context.js re-exports sun.js\'s sunDirection (one formula)', contextSunDirection === sunDirection);
check('non-numbers give null', sunDirection('x', 0) === null);
// core's solar position: the 2026 March equinox at local solar noon at 35° N, Greenwich: 55°, south.
const noon = core.sunAt(2026, 3, 20, 12 + 7.5 / 60, 35, 0);
check(`sunAt equinox noon at 35° N: altitude ${noon.altitude.toFixed(3)}°, azimuth ${noon.azimuth.toFixed(3)}° (55, 90)`, Math.abs(noon.altitude - 55) < 0.1 && Math.abs(noon.azimuth - 90) < 0.5);
check('sunAt\'s direction is sunDirection of its angles', far(noon.direction, sunDirection(noon.altitude, noon.azimuth)) < 1e-6);
finish();
