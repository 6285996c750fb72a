#version 300 es
// The garden's casters into the sun's shadow map (web/gl/shadow_map.js): the objects and every
// planted tree, placed as garden.vert places them (aInstance: foot x, y, z and turn in radians);
// aBirth: the garden year an ivy vertex grew in (0 elsewhere), for shadow.frag's year; with uSway
// 1 (Blow) a tree vertex skinned to its copy's poses first, as garden.vert does.
layout(location = 0) in vec3 aPosition;
layout(location = 3) in vec4 aInstance;
layout(location = 4) in float aBirth;
layout(location = 5) in uint aJoint;
layout(location = 6) in float aWeight;
layout(location = 7) in float aBlock;

uniform mat4 uSunViewProjection;
uniform int uSway;

#include "../common/skin.glsl"

out float vBirth;

void main() {
  float c = cos(aInstance.w), s = sin(aInstance.w);
  vec3 p = aPosition;
  if (uSway == 1) p = skinPosition(uint(aBlock) + aJoint, aWeight, aPosition);
  vec3 world = aInstance.xyz + vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
  vBirth = aBirth;
  gl_Position = uSunViewProjection * vec4(world, 1.0);
}
