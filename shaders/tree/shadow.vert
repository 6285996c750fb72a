#version 300 es
// The tree's parts into the sun's shadow map (web/gl/shadow_map.js): the same skinned, fluttering
// positions as tree.vert, seen from the sun.
layout(location = 0) in vec3 aPosition;
layout(location = 4) in uint aJoint;
layout(location = 5) in float aWeight;
layout(location = 6) in vec2 aUv;

uniform mat4 uSunViewProjection;

out vec2 vUv;

#include "../common/skin.glsl"
#include "tree_pose.glsl"

void main() {
  mat3 rotation;
  vUv = aUv;
  gl_Position = uSunViewProjection * vec4(swayedWorld(aPosition, aJoint, aWeight, aUv, rotation), 1.0);
}
