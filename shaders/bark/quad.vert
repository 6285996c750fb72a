#version 300 es
// The unrolled tile's rectangle (circumference × height, cm) in the plane z = uDepth of the page's
// world: the maps on it (image row 0 is the top of the patch; the tangent frame is the world's x
// around, y up, z out), once or repeated 2 × 2 (the seams in view), or the inner layer's flat
// colour beneath the plates.
layout(location = 0) in vec2 aCorner;  // 0..1

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted (cm), w: scale
uniform vec2 uPatch;
uniform float uDepth;  // cm
uniform float uRepeat;  // the maps' repeats across the rectangle (2: four tiles, the seams inside)

out vec2 vUv;
out vec3 vPosition;

void main() {
  vUv = vec2(aCorner.x, 1.0 - aCorner.y) * uRepeat;
  vec3 p = vec3(aCorner * uPatch, uDepth);
  vPosition = (p - uModel.xyz) * uModel.w;
  gl_Position = uViewProjection * vec4(vPosition, 1.0);
}
