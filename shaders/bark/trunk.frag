#version 300 es
// The trunk segment: the maps lit as the tile's (bark_light.glsl) on the cylinder's tangent frame.
precision highp float;

#include "bark_light.glsl"

in vec2 vUv;
in vec3 vNormal;
in vec3 vTangent;
in vec3 vPosition;

uniform sampler2D uBaseColour;
uniform sampler2D uNormalMap;
uniform sampler2D uOrm;
uniform vec3 uKeyLight;  // unit, towards the light
uniform vec3 uEye;

out vec4 outColor;

void main() {
  vec3 N = normalize(vNormal), T = normalize(vTangent), B = cross(N, T);
  vec3 lit = barkLit(texture(uBaseColour, vUv).rgb, texture(uNormalMap, vUv).xyz, texture(uOrm, vUv).rgb,
                     T, B, N, uKeyLight, normalize(uEye - vPosition));
  outColor = vec4(lit, 1.0);
}
