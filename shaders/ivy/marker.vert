#version 300 es
// Seed-point markers: one screen-facing point per seed (gl_PointSize), in scene units through
// uModel as ivy.vert.
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
uniform vec4 uModel;
uniform float uPointSize;
void main() {
  gl_Position = uViewProjection * vec4((aPosition - uModel.xyz) * uModel.w, 1.0);
  gl_PointSize = uPointSize;
}
