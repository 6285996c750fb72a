#version 300 es
// The tile's plates: a triangle whose first edge broke at or before the step shown (uStep) is
// dropped, so the crack shows the inner layer drawn beneath (spec §1.9); the rest in the surface's
// grey-brown (uMode 0, a little darker where stretched) or as a heat map of their stretch (uMode
// 1: blue relaxed, through orange, to pale yellow at the break strain). uMode 2 colours every
// triangle by the layer showing in it at the run's end (the maps' palette: S grey-brown, M1
// red-brown, M2 light tan, the inner layer dark), uMode 3 by its peel state (bonded: the plate
// colour, unbonded from M1 and peeling: orange, peeled off: the M1 red-brown beneath, pale); both
// drop nothing (the layer and the peel state are the end's, not replayed). Outside the patch (a
// copy's overhang past the seam) nothing is drawn.
precision highp float;

in vec2 vPatch;
in float vStretch;
in float vBroken;
in float vLayer;
in float vPeel;

uniform vec2 uPatch;  // circumference, height (cm)
uniform float uStep;
uniform int uMode;

out vec4 outColor;

vec3 heat(float t) {
  vec3 a = vec3(0.10, 0.16, 0.42), b = vec3(0.88, 0.42, 0.12), c = vec3(1.0, 0.95, 0.62);
  return t < 0.5 ? mix(a, b, t * 2.0) : mix(b, c, t * 2.0 - 1.0);
}

const vec3 LAYERS[4] = vec3[4](vec3(0.40, 0.34, 0.28), vec3(0.55, 0.30, 0.18), vec3(0.74, 0.60, 0.42),
                               vec3(0.16, 0.09, 0.06));
const vec3 PEEL[3] = vec3[3](vec3(0.46, 0.41, 0.35), vec3(0.93, 0.55, 0.12), vec3(0.80, 0.62, 0.56));

void main() {
  if (vPatch.x < 0.0 || vPatch.y < 0.0 || vPatch.x >= uPatch.x || vPatch.y >= uPatch.y) discard;
  if (uMode == 2) {
    outColor = vec4(LAYERS[clamp(int(vLayer + 0.5), 0, 3)], 1.0);
    return;
  }
  if (uMode == 3) {
    outColor = vec4(PEEL[clamp(int(vPeel + 0.5), 0, 2)], 1.0);
    return;
  }
  if (vBroken >= 0.0 && vBroken <= uStep) discard;
  float s = clamp(vStretch, 0.0, 1.0);
  vec3 plate = mix(vec3(0.50, 0.45, 0.38), vec3(0.36, 0.31, 0.26), s);
  outColor = vec4(uMode == 1 ? heat(s) : plate, 1.0);
}
