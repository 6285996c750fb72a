#version 300 es
// Hybrid mode cards: the atlas texel, transparent outside the branch (alpha test).
precision highp float;

in vec2 vUv;
uniform sampler2D uAtlas;
out vec4 outColor;

void main() {
  vec4 texel = texture(uAtlas, vUv);
  // Mip levels average a leaf's alpha with its transparent surroundings, so a fixed alpha test
  // would erase distant leaf clusters; the alpha is scaled up with the mip level the card is read
  // at (about 25 % per level), which keeps the covered area of a far card near its true size.
  vec2 texels = vUv * vec2(textureSize(uAtlas, 0));
  vec2 dx = dFdx(texels), dy = dFdy(texels);
  float lod = 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-8));
  float alpha = texel.a * (1.0 + 0.25 * max(lod, 0.0));
  if (alpha < 0.3) discard;
  outColor = vec4(texel.rgb / max(texel.a, 1e-4), 1.0);  // undo the darkening by transparent neighbours
}
