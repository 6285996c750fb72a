#version 300 es
// The tile's plates: a triangle whose first edge broke at or before the step shown (uStep) is
// dropped, so the crack shows the inner layer drawn beneath (spec §1.9); the rest in the surface's
// grey-brown (uMode 0, a little darker where stretched) or as a heat map of their stretch (uMode
// 1: blue relaxed, through orange, to pale yellow at the break strain). Outside the patch
// (a copy's overhang past the seam) nothing is drawn.
precision highp float;

in vec2 vPatch;
in float vStretch;
in float vBroken;

uniform vec2 uPatch;  // circumference, height (cm)
uniform float uStep;
uniform int uMode;

out vec4 outColor;

vec3 heat(float t) {
  vec3 a = vec3(0.10, 0.16, 0.42), b = vec3(0.88, 0.42, 0.12), c = vec3(1.0, 0.95, 0.62);
  return t < 0.5 ? mix(a, b, t * 2.0) : mix(b, c, t * 2.0 - 1.0);
}

void main() {
  if (vPatch.x < 0.0 || vPatch.y < 0.0 || vPatch.x >= uPatch.x || vPatch.y >= uPatch.y) discard;
  if (vBroken >= 0.0 && vBroken <= uStep) discard;
  float s = clamp(vStretch, 0.0, 1.0);
  vec3 plate = mix(vec3(0.50, 0.45, 0.38), vec3(0.36, 0.31, 0.26), s);
  outColor = vec4(uMode == 1 ? heat(s) : plate, 1.0);
}
