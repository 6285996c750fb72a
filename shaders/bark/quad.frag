#version 300 es
// The tile's rectangle: uMode 0 the maps lit as an engine would show them (bark_light.glsl: base
// colour, normal and occlusion under the key light), 2 the base-colour map as it is (an albedo:
// unlit), 1 the inner layer's red-brown (what a crack shows in the plate views).
precision highp float;

#include "bark_light.glsl"

in vec2 vUv;
in vec3 vPosition;

uniform sampler2D uBaseColour;
uniform sampler2D uNormalMap;
uniform sampler2D uOrm;
uniform int uMode;
uniform vec3 uKeyLight;  // unit, towards the light
uniform vec3 uEye;

out vec4 outColor;

void main() {
  if (uMode == 1) {
    outColor = vec4(0.30, 0.17, 0.11, 1.0);
    return;
  }
  vec3 base = texture(uBaseColour, vUv).rgb;
  if (uMode == 2) {
    outColor = vec4(base, 1.0);
    return;
  }
  vec3 lit = barkLit(base, texture(uNormalMap, vUv).xyz, texture(uOrm, vUv).rgb, vec3(1.0, 0.0, 0.0),
                     vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), uKeyLight, normalize(uEye - vPosition));
  outColor = vec4(lit, 1.0);
}
