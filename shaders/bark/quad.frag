#version 300 es
// The tile's rectangle: uMode 0 the base-colour map as it is (an albedo: unlit), 1 the inner
// layer's red-brown (what a crack shows in the plate views).
precision highp float;

in vec2 vUv;

uniform sampler2D uBaseColour;
uniform int uMode;

out vec4 outColor;

void main() {
  outColor = uMode == 0 ? vec4(texture(uBaseColour, vUv).rgb, 1.0) : vec4(0.30, 0.17, 0.11, 1.0);
}
