#version 300 es
// Depth only (the shadow map): leaf blades and blossoms cut out of their cards by the texture's
// alpha as in tree_textured.frag (glTF MASK 0.5), so the shadow has the leaves' shapes.
precision highp float;

in vec2 vUv;

uniform sampler2D uBaseMap;
uniform float uUseTexture;
uniform float uAlphaCutoff;

void main() {
  if (uUseTexture > 0.5 && uAlphaCutoff > 0.0 && texture(uBaseMap, vUv).a < uAlphaCutoff) discard;
}
