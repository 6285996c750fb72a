#version 300 es
// Seed-point markers: round orange dots with a dark rim, drawn over everything.
precision mediump float;
out vec4 outColor;
void main() {
  vec2 d = gl_PointCoord - 0.5;
  float r = length(d);
  if (r > 0.5) discard;
  outColor = r > 0.36 ? vec4(0.25, 0.12, 0.02, 1.0) : vec4(1.0, 0.55, 0.1, 1.0);
}
