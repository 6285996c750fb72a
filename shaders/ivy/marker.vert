#version 300 es
// Markers: one screen-facing point each (gl_PointSize), in scene units through uModel as ivy.vert:
// the seed points (aKind 3) and the buds of the L-string coloured by kind (0 apical A, 1 dormant D,
// 2 ending Z, as at the last step); a bud born after the scrubber's step uStep is not drawn.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in float aKind;
layout(location = 2) in float aBirth;
uniform mat4 uViewProjection;
uniform vec4 uModel;
uniform float uPointSize;
uniform float uStep;
out vec3 vColor;
void main() {
  gl_Position = aBirth > uStep + 0.5 ? vec4(2.0, 2.0, 2.0, 1.0)
                                     : uViewProjection * vec4((aPosition - uModel.xyz) * uModel.w, 1.0);
  gl_PointSize = aKind > 2.5 ? uPointSize : 0.6 * uPointSize;
  vColor = aKind < 0.5 ? vec3(0.2, 0.8, 0.25) : aKind < 1.5 ? vec3(0.95, 0.8, 0.2)
         : aKind < 2.5 ? vec3(0.45, 0.45, 0.5) : vec3(1.0, 0.55, 0.1);
}
