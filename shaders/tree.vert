#version 300 es
// Tree parts (bark tubes, leaf quads, flowers): world-space positions in metres, y up.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uViewProjection;

out vec3 vNormal;
out vec3 vWorld;

void main() {
  vNormal = aNormal;
  vWorld = aPosition;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
