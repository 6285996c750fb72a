#version 300 es
// Ground plane: a square of half-size uExtent at y = 0 centred under the tree.
layout(location = 0) in vec2 aCorner;  // -1..1

uniform mat4 uViewProjection;
uniform vec3 uCenter;
uniform float uExtent;

out vec2 vGround;  // world x, z

void main() {
  vec2 xz = uCenter.xz + aCorner * uExtent;
  vGround = xz;
  gl_Position = uViewProjection * vec4(xz.x, 0.0, xz.y, 1.0);
}
