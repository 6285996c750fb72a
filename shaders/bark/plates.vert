#version 300 es
// The bark study's unrolled tile as its lattice triangles (paper 003 Fig. 3; spec §1.9): three
// vertices per triangle at the surface nodes' positions (cm: x around the trunk, z along it), the
// triangle's stretch (its largest intact edge strain over that edge's break strain, 0..1) and the
// step its first edge broke (-1: intact), the layer showing in it (0 S, 1 M1, 2 M2, 3 inner) and
// its peel state (0 bonded, 1 unbonded from M1, 2 peeled off). Drawn in the plane z = 0 of the page's world through
// uModel, shifted by uShift (one of the four copies that close the torus over the seams).
layout(location = 0) in vec2 aPosition;
layout(location = 1) in float aStretch;
layout(location = 2) in float aBroken;
layout(location = 3) in float aLayer;
layout(location = 4) in float aPeel;

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted (cm), w: scale (world units per cm)
uniform vec2 uShift;  // cm

out vec2 vPatch;
out float vStretch;
out float vBroken;
out float vLayer;
out float vPeel;

void main() {
  vec2 p = aPosition + uShift;
  vPatch = p;
  vStretch = aStretch;
  vBroken = aBroken;
  vLayer = aLayer;
  vPeel = aPeel;
  gl_Position = uViewProjection * vec4((vec3(p, 0.0) - uModel.xyz) * uModel.w, 1.0);
}
