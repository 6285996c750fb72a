#version 300 es
// Hybrid mode cards on the tree page: card.frag's atlas texel (lit by the sun when the atlas was
// painted) dimmed where the sun's shadow map says the card is in shadow, as full mode's parts are
// (tree_textured.frag: in shadow a part keeps its sky light and loses the sun's, about 0.45 of its
// linear light for the sun and sky of the page), so the crown's shaded side and the branches under
// it darken in hybrid mode too. The grove's cards keep card.frag (no shadow map there).
precision highp float;

in vec2 vUv;
in vec4 vShadow;
uniform sampler2D uAtlas;
out vec4 outColor;

#include "../common/shadow.glsl"

void main() {
  vec4 texel = texture(uAtlas, vUv);
  // As card.frag: the alpha scaled up with the mip level, so far leaf clusters keep their area.
  vec2 texels = vUv * vec2(textureSize(uAtlas, 0));
  vec2 dx = dFdx(texels), dy = dFdy(texels);
  float lod = 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-8));
  float alpha = texel.a * (1.0 + 0.25 * max(lod, 0.0));
  if (alpha < 0.3) discard;
  vec3 colour = texel.rgb / max(texel.a, 1e-4);
  // The sRGB texel times the linear factor's sRGB (0.45 linear in full shadow).
  float light = mix(0.45, 1.0, sunVisibility(vShadow));
  outColor = vec4(colour * pow(light, 1.0 / 2.2), 1.0);
}
