#version 300 es
// The moss study's photon points: direct photons (depth 0) warm yellow, bounced ones (depth >= 1)
// blue, as the two kinds of figs 4.1/4.2; round points.
precision highp float;

in float vDepth;

out vec4 outColor;

void main() {
  vec2 d = gl_PointCoord - 0.5;
  if (dot(d, d) > 0.25) discard;
  outColor = vDepth < 0.5 ? vec4(1.0, 0.80, 0.10, 1.0) : vec4(0.15, 0.45, 1.0, 1.0);
}
