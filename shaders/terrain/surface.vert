#version 300 es
// The terrain's heightfield surface (paper 002): one vertex per cell centre in metres, y up
// ((x, h, −y) as the .glb), drawn through uModel (an offset and a uniform scale that fit the
// mountain in the view; uExaggerate stretches heights only) with its hypsometric tint colour. The
// level scrubber cuts the surface flat at uTop (m): the mountain as it stands when its contours
// up to that level have grown.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted, w: scale (world = (p - offset) * scale)
uniform float uExaggerate;
uniform float uTop;
uniform vec3 uCutColour;  // the tint at uTop (a cut vertex shows the height it is cut to)

out vec3 vNormal;
out vec3 vColour;

void main() {
  bool cut = aPosition.y > uTop;
  vec3 p = vec3(aPosition.x, min(aPosition.y, uTop), aPosition.z) - uModel.xyz;
  p.y *= uExaggerate;
  vNormal = cut ? vec3(0.0, 1.0, 0.0) : normalize(vec3(aNormal.x, aNormal.y / uExaggerate, aNormal.z));
  vColour = cut ? uCutColour : aColour;
  gl_Position = uViewProjection * vec4(p * uModel.w, 1.0);
}
