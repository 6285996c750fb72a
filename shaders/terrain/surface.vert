#version 300 es
// The terrain's heightfield surface (paper 002): one vertex per cell centre in metres, y up
// ((x, h, −y) as the .glb), drawn through uModel (an offset and a uniform scale that fit the
// mountain in the view; uExaggerate stretches heights only) with its hypsometric tint colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted, w: scale (world = (p - offset) * scale)
uniform float uExaggerate;

out vec3 vNormal;
out vec3 vColour;

void main() {
  vec3 p = aPosition - uModel.xyz;
  p.y *= uExaggerate;
  vNormal = normalize(vec3(aNormal.x, aNormal.y / uExaggerate, aNormal.z));
  vColour = aColour;
  gl_Position = uViewProjection * vec4(p * uModel.w, 1.0);
}
