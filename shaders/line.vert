#version 300 es
// Hybrid mode lines (thesis 4.2): one instance per segment, expanded to a screen-space quad of the
// segment's width D_i in pixels (eq. 4.1); both ends skinned to the sway.
layout(location = 0) in vec3 aP0;
layout(location = 1) in vec3 aP1;
layout(location = 2) in vec3 aColor;  // eq. 4.2
layout(location = 3) in float aWidth;  // pixels
layout(location = 4) in uvec2 aJoints;
layout(location = 5) in vec2 aWeights;

uniform mat4 uViewProjection;
uniform vec2 uViewport;  // pixels

out vec3 vColor;

#include "skin.glsl"

void main() {
  vec4 c0 = uViewProjection * vec4(skinPosition(aJoints.x, aWeights.x, aP0), 1.0);
  vec4 c1 = uViewProjection * vec4(skinPosition(aJoints.y, aWeights.y, aP1), 1.0);
  bool far = gl_VertexID >= 2;
  float side = (gl_VertexID & 1) == 0 ? -1.0 : 1.0;
  vec2 s0 = c0.xy / max(c0.w, 1e-6) * uViewport * 0.5;
  vec2 s1 = c1.xy / max(c1.w, 1e-6) * uViewport * 0.5;
  vec2 along = s1 - s0;
  vec2 normal = length(along) > 1e-6 ? normalize(vec2(-along.y, along.x)) : vec2(1.0, 0.0);
  vec4 clip = far ? c1 : c0;
  clip.xy += normal * side * 0.5 * aWidth / (uViewport * 0.5) * clip.w;
  vColor = aColor;
  gl_Position = clip;
}
