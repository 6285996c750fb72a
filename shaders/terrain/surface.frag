#version 300 es
// Hillshade of the terrain surface: Lambert from a low sun (north-west, as maps shade) over a
// sky/ground ambient, times the hypsometric tint (uTint 1) or a plain stone grey (uTint 0).
precision highp float;

in vec3 vNormal;
in vec3 vColour;

uniform vec3 uLightDirection;  // unit, towards the sun
uniform float uTint;

out vec4 outColor;

void main() {
  vec3 n = normalize(vNormal);
  vec3 base = mix(vec3(0.72, 0.71, 0.68), vColour, uTint);
  float diffuse = max(dot(n, uLightDirection), 0.0);
  float ambient = 0.28 + 0.12 * n.y;
  outColor = vec4(base * (ambient + 0.85 * diffuse), 1.0);
}
