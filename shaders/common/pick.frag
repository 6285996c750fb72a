#version 300 es
// Writes branch id + 1 as 24-bit RGB (0 = background), read back with readPixels at the click.
precision highp float;
precision highp int;

flat in uint vBranch;
out vec4 outColor;

void main() {
  uint v = vBranch + 1u;
  outColor = vec4(float(v & 255u), float((v >> 8) & 255u), float((v >> 16) & 255u), 255.0) / 255.0;
}
