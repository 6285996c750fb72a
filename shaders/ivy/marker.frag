#version 300 es
// Markers: round dots of the vertex colour with a dark rim, drawn over everything.
precision mediump float;
in vec3 vColor;
out vec4 outColor;
void main() {
  vec2 d = gl_PointCoord - 0.5;
  float r = length(d);
  if (r > 0.5) discard;
  outColor = r > 0.36 ? vec4(0.15, 0.1, 0.05, 1.0) : vec4(vColor, 1.0);
}
