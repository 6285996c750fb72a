#version 300 es
// The moss study's photon points (Nomura 2010 figs 4.1/4.2): every photon the last day stored, in
// metres through uModel as the land, a few pixels wide, pulled a little towards the eye so a point
// on a face is not hidden by it; its bounce depth picks its colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in float aDepth;  // 0 direct, n after n bounces

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted, w: scale
uniform float uPointSize;

out float vDepth;

void main() {
  vDepth = aDepth;
  gl_Position = uViewProjection * vec4((aPosition - uModel.xyz) * uModel.w, 1.0);
  gl_Position.z -= 0.0005 * gl_Position.w;
  gl_PointSize = uPointSize;
}
