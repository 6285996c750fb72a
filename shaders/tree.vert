#version 300 es
// Tree parts (bark tubes, leaf quads, flowers): world-space positions in metres, y up.
// aHighlight: 1 on the selected branch, 0.5 on the branches a cut there would take with it, else 0
// (a per-vertex buffer for the bark; the constant 0 for leaves and flowers).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in float aHighlight;

uniform mat4 uViewProjection;

out vec3 vNormal;
out vec3 vWorld;
out float vSelected;

void main() {
  vNormal = aNormal;
  vWorld = aPosition;
  vSelected = aHighlight;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
