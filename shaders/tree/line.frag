#version 300 es
// Hybrid mode lines: the eq. 4.2 colour (same output curve as tree.frag), blended by coverage.
precision highp float;

in vec3 vColor;
in float vCoverage;
out vec4 outColor;

void main() { outColor = vec4(pow(vColor, vec3(1.0 / 1.1)), vCoverage); }
