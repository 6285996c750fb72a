#version 300 es
// The moss study's land: Lambert from the page's sun over a sky/ground ambient, on its geology's
// reference colour (fig 3.1: humus #4A3322, sandy #C29A5B, asphalt #808080) tinted by the
// overlay: uOverlay 0 none, 1 coverage (towards moss green by sqrt(coverage), so a cell one moss
// covers a few per cent of still shows), 2 a field of the last day (irradiance S, T_s, rh_s,
// theta or best-species G: dark blue through orange to pale yellow over uRange), 3 none (the
// photon points are drawn over it).
precision highp float;

in vec3 vNormal;
in float vCoverage;
in float vValue;
in float vGeology;

uniform vec3 uLightDirection;  // unit, towards the sun
uniform int uOverlay;
uniform vec2 uRange;  // the field's value at the ramp's two ends

out vec4 outColor;

vec3 heat(float t) {
  vec3 a = vec3(0.10, 0.12, 0.35), b = vec3(0.85, 0.42, 0.12), c = vec3(1.0, 0.95, 0.65);
  return t < 0.5 ? mix(a, b, t * 2.0) : mix(b, c, t * 2.0 - 1.0);
}

void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  int g = int(vGeology + 0.5);
  vec3 base = g == 0 ? vec3(0.29, 0.20, 0.13) : g == 1 ? vec3(0.76, 0.60, 0.36) : vec3(0.50, 0.50, 0.50);
  if (uOverlay == 1) base = mix(base, vec3(0.20, 0.55, 0.12), sqrt(clamp(vCoverage, 0.0, 1.0)));
  if (uOverlay == 2) base = heat(clamp((vValue - uRange.x) / max(uRange.y - uRange.x, 1e-9), 0.0, 1.0));
  float diffuse = max(dot(n, uLightDirection), 0.0);
  float ambient = 0.35 + 0.12 * n.y;
  outColor = vec4(base * (ambient + 0.7 * diffuse), 1.0);
}
