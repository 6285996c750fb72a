#version 300 es
// Ground plane: a square of half-size uExtent at y = 0 centred under the tree.
layout(location = 0) in vec2 aCorner;  // -1..1

uniform mat4 uViewProjection;
uniform mat4 uSunViewProjection;  // the shadow map's (web/gl/shadow_map.js)
uniform vec3 uCenter;
uniform float uExtent;

out vec2 vGround;  // world x, z
out vec4 vShadow;  // the point in the sun's clip space

void main() {
  vec2 xz = uCenter.xz + aCorner * uExtent;
  vGround = xz;
  vShadow = uSunViewProjection * vec4(xz.x, 0.0, xz.y, 1.0);
  gl_Position = uViewProjection * vec4(xz.x, 0.0, xz.y, 1.0);
}
