#version 300 es
// A broken spring of the surface: red where it broke by the step shown (uStep), nothing where it
// breaks later or lies outside the patch (a copy's overhang past the seam).
precision highp float;

in vec2 vPatch;
in float vBroken;

uniform vec2 uPatch;  // circumference, height (cm)
uniform float uStep;

out vec4 outColor;

void main() {
  if (vPatch.x < 0.0 || vPatch.y < 0.0 || vPatch.x >= uPatch.x || vPatch.y >= uPatch.y) discard;
  if (vBroken > uStep) discard;
  outColor = vec4(0.86, 0.08, 0.06, 1.0);
}
