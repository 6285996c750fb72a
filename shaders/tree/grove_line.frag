#version 300 es
// Grove, hybrid mode lines: the eq. 4.2 colour (output curve of tree.frag), blended by coverage
// (a line thinner than a pixel is drawn 1 px wide and this opaque, as the page's line.frag).
precision highp float;

in vec3 vColor;
in float vCoverage;
out vec4 outColor;

void main() { outColor = vec4(pow(vColor, vec3(1.0 / 1.1)), vCoverage); }
