#version 300 es
// Hybrid mode cards: the atlas texel, transparent outside the branch (alpha test).
precision highp float;

in vec2 vUv;
uniform sampler2D uAtlas;
out vec4 outColor;

void main() {
  vec4 texel = texture(uAtlas, vUv);
  if (texel.a < 0.3) discard;
  outColor = vec4(texel.rgb / texel.a, 1.0);  // undo the darkening by transparent black neighbours
}
