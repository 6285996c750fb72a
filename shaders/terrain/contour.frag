#version 300 es
// Contour lines: dark brown, index contours (every fifth level) darker still.
precision mediump float;
in float vIndex;
out vec4 outColor;
void main() {
  outColor = vIndex > 0.5 ? vec4(0.18, 0.09, 0.03, 1.0) : vec4(0.33, 0.2, 0.1, 1.0);
}
