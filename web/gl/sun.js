// The one place the pages' light direction comes from: core/light's convention (y up, +x east,
// +z south, azimuth from +x towards +z, in degrees) and each page's default sun. The worker's
// module (web/bindings/light_bindings.cpp: sunDirection, sunAt) gives core's own numbers;
// tests/cli/sun.test.mjs checks this file's against them.
// Does not: draw, know a study's parameters (the tree's sun rows set its sun through setSun).

// Default suns, {elevation, azimuth} in degrees: the tree's is its sun rows' defaults
// (sun_elevation 60, sun_azimuth 0 in core/tree/tree_params.cpp); the ivy page's a high sun from
// the east-south-east; the terrain page's a low sun from the north-west, for relief shading.
export const DEFAULT_SUNS = Object.freeze({
  tree: Object.freeze({ elevation: 60, azimuth: 0 }),
  ivy: Object.freeze({ elevation: 50, azimuth: 30 }),
  terrain: Object.freeze({ elevation: 35, azimuth: 225 }),
});

// Unit direction towards the sun at elevation and azimuth in degrees (core's light::SunDirection
// in double precision: within 1e-6 of its floats), or null for non-numbers.
export function sunDirection(elevationDeg, azimuthDeg) {
  const el = (Number(elevationDeg) * Math.PI) / 180, az = (Number(azimuthDeg) * Math.PI) / 180;
  if (!Number.isFinite(el) || !Number.isFinite(az)) return null;
  const v = [Math.cos(el) * Math.cos(az), Math.sin(el), Math.cos(el) * Math.sin(az)];
  const l = Math.hypot(v[0], v[1], v[2]);
  return v.map((x) => x / l);
}

// The direction of a page's default sun ('tree', 'ivy' or 'terrain').
export function defaultSunDirection(page) {
  const sun = DEFAULT_SUNS[page];
  return sun ? sunDirection(sun.elevation, sun.azimuth) : null;
}
