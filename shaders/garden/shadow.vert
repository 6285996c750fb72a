#version 300 es
// The garden's casters into the sun's shadow map (web/gl/shadow_map.js): the objects and every
// planted tree, placed as garden.vert places them (aInstance: foot x, y, z and turn in radians);
// aBirth: the garden year an ivy vertex grew in (0 elsewhere), for shadow.frag's year.
layout(location = 0) in vec3 aPosition;
layout(location = 3) in vec4 aInstance;
layout(location = 4) in float aBirth;

uniform mat4 uSunViewProjection;

out float vBirth;

void main() {
  float c = cos(aInstance.w), s = sin(aInstance.w);
  vec3 p = aPosition;
  vec3 world = aInstance.xyz + vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
  vBirth = aBirth;
  gl_Position = uSunViewProjection * vec4(world, 1.0);
}
