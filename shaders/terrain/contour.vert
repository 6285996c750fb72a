#version 300 es
// The contour lines of the terrain (LINES, two vertices per ring edge) at their elevations, in
// the surface's frame (uModel, uExaggerate as surface.vert), lifted by uLift view units so the
// surface does not hide them; aLevel darkens every fifth contour (an index contour, as maps do),
// and a contour above the level scrubber's uLevel is moved outside the clip volume.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in float aLevel;

uniform mat4 uViewProjection;
uniform vec4 uModel;
uniform float uExaggerate;
uniform float uLift;
uniform float uLevel;

out float vIndex;

void main() {
  vec3 p = aPosition - uModel.xyz;
  p.y *= uExaggerate;
  vIndex = mod(aLevel + 0.5, 5.0) < 1.0 ? 1.0 : 0.0;
  gl_Position = aLevel > uLevel + 0.5 ? vec4(2.0, 2.0, 2.0, 1.0)
                                      : uViewProjection * vec4(p * uModel.w + vec3(0.0, uLift, 0.0), 1.0);
}
