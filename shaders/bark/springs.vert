#version 300 es
// The surface's broken springs as line segments over the tile (the 'Broken springs' toggle): two
// vertices a spring at its nodes' positions (cm: x around, z along; unwrapped from its first node)
// and the step it broke at. Drawn just in front of the tile (z = uDepth) through uModel, shifted by
// uShift (one of the four copies that close the torus over the seams).
layout(location = 0) in vec2 aPosition;
layout(location = 1) in float aBroken;

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted (cm), w: scale (world units per cm)
uniform vec2 uShift;  // cm
uniform float uDepth;  // cm

out vec2 vPatch;
out float vBroken;

void main() {
  vec2 p = aPosition + uShift;
  vPatch = p;
  vBroken = aBroken;
  gl_Position = uViewProjection * vec4((vec3(p, uDepth) - uModel.xyz) * uModel.w, 1.0);
}
