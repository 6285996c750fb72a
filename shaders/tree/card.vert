#version 300 es
// Hybrid mode cards (thesis 4.2): textured quads of branches and leaf clusters, skinned to the sway.
layout(location = 0) in vec3 aPosition;  // metres
layout(location = 1) in vec2 aUv;        // atlas
layout(location = 4) in uint aJoint;
layout(location = 5) in float aWeight;

uniform mat4 uViewProjection;

out vec2 vUv;

#include "../common/skin.glsl"

void main() {
  vUv = aUv;
  gl_Position = uViewProjection * vec4(skinPosition(aJoint, aWeight, aPosition), 1.0);
}
